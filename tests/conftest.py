"""Suite-wide pytest options: the CPU time of every test.

``pytest --cpu-durations=N`` lists the N tests that used the most CPU time (user + system, of
the test process and of the child processes it waited for: CLI runs, worker pools), the
suite's total, and every test above :data:`SLOW_CPU_SECONDS` that is not marked ``slow``.
Wall-clock ``--durations`` mixes in the waits of a shared machine; this is the budget the
suite is held to (issue 23: at most 5 s of CPU a test unless marked ``slow`` with a reason,
about 200 s in all).
"""

from __future__ import annotations

import os

import pytest

#: A test above this CPU time [s] must carry ``@pytest.mark.slow(reason=...)``.
SLOW_CPU_SECONDS = 5.0
_TIMES = pytest.StashKey[dict]()


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


def pytest_configure(config):
    config.stash[_TIMES] = {}


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    start = _cpu_seconds()
    yield
    item.config.stash[_TIMES][item.nodeid] = (_cpu_seconds() - start, item.get_closest_marker("slow") is not None)


def pytest_terminal_summary(terminalreporter, exitstatus, config):
    count = config.getoption("--cpu-durations")
    times = config.stash[_TIMES]
    if count is None or not times:
        return
    ranked = sorted(times.items(), key=lambda kv: -kv[1][0])
    write = terminalreporter.write_line
    terminalreporter.section("CPU time per test (setup + call + teardown, with waited-for children)")
    for nodeid, (seconds, slow) in ranked[: max(count, 0) or len(ranked)]:
        write(f"{seconds:8.2f}s  {nodeid}{'  [slow]' if slow else ''}")
    write(f"{sum(s for s, _ in times.values()):8.2f}s  total over {len(times)} tests")
    over = [nodeid for nodeid, (seconds, slow) in ranked if seconds > SLOW_CPU_SECONDS and not slow]
    if over:
        write(f"above {SLOW_CPU_SECONDS:g} s CPU and not marked slow: " + ", ".join(over))
