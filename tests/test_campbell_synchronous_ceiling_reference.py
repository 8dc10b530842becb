"""Reference: the Campbell diagram of a rotor holds its modes up to at least 1/rev.

Every spinning rotor is excited once per revolution by its residual imbalance (the synchronous
whirl of the unbalance response), so the Campbell diagram's ceiling is at least its top speed
× 1 even for a model with no design (no rotor, no torsional excitation lines): the API contract
of :func:`flexshaft.verdict.point_tasks.campbell_ceiling`'s docstring, "at least 1/rev" (no
docs page states the ceiling rule). The model: the Jeffcott rotor of tests/rotors.py without a
design, Ω_op = ω_n/1.1 and a two-speed diagram to scan_top × Ω_op = 1.3 Ω_op = 1.18 ω_n. Its
modes at rest: the disk's bending pair at ω_n = √(48EI/(mL³)) (both planes); the tube's own
modes are orders of magnitude higher (its mass is 3.5e-6 of the disk's). Below 1.1 × 1.18 ω_n =
1.30 ω_n lies the pair: 2 + 2 = 4 modes with campbell_modes = 2 (the API contract of
:func:`~flexshaft.verdict.point_tasks.campbell_mode_count`: every mode at rest below 1.1 × the
ceiling, plus two). The ceiling is a product of two floats: 1e-12 relative.
"""

from __future__ import annotations

import dataclasses

from rotors import WN, jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.resolution import REPORT
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.point_tasks import campbell_ceiling, campbell_mode_count


def test_a_model_without_a_design_tracks_its_modes_up_to_once_per_revolution():
    text = jeffcott_text(0.0, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(WN / 1.1)}")
    model = dataclasses.replace(build_model(loads_design(text)), design=None)
    resolution = dataclasses.replace(REPORT, campbell_speeds=2, campbell_modes=2)
    top = resolution.scan_top * model.speed
    assert abs(campbell_ceiling(model, resolution) / top - 1.0) < 1e-12
    assert top < WN * 1.2 and 1.1 * top > WN * 1.25  # the pair lies below 1.1 × the ceiling, clearly
    assert campbell_mode_count(model, resolution) == 2 + 2
