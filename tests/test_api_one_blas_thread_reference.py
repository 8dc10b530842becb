"""The Python API computes with one BLAS thread, whatever the caller's process has set.

A notebook imports flexshaft without ``OPENBLAS_NUM_THREADS=1`` (the commands set it before
numpy loads; a notebook's kernel has loaded numpy with one thread per core). The analyses'
dense problems are small, and a threaded BLAS spins on them: a screening assessment of the tuned
design through the API cost 0.77-2.8 s of CPU instead of 0.35 s on the 2-core VM with its other
core busy (flexshaft.parallel.threads). So the public entry points limit BLAS to one thread
while they run and give the caller's setting back afterwards.

Checked with threadpoolctl (an independent reader of the BLAS libraries' own thread counts,
``openblas_get_num_threads``): inside the work of ``fs.assess``, ``assess_point`` and
``fs.modes`` every loaded BLAS reports one thread while the caller had set two, and two again
after the call. The assessment is stopped at its first analysis (nothing is computed), the modes are those of
the 4-element Jeffcott rotor: a few ms.
"""

from __future__ import annotations

import pytest
from jeffcott_bearing import ACTIVE, model_with
from threadpoolctl import threadpool_info, threadpool_limits

import flexshaft as fs
from flexshaft.analyses import modal
from flexshaft.verdict import assess as assess_module


def _blas_threads() -> list[int]:
    return [info["num_threads"] for info in threadpool_info() if info["user_api"] == "blas"]


@pytest.fixture
def two_threads():
    """The caller's BLAS at two threads (skipped where the BLAS cannot run two)."""
    with threadpool_limits(limits=2, user_api="blas"):
        if not _blas_threads() or max(_blas_threads()) < 2:
            pytest.skip("this BLAS cannot be set to two threads")
        yield


class _Stop(Exception):
    pass


def test_an_assessment_runs_with_one_blas_thread_and_restores_the_callers(monkeypatch, two_threads):
    seen: list[list[int]] = []

    def first_analysis(*args, **kwargs):
        seen.append(_blas_threads())
        raise _Stop

    monkeypatch.setattr(assess_module, "analyse_point", first_analysis)
    with pytest.raises(_Stop):
        fs.assess(fs.baseline_design(), fs.SCREENING)
    with pytest.raises(_Stop):
        assess_module.assess_point(fs.baseline_design(), 0, fs.SCREENING)
    assert seen == [[1] * len(seen[0])] * 2
    assert min(_blas_threads()) == 2  # the caller's setting is back


def test_modes_run_with_one_blas_thread(monkeypatch, two_threads):
    seen: list[list[int]] = []
    solve = modal._solve

    def recording(*args, **kwargs):
        seen.append(_blas_threads())
        return solve(*args, **kwargs)

    monkeypatch.setattr(modal, "_solve", recording)
    fs.modes(model_with(ACTIVE), speed=0.0, n_modes=2)
    assert seen and all(threads == [1] * len(threads) for threads in seen)
    assert min(_blas_threads()) == 2
