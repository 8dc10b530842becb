"""Each envelope point's conditions as ``results.json`` (``envelope.points``) and the report's
envelope table (``envelope_rows``) write them: ambient and material temperature in °C and the
shaft speed in rpm, also for a design whose ``[operating]`` gives its speed in rad/s.

References (documented rules, quoted): docs/thermal.md, "The operating envelope": "omitted keys
take the file's own values", ``ambient_temperature_c`` "ambient air [°C]", ``material_temperature
= "given"`` with ``material_temperature_c`` "the material temperature with "given" [°C]",
``"ambient"`` the shaft at the ambient, ``speed_rpm`` "the operating point; omitted:
[operating]"; README (``--json``): "rotational speeds in rpm (_rpm) and absolute temperatures in
°C (_c)"; docs/requirements.md: the report's table of the points gives "their ambient and
material temperatures, speed, power". Unit rule: Ω [rad/s] is Ω·60/(2π) rpm, so the design's
500 rad/s is 4774.648 rpm (derived here). The design is the tests' small run design
(conftest.RUN_DESIGN) with two points of its own; the points' conditions and designs are the
product's (thermal.envelope.point_conditions, design.points.design_at_point: no analysis), their
verdicts one stand-in check each: about 0.05 s of CPU. Tolerance: one unit conversion, rel 1e-12.

Before the twenty-eighth session a point that kept the design's speed given in rad/s wrote
``speed_rpm: null`` to ``results.json`` and the report's envelope table raised a TypeError
(``operating.speed_rpm`` is None when the file gives ``speed``).
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import pytest
from conftest import RUN_DESIGN

from flexshaft.design import loads_design, with_overrides
from flexshaft.design.points import design_at_point
from flexshaft.report.results_json import _envelope_dict
from flexshaft.thermal.envelope import point_conditions
from flexshaft.verdict.envelope_text import ENVELOPE_COLUMNS, envelope_rows
from flexshaft.verdict.result import Check, Verdict

OMEGA = 500.0  # [rad/s], the design's [operating] speed
POINTS = [
    # a warm day with the shaft hot-soaked to a given 80 °C, at the design's own speed
    {"name": "warm", "ambient_temperature_c": 35.0, "material_temperature": "given", "material_temperature_c": 80.0},
    # a cool day, the shaft at the ambient, at a point speed of its own
    {"name": "cool", "ambient_temperature_c": 5.0, "material_temperature": "ambient", "speed_rpm": 3000.0},
]
#: (ambient °C, material °C, speed rpm) of each point, from the rules above.
EXPECTED = {"warm": (35.0, 80.0, OMEGA * 60.0 / (2.0 * math.pi)), "cool": (5.0, 5.0, 3000.0)}


@pytest.fixture(scope="module")
def assessment():
    design = with_overrides(
        loads_design(RUN_DESIGN), {"operating.speed_rpm": None, "operating.speed": OMEGA, "envelope.points": POINTS}
    )
    points = []
    for point in design.envelope.points:
        conditions = point_conditions(design, point)
        check = Check("spinup_deflection", "spin-up shaft orbit", "length", "at most", "pass", 1e-4, 2e-4, 1e-4)
        points.append(
            NS(
                name=point.name,
                analyses=NS(design=design_at_point(design, point, conditions), conditions=conditions),
                verdict=Verdict((check,)),
            )
        )
    return NS(design=design, points=points, governing_point="warm")


def test_results_json_point_temperatures_and_speed(assessment):
    written = {p["name"]: p for p in _envelope_dict(assessment)["points"]}
    assert set(written) == set(EXPECTED)
    for name, (ambient, material, rpm) in EXPECTED.items():
        p = written[name]
        assert p["ambient_temperature_c"] == pytest.approx(ambient, rel=1e-12)
        assert p["material_temperature_c"] == pytest.approx(material, rel=1e-12)
        assert p["speed_rpm"] == pytest.approx(rpm, rel=1e-12)


def test_report_envelope_table_point_temperatures_and_speed(assessment):
    """The table's cells: temperatures to 0.1 °C, the speed to 1 rpm (4774.6 → "4775")."""
    column = {name: k for k, name in enumerate(ENVELOPE_COLUMNS)}
    rows = {row[0].split(" ")[0]: row for row in envelope_rows(assessment)}
    assert set(rows) == set(EXPECTED)
    for name, (ambient, material, rpm) in EXPECTED.items():
        row = rows[name]
        assert row[column["ambient [°C]"]] == f"{ambient:.1f}"
        assert row[column["shaft material [°C]"]] == f"{material:.1f}"
        assert row[column["speed [rpm]"]] == f"{rpm:.0f}"
    assert rows["warm"][column["speed [rpm]"]] == "4775"
