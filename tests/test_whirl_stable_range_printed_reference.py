"""What ``flexshaft stability`` prints for a shaft with no whirl onset: the speed range shown stable.

Reference (documented rule, the command's help and docs/architecture.md: the whirl-stability
speeds run from rest to 1.5 × the operating speed unless ``--max-rpm`` is given): a shaft with
no onset in the sweep is stable at least to the top speed analysed, so its row says "stable to"
that speed — 1.5 × 4800 = 7200 rev/min by default, 9600 rev/min with ``--max-rpm 9600`` —
and not to the operating speed, 4800 rev/min, which would understate the range shown free of
whirl onset by a third or a half.

The model and the analysis are stand-ins (operating speed 4800 rev/min = 2π·80 rad/s, a
sweep with no onset): what is checked is the command's own choice of speed, not the
analysis. 7200 and 9600 print exactly at 4 significant figures; the conversion
rad/s -> rev/min (60/2π) of 2π·120 and 2π·160 rad/s lands within a few ulps of them, far
below the rounding of the printed cell. About 0.1 s.
"""

from __future__ import annotations

import importlib
import math
from types import SimpleNamespace

import numpy as np
import pytest
from typer.testing import CliRunner

import flexshaft.assembly
from flexshaft.cli import app

runner = CliRunner()
STABILITY = importlib.import_module("flexshaft.analyses.stability")  # the module, not the re-export
OPERATING = 2.0 * math.pi * 80.0  # 4800 rev/min [rad/s]


@pytest.fixture
def stable_sweep(monkeypatch: pytest.MonkeyPatch) -> None:
    """A model at 4800 rev/min whose sweep finds no onset (every damping ratio positive)."""

    def stability(model, speeds, n_modes, damping_model, reference):
        return SimpleNamespace(
            onset_speed=None,
            unstable_mode=None,
            onset_whirl=None,
            whirl=np.array([["forward"]] * len(speeds), dtype=object),
            stability_margin=np.array([0.03, 0.02]),
        )

    monkeypatch.setattr(flexshaft.assembly, "build_model", lambda design: SimpleNamespace(speed=OPERATING))
    monkeypatch.setattr(STABILITY, "stability", stability)


def _design_row(stdout: str) -> list[str]:
    row = next(line for line in stdout.splitlines() if line.startswith("│ design "))
    return [c.strip() for c in row.strip("│ ").split("│")]


@pytest.mark.parametrize(("extra", "top_rpm"), [([], "7200"), (["--max-rpm", "9600"], "9600")])
def test_a_stable_shaft_is_stable_to_the_top_speed(stable_sweep: None, extra: list[str], top_rpm: str) -> None:
    """No onset: the onset cell reads "stable to" the top analysed speed (1.5 × 4800 = 7200
    rev/min by default, or --max-rpm), no ratio to the operating speed, and the check passes
    (the requirement 1.15 × 4800 = 5520 rev/min lies below the top)."""
    result = runner.invoke(app, ["stability", "--n-speeds", "3", "--n-modes", "1", *extra])
    assert result.exit_code == 0, result.output
    cells = _design_row(result.stdout)
    assert cells[1] == f"stable to {top_rpm}"
    assert cells[2] == "—"  # onset / operating: no onset, no ratio
    assert cells[-1] == "PASS"
    assert f"analysed to {top_rpm} rpm" in result.stdout
