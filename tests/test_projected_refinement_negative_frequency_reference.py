"""A refinement on a projected loop model that lands at a negative frequency is redone on full
solves (analyses/local_projection.py, ``projected_refinements``).

Reference (the definition of the margins): the loop margins are read on the Nyquist half-axis
ω ≥ 0 of L(iω); a crossover or peak frequency below zero is no result of the loop, whatever
value a model gives there. A projected model that answers with one has "gone astray" and the
refinement is repeated on the full model (the module's docstring: "then on the full model, as
is one whose projected model gives no finite frequency").

Stand-ins, no physics of the driveline: one root task whose steps ask L at ω = 2 rad/s and
return ω = +2 when L there is positive, −2 otherwise; a projected model with T = −1/2, so
L = T/(1 − T) = −1/3 (worked by hand); a full model with L = +1 on ω ≥ 0 and, standing in for
the same wrong branch, −1/3 below zero (so a check made there would agree with the projected
value to the last bit). The refinement must end on full solves at (2, 1) exactly. CPU < 1 ms.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.local_projection import RefinementTask, projected_refinements


class _Astray:
    """A projected model whose closed loop is T = −1/2 everywhere; it cannot be enriched."""

    def closed(self, omegas, intervals):
        return np.full(len(omegas), -0.5 + 0j)

    def enriched(self, intervals, columns):
        raise np.linalg.LinAlgError("stand-in")


def _steps():
    L = yield 2.0
    return (2.0 if L.real > 0 else -2.0), L


def _full(omegas, tasks, keep=None):
    omegas = np.asarray(omegas, dtype=float)
    values = np.where(omegas < 0, -1.0 / 3.0, 1.0) + 0j
    if keep is not None:
        keep.extend(np.zeros(3, dtype=complex) for _ in omegas)
    return values


def test_a_projected_result_below_zero_frequency_is_refined_on_full_solves():
    task = RefinementTask(kind="root", lo=0, hi=1, start=_steps, role="gain")
    (result,) = projected_refinements([task], _full, lambda windows, tasks: _Astray(), [[0, 1]])
    assert result == (2.0, 1.0 + 0j)
