"""Multi-objective design optimization of the driveline with the verdict as constraints.

>>> from flexshaft.design import baseline_design
>>> from flexshaft.optimize import DesignProblem, default_variables, optimize
>>> variables, layup = default_variables(baseline_design())
>>> problem = DesignProblem(variables, layup=layup)       # driveline mass and the smallest margin
>>> result = optimize(problem, budget=400, run_dir="opt", jobs=2)   # doctest: +SKIP
>>> result.pareto                                          # doctest: +SKIP
>>> files = result.write_designs()                         # doctest: +SKIP
>>> result.verify(files)                                   # doctest: +SKIP

The search is NSGA-II (Deb et al. 2002) from pymoo (the optional extra ``flexshaft[optimize]``)
driven ask-and-tell: pymoo proposes a generation, :func:`~flexshaft.optimize.store.evaluate_candidates`
evaluates it on the sweep engine (local processes or Dask), every
evaluation is stored in the run folder, and pymoo is told the objectives and constraints
(:func:`~flexshaft.optimize.problem.objectives_and_constraints`: constrained domination,
feasible designs first). The first generation is a Latin hypercube from ``seed`` with the base
design's own values as its first member when they lie within the bounds; integer variables are
rounded by a repair operator. Given the seed, the search is deterministic, so a run started again
on its folder asks for the same candidates and reads them back instead of evaluating them: an
interrupted run resumes, and a larger budget continues a finished one.

``method="random"`` evaluates ``budget`` uniformly random candidates through the same engine
(the benchmark's reference).
"""

from __future__ import annotations

import json
import time
import warnings
from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft import __version__
from flexshaft.files import atomic_write_text
from flexshaft.optimize.problem import DesignProblem, objectives_and_constraints
from flexshaft.optimize.result import OptimizationResult, pareto_mask
from flexshaft.optimize.store import EVALUATIONS, EvaluationCache, evaluate_candidates
from flexshaft.optimize.variables import OptimizeError

__all__ = ["MANIFEST", "optimize"]

MANIFEST = "problem.json"


# ------------------------------------------------------------------------------------------------
# The result


# ------------------------------------------------------------------------------------------------
# The search


def _import_pymoo():
    try:
        import pymoo  # noqa: F401
    except ImportError as exc:
        raise OptimizeError("the optimizer needs pymoo, an optional extra: pip install 'flexshaft[optimize]'") from exc
    try:  # pymoo 0.6.1 prints a hint about its compiled modules
        from pymoo.config import Config

        Config.warnings["not_compiled"] = False
        Config.show_compile_hint = False
    except (ImportError, AttributeError, TypeError):
        pass


def _open_run(run_dir: Path | None, spec: dict) -> EvaluationCache:
    if run_dir is None:
        return EvaluationCache(None)
    run_dir.mkdir(parents=True, exist_ok=True)
    manifest = run_dir / MANIFEST
    if manifest.exists():
        try:
            stored = json.loads(manifest.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise OptimizeError(f"{manifest}: unreadable ({exc}); use another run folder or delete it") from None
        if stored != spec:
            differ = sorted(k for k in set(stored) | set(spec) if stored.get(k) != spec.get(k))
            raise OptimizeError(
                f"run folder {run_dir} belongs to another optimization (it differs in "
                f"{', '.join(differ)}); use another folder (a larger budget alone may reuse it)"
            )
    else:
        atomic_write_text(manifest, json.dumps(spec, indent=2, sort_keys=True, default=repr) + "\n")
    return EvaluationCache(run_dir / EVALUATIONS)


def _stored_pop_size(run_dir: Path) -> int | None:
    """The population of the run already in ``run_dir`` (None if there is none or it is unreadable:
    :func:`_open_run` then reports the folder)."""
    try:
        stored = json.loads((run_dir / MANIFEST).read_text(encoding="utf-8")).get("pop_size")
    except (OSError, ValueError, AttributeError):
        return None
    return stored if isinstance(stored, int) and not isinstance(stored, bool) and stored >= 2 else None


def _latin_hypercube(rng: np.random.Generator, n: int, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    d = lower.size
    u = (np.argsort(rng.random((n, d)), axis=0) + rng.random((n, d))) / n
    return lower + u * (upper - lower)


def _round_integers(problem: DesignProblem, X: np.ndarray) -> np.ndarray:
    X = np.array(X, dtype=float)
    mask = problem.integer_mask
    if mask.any():
        X[:, mask] = np.round(X[:, mask])
    return X


def _initial_population(problem: DesignProblem, n: int, seed: int) -> np.ndarray:
    lower, upper = problem.bounds
    X = _latin_hypercube(np.random.default_rng(seed), n, lower, upper)
    base = problem.base_values()
    if base is not None:
        X[0] = [v.encode(base[v.name]) for v in problem.variables]
    return _round_integers(problem, X)


def optimize(
    problem: DesignProblem,
    budget: int,
    run_dir: str | Path | None = None,
    *,
    pop_size: int | None = None,
    seed: int = 1,
    jobs: int = 1,
    client: Any = None,
    method: str = "nsga2",
    references: Mapping[str, Any] | None = None,
    base_label: str = "base",
    progress: Callable[[str], None] | None = None,
) -> OptimizationResult:
    """Search the Pareto set of ``problem`` with at most ``budget`` design evaluations.

    Parameters
    ----------
    problem : DesignProblem
        Variables, objectives, constraints; validated against the design schema first.
    budget : int
        Evaluations the search may ask for (cached ones count too: a resumed run replays them).
    run_dir : path, optional
        Run folder (:mod:`flexshaft.optimize.store`); None keeps everything in memory.
    pop_size : int, optional
        NSGA-II population (default ``max(16, 4 × variables)``, at most a third of the budget).
    seed : int
        Seed of the initial population and of the search.
    jobs, client
        Local worker processes, or a Dask client / scheduler address (the sweep engine's).
    method : {"nsga2", "random"}
        NSGA-II, or uniform random sampling of the bounds (the benchmark's reference).
    references : mapping, optional
        Label -> Design evaluated too and marked on the figure (the base always is).
    base_label : str
        The base design's label in ``references`` and on the figure.
    progress : callable, optional
        Called with one line per generation.
    """
    if isinstance(budget, bool) or not isinstance(budget, (int, np.integer)) or budget < 1:
        raise OptimizeError(f"budget: must be a whole number of evaluations >= 1 (got {budget!r})")
    if method not in ("nsga2", "random"):
        raise OptimizeError(f"method: must be 'nsga2' or 'random' (got {method!r})")
    if isinstance(jobs, bool) or int(jobs) < 1:
        raise OptimizeError(f"jobs: must be >= 1 (got {jobs!r})")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise OptimizeError(f"seed: must be a whole number >= 0 (got {seed!r})")
    n_var = len(problem.variables)
    if pop_size is not None and not isinstance(pop_size, bool) and int(pop_size) > budget:
        # its first generation alone would not fit: pop_size = 1e8 with a budget of 4 sampled an
        # initial population growing by 170 MB/s before evaluating anything
        raise OptimizeError(
            f"pop_size: must be at most the budget ({budget:,} evaluations): a larger population cannot "
            f"finish its first generation (got {int(pop_size):,})"
        )
    if pop_size is None:
        # a resumed or extended run keeps the population it started with (the default depends on the budget)
        pop_size = _stored_pop_size(Path(run_dir)) if run_dir is not None and method == "nsga2" else None
    if pop_size is None:
        pop_size = int(max(4, min(max(16, 4 * n_var), budget // 3)))
    if isinstance(pop_size, bool) or int(pop_size) < 2:
        raise OptimizeError(f"pop_size: must be >= 2 (got {pop_size!r})")
    pop_size = int(pop_size)
    problem.validate()
    if method == "nsga2":
        _import_pymoo()
    start = time.perf_counter()
    run_path = Path(run_dir) if run_dir is not None else None
    spec = {**problem.spec(), "method": method, "seed": int(seed), "pop_size": pop_size if method == "nsga2" else None}
    cache = _open_run(run_path, spec)
    say = progress or (lambda line: None)
    log = _Log(problem)

    def evaluate(X: np.ndarray, generation: int) -> tuple[np.ndarray, np.ndarray]:
        values = [problem.values(x) for x in X]
        records, computed = evaluate_candidates(
            problem, [problem.overrides(v) for v in values], cache, run_path, jobs=jobs, client=client
        )
        log.add(records, values, generation, computed)
        F, G = log.last_FG
        say(log.line(generation, time.perf_counter() - start))
        return F, G

    if method == "random":
        lower, upper = problem.bounds
        X = _round_integers(problem, np.random.default_rng(seed).uniform(lower, upper, (budget, n_var)))
        evaluate(X, 0)
    else:
        _nsga2(problem, budget, pop_size, seed, evaluate)
    refs = {base_label: problem.base, **dict(references or {})}
    reference_outputs = {}
    for label, design in refs.items():
        ref_problem = replace(problem, base=design, fixed={})
        records, computed = evaluate_candidates(ref_problem, [{}], cache, run_path, jobs=1, client=client)
        log.computed += computed
        outputs = dict(records[0]["outputs"])
        row = [[outputs[n] for n in problem.output_names]]
        F, G = objectives_and_constraints(ref_problem, row, [records[0]["error"] is None])
        outputs.update(zip(problem.all_output_names, problem.with_derived(row)[0]))
        outputs["limiting_check"] = problem.limiting(row)[0]
        outputs["feasible"] = bool(np.all(G <= 0.0))
        reference_outputs[label] = outputs
    evaluations = log.dataset()
    pareto = _pareto_dataset(problem, evaluations)
    return OptimizationResult(
        problem, evaluations, pareto, reference_outputs, run_path, log.computed, time.perf_counter() - start
    )


def _nsga2(problem: DesignProblem, budget: int, pop_size: int, seed: int, evaluate) -> None:
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.evaluator import Evaluator
    from pymoo.core.problem import Problem
    from pymoo.core.repair import Repair
    from pymoo.problems.static import StaticProblem

    mask = problem.integer_mask

    class RoundIntegers(Repair):
        def _do(self, _problem, X, **kwargs):
            X = np.array(X, dtype=float)
            X[:, mask] = np.round(X[:, mask])
            return X

    lower, upper = problem.bounds
    search = Problem(
        n_var=lower.size, n_obj=len(problem.objectives), n_ieq_constr=len(problem.constraints) + 1, xl=lower, xu=upper
    )
    algorithm = NSGA2(
        pop_size=pop_size,
        sampling=_initial_population(problem, pop_size, seed),
        repair=RoundIntegers(),
        eliminate_duplicates=True,
    )
    with warnings.catch_warnings():  # pymoo 0.6.1 warns about its own deprecated properties
        warnings.simplefilter("ignore", DeprecationWarning)
        algorithm.setup(search, seed=int(seed), verbose=False)
    done, generation = 0, 0
    while done < budget:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            pop = algorithm.ask()
        if pop is None or len(pop) == 0:
            break
        if done + len(pop) > budget:
            pop = pop[: budget - done]
        state = np.random.get_state()  # pymoo 0.6.1 draws from the global generator
        F, G = evaluate(pop.get("X"), generation)
        np.random.set_state(state)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            Evaluator().eval(StaticProblem(search, F=F, G=G), pop)
            algorithm.tell(infills=pop)
        done += len(pop)
        generation += 1


class _Log:
    """Every evaluated candidate in order, with its generation."""

    def __init__(self, problem: DesignProblem) -> None:
        self.problem = problem
        self.records: list[dict] = []
        self.values: list[dict] = []
        self.generations: list[int] = []
        self.seen: set[str] = set()
        self.computed = 0
        self.last_FG = (np.zeros((0, 0)), np.zeros((0, 0)))
        self.best: dict[str, float] = {}

    def add(self, records, values, generation: int, computed: int) -> None:
        names = self.problem.output_names
        outputs = np.array([[r["outputs"][n] for n in names] for r in records], dtype=float).reshape(
            len(records), len(names)
        )
        F, G = objectives_and_constraints(self.problem, outputs, [r["error"] is None for r in records])
        self.last_FG = (F, G)
        self.computed += computed
        for r, v, f, g in zip(records, values, F, G):
            if r["key"] in self.seen:
                continue
            self.seen.add(r["key"])
            self.records.append(r)
            self.values.append(v)
            self.generations.append(generation)
            if np.all(g <= 0):
                for o, fi in zip(self.problem.objectives, f):
                    best = self.best.get(o.output)
                    self.best[o.output] = fi if best is None else min(best, fi)

    def line(self, generation: int, elapsed: float) -> str:
        n_feasible = sum(1 for r in self.records if _feasible(self.problem, r))
        best = ", ".join(
            f"{'max' if o.sense == 'max' else 'min'} {o.output} "
            f"{(-1 if o.sense == 'max' else 1) * self.best[o.output]:.5g}"
            for o in self.problem.objectives
            if o.output in self.best
        )
        return (
            f"generation {generation}: {len(self.records)} designs evaluated ({self.computed} computed), "
            f"{n_feasible} feasible{'; ' + best if best else ''}; {elapsed:.0f} s"
        )

    def dataset(self):
        import xarray as xr

        problem = self.problem
        names = problem.output_names
        n = len(self.records)
        outputs = np.array([[r["outputs"][k] for k in names] for r in self.records], dtype=float).reshape(n, len(names))
        valid = np.array([r["error"] is None for r in self.records], dtype=bool)
        F, G = objectives_and_constraints(problem, outputs, valid)
        violation = np.clip(G, 0.0, None).sum(axis=1) if n else np.zeros(0)
        data = {}
        for v in problem.variables:
            attrs = {
                "units": v.units,
                "long_name": v.name,
                "design_path": ", ".join(v.paths),
                "lower_bound": v.lower,
                "upper_bound": v.upper,
                "scale": "log" if v.log else "linear",
                "integer": int(v.integer),
            }
            dtype = np.int64 if v.integer else float
            data[v.name] = ("evaluation", np.array([val[v.name] for val in self.values], dtype=dtype), attrs)
        full = problem.with_derived(outputs) if n else np.zeros((0, len(problem.all_output_names)))
        for i, (name, units, long_name) in enumerate(problem.outputs + problem.derived_outputs):
            data[name] = ("evaluation", full[:, i], {"units": units, "long_name": long_name})
        if problem.constraints:
            limiting = np.array(problem.limiting(outputs) if n else [], dtype=str)
            data["limiting_check"] = (
                "evaluation",
                limiting,
                {"long_name": "the constraint with the smallest normalised margin (the one that limits)"},
            )
        data["feasible"] = (
            "evaluation",
            (violation <= 0).astype(np.int8),
            {"long_name": "1: valid design, every constraint met (not evaluated counts as violated)"},
        )
        data["constraint_violation"] = (
            "evaluation",
            violation,
            {"long_name": "sum of the constraint violations (normalised margins)"},
        )
        data["generation"] = ("evaluation", np.array(self.generations, dtype=np.int64), {"long_name": "generation"})
        data["overrides"] = (
            "evaluation",
            np.array([json.dumps(r["overrides"], sort_keys=True) for r in self.records], dtype=str),
            {"long_name": "design overrides of the base (JSON)"},
        )
        data["error"] = (
            "evaluation",
            np.array([r["error"] or "" for r in self.records], dtype=str),
            {"long_name": "why the design is invalid (empty: valid)"},
        )

        attrs = {
            "title": problem.name,
            "base_design": str(problem.base.name),
            "objectives": json.dumps([[o.output, o.sense] for o in problem.objectives]),
            "constraints": json.dumps(list(problem.constraints)),
            "layup_template": problem.layup or "",
            "fidelity": problem.fidelity,
            "flexshaft_version": __version__,
        }
        return xr.Dataset(data, coords={"evaluation": np.arange(n)}, attrs=attrs)


def _feasible(problem: DesignProblem, record: dict) -> bool:
    outputs = [[record["outputs"][n] for n in problem.output_names]]
    _, G = objectives_and_constraints(problem, outputs, [record["error"] is None])
    return bool(np.all(G <= 0))


def _pareto_dataset(problem: DesignProblem, evaluations):
    feasible = np.flatnonzero(np.asarray(evaluations["feasible"].values, dtype=bool))
    F = (
        np.column_stack(
            [
                np.asarray(evaluations[o.output].values, float)[feasible] * (-1.0 if o.sense == "max" else 1.0)
                for o in problem.objectives
            ]
        )
        if feasible.size
        else np.zeros((0, len(problem.objectives)))
    )
    members = feasible[pareto_mask(F)] if feasible.size else feasible
    first = problem.objectives[0]
    order = np.argsort(
        np.asarray(evaluations[first.output].values, float)[members] * (-1.0 if first.sense == "max" else 1.0),
        kind="stable",
    )
    members = members[order]
    pareto = evaluations.isel(evaluation=members).rename({"evaluation": "design"})
    pareto = pareto.assign_coords(design=np.arange(members.size))
    pareto["evaluation"] = ("design", members.astype(np.int64), {"long_name": "index in the evaluations"})
    pareto.attrs["title"] = f"{problem.name}: Pareto set"
    return pareto
