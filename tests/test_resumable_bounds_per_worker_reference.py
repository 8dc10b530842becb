"""The bounds of a study sweep and of optimize's verification runs, counted by hand.

References (docs/limits.md, section 7 "The work of a command"; flexshaft.cli.bounds docstrings):

* A ``study`` sweep keeps its finished work and resumes: it is refused "above 4 hours per
  worker". Its points are shared among the workers, each point one model of the design, so with
  a stand-in model of t = 10 s a point, P points on w workers take P t / w: 2,000 points are
  20,000 s (5.6 h, refused) on one worker and 5,000 s (1.4 h, accepted) on four.
* ``optimize --verify`` runs in one go the full runs of the design files it writes, "at most
  ``--designs``" (docs/limits.md) and at most one per evaluation (API contract, check_verification's
  docstring; no docs page states it): count =
  min(designs, budget), time count × t / w against the 10-minute one-go limit. With t = 10 s:
  --designs 3 of a budget of 100,000 is 30 s on one worker; --designs 10 of a budget of 4 is
  40 s; 3 designs on 2 workers 15 s.

Stand-in model sizes, no analysis (< 0.1 s). The times are products and quotients of small
integers and 10.0: exact in binary floating point up to one rounding, compared with rel=1e-12.
The limits asked are docs/limits.md's numbers, 4 hours (4 * 3600.0 s) and 10 minutes (600.0 s),
not the module's constants.
"""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from flexshaft.cli import bounds
from flexshaft.cli.bounds import MAX_SECONDS, check_sweep, check_verification
from flexshaft.cli.common import UserError

POINT = SimpleNamespace(time_seconds=10.0, memory_bytes=1.0, free_dofs=100, shaft_nodes=2)


def test_a_sweep_is_bounded_per_worker(monkeypatch) -> None:
    monkeypatch.setattr(bounds, "_model_size", lambda design: POINT)
    with pytest.raises(UserError, match="allowed: 4 h"):
        check_sweep(None, "study two-angle", 2000, 1)  # 20,000 s on one worker
    check_sweep(None, "study two-angle", 2000, 4)  # 5,000 s a worker: accepted

    asked = []
    monkeypatch.setattr(bounds, "_refuse_if_large", lambda what, s, m, change, limit, per: asked.append((s, limit)))
    check_sweep(None, "study two-angle", 100, 4)
    assert asked[0][0] == pytest.approx(100 * 10.0 / 4, rel=1e-12)
    assert asked[0][1] == 4 * 3600.0  # docs/limits.md: 4 hours per worker


@pytest.mark.parametrize(
    "designs, budget, workers, seconds", [(3, 100_000, 1, 30.0), (10, 4, 1, 40.0), (3, 100_000, 2, 15.0)]
)
def test_verification_counts_at_most_designs_and_at_most_the_budget(
    monkeypatch, designs, budget, workers, seconds
) -> None:
    import flexshaft.assembly.size as size

    monkeypatch.setattr(size, "problem_size", lambda design, analysis, resolution: POINT)
    asked = []

    def record(what, s, memory, change, limit=MAX_SECONDS, per_worker=""):
        asked.append((s, limit))

    monkeypatch.setattr(bounds, "_refuse_if_large", record)
    check_verification(None, designs, budget, workers)
    assert asked[0][0] == pytest.approx(seconds, rel=1e-12)
    assert asked[0][1] == 600.0  # docs/limits.md: 10 minutes
