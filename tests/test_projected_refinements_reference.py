"""``projected_refinements`` (:mod:`flexshaft.analyses.local_projection`) on closed-form loops.

Two refinements whose answers are known by hand, run with a "projected model" that is exact
(it returns T = L/(1 + L) of the same analytic L as the "full model"):

* a crossover |L| = 1 of the integrator L(iω) = c/(iω), c = 7 rad/s, between 2 and 20 rad/s:
  the root is ω = c, where L = −i; there dL/d ln ω = −L and d²L/d ln ω² = L (by hand);
* a sensitivity peak of the real loop L = 1/S − 1 with S = 1 + exp(−(ln ω − ln 5)²): the peak
  is at ω = 5 rad/s with |S| = 2.

Since the projected model is exact, every refinement passes its check on the first round: each
costs exactly one full solve (the module's contract: the projected result is checked by one
full solve at its frequency), and the values kept are the full model's. The derivatives handed
to ``settle`` are central differences of step h = 1e-5 in ln ω: truncation h²/6 |L'''| ≈ 2e-11
and round-off 1e-16/h = 1e-11 relative for the slope (rtol 1e-8), round-off 4e-16/h² = 4e-6
for the curvature (rtol 1e-4). The root is refined to 1e-8 ω (rtol 1e-7), the peak to 1e-6 in
ln ω (atol 2e-6) where |S| is flat to second order (rtol 1e-10). CPU: a few milliseconds.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.local_projection import RefinementTask, golden_maximum, illinois_root, projected_refinements

C = 7.0  # the integrator's crossover [rad/s]


def _integrator(omega):
    return C / (1j * np.asarray(omega, dtype=float))


def _peaked(omega):
    return 1.0 / (1.0 + np.exp(-((np.log(np.asarray(omega, dtype=float)) - np.log(5.0)) ** 2))) - 1.0 + 0j


LOOPS = (_integrator, _peaked)


def _loop(omegas, tasks):
    return np.array([LOOPS[int(t)](w) for w, t in zip(omegas, tasks)], dtype=complex)


class ExactLocal:
    """A projected model equal to the full one (closed-loop T = L/(1 + L) of each task's L)."""

    def closed(self, omegas, intervals):
        L = _loop(omegas, intervals)
        return L / (1.0 + L)

    def enriched(self, intervals, columns):
        raise np.linalg.LinAlgError("not needed: the exact model passes every check")


def _tasks():
    magnitude = lambda L: abs(L) - 1.0  # noqa: E731
    sensitivity = lambda L: abs(1.0 / (1.0 + L))  # noqa: E731
    a, b = 2.0, 20.0
    root = RefinementTask(
        "root", 0, 1, lambda: illinois_root(magnitude, a, b, _integrator(a), _integrator(b), 1e-8 * C), "gain"
    )
    peak = RefinementTask("peak", 0, 1, lambda: golden_maximum(sensitivity, np.log(2.0), np.log(20.0), 1e-6))
    return [root, peak]


def _run():
    solved: list[float] = []
    settled: dict = {}

    def evaluate(omegas, tasks, keep=None):
        solved.extend(omegas)
        if keep is not None:
            keep.extend(np.zeros(3, dtype=complex) for _ in omegas)
        return _loop(omegas, tasks)

    def settle(tasks, omegas, full, slope, curvature, accepted):
        settled.update(tasks=tasks, omegas=omegas, full=full, slope=slope, curvature=curvature, accepted=accepted)
        return np.zeros(len(tasks), dtype=bool)

    results = projected_refinements(_tasks(), evaluate, lambda windows, active: ExactLocal(), [[0], [0]], settle)
    return results, solved, settled


def test_each_refinement_costs_one_full_solve_and_finds_the_closed_form():
    (root, peak), solved, settled = _run()
    assert len(solved) == 2 and list(settled["accepted"]) == [True, True]
    omega, L = root
    assert abs(omega - C) <= 1e-7 * C
    np.testing.assert_allclose(L, _integrator(omega), rtol=1e-14)
    assert abs(peak[0] - np.log(5.0)) <= 2e-6
    np.testing.assert_allclose(peak[1], 2.0, rtol=1e-10)


def test_the_derivatives_given_to_the_release_rule_are_those_of_the_loop():
    _, _, settled = _run()
    first = list(settled["tasks"]).index(0)
    L = _integrator(settled["omegas"][first])
    np.testing.assert_allclose(settled["full"][first], L, rtol=1e-14)
    np.testing.assert_allclose(settled["slope"][first], -L, rtol=1e-8)
    np.testing.assert_allclose(settled["curvature"][first], L, rtol=1e-4)
