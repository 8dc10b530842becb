"""Following a mode across a gap of the hysteretic problem lands it on the synchronous line.

Reference (tests/test_stability.py): a forward mode's branch roots s₊ (the loss of the side above
the spin, ω > Ω) and s₋ (below it) differ by the shaft loss, their frequencies by O(η²)ω. Where
ω₊ < Ω < ω₋ (a *gap*) neither lies on its own side, and the mode's only eigenvalue sits on the
line: Im s = Ω (the loss sign set-valued at ω = Ω), its real part between Re s₊ and Re s₋.
s₊, s₋ are computed here by QZ on another linearisation (:func:`test_stability.pencil_roots`),
the gap speed by the fixed-point iteration of that test (the baseline with K_d = 200 N s/m has
a gap near 414-418 rad/s, its modes 8 and 9).

The continuation :func:`~flexshaft.analyses.continuation.mode_root` started from either
branch root must find that on-line eigenvalue (Newton's method on each branch reaches a root on
the wrong side of the line; the two straddle it the wrong way round, so the root is followed in
the loss between them): converged, Im s = Ω to the synchronous band (1e-9 relative) and Re s
between the branch roots' (with the QZ-against-QR tolerance 1e-7 |s| of the reference test).
One reduced model (48 modes) and a few 96 × 96 QZ solves.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_stability import ABOVE, BELOW, damped_baseline, pencil_roots

from flexshaft.analyses.continuation import mode_root
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches


def test_mode_root_follows_a_gap_mode_onto_the_synchronous_line():
    red = reduce(damped_baseline(), 48)
    speed = 430.0
    above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
    pairs = [(p, below[np.argmin(np.abs(below - p))]) for p in above if 0.5 * speed < p.imag < 2 * speed]
    pairs = [(p, q) for p, q in pairs if 1e-6 < abs(p.imag - q.imag) / p.imag < 1e-3 and abs(p - q) < 0.05 * abs(p)]
    gaps = 0
    for p, q in pairs:
        for _ in range(4):  # the speed between the pair's frequencies, which move with the speed
            speed = 0.5 * (p.imag + q.imag)
            above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
            p, q = above[np.argmin(np.abs(above - p))], below[np.argmin(np.abs(below - q))]
        if not p.imag < speed < q.imag:
            continue  # a fold: both roots are eigenvalues (the fold test's subject)
        gaps += 1
        tol = 1e-7 * abs(p)
        lower, upper = branches(red, speed)
        for branch, target in ((upper, p), (lower, q)):
            s, Y = branch_roots(red, speed, branch.weights)
            k = int(np.argmin(np.abs(s - target)))
            assert abs(s[k] - target) <= tol
            root, _, ok = mode_root(red, speed, s[k], Y[:, k])
            assert ok
            assert root.imag == pytest.approx(speed, rel=1e-9)
            assert min(p.real, q.real) - tol <= root.real <= max(p.real, q.real) + tol
    assert gaps >= 1
