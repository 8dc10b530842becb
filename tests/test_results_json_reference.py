"""``results.json``'s numbers (what engineers script against) against the assessment's own SI
results converted with the unit factor each key names, and against the design file.

References (derived, unit definitions): 1 rpm = 2π/60 rad/s, so a speed ω [rad/s] is
ω·60/(2π) rpm; lengths and stresses stay SI (_m, _Pa). The design is the tests' small run design
(conftest.RUN_DESIGN: the Table 3.1 baseline on 4 shaft and 2 boom elements, layup (55/-55/0/0)s)
judged at its own operating point (no envelope) on tiny grids with the report's detail (three
spin-up speeds, 10, 332 and 653 rad/s around the 502.65 rad/s operating speed; a four-speed
Campbell diagram; the shaft's thermal results): about 0.25 s of CPU. Each key is
a copy or one multiplication of an analysis number, so the tolerance is round-off (1e-12).
"""

from __future__ import annotations

import math
import re
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest
from conftest import RUN_DESIGN

from flexshaft.analyses.spinup_response import SpinupResponse
from flexshaft.design import loads_design, with_overrides
from flexshaft.report.results_json import _spinup_peak, results_json, rpm_or_none
from flexshaft.resolution import Resolution
from flexshaft.verdict.assess import assess
from flexshaft.verdict.result import Check, Finding, Verdict

RPM_PER_RAD_S = 60.0 / (2.0 * math.pi)
#: The design's layup (55/-55/0/0)s, ply by ply from the inside, expanded by hand.
LAYUP = [55.0, -55.0, 0.0, 0.0, 0.0, 0.0, -55.0, 55.0]


#: Tiny grids with the report's detail (the Campbell diagram's critical speeds, the thermal study).
TINY = Resolution(
    "tiny", spinup_speeds=3, whirl_speeds=3, campbell_speeds=4, report_detail=True, modes=4, loop_peak_samples=1
)


@pytest.fixture(scope="module")
def run():
    a = assess(with_overrides(loads_design(RUN_DESIGN), {"envelope": None}), TINY)
    return a, results_json(a)


def test_spin_up_scan_peak_its_speed_and_the_operating_sample(run):
    """The scan's largest orbit [m], its speed in rpm, and the orbit at the operating speed: a
    sample of the scan itself (the spin-up checks end there; before, the sample nearest it was
    read, 653 rad/s for 502.65 on this coarse scan)."""
    a, data = run
    sp, imb = a.spinup, data["imbalance"]
    k = int(np.argmax(sp.shaft_peak))
    assert imb["max_shaft_orbit_scan_m"] == pytest.approx(sp.shaft_peak[k], rel=1e-12)
    assert imb["speed_of_max_scan_rpm"] == pytest.approx(sp.speeds[k] * RPM_PER_RAD_S, rel=1e-12)
    (at,) = np.flatnonzero(sp.speeds == a.model.speed)  # sampled exactly
    assert imb["max_shaft_orbit_at_operating_m"] == pytest.approx(sp.shaft_peak[at], rel=1e-12)


def test_spin_up_peak_speed_is_the_verdict_speed_in_rpm(run):
    a, data = run
    check = a.verdict.check("spinup_deflection")
    assert data["imbalance"]["max_shaft_orbit_spin_up_m"] == pytest.approx(check.value, rel=1e-12)
    assert data["imbalance"]["speed_of_max_rpm"] == pytest.approx(check.location["speed"] * RPM_PER_RAD_S, rel=1e-12)


def test_strength_keys_are_the_total_result_ply_numbered_from_one(run):
    """strength_static_plus_imbalance is the static + imbalance result (its phase is the worst
    one of the whirl, not 0), its stresses in (σ1, σ2, τ12) order, its ply numbered from 1 as in
    the design's layup."""
    a, data = run
    total, static = data["strength_static_plus_imbalance"], data["strength_static"]
    r = a.strength_total
    assert total["safety_factor"] == pytest.approx(r.safety_factor, rel=1e-12)
    assert total["phase_deg"] == pytest.approx(r.phase_deg, rel=1e-12)
    assert total["safety_factor"] != static["safety_factor"]  # the imbalance changes the result
    assert [total["sigma1_Pa"], total["sigma2_Pa"], total["tau12_Pa"]] == pytest.approx(list(r.stresses[:3]), rel=1e-12)
    assert len({abs(s) for s in r.stresses[:3]}) == 3  # distinct: a swapped component shows
    for entry, result in ((total, r), (static, a.strength_static)):
        assert entry["ply"] == result.ply + 1 >= 1
        assert entry["ply_angle_deg"] == LAYUP[entry["ply"] - 1]


def test_static_boom_tip_is_the_cantilevers_largest_deflection(run):
    """``static.boom_tip_v_m``/``_w_m`` [m]: the static displacement of the boom's tip node (its
    last node, x = L from the root). The tailboom is a cantilever from the fuselage under the
    3.5 g load factor and the end mass (one sign along it): a cantilever's deflection under
    loads of one sign grows monotonically from the clamped root (zero slope and deflection
    there) to the tip, so the tip holds the largest |v| of the boom's nodes and is not zero."""
    a, data = run
    dm, qs = a.model.dofs, a.static_displacement
    v = np.array([qs[dm.boom(i, "v")] for i in range(dm.n_boom_nodes)])
    w = np.array([qs[dm.boom(i, "w")] for i in range(dm.n_boom_nodes)])
    assert data["static"]["boom_tip_v_m"] == pytest.approx(v[-1], rel=1e-12)
    assert data["static"]["boom_tip_w_m"] == pytest.approx(w[-1], rel=1e-12)
    assert abs(v[-1]) == np.max(np.abs(v)) > 0.0
    assert np.all(np.diff(np.abs(v)) >= 0.0)  # monotone from root to tip


def test_rpm_or_none_converts_rad_s():
    """4800 rpm = 502.6548 rad/s comes back as 4800 rpm; None and NaN as None."""
    assert rpm_or_none(4800.0 * 2.0 * math.pi / 60.0) == pytest.approx(4800.0, rel=1e-12)
    assert rpm_or_none(None) is None and rpm_or_none(float("nan")) is None


def test_critical_speeds_in_rpm_modes_numbered_from_one(run):
    """Each critical speed ω [rad/s] as ω·60/(2π) rpm, its tracked mode numbered from 1 (as the
    mode tables number them)."""
    a, data = run
    criticals = a.campbell.critical_speeds
    assert criticals and len(data["critical_speeds"]) == len(criticals)
    for entry, c in zip(data["critical_speeds"], criticals):
        assert entry["speed_rpm"] == pytest.approx(c.speed * RPM_PER_RAD_S, rel=1e-12)
        assert entry["tracked_mode"] == c.mode + 1 >= 1


def test_thermal_air_temperature_in_celsius(run):
    """The shaft's air temperature T [K] as T − 273.15 °C (the Celsius scale's definition)."""
    a, data = run
    assert a.thermal.shaft
    for model, s in a.thermal.shaft.items():
        assert data["thermal"][f"shaft_{model}"]["air_c"] == pytest.approx(
            s.temperature.air_temperature - 273.15, rel=1e-12, abs=1e-12
        )


def _number_after(text: str, label: str) -> float:
    """The number printed right after ``label`` in ``text``."""
    match = re.search(re.escape(label) + r"\s*([-+0-9.e]+)", text)
    assert match, label
    return float(match.group(1))


def test_run_command_prints_the_json_numbers_in_display_units(run, capsys, tmp_path):
    """``flexshaft run``'s printed summary (cli/run.py) from results.json's SI numbers: the spin-up
    peak orbit x 1000 mm/m (3 significant figures: rel 5e-3), its speed in rpm and the storage
    moduli / 1e9 Pa/GPa (4 significant figures: rel 5e-4)."""
    from flexshaft.cli.run import _print_run

    a, data = run
    _print_run(a, data, tmp_path / "report.html", 1.0, None)
    text = capsys.readouterr().out
    imb, s = data["imbalance"], data["summary"]
    assert _number_after(text, "spin-up peak shaft orbit") == pytest.approx(
        imb["max_shaft_orbit_spin_up_m"] * 1000.0, rel=5e-3
    )
    assert _number_after(text, "mm at") == pytest.approx(imb["speed_of_max_rpm"], rel=5e-4)
    assert _number_after(text, "E* =") == pytest.approx(s["shaft_E_storage_Pa"] / 1e9, rel=5e-4)
    assert _number_after(text, "G* =") == pytest.approx(s["shaft_G_storage_Pa"] / 1e9, rel=5e-4)


def test_static_shaft_deflection_is_the_largest_radial_one(run):
    """``static.max_shaft_deflection_m``: the largest radial static deflection √(v² + w²) over the
    shaft's nodes (both components load this design: the largest |v| and |w| are both non-zero,
    so a single component reads short)."""
    a, data = run
    dm, qs = a.model.dofs, a.static_displacement
    v, w = dm.values(qs, "shaft", "v"), dm.values(qs, "shaft", "w")
    radial = max(math.sqrt(vi * vi + wi * wi) for vi, wi in zip(v, w))
    assert data["static"]["max_shaft_deflection_m"] == pytest.approx(radial, rel=1e-12)
    assert radial > max(np.max(np.abs(v)), np.max(np.abs(w))) * (1 + 1e-6)


def test_bearing_loads_each_under_its_key(run):
    """Each bearing's static lateral [N], static axial [N] and imbalance amplitude [N] copied from
    its reactions (the hangers carry the drive's axial load, so lateral and axial differ)."""
    a, data = run
    assert set(data["bearings"]) == set(a.bearing_reactions)
    for name, r in a.bearing_reactions.items():
        entry = data["bearings"][name]
        assert entry["static_lateral_N"] == pytest.approx(r.static_lateral, rel=1e-12)
        assert entry["static_axial_N"] == pytest.approx(r.static_axial, rel=1e-12)
        assert entry["imbalance_lateral_amplitude_N"] == pytest.approx(r.imbalance_lateral_amplitude, rel=1e-12)
    assert any(r.static_lateral != r.static_axial for r in a.bearing_reactions.values())


def test_bearing_static_offset_is_the_actuator_checks_static_part(run):
    """``static_offset_m`` of an active bearing is the static part of the actuator-excursion
    check (its evidence, gathered from the static displacement through the magnet's rows: an
    independent path); it is not zero (a PD bearing sags by its share of the weight over its
    stiffness). Tolerance 1e-12: the same norm of the same doubles."""
    a, data = run
    evidence = {e.name: e for e in a.evidence.actuators}
    assert evidence
    for name, e in evidence.items():
        assert data["bearings"][name]["static_offset_m"] == pytest.approx(e.static_offset, rel=1e-12)
        assert e.static_offset > 0.0


def test_stability_top_speed_and_every_root_speeds_in_rpm(run):
    """``analysed_to_rpm``: the stability analysis's highest speed (its last) × 60/(2π);
    ``every_root.speeds_rpm``: each speed of the every-root check × 60/(2π). Pinned also from
    the documented rules (docs/requirements.md, "The stability checks"): the tracked modes run
    from rest to 1.5 × the operating speed, 1.5 × 4800 rpm = 7200 rpm (the baseline's
    ``[operating] speed_rpm``); the every-root check holds rest, the operating speed and
    (1 + ``min_onset_margin``) × it, 0, 4800 and 1.15 × 4800 = 5520 rpm. Tolerance 1e-12: one
    product and one unit conversion of doubles."""
    a, data = run
    st = data["stability"]
    assert st["analysed_to_rpm"] == pytest.approx(1.5 * 4800.0, rel=1e-12)
    assert st["every_root"]["speeds_rpm"] == pytest.approx([0.0, 4800.0, 1.15 * 4800.0], rel=1e-12, abs=1e-9)
    assert st["analysed_to_rpm"] == pytest.approx(max(a.stability.speeds) * RPM_PER_RAD_S, rel=1e-12)
    assert st["every_root"]["speeds_rpm"] == pytest.approx([s * RPM_PER_RAD_S for s in a.roots.speeds], rel=1e-12)
    assert max(a.roots.speeds) > 2 * math.pi  # rad/s and rpm differ


def test_spin_up_peak_without_a_limit_is_the_largest_orbit_up_to_the_operating_speed():
    """Without a spin-up limit (the check not evaluated) the peak is the largest sampled shaft
    orbit up to the operating speed: speeds 1000, 3000, 6000 (operating), 7800 rpm with shaft
    orbits 0.01, 0.04, 0.02, 0.09 mm give 0.04 mm at 3000 rpm (not 0.09 mm at 7800 rpm, above
    the spin-up; not the smallest, 0.01 mm)."""
    rpm = np.array([1000.0, 3000.0, 6000.0, 7800.0])
    envelope = np.array([[1e-5, 4e-5, 2e-5, 9e-5], [0.5e-5, 1e-5, 1e-5, 1e-5]])  # two nodes, the first largest
    spinup = SpinupResponse(rpm / RPM_PER_RAD_S, None, None, None, envelope, {}, {})
    skipped = Check("spinup_deflection", "spin-up shaft orbit", "length", "at most", "not evaluated")
    a = SimpleNamespace(verdict=Verdict((skipped,)), spinup=spinup, model=SimpleNamespace(speed=6000.0 / RPM_PER_RAD_S))
    peak = _spinup_peak(a)
    assert peak["max_shaft_orbit_spin_up_m"] == pytest.approx(4e-5, rel=1e-12)
    assert peak["speed_of_max_rpm"] == pytest.approx(3000.0, rel=1e-12)


def test_the_spin_up_peak_is_the_governing_points_not_the_checks_worst():
    """results.json's numbers are those of the governing point (docs/requirements.md: "The
    assessment's own analyses (the report's figures, `results.json`'s numbers) are those of the
    governing point"), and the report states the check's own worst value beside them when it
    governs elsewhere. Hand-made findings: 0.4881 mm at 262.15 rad/s at cold_day (governing)
    and 0.4982 mm at 260.35 rad/s at hot_soak_start, the check's worst; the peak must read
    cold_day's, 262.15 · 60/(2π) = 2503.3 rpm. A single point's finding names no point and is
    read as the governing point's."""

    def finding(value, speed, **point):
        return Finding(value, 5e-3, 5e-3 - value, location={**point, "station": 0.0, "speed": speed})

    cold = finding(4.881e-4, 262.15, point="cold_day")
    hot = finding(4.982e-4, 260.35, point="hot_soak_start")
    worst = Check(
        "spinup_deflection",
        "spin-up shaft orbit",
        "length",
        "at most",
        "pass",
        4.982e-4,
        5e-3,
        5e-3 - 4.982e-4,
        location=dict(hot.location),
        findings=(cold, hot),
    )
    a = SimpleNamespace(verdict=Verdict((worst,)), governing_point="cold_day")
    peak = _spinup_peak(a)
    assert peak["max_shaft_orbit_spin_up_m"] == pytest.approx(4.881e-4, rel=1e-12)
    assert peak["speed_of_max_rpm"] == pytest.approx(262.15 * 60.0 / (2.0 * math.pi), rel=1e-12)
    single = replace(worst, findings=(finding(3.0e-4, 250.0),), location={"station": 0.0, "speed": 250.0})
    one = _spinup_peak(SimpleNamespace(verdict=Verdict((single,)), governing_point="nominal"))
    assert one["max_shaft_orbit_spin_up_m"] == pytest.approx(3.0e-4, rel=1e-12)
