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

import numpy as np
import pytest
from conftest import RUN_DESIGN

from flexshaft.design import loads_design, with_overrides
from flexshaft.report.results_json import results_json, rpm_or_none
from flexshaft.resolution import Resolution
from flexshaft.verdict.assess import assess

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
