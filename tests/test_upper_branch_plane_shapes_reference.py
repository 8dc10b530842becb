"""The shapes of the roots above the spin on the upper branch: one plane each (derived here).

Reference (derived). The Jeffcott rotor of tests/rotors.py (20 kg midspan disk, near-massless
pinned-pinned tube of stiffness k, loss factor η, no dashpot) with a bearing stiffness
k_v = 0.3 k at the disk in v only. Above the spin the rotating-frame loss has the weights
(i, i, 0) of :func:`~flexshaft.analyses.loss.frequency_coefficients` (module docstring of
:mod:`flexshaft.analyses.hysteretic_roots`): the loss stiffness is i η K', with no circulatory
term, so nothing couples the two bending planes (isotropic tube, a bearing in v only, a disk
without polar inertia). Each disk root on that side is then a single plane's:
``m s² + k(1 + iη) + k_plane = 0`` with k_plane = 0 (w) or k_v (v), and its shape has no
displacement of the disk in the other plane. (Below the spin the weights (i, 0, 1) add the
circulatory K_lat S (= η K′ S, real), which does couple the planes: a vector of that problem leans
|w|/|v| ~ 0.2 into the other plane at η = 0.05, measured, which is what the assertion tells
apart.)

At Ω = 0.5 ω_n both disk roots (ω ≈ 1.0 and 1.14 ω_n) lie above the spin, inside the band
Ω <= Im s < 3 Ω of :func:`~flexshaft.analyses.hysteretic_roots.consistent_values_below` with
``up_to = 3``, whose vectors are solved there by inverse iteration on the upper branch's
problem. Tolerances: the roots against the closed form at 1e-5 relative (the tube's 3.5e-6 of
the disk's mass, as in tests/test_shared_newton_factor_reference.py); the other plane's share
of the disk displacement below 1e-5 (the tube's gyroscopic coupling, 3.5e-6 of the mass times
the speed ratio, leaves 1.5e-8 measured; the coupled problem's 0.2 is 2e4 times the bound).

The modes of :func:`~flexshaft.analyses.hysteretic_roots.damped_modes` at the same speed, at
η = 0.3 (where the lower branch's problem at an upper root is far from singular: a vector of it
is no shape of the upper problem): the two lowest are the two planes' roots, distinct
(1.011 and 1.148 ω_n, closed form), each with its own plane's shape, same tolerances (the
tube's coupling leaves 1.7e-8 measured).
CPU: a 24-DOF model on a 6-mode basis, a few hundredths of a second.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott_text

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import consistent_values_below, damped_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA = 0.05
K_V = 0.3 * K_SHAFT


def _rotor(eta: float):
    text = jeffcott_text(eta, 0.0, elements=4).replace("stiffness = {}", f"stiffness = {{ v = {K_V} }}")
    return build_model(loads_design(text))


def _plane_root(eta: float, k_plane: float) -> complex:
    """The root with Im s > 0 of m s² + k(1 + iη) + k_plane = 0 (module docstring)."""
    roots = np.roots([M_DISK, 0.0, K_SHAFT * (1 + 1j * eta) + k_plane])
    return complex(roots[np.argmax(roots.imag)])


def _check_plane(model, red, s, Y, eta: float, speed: float) -> None:
    """Both planes' disk roots among ``s`` at their closed forms, each shape in its own plane."""
    v, w = disk_dofs(model)
    for k_plane, own, other in ((0.0, w, v), (K_V, v, w)):
        want = _plane_root(eta, k_plane)
        assert speed < want.imag
        k = int(np.argmin(np.abs(s - want)))
        assert s[k] == pytest.approx(want, rel=1e-5)
        assert np.linalg.norm(Y[:, k]) == pytest.approx(1.0, rel=1e-12)
        shape = np.zeros(model.dofs.size, complex)
        shape[model.dofs.free] = red.Phi @ Y[:, k]
        assert abs(shape[own]) > 0
        assert abs(shape[other]) < 1e-5 * abs(shape[own])


def test_band_roots_above_the_spin_move_the_disk_in_their_own_plane_only():
    """Each disk root of the band above the spin is its plane's closed-form root, and its unit
    modal shape moves the disk in that plane only (module docstring)."""
    model = _rotor(ETA)
    red = reduce(model, 6)
    speed = 0.5 * WN
    s, Y = consistent_values_below(red, speed, up_to=3.0)
    assert all(_plane_root(ETA, k).imag < 3 * speed for k in (0.0, K_V))
    _check_plane(model, red, s, Y, ETA, speed)


def test_damped_modes_above_the_spin_are_the_two_planes_roots():
    """damped_modes' two lowest modes: the two planes' distinct roots, each in its own plane
    (module docstring), at η = 0.3."""
    eta = 0.3
    model = _rotor(eta)
    red = reduce(model, 6)
    speed = 0.5 * WN
    s, Y = damped_modes(red, speed, 2)
    assert abs(_plane_root(eta, K_V) - _plane_root(eta, 0.0)) > 0.1 * WN
    _check_plane(model, red, s, Y, eta, speed)
