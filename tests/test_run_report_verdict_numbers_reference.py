"""The run report shows the numbers its verdict uses (report/run_sections.py, report/driveline.py).

The rule, from the hand-written docs: "The report formats an `Assessment` (and the thesis studies
beside it); it computes nothing physical." (docs/architecture.md:99-100); "The assessment's own
analyses (the report's figures, `results.json`'s numbers) are those of the **governing point**"
(docs/requirements.md:142-143), and the report's "Magnetic-bearing loops" section (each loop's
sensitivity peak, margins and a figure with the requirements) is drawn "where the
sensitivity-peak check governs" (docs/requirements.md:160-163). Here the design has one
operating point, so the report's numbers are those of the verdict's checks. The reference of
each test is the assessment's own verdict, read through its public checks (value, limit,
location) and converted by hand from the unit definitions (derived): rpm = 60·Ω/(2π);
°C = K − 273.15; degrees = radians·180/π. Where a test rests on a row of the requirements table
(docs/requirements.md) it quotes it.

The assessment is the session's ``tuned_nominal_screening`` (the embedded tuned design at its
own operating point, SCREENING resolution: two magnetic bearings, loops, the self-heating
equilibrium; shared with other test files, about 1 s of CPU once per session). The report's
plan only records figure jobs (nothing is drawn): each test takes a few milliseconds.
"""

from __future__ import annotations

import dataclasses
import math
import re
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.report.driveline import plan_run_report
from flexshaft.report.run_sections import Figures, loops_section, stability_section, thermal_section
from flexshaft.thermal.correlations import Nusselt
from flexshaft.thermal.tailboom import BoomTemperature


def _job(plan, stem: str):
    (job,) = [j for j in plan.jobs if j.stem == stem]
    return job


def _rpm(rad_s: float) -> float:
    return rad_s * 60.0 / (2.0 * math.pi)


def test_loop_paragraph_states_the_limits_of_the_loop_checks(tuned_nominal_screening, tmp_path):
    """The "Required:" sentence of the loops section gives each loop check's own limit: |S|max ≤
    the loop_sensitivity limit, gain margin ≥ the loop_gain_margin limit [dB], phase margin ≥ the
    loop_phase_margin limit converted from radians to degrees. docs/requirements.md:109-111 says
    which requirement each check reads: ``loop_sensitivity`` … ``max_sensitivity_peak``,
    ``loop_gain_margin`` … ``min_gain_margin_db``, ``loop_phase_margin`` …
    ``min_phase_margin_deg``. The sentence prints them with ``:g`` (6 significant digits), so
    the comparison is to 1e-5 relative."""
    a = tuned_nominal_screening
    section = loops_section(a, Figures(tmp_path))
    assert section is not None
    text = " ".join(section.paragraphs)
    found = re.search(r"\|S\|max ≤ ([0-9.eE+-]+), gain margin ≥ ([0-9.eE+-]+) dB, phase margin ≥ ([0-9.eE+-]+)°", text)
    assert found is not None, text
    peak, gain, phase = (float(g) for g in found.groups())
    v = a.verdict
    assert peak == pytest.approx(v.check("loop_sensitivity").limit, rel=1e-5)
    assert gain == pytest.approx(v.check("loop_gain_margin").limit, rel=1e-5)
    assert phase == pytest.approx(v.check("loop_phase_margin").limit * 180.0 / math.pi, rel=1e-5)
    # the tuned design's three limits are distinct, so a limit read from a neighbour is seen
    assert len({peak, gain, phase}) == 3


def test_loop_table_peak_is_the_sensitivity_checks_reading(tuned_nominal_screening, tmp_path):
    """The Loop margins table's |S|max of the loop where the loop_sensitivity check governs is the
    check's value, the ratio max |S(iω)| it compares with max_sensitivity_peak (not in dB), and
    its "at [Hz]" the check's frequency [rad/s] / 2π. The ratio is what the requirement grades:
    "zone A below 3 (9.5 dB), B below 4 (12 dB)" (docs/requirements.md:75), and the
    loop_sensitivity check reads ``max_sensitivity_peak`` (docs/requirements.md:109). The same
    doubles pass through (1e-12)."""
    a = tuned_nominal_screening
    check = a.verdict.check("loop_sensitivity")
    (table,) = loops_section(a, Figures(tmp_path)).tables
    rows = {row[0]: row for row in table.rows}
    row = rows[check.location["actuator"]]
    assert row[1] == pytest.approx(check.value, rel=1e-12)
    assert row[3] == pytest.approx(check.location["frequency"] / (2.0 * math.pi), rel=1e-12)
    assert max(r[1] for r in table.rows) == pytest.approx(check.value, rel=1e-12)


def test_stable_to_is_the_whirl_onset_checks_reading(tuned_nominal_screening, tmp_path):
    """The tuned design has no whirl onset in its scan: the whirl_onset check's value is the top of
    the scan it found stable [rad/s] (above its limit, (1 + margin) × Ω_op): "with no onset up to
    the highest speed analysed, that speed as a lower bound" (docs/requirements.md:103). The
    onset table says "stable to" that speed in rpm = 60·Ω/(2π), printed to the rpm."""
    a = tuned_nominal_screening
    check = a.verdict.check("whirl_onset")
    assert a.stability.onset_speed is None and check.value > check.limit
    section = stability_section(a, None, Figures(tmp_path), _rpm(a.model.speed))
    (table,) = [t for t in section.tables if t.caption.startswith("Onset speed")]
    rows = {row[0]: row for row in table.rows}
    # the design's analysis is the exact hysteretic one: its column (audit a2: it stood under
    # "viscous equivalent")
    assert a.stability.damping_model == "hysteretic" and table.columns[2] == "exact hysteretic"
    assert rows["this design"][1:] == ["—", f"stable to {_rpm(check.value):.0f}"]


def test_actuator_figure_marks_what_the_actuator_checks_judge(tuned_nominal_screening, tmp_path):
    """The actuator figure marks, per bearing, the excursion (static offset + spin-up orbit) and
    the force (static + spin-up) the actuator checks judge, at their speeds in rpm: "The static
    offset is added to the orbit amplitude (and the static force to the force amplitude)"
    (docs/requirements.md:116-117). For the
    bearing where each check governs the mark is the check's value and speed. The mark is the
    same sum of the same two doubles as the check's value (1 ulp at most, hence 1e-12 relative);
    the speed is converted here, rpm = 60·Ω/(2π) (1e-12 relative: one multiplication)."""
    a = tuned_nominal_screening
    checked = _job(plan_run_report(a, tmp_path), "actuators").kwargs["checked"]
    orbit, force = a.verdict.check("actuator_orbit"), a.verdict.check("actuator_force")
    rpm_orbit, excursion, _, _ = checked[orbit.location["actuator"]]
    assert excursion == pytest.approx(orbit.value, rel=1e-12)
    assert rpm_orbit == pytest.approx(_rpm(orbit.location["speed"]), rel=1e-12)
    _, _, rpm_force, peak_force = checked[force.location["actuator"]]
    assert peak_force == pytest.approx(force.value, rel=1e-12)
    assert rpm_force == pytest.approx(_rpm(force.location["speed"]), rel=1e-12)
    # the marks are the readings the checks compare with their limits: none beyond the check's worst
    # (the tuned design's two bearings have the same gap and force capacity)
    assert max(c[1] for c in checked.values()) == pytest.approx(orbit.value, rel=1e-12)
    assert max(c[3] for c in checked.values()) == pytest.approx(force.value, rel=1e-12)


def test_safety_factor_figure_dashes_the_tsai_wu_limit(tuned_nominal_screening, tmp_path):
    """The strength figure's dashed required factor is the tsai_wu check's limit (the design's
    min_safety_factor: the tsai_wu row reads ``min_safety_factor``, the buckling row
    ``min_buckling_safety_factor``, docs/requirements.md:100, 102), not another requirement's
    (the buckling factor's 2.0 differs from it)."""
    a = tuned_nominal_screening
    required = _job(plan_run_report(a, tmp_path), "safety_factor").kwargs["required"]
    assert required == a.verdict.check("tsai_wu").limit
    assert required != a.verdict.check("buckling").limit


def _margin(text: str) -> float:
    found = re.search(r"margin to the allowable temperature (-?[0-9.]+) K", text)
    assert found is not None, text
    return float(found.group(1))


def test_self_heating_margin_is_the_temperature_checks(tuned_nominal_screening, tmp_path):
    """The thermal section's "margin to the allowable temperature" is the self-heating
    equilibrium's margin. Here it equals the temperature check's limit − value [K] (the allowable
    above the largest shaft temperature: positive when the check passes) because at the design's
    own operating point, with no hot-soaked start, the check's value is the self-heating
    equilibrium ("maximum shaft temperature: the self-heating equilibrium, or the material
    temperature of a hot-soaked start when it is higher", docs/requirements.md:112); with a
    hotter hot-soak start or another governing point the two would differ. Both of the section's
    forms are read: the screening one (the self-heating equilibrium alone) and the report's (with
    shaft profiles; a stand-in profile, the assessment's own self-heating result). The stand-in
    is the fixture's assessment with only its thermal result's shaft profiles replaced
    (``dataclasses.replace``), so every other field (points, governing point) is real. Printed
    with one decimal: to 0.05 K."""
    a = tuned_nominal_screening
    check = a.verdict.check("temperature")
    expected = check.limit - check.value
    assert expected > 1.0  # the tuned design passes by tens of kelvin: a sign slip is seen
    screening = thermal_section(a, Figures(tmp_path))
    assert _margin(" ".join(screening.paragraphs)) == pytest.approx(expected, abs=0.05 + 1e-9)
    x = np.array([0.0, 1.0])
    shaft = NS(
        temperature=NS(
            x=x, temperature=np.array([315.0, 316.0]), air_temperature=313.15, heat_transfer_coefficient=25.0
        ),
        sources=NS(total=np.array([1.0]), vibration=np.array([0.5]), static=np.array([0.5])),
        peak_rise=2.85,
    )
    assert a.thermal is not None and a.thermal.self_heating is not None
    thermal = dataclasses.replace(a.thermal, shaft={"rotating": shaft}, tailboom={}, profiles=None)
    report = thermal_section(dataclasses.replace(a, thermal=thermal), Figures(tmp_path))
    assert _margin(" ".join(report.paragraphs)) == pytest.approx(expected, abs=0.05 + 1e-9)


def test_tailboom_table_in_celsius(tuned_nominal_screening, tmp_path):
    """The tailboom table's [°C] column: a hover skin at 317.15 K is 44.0 °C (the thesis's hover
    value the caption quotes), a parked one at 362.15 K 89.0 °C; °C = K − 273.15 (1e-9: one
    subtraction of numbers of order 300). The stand-in is the fixture's assessment with its
    thermal result's shaft profiles and tailboom replaced (``dataclasses.replace``): its other
    fields (points, governing point) are real."""
    a = tuned_nominal_screening
    x = np.array([0.0, 1.0])
    shaft = NS(
        temperature=NS(
            x=x, temperature=np.array([318.0, 319.0]), air_temperature=317.15, heat_transfer_coefficient=25.0
        ),
        sources=NS(total=np.array([1.0]), vibration=np.array([0.5]), static=np.array([0.5])),
        peak_rise=1.85,
    )

    def boom(condition, kelvin, h, method):
        return BoomTemperature(condition, kelvin, h, Nusselt(100.0, method, True), 1e4, 10.0, 0.3, 500.0, 20.0, 480.0)

    tailboom = {
        "hover": boom("hover", 317.15, 30.0, "churchill_bernstein"),
        "parked": boom("parked", 362.15, 5.0, "morgan"),
    }
    assert a.thermal is not None
    thermal = dataclasses.replace(
        a.thermal, shaft={"rotating": shaft}, tailboom=tailboom, self_heating=None, profiles=None
    )
    section = thermal_section(dataclasses.replace(a, thermal=thermal), Figures(tmp_path))
    (table,) = [t for t in section.tables if t.caption.startswith("Tailboom skin temperature")]
    assert list(table.columns)[:3] == ["condition", "temperature [°C]", "h [W/m² K]"]
    rows = {row[0]: row for row in table.rows}
    assert rows["hover"][1] == pytest.approx(44.0, abs=1e-9)
    assert rows["parked"][1] == pytest.approx(89.0, abs=1e-9)
    assert (rows["hover"][2], rows["parked"][2]) == (30.0, 5.0)
