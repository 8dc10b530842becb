"""What a user is told about a run folder: nothing for a new one, the folder's own study when
it is refused.

References (API contract, quoted verbatim):

* :func:`flexshaft.sweep.store._discard_chunks`, the one place that warns about a folder's
  history: "``None`` (no manifest, no chunks: a new folder) is silent", and
  :class:`~flexshaft.sweep.study.SweepWarning`'s docstring: "Stored results that were not reused
  (named, with the reason) and are recomputed." A new folder holds no stored result, so a first
  run into it raises no ``SweepWarning``.
* docs/studies.md: "A folder whose intact manifest is another study's is refused.", and
  :class:`~flexshaft.sweep.study.DifferentStudyError`: "``held`` names the stored study (its
  name and fingerprint)." The stored study is the one first run in the folder; its fingerprint
  is that study's own :meth:`~flexshaft.sweep.Study.fingerprint` (computed from its
  specification, not by the store), and the refused study's fingerprint differs from it.

The study is :mod:`tests.test_sweep_integrity`'s closed-form one (no model built): 12 points,
well under 0.1 s of CPU per run.
"""

from __future__ import annotations

import warnings

import pytest

from flexshaft.sweep import DifferentStudyError, SweepWarning, run_sweep
from tests.test_sweep_integrity import CHUNK, _study


def test_a_first_run_into_a_new_folder_warns_nothing(tmp_path):
    folder = tmp_path / "new"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        run_sweep(_study(), folder, chunk_size=CHUNK, progress=False)
    assert [str(w.message) for w in caught if issubclass(w.category, SweepWarning)] == []
    assert not list(tmp_path.glob("new/chunks.discarded-*"))  # nothing was there to move aside


def test_the_refusal_names_the_study_the_folder_holds(tmp_path):
    folder = tmp_path / "run"
    held, other = _study(wall=0.003), _study(wall=0.004)  # another fixed wall: another study
    run_sweep(held, folder, chunk_size=CHUNK, progress=False)
    held_print, other_print = held.fingerprint()[:12], other.fingerprint()[:12]
    assert held_print != other_print
    with pytest.raises(DifferentStudyError) as refused:
        run_sweep(other, folder, chunk_size=CHUNK, progress=False)
    for text in (str(refused.value), refused.value.held):
        assert held_print in text and repr(held.name) in text
        assert other_print not in text
