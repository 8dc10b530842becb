"""The run report's section tables and sentences (report/run_sections.py) on hand-built inputs.

Each section is fed a stand-in of the assessment (plain namespaces with the attributes the
section reads, SI values) whose displayed values are converted by hand from the unit
definitions (derived): 1 m = 1000 mm; rpm = 60·Ω/(2π), so Ω = 2π·N/60 rad/s shows as N rpm;
°C = K − 273.15. The major semi-axis of a circular orbit (V, W) = (a, −ia) is its radius a.
Every input is distinct, so a value in a neighbour's column or row is seen. The figures are
only recorded as jobs (never drawn): CPU about 10 ms.
"""

from __future__ import annotations

import math
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.report.run_sections import Figures, imbalance_section, stability_section, thermal_section


def _rad_s(rpm: float) -> float:
    return 2.0 * math.pi * rpm / 60.0


def _table(section, caption_start: str):
    (table,) = [t for t in section.tables if t.caption.startswith(caption_start)]
    return table


# ------------------------------------------------------------------ imbalance response


def _imbalance(tmp_path, figs=None):
    model = NS(actuators=[], dofs=None, design=NS(loads=NS(imbalance_placement="distributed")), speed=_rad_s(6000))
    spinup = NS(
        speeds=np.array([_rad_s(1000), _rad_s(6000)]),
        shaft_peak=np.array([1e-5, 2e-5]),
        response=None,  # no complex response: no Bode figure
        actuator_force={"amb_1": None},
    )
    reactions = {
        "fwd": NS(
            kind="ball",
            x_shaft=0.25,
            static_lateral=300.0,
            static_axial=40.0,
            imbalance_lateral_amplitude=12.0,
            orbit=(1.0e-4, -1.0e-4j),  # a circle of radius 0.1 mm
            gap=5.0e-4,  # 0.5 mm
            static_position=(-3.0e-4, 4.0e-4),  # (v, w) [m]
            static_offset=5.0e-4,  # its distance from the centre, 0.5 mm (a 3-4-5 triangle)
        )
    }
    a = NS(points=(), model=model, spinup=spinup, bearing_reactions=reactions, evidence=NS(operating_range=None))
    data = {
        "imbalance": {
            "actuator_max_displacement_m": {"amb_1": 2.5e-4},
            "actuator_max_force_N": {"amb_1": 120.0},
            "max_shaft_orbit_spin_up_m": 1.2e-4,
            "speed_of_max_rpm": 3125.0,
            "max_shaft_orbit_at_operating_m": 3.0e-5,
            "max_shaft_orbit_scan_m": 4.5e-4,
            "speed_of_max_scan_rpm": 7000.0,
        }
    }
    return imbalance_section(a, figs or Figures(tmp_path), data, 6000.0)


def test_actuator_table_in_mm_and_newtons(tmp_path):
    """0.25 mm (2.5e-4 m) and 120 N under [mm] and [N]."""
    table = _table(_imbalance(tmp_path), "Actuators")
    assert list(table.columns) == ["actuator", "max relative displacement [mm]", "max force [N]"]
    ((name, mm, force),) = table.rows
    assert name == "amb_1" and mm == pytest.approx(0.25, rel=1e-12) and force == 120.0


def test_bearing_table_columns(tmp_path):
    """Static lateral 300 N, axial 40 N, imbalance 12 N, a static offset (v, w) = (−0.3, 0.4) mm
    of length 0.5 mm (3-4-5), a circular orbit of 0.1 mm, a gap of 0.5 mm."""
    table = _table(_imbalance(tmp_path), "Bearing loads")
    assert list(table.columns)[3:] == [
        "static lateral [N]",
        "static axial [N]",
        "imbalance force amplitude [N]",
        "static offset [mm]",
        "relative orbit [mm]",
        "gap [mm]",
    ]
    ((name, kind, x, lateral, axial, imbalance, offset, orbit, gap),) = table.rows
    assert (name, kind, x, lateral, axial, imbalance) == ("fwd", "ball", 0.25, 300.0, 40.0, 12.0)
    assert offset == pytest.approx(0.5, rel=1e-12)
    assert orbit == pytest.approx(0.1, rel=1e-12) and gap == pytest.approx(0.5, rel=1e-12)


def test_bearing_orbits_drawn_about_each_static_position(tmp_path):
    """The orbit figure's job gets each bearing's orbit, gap and static position under the same
    label, "fwd (x = 0.25 m)" (x to 2 decimals), so the figure draws static offset + orbit, the
    sum the actuator-excursion check judges."""
    figs = Figures(tmp_path)
    _imbalance(tmp_path, figs)
    (job,) = [j for j in figs.jobs if j.stem == "bearing_orbits"]
    label = "fwd (x = 0.25 m)"
    orbits, gaps = job.args
    assert orbits == {label: (1.0e-4, -1.0e-4j)} and gaps == {label: 5.0e-4}
    assert job.kwargs["centres"] == {label: (-3.0e-4, 4.0e-4)}


def test_imbalance_sentence_in_mm(tmp_path):
    """1.2e-4 m → 0.120 mm at 3125 rpm; 3e-5 m → 0.0300 mm; 4.5e-4 m → 0.450 mm at 7000 rpm."""
    (text,) = _imbalance(tmp_path).paragraphs
    assert "operating speed 0.120 mm at 3125 rpm" in text
    assert "0.0300 mm at the operating speed" in text
    assert "whole scan 0.450 mm at 7000 rpm" in text


def test_bode_curve_of_the_largest_orbit_at_the_operating_speed(tmp_path):
    """Three nodes at x = 0, 1, 2 m, speeds 1000, 3000 and 6000 rpm (the operating speed, the
    last); the orbit envelope is largest at node 1 (x = 1.00 m) at 6000 rpm (node 2 at 1000
    rpm); of its two load cases the second has the larger v at 6000 rpm: the curve is labelled
    "largest orbit at 6000 rpm (x = 1.00 m), v, case 2" (cases numbered from 1) and is that
    case's v."""
    speeds = np.array([_rad_s(1000), _rad_s(3000), _rad_s(6000)])
    envelope = np.array([[1.0, 1.0, 1.0], [2.0, 2.0, 5.0], [9.0, 3.0, 2.0]])
    q = np.zeros((6, 2, 3), dtype=complex)  # (dof, load case, speed); v of node k is dof 2k
    q[2] = [[1.0, 1.0, 1.0], [0.5, 0.5, 3.0]]
    q[4] = [[4.0, 1.0, 1.0], [1.0, 1.0, 1.0]]
    dofs = NS(shaft=lambda node, direction: 2 * node + (direction != "v"), shaft_x=np.array([0.0, 1.0, 2.0]))
    model = NS(actuators=[], dofs=dofs, design=NS(loads=NS(imbalance_placement="distributed")), speed=speeds[-1])
    spinup = NS(speeds=speeds, shaft_peak=envelope.max(axis=0), envelope=envelope, response=q, actuator_force={})
    data = {
        "imbalance": {
            "max_shaft_orbit_spin_up_m": 1e-4,
            "speed_of_max_rpm": 1000.0,
            "max_shaft_orbit_at_operating_m": 1e-4,
            "max_shaft_orbit_scan_m": 1e-4,
            "speed_of_max_scan_rpm": 1000.0,
        }
    }
    figs = Figures(tmp_path)
    imbalance_section(
        NS(points=(), model=model, spinup=spinup, bearing_reactions={}, evidence=NS(operating_range=None)),
        figs,
        data,
        6000.0,
    )
    (job,) = [j for j in figs.jobs if j.stem == "imbalance_bode"]
    curves = job.args[1]
    assert list(curves) == ["largest orbit at 6000 rpm (x = 1.00 m), v, case 2"]
    np.testing.assert_array_equal(next(iter(curves.values())), [0.5, 0.5, 3.0])


# ------------------------------------------------------------------ whirl stability


def _result(onset_rpm, speeds, damping_model="hysteretic"):
    return NS(
        damping_model=damping_model,
        speeds=speeds,
        log_decrements=np.zeros((2, speeds.size)),
        onset_speed=None if onset_rpm is None else _rad_s(onset_rpm),
        whirl=["forward", "backward"],
        onset_description=lambda: "",
    )


def _unread(key):
    raise KeyError(key)


def _stability(tmp_path):
    speeds = np.array([_rad_s(1000), _rad_s(3000), _rad_s(6000)])
    a = NS(
        points=(),  # one operating point: the sections show the assessment's own analyses
        verdict=NS(check=_unread),  # no whirl-onset check: the tracked modes' onset alone
        stability=_result(None, speeds),
        modes_at_speed=None,  # no modes at the operating speed: no curve greyed out
        model=NS(speed=_rad_s(4800)),
        design=NS(requirements=NS(required_log_decrement=0.1, min_onset_margin=0.15), bearings=[]),
        roots=NS(
            coverage=lambda: "every root",
            speeds=np.array([_rad_s(1000), _rad_s(6000)]),
            n_roots=np.array([12, 14]),
            least_damping_ratio=np.array([0.05, -0.01]),
            unstable_counts=np.array([0, 2]),
        ),
    )
    gain_map = NS(
        kp=np.array([1e5, 2e5]),
        kd=np.array([10.0, 20.0, 40.0]),
        onset_speed=np.array([_rad_s(4000), _rad_s(5000)]),
        max_speed=_rad_s(9000),
        margin_at_operating=np.array([[0.01, 0.02, 0.03], [0.04, 0.05, 0.06]]),
    )
    thesis = NS(
        shaft_comparison={"shaft A": {"viscous": _result(3000, speeds), "hysteretic": _result(4000, speeds)}},
        gain_map=gain_map,
    )
    return stability_section(a, thesis, Figures(tmp_path), 6000.0)


def test_onset_table_viscous_and_hysteretic_columns(tmp_path):
    """The design stable to the top speed, 6000 rpm, by its exact hysteretic analysis (the
    stability analysis's default: its value under "exact hysteretic", audit a2: it stood under
    "viscous equivalent"); shaft A viscous 3000, hysteretic 4000 rpm."""
    table = _table(_stability(tmp_path), "Onset speed")
    assert list(table.columns) == ["shaft", "viscous equivalent", "exact hysteretic"]
    assert [list(r) for r in table.rows] == [["this design", "—", "stable to 6000"], ["shaft A", "3000", "4000"]]


def test_onset_table_a_viscous_analysis_under_viscous(tmp_path, monkeypatch):
    """A design analysed with the viscous-equivalent model: its onset under that column."""
    original = _result

    def viscous(onset_rpm, speeds, damping_model="viscous"):
        return original(onset_rpm, speeds, damping_model)

    monkeypatch.setitem(globals(), "_result", viscous)
    table = _table(_stability(tmp_path), "Onset speed")
    assert list(table.rows[0]) == ["this design", "stable to 6000", "—"]


def test_every_root_table_in_rpm(tmp_path):
    """Speeds 1000 and 6000 rpm; 12 and 14 roots of which 0 and 2 unstable."""
    table = _table(_stability(tmp_path), "Every root")
    assert list(table.columns) == ["speed [rpm]", "roots", "least damping ratio ζ", "unstable roots"]
    (s1, n1, z1, u1), (s2, n2, z2, u2) = table.rows
    assert s1 == pytest.approx(1000.0, rel=1e-12) and s2 == pytest.approx(6000.0, rel=1e-12)
    assert (n1, n2, u1, u2) == (12, 14, 0, 2) and (z1, z2) == (0.05, -0.01)


def test_gain_map_columns_follow_kd(tmp_path):
    """Row K_p, then the damping ratio at each K_d in the order of ``kd``."""
    table = _table(_stability(tmp_path), "Smallest damping ratio")
    assert list(table.columns) == ["K_p [N/m]", "K_d = 10", "K_d = 20", "K_d = 40"]
    assert [list(r) for r in table.rows] == [[1e5, 0.01, 0.02, 0.03], [2e5, 0.04, 0.05, 0.06]]


# ------------------------------------------------------------------ thermal


def _shaft():
    x = np.array([0.0, 1.0, 2.0])
    return NS(
        temperature=NS(
            x=x, temperature=np.array([315.0, 320.0, 316.0]), air_temperature=313.15, heat_transfer_coefficient=25.0
        ),
        sources=NS(total=np.array([2.0, 2.5]), vibration=np.array([1.0, 2.0]), static=np.array([0.5, 1.0])),
        peak_rise=6.85,
    )


#: A point whose temperature check read nothing (no thermal result of its own): the section's
#: temperature figure then draws the rise and heat alone (tests/test_temperature_check_figure_reference.py
#: covers the check's own panel).
UNREAD_POINT = NS(name="operating point", analyses=NS(thermal=None, conditions=None), evidence=NS(max_temperature=None))


def one_point(**fields):
    """A stand-in assessment of one operating point without a temperature check."""
    return NS(
        points=(UNREAD_POINT,),
        governing_point=UNREAD_POINT.name,
        point=lambda name: UNREAD_POINT,
        verdict=NS(check=_unread),
        **fields,
    )


def _thermal(shaft: dict, sh):
    env = NS(ambient_temperature=303.15)
    return NS(environment=env, shaft=shaft, tailboom={}, self_heating=sh, profiles=None, loss_model="rotating")


def test_self_heating_table_in_celsius_and_watts(tmp_path):
    """Air 313.15 K = 40 °C, h 25, vibration heat 1 + 2 = 3 W, static 0.5 + 1 = 1.5 W, rise 6.85 K;
    ambient 303.15 K = 30.0 °C."""
    sh = NS(status="converged", iterations=4, margin=12.5, max_temperature=353.15)
    section = thermal_section(one_point(thermal=_thermal({"rotating": _shaft()}, sh)), Figures(tmp_path))
    table = _table(section, "Shaft self-heating")
    assert list(table.columns) == [
        "loss model",
        "air [°C]",
        "h [W/m² K]",
        "vibration heat [W]",
        "static heat [W]",
        "peak rise [K]",
    ]
    ((lm, air, h, vib, static, rise),) = table.rows
    assert lm == "rotating" and air == pytest.approx(40.0, abs=1e-9)
    assert (h, vib, static, rise) == (25.0, 3.0, 1.5, 6.85)
    assert section.paragraphs[0].startswith("Ambient 30.0 °C;")


def test_self_heating_alone_peak_in_celsius(tmp_path):
    """Without shaft profiles: the peak 353.15 K is 80.0 °C."""
    sh = NS(status="converged", iterations=4, margin=12.5, max_temperature=353.15)
    section = thermal_section(NS(points=(), thermal=_thermal({}, sh)), Figures(tmp_path))
    (text,) = section.paragraphs
    assert "peak 80.0 °C" in text and "margin to the allowable temperature 12.5 K" in text


def test_the_every_root_checks_lower_onset_beside_the_tracked_modes():
    """docs/requirements.md (`whirl_onset`): the check's value is the lowest onset of the tracked
    modes "or the lowest of rest, the operating speed and (1 + margin) × it where any root of
    the closed loop is unstable". An unstable untracked root at rest (0 rpm) beside tracked modes
    stable to the top: the onset cell adds "; every root: 0 (untracked root)" (audit a2: the
    table said "stable to 7200" beside a verdict failing at rest). A tracked onset at or below
    the check's value, or a check reading a tracked mode, adds nothing."""
    from flexshaft.report.verdict import every_root_onset

    def verdict(value, mode):
        check = NS(value=value, location={"mode": mode})
        return NS(check=lambda key: check if key == "whirl_onset" else _unread(key))

    assert every_root_onset(verdict(0.0, "untracked root"), None) == "; every root: 0 (untracked root)"
    assert every_root_onset(verdict(_rad_s(3000), "divergence (real root)"), _rad_s(5000)) == (
        "; every root: 3000 (divergence (real root))"
    )
    assert every_root_onset(verdict(_rad_s(3000), "untracked root"), _rad_s(3000)) == ""
    assert every_root_onset(verdict(_rad_s(3000), "1 (forward)"), None) == ""
    assert every_root_onset(NS(check=_unread), None) == ""
