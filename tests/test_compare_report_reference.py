"""The ``flexshaft compare`` report's values and tables (report/compare.py) on hand-built inputs.

A stand-in comparison (plain namespaces with the attributes the sections read, SI values) whose
displayed values are converted by hand from the unit definitions (derived): °C = K − 273.15;
rpm = 60·Ω/(2π), so Ω = 2π·N/60 rad/s shows as N rpm; a fraction f shows as 100·f %; 1 MPa =
1e6 Pa. Design A's and design B's inputs are distinct, so a value in the other design's column
(or a neighbour's column) is seen. Figures are replaced by a stub that draws nothing. CPU about
0.01 s.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace as NS

import numpy as np

from flexshaft.report import compare
from flexshaft.report.compare import format_metric


def _rad_s(rpm: float) -> float:
    return 2.0 * math.pi * rpm / 60.0


def test_temperature_in_celsius_and_a_lower_bound_as_greater_than():
    """353.15 K is 80.0 °C; a whirl onset beyond the top of the scan (6000 rpm) is "> 6000 rpm"."""
    assert format_metric("shaft_temperature", "K", 353.15) == "80.0 °C"
    assert format_metric("whirl_onset", "rad/s", _rad_s(6000.0), lower_bound=True) == "> 6000 rpm"


def _check(value, margin, limit=1.5, sense="at least", station=1.0):
    return NS(
        key="strength",
        title="strength safety factor",
        kind="plain",
        value=value,
        margin=margin,
        limit=limit,
        sense=sense,
        status="pass" if margin >= 0 else "fail",
        lower_bound=False,
        location={"station": station},
        note="",
    )


def _verdict_comparison():
    a = _check(2.0, 0.5, station=1.0)  # design A: R = 2 at x = 1 m
    b = _check(1.2, -0.3, station=2.5)  # design B: R = 1.2 at x = 2.5 m, fails
    checks = ({"strength": a}, {"strength": b})
    runs = (NS(verdict=NS(summary="A: PASS")), NS(verdict=NS(summary="B: FAIL")))
    return NS(labels=("A", "B"), runs=runs, check_keys=("strength",), check=lambda key, d: checks[d].get(key))


def test_verdict_row_keeps_each_design_in_its_columns_and_a_minimum_as_at_least():
    """Limit "≥ 1.5" (a minimum), A: 2 (+0.5, PASS), B: 1.2 (−0.3, FAIL), where "x = 1.00 m / x = 2.50 m"."""
    section = compare._verdict_section(_verdict_comparison())
    ((row,),) = [t.rows for t in section.tables]
    assert row == [
        "strength safety factor",
        "≥ 1.5",
        "2",
        "+0.5",
        "PASS",
        "1.2",
        "-0.3",
        "FAIL",
        "x = 1.00 m / x = 2.50 m",
    ]


def _stub_figures(monkeypatch):
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    for name in ("campbell_overlay_figure", "spinup_overlay_figure", "safety_factor_overlay_figure"):
        monkeypatch.setattr(compare, name, lambda *args, **kwargs: None)


def test_critical_speed_rows_margin_then_required(monkeypatch, tmp_path):
    """A critical at 3000 rpm, AF 4, margin 0.25 (25.0 %) against 0.12 (12.0 %) required, at x = 0.75 m (750 mm)."""
    _stub_figures(monkeypatch)
    run = NS(
        model=NS(speed=_rad_s(6000.0), design=NS(requirements=NS(max_spinup_deflection=1e-3))),
        campbell=NS(speeds=np.zeros(1), frequencies=np.zeros((1, 1)), whirl=[["forward"]]),
        spinup=NS(speeds=np.zeros(1), shaft_peak=np.zeros(1)),
    )
    critical = {
        "speed": _rad_s(3000.0),
        "mode": "1 (forward)",
        "amplification_factor": 4.0,
        "margin": 0.25,
        "required": 0.12,
        "passed": True,
        "station": 0.75,
    }
    comparison = NS(
        labels=("A", "B"), runs=(run, run), critical_speeds=lambda d: [critical] if d == 0 else [], metrics=list
    )
    section = compare._dynamics_section(comparison, tmp_path)
    table = section.tables[0]
    assert list(table.columns) == ["design", "speed", "mode", "AF", "margin", "required", "status", "station"]
    assert table.rows == [["A", "3000 rpm", "1 (forward)", 4.0, "25.0 %", "12.0 %", "PASS", "750 mm"]]


def test_metal_tube_table_alternating_then_mean_stress_in_mpa(monkeypatch, tmp_path):
    """Worst fatigue point: n_f 1.8 at x = 0.7 m, σ_a 40 MPa, σ_m 15 MPa, τ_m 25 MPa; yield n_y 3.2;
    buckling T_cr/T 6.5."""
    _stub_figures(monkeypatch)
    fatigue = {"safety_factor": 1.8, "station": 0.7, "sigma_alternating": 40e6, "sigma_mean": 15e6, "tau_mean": 25e6}
    metal = NS(
        evaluated=True,
        along_shaft=lambda: ([0.0, 1.0], [2.0, 2.0]),
        segments=["segment 1"],
        worst=lambda kind, segment: fatigue if kind == "fatigue" else {"safety_factor": 3.2},
        buckling=[NS(segment="segment 1", safety_factor=6.5)],
    )
    run = NS(
        strength_total=None,
        metal_strength=metal,
        points=(),
        model=NS(design=NS(requirements=NS(min_safety_factor=1.5))),
    )
    section = compare._strength_section(
        NS(labels=("A", "B"), runs=(run, NS(strength_total=None, metal_strength=None, points=()))), tmp_path
    )
    (table,) = section.tables
    assert list(table.columns)[3:6] == ["σ_a [MPa]", "σ_m [MPa]", "τ_m [MPa]"]
    assert table.rows == [["segment 1", 1.8, 0.7, 40.0, 15.0, 25.0, 3.2, 6.5]]


def test_each_design_hands_its_own_limits_and_speed_to_the_overlays(monkeypatch, tmp_path):
    """Each design is judged against its own [requirements] at its own operating speed, so the
    overlays get one value per design: A at 4800 rpm with a 0.5 mm orbit limit and a required
    safety factor of 1.5, B at 6000 rpm with 1 mm and 2.25 (Ω = 2π·N/60 rad/s)."""
    _stub_figures(monkeypatch)
    calls: dict = {}
    monkeypatch.setattr(compare, "campbell_overlay_figure", lambda curves, op: calls.setdefault("campbell", op))
    monkeypatch.setattr(
        compare, "spinup_overlay_figure", lambda curves, op, limit: calls.setdefault("spinup", (op, limit))
    )
    monkeypatch.setattr(compare, "safety_factor_overlay_figure", lambda c, req: calls.setdefault("strength", req))

    def run(rpm, orbit, required):
        return NS(
            model=NS(
                speed=_rad_s(rpm), design=NS(requirements=NS(max_spinup_deflection=orbit, min_safety_factor=required))
            ),
            campbell=NS(speeds=np.zeros(1), frequencies=np.zeros((1, 1)), whirl=[["forward"]]),
            spinup=NS(speeds=np.zeros(1), shaft_peak=np.zeros(1)),
            strength_total=NS(x_along=np.array([0.0, 1.0]), along_shaft=np.array([3.0, 4.0])),
            points=(),  # one operating point: the assessment's own strength
            metal_strength=None,
        )

    comparison = NS(
        labels=("A", "B"),
        runs=(run(4800.0, 5e-4, 1.5), run(6000.0, 1e-3, 2.25)),
        critical_speeds=lambda d: [],
        metrics=list,
    )
    compare._dynamics_section(comparison, tmp_path)
    compare._strength_section(comparison, tmp_path)
    op, limit = calls["spinup"]
    assert calls["campbell"] == op and set(op) == {"A", "B"}
    # rpm back from rad/s: one multiplication and one division, 1e-12 relative
    assert abs(op["A"] - 4800.0) <= 1e-12 * 4800.0 and abs(op["B"] - 6000.0) <= 1e-12 * 6000.0
    assert limit == {"A": 5e-4, "B": 1e-3}
    assert calls["strength"] == {"A": 1.5, "B": 2.25}
