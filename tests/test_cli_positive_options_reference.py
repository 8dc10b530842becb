"""Options that take a positive quantity refuse zero and negatives as "must be positive".

README: exit code 2 is "a user error", and "Bad input is refused before any computation with a
message naming the field, the value and what is allowed". An option that must be above
zero (``stability --max-rpm``: the top of a speed sweep; ``--reference-hz``: the speed of a
reference frequency; ``--gap``: an actuator gap) used to be checked as ``>= 1e-09`` and the
message said so ("must be >= 1e-09 (got 0)"), a bound the user never chose. The references are
the rule itself: zero and negatives refused, the smallest positive double accepted.

No analysis runs: the checks come before any model is built (milliseconds).
"""

from __future__ import annotations

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.cli.common import UserError, check_finite

runner = CliRunner()


@pytest.mark.parametrize("bad", [0.0, -0.0, -1.0])
def test_a_positive_option_refuses_zero_and_negatives_saying_positive(bad):
    with pytest.raises(UserError, match=r"^--max-rpm: must be positive \(got -?[01]\)$"):
        check_finite("--max-rpm", bad, positive=True)


def test_a_positive_option_accepts_the_smallest_positive_number():
    assert check_finite("--gap", 5e-324, positive=True) == 5e-324  # just above the open bound


@pytest.mark.parametrize(("option", "value"), [("--max-rpm", "0"), ("--reference-hz", "-1")])
def test_stability_refuses_a_non_positive_sweep_bound_with_exit_2(option, value):
    result = runner.invoke(app, ["stability", option, value])
    assert result.exit_code == 2
    assert f"{option}: must be positive (got {value})" in result.output
    assert "1e-09" not in result.output


@pytest.mark.parametrize("value", ["1e-300", "0.000999"])
def test_stability_refuses_a_reference_frequency_below_its_floor(value):
    """docs/limits.md: "`flexshaft stability --reference-hz` takes at least 0.001 Hz" (the
    viscous model's damping η K/ω_ref grows as 1/ω_ref; 1e-200 Hz ended in an internal error,
    exit 4, in the eigen-solver). Refused with exit 2 before the design is loaded."""
    result = runner.invoke(app, ["stability", "--damping-model", "viscous", "--reference-hz", value])
    assert result.exit_code == 2
    message = " ".join(result.output.split())
    assert "--reference-hz: at least 0.001 Hz" in message and f"(got {float(value):g})" in message


def test_the_stability_api_holds_the_same_floor():
    """docs/limits.md: the floor holds in the Python API as well: ``stability(..., "viscous",
    reference_frequency)`` refuses ω_ref below 2π·0.001 rad/s with a RefusedInputError naming
    the argument (at 1e-300 rad/s LAPACK's eigen-solver failed with "illegal value", an error
    that named nothing). The tests' Jeffcott rotor (tests/rotors.py), one speed: milliseconds."""
    import math

    from rotors import jeffcott

    from flexshaft.analyses.guards import RefusedInputError
    from flexshaft.analyses.stability import stability
    from flexshaft.units import hz_to_rpm, rpm_to_rad_s

    model = jeffcott(0.01, 10.0)
    for omega_ref in (1e-300, 2 * math.pi * 0.000999):
        with pytest.raises(RefusedInputError, match=r"^reference_frequency must be >= 0\.00628319 rad/s"):
            stability(model, [100.0], 2, "viscous", omega_ref)
    # the floor itself is taken, however 0.001 Hz is converted: the command's way (through rpm,
    # 0.006283185307179586 rad/s) and 2π·0.001 (0.006283185307179587) differ in the last digit
    for omega_ref in (rpm_to_rad_s(hz_to_rpm(0.001)), 2 * math.pi * 0.001):
        assert stability(model, [100.0], 2, "viscous", omega_ref).speeds.size == 1


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["runup", "--duration", "0"], "--duration: must be >= 0.001 s (got 0)"),
        (["runup", "--dwell", "4000"], "--dwell: must be <= 3600 s (got 4000)"),
        (["montecarlo", "--grade", "0"], "--grade: must be >= 0.001 mm/s (got 0)"),
        (["montecarlo", "--force-limit", "0"], "--force-limit: must be >= 1e-06 N (got 0)"),
        (["modes", "--speed-rpm", "-3"], "--speed-rpm: must be >= 0 rpm (got -3)"),
    ],
    ids=["duration", "dwell", "grade", "force limit", "speed"],
)
def test_a_bound_is_given_in_the_options_unit(args, words):
    """What is allowed comes with its unit, the one each option's help names (the help texts
    are the API contract: "[s]", "Balance quality grade G [mm/s]", "[N]", "[rpm]"): "must be >=
    0.001" alone left the user to guess seconds or minutes. Refused before any computation."""
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    assert words in " ".join(result.output.split())
