"""Roots above the spin that are stable without the loss: reported at their loss-free value.

The rule (docs/requirements.md, *The stability checks*): the every-root check solves "every root
of the closed-loop first-order system" "... and the hysteretic loss where it can move a root
across the axis"; above the spin the loss only damps (the module docstring of
flexshaft.analyses.root_stability, step 3: "A root above the spin that is stable without the
loss is stable with it"), so such a root is reported loss-free (``RootStability.roots``: "loss-free
otherwise (the roots above the spin that are stable without the loss)"): a lower bound of its
damping, exact for the loss-free loop, never a first-order estimate of extra damping.

Reference (derived, as in tests/test_root_stability_lagged_magnet_reference.py). The Jeffcott
rotor of tests/rotors.py (disk m, shaft stiffness k, loss factor η = 0.02, external damper c_e at
the disk) with a bearing stiffness k_v in v only (the planes' roots differ) and a magnetic bearing
whose proportional law passes an amplifier lag (force −k_p d/(1 + s/ω_a), k_s = 0): a model with
controller states, so the full check (no passive argument). The disk has no tilt at midspan, so
each plane is one degree of freedom whose loss-free root solves the cubic

    (m s² + c_e s + k + k_plane)(1 + s/ω_a) + k_p = 0,      k_plane = k_v or 0.

With k_p = 0.02 k and ω_a = 2π·500 rad/s the lag's negative damping (about k_p/ω_a = 12 N s/m)
is below c_e = 40 N s/m: both roots stable without the loss (ζ ≈ 2.3e-3), at about ω_n, above the
spin Ω = ω_n/2. With the loss (i η k above the spin) the same cubic's root lies 0.9-1 % of |s|
away (ηω_n/2 ≈ 3 /s more damping), so the loss-free value is told from any loss-shifted one.

The disk's axial mode is a neutral root of the loss-free loop (no damper acts in u): the tube,
held axially at its start only, is an axial spring k_ax = E A/(L/2) under the disk, so
s = i sqrt(k_ax/m) (3853 rad/s), on the axis without the loss and above the spin: it too is
reported loss-free, on the axis, where the loss's first-order shift would give it ζ = η/2 = 0.01.

Tolerance: the tube's mass (3.5e-6 of the disk's) and the 4-element mesh leave the model's disk
roots within 1e-6 of the single-degree-of-freedom ones (measured 8.6e-7); 1e-5 is asserted,
a thousandth of the loss's shift. The axial root's real part is asserted within 1e-4 |s|
(0.4 /s), a hundredth of the loss's shift ηω_ax/2 = 38.5 /s and above the dense solve's
worst round-off ε‖A‖ ≈ 2.2e-16 × (1.7e7 rad/s)² ≈ 0.06 /s (measured 3e-10 /s).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, WN, E, L, jeffcott_text

from flexshaft.analyses.root_stability import root_stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, C_E = 0.02, 40.0
K_V = 0.1 * K_SHAFT
K_P = 0.02 * K_SHAFT
F_A = 500.0  # amplifier bandwidth [Hz]
W_A = 2 * np.pi * F_A
SPEED = 0.5 * WN


def damped_lagged_rotor():
    text = jeffcott_text(ETA, C_E, elements=4).replace("stiffness = {}", f"stiffness = {{ v = {K_V} }}")
    magnet = (
        f'[[bearings]]\nname = "amb"\nkind = "active"\nx = {L / 2}\nkp = {K_P}\nkd = 0.0\nks = 0.0\nki = 1.0\n'
        f"amplifier_bandwidth = {F_A}\n\n[[disks]]"
    )
    return build_model(loads_design(text.replace("[[disks]]", magnet)))


def plane_root(eta: float, k_plane: float) -> complex:
    """The oscillatory root (Im s > 0) of the plane's cubic, with loss η k above the spin."""
    cubic = np.polyadd(np.polymul([M_DISK, C_E, K_SHAFT * (1 + 1j * eta) + k_plane], [1 / W_A, 1.0]), [K_P])
    roots = np.roots(cubic)
    return complex(roots[np.argmax(roots.imag)])


def test_stable_disk_roots_above_the_spin_are_reported_loss_free():
    """Each plane's disk root is its loss-free cubic root to 1e-5, 1 % from the lossy one."""
    result = root_stability(damped_lagged_rotor(), [SPEED])
    assert result.method == "full"
    assert result.stable
    roots = result.roots_at(SPEED)
    for k_plane in (0.0, K_V):
        free, lossy = plane_root(0.0, k_plane), plane_root(ETA, k_plane)
        assert free.real < 0 and free.imag > SPEED  # stable without the loss, above the spin
        assert abs(lossy - free) > 5e-3 * abs(free)  # the loss's shift is resolvable
        nearest = complex(roots[np.argmin(np.abs(roots - free))])
        assert nearest == pytest.approx(free, rel=1e-5)


def test_the_neutral_axial_root_above_the_spin_stays_on_the_axis():
    """The disk's axial root: i sqrt(E A/(L/2) / m) to 1e-5, |Re s| <= 1e-4 |s| (loss-free)."""
    result = root_stability(damped_lagged_rotor(), [SPEED])
    axial = 1j * np.sqrt(E * np.pi * (DO**2 - DI**2) / 4 / (L / 2) / M_DISK)
    roots = result.roots_at(SPEED)
    nearest = complex(roots[np.argmin(np.abs(roots - axial))])
    assert nearest.imag == pytest.approx(axial.imag, rel=1e-5)
    assert abs(nearest.real) <= 1e-4 * abs(axial)
