"""A wide fold of the hysteretic problem: the whirl onset at the less stable root's own frequency.

Reference (derived here). A 20 kg tip disk on a near-massless steel tube (length L, a cantilever
whose root is guided: its slope held, its translation free, so the tube is the spring
k = 3EI/L³ between the two ends; Euler-Bernoulli elements, exact for a tip load) over a 50 kg
pedestal disk at the root, held to the ground by a spring k₂ = 2k and a dashpot c₂ = 10⁴ N s/m
in both lateral directions. The tube's loss factor is η = 0.4 with the rotating-frame loss; no
disk has polar inertia, so nothing depends on the speed Ω but the side of the synchronous line.

In complex coordinates r = v + i w (tip r₁, root r₂) a forward whirl r ∝ e^{st}, ω = Im s > 0,
meets the tube's force k(1 + iησ)(r₁ − r₂), σ = sgn(ω − Ω) (the rotating material sees ω − Ω:
:mod:`flexshaft.analyses.loss`, Genta 2005 §4.6), so each side of the line is the quartic

    (m₁s² + k_σ)(m₂s² + c₂s + k₂ + k_σ) − k_σ² = 0,    k_σ = k(1 + iησ),

and a backward whirl meets k(1 + iη) at every speed (its rotating-frame frequency ω + Ω > 0): the
σ = +1 quartic. The eigenvalues at Ω, R(Ω) as :mod:`flexshaft.analyses.hysteretic_roots` defines
them, are each quartic's roots on their own side, σ = +1 for Im s ≥ Ω and σ = −1 for Im s ≤ Ω,
plus, for a mode with no root on its own side (a *gap*), its root on the line Im s = Ω of the
quartic with k(1 + iημ), μ ∈ [−1, 1] (found here by bisection on μ).

Why this rotor. The heavy, uneven damping (the dashpot under the pedestal only, against the
tube's loss) makes the modes complex, so the tube's loss moves a root's frequency at first order
in η, not at O(η²) as on a rotor whose two branch roots mirror each other (the Jeffcott rotor:
s₋ = −c/m − s̄₊, one frequency). The upper mode's branch roots are s₊ ≈ −95.5 + 264.7i
(σ = +1) and s₋ ≈ 9.7 + 247.4i (σ = −1, unstable): a fold 17 rad/s wide, a sixth of their
distance |s₊ − s₋| ≈ 107 rad/s. For 247.4 < Ω < 264.7 both are eigenvalues and the mode is
unstable (a fold keeps its less stable root); below 247.4 only s₊ is, and every other root is
stable (asserted): the whirl onset is Ω* = Im s₋ exactly, where s₋ turns consistent. A
continuation arriving from below on s₊ that kept it without solving the σ = −1 side once s₊ lay
more than a tenth of its distance above the line (the code's first-order estimate of the
distance, about 93 rad/s here) would miss s₋ for 247.4 < Ω < 264.7 − 9.3 and report the onset
late (measured by an independent review: 255.4 rad/s with the single step's factor changed to a
tenth, 250.0 with the batched step's, instead of 247.37). (A mode with a root on its own
side has no on-line root in R(Ω): the quartic with −1 ≤ μ < −0.83 has roots with Re s > 0 down
to Im s = 246.0, which that convention does not count.)

Tolerances: the quartics' roots by numpy.roots are exact to round-off (about 1e-12 relative); the
tube's mass (3.5e-5 kg against 70 kg of disks) moves the model's roots by about 1e-6 relative
(measured 8e-8 at the onset) and the onset refinement stops within 1e-7 of the speed: the onset is
checked to 1e-5 relative (2.5e-3 rad/s, over 1000 times below the 2.6-8 rad/s a late fold
acceptance makes), each damping ratio to 1e-5 absolute (the roots agree to 1e-6 relative; the on-line
root's frequency is held to the synchronous band, 1e-9 relative, its real part to that times
|dRe s/dIm s| along μ, about 0.3 at 150 rad/s). One 4-mode stability run on an 8-vector basis,
about 0.25 s of CPU.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

E, DO, DI, LENGTH = 210e9, 0.05, 0.04, 0.5
K = 3 * E * np.pi * (DO**4 - DI**4) / 64 / LENGTH**3  # the guided cantilever's tip stiffness [N/m]
M1, M2, K2, C2, ETA = 20.0, 50.0, 2 * K, 1.0e4, 0.4
SPEEDS = np.linspace(0.0, 300.0, 31)  # 10 rad/s apart: 250 and 260 inside the fold

TEXT = f"""
name = "tip disk on a damped pedestal"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = 0.1
loss_factor = {ETA}
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "theta", "beta", "gamma"]
[[bearings]]
name = "pedestal"
kind = "contact"
x = 0.0
stiffness = {{ v = {K2}, w = {K2} }}
damping = {{ v = {C2}, w = {C2} }}
[[disks]]
name = "pedestal"
x = 0.0
mass = {M2}
[[disks]]
name = "tip"
x = {LENGTH}
mass = {M1}
[operating]
speed_rpm = 0.0
power = 0.0
[analysis]
internal_damping = "rotating"
[mesh]
shaft_elements = 4
"""


def quartic_roots(mu: float) -> np.ndarray:
    """Roots with Im s > 0 of (m₁s² + k_μ)(m₂s² + c₂s + k₂ + k_μ) − k_μ² = 0, k_μ = k(1 + iημ),
    sorted by Im s (μ = σ on either side of the line)."""
    k = K * (1 + 1j * ETA * mu)
    poly = np.polymul([M1, 0.0, k], [M2, C2, K2 + k])
    poly[-1] -= k * k
    r = np.roots(poly)
    r = r[r.imag > 0]
    return r[np.argsort(r.imag)]


def on_line_root(speed: float) -> complex:
    """The lower mode's root on the line Im s = Ω: the μ where the frequency of the quartic's
    lower root crosses Ω (one crossing on a 41-point grid of μ ∈ [−1, 1], asserted), by bisection."""
    mus = np.linspace(-1.0, 1.0, 41)
    above = np.array([quartic_roots(mu)[0].imag > speed for mu in mus])
    crossings = np.flatnonzero(above[:-1] != above[1:])
    assert crossings.size == 1
    a, b = mus[crossings[0]], mus[crossings[0] + 1]
    for _ in range(50):
        mu = 0.5 * (a + b)
        if (quartic_roots(mu)[0].imag > speed) == above[crossings[0]]:
            a = mu
        else:
            b = mu
    return complex(quartic_roots(0.5 * (a + b))[0])


def reference_eigenvalues(speed: float) -> np.ndarray:
    """R(Ω): the backward whirls (σ = +1, both modes), each forward mode's roots on their own
    side, and the lower mode's on-line root in its gap."""
    up, down = quartic_roots(+1.0), quartic_roots(-1.0)
    out = list(up)  # backward whirl
    for mode in range(2):  # forward whirl; index 0 the lower mode on both sides (disjoint bands)
        consistent = [s for s in (up[mode],) if s.imag >= speed] + [s for s in (down[mode],) if s.imag <= speed]
        out += consistent if consistent else [on_line_root(speed)]
    return np.array(out)


def zeta(s):
    return -np.real(s) / np.abs(s)


@pytest.fixture(scope="module")
def result():
    return stability(build_model(loads_design(TEXT)), SPEEDS, n_modes=4, basis_size=8)


def test_the_reference_rotor_has_a_wide_unstable_fold():
    """The premises of the module docstring, from the quartics alone."""
    up, down = quartic_roots(+1.0), quartic_roots(-1.0)
    assert up.size == down.size == 2
    assert np.all(up.real < 0)  # above the line (and every backward whirl): stable
    assert down[0].real < 0 < down[1].real  # below it only the upper mode's root is unstable
    s_plus, s_minus = up[1], down[1]
    assert s_minus.imag < s_plus.imag  # a fold, 17 rad/s wide
    assert s_plus.imag - s_minus.imag > 0.1 * abs(s_plus - s_minus)
    assert up[0].imag < down[0].imag < s_minus.imag  # the lower mode's gap lies below the fold
    for mu in np.linspace(-1.0, 1.0, 41):  # its on-line roots: stable along the whole gap
        lower = quartic_roots(mu)[0]
        assert lower.real < 0 and lower.imag < 0.7 * s_minus.imag


def test_the_whirl_onset_is_the_folds_less_stable_root_frequency(result):
    """Ω* = Im s₋ of the σ = −1 quartic, to 1e-5 relative; unstable mode a forward whirl."""
    onset = quartic_roots(-1.0)[1].imag
    assert result.onset_speed == pytest.approx(onset, rel=1e-5)
    assert "forward" in result.onset_description()


def test_every_speed_reports_the_least_damping_of_its_eigenvalues(result):
    """The smallest damping ratio at each grid speed is that of R(Ω), the fold's less stable
    root at 250 and 260 rad/s (ζ = −0.039), below 247.4 the mode's s₊ alone."""
    for speed, margin in zip(SPEEDS, result.stability_margin):
        assert margin == pytest.approx(zeta(reference_eigenvalues(speed)).min(), abs=1e-5)
    inside = (SPEEDS > quartic_roots(-1.0)[1].imag) & (SPEEDS < quartic_roots(+1.0)[1].imag)
    assert np.count_nonzero(inside) == 2
    assert np.all(result.stability_margin[inside] < -0.03)
