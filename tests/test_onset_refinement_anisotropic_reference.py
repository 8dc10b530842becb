"""Hysteretic whirl onset of an anisotropic overhung rotor: the forward synchronous crossing.

The rotor (built on the design text of tests/test_overhung_disk_whirl.py): a steel tube clamped
at x = 0, L = 0.5 m, 50 × 40 mm, Euler-Bernoulli elements (the default), a rigid disk at the
tip (m = 20 kg, I_d = 1.0, I_p = 0.9 kg m²) and a tip contact bearing k_v = 2e5, k_w = 2e6 N/m;
no damping anywhere but the shaft's hysteretic loss η in the rotating frame.

Reference (derived). The shaft's loss (flexshaft.analyses.loss) is i η K_lat (σ_B P_B + σ P_F)
on a whirl e^{iωt}: the forward circular part P_F of the motion turns at ω − Ω in the rotating
material and meets the loss sgn(ω − Ω) η, the backward part P_B always meets +η. Above the spin
(ω > Ω) every mode is damped. Below it (ω < Ω) the forward part's loss turns into an energy
input, so a mode whose shaft strain energy is mostly forward (E_F > E_B) gains energy ∝ η (E_F
− E_B) per cycle; with nothing in the fixed frame to damp it, it is unstable however small η is
(a backward-dominant mode, E_F < E_B, stays damped). The hysteretic loss does not fade as ω → Ω
(a sign, not ω − Ω), so the onset is a jump exactly where a forward-dominant mode's frequency
meets the spin: ω(Ω) = Ω. There the undamped model (η → 0) has the root s = iΩ, i.e. Ω is a
root of

    det(K − Ω² M + i Ω² G) = 0,

with per plane (tip deflection, tip slope) K = EI/L³ [[12 + k_b L³/EI, −6L], [−6L, 4L²]]
(massless clamped tube), M = diag(m, I_d), and G coupling the two slopes through I_p (G[sv, sw]
= I_p = −G[sw, sv]; for a circular forward whirl W = −iV this is the familiar +I_p Ω ω of the
forward tilt). Its roots below 2000 rad/s: 183.095, 322.1075, 597.167 and 1784.51 rad/s. With
the null vector x = (V, SV, W, SW) split into F = (V + iW)/2 and B = (V − iW)/2 (per plane,
deflection and slope), the shaft strain energies are E_F/E_B = 0.39, 2.89, 0.0026 and 1.5e6. So
183.1 (the soft plane's mode, falling with speed) and 597.2 (the backward tilt mode) cross the
line with backward-dominant whirl, which the circulatory loss damps (they stay stable);
322.1075 is the first forward-dominant crossing (the stiff plane's mode, rising with slope
dω/dΩ = 0.114): the onset. 1784.5 (the forward tilt mode) lies above it.

Tolerances. At finite η the backward part of the elliptical whirl is still damped on the line,
so the jump moves off the undamped crossing, but only at second order: for the undamped
gyroscopic mode s = iω, x, the left eigenvector is x^H, so a loss ΔK shifts s at first order by
−x^H ΔK x / x^H (2sM + ΩG) x, whose denominator is imaginary (G skew) and whose numerator is i
times real (K_lat commutes with S on the axisymmetric tube, so K_lat P_F, K_lat P_B are
Hermitian): a real shift, Re s only. Hence Ω*(η) = Ω₀ + c η² + O(η⁴) (the code at η = 0.05,
0.025, 0.0125 sits 5.8e-5, 1.45e-5, 3.5e-6 above Ω₀: ratios 4.0, 4.1). The test therefore
extrapolates η → 0 from η = 0.05 and 0.025, (4 Ω*(η/2) − Ω*(η))/3, and asserts it at 2e-6
relative: each onset is converged to 1e-7 of the speed (the refinement's stop), which the
extrapolation weighs by (4 + 1)/3; the tube's mass, 3.5e-5 kg = 1.8e-6 of the disk's (0.1 kg/m³
× π(D_o² − D_i²)/4 × L), lowers the frequency by at most half that by Rayleigh's quotient and
the crossing by that over (1 − dω/dΩ) = 0.89: ≤ 1.0e-6; the O(η⁴) remainder is of order (c
η²)², ~1e-9 (measured agreement ≤ 1.2e-7 on all three grids). The ratio (Ω*(η) − Ω₀)/(Ω*(η/2) −
Ω₀) must be 4, the η² law, to ± 0.3: a common offset ≤ 1.0e-6 (the tube's mass) on offsets of
5.8e-5 and 1.45e-5 moves it by ≤ 0.2, the 1e-7 convergence of each onset by ≤ 0.04.

The grids [0, 400], [0, 2000], [0, 3000, 4000] bracket the crossing between speeds far from it
(the refinement's regula falsi, starting from the mode's eigenvalue interpolated inside the
bracket, must follow the stiff plane's mode back from the unstable end: on the coarse brackets
a guess extrapolated away from that end loses it, and the onset falls back to the grid's
interpolation, 8 % and 40 % off). The wide brackets [0, 8000] and [0, 12000] (the model is
unstable at their top) hold the crossing mode's shape far from the unstable end's: there the
regula falsi once accepted roots of another mode whose MAC with it was only 0.43 (the
continuation's weak same-mode test, 0.25) and settled on a false jump, 428.0 and 509.5 rad/s
(the extrapolation 35 % and 61 % off), instead of following the mode down the bracket.
Measured: the extrapolation within 1.2e-7 of Ω₀ on all five grids. Ten stability runs of a
4-element model: 0.26 s (measured).

(The 6e-5 gap at η = 0.05 is this η² term, not the tube: the elements are Euler-Bernoulli, no
shear, and the tube's mass is 1.8e-6 of the disk's; a direct comparison at η = 0.05 would need
a tolerance from c, which only the code gives, hence the extrapolation.)
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

import flexshaft as fs
from flexshaft.analyses.stability import stability
from flexshaft.design import loads_design

E, G_SHEAR = 210e9, 80e9
DO, DI, L = 0.05, 0.04, 0.5
MASS, I_D, I_P = 20.0, 1.0, 0.9
K_V, K_W = 2e5, 2e6
EI = E * np.pi * (DO**4 - DI**4) / 64
ETA = 0.05


def design_text(eta: float) -> str:
    return f"""
name = "anisotropic overhung disk"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G_SHEAR}
density = 0.1
loss_factor = {eta}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
[[bearings]]
name = "tip"
kind = "contact"
x = {L}
stiffness = {{ v = {K_V}, w = {K_W} }}
[[disks]]
name = "disk"
x = {L}
mass = {MASS}
diametral_inertia = {I_D}
polar_inertia = {I_P}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 4
"""


def synchronous_matrix(speed: float) -> np.ndarray:
    """K − Ω² M + i Ω² G on (tip v, slope v, tip w, slope w) of the massless clamped tube."""
    tube = EI / L**3 * np.array([[12.0, -6.0 * L], [-6.0 * L, 4.0 * L**2]])
    K = np.zeros((4, 4))
    K[:2, :2] = tube + np.diag([K_V, 0.0])
    K[2:, 2:] = tube + np.diag([K_W, 0.0])
    M = np.diag([MASS, I_D, MASS, I_D])
    G = np.zeros((4, 4))
    G[1, 3], G[3, 1] = I_P, -I_P
    return K - speed**2 * M + 1j * speed**2 * G


def crossings(top: float) -> list[float]:
    """Speeds below ``top`` where a mode of the undamped rotor meets the spin (det = 0)."""

    def det(speed: float) -> float:
        return float(np.linalg.det(synchronous_matrix(speed)).real)  # real: G is skew

    grid = np.linspace(1.0, top, 2000)
    values = [det(speed) for speed in grid]
    return [
        brentq(det, grid[i], grid[i + 1], xtol=1e-12, rtol=1e-15)
        for i in range(grid.size - 1)
        if np.sign(values[i]) != np.sign(values[i + 1])
    ]


def forward_share(speed: float) -> float:
    """E_F/E_B of the tube's strain energy in the null vector of the synchronous matrix."""
    values, vectors = np.linalg.eig(synchronous_matrix(speed))
    x = vectors[:, np.argmin(np.abs(values))]
    tube = EI / L**3 * np.array([[12.0, -6.0 * L], [-6.0 * L, 4.0 * L**2]])
    forward, backward = (x[:2] + 1j * x[2:]) / 2, (x[:2] - 1j * x[2:]) / 2
    return float((forward.conj() @ tube @ forward).real / (backward.conj() @ tube @ backward).real)


def test_the_onset_is_the_first_forward_dominant_synchronous_crossing():
    roots = crossings(2000.0)
    assert len(roots) == 4
    shares = [forward_share(root) for root in roots]
    first = next(root for root, share in zip(roots, shares) if share > 1.0)
    assert first == roots[1]  # 183 rad/s crosses backward-dominant (E_F/E_B = 0.39)
    assert shares[0] < 0.5 and shares[1] > 2.0

    models = {eta: fs.build_model(loads_design(design_text(eta))) for eta in (ETA, ETA / 2)}
    for grid in ([0.0, 400.0], [0.0, 2000.0], [0.0, 3000.0, 4000.0], [0.0, 8000.0], [0.0, 12000.0]):
        onset = {}
        for eta, model in models.items():
            result = stability(model, np.array(grid), n_modes=4, damping_model="hysteretic")
            assert result.onset_kind == "oscillatory"
            onset[eta] = result.onset_speed
        extrapolated = (4.0 * onset[ETA / 2] - onset[ETA]) / 3.0
        assert extrapolated == pytest.approx(first, rel=2e-6), grid
        ratio = (onset[ETA] - first) / (onset[ETA / 2] - first)
        assert ratio == pytest.approx(4.0, abs=0.3), grid
