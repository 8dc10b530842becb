"""Solutions of sparse linear systems checked against singularity by iterative refinement.

A stiffness singular to working precision (an unsupported rigid-body motion) leaves a pivot of
round-off size, ε‖K‖, instead of an exact zero, and its solution grows as 1/ε (up to 2e12 m for
100 N on a free-free driveline) without any error from the factorisation. A pivot that small is
also what a regular but ill-conditioned system has (a shaft on soft springs, a fine mesh). The
rule of the banded harmonic solver (:mod:`flexshaft.analyses.banded`) tells them apart:
iterative refinement contracts by about κ·ε a step on a regular matrix and not at all on a
singular one.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from flexshaft.analyses.banded import FORWARD_ERROR_LIMIT, REFINEMENT_STEPS

__all__ = ["checked_solve", "refined"]


def checked_solve(A, b: np.ndarray) -> np.ndarray | None:
    """Solution of ``A x = b`` (columns), or None when ``A`` is singular to working precision.

    Rank check against the conditioning: ``A`` is equilibrated (rows, then columns, scaled to
    a largest entry of 1, so that stiffness rows of 1e15 N/m and the unit rows of an
    integrating actuator's constraint weigh alike), factorised, and iterative refinement must
    converge both on the loads and on a random probe, which no singular matrix's range
    contains: on a regular matrix refinement contracts by about κ·ε a step, on a singular one
    its corrections stay of order one (the rule of the banded harmonic solver).
    """
    A = sp.csr_matrix(A)
    rows = np.asarray(abs(A).max(axis=1).todense()).ravel()
    if not np.all(rows > 0):
        return None
    scaled = sp.diags(1.0 / rows) @ A
    cols = np.asarray(abs(scaled).max(axis=0).todense()).ravel()
    if not np.all(cols > 0):
        return None
    scaled = (scaled @ sp.diags(1.0 / cols)).tocsc()
    try:
        lu = spla.splu(scaled)
    except RuntimeError:
        return None
    probe = np.random.default_rng(0).standard_normal((b.shape[0], 1))
    if refined(scaled, lu, probe) is None:
        return None
    y = refined(scaled, lu, b / rows[:, None])
    return None if y is None else y / cols[:, None]


def refined(A, lu, b: np.ndarray) -> np.ndarray | None:
    """Solution of ``A x = b`` (columns) by the factor ``lu`` and iterative refinement, or None
    when the corrections do not contract to :data:`~flexshaft.analyses.banded.FORWARD_ERROR_LIMIT`
    (``A`` singular to working precision; the rule of the banded harmonic solver)."""
    x = lu.solve(b)
    previous = np.inf
    for _ in range(REFINEMENT_STEPS):
        dx = lu.solve(b - A @ x)
        if not (np.all(np.isfinite(x)) and np.all(np.isfinite(dx))):
            return None
        x = x + dx
        change = float(np.max(np.linalg.norm(dx, axis=0) / np.maximum(np.linalg.norm(x, axis=0), np.finfo(float).tiny)))
        if change <= FORWARD_ERROR_LIMIT:
            return x
        if change > 0.5 * previous:
            return None
        previous = change
    return None
