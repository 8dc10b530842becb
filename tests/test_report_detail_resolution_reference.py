"""What only the report shows, at the resolution asked for (flexshaft.verdict.operating_point):
add_report_detail computes it "at ``resolution`` (default ``p.resolution``)", and analyse_point
with the detail computes it too ("Also compute what only the report shows").

A point of the Jeffcott rotor of tests/rotors.py is analysed at the smallest grids (no Campbell
diagram, 4 modes) without the detail, then given the detail at a resolution with a 4-speed
Campbell diagram and 6 modes; and analysed with the detail at that resolution (its Campbell
diagram, an analysis run beside the others, is there as well as its modes at rest).
Resolution's docstring: the Campbell diagram's speeds run "rest to ``scan_top`` × Ω_op"; so its
speeds are linspace(0, scan_top Ω_op, 4) and the modes at rest are 6.

Reference (closed form, tests/rotors.py): a heavy midspan disk m, without polar inertia, on a
pinned-pinned tube of midspan stiffness k = 48 E I / L³, with a stationary dashpot c_e at the
disk. Each lateral direction is one damped oscillator m s² + c_e s + k = 0, whose roots have
|s| = √(k/m) = ω_n exactly whatever c_e (below critical); without polar inertia the spin adds no
gyroscopic coupling and the stationary dashpot no circulatory term, so the two whirls have
|s| = ω_n at every speed of the diagram. ζ = 0.01 keeps the spin-up scan off the undamped
resonance. Tolerance 1e-5: the tube's own mass (3.5e-6 of the disk's) moves ω_n by Rayleigh's
−(17/70)(3.5e-6) ≈ −8.5e-7 (tests/test_report_detail_reference.py), and the next root, the
axial one, is 12.8 ω_n. CPU: one point at the smallest grids and one 4-speed diagram each, about 0.3 s per test.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from conftest import SMALLEST
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.operating_point import add_report_detail, analyse_point

OMEGA_OP = 1.2 * WN
C_E = 2 * 0.01 * np.sqrt(K_SHAFT * M_DISK)  # ζ = 0.01


TEXT = jeffcott_text(0.0, C_E).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(OMEGA_OP)}")
ASKED = dataclasses.replace(SMALLEST, campbell_speeds=4, modes=6)


def _holds_the_detail(shown, asked):
    """The Campbell diagram on the asked speeds and the modes at rest, each whirl at ω_n."""
    camp = shown.campbell
    assert camp is not None
    assert camp.speeds == pytest.approx(np.linspace(0.0, asked.scan_top * OMEGA_OP, 4), rel=1e-12, abs=1e-12)
    for s, kind in zip(np.asarray(camp.eigenvalues), np.asarray(camp.kind), strict=True):
        whirls = np.sort(np.abs(s[kind == "lateral"]))[:2]
        assert whirls == pytest.approx(np.full(2, WN), rel=1e-5)
    at_rest = shown.modes_at_rest
    assert at_rest is not None and at_rest.eigenvalues.size == asked.modes
    lateral = np.abs(np.asarray(at_rest.eigenvalues)[np.asarray(at_rest.kind) == "lateral"][:2])
    assert lateral == pytest.approx(np.full(2, WN), rel=1e-5)


def test_the_detail_is_added_at_the_resolution_asked_for():
    bare = analyse_point(loads_design(TEXT), SMALLEST, detail=False)
    assert bare.campbell is None and bare.modes_at_rest is None  # the premise: no detail yet
    shown = add_report_detail(bare, ASKED)
    assert shown.resolution == ASKED
    _holds_the_detail(shown, ASKED)


def test_a_point_analysed_with_the_detail_has_its_campbell_diagram():
    _holds_the_detail(analyse_point(loads_design(TEXT), ASKED, detail=True), ASKED)
