"""The one recipe that judges a design: :func:`assess` and its :class:`Assessment`.

``assess(design, resolution)`` analyses the design at each of its operating points
(:func:`~flexshaft.verdict.operating_point.analyse_point`), gathers the evidence each
requirement needs (:func:`~flexshaft.verdict.gather.gather_evidence`), checks it against the
design's ``[requirements]`` (:func:`~flexshaft.verdict.checks.evaluate`) and combines the points
(:func:`~flexshaft.verdict.envelope.envelope_verdict`): every check at every point, the worst
one and where.

The operating points: a design without an ``[envelope]`` is judged at its own operating point
(its ``[operating]`` speed and power, its materials at their reference temperature). With one,
at each of its points (cold day, standard day, hot-soak start, ...), each the design at that
point (:func:`flexshaft.thermal.envelope.point_conditions`,
:func:`flexshaft.design.points.design_at_point`). What only the report shows (modes at rest,
the Campbell diagram, the strength's load shares, the thermal sweeps) is computed once, at the
governing point (:func:`~flexshaft.verdict.envelope.governing_point`); the checks do not read it.

``flexshaft run`` (at :data:`~flexshaft.resolution.REPORT`), the optimizer (at its fidelity),
``flexshaft compare`` and ``flexshaft check`` (its size estimate counts the same
:class:`~flexshaft.resolution.Resolution` and points) all go through it, so one design at one
resolution is judged identically by each.

>>> import flexshaft as fs
>>> a = fs.assess(fs.baseline_design(), fs.SCREENING)    # doctest: +SKIP
>>> a.verdict.summary, a.governing_point, [p.name for p in a.points]  # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
import html
from collections.abc import Callable
from concurrent.futures import Executor
from dataclasses import dataclass

from flexshaft.analyses.guards import RefusedInputError
from flexshaft.assembly.size import check_problem_size
from flexshaft.design import Design, DesignError, Problem
from flexshaft.design.points import design_at_point
from flexshaft.parallel.threads import single_blas_thread
from flexshaft.resolution import REPORT, Resolution
from flexshaft.thermal.envelope import PointConditions, point_conditions
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.gather import gather_evidence
from flexshaft.verdict.operating_point import PointAnalyses, add_campbell, add_report_detail, analyse_point
from flexshaft.verdict.result import Verdict

__all__ = [
    "Assessment",
    "PointAssessment",
    "assess",
    "assess_point",
    "check_point",
    "combine_points",
    "envelope_problems",
]


@dataclass(frozen=True, kw_only=True)
class Assessment(PointAnalyses):
    """A design judged at its operating points, SI units. Frozen: computed once.

    ``design`` is the design assessed. The other fields of :class:`PointAnalyses` (the model, the
    modes, Campbell diagram, spin-up response, critical speeds, strength, buckling, metal
    strength, coupling misalignment, bearing reactions, thermal results, whirl stability,
    every-root check, torsional dynamics, bearing loops, the point's conditions and the notes)
    are those of the governing point, with what only the report shows (the design at that
    point is ``model.design``); ``evidence`` is that point's.

    Attributes
    ----------
    evidence : Evidence
        The governing point's evidence.
    verdict : Verdict
        Every check at every point: the worst value and where (its location's ``"point"``
        names the envelope point; none without an ``[envelope]``).
    points : tuple of PointAssessment
        Each operating point's analyses, evidence and verdict, in the envelope's order (one,
        named ``"operating point"``, without an ``[envelope]``).
    governing_point : str
        The point of the tightest check, whose analyses the fields above are.
    """

    evidence: Evidence
    verdict: Verdict
    points: tuple[PointAssessment, ...]
    governing_point: str

    def point(self, name: str) -> PointAssessment:
        """The operating point called ``name``."""
        for p in self.points:
            if p.name == name:
                return p
        raise KeyError(name)

    def __repr__(self) -> str:
        where = f", governed by {self.governing_point}" if len(self.points) > 1 else ""
        return (
            f"Assessment({self.design.name!r} at the {self.resolution.name} resolution{where}: {self.verdict.summary})"
        )

    def _repr_html_(self) -> str:
        """The design, the verdict headline and table (:meth:`Verdict._repr_html_`), the
        analyses it holds and the notes."""
        rpm = rad_s_to_rpm(self.operating_speed)
        fields = [f.name for f in dataclasses.fields(PointAnalyses) if getattr(self, f.name) is not None]
        analyses = [n for n in fields if n not in ("design", "resolution", "model", "notes")]
        points = (
            f"; {len(self.points)} operating points, analyses shown at {html.escape(self.governing_point)}"
            if len(self.points) > 1
            else ""
        )
        parts = [
            f"<p><b>{html.escape(self.design.name)}</b><br>assessed at {rpm:.0f} rpm, "
            f"{html.escape(self.resolution.name)} resolution{points}</p>",
            self.verdict._repr_html_(),
            '<p style="font-size:smaller">analyses: '
            + html.escape(", ".join(f".{n}" for n in (*analyses, "evidence")))
            + "; the table: .to_dataframe()</p>",
        ]
        parts += [f'<p style="font-size:smaller">note: {html.escape(note)}</p>' for note in self.notes]
        return "".join(parts)

    def to_dataframe(self):
        """The verdict's checks (:meth:`Verdict.to_dataframe`; pandas imported there)."""
        return self.verdict.to_dataframe()


def _judged(name: str, analyses: PointAnalyses) -> PointAssessment:
    evidence = gather_evidence(analyses)
    return PointAssessment(
        name=name, analyses=analyses, evidence=evidence, verdict=evaluate(evidence, analyses.design.requirements)
    )


def check_point(a: Assessment, key: str) -> str:
    """The name of the operating point where check ``key`` governs: its location's ``"point"``
    (the governing point when the check names none or the verdict has no such check). What a
    report section shows for one check is drawn there."""
    try:
        return str(a.verdict.check(key).location.get("point", a.governing_point))
    except KeyError:
        return a.governing_point


@single_blas_thread
def assess(
    design: Design,
    resolution: Resolution = REPORT,
    *,
    executor: Executor | None = None,
    progress: Callable[[str], None] | None = None,
) -> Assessment:
    """Analyse ``design`` at ``resolution`` at each operating point and judge it against its
    ``[requirements]`` (module docstring).

    Parameters
    ----------
    design : Design
        A validated design.
    resolution : Resolution
        Grid sizes and ranges (:data:`~flexshaft.resolution.SCREENING`,
        :data:`~flexshaft.resolution.VERDICT`, :data:`~flexshaft.resolution.REPORT`,
        :data:`~flexshaft.resolution.FINE`, or your own).
    executor : concurrent.futures.Executor, optional
        A pool (e.g. :func:`flexshaft.parallel.pool.worker_pool`) that computes the independent
        analyses while this process computes the rest; the results do not depend on it.
    progress : callable, optional
        Called with a short label before each step.

    Raises
    ------
    DesignError
        When the assessment could not finish (its size estimate is above the hard caps,
        :func:`~flexshaft.assembly.size.check_problem_size`; a ProblemSizeWarning when it is
        large), or an envelope point puts the shaft outside a lamina's temperature table or the
        design at a point breaks the schema.
    RefusedInputError
        (a ValueError) When ``design`` is not a Design or ``resolution`` not a Resolution.
    """
    _check_arguments(design, resolution)
    check_problem_size(design, "assess", resolution, stacklevel=3)  # refuses what cannot finish; warns when large
    if design.envelope is None:
        analyses = analyse_point(design, resolution, executor=executor, progress=progress)
        if progress is not None:
            progress("requirements verdict")
        only = _judged("operating point", analyses)
        return Assessment(
            **vars(analyses), evidence=only.evidence, verdict=only.verdict, points=(only,), governing_point=only.name
        )
    # every point's design first: a point that breaks the schema is refused before any analysis
    prepared = [_point_design(design, index) for index in range(len(design.envelope.points))]
    judged = [_analyse_and_judge(*point, resolution, executor, progress) for point in prepared]
    return combine_points(design, judged, resolution, progress=progress)


@single_blas_thread
def assess_point(
    design: Design,
    index: int,
    resolution: Resolution = REPORT,
    *,
    executor: Executor | None = None,
    progress: Callable[[str], None] | None = None,
) -> PointAssessment:
    """The step :func:`assess` takes at point ``index`` of the design's ``[envelope]``: the
    design at that point analysed at ``resolution`` (without the report's detail) and judged.

    The points are independent: a caller with several processes may compute them apart (the
    explorer does) and hand them, in the envelope's order, to :func:`combine_points`.

    Raises
    ------
    DesignError
        As :func:`assess` for that point; ValueError when the design has no envelope or no such
        point.
    """
    _check_arguments(design, resolution)
    if design.envelope is None or not 0 <= index < len(design.envelope.points):
        count = 0 if design.envelope is None else len(design.envelope.points)
        raise ValueError(f"index: the design's envelope has {count} points, got {index!r}")
    return _analyse_and_judge(*_point_design(design, index), resolution, executor, progress)


def _check_arguments(design: object, resolution: object) -> None:
    """Refuse anything but a validated Design and a Resolution (a preset's name such as
    "screening" used to fail deep inside with an AttributeError)."""
    if not isinstance(design, Design):
        raise RefusedInputError(
            f"design must be a validated flexshaft.design.Design (got {type(design).__name__}); "
            "use load_design, loads_design or design_from_dict"
        )
    if not isinstance(resolution, Resolution):
        raise RefusedInputError(
            f"resolution must be a flexshaft.Resolution (got {resolution!r}); allowed: "
            "fs.SCREENING, fs.VERDICT, fs.REPORT, fs.FINE or dataclasses.replace(one of them, ...)"
        )


def _point_design(design: Design, index: int) -> tuple[str, PointConditions, Design]:
    """The name, conditions and design of the envelope's point ``index`` (DesignError naming
    the point when its temperature or its design is refused)."""
    assert design.envelope is not None
    point = design.envelope.points[index]
    try:
        conditions = point_conditions(design, point)
    except ValueError as exc:  # a material temperature outside a lamina's table, a law out of bounds
        raise DesignError([Problem(f"envelope.points[{index}]", str(exc))], "<envelope>") from None
    try:
        at_point = design_at_point(design, point, conditions)
    except DesignError as exc:  # the design at the point breaks the schema (e.g. power without speed)
        raise DesignError(
            [Problem(f"envelope.points[{index}] ({point.name})", str(problem)) for problem in exc.problems],
            "<envelope>",
        ) from None
    return point.name, conditions, at_point


def envelope_problems(design: Design) -> list[Problem]:
    """What the verdict refuses at the points of ``design``'s envelope, each problem naming its
    point (the same recipe, :func:`_point_design`; a few ms a point): a material temperature
    beyond a lamina's table, the matrix law taking a lamina out of the schema's bounds there, a
    design at the point the schema refuses. ``flexshaft check`` reports them, so that a design it
    accepts runs (a hot-soak point at 88.8 °C with θ_E = 5 K took E_T to 1.9 Pa, below the
    schema's 1 kPa, and ``run`` refused a design ``check`` had accepted)."""
    problems: list[Problem] = []
    for index in range(0 if design.envelope is None else len(design.envelope.points)):
        try:
            _point_design(design, index)
        except DesignError as error:
            problems.extend(error.problems)
    return problems


def _analyse_and_judge(
    name: str,
    conditions: PointConditions,
    at_point: Design,
    resolution: Resolution,
    executor: Executor | None,
    progress: Callable[[str], None] | None,
) -> PointAssessment:
    step = None if progress is None else (lambda label: progress(f"{name}: {label}"))
    analyses = analyse_point(
        at_point, resolution, conditions=conditions, detail=False, executor=executor, progress=step
    )
    return _judged(name, analyses)


def combine_points(
    design: Design,
    judged: list[PointAssessment],
    resolution: Resolution = REPORT,
    *,
    progress: Callable[[str], None] | None = None,
) -> Assessment:
    """The assessment of ``design`` from its envelope's points judged by :func:`assess_point`
    at ``resolution`` (in the envelope's order): the combined verdict, the governing point and,
    at that point, what the resolution shows beyond the checks (the report's detail, or the
    explorer's Campbell diagram)."""
    names = [p.name for p in design.envelope.points] if design.envelope is not None else []
    if [p.name for p in judged] != names:
        raise ValueError(f"judged: the design's envelope points {names} in order, got {[p.name for p in judged]}")
    if progress is not None:
        progress("requirements verdict")
    judged = list(judged)
    governing = governing_point(judged)
    index = next(k for k, p in enumerate(judged) if p.name == governing)
    if resolution.report_detail:
        if progress is not None:
            progress(f"{governing}: the report's detail")
        judged[index] = _judged(governing, add_report_detail(judged[index].analyses))
    elif resolution.campbell_speeds:  # a Campbell diagram to draw (the explorer's) at the governing point
        judged[index] = _judged(governing, add_campbell(judged[index].analyses))
    shown = judged[index]
    return Assessment(
        **{**vars(shown.analyses), "design": design},
        evidence=shown.evidence,
        verdict=envelope_verdict(judged),
        points=tuple(judged),
        governing_point=governing,
    )
