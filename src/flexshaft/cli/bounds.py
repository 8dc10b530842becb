"""The work of a command, bounded before it computes: its options and the design together.

A design is bounded on its own (:func:`flexshaft.assembly.size.check_problem_size`: DOFs, load
cases, controller states). A command multiplies it by its options (speeds × gains × modes ×
samples × DOFs); each command calls its function here after reading its options and the design
and before writing or computing anything. A command whose estimate exceeds its limit is
refused (exit 2) with the numbers and the options to change; every option's range in
``--help`` runs at the command's defaults.

Limits: :data:`MAX_SECONDS` for the commands that run in one go (``stability``, ``runup``,
``study spinup-map``, ``modes``), :data:`MAX_RESUMABLE_SECONDS` per worker for those that keep
their finished work and resume (the ``study`` sweeps, ``montecarlo``, ``optimize``), and
:data:`MAX_BYTES` of memory for all. The time constants were measured on the development
machine (2 shared cores, one BLAS thread, docs/limits.md) and err on the slow side; they give
the order of magnitude, not a promise.
"""

from __future__ import annotations

import math
from typing import Any

from flexshaft.cli.common import fail

__all__ = [
    "MAX_BYTES",
    "MAX_RESUMABLE_SECONDS",
    "MAX_SECONDS",
    "check_modes",
    "check_montecarlo",
    "check_optimize",
    "check_runup",
    "check_spinup_map",
    "check_stability",
    "check_sweep",
    "check_verification",
    "eigen_basis_range",
]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Longest estimated time of a command that runs in one go [s].
MAX_SECONDS = 600.0
#: Longest estimated time per worker of a command that keeps its finished work and resumes [s].
MAX_RESUMABLE_SECONDS = 4 * 3600.0
#: Largest estimated memory of a command [bytes].
MAX_BYTES = 2 * 1024**3

# Measured constants (development machine, one BLAS thread; docs/limits.md).
#: Spin-up map, per gain pair, speed and shaft node [s] (2.9e-6 s per pair and speed on the
#: baseline's 37 shaft nodes).
SPINUP_MAP_SECONDS = 8e-8
#: Spin-up map memory per speed and shaft node [bytes] (blocks of 32 gain pairs; 3.5 kB measured).
SPINUP_MAP_BYTES = 4096
#: Run-up, per output sample and envelope state [s] (26 s for 192,001 samples of 60 states).
RUNUP_SECONDS = 2.5e-6
#: Monte-Carlo, per sample and shaft node [s] (6 ms a sample on the baseline's 37 nodes).
MONTECARLO_SECONDS = 2e-4


def _duration(seconds: float) -> str:
    if seconds < 120:
        return f"{seconds:.2g} s"
    if seconds < 7200:
        return f"{seconds / 60:.2g} min"
    return f"{seconds / 3600:.3g} h"


def _size(size: float) -> str:
    return f"{size / 1024**3:.2g} GiB" if size >= 0.1 * 1024**3 else f"{size / 1024**2:.3g} MiB"


def _refuse_if_large(
    what: str, seconds: float, memory: float, change: str, limit: float = MAX_SECONDS, per_worker: str = ""
) -> None:
    """Refuse (exit 2) when ``seconds`` exceeds ``limit`` or ``memory`` exceeds :data:`MAX_BYTES`."""
    over = []
    if seconds > limit:
        over.append(f"take about {_duration(seconds)}{per_worker} (allowed: {_duration(limit)})")
    if memory > MAX_BYTES:
        over.append(f"need about {_size(memory)} of memory (allowed: {_size(MAX_BYTES)})")
    if over:
        fail(f"{what} would {' and '.join(over)}; {change}")


def _model_size(design: Any):
    import warnings

    from flexshaft.assembly.size import ProblemSizeWarning, problem_size

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        return problem_size(design, "model")


def eigen_basis_range(n_modes: int, free_dofs: int, actuators: int = 0) -> tuple[int, int]:
    """(first, largest) basis vectors of an accuracy-controlled eigen-solve of ``n_modes``
    modes: the first and the last basis of :func:`~flexshaft.analyses.eigen_error.accurate_bases`
    (``size`` modes and the static corrections of the lowest ``enrich``); each corrected mode
    adds up to five vectors (G, the dampers, three loss matrices) and each actuator two
    (:func:`~flexshaft.analyses.reduced_basis.enrich_basis`); the whole model caps both."""
    from flexshaft.analyses.eigen_error import accurate_bases

    bases = accurate_bases(n_modes)
    first, last = (min(size + 5 * enrich + 2 * actuators, free_dofs) for size, enrich in (bases[0], bases[-1]))
    return first, last


def check_stability(design: Any, n_speeds: int, n_modes: int, shafts: int = 1) -> None:
    """``flexshaft stability``: ``shafts`` × ``n_speeds`` eigen-solutions of the basis chosen
    for accuracy for ``n_modes`` tracked modes: the time at the first basis tried, the memory at
    the largest it can grow to (:func:`eigen_basis_range`)."""
    from flexshaft.assembly.size import eigen_seconds

    size = _model_size(design)
    first, largest = eigen_basis_range(n_modes, size.free_dofs, size.actuators)
    states = 2 * first + size.controller_states
    worst = 2 * largest + size.controller_states
    seconds = shafts * (size.time_seconds + n_speeds * eigen_seconds(states))
    memory = 4 * 16.0 * worst**2 + 16.0 * n_speeds * n_modes * shafts * 4
    _refuse_if_large(
        f"--n-speeds {n_speeds} × --n-modes {n_modes} (a basis of {first} to {largest} vectors, {states} to "
        f"{worst} states{f', {shafts} shafts' if shafts > 1 else ''}, {size.free_dofs:,} free DOFs)",
        seconds,
        memory,
        "use fewer speeds (--n-speeds) or tracked modes (--n-modes)",
    )


def check_modes(design: Any, n_modes: int) -> None:
    """``flexshaft modes``: one eigen-solution of the basis chosen for accuracy for ``n_modes``
    modes: the time at the first basis tried, the memory at the largest (:func:`eigen_basis_range`)."""
    from flexshaft.assembly.size import eigen_seconds

    size = _model_size(design)
    first, largest = eigen_basis_range(n_modes, size.free_dofs, size.actuators)
    states = 2 * first + size.controller_states
    worst = 2 * largest + size.controller_states
    _refuse_if_large(
        f"--n-modes {n_modes} (a basis of {first} to {largest} vectors, {states} to {worst} states)",
        size.time_seconds + eigen_seconds(states),
        8.0 * size.free_dofs * largest + 4 * 16.0 * worst**2,
        "ask for fewer modes (--n-modes)",
    )


def check_spinup_map(design: Any, n_gains: int, n_speeds: int) -> None:
    """``flexshaft study spinup-map``: the actuator receptance at ``n_speeds`` speeds and the
    spin-up peaks of ``n_gains``² gain pairs at each (:func:`flexshaft.analyses.spinup.spinup_map`)."""
    from flexshaft.assembly.size import harmonic_seconds

    size = _model_size(design)
    pairs = n_gains * n_gains
    receptance = n_speeds * (1 + 2 * size.actuators) * harmonic_seconds(size.free_dofs, size.boom_nodes > 0)
    seconds = size.time_seconds + receptance + SPINUP_MAP_SECONDS * pairs * n_speeds * size.shaft_nodes
    memory = float(SPINUP_MAP_BYTES) * n_speeds * size.shaft_nodes * max(1.0, size.actuators / 2)
    _refuse_if_large(
        f"--n-gains {n_gains} (× {n_gains}: {pairs:,} gain pairs) × --n-speeds {n_speeds:,} on "
        f"{size.shaft_nodes} shaft nodes",
        seconds,
        memory,
        "use fewer gains (--n-gains) or speeds (--n-speeds)",
    )


def check_runup(model: Any, duration: float, dwell: float, top: float) -> None:
    """``flexshaft runup``: the output samples of the run (at most
    :data:`flexshaft.analyses.transient.MAX_OUTPUTS`, 8 per period of the fastest envelope
    content at the largest speed ``top`` [rad/s]) and the envelope states kept at each."""
    from flexshaft.analyses.transient import MAX_OUTPUTS, default_basis_size, default_output_step
    from flexshaft.units import rad_s_to_rpm

    step = default_output_step(top)
    samples = math.ceil((duration + dwell) / step) + 1
    if samples > MAX_OUTPUTS:
        longest = (MAX_OUTPUTS - 1) * step
        fail(
            f"--duration {duration:g} s + --dwell {dwell:g} s up to {rad_s_to_rpm(top):.6g} rpm would give "
            f"{samples:,} output samples (8 per period of the fastest envelope content); at most "
            f"{MAX_OUTPUTS:,}: a run of at most {longest:.4g} s at this speed"
        )
    basis = default_basis_size(model, top)
    states = 2 * basis + _model_size(model.design).controller_states
    nodes = model.dofs.n_shaft_nodes
    memory = samples * 16.0 * (states + 5 * nodes + 8 * len(model.actuators))
    seconds = RUNUP_SECONDS * samples * states * max(1.0, states / 60)
    _refuse_if_large(
        f"--duration {duration:g} s + --dwell {dwell:g} s ({samples:,} output samples of {states} envelope "
        f"states and {nodes} shaft nodes)",
        seconds,
        memory,
        "use a shorter run (--duration, --dwell)",
    )


def check_montecarlo(design: Any, samples: int, workers: int) -> None:
    """``flexshaft montecarlo``: ``samples`` combinations of the unit responses over the shaft
    nodes (resumable: per worker)."""
    size = _model_size(design)
    seconds = size.time_seconds + samples * MONTECARLO_SECONDS * size.shaft_nodes / max(workers, 1)
    memory = 8.0 * samples * (8 + 4 * size.actuators + 3 * size.bays) * 2
    _refuse_if_large(
        f"--samples {samples:,} on {size.shaft_nodes} shaft nodes",
        seconds,
        memory,
        "use fewer samples (--samples) or more workers (--jobs, --dask)",
        MAX_RESUMABLE_SECONDS,
        f" on {workers} worker(s)",
    )


def check_sweep(design: Any, command: str, points: int, workers: int) -> None:
    """A ``flexshaft study`` sweep of ``points`` designs (resumable: per worker); each point
    builds and analyses its model (:func:`flexshaft.assembly.size.problem_size`)."""
    size = _model_size(design)
    seconds = points * size.time_seconds / max(workers, 1)
    _refuse_if_large(
        f"{command}: {points:,} points of {size.free_dofs:,} free DOFs",
        seconds,
        size.memory_bytes,
        "use a coarser grid, a coarser mesh (mesh.shaft_elements) or more workers (--jobs, --dask)",
        MAX_RESUMABLE_SECONDS,
        f" on {workers} worker(s)",
    )


def check_optimize(design: Any, budget: int, fidelity: str, workers: int, source: str = "<problem size>") -> None:
    """``flexshaft optimize``: ``budget`` assessments at the ``fidelity`` resolution (resumable:
    per worker). The base design's own refusals come first (the ``"worst"`` placement beyond
    its bays: :func:`flexshaft.assembly.size.check_problem_size`), naming ``source``."""
    import math
    import warnings

    from flexshaft.assembly.size import ProblemSizeWarning, check_problem_size
    from flexshaft.resolution import SCREENING, VERDICT

    resolution = {"screening": SCREENING, "verdict": VERDICT}[fidelity]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        inf = math.inf  # the budget's caps below
        size = check_problem_size(design, "assess", resolution, hard_memory=inf, hard_time=inf, source=source)
    _refuse_if_large(
        f"--budget {budget:,} evaluations at the {fidelity} fidelity (about {_duration(size.time_seconds)} each)",
        budget * size.time_seconds / max(workers, 1),
        size.memory_bytes,
        "lower --budget, use --fidelity screening, or more workers (--jobs, --dask)",
        MAX_RESUMABLE_SECONDS,
        f" on {workers} worker(s)",
    )


def check_verification(design: Any, designs: int, budget: int, workers: int) -> None:
    """``flexshaft optimize --verify``: a full-run assessment (at the report's resolution) of
    each written design, at most ``--designs`` and at most one per evaluation, in one go (not
    resumable: :data:`MAX_SECONDS`)."""
    import warnings

    from flexshaft.assembly.size import ProblemSizeWarning, problem_size
    from flexshaft.resolution import REPORT

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        size = problem_size(design, "assess", REPORT)
    count = min(designs, budget)
    _refuse_if_large(
        f"--verify of up to {count:,} written designs (--designs {designs:,}; a full run of about "
        f"{_duration(size.time_seconds)} each)",
        count * size.time_seconds / max(workers, 1),
        size.memory_bytes,
        "lower --designs, or pass --no-verify and run the design files you want with flexshaft run",
        per_worker=f" on {workers} worker(s)",
    )


def workers_of(jobs: int, client: Any) -> int:
    """Workers of a command: ``--jobs`` up to the CPUs this process may run on (more processes
    than CPUs do not shorten the run), or the threads of the Dask cluster."""
    if client is None:
        from flexshaft.parallel.pool import available_cpus

        return max(min(int(jobs), available_cpus()), 1)
    try:
        return max(1, sum(client.nthreads().values()))
    except Exception:  # noqa: BLE001 - any client-like object without the call
        return max(int(jobs), 1)
