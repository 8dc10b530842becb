"""The comparison's masses stay in kilograms from the inventory to the report, its part counts are
the parts counted by hand, and the verdict table lists two different limits in the designs'
column order and marks a lower-bound value (comparison.py, report/compare.py).

References (derived here, by hand, and docs/segmented-driveline.md's hand-written tables):

* tube mass m = ρ π (D_o² − D_i²)/4 · L. Design A, the embedded aluminium driveline "current"
  (docs/segmented-driveline.md: "five 6061-T6 tubes, D_o 101.6 mm (4 in), wall 1.651 mm
  (0.065 in)", stations 0 to 8.05 m): ρ = 2700 kg/m³, D_i = 0.098298 m, L = 8.05 m:
  m = 11.2677 kg (the comparison table's "11.27 kg"), checked against the product's model of
  that design; the stand-in run below takes it as its tube mass. Plus four 1.0 kg couplings,
  four 1.4 kg hangers and a 1.2 kg damper (the table's "4.00 / 5.60 / 1.20 kg"); design A's
  5 kg gearbox bearing (role gearbox) is not counted (the table places the
  "intermediate-gearbox input bearing (role `gearbox`) at 8.05 m" and counts four hangers):
  total 22.0677 kg. Design B, a one-piece tube of 15.31 kg (given, the table's "15.31 kg") on
  two 1.4 kg hangers and two 7 kg actuators ("14.00 kg (2 × 7 kg, assumed)"): 32.11 kg.
  docs/architecture.md: results are "a frozen dataclass in SI units" with ".to_dataset()
  (xarray, units in the attributes)": the mass of a kind is in kg; the comparison table writes
  kilograms with two decimals ("4.00 / 5.60 / 1.20 kg", "15.31 kg", "14.00 kg"), so the report
  writes "22.07 kg".
* the verdict table's columns run design A then design B ("A value" … "B status", "where
  (A / B)"), so two different limits read "A's / B's": a spin-up peak limit of 5 mm for A and
  2 mm for B reads "5 mm / 2 mm".
* counts, derived here: four couplings join five tubes; the gearbox bearing is not counted.
  docs/segmented-driveline.md's comparison table, "**parts** (tubes, couplings, hangers,
  dampers, actuators)": current "**14** (5, 4, 4, 1, 0)", tuned "**5** (1, 0, 2, 0, 2)"; by
  hand A 5 + 4 + 4 + 1 + 0 = 14 parts, B 1 + 0 + 2 + 0 + 2 = 5.
* docs/requirements.md, whirl_onset: "with no onset up to the highest speed analysed, that speed
  as a lower bound", written "> 7200 rpm" as in docs/segmented-driveline.md's comparison table;
  its margin carries the mark too (docs/thesis-reproduction.md's verdict table: "> 7200 rpm |
  ≥ 5520 rpm | > +1680 rpm"), so against a 5760 rpm limit "> +1440 rpm".

The runs are stand-ins (no analysis): CPU under 0.01 s a test (under 1 s for the first dataset,
the xarray import); the one product model (the tube mass) builds in about 0.25 s. Masses are sums
of a few numbers of order 10 (error ~1e-15 relative), so 1e-12 relative holds on any machine.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import pytest

from flexshaft.assembly import build_model
from flexshaft.comparison import PART_KINDS, Comparison, driveline_inventory
from flexshaft.design import embedded_design
from flexshaft.report import compare as report
from flexshaft.verdict.result import Check

TUBE_A = 2700.0 * math.pi * (0.1016**2 - (0.1016 - 2 * 1.651e-3) ** 2) / 4.0 * 8.05


def _bearing(name, role, mass, kind="contact"):
    return NS(name=name, role=role, mass=mass, kind=kind)


def _design_a():
    couplings = [NS(name=f"c{k}", mass=1.0) for k in range(4)]
    bearings = [_bearing(f"h{k}", "hanger", 1.4) for k in range(4)]
    bearings += [_bearing("d", "damper", 1.2), _bearing("gb", "gearbox", 5.0)]
    return NS(name="aluminium", couplings=couplings, bearings=bearings)


def _design_b():
    bearings = [_bearing(f"h{k}", "hanger", 1.4) for k in range(2)]
    bearings += [_bearing(f"amb{k}", "hanger", 7.0, kind="active") for k in range(2)]
    return NS(name="fmc", couplings=[], bearings=bearings)


class _Verdict:
    def __init__(self, checks=()):
        self.checks = list(checks)
        self.summary = "PASS"
        self.headline = "PASS"

    def check(self, key):
        for c in self.checks:
            if c.key == key:
                return c
        raise KeyError(key)

    def to_dict(self):
        return {"summary": self.summary}


def _run(design, shaft_mass, checks=()):
    dofs = NS(values=lambda q, member, which: [0.0])
    model = NS(design=design, shaft_mass=shaft_mass, speed=500.0, dofs=dofs, couplings=[])
    return NS(model=model, verdict=_Verdict(checks), resolution=NS(scan_top=1.3), static_displacement=[0.0], notes=[])


def _comparison(checks=((), ())):
    runs = (_run(_design_a(), TUBE_A, checks[0]), _run(_design_b(), 15.31, checks[1]))
    return Comparison(
        labels=("A", "B"),
        runs=runs,
        inventories=(driveline_inventory(runs[0].model), driveline_inventory(runs[1].model)),
    )


def test_tube_mass_by_hand():
    """ρ π (D_o² − D_i²)/4 L = 2700 · π/4 · (0.1016² − 0.098298²) · 8.05 = 11.2677 kg, and the
    product's model of the embedded "current" design has that tube mass (docs/segmented-driveline.md:
    "11.27 kg"). The model sums five tubes' element masses, a few ulp each: 1e-12 relative."""
    assert TUBE_A == pytest.approx(11.2677, abs=1e-4)
    assert build_model(embedded_design("current")).shaft_mass == pytest.approx(TUBE_A, rel=1e-12)


def test_compared_masses_are_kilograms_of_each_kind():
    """Every mass metric in kg (SI), each kind's value the hand sum of its parts."""
    found = {m.key: m for m in _comparison().metrics()}
    expected = {
        "segments": (TUBE_A, 15.31),
        "couplings": (4.0, 0.0),
        "hangers": (5.6, 2.8),
        "dampers": (1.2, 0.0),
        "actuators": (0.0, 14.0),
    }
    for kind in PART_KINDS:
        metric = found[f"mass_{kind}"]
        assert metric.unit == "kg", kind
        assert metric.values == pytest.approx(expected[kind], rel=1e-12, abs=1e-12), kind
    assert found["mass_total"].unit == "kg"
    assert found["mass_total"].values == pytest.approx((TUBE_A + 10.8, 32.11), rel=1e-12)


def test_dataset_gives_every_mass_metric_in_kg():
    """The dataset's metric_units (units in the attributes): kg for every mass metric. The first
    dataset of a run costs under 1 s (the xarray import)."""
    ds = _comparison().to_dataset()
    units = dict(zip(ds["metric"].values.tolist(), ds["metric_units"].values.tolist()))
    for kind in (*PART_KINDS, "total"):
        assert units[f"mass_{kind}"] == "kg", kind
    assert ds["part_mass"].attrs["units"] == "kg"


def test_results_json_gives_every_mass_metric_in_kg():
    metrics = {m["key"]: m for m in report.comparison_json(_comparison())["metrics"]}
    for kind in (*PART_KINDS, "total"):
        assert metrics[f"mass_{kind}"]["unit"] == "kg", kind
    assert metrics["mass_total"]["values"]["B"] == pytest.approx(32.11, rel=1e-12)


def test_summary_key_numbers_write_kilograms():
    """Driveline total 22.0677 kg → "22.07 kg" (A), 32.11 kg → "32.11 kg" (B): kilograms, two
    decimals, as docs/segmented-driveline.md's comparison table writes each kind's mass."""
    table = report._summary_section(_comparison()).tables[0]
    (row,) = [r for r in table.rows if r[0] == "mass: driveline total"]
    assert row[1:3] == ["22.07 kg", "32.11 kg"]


def test_format_metric_kilograms():
    """A mass in kg is written in kg, two decimals, as docs/segmented-driveline.md's comparison
    table writes them ("15.31 kg", "4.00 / 5.60 / 1.20 kg"): 15.31 kg, 0.5 kg → "0.50 kg"."""
    assert report.format_metric("mass_segments", "kg", 15.31) == "15.31 kg"
    assert report.format_metric("mass_hangers", "kg", 0.5) == "0.50 kg"


def _spinup_check(limit, value):
    return Check(
        key="spinup_deflection",
        title="spin-up peak",
        kind="length",
        sense="at most",
        status="pass",
        value=value,
        limit=limit,
        margin=limit - value,
        location={"station": 4.0},
    )


def test_verdict_table_two_limits_in_column_order():
    """A's limit 5 mm, B's 2 mm: the limit cell reads "5 mm / 2 mm" (A first, as the columns);
    each design's value and margin stay on its side: A 1 mm (+4 mm), B 0.5 mm (+1.5 mm)."""
    checks = ([_spinup_check(5e-3, 1e-3)], [_spinup_check(2e-3, 0.5e-3)])
    section = report._verdict_section(_comparison(checks))
    (table,) = section.tables
    assert table.columns[2] == "A value" and table.columns[5] == "B value"
    (row,) = table.rows
    assert row[1] == "5 mm / 2 mm"
    assert row[2:4] == ["1 mm", "+4 mm"]
    assert row[5:7] == ["0.5 mm", "+1.5 mm"]


def test_part_counts_by_hand():
    """Counts by hand: A has five tubes (four couplings join five), 4 couplings, 4 hangers,
    1 damper, no actuator (the gearbox bearing not counted): 14 parts; B one tube, 2 hangers,
    2 actuators: 5 parts. Counts are dimensionless (unit "1")."""
    found = {m.key: m for m in _comparison().metrics()}
    expected = {"segments": (5, 1), "couplings": (4, 0), "hangers": (4, 2), "dampers": (1, 0), "actuators": (0, 2)}
    for kind in PART_KINDS:
        assert found[f"count_{kind}"].unit == "1", kind
        assert found[f"count_{kind}"].values == expected[kind], kind
    assert found["count_total"].values == (14, 5)


def test_verdict_table_marks_a_lower_bound_value():
    """docs/requirements.md, whirl_onset: "with no onset up to the highest speed analysed, that
    speed as a lower bound". A: stable to the top of its scan, 7200 rpm, against a 5760 rpm
    limit: value "> 7200 rpm", margin "> +1440 rpm"; B's onset found at 6000 rpm: no mark."""
    rpm = 2.0 * math.pi / 60.0

    def onset(value, lower_bound):
        return Check(
            key="whirl_onset",
            title="whirl onset speed",
            kind="speed",
            sense="at least",
            status="pass",
            value=value * rpm,
            limit=5760.0 * rpm,
            margin=(value - 5760.0) * rpm,
            lower_bound=lower_bound,
        )

    (table,) = report._verdict_section(_comparison(([onset(7200.0, True)], [onset(6000.0, False)]))).tables
    (row,) = table.rows
    assert row[2:4] == ["> 7200 rpm", "> +1440 rpm"]
    assert row[5:7] == ["6000 rpm", "+240 rpm"]
