"""Monte-Carlo exceedances: the exact upper confidence bound instead of "0 ± 0", where it is
shown (terminal, figure, JSON), the progress bar kept off stdout, and the run-up figure's range.

References: the closed form of the one-sided Clopper–Pearson bound with no event,
p_u = 1 − (1 − c)^(1/N); for k events the bound's defining equation, the binomial tail
Σ_{i≤k} C(N, i) p_uⁱ (1 − p_u)^(N−i) = 1 − c, summed here in exact rational arithmetic at the
bound (an independent route from the beta quantile the code uses).
"""

from __future__ import annotations

import json
from fractions import Fraction
from math import comb
from types import SimpleNamespace

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from typer.testing import CliRunner  # noqa: E402

from flexshaft.cli import app  # noqa: E402
from flexshaft.montecarlo import Exceedance, clopper_pearson_upper  # noqa: E402
from flexshaft.plot.transient import montecarlo_figure, runup_envelope_figure  # noqa: E402


@pytest.mark.parametrize("n", [1, 10, 200, 500, 100_000])
def test_upper_bound_with_no_event_is_the_closed_form(n):
    assert clopper_pearson_upper(0, n) == pytest.approx(1.0 - 0.05 ** (1.0 / n), rel=1e-12)
    assert clopper_pearson_upper(0, n, 0.99) == pytest.approx(1.0 - 0.01 ** (1.0 / n), rel=1e-12)
    # the "rule of three": 3/N for large N (within 0.2 % at N = 1e5)
    if n >= 100_000:
        assert clopper_pearson_upper(0, n) == pytest.approx(3.0 / n, rel=2e-3)


@pytest.mark.parametrize(("k", "n"), [(1, 10), (3, 200), (17, 500), (199, 200)])
def test_upper_bound_solves_the_binomial_tail_equation(k, n):
    """At p_u the probability of k or fewer events is 1 − c = 0.05 (exact rational sum of the
    binomial terms at p_u; the float p_u carries 1e-16 relative error, so 1e-10 absolute)."""
    p = Fraction(clopper_pearson_upper(k, n))
    tail = sum(comb(n, i) * p**i * (1 - p) ** (n - i) for i in range(k + 1))
    assert float(tail) == pytest.approx(0.05, abs=1e-10)
    assert clopper_pearson_upper(k, n) > k / n


def test_upper_bound_edges_and_refusals():
    assert clopper_pearson_upper(5, 5) == 1.0
    for args, match in (((-1, 5), "0 <= events"), ((6, 5), "0 <= events"), ((0, 0), "samples >= 1")):
        with pytest.raises(ValueError, match=match):
            clopper_pearson_upper(*args)
    with pytest.raises(ValueError, match="whole numbers"):
        clopper_pearson_upper(0.5, 10)
    with pytest.raises(ValueError, match="confidence"):
        clopper_pearson_upper(0, 10, 1.0)


def test_exceedance_reports_a_bound_not_zero_plus_minus_zero():
    none = Exceedance(0, 200)
    assert none.probability == 0.0 and none.standard_error == 0.0
    assert none.describe() == "0 of 200 samples: P < 0.0149 (95 % upper bound)"
    some = Exceedance(3, 200)
    assert some.describe() == "3 of 200 samples: P = 0.015, < 0.0383 (95 % upper bound)"
    data = none.to_dict()
    assert data["events"] == 0 and data["samples"] == 200
    assert data["upper_bound"] == pytest.approx(1 - 0.05 ** (1 / 200), rel=1e-12)


def _samples(excursion_mm, load_n):
    xr = pytest.importorskip("xarray")
    n = len(excursion_mm)
    return xr.Dataset(
        {
            "shaft_peak": ("sample", np.linspace(1e-4, 3e-4, n)),
            "safety_factor": ("sample", np.linspace(30.0, 31.0, n)),
            "actuator_excursion_max": ("sample", np.asarray(excursion_mm) * 1e-3),
            "actuator_load_max": ("sample", np.asarray(load_n, dtype=float)),
        }
    )


def test_figure_marks_each_limits_count_and_upper_bound():
    n = 50
    ds = _samples(np.r_[np.full(n - 2, 0.3), 0.6, 0.7], np.full(n, 200.0))  # 2 over the gap, none over the force
    events = {"gap": (2, n, clopper_pearson_upper(2, n)), "force": (0, n, clopper_pearson_upper(0, n))}
    fig = montecarlo_figure(ds, gap=5e-4, force_limit=1500.0, exceedances=events)
    _, _, gap_panel, force_panel = fig.axes
    for panel, limit, (k, _, upper) in ((gap_panel, 0.5, events["gap"]), (force_panel, 1500.0, events["force"])):
        (mark,) = [ln for ln in panel.get_lines() if ln.get_marker() == "v"]
        assert mark.get_xdata()[0] == pytest.approx(limit) and mark.get_ydata()[0] == pytest.approx(upper)
        (text,) = [t.get_text() for t in panel.texts]
        assert text.startswith(f"{k} of {n} samples exceed") and f"{upper:.3g}" in text
    assert "P < 0.0582 (95 % upper bound)" in force_panel.texts[0].get_text()  # 1 − 0.05^(1/50)


class _Limits(SimpleNamespace):
    pass


def test_result_counts_each_bearing_against_its_own_limit():
    from flexshaft.montecarlo.steady import MonteCarloResult

    xr = pytest.importorskip("xarray")
    ds = xr.Dataset(
        {
            "actuator_excursion_a": ("sample", [1e-4, 6e-4, 1e-4, np.nan]),
            "actuator_excursion_b": ("sample", [1e-4, 1e-4, 3e-4, 1e-4]),
            "actuator_load_a": ("sample", [10.0, 10.0, 10.0, 10.0]),
            "actuator_load_b": ("sample", [10.0, 10.0, 10.0, 10.0]),
        }
    )
    limits = {"a": _Limits(gap=5e-4, force_capacity=100.0), "b": _Limits(gap=2e-4, force_capacity=None)}
    result = MonteCarloResult(ds, limits)
    assert (result.gap_events.events, result.gap_events.samples) == (2, 3)  # the NaN sample is left out
    assert (result.force_events.events, result.force_events.samples) == (0, 4)
    assert result.force_exceedance == (0.0, 0.0)
    assert result.force_events.upper_bound() == pytest.approx(1 - 0.05 ** (1 / 4))


SMALL = """
name = "two-bay rotor"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7850.0
loss_factor = 0.002
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = { v = 5e7, w = 5e7 }
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
kp = 2e6
kd = 200.0
gap = 1.0e-3
force_capacity = 1.0e4
[[bearings]]
name = "right"
kind = "contact"
x = 2.0
stiffness = { v = 5e7, w = 5e7 }
[operating]
speed_rpm = 6000.0
power = 0.0
[loads]
eccentricity = 10e-6
[mesh]
shaft_elements = 6
"""


def test_cli_prints_the_bound_and_keeps_the_progress_bar_off_stdout(tmp_path):
    """Not on a terminal (the runner's streams are not TTYs): no progress bar anywhere, the
    bound in the terminal lines and in the JSON."""
    design = tmp_path / "two_bay.toml"
    design.write_text(SMALL, encoding="utf-8")
    runner = CliRunner()
    args = ["montecarlo", str(design), "--samples", "10", "--grade", "6.3"]
    plain = runner.invoke(app, [*args, "--out", str(tmp_path / "a")])
    assert plain.exit_code == 0, plain.output
    assert "chunks" not in plain.stdout and "━" not in plain.stdout and "━" not in plain.stderr
    bound = f"{1 - 0.05 ** (1 / 10):.3g}"
    assert f"N exceeded (static + dynamic) in 0 of 10 samples: P < {bound} (95 % upper bound)" in plain.stdout
    assert "± 0" not in plain.stdout
    as_json = runner.invoke(app, [*args, "--out", str(tmp_path / "b"), "--json"])
    assert as_json.exit_code == 0, as_json.output
    data = json.loads(as_json.stdout)
    assert data["force_exceedance"]["events"] == 0 and data["force_exceedance"]["samples"] == 10
    assert data["force_exceedance"]["upper_bound"] == pytest.approx(1 - 0.05 ** (1 / 10), rel=1e-12)


def test_runup_axes_span_three_decades_below_each_panels_peak():
    """A run from rest starts at 1e-9 of its peak: each log axis shows 3 decades below the
    largest value drawn in its panel (limit lines included), not the whole range."""
    t = np.linspace(0.0, 1.0, 201)  # holds t = 0.6, the peak
    speed = 500.0 * t
    shape = 1e-9 + np.exp(-(((t - 0.6) / 0.05) ** 2))
    run = SimpleNamespace(
        speed=speed,
        shaft_peak=2e-3 * shape,  # peak 2 mm
        actuator_displacement=np.vstack([1e-4 * shape, 0.5e-4 * shape]),  # peak 0.1 mm
        actuator_force=np.vstack([50.0 * shape, 20.0 * shape]),  # peak 50 N
    )
    fig = runup_envelope_figure({"run": run}, operating_rpm=4000.0, gap=5e-4)
    shaft, orbit, force = fig.axes
    assert shaft.get_ylim() == pytest.approx((2.0e-3, 4.0), rel=1e-6)  # mm: peak 2, 3 decades below
    assert orbit.get_ylim() == pytest.approx((0.5e-3, 1.0), rel=1e-6)  # the 0.5 mm gap line is the top
    assert force.get_ylim() == pytest.approx((50e-3, 100.0), rel=1e-6)
    with pytest.raises(ValueError, match="decades"):
        runup_envelope_figure({"run": run}, decades=0.0)
