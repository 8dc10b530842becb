"""The Campbell core against closed forms: a fold at the first speed, a degenerate pair's whirl at
every speed, and the mode summary of hand-built roots.

References
----------
* The Jeffcott rotor of tests/rotors.py with a rotating-frame loss η and an external dashpot c_e:
  in r = v + i w its forward whirl solves ``m s² + c_e s + k(1 + iησ) = 0``, σ = sgn(ω − Ω)
  (tests/test_damping.py, tests/test_hysteretic_fold_reference.py derive it). The two branch
  roots are s₊ (σ = +1, stable) and ``s₋ = −c_e/m − s̄₊`` (σ = −1, Re s₋ ≈ (ηω_n − c_e/m)/2 > 0
  here): one damped frequency ω_d. At Ω = ω_d both are consistent (a fold), and the documented
  rule (:mod:`flexshaft.analyses.stability`, :func:`~flexshaft.analyses.continuation.mode_root`)
  keeps the **less stable**, s₋, so the verdict does not depend on which root a solver met first.
  Above ω_d the forward root is s₋; the backward whirl (seen at ω + Ω > 0 from the rotor) keeps
  s₊. So a Campbell diagram whose first speed is the fold reports {s₋, s₊} at both speeds.
* Without internal loss (η = 0) the Jeffcott rotor's disk equation ``m r̈ + c_e ṙ + k r = 0`` has
  no gyroscopic coupling (a point disk, I_p = 0; the tube's own split is 8.7e-9 relative at ω_n,
  below the labeller's 1e-8): the forward (r = e^{st}) and backward (r = e^{s̄t}, conjugate
  orbit) whirls share one eigenvalue at every speed, so each tracked mode of the pair is a
  circular whirl, one forward and one backward (whirl ratios +1 and −1), never the solver's
  arbitrary (planar or elliptic) combination of the two.
  At a single speed of rest the pair is exactly degenerate, and its labels are those of the
  circular whirls too (the Campbell diagram's and ``modes``'s).
* Heavy damping reorders |s| and Im s: the Jeffcott pair with ζ = 0.95 has Im s = 0.312 ω_n but
  |s| = ω_n, and a torsional mode of the disk (polar inertia J on the tube's half length L/2,
  held in twist at x = 0: ω_t = √(G J_p/(L/2)/J), set to 0.6 ω_n, undamped) lies between them.
  The modes are numbered and chosen by damped frequency Im s (:class:`~flexshaft.analyses.modal.Modes`,
  :func:`~flexshaft.analyses.eigen.lowest_modes`): the two lowest are the lateral pair, not the
  torsional mode that is lowest by |s|.
* The mode summary of hand-built curves s = −ζω_n + iω_n√(1 − ζ²): damped frequency ω_d/2π [Hz],
  log decrement δ = 2πζ/√(1 − ζ²), the speed of the smallest δ in rpm (60/2π per rad/s), modes
  numbered from 1 (the tables' numbering).

Tolerances: the Jeffcott roots 1e-4 relative as tests/test_campbell_jeffcott_reference.py (the
tube's mass, 3.5e-6 of the disk's, leaves ~1e-6); the whirl ratios 1e-6 (a circular orbit is ±1 up
to the tube's round-off); the hand-built summary 1e-12 (arithmetic only).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, WN, G, L, jeffcott, jeffcott_text

import flexshaft as fs
from flexshaft.analyses.campbell import Campbell, campbell, track_modes
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA = 0.02
C_E = 2 * 0.003 * M_DISK * WN


def test_a_fold_at_the_first_speed_keeps_the_less_stable_root():
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA)])
    s_plus = complex(roots[np.argmax(roots.imag)])  # σ = +1: the stable root
    s_minus = -C_E / M_DISK - np.conj(s_plus)  # σ = −1: destabilised by the loss
    model = jeffcott(ETA, C_E)
    red = reduce(model, 12)
    speed = s_minus.imag
    for _ in range(4):  # the model's fold speed (its ω_d differs from the closed form's by ~1e-6)
        s, _ = branch_roots(red, speed, branches(red, speed)[0].weights)
        speed = float(s[int(np.argmin(np.abs(s - complex(s_minus.real, speed))))].imag)
    diagram = campbell(model, np.array([speed, 1.05 * speed]), n_modes=2, basis_size=12)
    for row in diagram.eigenvalues:
        found = sorted(row, key=lambda z: z.real)
        assert found[0] == pytest.approx(s_plus, rel=1e-4)  # the backward whirl
        assert found[1] == pytest.approx(s_minus, rel=1e-4)  # the forward whirl: the less stable
    assert np.all(diagram.eigenvalues.real.max(axis=1) > 0)  # unstable from the fold on
    # At the fold s₊ and s₋ share Im s, so which of them the first speed's solve meets is a
    # last-digit matter (the kernels differ): started from the stable branch's roots only, the
    # tracked pair must still be {s₊, s₋}, the polish taking the less stable root itself.

    def stable_branch(x: float):
        roots, vectors = branch_roots(red, x, branches(red, x)[1].weights)
        keep = roots.imag > 0
        return roots[keep], vectors[:, keep]

    tracked = track_modes(model, red, np.array([speed]), 2, solve=stable_branch)
    found = sorted(tracked.eigenvalues[0], key=lambda z: z.real)
    assert found[0] == pytest.approx(s_plus, rel=1e-4) and found[1] == pytest.approx(s_minus, rel=1e-4)


def test_a_degenerate_pair_is_one_forward_and_one_backward_circular_whirl_at_every_speed():
    c_e = 2 * 0.05 * M_DISK * WN
    speeds = np.array([0.0, 0.5, 1.0]) * WN
    diagram = campbell(jeffcott(0.0, c_e), speeds, n_modes=2)
    s = complex(np.roots([M_DISK, c_e, K_SHAFT])[0])
    assert diagram.eigenvalues == pytest.approx(np.full((3, 2), complex(s.real, abs(s.imag))), rel=1e-4)
    for i in range(speeds.size):
        ratios = np.sort(diagram.whirl_ratios[i])
        assert ratios == pytest.approx([-1.0, 1.0], abs=1e-6)
        assert sorted(diagram.whirl[i]) == ["backward", "forward"]


def test_mode_summary_of_hand_built_curves():
    speeds = np.array([0.0, 100.0, 200.0])  # rad/s
    wn = np.array([[300.0, 500.0], [310.0, 480.0], [320.0, 460.0]])  # rad/s
    zeta = np.array([[0.05, 0.30], [0.02, 0.25], [0.04, 0.10]])
    s = -zeta * wn + 1j * wn * np.sqrt(1 - zeta**2)
    whirl = np.array([["forward", "backward"]] * 3)
    kind = np.array([["lateral", "lateral"], ["lateral", "lateral"], ["lateral", "torsional"]])
    curves = Campbell(speeds, s, whirl, np.zeros((3, 2)), (), kind)
    rows = curves.mode_summary()
    delta = 2 * np.pi * zeta / np.sqrt(1 - zeta**2)
    for m, row in enumerate(rows):
        k = int(np.argmin(zeta[:, m]))  # δ rises with ζ
        assert row[0] == m + 1
        assert row[1] == pytest.approx(wn[0, m] * np.sqrt(1 - zeta[0, m] ** 2) / (2 * np.pi), rel=1e-12)
        assert row[2] == pytest.approx(wn[-1, m] * np.sqrt(1 - zeta[-1, m] ** 2) / (2 * np.pi), rel=1e-12)
        assert row[3] == kind[-1, m]
        assert row[4] == whirl[-1, m]
        assert row[5] == pytest.approx(delta[k, m], rel=1e-12)
        assert row[6] == pytest.approx(speeds[k] * 60 / (2 * np.pi), rel=1e-12)
    assert curves.damping_ratios == pytest.approx(zeta, rel=1e-12)
    assert curves.log_decrements == pytest.approx(delta, rel=1e-12)


def test_a_degenerate_pair_at_rest_alone_is_labelled_by_whirl():
    model = jeffcott(0.0, 2 * 0.05 * M_DISK * WN)
    diagram = campbell(model, np.array([0.0]), n_modes=2)
    assert np.sort(diagram.whirl_ratios[0]) == pytest.approx([-1.0, 1.0], abs=1e-6)
    assert sorted(diagram.whirl[0]) == ["backward", "forward"]
    at_rest = fs.modes(model, 0.0, n_modes=2)
    assert np.sort(at_rest.whirl_ratios) == pytest.approx([-1.0, 1.0], abs=1e-6)
    assert sorted(at_rest.whirl) == ["backward", "forward"]


def heavily_damped_with_torsion_text(zeta: float = 0.95) -> str:
    """The Jeffcott rotor with a dashpot of damping ratio ``zeta`` and a disk polar inertia that
    puts its torsional mode at ω_t = √(G J_p/(L/2)/J) = 0.6 ω_n (module docstring)."""
    k_t = G * np.pi * (DO**4 - DI**4) / 32 / (L / 2)
    w_t = 0.6 * WN
    inertia = f"mass = 20.0\npolar_inertia = {k_t / w_t**2}"
    return jeffcott_text(0.0, 2 * zeta * M_DISK * WN).replace("mass = 20.0", inertia)


def test_heavily_damped_pair_is_tracked_before_a_mode_lower_by_modulus():
    zeta, w_t = 0.95, 0.6 * WN
    text = heavily_damped_with_torsion_text(zeta)
    diagram = campbell(build_model(loads_design(text)), np.array([0.0, 0.01 * WN]), n_modes=2)
    lateral = WN * complex(-zeta, np.sqrt(1 - zeta**2))
    assert abs(lateral) > w_t > lateral.imag  # |s| and Im s order the modes differently
    assert diagram.eigenvalues == pytest.approx(np.full((2, 2), lateral), rel=1e-4)
    assert diagram.kind is not None and np.all(diagram.kind == "lateral")
