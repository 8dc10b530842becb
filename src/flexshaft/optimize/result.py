"""The result of an optimization: every evaluation, the Pareto front of the feasible designs, its
hypervolume, figure, design files and their re-verification.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft.design import with_overrides
from flexshaft.netcdf import write_netcdf
from flexshaft.optimize.files import verify_design_files, write_design_file
from flexshaft.optimize.problem import DesignProblem
from flexshaft.optimize.variables import OptimizeError
from flexshaft.plot.optimize import pareto_front

__all__ = ["OptimizationResult", "hypervolume", "pareto_mask"]


def pareto_mask(F: np.ndarray) -> np.ndarray:
    """True for the rows of ``F`` (n, m; minimised) that no other row dominates (duplicates
    of a non-dominated row are all kept)."""
    F = np.asarray(F, dtype=float)
    n = F.shape[0]
    keep = np.ones(n, dtype=bool)
    for i in range(n):
        dominates_i = np.all(F <= F[i], axis=1) & np.any(F < F[i], axis=1)
        keep[i] = not dominates_i.any()
    return keep


def hypervolume(F: np.ndarray, reference: Sequence[float]) -> float:
    """Hypervolume dominated by the rows of ``F`` (minimised) up to the ``reference`` point.

    Exact sweep for two objectives; pymoo's indicator for more.
    """
    F = np.asarray(F, dtype=float).reshape(-1, len(reference))
    ref = np.asarray(reference, dtype=float)
    F = F[np.all(F < ref, axis=1)]
    if F.size == 0:
        return 0.0
    if F.shape[1] == 1:
        return float(ref[0] - F[:, 0].min())
    if F.shape[1] == 2:
        F = F[pareto_mask(F)]
        F = F[np.argsort(F[:, 0])]
        widths = np.diff(np.append(F[:, 0], ref[0]))
        return float(np.sum(widths * (ref[1] - F[:, 1])))
    from pymoo.indicators.hv import HV

    return float(HV(ref_point=ref)(F))


@dataclass
class OptimizationResult:
    """What :func:`optimize` found.

    Attributes
    ----------
    problem : DesignProblem
    evaluations : xarray.Dataset
        Every candidate evaluated (dimension ``evaluation``): variable values, outputs,
        ``feasible``, ``constraint_violation``, ``generation``, ``overrides`` (JSON), ``error``.
    pareto : xarray.Dataset
        The feasible non-dominated candidates (dimension ``design``, sorted by the first
        objective), the same variables, and ``evaluation`` (index into ``evaluations``).
    references : dict
        Label -> outputs of the reference designs (the base first), evaluated the same way.
    run_dir : Path or None
    n_computed : int
        Evaluations computed by this call (the rest came from the run folder).
    elapsed : float
        Wall time of this call [s].
    """

    problem: DesignProblem
    evaluations: Any
    pareto: Any
    references: dict = field(default_factory=dict)
    run_dir: Path | None = None
    n_computed: int = 0
    elapsed: float = 0.0

    @property
    def objective_names(self) -> tuple[str, ...]:
        return tuple(o.output for o in self.problem.objectives)

    def __repr__(self) -> str:
        n = self.evaluations.sizes.get("evaluation", 0)
        feasible = int(self.evaluations["feasible"].sum()) if n else 0
        return (
            f"OptimizationResult({n} evaluations, {feasible} feasible, {self.pareto.sizes.get('design', 0)} "
            f"on the Pareto front; objectives {', '.join(self.objective_names)})"
        )

    def minimised(self, ds=None) -> np.ndarray:
        """Objectives of ``ds`` (default: the Pareto set) as minimised values (n, m)."""
        ds = self.pareto if ds is None else ds
        return (
            np.column_stack(
                [
                    np.asarray(ds[o.output].values, dtype=float) * (-1.0 if o.sense == "max" else 1.0)
                    for o in self.problem.objectives
                ]
            )
            if ds.sizes.get(_dim(ds), 0)
            else np.zeros((0, len(self.problem.objectives)))
        )

    def hypervolume(self, reference: Sequence[float]) -> float:
        """Hypervolume of the Pareto front in minimised objectives (maximised ones negated)."""
        return hypervolume(self.minimised(), reference)

    def plot(self, ax=None, x: str | None = None, y: str | None = None):
        """Pareto-front figure of two objectives (default the first two), every evaluation shown,
        the base and reference designs marked. Returns the matplotlib axes."""

        names = self.objective_names
        x = x or names[0]
        y = y or (names[1] if len(names) > 1 else names[0])
        objectives = {o.output: o for o in self.problem.objectives}
        ev, pa = self.evaluations, self.pareto

        def label(name: str) -> str:
            o = objectives.get(name)
            if o is not None and o.label:
                return o.label
            units = ev[name].attrs.get("units", "") if name in ev else ""
            return f"{name} [{units}]" if units else name

        refs = {
            k: (v.get(x, np.nan), v.get(y, np.nan), bool(v.get("feasible", False))) for k, v in self.references.items()
        }
        sense = (objectives[x].sense if x in objectives else "min", objectives[y].sense if y in objectives else "min")
        return pareto_front(
            np.asarray(ev[x].values, float),
            np.asarray(ev[y].values, float),
            np.asarray(ev["feasible"].values, bool),
            np.asarray(pa[x].values, float),
            np.asarray(pa[y].values, float),
            references=refs,
            x_label=label(x),
            y_label=label(y),
            senses=sense,
            title=self.problem.name,
            ax=ax,
        )

    def blocking_checks(self) -> list[dict]:
        """Which requirements reject the evaluated designs, one row per constraint.

        Each row: ``check`` (the verdict check key, or the output of a custom constraint),
        ``rejected`` (valid candidates it rejects: margin < 0 or not evaluated), ``alone`` (of
        them, those no other constraint rejects: the designs this check alone keeps out),
        ``not_evaluated``, ``best_margin`` (the largest normalised margin any valid candidate
        reached, NaN if it was never evaluated) and ``best_evaluation`` (its index in
        :attr:`evaluations`, −1 if none). Sorted by ``rejected``, most first. Candidates the
        schema refused or whose evaluation failed make one more row, ``valid design``, with
        ``rejected`` their count (they count in no check's row).
        """
        ev = self.evaluations
        n = ev.sizes.get("evaluation", 0)
        valid = np.array([not str(e) for e in ev["error"].values], dtype=bool) if n else np.zeros(0, bool)
        constraints = self.problem.constraints
        margins = (
            np.column_stack([np.asarray(ev[c].values, dtype=float) for c in constraints])
            if n and constraints
            else np.zeros((n, len(constraints)))
        )
        margins = margins[valid]
        fails = ~(margins >= 0.0)  # NaN: not evaluated, a violation
        rows: list[dict[str, Any]] = []
        for k, name in enumerate(constraints):
            column = margins[:, k]
            evaluated = ~np.isnan(column)  # +inf: a pass with nothing to measure (no phase crossover)
            best = (
                int(np.flatnonzero(valid)[np.flatnonzero(evaluated)[np.argmax(column[evaluated])]])
                if evaluated.any()
                else -1
            )
            rows.append(
                {
                    "check": name.removeprefix("margin_"),
                    "rejected": int(fails[:, k].sum()),
                    "alone": int((fails[:, k] & (fails.sum(axis=1) == 1)).sum()),
                    "not_evaluated": int((~evaluated).sum()),
                    "best_margin": float(column[evaluated].max()) if evaluated.any() else float("nan"),
                    "best_evaluation": best,
                }
            )
        rows.sort(key=lambda r: (-r["rejected"], -r["alone"]))
        if (~valid).any():
            rows.append(
                {
                    "check": "valid design",
                    "rejected": int((~valid).sum()),
                    "alone": int((~valid).sum()),
                    "not_evaluated": int((~valid).sum()),
                    "best_margin": float("nan"),
                    "best_evaluation": -1,
                }
            )
        return rows

    def write_designs(self, folder: str | Path | None = None, max_designs: int = 8) -> list[Path]:
        """Write Pareto designs as design files ``pareto_NN.toml`` (all of them, or
        ``max_designs`` spread evenly along the front, its ends included).

        Returns the paths, in Pareto order; the Pareto dataset gets their names (``file``).
        """

        if folder is None:
            if self.run_dir is None:
                raise OptimizeError("write_designs needs a folder (the optimization had no run folder)")
            folder = self.run_dir / "designs"
        folder = Path(folder)
        folder.mkdir(parents=True, exist_ok=True)
        for stale in folder.glob("pareto_*.toml"):  # an earlier, longer front's files must not linger
            stale.unlink()
        n = self.pareto.sizes.get("design", 0)
        picks = sorted(set(np.round(np.linspace(0, n - 1, min(n, max(int(max_designs), 1)))).astype(int))) if n else []
        paths = []
        files = [""] * n
        for rank, k in enumerate(picks, start=1):
            overrides = json.loads(str(self.pareto["overrides"].values[k]))
            summary = ", ".join(
                f"{o.output} {float(self.pareto[o.output].values[k]):.6g}" for o in self.problem.objectives
            )
            name = (
                f"flexshaft optimize: Pareto design {rank} of {len(picks)} ({summary}); from: {self.problem.base.name}"
            )
            design = with_overrides(self.problem.base, {**overrides, "name": name})
            comments = [
                f"flexshaft design file written by `flexshaft optimize` ({self.problem.name}).",
                f"Pareto design {rank} of {len(picks)} written ({n} on the front): {summary}.",
                f"Base design: {self.problem.base.name}",
                "Changed from the base (design paths, SI units, ply angles in degrees):",
                *[f"  {k} = {json.dumps(v)}" for k, v in overrides.items()],
                f"Evaluated at the {self.problem.fidelity!r} fidelity; re-verify with `flexshaft run --strict`.",
                "",
            ]
            path = write_design_file(
                design,
                folder / f"pareto_{rank:02d}.toml",
                comments,
                base=self.problem.base,
                base_text=self.problem.base_text,
            )
            paths.append(path)
            files[k] = path.name
        self.pareto["file"] = ("design", np.array(files, dtype=str), {"long_name": "design file written"})
        return paths

    def verify(self, paths: Sequence[str | Path], *, jobs: int = 1, client: Any = None):
        """Full ``flexshaft run`` verdict of written design files (see
        :func:`~flexshaft.optimize.files.verify_design_files`); the Pareto dataset gets
        ``verified`` (1 pass, 0 fail, −1 not written)."""

        ds = verify_design_files(paths, jobs=jobs, client=client)
        if "file" in self.pareto:
            passed = {Path(p).name: float(v) for p, v in zip(ds["design_file"].values, ds["passed"].values)}
            verified = np.array([passed.get(str(f), -1.0) for f in self.pareto["file"].values])
            self.pareto["verified"] = (
                "design",
                verified,
                {"long_name": "full-run verdict: 1 pass, 0 fail, -1 not verified"},
            )
        return ds

    def save(self, folder: str | Path | None = None) -> dict[str, Path]:
        """Write ``evaluations.nc``, ``pareto.nc`` and ``blocking_checks.json`` (the table of
        :meth:`blocking_checks`, non-finite margins as null) into ``folder`` (default: the run
        folder)."""

        folder = Path(folder) if folder is not None else self.run_dir
        if folder is None:
            raise OptimizeError("save needs a folder (the optimization had no run folder)")
        folder.mkdir(parents=True, exist_ok=True)
        blocking = folder / "blocking_checks.json"
        rows = [
            {k: (v if not isinstance(v, float) or np.isfinite(v) else None) for k, v in r.items()}
            for r in self.blocking_checks()
        ]
        blocking.write_text(
            json.dumps({"evaluations": int(self.evaluations.sizes.get("evaluation", 0)), "checks": rows}, indent=2)
            + "\n",
            encoding="utf-8",
        )
        return {
            "evaluations": write_netcdf(self.evaluations, folder / "evaluations.nc"),
            "pareto": write_netcdf(self.pareto, folder / "pareto.nc"),
            "blocking": blocking,
        }


def _dim(ds) -> str:
    return "design" if "design" in ds.dims else "evaluation"
