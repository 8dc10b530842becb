"""Torsional dynamics of the driveline (issue 25, point 2) against closed forms derived here.

Test shafts. A steel tube (G = 80 GPa, D_o 0.1 m, wall 5 mm, L = 2 m) in torsion: k = G J_p/L
and, with ``density = 0.01`` kg/m³, a near-massless spring: its own polar inertia ρ J_p L
(6.8e-8 kg m², 1e-7 of the end inertias) moves the lumped closed forms' roots by about 5e-8
(proportional to ρ: measured 5e-7 at ρ = 0.1), and the conditioning of the mass matrix (end to
interior-node inertia ~1e9) costs the dense eigen-solver about as much (below ρ = 1e-3 it takes
over: 2e-6 at 1e-4). The lumped closed forms are asserted to 3e-7. With steel's density the
shaft is a continuous rod, checked against its frequency equation. Ends: a disk's polar inertia, the ``[main_gearbox]``
(inertia on the forward twist, spring to the infinite inertia ahead) and the ``[tail_rotor]``
(inertia J_tr/n², drive springs k_input and k_hub/n² in series).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from flexshaft.analyses.modal import modes
from flexshaft.analyses.torsional import (
    TORSIONAL_SEPARATION,
    separation_margin,
    torsional_excitations,
    torsional_forced_response,
    torsional_modes,
    torsional_separation,
)
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import torque_load
from flexshaft.design import DesignError, loads_design, tuned_design, with_overrides

G_STEEL, RHO_STEEL = 80e9, 7800.0
DO, WALL, LENGTH = 0.1, 0.005, 2.0
J_POLAR = np.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 32
K_SHAFT = G_STEEL * J_POLAR / LENGTH


def shaft_text(
    tables: str = "",
    fixed_start: str = '["u", "v", "w", "theta"]',
    density: float = 1e-2,
    elements: int = 8,
    rpm: float = 3000.0,
    operating: str = "",
) -> str:
    """A shaft on two stiff contact bearings; ``tables`` adds disks, [tail_rotor], [main_gearbox],
    ``operating`` more lines of [operating] (e.g. a speed_range). Also the torsional reference
    files' shaft (tests/test_torsional_shapes_and_band_reference.py and two more)."""
    return f"""
name = "torsion test shaft"
[materials.steel]
kind = "isotropic"
E = 210e9
G = {G_STEEL}
density = {density}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = {fixed_start}
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e8, w = 1e8 }}
[[bearings]]
name = "aft"
kind = "contact"
x = {LENGTH}
stiffness = {{ v = 1e8, w = 1e8 }}
[operating]
speed_rpm = {rpm}
power = 100.0e3
{operating}
[mesh]
shaft_elements = {elements}
{tables}
"""


def model_of(text: str):
    return build_model(loads_design(text))


# ------------------------------------------------------------------------------------------------
# Natural frequencies against closed forms


def test_two_inertias_on_a_shaft_give_the_closed_form():
    """Free-free: a disk J1 at the forward end, a rigidly driven tail rotor J2 = J_tr/n² at the
    aft end: ω² = k (J1 + J2)/(J1 J2) and a rigid-body twist at 0 Hz."""
    J1, J_tr, n = 0.3, 4.0, 2.5
    J2 = J_tr / n**2
    text = shaft_text(
        f'[[disks]]\nname = "hub"\nx = 0.0\nmass = 1.0\npolar_inertia = {J1}\n'
        f"[tail_rotor]\nblades = 3\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n",
        fixed_start='["u", "v", "w"]',
    )
    tm = torsional_modes(model_of(text), 2)
    expected = np.sqrt(K_SHAFT * (J1 + J2) / (J1 * J2)) / (2 * np.pi)
    assert tm.natural_frequencies[0] == 0.0
    assert tm.natural_frequencies[1] == pytest.approx(expected, rel=3e-7)


def test_gearbox_on_a_spring_and_a_tail_rotor_give_the_two_dof_closed_form():
    """[main_gearbox] J_g on the forward twist with k_g to the (infinite) inertia ahead, the
    massless shaft k, the rotor J_r: the roots of J_g J_r ω⁴ − (J_g k + J_r (k_g + k)) ω² + k_g k = 0."""
    Jg, kg, J_tr, n = 0.2, 5.0e5, 3.0, 2.0
    Jr = J_tr / n**2
    text = shaft_text(
        f"[main_gearbox]\npolar_inertia = {Jg}\nstiffness = {kg}\n"
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n",
        fixed_start='["u", "v", "w"]',
    )
    k = K_SHAFT
    a, b, c = Jg * Jr, -(Jg * k + Jr * (kg + k)), kg * k
    roots = np.sort((-b + np.array([-1.0, 1.0]) * np.sqrt(b * b - 4 * a * c)) / (2 * a))
    tm = torsional_modes(model_of(text), 2)
    np.testing.assert_allclose(tm.natural_frequencies, np.sqrt(roots) / (2 * np.pi), rtol=3e-7)


def test_tail_rotor_drive_springs_add_in_series_through_the_gear_ratio():
    """Held forward end, massless shaft, elastic drive: one mode ω² = k_eff/(J_tr/n²) with
    1/k_eff = 1/k_shaft + 1/k_input + n²/k_hub (k_hub reflected by 1/n², J_tr by 1/n²)."""
    J_tr, n, k_in, k_hub = 12.0, 3.4, 4.0e4, 2.5e5
    text = shaft_text(
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n"
        f"input_stiffness = {k_in}\nhub_stiffness = {k_hub}\naerodynamic_damping = 0.0\n"
    )
    model = model_of(text)
    assert model.dofs.extra == ("tail_rotor",)
    k_eff = 1.0 / (1.0 / K_SHAFT + 1.0 / k_in + n**2 / k_hub)
    tm = torsional_modes(model, 1)
    assert tm.natural_frequencies[0] == pytest.approx(np.sqrt(k_eff * n**2 / J_tr) / (2 * np.pi), rel=3e-7)


def _tip_inertia_roots(mass_ratio: float, count: int) -> np.ndarray:
    """Roots x = ωL/c of x tan x = ρ J_p L / J_tip, one in each ((k−1)π, (k − ½)π)."""
    return np.array(
        [
            brentq(lambda x: x * np.tan(x) - mass_ratio, (k - 1) * np.pi + 1e-12, (k - 0.5) * np.pi - 1e-12)
            for k in range(1, count + 1)
        ]
    )


@pytest.mark.parametrize("elements", [40, 80])
def test_uniform_shaft_with_a_tip_inertia_matches_its_frequency_equation(elements):
    """Fixed-free steel rod with the tail rotor's reflected inertia at the tip:
    (ωL/c) tan(ωL/c) = ρ J_p L / J_tip, c = √(G/ρ). Linear twist elements with a consistent mass
    overestimate ω by (kh)²/24 (k = ω/c, h the element length): each mode within 1.5 times that
    bound, and the error of mode 3 falls by 4 ± 0.4 per halving of h (second order)."""
    J_tr, n = 0.8, 2.0
    J_tip = J_tr / n**2
    text = shaft_text(
        f"[tail_rotor]\nblades = 2\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n", density=RHO_STEEL, elements=elements
    )
    c = np.sqrt(G_STEEL / RHO_STEEL)
    x = _tip_inertia_roots(RHO_STEEL * J_POLAR * LENGTH / J_tip, 3)
    exact = x * c / LENGTH / (2 * np.pi)
    tm = torsional_modes(model_of(text), 3)
    error = tm.natural_frequencies / exact - 1.0
    h = LENGTH / elements
    bound = (x / LENGTH * h) ** 2 / 24
    assert np.all(error > 0) and np.all(error < 1.5 * bound), (error, bound)


def test_tip_inertia_error_converges_at_second_order():
    J_tr, n = 0.8, 2.0
    x = _tip_inertia_roots(RHO_STEEL * J_POLAR * LENGTH / (J_tr / n**2), 3)
    exact = x[2] * np.sqrt(G_STEEL / RHO_STEEL) / LENGTH / (2 * np.pi)
    errors = []
    for elements in (40, 80):
        text = shaft_text(
            f"[tail_rotor]\nblades = 2\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n",
            density=RHO_STEEL,
            elements=elements,
        )
        errors.append(torsional_modes(model_of(text), 3).natural_frequencies[2] / exact - 1.0)
    assert errors[0] / errors[1] == pytest.approx(4.0, abs=0.4)


# ------------------------------------------------------------------------------------------------
# The subsystem is the full model's torsion; the old model is unchanged without the new keys


def test_torsional_subsystem_agrees_with_the_full_models_torsional_modes():
    """The tuned design (tail rotor behind an elastic drive, hysteretic shaft, aerodynamic
    damping) at 4800 rpm: the modes `modes` labels torsional are those of the subsystem. The
    full model reduces on a truncated modal basis and refines by Newton to 1e-10: frequencies
    agree to 1e-7, damping ratios to 1e-6 relative (measured 5e-9 and 1e-8)."""
    model = build_model(tuned_design())
    full = modes(model, speed=model.speed, n_modes=30)
    torsional = full.kind == "torsional"
    tm = torsional_modes(model, int(torsional.sum()))
    np.testing.assert_allclose(full.frequencies[torsional], tm.frequencies, rtol=1e-7)
    np.testing.assert_allclose(full.damping_ratios[torsional], tm.damping_ratios, rtol=1e-6)


def test_without_the_new_keys_the_model_has_no_drive_terms():
    """A design without [tail_rotor]/[main_gearbox] builds the model of before (no extra DOF,
    the torque on the shaft's aft twist); a rigid [main_gearbox] is fixed_start = ["theta"]."""
    plain = with_overrides(tuned_design(), {"tail_rotor": None})
    model = build_model(plain)
    assert model.dofs.extra == () and not model.drive.has_rotor
    Q = torque_load(model)
    assert Q[model.dofs.shaft(-1, "theta")] == pytest.approx(-model.power / model.speed)
    rigid = build_model(with_overrides(plain, {"main_gearbox": {"polar_inertia": 0.5}, "shaft.fixed_start": []}))
    for name in ("M", "K", "C", "G"):
        assert abs(getattr(rigid, name) - getattr(model, name)).sum() == 0.0
    np.testing.assert_array_equal(rigid.dofs.free, model.dofs.free)


def test_a_rigid_drive_is_an_inertia_on_the_aft_twist():
    """Without drive springs the rotor's J_tr/n² sits on the shaft's aft twist, as a disk's
    polar inertia there: the same torsional frequencies (to round-off)."""
    J_tr, n = 0.8, 2.0
    rotor = shaft_text(f"[tail_rotor]\nblades = 2\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n", density=RHO_STEEL)
    disk = shaft_text(
        f'[[disks]]\nname = "tip"\nx = {LENGTH}\nmass = 0.0\npolar_inertia = {J_tr / n**2}\n', density=RHO_STEEL
    )
    np.testing.assert_allclose(
        torsional_modes(model_of(rotor), 4).natural_frequencies,
        torsional_modes(model_of(disk), 4).natural_frequencies,
        rtol=1e-12,
    )


def test_an_elastic_end_refuses_a_held_twist():
    base = loads_design(shaft_text())
    with pytest.raises(DesignError, match="shaft.fixed_start"):
        with_overrides(base, {"main_gearbox": {"stiffness": 1e5}})
    with pytest.raises(DesignError, match="shaft.fixed_end"):
        with_overrides(
            base,
            {"shaft.fixed_end": ["theta"], "tail_rotor": {"blades": 4, "polar_inertia": 1.0, "gearbox_ratio": 2.0}},
        )
    with pytest.raises(DesignError, match="tail_rotor.polar_inertia"):
        with_overrides(base, {"tail_rotor": {"blades": 4, "polar_inertia": 0.0, "gearbox_ratio": 2.0}})


# ------------------------------------------------------------------------------------------------
# Excitations and separation margins


def test_separation_margin_of_a_band():
    """min |f_n − f_e|/f_e over [9, 10] Hz: below 1 − f/9, above f/10 − 1, inside 0."""
    assert separation_margin(7.0, 9.0, 10.0) == pytest.approx(1 - 7 / 9)
    assert separation_margin(12.0, 9.0, 10.0) == pytest.approx(0.2)
    assert separation_margin(9.5, 9.0, 10.0) == 0.0
    assert separation_margin(0.0, 9.0, 10.0) == 1.0
    with pytest.raises(ValueError, match="band"):
        separation_margin(5.0, 10.0, 9.0)


def test_tuned_excitations_by_hand():
    """4800 rpm shaft, 4 blades at n = 3.42, main rotor 289 rpm with 4 blades: 80 Hz, 80/3.42 and
    4 × 80/3.42 Hz, 289/60 × (1, 2, 3, 4) Hz; over the range 0.95-1.05."""
    design = tuned_design()
    speed = design.operating.speed_rad_s
    bands = {e.name: e.band(0.95 * speed, 1.05 * speed) for e in torsional_excitations(design)}
    hand = {
        "shaft 1/rev": 80.0,
        "tail rotor 1/rev": 80.0 / 3.42,
        "tail rotor 4/rev": 320.0 / 3.42,
        "main rotor 1/rev": 289.0 / 60,
        "main rotor 2/rev": 2 * 289.0 / 60,
        "main rotor 3/rev": 3 * 289.0 / 60,
        "main rotor 4/rev": 4 * 289.0 / 60,
    }
    assert set(bands) == set(hand)
    for name, f in hand.items():
        np.testing.assert_allclose(bands[name], (0.95 * f, 1.05 * f), rtol=1e-12)


def test_separation_of_a_closed_form_mode_from_the_nearest_excitation():
    """The elastic-drive shaft of the series test (one mode, closed form f_1) run at a speed
    that puts the tail rotor's 1/rev 5 % below f_1 over a ±2 % range: the margin is
    f_1/(1.02 f_e) − 1 = 1/(0.95·1.02) − 1, against that excitation, and fails the 10 %."""
    J_tr, n, k_in = 12.0, 3.4, 4.0e4
    k_eff = 1.0 / (1.0 / K_SHAFT + 1.0 / k_in)
    f1 = np.sqrt(k_eff * n**2 / J_tr) / (2 * np.pi)
    rpm = 0.95 * f1 * n * 60.0  # tail-rotor 1/rev at 0.95 f1
    text = shaft_text(
        f"[tail_rotor]\nblades = 5\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\ninput_stiffness = {k_in}\n"
    )
    text = text.replace("speed_rpm = 3000.0", f"speed_rpm = {rpm}\nspeed_range = [0.98, 1.02]")
    (first, *_) = torsional_separation(model_of(text))
    assert first.natural_frequency == pytest.approx(f1, rel=3e-7)
    assert (first.excitation, first.source, first.order) == ("tail rotor 1/rev", "tail_rotor", 1)
    assert first.margin == pytest.approx(first.natural_frequency / (1.02 * f1 * 0.95) - 1.0, rel=1e-12)
    assert first.margin == pytest.approx(1.0 / (0.95 * 1.02) - 1.0, rel=1e-5)
    assert not first.passed and first.required == TORSIONAL_SEPARATION


# ------------------------------------------------------------------------------------------------
# Forced response to the tail rotor's torque oscillation


@pytest.mark.parametrize("eta", [0.0, 0.05])
def test_forced_response_matches_the_damped_single_dof_closed_form(eta):
    """Held forward end, massless shaft of complex stiffness k_s(1 + iη), drive spring k_in, rotor
    J = J_tr/n² with aerodynamic damping c = c_tr/n². A torque a T on the rotor at ω gives the
    rotor twist φ = aT/(k* − Jω² + icω), 1/k* = 1/(k_s(1 + iη)) + 1/k_in, and the shaft carries
    k* φ: |T_shaft| = a T |k*/(k* − Jω² + icω)| at ω = Ω/n and NΩ/n. Stress |T| r_o/J_p; the
    factor 1 + Σ|T_k|/T (uniform torque in a massless shaft). The shaft's own inertia (module
    docstring), left out here, changes a harmonic's torque by about J_s ω²/k: 2.3e-9 at 1/rev and
    2.7e-8 at 4/rev (measured with both η): 1e-7 asserted, 3.7 times the larger."""
    J_tr, n, k_in, c_tr, blades = 12.0, 3.4, 4.0e4, 30.0, 4
    text = shaft_text(
        f"[tail_rotor]\nblades = {blades}\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\ninput_stiffness = {k_in}\n"
        f"aerodynamic_damping = {c_tr}\ntorque_oscillation_1p = 0.05\ntorque_oscillation_np = 0.1\n"
    ).replace("loss_factor = 0.0", f"loss_factor = {eta}")
    model = model_of(text)
    speed = model.speed
    response = torsional_forced_response(model)
    T = 100.0e3 / speed
    k_star = 1.0 / (1.0 / (K_SHAFT * (1 + 1j * eta)) + 1.0 / k_in)
    J, c = J_tr / n**2, c_tr / n**2
    amplitudes = []
    for harmonic, order, a in zip(response.harmonics, (1, blades), (0.05, 0.1)):
        w = order * speed / n
        expected = a * T * abs(k_star / (k_star - J * w * w + 1j * c * w))
        assert harmonic.order == order and harmonic.frequency == pytest.approx(w / (2 * np.pi))
        assert harmonic.excitation == pytest.approx(a * T)
        assert harmonic.torque == pytest.approx(expected, rel=1e-7)
        assert harmonic.shear_stress == pytest.approx(expected * (DO / 2) / J_POLAR, rel=1e-7)
        amplitudes.append(expected)
    assert response.steady_torque == pytest.approx(T)
    assert response.torque_factor == pytest.approx(1 + sum(amplitudes) / T, rel=1e-7)
    assert response.peak_shear_stress == pytest.approx((T + sum(amplitudes)) * (DO / 2) / J_POLAR, rel=1e-7)


def test_forced_response_at_resonance_amplifies_by_the_quality_factor():
    """A rigid drive (the rotor's inertia and damping on the shaft's aft twist) with the tail
    rotor's 1/rev tuned onto ω_n = √(k/J): the shaft carries k φ = aT k/(i c ω_n), a torque
    ratio of exactly 1/(2ζ), ζ = c/(2 J ω_n). The shaft's own inertia detunes ω_n by ~5e-8 and
    the peak by (that/ζ)² ≈ 1e-8 (measured): 1e-6 asserted."""
    J_tr, n, c_tr = 12.0, 3.4, 30.0
    J, c = J_tr / n**2, c_tr / n**2
    wn = np.sqrt(K_SHAFT / J)
    rpm = wn * n * 60.0 / (2 * np.pi)
    text = shaft_text(
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\naerodynamic_damping = {c_tr}\n"
    ).replace("speed_rpm = 3000.0", f"speed_rpm = {rpm}")
    response = torsional_forced_response(model_of(text))
    zeta = c / (2 * J * wn)
    assert response.harmonics[0].frequency == pytest.approx(wn / (2 * np.pi), rel=1e-12)
    assert response.harmonics[0].amplification == pytest.approx(1 / (2 * zeta), rel=1e-6)


def test_forced_response_needs_a_tail_rotor():
    with pytest.raises(ValueError, match="tail_rotor"):
        torsional_forced_response(model_of(shaft_text()))
