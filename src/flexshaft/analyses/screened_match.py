r"""The match of the tracked curves to every root at a speed, with the vectors of the few it can pick.

When the continuation of the tracked modes cannot be trusted at a speed (a shape changed too
much, a mode lost), :func:`~flexshaft.analyses.campbell.track_modes` solves every eigenvalue
there and matches the previous speed's curves to them: the cost :func:`match_cost` of each
pair (1 − MAC of the shapes plus a tenth of the relative frequency distance), an optimal
assignment of distinct roots, whose usual case is each curve's own cheapest root.
With the hysteretic loss that solve was :func:`~flexshaft.analyses.hysteretic_roots.consistent_roots`:
a dense eigen-solve of each branch with every eigenvector, for the MAC of every root.

:func:`screened_match` gives the same match from the vectors of a few roots. Each branch is
solved without its vectors (``solved_below`` of :mod:`flexshaft.analyses.hysteretic_roots`:
R(Ω) with the vectors of the roots below the spin and on the line, which its pairing solves
anyway); the roots of the upper branch up to :data:`_BAND` times the largest previous |s| get
theirs by inverse iteration (``separated_vectors``). Those are the *candidates*: each curve's
cheapest candidate is its match when

* the curves' cheapest candidates are distinct (the assignment's usual case; else None: the
  caller solves every vector), and
* no other root can cost a curve as little: for each root left out (an upper-branch root above
  the spin, whose unit null vector y of T(s) is bounded componentwise from the root alone,
  :func:`~flexshaft.analyses.hysteretic_roots.mac_bounds`), ``1 − min(1, 2 b²) + 0.1 Δω/ω``,
  with b the bound of ``|yᴴ v|`` for the curve's previous shape v, exceeds the curve's cheapest
  candidate's cost. The factor of two covers a dense solve's vector that mixes two nearly double
  roots and the roots' round-off, as in the pairing's ``_may_pair``. Else None.

Then every root's cost is at least the cheapest candidate's, strictly, so each curve's cheapest
root over all roots is that candidate (the first of equal ones, in the same order): the match of
the dense solve with every vector, up to the round-off in which the two solves' roots and
vectors differ (each match is refined by Newton's method afterwards). On the tuned design's
whirl tracking (56 basis vectors) at 37.7 rad/s: 2 dense solves without vectors and about 20
inverse iterations instead of 2 dense solves with every vector.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.eigen import ReducedModel
from flexshaft.analyses.hysteretic_roots import (
    branches,
    consistent_from,
    mac_bounds,
    on_branch,
    separated_vectors,
    solved_below,
)

__all__ = ["mac", "match_cost", "screened_match"]

#: The upper-branch roots up to this factor times the largest |s| of the previous curves get their
#: vectors (the candidates); the others are excluded by the bound of their MAC, or the caller
#: solves every vector.
_BAND = 2.0


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Modal assurance criterion |aᴴb|² of unit columns (a: (n, p), b: (n, q)) → (p, q)."""
    return np.abs(a.conj().T @ b) ** 2


def _distance(lam_prev: np.ndarray, lam: np.ndarray) -> np.ndarray:
    """A tenth of the frequency distance (curves, roots), relative to each curve's frequency."""
    scale = np.maximum(np.abs(lam_prev.imag)[:, None], 1e-12)
    return 0.1 * np.abs(lam_prev.imag[:, None] - lam.imag[None, :]) / scale


def match_cost(lam_prev: np.ndarray, Y_prev: np.ndarray, lam: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """Cost (curves, roots) of matching the previous curves (eigenvalues ``lam_prev``, unit shapes
    ``Y_prev``) to roots ``lam`` (unit shapes ``Y``): 1 − MAC plus a tenth of the frequency
    distance relative to the curve's frequency."""
    return 1 - mac(Y_prev, Y) + _distance(lam_prev, lam)


def screened_match(
    red: ReducedModel, speed: float, lam_prev: np.ndarray, Y_prev: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Every hysteretic eigenvalue at ``speed`` and the match of the previous curves to them
    (module docstring): ``(s, Y, index)``, R(Ω) sorted by |s| as
    :func:`~flexshaft.analyses.hysteretic_roots.consistent_roots` gives it (zero columns of Y for
    roots left out), and the root of each curve; None when the match needs every vector (or the
    problem has no two branches: rotating loss at a speed > 0)."""
    parts = branches(red, speed)
    if not red.has_loss or len(parts) != 2 or lam_prev.size == 0:
        return None
    lower, upper = parts
    solved, every = solved_below(red, speed, lower, upper)
    s, Y = consistent_from(red, speed, solved)
    if s.size < lam_prev.size:
        return None
    missing = np.flatnonzero(~np.any(Y, axis=0) & (np.abs(s) <= _BAND * np.abs(lam_prev).max()))
    vectors = separated_vectors(red, speed, upper.weights, every, s[missing])
    if vectors is None:
        return None
    Y[:, missing] = vectors
    have = np.any(Y, axis=0)
    candidates, rest = np.flatnonzero(have), np.flatnonzero(~have)
    cost = match_cost(lam_prev, Y_prev, s[candidates], Y[:, candidates])
    best = np.argmin(cost, axis=1)
    if np.unique(best).size != best.size:
        return None
    if rest.size:
        if not np.all(on_branch(upper, s[rest].imag, speed) & (s[rest].imag >= speed)):
            return None  # only the upper branch's roots above the spin are left without a vector
        bound = mac_bounds(red, speed, upper.weights, s[rest], Y_prev)
        if bound is None:
            return None
        # (curves, rest): the least each root can cost, its MAC at most min(1, 2 b²)
        lowest = 1 + _distance(lam_prev, s[rest]) - np.fmin(1.0, 2 * bound.T**2)
        if not np.all(lowest > cost[np.arange(best.size), best][:, None]):
            return None
    return s, Y, candidates[best]
