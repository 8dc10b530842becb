"""What a command's bound refusals name, and --json's non-finite numbers, against the docs.

* Run-up samples (docs/limits.md, the run-up: "more than 200,000 output samples (8 per period of
  the fastest envelope content: at most 312.5 s at 4800 rpm)"; ``flexshaft runup --help``: "8 per
  revolution at the top speed"). The output step at a top speed of N rpm is therefore
  Δt = 60 / (8 N) s (4800 rpm: 1.5625 ms, and 199,999 × 1.5625 ms ≈ 312.498 s, printed 312.5 s
  (docs/limits.md)). The refusal names the top speed in rpm as the user gave it (the larger of
  --start-rpm and --stop-rpm), the samples and the longest run 199,999 Δt. A run of
  T = duration + dwell has samples at t = 0 and t = T and every Δt between: ceil(T / Δt) + 1 of
  them. T is chosen so that T / Δt is not whole, 0.2 sample or more from the nearest integer (at
  a whole quotient floor gives the same count as ceil, and a Δt rounded one ulp low one sample
  more):

  - ``--stop-rpm 3000 --duration 10.001 --dwell 3600``: Δt = 2.5 ms, T / Δt = 3610.001 / 0.0025
    = 1,444,000.4, so ceil(1,444,000.4) + 1 = 1,444,002 samples; at most
    199,999 × 0.0025 = 499.9975 s, printed "500 s" (4 digits);
  - ``--start-rpm 6000 --stop-rpm 100`` (a run-down, the top speed is the start), the same times:
    Δt = 1.25 ms, T / Δt = 3610.001 / 0.00125 = 2,888,000.8, so ceil(2,888,000.8) + 1 =
    2,888,002 samples; at most 199,999 × 0.00125 = 249.99875 s, printed "250 s".

  The exact sample counts hold at any mesh: they depend on the speeds and times only.
* Optimizer budget: docs/optimizer.md's fidelity table, ``verdict`` 651 unbalance speeds and 41
  whirl speeds, ``screening`` 261 and 21, measured 0.33 s and 0.25 s an evaluation; the
  refusal's own advice is "use --fidelity screening". So the per-evaluation estimate at the
  screening fidelity is below the verdict one (an ordering, no number of the code's copied), and
  a budget is priced at the fidelity it names.
* README, "--json": "Infinite or undefined numbers are `null`" (strict JSON, RFC 8259, has no
  Infinity or NaN; docs/optimizer.md: a best margin "`inf` (`null` in JSON)"). The data every
  --json is made into (``json_ready``) holds them as None, and the printer every --json goes
  through prints them as null, as Python floats and as numpy scalars.

No analysis is run: the run-up builds the baseline's model (< 0.3 s) and is refused before
integrating; the optimizer bound counts the design (problem_size).
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.bounds import check_optimize
from flexshaft.cli.common import UserError, json_ready, print_json
from flexshaft.design import embedded_design

runner = CliRunner()


@pytest.mark.parametrize(
    "speeds, top_rpm, samples, longest",
    [
        (["--stop-rpm", "3000"], "3000 rpm", "1,444,002 output samples", "at most 500 s"),
        (["--start-rpm", "6000", "--stop-rpm", "100"], "6000 rpm", "2,888,002 output samples", "at most 250 s"),
    ],
    ids=["run-up to 3000 rpm", "run-down from 6000 rpm"],
)
def test_runup_sample_refusal_names_the_top_speed_in_rpm(speeds, top_rpm, samples, longest, tmp_path) -> None:
    """Exit 2 (docs/limits.md: refused before integrating), naming the top speed the user gave in
    rpm, the samples ceil(T / Δt) + 1 at Δt = 60 / (8 N) and the longest run 199,999 Δt (module
    docstring)."""
    out = tmp_path / "o"
    result = runner.invoke(app, ["runup", *speeds, "--duration", "10.001", "--dwell", "3600", "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert f"up to {top_rpm} would give" in result.output, result.output
    assert samples in result.output, result.output
    assert longest in result.output, result.output
    assert not out.exists()


def _seconds_each(message: str) -> float:
    """The per-evaluation time of an optimizer refusal ("about 4.7 s each", "about 1.2 min each")."""
    found = re.search(r"about ([0-9.e+]+) (s|min|h) each", message)
    assert found, message
    return float(found.group(1)) * {"s": 1.0, "min": 60.0, "h": 3600.0}[found.group(2)]


def _refusal(fidelity: str) -> str:
    with pytest.raises(UserError) as refused:
        # 100,000 evaluations on one worker: refused at either fidelity (docs/optimizer.md measured
        # 0.33 s and 0.25 s an evaluation: 100,000 × 0.25 s ≈ 6.9 h, above docs/limits.md's 4 hours
        # per worker, and the estimates err on the slow side)
        check_optimize(embedded_design("baseline"), 100_000, fidelity, 1)
    return str(refused.value)


def test_optimizer_budget_priced_at_the_fidelity_it_names() -> None:
    """The screening refusal names the screening fidelity and costs each evaluation less than the
    verdict one (docs/optimizer.md: 261 against 651 unbalance speeds, 21 against 41 whirl speeds,
    0.25 s against 0.33 s measured)."""
    verdict, screening = _refusal("verdict"), _refusal("screening")
    assert "at the verdict fidelity" in verdict and "at the screening fidelity" in screening
    assert _seconds_each(screening) < _seconds_each(verdict), (screening, verdict)


def test_json_prints_infinite_and_undefined_numbers_as_null(capsys) -> None:
    """README: "Infinite or undefined numbers are `null`": first the data every --json is made of
    (``json_ready``) holds None for them, a value check; then the printer writes strict JSON that
    a strict parser reads back; finite numbers unchanged."""
    data = {
        "best_margin": float("inf"),
        "peak_m": float("nan"),
        "onset_rpm": np.float64(-np.inf),
        "frequency_Hz": [1.5, np.float64(np.nan)],
        "mass_kg": 2.25,
    }
    expected = {"best_margin": None, "peak_m": None, "onset_rpm": None, "frequency_Hz": [1.5, None], "mass_kg": 2.25}
    assert json_ready(data) == expected
    print_json(data)
    text = capsys.readouterr().out

    def strict(constant: str):
        raise AssertionError(f"{constant} is not JSON")

    assert json.loads(text, parse_constant=strict) == expected
