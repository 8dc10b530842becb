"""The buckling solvers refuse a tube without a positive, finite radius or length.

Reference (derived here): a shell of revolution exists only for a mid-surface radius R > 0, and
the simply supported span only for a length L > 0; the torque-shear-flow relation
T = 2 pi R^2 N_xy and the axial Ritz integrals (L/2 over a span) are meaningless at R = 0 or
L <= 0. So R = 0, L = 0 and L < 0 (and an infinite L for the finite-length solver) are refused
by name, not turned into an inf, a nan or a negative-length integral; a regular tube next to
them (R = 0.05 m, L = 1 m) is accepted and gives finite matrices with a positive diagonal of K
(K is positive definite for a physical tube).

Cost: a 3-term Ritz model of one aluminium wall, a few milliseconds per call. The refusals are
exact; the finiteness checks need no tolerance.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.buckling import galerkin_matrices, infinite_cylinder_torque
from flexshaft.laminate import Lamina, Laminate

E, NU, T = 70e9, 0.33, 2e-3
WALL = Laminate([0.0], [T], Lamina.isotropic(E, E / (2 * (1 + NU)), 2700.0))


@pytest.mark.parametrize("theory", ["shear", "classical"])
def test_a_regular_tube_is_accepted(theory: str) -> None:
    K, G = galerkin_matrices(WALL, 0.05, 1.0, 2, 3, theory=theory)  # type: ignore[arg-type]
    assert np.all(np.isfinite(K)) and np.all(np.isfinite(G))
    assert np.all(np.diag(K).real > 0.0)


@pytest.mark.parametrize(
    ("radius", "length", "name"),
    [(0.0, 1.0, "radius"), (0.05, 0.0, "length"), (0.05, -1.0, "length"), (0.05, np.inf, "length")],
)
def test_a_degenerate_tube_is_refused(radius: float, length: float, name: str) -> None:
    with pytest.raises(ValueError, match=f"{name} must be positive and finite"):
        galerkin_matrices(WALL, radius, length, 2, 3)


def test_the_endless_tube_refuses_a_zero_radius() -> None:
    with pytest.raises(ValueError, match="radius must be positive and finite"):
        infinite_cylinder_torque(WALL, 0.0, n_max=3)
