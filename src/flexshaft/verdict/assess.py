"""The one recipe that judges a design: :func:`assess` and its :class:`Assessment`.

``assess(design, resolution)`` analyses the design at its operating point
(:func:`~flexshaft.verdict.operating_point.analyse_point`), gathers the evidence each
requirement needs (:func:`~flexshaft.verdict.gather.gather_evidence`) and checks it against the
design's ``[requirements]`` (:func:`~flexshaft.verdict.checks.evaluate`). ``flexshaft run`` (at
:data:`~flexshaft.resolution.REPORT`), the optimizer (at its fidelity), ``flexshaft compare``
and ``flexshaft check`` (its size estimate counts the same :class:`~flexshaft.resolution.Resolution`)
all go through it, so one design at one resolution is judged identically by each.

>>> import flexshaft as fs
>>> a = fs.assess(fs.baseline_design(), fs.SCREENING)    # doctest: +SKIP
>>> a.verdict.summary, a.campbell, a.spinup.shaft_peak.max()  # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
import html
from collections.abc import Callable
from concurrent.futures import Executor
from dataclasses import dataclass

from flexshaft.assembly.size import check_problem_size
from flexshaft.design import Design
from flexshaft.resolution import REPORT, Resolution
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.evidence import Evidence
from flexshaft.verdict.gather import gather_evidence
from flexshaft.verdict.operating_point import PointAnalyses, analyse_point
from flexshaft.verdict.result import Verdict

__all__ = ["Assessment", "assess"]


@dataclass(frozen=True, kw_only=True)
class Assessment(PointAnalyses):
    """A design judged at its operating point: every analysis of :class:`PointAnalyses` (the
    modes, Campbell diagram, spin-up response, critical speeds, strength, buckling, metal
    strength, coupling misalignment, bearing reactions, thermal results, whirl stability and the
    notes), the ``evidence`` its checks read and the ``verdict``, SI units. Frozen: computed once.
    """

    evidence: Evidence
    verdict: Verdict

    def __repr__(self) -> str:
        return f"Assessment({self.design.name!r} at the {self.resolution.name} resolution: {self.verdict.summary})"

    def _repr_html_(self) -> str:
        """The design, the verdict headline and table (:meth:`Verdict._repr_html_`), the
        analyses it holds and the notes."""
        rpm = rad_s_to_rpm(self.operating_speed)
        fields = [f.name for f in dataclasses.fields(PointAnalyses) if getattr(self, f.name) is not None]
        analyses = [n for n in fields if n not in ("design", "resolution", "model", "notes")]
        parts = [
            f"<p><b>{html.escape(self.design.name)}</b><br>assessed at {rpm:.0f} rpm, "
            f"{html.escape(self.resolution.name)} resolution</p>",
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


def assess(
    design: Design,
    resolution: Resolution = REPORT,
    *,
    executor: Executor | None = None,
    progress: Callable[[str], None] | None = None,
) -> Assessment:
    """Analyse ``design`` at ``resolution`` and judge it against its ``[requirements]``.

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
        :func:`~flexshaft.assembly.size.check_problem_size`); a
        :class:`~flexshaft.assembly.size.ProblemSizeWarning` when it is large.
    """
    check_problem_size(design, "assess", resolution, stacklevel=3)  # refuses what cannot finish; warns when large
    analyses = analyse_point(design, resolution, executor=executor, progress=progress)
    if progress is not None:
        progress("requirements verdict")
    evidence = gather_evidence(analyses)
    return Assessment(**vars(analyses), evidence=evidence, verdict=evaluate(evidence, design.requirements))
