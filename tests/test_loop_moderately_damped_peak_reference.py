"""A moderately damped sensitivity peak (ζ = 0.1) is found on a coarse loop grid: the grid
samples every closed-loop pole lighter than its resolved damping, not only the very light ones
(flexshaft.analyses.loop_grid, bearing_loops; mutation hunt h56c).

The rigid rotor of tests/test_amb.py (1 m tube 1e4 times stiffer than steel with a 20 kg disk
at mid-span: m = 42.05 kg, I_t = 2.360 kg m² about the centre) on two PD magnetic bearings
(k_i = 1, k_s = 0: G(s) = k_p + k_d s, k_p = 1e5 N/m, k_d = 290 N s/m) at a = ∓0.4 m about
the centre, at rest: the planes uncouple, and in one plane the rigid body (centre translation,
tilt) has M = diag(m, I_t) and the bearings' rows b₁ = (1, −0.4), b₂ = (1, 0.4). The closed
loop's translation root has ζ = k_d/√(2 k_p m) = 0.100 and its tilt root ζ = k_d a/√(2 k_p I_t)
= 0.169: both moderately damped, half-power widths of 20-34 % of their frequencies.

Loop 1 is broken at bearing 1's controller with bearing 2 closed: Z_o(s) = M s² + G b₂b₂ᵀ,
L = G b₁ᵀ Z_o⁻¹ b₁, and by the matrix determinant lemma det Z_c = det Z_o (1 + L) with
Z_c = Z_o + G b₁b₁ᵀ, so S(iω) = 1/(1 + L) = det Z_o/det Z_c (derived here). The reference
peak of |S| is the maximum of this 2×2 closed form: sampled on 20001 log points over 1-1000 Hz
and refined by a bounded scalar search to 1e-10 in ω.

The loops run on a deliberately coarse grid, 20 logarithmic points over 1-1000 Hz (44 % steps,
wider than both peaks). The refined peak is the golden-section search's, to 1e-6 in ln ω
(tests/test_loop_robustness.py), and the FE rotor's roots match the rigid closed form to about
1e-6 (tests/test_amb.py); measured against the closed form: |S| off by 4.4e-7, the peak's
frequency by -4.3e-6. Asserted: |S|max within rel 1e-5 (a flat top: the value's error is second
order in the frequency's) and its frequency within rel 1e-4. A grid without points at
the ζ = 0.1 pole reads a shoulder at 20 Hz (|S| = 1.94) for the peak of 2.59 at 11.0 Hz.
CPU: one small model and its loops on 20 points, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import minimize_scalar
from test_amb import I_T, MASS, rotor_text

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

KP, KD, A = 1.0e5, 290.0, 0.4


def _sensitivity(omega):
    """|S(iω)| of loop 1 from the rigid body's 2×2 dynamic stiffness (module docstring);
    ``omega`` a float or an array [rad/s]."""
    s = 1j * np.asarray(omega, dtype=float)
    g = KP + KD * s
    b1, b2 = np.array([1.0, -A]), np.array([1.0, A])
    z_open = np.diag([MASS, I_T]) * (s * s)[..., None, None] + g[..., None, None] * np.outer(b2, b2)
    z_closed = z_open + g[..., None, None] * np.outer(b1, b1)
    return np.abs(np.linalg.det(z_open) / np.linalg.det(z_closed))


def _reference_peak() -> tuple[float, float]:
    omegas = 2 * np.pi * np.geomspace(1.0, 1000.0, 20001)
    k = int(np.argmax(_sensitivity(omegas)))
    found = minimize_scalar(
        lambda w: -float(_sensitivity(w)),
        bounds=(omegas[k - 1], omegas[k + 1]),
        method="bounded",
        options={"xatol": 1e-10},
    )
    return float(-found.fun), float(found.x / (2 * np.pi))


def test_a_zeta_tenth_peak_is_found_between_coarse_grid_points():
    assert KD / np.sqrt(2 * KP * MASS) == pytest.approx(0.1, abs=1e-3)
    model = build_model(loads_design(rotor_text(f"kp = {KP}\nkd = {KD}")))
    peak, frequency = _reference_peak()
    for loop in bearing_loops(model, speed=0.0, n_points=20, frequency_range=(1.0, 1000.0)):
        assert loop.margins.peak_sensitivity == pytest.approx(peak, rel=1e-5), (loop.actuator, loop.axis)
        assert loop.margins.peak_frequency == pytest.approx(frequency, rel=1e-4), (loop.actuator, loop.axis)
