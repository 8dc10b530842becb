"""A study's fingerprint names what it computes, not where a callable sits in memory.

A run folder keeps the fingerprint of the study that wrote it (flexshaft.sweep.store), and
running the same study on the same folder again must reuse its chunks: equal studies, equal
fingerprints. The thesis's gain study sets K_p through ``functools.partial(_gains, paths)``,
whose repr holds its memory address; the fingerprint took that repr, so every construction of
the study had another fingerprint and ``flexshaft study gain --out F`` run twice refused its own
folder ("holds a different study"). The properties checked here are exact: two constructions
of one study fingerprint alike, in this process and in another one, and a study whose partial
binds other arguments (other bearings; an array of 2000 numbers differing in one, whose repr
elides the difference) fingerprints differently.
"""

from __future__ import annotations

import functools
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from flexshaft.design import baseline_design
from flexshaft.sweep import Output, Study, Variable

HERE = Path(__file__).resolve().parent


def _set(paths: tuple[str, ...], value: float) -> dict[str, float]:
    return dict.fromkeys(paths, value)


def _evaluate(point) -> dict[str, float]:
    return {"kp_read": float(point.design.bearings[1].kp)}


def _study(paths: tuple[str, ...]) -> Study:
    variable = Variable("kp", [4e5, 5e5], overrides=functools.partial(_set, paths), units="N/m")
    return Study("gain", (variable,), (Output("kp_read", "N/m"),), _evaluate, base=baseline_design())


def test_equal_studies_fingerprint_alike_and_other_arguments_differ() -> None:
    paths = ("bearings[1].kp", "bearings[2].kp")
    first, second = _study(paths), _study(paths)
    assert first.variables[0].overrides is not second.variables[0].overrides
    assert first.fingerprint() == second.fingerprint()
    assert "0x" not in str(first.spec()["variables"])  # no memory address
    assert _study(("bearings[1].kp",)).fingerprint() != first.fingerprint()


def test_another_process_fingerprints_the_study_alike() -> None:
    """The folder's fingerprint was written by an earlier process: the function ``_set`` sits
    at another address there (the partial's repr printed it)."""
    paths = ("bearings[1].kp", "bearings[2].kp")
    code = (
        "import sys; sys.path.insert(0, sys.argv[1]); "
        "import test_study_fingerprint_partial_reference as t; "
        "print(t._study(('bearings[1].kp', 'bearings[2].kp')).fingerprint())"
    )
    env = {**os.environ, "PYTHONHASHSEED": "random"}
    out = subprocess.run([sys.executable, "-c", code, str(HERE)], capture_output=True, text=True, env=env, check=True)
    assert out.stdout.strip() == _study(paths).fingerprint()


def _scaled(factors, value: float) -> dict[str, float]:
    return {"bearings[1].kp": value * float(np.asarray(factors)[0])}


def test_arguments_whose_repr_elides_them_fingerprint_by_their_content() -> None:
    a, b = np.ones(2000), np.ones(2000)
    b[1000] = 2.0
    assert repr(a) == repr(b)  # numpy shows the first and last three of 2000
    first, second = (
        Study(
            "gain",
            (Variable("kp", [4e5], overrides=functools.partial(_scaled, f), units="N/m"),),
            (Output("kp_read", "N/m"),),
            _evaluate,
            base=baseline_design(),
        )
        for f in (a, b)
    )
    assert first.fingerprint() != second.fingerprint()
