"""Problem-size estimate: memory and time of a design's analyses, before computing them.

:func:`problem_size` counts what the analyses will hold from the design alone (no matrices are
built): the mesh nodes and DOFs, bearings, actuators and their controller states, imbalance
bays and load cases. From them it estimates the largest arrays and the run time:

* modal basis: a dense generalised eigen-solve (``8 n²`` bytes per matrix, about five such
  arrays) up to :data:`SPARSE_BASIS_ABOVE` free DOFs, else sparse shift-invert Lanczos (a
  banded factor and the Lanczos vectors, ``O(n)``);
* banded harmonic solves: ``16 n (3 k + 1)`` bytes for a half-bandwidth ``k``, counted twice (the
  LU buffer and the matrix's values on the band's pattern);
* first-order eigen-problems of ``2 nb + s`` states (``nb`` modal coordinates, ``s``
  controller states): four arrays of ``16 (2 nb + s)²`` bytes and ``~5e-9 (2 nb + s)³`` s each;
* the spin-up responses of an assessment: ``16 · DOFs · load cases · speeds`` bytes, counted
  twice (room for one copy).

An assessment (:func:`flexshaft.verdict.assess.assess`) is counted from the grids of its
:class:`~flexshaft.resolution.Resolution` (spin-up and whirl speeds, the report's Campbell
speeds), the very numbers it computes with, once per point of the design's ``[envelope]`` (the
report's detail once). Its time is the sum of the parts of one point, each fitted to its measured
CPU time (``benchmarks/size_estimate.py``) in the free DOFs ``F``: the projected spin-up scan
(``n_s F`` and ``F²``), the whirl stability (per whirl speed, ``+ F``), the every-root check and
the bearing loops (``F`` and ``F²``; a dense eigen-solution of the whole model at three speeds when an
actuator has controller states or a remote sensor), the torsional modes (a dense complex
eigen-solution, ``(2 × twist DOFs)³``) and the rest (lateral modes, strength, buckling,
thermal, ``F``); controller states add the cube of the states to every eigen-solution.
``flexshaft run`` adds the thesis studies (their whirl speeds, ``+ F``) and the report's
figures and files to the report's assessment.

:func:`check_problem_size` raises a :class:`~flexshaft.design.DesignError` naming the fields to
change when an estimate exceeds its hard cap (:data:`HARD_MEMORY_BYTES`,
:data:`HARD_TIME_SECONDS`) and warns with :class:`ProblemSizeWarning` above the soft caps.
:func:`~flexshaft.assembly.build.build_model` checks the model-level estimate;
:func:`~flexshaft.verdict.assess.assess` the ``assess`` estimate (the spin-up responses and every
analysis of the assessment); ``flexshaft check`` and ``flexshaft run`` the ``run`` estimate
(the report's assessment and the thesis studies).

The time constants were measured on the development machine (2 shared cores, one BLAS
thread, 2026-12-03) and err on the slow side: the estimate is 1.2 to 2.3 times the measured CPU
time of an assessment, a run or a model of the tuned and baseline designs from 36 to 400 shaft
elements (docs/limits.md, section 5). They give the order of magnitude, not a promise. The tuned
design estimates 0.03 GB and about 25 s for ``run`` (measured: 17 s of CPU).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from flexshaft.assembly.drive import drive_extra_dofs
from flexshaft.assembly.mesh import design_mesh, merge_stations, merge_tolerance
from flexshaft.design import DesignError, Problem
from flexshaft.parallel.point_label import labelled
from flexshaft.resolution import FINE, REPORT, Resolution

__all__ = [
    "HARD_MEMORY_BYTES",
    "HARD_TIME_SECONDS",
    "MAX_WORST_BAYS",
    "SOFT_DOFS",
    "SOFT_MEMORY_BYTES",
    "SOFT_TIME_SECONDS",
    "SPARSE_BASIS_ABOVE",
    "ProblemSize",
    "ProblemSizeWarning",
    "bearing_bays",
    "check_problem_size",
    "eigen_seconds",
    "harmonic_seconds",
    "problem_size",
]

#: Free-DOF count above which the modal basis is computed by sparse shift-invert
#: (:func:`flexshaft.analyses.reduced_basis.modal_basis`).
SPARSE_BASIS_ABOVE = 900
#: Modal basis of the run's eigen-analyses (10 to 12 modes: ``max(4 n_modes, 60)``).
RUN_BASIS = 60
#: Eigen-solutions per whirl speed of the thesis studies of ``flexshaft run``
#: (:mod:`flexshaft.thesis.report_studies`): three shafts under two damping models, and with PD
#: active bearings the gain map's 3 K_p × 4 K_d.
THESIS_WHIRL_SOLVES = 6
THESIS_GAIN_MAP_SOLVES = 12
#: Most imbalance bays the ``"worst"`` placement enumerates (2^(bays−1) = 512 load cases).
MAX_WORST_BAYS = 10
#: Estimated memory above which a design is refused / warned about [bytes].
HARD_MEMORY_BYTES = 2 * 1024**3
SOFT_MEMORY_BYTES = 512 * 1024**2
#: Estimated time above which a design is refused / warned about [s].
HARD_TIME_SECONDS = 4 * 3600.0
SOFT_TIME_SECONDS = 600.0
#: DOF count above which a warning says that a finer mesh is no more accurate: the dynamic
#: stiffness's condition number grows as (elements per member)⁴ and, near 400 elements per
#: member, the harmonic solver starts to report false singular systems.
SOFT_DOFS = 3000

# Time constants [s] (development machine, one BLAS thread).
_EIG_CUBIC = 5e-9  # dense nonsymmetric eigen-solve, per state³
_EIG_FIXED = 0.01  # Newton refinement and tracking per speed
_DENSE_BASIS_CUBIC = 5e-10  # dense generalised symmetric eigen-solve, per DOF³
_SPARSE_BASIS_LINEAR = 1.6e-7  # shift-invert Lanczos, per DOF
_BANDED_SOLVE = 2e-8  # banded LU, per DOF × half-bandwidth²
_BANDED_FIXED = 2e-4

# An assessment's parts, per envelope point [s] (fitted 2026-12-03 to benchmarks/size_estimate.py
# on the tuned and baseline designs at 343 to 3,730 free DOFs, with 20 % or more to spare;
# docs/limits.md, section 5).
# F is the free DOFs, n_s the spin-up speeds, n_w the whirl speeds.
_SPINUP_PER_SPEED_DOF = 1e-6  # projected spin-up scan: per speed and free DOF (× n_s F)
_SPINUP_PER_DOF2 = 1.2e-7  # its bases, refinement and full checks (× F², measured F^1.4)
_STABILITY_FIXED = 0.04  # whirl stability: its basis (+ per free DOF)
_STABILITY_PER_DOF = 7e-5
_WHIRL_SPEED = 1e-2  # one whirl speed on the reduced model (+ per free DOF; 3-13 ms measured)
_WHIRL_SPEED_PER_DOF = 1.5e-6
_ROOTS_FIXED = 0.1  # the passive every-root check and the bearing loops (+ per free DOF)
_ROOTS_PER_DOF = 1.2e-3
_ROOTS_PER_DOF2 = 3.5e-7  # (× F²: the baseline's loops took 8.1 s a point at 3,730 free DOFs, the tuned 3.4 s)
_TORSION_FIXED = 0.02  # torsional modes: a dense complex eigen-solution of 2 × twist DOFs
_TORSION_CUBIC = 3.5e-9  # (× (2 twist DOFs)³)
_POINT_FIXED = 0.2  # lateral modes, strength, buckling, thermal (+ per free DOF)
_POINT_PER_DOF = 1.3e-4
_DETAIL_FIXED = 0.75  # the report's detail at the governing point (+ per free DOF, + Campbell)
_DETAIL_PER_DOF = 3e-4
# ``flexshaft run``'s thesis studies and report (imports, figures, files), on top of its assessment:
_RUN_FIXED = 6.0
_STUDY_SPEED = 9e-3  # per whirl speed of a thesis study (+ per free DOF)
_STUDY_SPEED_PER_DOF = 1.6e-5


def eigen_seconds(states: int) -> float:
    """Estimated time of one first-order eigen-solution of ``states`` states, with its mode
    tracking [s] (one speed of a Campbell diagram or a whirl-stability analysis)."""
    return _EIG_FIXED + _EIG_CUBIC * float(states) ** 3


def harmonic_seconds(free_dofs: int, boom: bool = True) -> float:
    """Estimated time of one banded harmonic solve of ``free_dofs`` free DOFs [s] (one speed of
    a spin-up or frequency response; half-bandwidth 24 with a tailboom, 12 without)."""
    half_band = 24 if boom else 12
    return _BANDED_FIXED + _BANDED_SOLVE * free_dofs * half_band**2


class ProblemSizeWarning(UserWarning):
    """The design's analyses will be large or slow (between the soft and the hard cap).

    A UserWarning (shown by default; a ResourceWarning would be hidden outside ``__main__``).
    """


@dataclass(frozen=True)
class ProblemSize:
    """What a design's analyses hold and how long they take (estimates).

    Attributes
    ----------
    analysis : {"model", "assess", "run"}
        ``"model"``: building the model and its modes; ``"assess"``: an assessment at
        ``resolution``; ``"run"``: all of ``flexshaft run`` (the assessment and the thesis
        studies).
    shaft_nodes, boom_nodes, dofs, free_dofs : int
        Mesh size (after merging close stations).
    bearings, actuators, disks : int
    controller_states : int
        States added by the actuators' controllers: the law's order (plus one for an
        amplifier lag) on each of the two lateral directions, collocated or not (a remote
        sensor's magnet adds only its static ``−k_s``).
    bays, load_cases : int
        Imbalance bays and the load cases of the imbalance placement.
    n_speeds : int
        Spin-up speeds of the assessment (0 for ``"model"``).
    campbell_speeds, whirl_speeds : int
        Speeds of its Campbell diagram and whirl stability (0 for ``"model"``).
    n_modes : int
        Modes of its modal analyses (at the operating speed a few more where the whirl-damping
        check's scope, every lateral mode below the onset requirement's speed, reaches past
        them: not counted).
    dense_basis : bool
        Whether the modal basis is a dense eigen-solve.
    memory : dict of str to float
        Largest arrays by part [bytes].
    time : dict of str to float
        Time by part [s].
    """

    analysis: str
    shaft_nodes: int
    boom_nodes: int
    dofs: int
    free_dofs: int
    bearings: int
    actuators: int
    disks: int
    controller_states: int
    bays: int
    load_cases: int
    n_speeds: int
    campbell_speeds: int
    whirl_speeds: int
    n_modes: int
    dense_basis: bool
    memory: dict = field(default_factory=dict)
    time: dict = field(default_factory=dict)

    @property
    def memory_bytes(self) -> float:
        """Estimated peak memory [bytes] (the parts added up: an upper estimate)."""
        return float(sum(self.memory.values()))

    @property
    def time_seconds(self) -> float:
        """Estimated time [s]."""
        return float(sum(self.time.values()))

    @property
    def largest_memory(self) -> str:
        return max(self.memory, key=lambda part: self.memory[part])

    @property
    def largest_time(self) -> str:
        return max(self.time, key=lambda part: self.time[part])

    def summary(self) -> str:
        """One line: the counts and the estimates."""
        nodes = (
            f"{self.shaft_nodes:,} shaft and {self.boom_nodes:,} boom nodes"
            if self.boom_nodes
            else f"{self.shaft_nodes:,} shaft nodes, no tailboom"
        )
        return (
            f"{self.dofs:,} DOFs ({nodes}), "
            f"{self.bearings} bearings ({self.actuators} active, {self.controller_states} controller states), "
            f"{self.disks} disks, {self.load_cases:,} imbalance load case(s): about "
            f"{_gigabytes(self.memory_bytes)} and {_duration(self.time_seconds)} for {self.analysis!r}"
        )


def bearing_bays(stations, tolerance: float) -> list[tuple[float, float]]:
    """Bays between consecutive bearing stations [m], stations closer than ``tolerance`` [m]
    counted as one (the mesh merges them too, :func:`~flexshaft.assembly.mesh.merge_stations`)."""
    xs = merge_stations(list(stations), tolerance) if len(stations) else np.zeros(0)
    return [(float(a), float(b)) for a, b in zip(xs[:-1], xs[1:]) if b > a]


def _controller_order(bearing) -> int:
    numerator, denominator = bearing.transfer_function()
    den = np.trim_zeros(np.asarray(denominator, dtype=float), "f")
    return max(den.size - 1, 0) + (1 if bearing.amplifier_bandwidth is not None else 0)


def problem_size(
    design, analysis: Literal["model", "assess", "run"] = "run", resolution: Resolution = REPORT
) -> ProblemSize:
    """Estimate the size of the analyses of ``design`` (see the module docstring).

    Parameters
    ----------
    design : Design
        A validated design.
    analysis : {"model", "assess", "run"}
        Building the model and computing its modes; an assessment at ``resolution``; or the
        whole of ``flexshaft run`` (the assessment and the thesis studies).
    resolution : Resolution
        The grids of the assessment.
    """
    if analysis not in ("model", "assess", "run"):
        raise ValueError(f"analysis must be 'model', 'assess' or 'run' (got {analysis!r})")
    shaft_x, boom_x = design_mesh(design)
    dofs = 6 * shaft_x.size + 5 * boom_x.size + len(drive_extra_dofs(design))  # + drive-train twists
    fixed = len(design.shaft.fixed_start) + len(design.shaft.fixed_end) + (5 if boom_x.size else 0)
    free = dofs - fixed
    active = [b for b in design.bearings if b.kind == "active"]
    # the law's states on each lateral direction; a remote sensor adds none (its magnet's −k_s is static)
    states = sum(2 * _controller_order(b) for b in active)
    span = design.shaft.x_end - design.shaft.x_start
    bays = len(bearing_bays([b.x for b in design.bearings], merge_tolerance(span, design.mesh.shaft_elements))) or 1
    worst = design.loads.imbalance_placement == "worst"
    cases = 2 ** (bays - 1) if worst else 1
    nb = min(RUN_BASIS, free)
    dense = free <= SPARSE_BASIS_ABOVE or nb >= free // 2
    half_band = 24 if boom_x.size else 12
    n_states = 2 * nb + states

    memory = {"matrices": 8 * 12.0 * 40 * dofs}
    time = {"assembly": 2e-5 * dofs + 0.03}
    if dense:
        memory["modal basis (dense)"] = 5 * 8.0 * free**2
        basis_time = _DENSE_BASIS_CUBIC * free**3 + 0.01
    else:
        memory["modal basis (sparse)"] = 8.0 * free * (6 * half_band + 2 * nb + 2)
        basis_time = _SPARSE_BASIS_LINEAR * free + 0.05
    memory["state matrices"] = 4 * 16.0 * n_states**2
    speed_time = eigen_seconds(n_states)
    n_speeds = campbell_speeds = whirl_speeds = 0
    if analysis == "model":
        time["modal basis"] = basis_time
        time["eigen-solutions"] = 2 * speed_time
    else:
        n_speeds, campbell_speeds, whirl_speeds = (
            resolution.spinup_speeds,
            resolution.campbell_speeds,
            resolution.whirl_speeds,
        )
        memory["banded harmonic solver"] = 16.0 * free * (3 * half_band + 1) * 2
        memory["spin-up responses"] = 16.0 * dofs * cases * n_speeds * 2
        points = len(design.envelope.points) if design.envelope is not None else 1
        passive = all(_controller_order(b) == 0 and b.sensor_offset == 0.0 for b in active)
        # per whirl speed: a reduced eigen-solution; controller states add to its dense state matrix
        with_states = _EIG_CUBIC * (n_states**3 - (2 * nb) ** 3)
        per_whirl = _WHIRL_SPEED + _WHIRL_SPEED_PER_DOF * free + with_states
        twist = shaft_x.size + len(drive_extra_dofs(design))  # the torsional model's DOFs
        spinup = _SPINUP_PER_SPEED_DOF * n_speeds * free + _SPINUP_PER_DOF2 * free**2
        spinup += 16e-9 * dofs * (cases - 1) * n_speeds  # the other load cases' responses
        time["spin-up scan"] = points * spinup
        time["whirl stability"] = points * (_STABILITY_FIXED + _STABILITY_PER_DOF * free + whirl_speeds * per_whirl)
        if passive:
            roots = _ROOTS_FIXED + _ROOTS_PER_DOF * free + _ROOTS_PER_DOF2 * free**2
        else:  # the exact check: a dense eigen-solution of the whole model at three speeds
            full_states = 2 * free + states  # states: both lateral directions already
            roots = (
                3 * (_EIG_FIXED + 3 * _EIG_CUBIC * full_states**3) + _ROOTS_PER_DOF * free + _ROOTS_PER_DOF2 * free**2
            )
            memory["every-root state matrix"] = 3 * 16.0 * full_states**2
        time["every-root check and loops"] = points * roots
        time["torsional modes"] = points * (_TORSION_FIXED + _TORSION_CUBIC * (2.0 * twist) ** 3)
        time["modes, strength, buckling, thermal"] = points * (_POINT_FIXED + _POINT_PER_DOF * free)
        if resolution.report_detail:
            time["report detail"] = (
                _DETAIL_FIXED + _DETAIL_PER_DOF * free + campbell_speeds * per_whirl + 2 * basis_time
            )
        if analysis == "run":
            # the gain map of a PD-only (passive) design
            study_speeds = (THESIS_WHIRL_SOLVES + (THESIS_GAIN_MAP_SOLVES if active and passive else 0)) * whirl_speeds
            time["thesis studies and report"] = _RUN_FIXED + study_speeds * (
                _STUDY_SPEED + _STUDY_SPEED_PER_DOF * free + with_states
            )
    return ProblemSize(
        analysis,
        int(shaft_x.size),
        int(boom_x.size),
        int(dofs),
        int(free),
        len(design.bearings),
        len(active),
        len(design.disks),
        int(states),
        int(bays),
        int(cases),
        int(n_speeds),
        int(campbell_speeds),
        int(whirl_speeds),
        int(resolution.modes),
        bool(dense),
        memory,
        time,
    )


def _gigabytes(size: float) -> str:
    return f"{size / 1024**3:.2g} GiB" if size >= 0.1 * 1024**3 else f"{size / 1024**2:.3g} MiB"


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.2g} s"
    if seconds < 7200:
        return f"{seconds / 60:.2g} min"
    return f"{seconds / 3600:.2g} h"


def _what_to_change(size: ProblemSize, design) -> list[tuple[str, str]]:
    """(field path, advice) pairs that reduce the largest estimates."""
    advice = []
    if size.load_cases > 1:
        advice.append(
            (
                "loads.imbalance_placement",
                f'"worst" enumerates 2^(bays-1) = {size.load_cases:,} load cases over {size.bays} bays: use '
                '"mid_bay" or "distributed", or fewer bearings',
            )
        )
    if size.controller_states > 2 * RUN_BASIS:
        advice.append(
            (
                "bearings",
                f"{size.actuators} active bearings add {size.controller_states:,} controller "
                "states: use fewer active bearings or lower-order controllers",
            )
        )
    if size.dofs > SOFT_DOFS or advice == []:
        # mesh.boom_elements meshes the tailboom only: without one it adds no DOF (design_mesh)
        meshed = (
            f"{design.mesh.shaft_elements} shaft and {design.mesh.boom_elements} boom elements"
            if size.boom_nodes
            else f"{design.mesh.shaft_elements} shaft elements (no tailboom)"
        )
        advice.append(
            (
                "mesh.shaft_elements",
                f"{meshed} give {size.dofs:,} DOFs: use fewer (36 and 24 converge "
                "the baseline's lowest frequencies within 3e-8)",
            )
        )
    return advice


def _finer_than_fine(resolution: Resolution) -> tuple[str, str] | None:
    """(``"resolution"``, advice) when a grid of ``resolution`` is finer than :data:`FINE`'s:
    a refusal then names the resolution (``spinup_speeds = 10**9`` was refused as "use fewer
    shaft elements" on the 36-element tuned design)."""
    names = ("spinup_speeds", "whirl_speeds", "campbell_speeds")
    finer = [(n, getattr(resolution, n), getattr(FINE, n)) for n in names if getattr(resolution, n) > getattr(FINE, n)]
    if not finer:
        return None
    grids = ", ".join(f"{n} = {v:,} (fs.FINE: {f:,})" for n, v, f in finer)
    return ("resolution", f"{grids}: use coarser grids (the presets fs.SCREENING to fs.FINE)")


def check_problem_size(
    design,
    analysis: Literal["model", "assess", "run"] = "run",
    resolution: Resolution = REPORT,
    *,
    hard_memory: float = HARD_MEMORY_BYTES,
    soft_memory: float = SOFT_MEMORY_BYTES,
    hard_time: float = HARD_TIME_SECONDS,
    soft_time: float = SOFT_TIME_SECONDS,
    stacklevel: int = 2,
    source: str = "<problem size>",
) -> ProblemSize:
    """:func:`problem_size`, refused above the hard caps and warned about above the soft ones.

    A refused ``"worst"`` placement is not also counted against the caps: the memory and time
    are those of the design with one load case (what ``"mid_bay"`` or ``"distributed"`` runs), so
    a refusal names only what would still be too large once the placement is changed.

    Raises
    ------
    DesignError
        When the ``"worst"`` placement has more than :data:`MAX_WORST_BAYS` bays (``assess``,
        ``run``), or
        an estimate exceeds ``hard_memory`` [bytes] or ``hard_time`` [s]; the message gives the
        numbers and the fields to change; ``source`` names the design (its file) in the error.

    Warns
    -----
    ProblemSizeWarning
        Above ``soft_memory``, ``soft_time`` or :data:`SOFT_DOFS` DOFs (``stacklevel`` as for
        :func:`warnings.warn`: 2 points at the caller).
    """
    size = problem_size(design, analysis, resolution)
    problems: list[Problem] = []
    if analysis != "model" and design.loads.imbalance_placement == "worst" and size.bays > MAX_WORST_BAYS:
        problems.append(
            Problem(
                "loads.imbalance_placement",
                f'"worst" would enumerate 2^(bays-1) = 2^{size.bays - 1} load cases over {size.bays} '
                f'bays (got "worst"; allowed: at most {MAX_WORST_BAYS} bays, i.e. '
                f'{2 ** (MAX_WORST_BAYS - 1)} cases, or "mid_bay" / "distributed")',
            )
        )
        one_case = design.loads.model_copy(update={"imbalance_placement": "mid_bay"})
        size = problem_size(design.model_copy(update={"loads": one_case}), analysis, resolution)
    over = []
    if size.memory_bytes > hard_memory:
        over.append(
            f"needs about {_gigabytes(size.memory_bytes)} (mostly {size.largest_memory}; allowed: "
            f"{_gigabytes(hard_memory)})"
        )
    if size.time_seconds > hard_time:
        over.append(
            f"takes about {_duration(size.time_seconds)} (mostly {size.largest_time}; allowed: {_duration(hard_time)})"
        )
    if over:
        changes = _what_to_change(size, design)
        finer = _finer_than_fine(resolution) if analysis != "model" else None
        if finer is not None:  # a custom resolution's grids, not the mesh (fs.assess(design, replace(SCREENING, ...)))
            changes = [finer, *(c for c in changes if c[0] != "mesh.shaft_elements" or size.dofs > SOFT_DOFS)]
        for path, advice in changes:
            problems.append(
                Problem(
                    path,
                    f"{advice}; {analysis!r} of {size.dofs:,} DOFs, {size.load_cases:,} "
                    f"load case(s) and {size.controller_states:,} controller states " + " and ".join(over),
                )
            )
    if problems:
        raise DesignError(problems, source)
    notes = []
    if size.memory_bytes > soft_memory:
        notes.append(f"needs about {_gigabytes(size.memory_bytes)} (mostly {size.largest_memory})")
    if size.time_seconds > soft_time:
        notes.append(f"takes about {_duration(size.time_seconds)} (mostly {size.largest_time})")
    if size.dofs > SOFT_DOFS:
        notes.append(f"has {size.dofs:,} DOFs: a finer mesh is no more accurate and its harmonic solves lose digits")
    if notes:
        advice = "; ".join(f"{path}: {text}" for path, text in _what_to_change(size, design))
        warnings.warn(
            labelled(f"{size.summary()}; the analysis {' and '.join(notes)}. To reduce it: {advice}"),
            ProblemSizeWarning,
            stacklevel=stacklevel,
        )
    return size
