"""The wanted damped modes with their vectors solved only where read (hysteretic_roots.lowest_roots).

References (derived in tests/test_damping.py and the module docstring of
flexshaft.analyses.hysteretic_roots): on the Jeffcott-like rotor of tests/rotors.py, above the
spin (and at rest) both whirls of the disk mode solve the same equation
``m s² + c_e s + k(1 + iη) = 0``: a double root whose eigenspace is the whole (v, w) plane of the
disk. The two vectors returned must span that plane: a repeated vector (what inverse iteration
from one start gives two equal roots; ``_SEPARATED`` sends roots that close to the dense solve)
would not. Below the spin the forward whirl's loss changes sign and the pair splits. Every
returned pair (s, y) must satisfy its own branch's defining equation ``T(s) y = 0`` (a residual
check, independent of how y was found).

Tolerances: the model's disk root differs from the closed form by the tube's mass (7e-6 of the
disk's) and the mesh, 1e-4 relative as in tests/test_damping.py. Independence: the ratio of the
singular values of the two unit disk-plane vectors' 2 x 2 matrix is round-off (1e-16 times the
conditioning) for a repeated vector and of order one for a basis of the plane (the whirls of the
isotropic disk are orthogonal: about 1 here); 1e-6 separates the two. Residual:
a dense solve's root errs by about ε‖A‖ (ε = 2.2e-16, ‖A‖ the largest entry of the first-order
matrix: the tube's stiff modes), and inverse iteration leaves the vector's error at round-off,
so ‖T(s) y‖ stays below 1e-9 ‖T(s)‖ with margin. Small model (8 elements, 12 modes): each
solve is of a 24 x 24 matrix, well under a second in all.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branches, damped_modes, lowest_roots, on_branch

ETA = 0.02
C_E = 2 * 0.003 * M_DISK * WN


@pytest.fixture(scope="module")
def rotor():
    model = jeffcott(ETA, C_E)
    return model, reduce(model, 12)


def _disk_plane(model, red, Y):
    """The disk's (v, w) displacements of the modal coordinates ``Y`` (2, k)."""
    free = list(model.dofs.free)
    rows = [free.index(d) for d in disk_dofs(model)]
    return red.shapes(Y)[rows]


@pytest.mark.parametrize("speed_over_wn", [0.0, 0.5])
def test_the_double_root_above_the_spin_keeps_two_independent_vectors(rotor, speed_over_wn):
    model, red = rotor
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + 1j * ETA)])
    s_plus = roots[np.argmax(roots.imag)]
    speed = speed_over_wn * WN
    s, Y = damped_modes(red, speed, 2)
    assert np.all(np.abs(s - s_plus) <= 1e-4 * abs(s_plus))
    for vectors in (Y, lowest_roots(red, speed, 2)[1][:, :2]):
        plane = _disk_plane(model, red, vectors)
        plane = plane / np.linalg.norm(plane, axis=0)
        sv = np.linalg.svd(plane, compute_uv=False)
        assert sv[-1] >= 1e-6 * sv[0]


def test_every_vector_returned_solves_its_own_branch(rotor):
    model, red = rotor
    speed = 1.5 * WN  # supercritical: the disk modes below the spin, the tube's above it
    s, Y = lowest_roots(red, speed, 6)
    solved = np.flatnonzero(np.any(Y, axis=0))
    assert solved.size >= 6
    for k in solved:
        branch = next(b for b in branches(red, speed) if on_branch(b, s[k].imag, speed))
        T, _ = red.newton_terms(complex(s[k]), speed, branch.weights, Y[:, k])
        assert np.linalg.norm(T @ Y[:, k]) <= 1e-9 * np.linalg.norm(T, 2) * np.linalg.norm(Y[:, k])
