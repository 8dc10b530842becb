"""A design whose ``[operating]`` gives ``speed`` [rad/s] instead of ``speed_rpm`` runs through
every command as the same design in rpm does.

The schema accepts either key (the ``[operating]`` table's documented keys, Operating:
"exactly one of ``speed_rpm`` [rev/min] or ``speed`` [rad/s]").
Was: ``run`` (with its thesis studies, the default), ``study all``, ``study spinup-map`` and
``montecarlo --grade`` compared ``operating.speed_rpm > 0`` before any computation, and with
``speed`` given that key is None: each stopped with "internal error: TypeError" (exit 4); and an
envelope point keeping the design's speed had no rpm for results.json and the report's table.

References: 1 rpm = 2π/60 rad/s (the minute and the revolution), so 502.6548245743669 rad/s
(= 4800 · 2π/60 to the last digit printed by repr) is 4800 rpm to round-off (rel 1e-15: one
multiplication and one division). The commands' guards are stopped where each has accepted the
design and starts its size check (replaced here by a clean exit 7 that records its input), so no
analysis runs: about 0.1 s a command.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest
import typer
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import design_from_dict, embedded_design
from flexshaft.optimize.files import write_design_file

RAD_S = 4800.0 * 2.0 * math.pi / 60.0


def _in_rad_s(speed: float):
    data = copy.deepcopy(embedded_design("tuned").model_dump())
    data["operating"]["speed_rpm"], data["operating"]["speed"] = None, speed
    if speed == 0.0:  # at rest: no power (P/Ω), and the envelope's points keep the design's speed
        data["operating"]["power"], data["envelope"] = 0.0, None
    return design_from_dict(data)


def test_the_operating_speed_in_rpm_is_the_rad_s_one_converted():
    assert _in_rad_s(RAD_S).operating.rpm == pytest.approx(4800.0, rel=1e-15)
    assert embedded_design("tuned").operating.rpm == 4800.0  # as written


@pytest.mark.parametrize(
    "command, guard",
    [
        (["run"], "flexshaft.assembly.size.check_problem_size"),
        (["study", "all"], "flexshaft.assembly.size.check_problem_size"),
        (["study", "spinup-map"], "flexshaft.cli.bounds.check_spinup_map"),
        (["montecarlo", "--grade", "6.3", "--samples", "10"], "flexshaft.cli.bounds.check_montecarlo"),
    ],
)
def test_a_design_in_rad_s_reaches_the_size_check(tmp_path: Path, monkeypatch, command, guard):
    seen = []

    def stop(design, *args, **kwargs):
        seen.append((design.operating.speed_rad_s, args))
        raise typer.Exit(7)

    module, name = guard.rsplit(".", 1)
    monkeypatch.setattr(module + "." + name, stop)
    path = write_design_file(_in_rad_s(RAD_S), tmp_path / "rad_s.toml")
    result = CliRunner().invoke(app, [*command, str(path), "-o", str(tmp_path / "out")])
    assert result.exit_code == 7, result.output
    assert "internal error" not in result.output
    assert seen and seen[0][0] == RAD_S
    if command == ["run"]:  # the thesis studies kept: the run-sized check, not the assessment's
        assert seen[0][1][0] == "run"


def test_a_design_at_rest_in_rad_s_is_refused_by_the_studies(tmp_path: Path):
    path = write_design_file(_in_rad_s(0.0), tmp_path / "rest.toml")
    result = CliRunner().invoke(app, ["study", "all", str(path), "-o", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    assert "operating speed" in result.output
