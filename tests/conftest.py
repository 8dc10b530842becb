"""Suite-wide pytest options: the CPU time of every test.

``pytest --cpu-durations=N`` lists the N tests that used the most CPU time (user + system, of
the test process and of the child processes it waited for: CLI runs, worker pools), the
suite's total, and every test above :data:`SLOW_CPU_SECONDS` that is not marked ``slow``.
Wall-clock ``--durations`` mixes in the waits of a shared machine; this is the budget the
suite is held to (issue 23: at most 5 s of CPU a test unless marked ``slow`` with a reason,
about 200 s in all).

A result computed once for the whole session and read by several tests (:func:`shared_result`,
:func:`charged_to_session`: a run of the CLI, an assessment) is listed on its own line,
``shared: <name>``, and not in the CPU of the test that happened to ask for it first (which one
that is depends on how pytest-xdist spreads the tests over its workers); the total counts it once.
"""

from __future__ import annotations

import contextlib
import os
import pickle
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

# One BLAS thread in every test process and the commands it starts, as `flexshaft` runs its own
# workers (flexshaft.cli sets the same unless the user chose): OpenBLAS's idle threads spin, and
# two xdist workers each with two BLAS threads on two cores nearly doubled the suite's CPU time
# for the same results. A test that needs more threads sets them in its subprocess's env.
for _name in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

#: A test above this CPU time [s] must carry ``@pytest.mark.slow(reason=...)``.
SLOW_CPU_SECONDS = 5.0
_TIMES = pytest.StashKey["_CpuTimes"]()
#: The session's shared computations finished in this process during the current test phase:
#: (name, CPU seconds), moved to the phase's report by :func:`pytest_runtest_makereport`.
_SHARED_CPU: list[tuple[str, float]] = []


def _cpu_seconds() -> float:
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def pytest_addoption(parser):
    parser.addoption(
        "--cpu-durations",
        type=int,
        default=None,
        metavar="N",
        help="show the N tests that used the most CPU time (this process and its waited-for children)",
    )


class _CpuTimes:
    """Sums each test's CPU time from its reports: in a serial run, and in pytest-xdist's
    controller, which runs no test itself and receives the workers' reports."""

    def __init__(self) -> None:
        self.times: dict[str, list] = {}
        self.shared: dict[str, float] = {}

    def pytest_runtest_logreport(self, report) -> None:
        props = dict(report.user_properties)
        if "cpu_seconds" in props:
            entry = self.times.setdefault(report.nodeid, [0.0, props["marked_slow"]])
            entry[0] += props["cpu_seconds"]
        for name, seconds in props.get("shared_cpu", ()):
            self.shared[name] = self.shared.get(name, 0.0) + seconds


def pytest_configure(config):
    from threadpoolctl import threadpool_limits  # a BLAS already loaded (by a plugin) ignores the env

    threadpool_limits(limits=1, user_api="blas")
    _build_each_cli_command_once()
    _collect_garbage_less_often()
    config.stash[_TIMES] = _CpuTimes()
    config.pluginmanager.register(config.stash[_TIMES], "cpu-durations")


def _build_each_cli_command_once() -> None:
    """Make typer's ``CliRunner`` build the click command of an app once per process.

    ``typer.testing.CliRunner.invoke(app, ...)`` converts the Typer app into its click command
    at every call (``typer.main.get_command``: the signature and type hints of every command of
    the CLI), about 50 ms a call here, some 300 calls in the suite: 15 s of CPU spent building
    the same command. The command is the same object between calls (typer keeps no state on
    it; click builds a fresh context per invocation), so it is built once per app. A typer
    version without this module-level name is left as it is."""
    import typer.testing

    build = getattr(typer.testing, "_get_command", None)
    if build is None:
        return
    built: dict[int, tuple[Any, Any]] = {}

    def build_once(app):
        if id(app) not in built:
            built[id(app)] = (app, build(app))  # the app is held: its id cannot be reused
        return built[id(app)][1]

    typer.testing._get_command = build_once


#: The collector's thresholds in a test process (:func:`_collect_garbage_less_often`).
GC_THRESHOLDS = (10_000, 10, 10)


def _collect_garbage_less_often() -> None:
    """Start the garbage collector's young collection every 10,000 net allocations of tracked
    objects instead of 700, so that its full collections, each walking every object of the
    process, are rarer (4 or 5 a worker over the suite instead of 30 to 43): in a test process,
    not in flexshaft's.

    A test process holds 300,000 objects once the suite is collected (235 test modules,
    hypothesis, playwright, pytest's own) and 420,000 to 620,000 by its end; with Python's
    defaults (700, 10, 10) each of the 30 to 43 full collections a worker makes walks them all,
    and they cost 3.2 to 5.0 s of CPU a worker, 8 to 10 s of the suite's, all charged to whatever
    test allocated last. With these thresholds the full collections cost 0.3 to 0.9 s a worker (``gc.callbacks``, the
    whole suite on two workers, 2026-12-05: 2.6 s in all against 9.9 s). flexshaft's own
    processes hold some 60,000 objects: a screening assessment spends 0.2 ms of its 0.37 s in
    the collector, so the CLI keeps Python's defaults, and the commands the suite starts as
    subprocesses (and their worker pools) run as a user's do. Memory: at most 10,000 young
    objects wait for their collection (one figure is some 100,000, freed by
    ``flexshaft.plot.output.one_collection`` as before)."""
    import gc

    gc.set_threshold(*GC_THRESHOLDS)


@pytest.fixture(scope="session", autouse=True)
def _run_in_the_test_process():
    """``flexshaft run`` called in the test process (typer's ``CliRunner``) works in that process:
    no pool of forked workers (``flexshaft.cli.run._worker_processes`` returns 1).

    pytest-xdist already runs one test per core, so a run's pool only oversubscribes the
    cores, and each of its two workers imports matplotlib again: measured, three runs of
    tests/test_cli.py's ``--strict`` tests took 13.6 s of CPU with the pool and 8.0 s without,
    in the same wall time. The results are the same either way: tests/test_tasks.py and
    tests/test_studies.py compare the pool's results with the ones computed in process.
    A test marked ``run_pool`` gets the pool as a user's run does (:func:`_run_pool_if_marked`);
    the CLI started as a subprocess (the README's quick start, its loop) always has it."""
    import importlib

    run_module = importlib.import_module("flexshaft.cli.run")  # the module: `flexshaft.cli.run` is the command
    own = run_module._worker_processes
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(run_module, "_worker_processes", lambda: 1)
        yield run_module, own


@pytest.fixture(autouse=True)
def _run_pool_if_marked(request, _run_in_the_test_process):
    """The run's own pool of workers for a test marked ``run_pool`` (see above)."""
    if request.node.get_closest_marker("run_pool") is None:
        yield
        return
    run_module, own = _run_in_the_test_process
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(run_module, "_worker_processes", own)
        yield


_PHASE_START = pytest.StashKey[float]()


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    # each phase's CPU travels with its report (xdist sends user_properties to the controller)
    seconds = _cpu_seconds() - item.stash.get(_PHASE_START, _cpu_seconds())
    shared = list(_SHARED_CPU)  # the session's computations this phase did: counted apart
    _SHARED_CPU.clear()
    outcome = yield
    report = outcome.get_result()
    report.user_properties.append(("cpu_seconds", seconds - sum(s for _, s in shared)))
    report.user_properties.append(("shared_cpu", shared))
    report.user_properties.append(("marked_slow", item.get_closest_marker("slow") is not None))


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item):
    item.stash[_PHASE_START] = _cpu_seconds()
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item):
    item.stash[_PHASE_START] = _cpu_seconds()
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_teardown(item):
    item.stash[_PHASE_START] = _cpu_seconds()
    yield


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    count = config.getoption("--cpu-durations")
    times = {nodeid: tuple(entry) for nodeid, entry in config.stash[_TIMES].times.items()}
    if count is None or not times:
        return
    shared = config.stash[_TIMES].shared
    rows = [(nodeid, seconds, "  [slow]" if slow else "") for nodeid, (seconds, slow) in times.items()]
    rows += [
        (f"shared: {name}", seconds, "  [computed once, read by several tests]") for name, seconds in shared.items()
    ]
    rows.sort(key=lambda row: -row[1])
    write = terminalreporter.write_line
    terminalreporter.section("CPU time per test (setup + call + teardown, with waited-for children)")
    for name, seconds, tag in rows[: max(count, 0) or len(rows)]:
        write(f"{seconds:8.2f}s  {name}{tag}")
    total = sum(seconds for _, seconds, _ in rows)
    write(f"{total:8.2f}s  total over {len(times)} tests and {len(shared)} shared results")
    ranked = sorted(times.items(), key=lambda kv: -kv[1][0])
    over = [nodeid for nodeid, (seconds, slow) in ranked if seconds > SLOW_CPU_SECONDS and not slow]
    if over:
        write(f"above {SLOW_CPU_SECONDS:g} s CPU and not marked slow: " + ", ".join(over))


# ------------------------------------------------------------------------------------------------
# Results shared by the whole session, across pytest-xdist's workers


@contextlib.contextmanager
def session_lock(factory: pytest.TempPathFactory, name: str) -> Iterator[Path | None]:
    """Hold the session-wide lock ``name`` and yield the folder that every worker of this test
    session shares (pytest-xdist's documented pattern for a fixture computed once per session:
    the first worker computes under the lock, the others wait and read what it left).

    Yields None in a run without xdist workers, or without POSIX locks: each process then
    computes for itself."""
    if os.environ.get("PYTEST_XDIST_WORKER") is None:
        yield None
        return
    try:
        import fcntl
    except ImportError:  # no POSIX locks: one computation per worker
        yield None
        return
    shared = factory.getbasetemp().parent  # this session's, above each worker's own
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield shared


_SHARED: dict[str, Any] = {}


def charged_to_session(name: str, compute: Callable[..., Any], *args: Any) -> Any:
    """``compute(*args)``, its CPU time (with the child processes it waited for) reported as the
    session's shared result ``name`` (``--cpu-durations``) instead of the asking test's."""
    start = _cpu_seconds()
    try:
        return compute(*args)
    finally:
        _SHARED_CPU.append((name, _cpu_seconds() - start))


def shared_result(factory: pytest.TempPathFactory, name: str, compute: Callable[[], Any]) -> Any:
    """``compute()`` once per test session, for every test module and xdist worker that asks for
    ``name``: a read-only result (an assessment, a comparison) that several modules check.

    The worker that first asks computes it (``shared: name`` in ``--cpu-durations``, not in its
    test's CPU time: :func:`charged_to_session`) and leaves it pickled
    in the session's shared folder; the others load that file. Callers must not mutate it."""
    if name in _SHARED:
        return _SHARED[name]
    with session_lock(factory, name) as shared:
        if shared is None:
            value = charged_to_session(name, compute)
        else:
            record = shared / f"{name}.pickle"
            if record.is_file():
                value = pickle.loads(record.read_bytes())
            else:
                value = charged_to_session(name, compute)
                partial = record.with_suffix(".partial")
                partial.write_bytes(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))
                partial.replace(record)
    _SHARED[name] = value
    return value


@pytest.fixture(scope="session")
def embedded_comparison(tmp_path_factory):
    """``flexshaft.comparison.compare()``: the embedded tuned and current designs, each assessed at
    its envelope's points at the report's resolution (about 11 s of CPU, once per session). Its
    first run is ``assess(tuned_design(), REPORT)``, the tuned design's verdict as ``flexshaft
    run`` computes it (tests/test_compare.py, tests/test_reproduction.py)."""
    from flexshaft.comparison import compare

    return shared_result(tmp_path_factory, "embedded_comparison", compare)


@pytest.fixture(scope="session")
def tuned_nominal_screening(tmp_path_factory):
    """The embedded tuned design without its ``[envelope]`` (its own operating point), assessed at
    the screening resolution, once per session (tests/test_envelope_verdict.py,
    tests/test_verdict.py)."""

    def compute():
        from flexshaft.design import tuned_design, with_overrides
        from flexshaft.resolution import SCREENING
        from flexshaft.verdict.assess import assess

        return assess(with_overrides(tuned_design(), {"envelope": None}), SCREENING)

    return shared_result(tmp_path_factory, "tuned_nominal_screening", compute)


def _run_design() -> str:
    """A small design for the ``run`` command's own behaviour (its output folder, marker, JSON):
    the Table 3.1 baseline on a coarse mesh (4 shaft, 2 boom elements) with one point of its
    envelope (hot_soak_start: the run still goes through the envelope's per-point steps and
    verdict), no aluminium (no thesis-shaft comparison), and markup in the actuators' names (it
    must reach the verdict table literally)."""
    import re

    from flexshaft.design import baseline_text

    text = baseline_text()
    small = text.replace("shaft_elements = 36", "shaft_elements = 4", 1).replace(
        "boom_elements = 24", "boom_elements = 2", 1
    )
    aluminium = text[text.index("[materials.al6061_t6]") : text.index("[materials.boom_aluminium]")]
    two_points = re.compile(r"\[\[envelope\.points\]\]\nname = \"(cold_day|standard_day)\".*?(?=\[\[envelope)", re.S)
    return (
        two_points.sub("", small)
        .replace(aluminium, "", 1)
        .replace('name = "amb_1"', 'name = "[bold]amb_1[/]"', 1)
        .replace('name = "amb_2"', 'name = "[red]amb_2"', 1)
    )


#: The design of :func:`small_run` (tests/test_cli_outputs.py and others read it).
RUN_DESIGN = _run_design()


def _smallest_grids():
    from flexshaft.resolution import Resolution

    return Resolution(
        "smallest",
        spinup_speeds=3,
        whirl_speeds=3,
        campbell_speeds=0,
        report_detail=False,
        modes=4,
        loop_peak_samples=1,
    )


#: The smallest grids a :class:`~flexshaft.resolution.Resolution` accepts, for the tests whose
#: checks read none of them (static loads and strength, the verdict's bookkeeping): CPU budget,
#: issue 23 (tests/test_mutation_gaps.py, tests/test_verdict.py, tests/test_datasets.py).
SMALLEST = _smallest_grids()


@pytest.fixture(scope="session")
def small_run(tmp_path_factory) -> dict:
    """``flexshaft run design.toml --studies none --json --out results`` of :data:`RUN_DESIGN`,
    once per session (about 3 s of CPU, mostly the report's figures), in a folder every xdist
    worker shares: tests read it, and a test that writes into a run folder copies ``out``
    first (the design file stays where it is: the copy's marker names it). Keys: ``design``,
    ``out``, ``exit_code``, ``stdout``, ``stderr``, ``results`` (results.json's bytes)."""

    def compute(folder: Path) -> dict:
        from typer.testing import CliRunner

        from flexshaft.cli import app

        design = folder / "design.toml"
        design.write_text(RUN_DESIGN, encoding="utf-8")
        result = CliRunner().invoke(
            app, ["run", str(design), "--studies", "none", "--json", "--out", str(folder / "results")]
        )
        return {
            "exit_code": result.exit_code,
            "stdout": result.stdout,
            "stderr": result.stderr,
            "output": result.output,
        }

    with session_lock(tmp_path_factory, "small_run") as shared:
        if shared is None:
            folder = tmp_path_factory.mktemp("small_run")
            record = charged_to_session("small_run", compute, folder)
        else:
            import json

            folder, saved = shared / "small_run", shared / "small_run.json"
            if saved.is_file():
                record = json.loads(saved.read_text(encoding="utf-8"))
            else:
                import shutil

                shutil.rmtree(folder, ignore_errors=True)
                folder.mkdir()
                record = charged_to_session("small_run", compute, folder)
                saved.write_text(json.dumps(record), encoding="utf-8")
    assert record["exit_code"] == 0, record["output"]
    out = folder / "results"
    return {"design": folder / "design.toml", "out": out, **record, "results": (out / "results.json").read_bytes()}
