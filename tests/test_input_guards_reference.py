"""The analyses' input guards (flexshaft.analyses.guards) at and just beyond each documented bound.

References are the guards' own documented contracts (their docstrings), checked with inputs
picked by hand, never with a number the code printed:

* ``check_speed``: "A finite real number >= 0 (> 0 with ``positive``)", the message naming the
  argument, its value and what is allowed (module docstring: "a ``ValueError`` naming the
  argument, its value and what is allowed").
* ``check_spin_speed`` / ``check_spin_speeds``: "at most MAX_SPEED", the design limit of 10^6
  rev/min = 10^6 · 2π/60 rad/s = 104,719.755... rad/s (derived); the speeds "finite, >= 0 ...
  non-empty ... strictly increasing with ``increasing``".
* ``check_count``: "An integer >= ``minimum`` (an integral float is accepted)".
* ``require_finite``: "Raise NonFiniteResultError when the result ``value`` holds NaN or inf"
  (a complex result such as an eigenvalue array included: NaN in its real or imaginary part).

No model is built: each check is a few float comparisons, so the file runs in milliseconds.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.guards import (
    MAX_SPEED,
    NonFiniteResultError,
    RefusedInputError,
    check_count,
    check_speed,
    check_spin_speed,
    check_spin_speeds,
    require_finite,
)

#: 10^6 rev/min in rad/s, by hand: 10^6 rev/min · 2π rad/rev / 60 s/min.
LIMIT_BY_HAND = 1e6 * 2 * math.pi / 60


def test_the_speed_limit_is_a_million_rev_per_min():
    # Two roundings of the same product: equal to a few ulp (1e-12 relative is ~4500 ulp).
    assert MAX_SPEED == pytest.approx(LIMIT_BY_HAND, rel=1e-12)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, -1e-300, -1.0])
def test_check_speed_refuses_nan_inf_and_negatives_naming_the_value(bad):
    with pytest.raises(RefusedInputError) as caught:
        check_speed(bad, name="omega")
    message = str(caught.value)
    assert message.startswith("omega must be a finite number >= 0 rad/s")
    assert f"(got {bad!r})" in message


def test_check_speed_accepts_rest_and_refuses_zero_when_positive():
    assert check_speed(0.0) == 0.0  # ">= 0": the shaft at rest is allowed
    assert check_speed(0) == 0.0
    with pytest.raises(RefusedInputError, match=r"^duration must be a finite number > 0 s \(got 0\.0\)$"):
        check_speed(0.0, name="duration", unit="s", positive=True)
    assert check_speed(1e-300, positive=True) == 1e-300  # just beyond the open bound


def test_check_spin_speed_accepts_the_limit_and_refuses_just_above():
    assert check_spin_speed(MAX_SPEED) == MAX_SPEED  # "at most"
    above = MAX_SPEED * (1 + 1e-12)
    with pytest.raises(RefusedInputError, match=r"^speed must be at most 104,720 rad/s") as caught:
        check_spin_speed(above)
    assert f"(got {above!r})" in str(caught.value)
    with pytest.raises(RefusedInputError, match="finite"):
        check_spin_speed(math.nan)


@pytest.mark.parametrize(
    "speeds",
    [[0.0, math.nan, 2.0], [math.nan], [1.0, math.inf], [1.0, -1.0, 3.0], [-1e-300]],
    ids=["nan-inside", "nan-alone", "inf", "one-negative", "tiny-negative"],
)
def test_check_spin_speeds_refuses_non_finite_and_negative_members(speeds):
    with pytest.raises(RefusedInputError, match=r"^sweep must be finite and >= 0 rad/s"):
        check_spin_speeds(speeds, name="sweep")


def test_check_spin_speeds_refuses_an_empty_sequence():
    with pytest.raises(RefusedInputError, match=r"^sweep must be a non-empty 1-D sequence"):
        check_spin_speeds([], name="sweep")


def test_check_spin_speeds_too_fast_names_the_fastest_speed():
    # 3e5 rad/s > 104,720 rad/s; the refusal shows the offending speed, not another one.
    with pytest.raises(RefusedInputError) as caught:
        check_spin_speeds([1.0, 3e5, 2.0])
    assert str(caught.value).endswith("(got 300000.0)")
    np.testing.assert_array_equal(check_spin_speeds([0.0, MAX_SPEED]), [0.0, MAX_SPEED])


def test_check_spin_speeds_strictly_increasing():
    with pytest.raises(RefusedInputError, match="^speeds must be strictly increasing$"):
        check_spin_speeds([1.0, 1.0, 2.0], increasing=True)  # a repeat is not strictly increasing
    with pytest.raises(RefusedInputError, match="strictly increasing"):
        check_spin_speeds([1.0, 3.0, 2.0, 4.0], increasing=True)  # down once inside
    np.testing.assert_array_equal(check_spin_speeds([1.0, 1.0, 2.0]), [1.0, 1.0, 2.0])  # not asked
    np.testing.assert_array_equal(check_spin_speeds([0.0, 1e-9, 2.0], increasing=True), [0.0, 1e-9, 2.0])


@pytest.mark.parametrize(
    ("value", "minimum"), [(0, 1), (2, 3), (-1, 0), (2.5, 1), (math.nan, 1), (math.inf, 1), (True, 1), ("3", 1)]
)
def test_check_count_refuses_below_the_minimum_fractions_and_non_numbers(value, minimum):
    with pytest.raises(RefusedInputError) as caught:
        check_count(value, "modes", minimum=minimum)
    assert str(caught.value) == f"modes must be an integer >= {minimum} (got {value!r})"


def test_check_count_accepts_the_minimum_and_integral_floats():
    assert check_count(1, "modes") == 1
    assert check_count(3, "steps", minimum=3) == 3
    assert check_count(0, "extra", minimum=0) == 0
    counted = check_count(2.0, "modes")
    assert counted == 2 and type(counted) is int
    assert check_count(np.int64(5), "modes") == 5


@pytest.mark.parametrize(
    "value",
    [
        np.array([1.0, math.nan]),
        np.array([math.inf]),
        np.array([1 + 1j, complex(math.nan, 0.0)]),
        np.array([complex(0.0, math.inf)]),
        complex(math.nan, 1.0),
    ],
    ids=["float-nan", "float-inf", "complex-nan-real", "complex-inf-imag", "complex-scalar"],
)
def test_require_finite_refuses_nan_and_inf_results(value):
    with pytest.raises(NonFiniteResultError, match=r"^the eigenvalues came out NaN or inf"):
        require_finite("eigenvalues", value)


def test_require_finite_passes_finite_results():
    require_finite("eigenvalues", np.array([1 + 2j, -3j]))
    require_finite("frequencies", np.array([0.0, 1e300]))
    require_finite("count", np.array([1, 2]))


def test_text_and_booleans_are_not_speeds():
    """A speed is "a finite real number" (check_speed's docstring): the text "3", the bytes b"4"
    and a list of texts are refused although float() would read them; booleans are refused in a
    list as they are alone."""
    from flexshaft.analyses.guards import RefusedInputError, check_speed, check_spin_speeds

    for value in ("3", b"4"):
        with pytest.raises(RefusedInputError, match="finite number"):
            check_speed(value)
    for values in (["1", "2"], "12", [True, False]):
        with pytest.raises(RefusedInputError, match="1-D sequence of numbers"):
            check_spin_speeds(values)
    np.testing.assert_array_equal(check_spin_speeds([1, 2.5]), [1.0, 2.5])
