"""The data the run report's thermal and gain-map figures are handed, and the sentence stating a
check that governs at another point (report/run_sections.py), on hand-built stand-ins.

References (derived, by hand, from the figures' own axes and the docs):

* Shaft temperature figure (plot/thermal.py's axes: "T − T_air [K]" and "heat generated
  [W/m]"): the rise is each node's temperature less the shaft's air temperature (docs/thermal.md:
  "the boom's hover skin temperature, the shaft's air in operation", here 313.15 K, not the
  303.15 K ambient); an element's heat per length is its
  heat over its length, drawn at its midpoint. Nodes x = 0, 0.5, 2 m (elements 0.5 m and 1.5 m,
  so W and W/m differ), heats 2 W and 3 W: 4 W/m at 0.25 m and 2 W/m at 1.25 m; temperatures
  315, 320, 316 K: rises 1.85, 6.85, 2.85 K.
* Gain map figure ("Onset speed against the actuator gains", an rpm axis): Ω = 2π·N/60 rad/s
  is N rpm, so onsets 2π·4000/60 and 2π·5000/60 rad/s are 4000 and 5000 rpm, the top speed
  2π·9000/60 rad/s 9000 rpm.
* docs/requirements.md ("Where the points show"): the thermal section "names that point and
  states the temperature check's own value and point when it governs elsewhere". A check of
  value 358.15 K = 85.0 °C (°C = K − 273.15), limit ≤ 373.15 K = 100.0 °C and margin 15 K at
  ``hot_soak_start``, beside the governing point ``cold_day``: the sentence states 85.0 °C and
  ≤ 100.0 °C, not the margin.

Every value is exact to rounding: rel 1e-12 (measured ≤ 1.3e-14 (the rise 315 − 313.15
cancels: up to about 170·eps); conversions ≤ 2e-16). The figures are only recorded as jobs
(never drawn): CPU about 10 ms.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np
import pytest
from test_report_sections_tables_reference import UNREAD_POINT, _rad_s, _result, _thermal, _unread, one_point

from flexshaft.report.run_sections import Figures, stability_section, thermal_section


def _uneven_shaft():
    return NS(
        temperature=NS(
            x=np.array([0.0, 0.5, 2.0]),
            temperature=np.array([315.0, 320.0, 316.0]),
            air_temperature=313.15,
            heat_transfer_coefficient=25.0,
        ),
        sources=NS(total=np.array([2.0, 3.0]), vibration=np.array([1.5, 2.0]), static=np.array([0.5, 1.0])),
        peak_rise=6.85,
    )


def _self_heating():
    return NS(status="converged", iterations=4, margin=12.5, max_temperature=353.15)


def test_shaft_temperature_figure_rise_above_air_and_heat_per_metre_at_midpoints(tmp_path):
    figs = Figures(tmp_path)
    thermal = _thermal({"rotating": _uneven_shaft()}, _self_heating())
    assert thermal.environment.ambient_temperature != 313.15  # the premise: ambient is not the air
    thermal_section(one_point(thermal=thermal), figs)
    (job,) = [j for j in figs.jobs if j.stem == "shaft_temperature"]
    x, rise, xe, heat = job.args
    np.testing.assert_array_equal(x, [0.0, 0.5, 2.0])
    assert list(rise) == ["rotating loss model"] and list(heat) == ["rotating loss model"]
    np.testing.assert_allclose(rise["rotating loss model"], [1.85, 6.85, 2.85], rtol=1e-12)
    np.testing.assert_allclose(xe, [0.25, 1.25], rtol=1e-12)
    np.testing.assert_allclose(heat["rotating loss model"], [4.0, 2.0], rtol=1e-12)


def temperature_verdict(value: float, margin: float, point: str = "hot_soak_start"):
    """A stand-in verdict whose only check is the temperature's, ``value`` [K] against a 373.15 K
    allowable with ``margin`` [K], governing at ``point``."""
    check = NS(
        title="Shaft temperature",
        kind="temperature",
        sense="at most",
        value=value,
        limit=373.15,
        margin=margin,
        location={"point": point},
    )

    def by_key(key):
        if key != "temperature":
            raise KeyError(key)
        return check

    return NS(check=by_key)


def test_thermal_section_states_the_temperature_checks_value_where_it_governs(tmp_path):
    a = NS(
        points=("cold_day", "hot_soak_start"),
        governing_point="cold_day",
        point=lambda name: UNREAD_POINT,
        verdict=temperature_verdict(358.15, 15.0),
        thermal=_thermal({"rotating": _uneven_shaft()}, _self_heating()),
    )
    text = " ".join(thermal_section(a, Figures(tmp_path)).paragraphs)
    assert "Self-heating at cold_day" in text
    assert "The Shaft temperature check governs at hot_soak_start: 85.0 °C (required ≤ 100.0 °C)." in text


PD = NS(kind="active", kp=2e5, kd=15.0, controller=None)


@pytest.mark.parametrize(
    ("active", "expected"),
    [
        ((PD, PD), (15.0, None)),  # both K_p 2e5, K_d 15: the design's point, stable (None: at the map's top)
        ((PD, NS(kind="active", kp=2e5, kd=30.0, controller=None)), None),  # two K_d: no one point
        ((PD, NS(kind="active", kp=2e5, kd=15.0, controller=object())), None),  # a controller: no (K_p, K_d)
    ],
    ids=["same-gains", "two-kd", "controller"],
)
def test_gain_map_figure_onsets_and_top_speed_in_rpm(tmp_path, active, expected):
    speeds = np.array([_rad_s(1000), _rad_s(3000), _rad_s(6000)])
    a = NS(
        points=(),
        verdict=NS(check=_unread),
        stability=_result(None, speeds),
        modes_at_speed=None,
        model=NS(speed=_rad_s(4800)),
        design=NS(
            requirements=NS(required_log_decrement=0.1, min_onset_margin=0.15), bearings=[NS(kind="contact"), *active]
        ),
        roots=NS(
            coverage=lambda: "every root",
            speeds=speeds[:1],
            n_roots=np.array([12]),
            least_damping_ratio=np.array([0.05]),
            unstable_counts=np.array([0]),
        ),
    )
    gain_map = NS(
        kp=np.array([1e5, 2e5]),
        kd=np.array([10.0, 20.0]),
        onset_speed=np.array([_rad_s(4000), _rad_s(5000)]),
        max_speed=_rad_s(9000),
        margin_at_operating=np.array([[0.01, 0.02], [0.03, 0.04]]),
    )
    figs = Figures(tmp_path)
    stability_section(a, NS(shaft_comparison={}, gain_map=gain_map), figs, 4800.0)
    (job,) = [j for j in figs.jobs if j.stem == "stability_map"]
    kd, onset, op_rpm, top_rpm = job.args
    np.testing.assert_array_equal(kd, [10.0, 20.0])
    assert list(onset.values()) == [pytest.approx(4000.0, rel=1e-12), pytest.approx(5000.0, rel=1e-12)]
    assert op_rpm == 4800.0 and top_rpm == pytest.approx(9000.0, rel=1e-12)
    # the whirl-onset check's requirement, (1 + min_onset_margin) × the operating speed
    # (docs/requirements.md), 1.15 × 4800 = 5520 rpm; the design's own gains at its onset
    # when every active bearing has the same PD gains
    assert job.kwargs["required_rpm"] == pytest.approx(5520.0, rel=1e-12)
    if expected is None:
        assert job.kwargs["design"] is None
    else:
        kd_design, onset_design, label = job.kwargs["design"]
        assert (kd_design, onset_design) == expected and "K_p = 2e+05 N/m" in label
