"""The cap on the roots above the spin solved with the loss counts confirmed-unstable roots only.

Reference (derived in tests/test_root_stability_lagged_magnet_reference.py): the Jeffcott rotor
with a stiffness k_v in v only and a magnetic bearing whose proportional law passes an amplifier
lag; each plane's disk root with the hysteretic loss above the spin solves the cubic
(m s² + k(1 + iη) + k_plane)(1 + s/ω_a) + k_p = 0, and its first-order value is
s₀ + Δs, Δs = −iηk/f'(s₀). The module docstring's rule (step 3): the roots above the spin that
the first-order shift does not settle are solved with the loss, least stable first, until
:data:`~flexshaft.analyses.root_stability.MAX_SOLVED_UNSTABLE` of them are *confirmed unstable*;
the rest keep their first-order value (``refined`` False).

With the cap lowered to one (monkeypatched) the two planes tell the rule apart:

* η = 0.2, k_p = 0.3 k: both roots unsettled by the first-order shift (half of it leaves them
  unstable) and both stable when solved: none is confirmed unstable, so both are solved, and
  each is its exact cubic root (2.6e-3 to 3.0e-3 |s| from s₀ + Δs, 1e-5 asserted: the tube's
  mass and mesh leave 8e-7, measured in the lagged-magnet test);
* η = 0.02, k_p = 0.2 k: both roots unstable with the loss: the first solved is confirmed, so
  the second keeps its first-order value (refined False), 3e-5 |s| from the exact root at this
  small η (closed forms above: asserted > 2e-5), told from it at 5e-6 (the model's 8e-7 mesh
  error, six times below), and the solved one is the exact root (1e-5).
"""

from __future__ import annotations

import pytest
from rotors import K_SHAFT
from test_root_stability_lagged_magnet_reference import K_V, SPEED, first_order, lagged_rotor, nearest, plane_root

from flexshaft.analyses import root_stability as rs


def test_roots_the_loss_stabilises_do_not_use_up_the_solve_cap(monkeypatch):
    """η = 0.2, k_p = 0.3 k, cap 1: no root is confirmed unstable, so both are solved exactly."""
    monkeypatch.setattr(rs, "MAX_SOLVED_UNSTABLE", 1)
    eta, kp = 0.2, 0.3 * K_SHAFT
    result = rs.root_stability(lagged_rotor(eta, kp), [SPEED])
    assert result.method == "full" and result.stable
    for k in (0.0, K_V):
        s0, settled, exact = plane_root(0.0, kp, k), first_order(eta, kp, k), plane_root(eta, kp, k)
        assert s0.real > 0 and exact.real < 0
        assert abs(settled - exact) > 1e-3 * abs(exact)
        assert nearest(result.roots[0], exact) == pytest.approx(exact, rel=1e-5)


def test_the_solve_cap_stops_after_the_confirmed_unstable_roots(monkeypatch):
    """η = 0.02, k_p = 0.2 k, cap 1: both roots unstable with the loss; one is solved (exact,
    refined) and the other keeps its first-order value (refined False)."""
    monkeypatch.setattr(rs, "MAX_SOLVED_UNSTABLE", 1)
    eta, kp = 0.02, 0.2 * K_SHAFT
    result = rs.root_stability(lagged_rotor(eta, kp), [SPEED])
    assert len(result.unstable) == 2
    refined = [r for r in result.unstable if r.refined]
    estimated = [r for r in result.unstable if not r.refined]
    assert len(refined) == len(estimated) == 1
    exact = {k: plane_root(eta, kp, k) for k in (0.0, K_V)}
    settled = {k: first_order(eta, kp, k) for k in (0.0, K_V)}
    solved_plane = min(exact, key=lambda k: abs(exact[k] - refined[0].root))
    other = K_V if solved_plane == 0.0 else 0.0
    assert refined[0].root == pytest.approx(exact[solved_plane], rel=1e-5)
    assert abs(settled[other] - exact[other]) > 2e-5 * abs(exact[other])
    assert estimated[0].root == pytest.approx(settled[other], rel=5e-6)
