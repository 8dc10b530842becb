"""The caps of a command's work and of its arguments, against the documented rules.

* Memory: docs/limits.md section 7 refuses every command "above ... **2 GiB** (estimated)",
  exit 2. At the boundary: an estimate of exactly 2 GiB = 2 × 1024³ bytes runs, one byte more is
  refused. On a real path: the spin-up map keeps 4096 bytes per speed and shaft node (its
  measured 3.5 kB, bounds module), and docs/limits.md records what 20,000 speeds did before the
  bound: it "held 2.6 GiB after 180 s". The estimate 4096 × 20,000 × n B exceeds 2 GiB for
  n > 2 × 1024³ / (4096 × 20,000) = 26.2 shaft nodes, which the baseline's 36 shaft elements
  (at least 37 nodes) give, and stays below a cap mistaken as 16 GiB up to 209 nodes: refused
  for its memory (with 2 gains, 4 pairs, the time stays far below 10 minutes, so the memory
  alone decides).
* Workers: the resumable commands are capped at 4 hours per worker, "(`--jobs`, counted up to
  the machine's CPUs, or the Dask cluster's threads)" (docs/limits.md section 7): more processes
  than CPUs do not shorten the run. On a machine of 2 CPUs, ``--jobs 64`` counts 2 workers.
  docs/limits.md: ``optimize --budget 100000`` is "refused: about 173 h on 1 worker"; on 2
  workers that is about 86 h, still far above 4 h, while dividing it by 64 workers (2.7 h) would
  pass. The CPUs are set to 2 by a stand-in for the affinity count, so that the test reads the
  same on any machine.
* Arguments: "A bad design file or argument gets a message naming the field, the value and what
  is allowed, before any computation; never ... a silent NaN" (project rules; README: exit 2 for
  a user error). An infinite number is no finite argument: ``--reference-hz inf`` (a lower bound
  only, no upper bound that would refuse it on the way) is refused, naming the option, before
  the design is read.

No analysis is run: the baseline's mesh is counted (problem_size) and nothing else (< 0.5 s).
"""

from __future__ import annotations

import math

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app, bounds
from flexshaft.cli.bounds import check_optimize, check_spinup_map, workers_of
from flexshaft.cli.common import UserError, check_finite
from flexshaft.design import embedded_design

GIB = 1024**3


def test_memory_cap_is_two_gib_at_its_edge() -> None:
    """An estimate of exactly 2 GiB runs; 2 GiB + 1 byte is refused, naming the allowed 2 GiB
    (docs/limits.md section 7: refused "above ... 2 GiB"). The time is 0 s, so only the memory
    decides."""
    bounds._refuse_if_large("work", 0.0, 2.0 * GIB, "change it")
    with pytest.raises(UserError) as refused:
        bounds._refuse_if_large("work", 0.0, 2.0 * GIB + 1.0, "change it")
    assert "of memory (allowed: 2 GiB)" in str(refused.value)


def test_spinup_map_of_twenty_thousand_speeds_refused_for_memory() -> None:
    """4096 B × 20,000 speeds × n shaft nodes > 2 GiB for 27 ≤ n ≤ 209 (module docstring):
    refused for its memory, naming --n-speeds (docs/limits.md: 20,000 speeds held 2.6 GiB)."""
    design = embedded_design("baseline")
    assert 27 <= bounds._model_size(design).shaft_nodes <= 209  # the range the bound above needs
    with pytest.raises(UserError) as refused:
        check_spinup_map(design, 2, 20000)
    message = str(refused.value)
    assert "of memory (allowed: 2 GiB)" in message
    assert "--n-speeds" in message
    assert "take about" not in message  # the time is within 10 minutes: the memory decides


def test_jobs_count_up_to_the_cpus(monkeypatch) -> None:
    """On 2 CPUs, --jobs 64 counts 2 workers and --jobs 1 one (docs/limits.md section 7)."""
    import flexshaft.parallel.pool as pool

    monkeypatch.setattr(pool, "available_cpus", lambda: 2)
    assert workers_of(64, None) == 2
    assert workers_of(1, None) == 1


def test_optimize_budget_not_shortened_by_more_jobs_than_cpus(monkeypatch) -> None:
    """optimize --budget 100000 (about 173 h on 1 worker, docs/limits.md) with --jobs 64 on 2
    CPUs is about 86 h per worker: refused, counted on 2 workers (4 h allowed)."""
    import flexshaft.parallel.pool as pool

    monkeypatch.setattr(pool, "available_cpus", lambda: 2)
    with pytest.raises(UserError) as refused:
        check_optimize(embedded_design("baseline"), 100000, "verdict", workers_of(64, None))
    message = str(refused.value)
    assert "on 2 worker(s) (allowed: 4 h)" in message


@pytest.mark.parametrize("value", [math.inf, -math.inf, math.nan])
def test_non_finite_argument_refused_naming_the_option(value: float) -> None:
    """Infinity and NaN are refused as not finite, even with no upper bound to refuse +inf."""
    with pytest.raises(UserError) as refused:
        check_finite("--reference-hz", value, 1e-9)
    assert str(refused.value).startswith("--reference-hz: must be a finite number")


def test_stability_refuses_an_infinite_reference_frequency() -> None:
    """``stability --reference-hz inf``: exit 2, naming the option and that it must be finite,
    no traceback, no internal error (README: exit codes)."""
    result = CliRunner().invoke(app, ["stability", "--reference-hz", "inf"])
    assert result.exit_code == 2, (result.exit_code, result.output)
    assert "--reference-hz: must be a finite number (got inf)" in result.stderr
    assert "Traceback" not in result.output and "internal error" not in result.stderr
