"""The passive every-root check's basis schedule stays within its stated cap.

Reference (API contract: the function's docstring, flexshaft.analyses.root_stability.
_passive_bases; no hand-written doc states this cap): the first basis twice as many modes as lie
below the top speed, n (at least 16), the lowest max(n, 8) of them enriched with their static
corrections, "then both doubled while the basis holds at most four times the plain modal basis
of the modes below the top speed, 4·max(4n, 60) vectors", ending with every mode only when the
model has no more free DOFs than that. The cap counts the basis's vectors, modes plus
corrections. (docs/model.md's "4 · max(4n, 60) for `modes`" is not this rule: `modes` and
tracked_to_accuracy count their caps in modes alone, and the docstring's "the bound of
tracked_to_accuracy" is loose too, that one being 4 · max(4n, 40) modes.) Passing the cap costs
time and changes the basis reported, nothing else: the roots are then a larger basis's.

Derived here for n = 15 modes below the top speed and 1000 free DOFs: the cap is
4 · max(60, 60) = 240 vectors; the bases (modes, corrections) are (30, 15), (60, 30), (120, 60),
holding 45, 90 and 180 vectors; the next doubling (240, 120) would hold 360 > 240, and the whole
model (1000 > 240) is not tried. Exact integers: compared exactly. The schedule reads only the
model's free-DOF count and the modal basis's squared frequencies, given here directly (15
frequencies 10, 20, ..., 150 rad/s below a top speed of 155 rad/s, 45 more above).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.analyses import root_stability


def test_passive_bases_hold_at_most_four_times_the_plain_basis():
    n_free = 1000
    model = SimpleNamespace(dofs=SimpleNamespace(free=np.arange(n_free)))
    modes = SimpleNamespace(w2=(10.0 * np.arange(1, 61)) ** 2)
    n_below = 15
    assert int(np.sum(np.sqrt(modes.w2) < 155.0)) == n_below
    cap = 4 * max(4 * n_below, 60)
    bases = root_stability._passive_bases(model, modes, 155.0)
    assert bases == [(30, 15), (60, 30), (120, 60)]
    assert all(size + enrich <= cap for size, enrich in bases)
