"""The viscous whirl study of one design takes the reference frequency it is given
(:func:`flexshaft.thesis.whirl.shaft_stability`), checked against the Jeffcott rotor's closed form.

flexshaft's viscous internal-damping model (thesis chapter 4) turns the shaft's loss factor η into
the rotating viscous damping c_i = η k / ω_ref. For a Jeffcott rotor (disk m on a massless shaft of
stiffness k, stationary damping c_e at the disk) the complex-coordinate equation
m r'' + (c_e + c_i) r' + (k − i c_i Ω) r = 0 has a root on the imaginary axis, s = i ω_n, exactly
when c_i Ω = (c_e + c_i) ω_n (insert s = iω: real part k − m ω² = 0, imaginary part
(c_e + c_i) ω − c_i Ω = 0), so the whirl onset is

    Ω_onset = ω_n (1 + c_e / c_i) = ω_n (1 + c_e ω_ref / (η k)).

The rotor is the validation case ``jeffcott-rotating-damping-onset``'s (k = 75 398 N/m, m = 10 kg,
c_e = 8.6832 N s/m = 2 ζ_e m ω_n with ζ_e = 0.005, η = 0.02). With ω_ref = 2 ω_n, c_e ω_ref/(η k) =
2 ζ_e m ω_n · 2 ω_n / (η m ω_n²) = 4 ζ_e / η = 1, so Ω_onset = 2 ω_n; the study's default ω_ref
(the first shaft mode, ω_n here) would give 1.5 ω_n. Tolerance 1e-6: the design's shaft carries
0.01 kg/m³ × π/4 (0.02 m)² × 1 m = 3.1 mg under the 10 kg disk, so ω_n (and the onset with it)
is lower than the massless closed form's by ½ (17/35) 3.1e-6/10 = 7.6e-8 (Rayleigh's effective
mass of a pinned-pinned shaft at its middle), and the onset is solved to 1e-7 of the speed
between the analysed speeds (analyses/stability.py's regula falsi): ~2e-7 at most. CPU: about
0.1 s.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.thesis.whirl import shaft_stability
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import case_design

K, M, C_E, ETA = 75398.22368615503, 10.0, 8.683215054699211, 0.02


def test_the_viscous_study_uses_the_reference_frequency_it_is_given():
    design = case_design(case_by_id("jeffcott-rotating-damping-onset"))
    omega_n = math.sqrt(K / M)
    omega_ref = 2.0 * omega_n
    expected = omega_n * (1.0 + C_E * omega_ref / (ETA * K))
    assert expected == pytest.approx(2.0 * omega_n, rel=1e-6)  # 4 ζ_e / η = 1
    res = shaft_stability(
        design, np.linspace(0.0, 3.0 * omega_n, 31), "viscous", n_modes=2, reference_frequency=omega_ref
    )
    assert res.onset_speed == pytest.approx(expected, rel=1e-6)
