"""Reference: the verdict's every-root check solves at (1 + min_onset_margin) × the operating speed.

docs/requirements.md ("The stability checks: tracked modes and every root"): the every-root
check holds "every root of the closed-loop first-order system at rest, at the operating speed and
at (1 + `min_onset_margin`) × it", "so an unstable root at (1 + `min_onset_margin`) × the
operating speed itself fails".

The rotor: the Jeffcott rotor of tests/rotors.py (disk m on a near-massless tube, k = 48EI/L³,
ω_n = √(k/m)) with a rotating hysteretic loss η = 0.02 and an external dashpot of ζ_e = 0.002,
run at Ω_op = ω_n/1.1 with the default margin 0.15 (1.15 Ω_op = 1.045 ω_n). In complex
coordinates the disk obeys m s² + c_e s + k(1 + iη sgn(ω − Ω)) = 0 (derived here from the
rotating-frame loss: it opposes the whirl relative to the spin). Below the spin (Ω > ω_n) the
forward root solves m s² + c_e s + k(1 − iη) = 0, whose real part ≈ (η√(mk) − c_e)/(2m) =
ω_n (η/2 − ζ_e) > 0: unstable. At rest and at Ω_op (< ω_n) the forward whirl outruns the spin and
the loss damps it: stable. So the check's one unstable root is at 1.15 Ω_op, and it is that
quadratic's root. Tolerance 1e-4 relative: the tube's mass is 3.5e-6 of the disk's and the
8-element mesh's condensation of the tube is exact for the static stiffness (measured 6e-7).
"""

from __future__ import annotations

import numpy as np
from conftest import SMALLEST
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict import point_tasks

ETA, ZETA_E = 0.02, 0.002


def test_the_every_root_check_finds_the_whirl_between_the_operating_and_the_required_speed():
    c_e = 2.0 * ZETA_E * M_DISK * WN
    text = jeffcott_text(ETA, c_e).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(WN / 1.1)}")
    design = loads_design(text)
    assert design.requirements.min_onset_margin == 0.15  # docs/requirements.md's default
    model = build_model(design)
    required = 1.15 * model.speed
    assert model.speed < WN < required
    roots, loops = point_tasks._roots_and_loops(model, SMALLEST)
    assert loops is None  # no active bearing: no loops
    assert np.allclose(roots.speeds, [0.0, model.speed, required], rtol=1e-12, atol=0.0)
    assert len(roots.unstable) == 1, roots.unstable
    found = roots.unstable[0]
    assert abs(found.speed / required - 1.0) < 1e-12
    quadratic = np.roots([M_DISK, c_e, K_SHAFT * (1.0 - 1j * ETA)])
    forward = quadratic[np.argmax(quadratic.imag)]
    assert forward.real > 0.0
    assert abs(found.root - forward) < 1e-4 * abs(forward), (found.root, forward)
    assert abs(found.root.real / forward.real - 1.0) < 1e-3, (found.root, forward)
