"""Active magnetic bearing (issue 13, item 3) against references derived here.

The bearing: force on the shaft f = k_s d_a + k_i i, i = −A(s) C(s) d_s (flexshaft.assembly.model
.Actuator). Test rotor: a near-rigid steel-like tube (E = 2.1e15 Pa, 1e4 × steel, so its first
bending mode lies near 1e5 rad/s, far above the rigid-body modes of ~200-400 rad/s) with a
central disk, held only by two magnetic bearings at x = 0.1 and 0.9 m (l = 0.4 m from the
centre), u and θ held at x = 0. Its rigid-body mass and transverse inertia follow exactly from
the consistent mass matrix (Hermite shapes reproduce rigid motion): m = ρAL + m_d,
I_t = ρAL³/12 + ρIL + I_d. Per lateral plane (translation y at the centre, tilt θ), bearing j
at x_j = ∓l sees d_j = y + x_j θ.

Tolerance of the rigid-rotor comparisons. The FE rotor is flexible: its rigid-body roots
differ from the rigid closed form by a flexibility error ∝ 1/E (measured 9e-5, 9e-6, 1.1e-6
relative at E = 2.1e13, 2.1e14, 2.1e15), and round-off of the stiff state matrix takes over
beyond. At E = 2.1e15 the oscillatory roots agree to ~1e-6 and the fast real poles of the
controller (~6000 1/s) to ~1.4e-5; 5e-6 and 3e-5 are asserted.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
import scipy.sparse.linalg as sla

from flexshaft.analyses import frequency_response, imbalance_response, modes, static_response
from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.reactions import bearing_forces
from flexshaft.analyses.reduced_basis import modal_basis
from flexshaft.analyses.response import orbit_amplitude, static_actuator_forces
from flexshaft.analyses.spinup import actuator_receptance, spinup_curves, spinup_map
from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Controller
from flexshaft.design import DesignError, baseline_design, loads_design, with_overrides
from flexshaft.elements import magnetic

L, DO, WALL, RHO, E_RIGID = 1.0, 0.1, 0.01, 7800.0, 2.1e15
M_DISK, I_DISK, IP_DISK = 20.0, 0.5, 1.0
X_BEARINGS = (0.1, 0.9)
HALF_SPAN = 0.4
AREA = np.pi * (DO**2 - (DO - 2 * WALL) ** 2) / 4
INERTIA = np.pi * (DO**4 - (DO - 2 * WALL) ** 4) / 64
MASS = RHO * AREA * L + M_DISK
I_T = RHO * AREA * L**3 / 12 + RHO * INERTIA * L + I_DISK

KS, KI = 5.0e5, 100.0  # N/m, N/A
KP, KD, K_INT = 1.5e4, 10.0, 2.0e5  # A/m, A s/m, A/(m s)
F_D, F_A = 500.0, 1000.0  # derivative-filter corner and amplifier bandwidth [Hz]


def rotor_text(keys: str | list[str], speed_rpm: float = 0.0, modulus: float = E_RIGID) -> str:
    """The test rotor; ``keys`` are the TOML lines of both bearings (or one string per bearing)."""
    per = [keys, keys] if isinstance(keys, str) else keys
    bearings = "".join(
        f'\n[[bearings]]\nname = "amb_{k + 1}"\nkind = "active"\nx = {x}\n{per[k]}\n' for k, x in enumerate(X_BEARINGS)
    )
    return f"""
name = "rigid rotor on two magnetic bearings"
[materials.stiff]
kind = "isotropic"
E = {modulus}
G = {modulus / 2.6}
density = {RHO}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "stiff"
fixed_start = ["u", "theta"]
{bearings}
[[disks]]
name = "disk"
x = 0.5
mass = {M_DISK}
diametral_inertia = {I_DISK}
polar_inertia = {IP_DISK}
[operating]
speed_rpm = {speed_rpm}
power = 0.0
[mesh]
shaft_elements = 8
"""


def rotor(keys, speed_rpm: float = 0.0, modulus: float = E_RIGID):
    return build_model(loads_design(rotor_text(keys, speed_rpm, modulus)))


PID_KEYS = (
    f"kp = {KP}\nkd = {KD}\nintegral_gain = {K_INT}\nderivative_cutoff = {F_D}\n"
    f"amplifier_bandwidth = {F_A}\nks = {KS}\nki = {KI}"
)


def by_magnitude(s: np.ndarray) -> np.ndarray:
    return s[np.argsort(np.abs(s), kind="stable")]


def hand_state_matrix(offsets=(0.0, 0.0), integral=K_INT, derivative=KD, wd=2 * np.pi * F_D, wa=2 * np.pi * F_A):
    """Rigid rotor + two PID bearings, one lateral plane, written out by hand.

    States z = [y, θ, ẏ, θ̇, (x_I, x_F, i) per bearing]: sensed d_s = y + (x_j + δ_j) θ,
    ẋ_I = d_s (integrator), ẋ_F = ω_d (d_s − x_F) (so ω_d (d_s − x_F) = s/(1 + s/ω_d) d_s),
    command u = K_p d_s + K_I x_I + K_d ω_d (d_s − x_F), amplifier i̇ = ω_a (−u − i), force
    f_j = k_s d_a + k_i i with d_a = y + x_j θ acting on (y, θ) through (1, x_j).
    """
    A = np.zeros((10, 10))
    A[0, 2] = A[1, 3] = 1.0
    inverse_mass = np.diag([1.0 / MASS, 1.0 / I_T])
    for j, x in enumerate((-HALF_SPAN, HALF_SPAN)):
        b_a = np.array([1.0, x])
        b_s = np.array([1.0, x + offsets[j]])
        o = 4 + 3 * j
        A[o, 0:2] = b_s
        A[o + 1, 0:2] = wd * b_s
        A[o + 1, o + 1] = -wd
        command_q = KP * b_s + derivative * wd * b_s
        A[o + 2, 0:2] = -wa * command_q
        A[o + 2, o] = -wa * integral
        A[o + 2, o + 1] = wa * derivative * wd
        A[o + 2, o + 2] = -wa
        A[2:4, 0:2] += inverse_mass @ np.outer(b_a, KS * b_a)
        A[2:4, o + 2] += inverse_mass @ (KI * b_a)
    return A


def assert_spectrum_contains(full: np.ndarray, reference: np.ndarray, rtol: float) -> None:
    """Every reference eigenvalue has a partner in ``full`` within ``rtol`` (each used once)."""
    pool = list(full)
    for s in reference:
        k = int(np.argmin([abs(p - s) for p in pool]))
        assert abs(pool[k] - s) <= rtol * abs(s), (s, pool[k])
        pool.pop(k)


# ------------------------------------------------------------------------------------------------
# Magnet physics


def test_current_gain_and_force_slope_are_the_derivatives_of_the_magnet_pair_force():
    """f(i, x) = k[(i0 + i)²/(g0 − x)² − (i0 − i)²/(g0 + x)²], k = ¼μ0N²A cos α, differentiated
    numerically (central differences, step 1e-6 of the scale: truncation ~1e-12)."""
    turns, area, i0, g0, alpha = 200.0, 8e-4, 4.775, 1e-3, np.pi / 8
    k = 0.25 * 4e-7 * np.pi * turns**2 * area * np.cos(alpha)

    def force(i, x):
        return k * ((i0 + i) ** 2 / (g0 - x) ** 2 - (i0 - i) ** 2 / (g0 + x) ** 2)

    hi, hx = 1e-6 * i0, 1e-6 * g0
    ki = (force(hi, 0.0) - force(-hi, 0.0)) / (2 * hi)
    ks = (force(0.0, hx) - force(0.0, -hx)) / (2 * hx)
    assert magnetic.current_gain(turns, area, i0, g0, alpha) == pytest.approx(ki, rel=1e-9)
    assert magnetic.force_slope(turns, area, i0, g0, alpha) == pytest.approx(ks, rel=1e-9)
    assert ks > 0  # the magnets pull the shaft further off centre


def test_saturation_force_is_one_magnet_at_the_saturation_flux_density():
    """B = μ0 N i/(2 g) in the two gaps of a horseshoe; at B = B_sat the force k i²/g² equals
    B_sat² A cos α/μ0; 1 T over 1 cm² of pole face pulls B²/(2μ0) = 39.79 N (the textbook
    '40 N/cm²'); with the bias at half saturation f_sat = k_s g0."""
    turns, area, g0, alpha, b_sat = 200.0, 8e-4, 1e-3, np.pi / 8, 1.2
    i_sat = 2 * g0 * b_sat / (4e-7 * np.pi * turns)
    one_magnet = magnetic.magnet_constant(turns, area, alpha) * i_sat**2 / g0**2
    assert magnetic.saturation_force(b_sat, area, alpha) == pytest.approx(one_magnet, rel=1e-12)
    per_pole = magnetic.saturation_force(1.0, 1e-4) / 2
    assert per_pole == pytest.approx(1.0 / (2 * 4e-7 * np.pi) * 1e-4, rel=1e-12) and per_pole == pytest.approx(
        39.79, abs=0.01
    )
    i0 = i_sat / 2
    assert magnetic.bias_flux_density(turns, i0, g0) == pytest.approx(b_sat / 2, rel=1e-12)
    assert magnetic.saturation_force(b_sat, area, alpha) == pytest.approx(
        magnetic.force_slope(turns, area, i0, g0, alpha) * g0, rel=1e-12
    )
    with pytest.raises(ValueError, match="air_gap must be a finite number > 0"):
        magnetic.force_slope(turns, area, i0, 0.0)


def test_magnet_constant_matches_the_measured_value_of_a_laboratory_bearing():
    """TU Darmstadt AMrotor rig (github.com/AppliedMechanics/AMrotor, Config_Sim_Mag1.m): pole
    area 2.9 cm², 2 × 104 turns, α = 22.5°, k = 3.63e-6 N m²/A² from measured characteristic
    curves. The ideal-magnet formula neglects iron reluctance, leakage and fringing, which lower
    the real k a little: 0.5 % is allowed (measured difference 0.32 %, quoted to 3 digits)."""
    assert magnetic.magnet_constant(208.0, 2.9e-4, np.radians(22.5)) == pytest.approx(3.63e-6, rel=5e-3)


def test_magnet_geometry_keys_build_the_actuator_of_its_gains():
    geometry = {
        "coil_turns": 200.0,
        "pole_area": 8e-4,
        "bias_current": 4.775,
        "air_gap": 1e-3,
        "saturation_flux_density": 1.2,
    }
    keys = "kp = 1.0e4\n" + "\n".join(f"{k} = {v}" for k, v in geometry.items())
    act = rotor(keys).actuators[0]
    alpha = np.radians(22.5)  # default pole angle (8-pole stator)
    k = 0.25 * 4e-7 * np.pi * 200.0**2 * 8e-4 * np.cos(alpha)
    assert act.current_gain == pytest.approx(4 * k * 4.775 / 1e-6, rel=1e-12)
    assert act.negative_stiffness == pytest.approx(4 * k * 4.775**2 / 1e-9, rel=1e-12)
    assert act.saturation_force == pytest.approx(1.2**2 * 8e-4 * np.cos(alpha) / (4e-7 * np.pi), rel=1e-12)
    assert (act.air_gap, act.bias_current) == (1e-3, 4.775)


# ------------------------------------------------------------------------------------------------
# Rigid rotor: closed forms and hand-built state-space models


def test_pd_magnetic_bearings_give_the_closed_form_rigid_rotor_roots():
    """k = k_i K_p − k_s, c = k_i K_d per bearing: translation m s² + 2c s + 2k = 0, tilt
    I_t s² + 2c l² s + 2k l² = 0, each in both lateral planes."""
    model = rotor(f"kp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}")
    k, c = KI * KP - KS, KI * KD
    translation = np.roots([MASS, 2 * c, 2 * k])
    tilt = np.roots([I_T, 2 * c * HALF_SPAN**2, 2 * k * HALF_SPAN**2])
    expected = by_magnitude(np.array([r for r in (*translation, *tilt) if r.imag > 0] * 2))
    found = modes(model, 0.0, 4).eigenvalues
    np.testing.assert_allclose(np.sort_complex(found), np.sort_complex(expected), rtol=5e-6)


def test_open_loop_magnet_is_a_divergence_reported_by_modes_and_stability():
    """C = 0: m ÿ = 2 k_s y, I_t θ̈ = 2 k_s l² θ: real roots +√(2k_s/m), +√(2k_s l²/I_t). They are
    not oscillatory, so they must be reported as divergent modes (Im s = 0, ζ = −1) and as a
    divergence of the stability analysis from the first speed on."""
    model = rotor(f"kp = 0.0\nks = {KS}\nki = {KI}")
    md = modes(model, 0.0, 4)
    expected = np.sort([np.sqrt(2 * KS / MASS)] * 2 + [np.sqrt(2 * KS * HALF_SPAN**2 / I_T)] * 2)
    assert np.all(md.divergent) and np.all(md.eigenvalues.imag == 0)
    np.testing.assert_allclose(np.sort(md.eigenvalues.real), expected, rtol=5e-6)
    assert np.allclose(md.damping_ratios, -1.0)
    result = stability(model, [0.0, 100.0, 200.0], n_modes=2)  # tracks the (stable) bending modes
    assert result.onset_kind == "divergence" and result.onset_speed == 0.0 and result.unstable_mode is None
    assert result.divergence[0] == pytest.approx(expected[-1], rel=5e-6)
    # spinning, the gyroscopic moment couples the two tilt planes (their real roots merge into
    # an unstable complex pair); the translation root √(2k_s/m) stays real at every speed
    assert np.all(result.divergence[1:] >= expected[0] * (1 - 5e-6))
    assert np.all(result.stability_margin == -1.0) and result.divergent
    # K_p below k_s/k_i: still a divergence, with 2(k_s − k_i K_p) in place of 2 k_s
    weak = modes(rotor(f"kp = {0.5 * KS / KI}\nks = {KS}\nki = {KI}"), 0.0, 4)
    np.testing.assert_allclose(np.sort(weak.eigenvalues.real), expected / np.sqrt(2), rtol=5e-6)


def test_a_divergence_onset_is_saved_without_a_mode_number(tmp_path):
    """The open-loop magnet diverges from the first speed on (previous test: real roots
    +√(2k_s/m), +√(2k_s l²/I_t)) and no tracked mode is unstable: the dataset and the netCDF
    file carry the onset speed (0 rad/s) and kind "divergence", and no mode number (there is
    none: it once failed on int(None))."""
    xr = pytest.importorskip("xarray")
    result = stability(rotor(f"kp = 0.0\nks = {KS}\nki = {KI}"), [0.0, 100.0, 200.0], n_modes=2)
    assert result.unstable_mode is None
    ds = result.to_dataset()
    assert ds.attrs["onset_kind"] == "divergence" and ds.attrs["onset_speed"] == 0.0
    assert "unstable_mode" not in ds.attrs
    with xr.open_dataset(result.save(tmp_path / "stability")) as saved:
        assert saved.attrs["onset_kind"] == "divergence" and saved.attrs["onset_speed"] == 0.0


def test_pid_with_filtered_derivative_and_amplifier_lag_matches_the_hand_built_closed_loop():
    model = rotor(PID_KEYS)
    hand = la.eigvals(hand_state_matrix())
    oscillatory = by_magnitude(hand[hand.imag > 0])
    found = modes(model, 0.0, 4).eigenvalues
    np.testing.assert_allclose(np.sort_complex(found), np.sort_complex(np.repeat(oscillatory, 2)), rtol=5e-6)
    # the whole spectrum, real controller poles included: the model's first-order matrix
    # (exact: the basis is every free DOF) holds each hand root twice (two lateral planes)
    red = reduce(model, model.dofs.free.size)
    assert red.n_states == 2 * model.dofs.free.size + 2 * 2 * 3  # three controller states per direction
    assert_spectrum_contains(la.eigvals(red.state_matrix(0.0)), np.repeat(hand, 2), rtol=3e-5)


def test_noncollocated_sensors_match_the_hand_built_model():
    """Sensors 0.08 m inboard of bearing 1 and 0.03 m outboard of bearing 2 (unequal, so that the
    translation and tilt couple): eigenvalues against the hand-built closed loop, the sensing
    kinematics, and the harmonic response."""
    offsets = (0.08, 0.03)
    model = rotor([PID_KEYS + f"\nsensor_offset = {offsets[0]}", PID_KEYS + f"\nsensor_offset = {offsets[1]}"])
    assert not model.actuators[0].collocated
    hand = la.eigvals(hand_state_matrix(offsets))
    assert not np.allclose(np.sort_complex(hand), np.sort_complex(la.eigvals(hand_state_matrix())), rtol=1e-3)
    oscillatory = by_magnitude(hand[hand.imag > 0])
    found = modes(model, 0.0, 2 * oscillatory.size).eigenvalues
    np.testing.assert_allclose(np.sort_complex(found), np.sort_complex(np.repeat(oscillatory, 2)), rtol=5e-6)
    red = reduce(model, model.dofs.free.size)
    assert_spectrum_contains(la.eigvals(red.state_matrix(0.0)), np.repeat(hand, 2), rtol=3e-5)

    # the sensing rows measure y + (x_j + δ_j) θ of a rigid motion (v = y + (x − ½)θ, γ = θ)
    dm = model.dofs
    x = np.asarray(dm.shaft_x)
    y, theta = 1e-4, 2e-3
    rigid = np.zeros(dm.size)
    rigid[dm.shaft(np.arange(x.size), "v")] = y + (x - 0.5) * theta
    rigid[dm.shaft(np.arange(x.size), "gamma")] = theta
    for j, a in enumerate(model.actuators):
        x_j = X_BEARINGS[j] - 0.5
        assert (a.sensing_rows @ rigid)[0] == pytest.approx(y + (x_j + offsets[j]) * theta, rel=1e-12)
        assert (a.lateral_rows @ rigid)[0] == pytest.approx(y + x_j * theta, rel=1e-12)

    # harmonic response (banded solver, B_aᵀ G B_s term) against a dense solve of the same
    # matrices with the law written out here. A steel tube (E = 210 GPa): the near-rigid one
    # makes Z too ill-conditioned (1e12) for a 1e-6 forward error.
    model = rotor(
        [PID_KEYS + f"\nsensor_offset = {offsets[0]}", PID_KEYS + f"\nsensor_offset = {offsets[1]}"], modulus=2.1e11
    )
    dm, free = model.dofs, model.dofs.free
    load = np.zeros(dm.size)
    load[dm.shaft(dm.node_at("shaft", 0.5), "v")] = 1.0
    load[dm.shaft(dm.node_at("shaft", 0.5), "gamma")] = 0.3
    wd, wa = 2 * np.pi * F_D, 2 * np.pi * F_A
    for omega in (50.0, 219.0, 400.0):
        s = 1j * omega
        law = KI * (KP + K_INT / s + KD * s / (1 + s / wd)) / (1 + s / wa)
        Z = (model.K - omega**2 * model.M).toarray().astype(complex)
        for a in model.actuators:
            B_a, B_s = a.lateral_rows.toarray(), a.sensing_rows.toarray()
            Z += law * B_a.T @ B_s - KS * B_a.T @ B_a
        direct = np.linalg.solve(Z[np.ix_(free, free)], load[free])
        np.testing.assert_allclose(
            frequency_response(model, load, omega)[free], direct, rtol=1e-8, atol=1e-10 * np.abs(direct).max()
        )


def test_noncollocated_pd_bearings_match_the_hand_built_second_order_model():
    """A PD law without filters or lag has no controller states: its K_p and K_d act from the
    sensing to the actuation rows as non-symmetric stiffness and damping,
    K = Σ (k_i K_p b_a b_sᵀ − k_s b_a b_aᵀ), C = Σ k_i K_d b_a b_sᵀ on (y, θ)."""
    offsets = (0.06, -0.02)
    model = rotor([f"kp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}\nsensor_offset = {o}" for o in offsets])
    K, C = np.zeros((2, 2)), np.zeros((2, 2))
    for j, x in enumerate((-HALF_SPAN, HALF_SPAN)):
        b_a, b_s = np.array([1.0, x]), np.array([1.0, x + offsets[j]])
        K += KI * KP * np.outer(b_a, b_s) - KS * np.outer(b_a, b_a)
        C += KI * KD * np.outer(b_a, b_s)
    M = np.diag([MASS, I_T])
    first_order = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    hand = la.eigvals(first_order)
    found = modes(model, 0.0, 4).eigenvalues
    # 1e-5 (measured 6.5e-6): round-off of the Newton refinement of the double roots (one per
    # plane) on the ill-conditioned stiff tube; the state-matrix eigenvalues agree to 4e-7, and
    # the error does not follow the 1/E flexibility trend between E = 1e15 and 5e15
    np.testing.assert_allclose(np.sort_complex(found), np.sort_complex(np.repeat(hand[hand.imag > 0], 2)), rtol=1e-5)
    # static: K (y, θ) = (P, M) at the disk; the magnets' displacements y + x_j θ (the tube's own
    # bending adds ~1e-5 of the bearing deflection: 1e-4 asserted)
    dm = model.dofs
    centre = dm.node_at("shaft", 0.5)
    load = np.zeros(dm.size)
    load[dm.shaft(centre, "v")], load[dm.shaft(centre, "gamma")] = 500.0, 80.0
    y, theta = np.linalg.solve(K, [500.0, 80.0])
    q = static_response(model, load)
    for j, a in enumerate(model.actuators):
        assert (a.lateral_rows @ q)[0] == pytest.approx(y + (X_BEARINGS[j] - 0.5) * theta, rel=1e-4)


def test_integrating_controller_holds_the_sensors_statically_and_carries_the_lever_reactions():
    """With integral action the static equilibrium is d_s = 0 at each sensor; the bearing forces
    are then the reactions of a two-support beam (statically determinate: any flexibility)."""
    offsets = (0.0, 0.05)
    model = rotor([PID_KEYS, PID_KEYS + f"\nsensor_offset = {offsets[1]}"])
    dm = model.dofs
    node, P = dm.node_at("shaft", 0.7), 1000.0
    x_load = dm.shaft_x[node]
    load = np.zeros(dm.size)
    load[dm.shaft(node, "v")] = P
    q = static_response(model, load)
    for a in model.actuators:
        assert np.abs(a.sensing_rows @ q).max() < 1e-12 * np.abs(q).max()
    forces = static_actuator_forces(model, load)
    x1, x2 = X_BEARINGS
    reaction_2 = P * (x_load - x1) / (x2 - x1)
    assert forces["amb_1"][0] == pytest.approx(P - reaction_2, rel=1e-9)
    assert forces["amb_2"][0] == pytest.approx(reaction_2, rel=1e-9)
    assert abs(forces["amb_1"][1]) < 1e-9 * P
    with pytest.raises(ValueError, match="integrate"):
        bearing_forces(model, q)
    via_loads = bearing_forces(model, q, loads=load)
    assert via_loads["amb_2"][1].real == pytest.approx(reaction_2, rel=1e-9)


def test_pd_bearing_static_deflection_is_the_reaction_over_the_net_stiffness():
    """Centre load P on two PD magnetic bearings: each carries P/2 (statics) and deflects
    P/(2(k_i K_p − k_s)); the shaft's own bending does not enter the bearing deflection."""
    model = rotor(f"kp = {KP}\nkd = {KD}\nks = {KS}\nki = {KI}")
    dm = model.dofs
    load = np.zeros(dm.size)
    load[dm.shaft(dm.node_at("shaft", 0.5), "w")] = 800.0
    q = static_response(model, load)
    for a in model.actuators:  # 1e-7: conditioning of the stiff tube (K ~ 1e15 N/m against 1e6)
        assert (a.lateral_rows @ q)[1] == pytest.approx(400.0 / (KI * KP - KS), rel=1e-7)
    assert bearing_forces(model, q)["amb_1"][2].real == pytest.approx(400.0, rel=1e-7)


# ------------------------------------------------------------------------------------------------
# Campbell and stability against the frequency response


def test_campbell_and_stability_with_a_transfer_function_controller_agree_with_frf_peaks():
    """Peaks of the forward-whirl receptance of the PID rotor against the damped eigenvalues.

    A single-DOF peak of |H| sits at ω_n√(1 − 2ζ²), ζ²ω_n/2 below the damped frequency
    ω_n√(1 − ζ²); the half-power bandwidth is 2ζω_n. Asserted: the peak lies within 5 % of the
    half-power bandwidth of ω_d, and within 1 % of it of ω_n√(1 − 2ζ²) (measured ≤ 0.9 %, the
    forward tilt mode at speed, whose gyroscopic stiffening makes it not quite single-DOF; the
    translation mode to 0.01 %). Stability tracks the same eigenvalues (same physics)."""
    from scipy.optimize import minimize_scalar

    model = rotor(PID_KEYS)
    speeds = np.array([0.0, 150.0, 300.0, 450.0])
    exact = model.dofs.free.size  # every free DOF in the basis: both analyses exact
    camp = campbell(model, speeds, n_modes=4, basis_size=exact)
    stab = stability(model, speeds, n_modes=4, basis_size=exact)
    assert stab.onset_speed is None and stab.onset_kind is None and not stab.divergent
    np.testing.assert_allclose(
        np.sort_complex(stab.eigenvalues.ravel()), np.sort_complex(camp.eigenvalues.ravel()), rtol=1e-9
    )
    dm = model.dofs
    node = dm.node_at("shaft", 0.5)
    v, w, beta, gamma = (dm.shaft(node, f) for f in ("v", "w", "beta", "gamma"))

    def receptance(kind, omega, speed):
        Q = np.zeros(dm.size, complex)
        if kind == "translation":  # forward rotating force (v, w) = (1, −i)
            Q[v], Q[w] = 1.0, -1j
            q = frequency_response(model, Q, omega, speed)
            return abs(q[v] + 1j * q[w]) / 2
        Q[gamma], Q[beta] = 1.0, 1j  # forward rotating moment: (γ, −β) turns like (v, w)
        q = frequency_response(model, Q, omega, speed)
        return abs(q[gamma] - 1j * q[beta]) / 2

    checked = 0
    for k, speed in enumerate(speeds):
        for m in range(4):
            s = camp.eigenvalues[k, m]
            if camp.whirl[k, m] == "backward":
                continue
            kind = "translation" if s.imag < 300.0 else "tilt"
            omega_n, zeta = abs(s), -s.real / abs(s)
            peak = minimize_scalar(
                lambda om, kind=kind, speed=speed: -receptance(kind, om, speed),
                bounds=(0.8 * s.imag, 1.2 * s.imag),
                method="bounded",
                options={"xatol": 1e-7},
            ).x
            bandwidth = 2 * zeta * omega_n
            assert abs(peak - s.imag) < 0.05 * bandwidth
            assert abs(peak - omega_n * np.sqrt(1 - 2 * zeta**2)) < 0.01 * bandwidth
            checked += 1
    # every speed has a forward translation and a forward tilt mode: the translation pair is
    # degenerate at every speed (no gyroscopic coupling in translation of the symmetric rotor),
    # the tilt pair at rest, and a degenerate pair is resolved into one forward and one
    # backward whirl (flexshaft.analyses.classify.circular_pairs)
    assert checked == 2 * len(speeds)


# ------------------------------------------------------------------------------------------------
# The thesis's PD bearing on the embedded baseline


@pytest.fixture(scope="module")
def thesis():
    return build_model(baseline_design())


@pytest.fixture(scope="module")
def thesis_0f8aaa9():
    """The PD baseline of commit 0f8aaa9 (tests/data), from before the magnetic bearing existed."""
    from pathlib import Path

    from flexshaft.design import load_design

    return build_model(load_design(Path(__file__).parent / "data" / "baseline_0f8aaa9.toml"))


def _free_matrices(model):
    """Dense free-DOF matrices of a PD-bearing model: M, K + K_p, C + K_d, G and the loss
    matrices F, K_lat, K_lat S [SI]."""
    from flexshaft.assembly.sparse import restrict

    assert model.all_pd
    free = model.dofs.free

    def take(A):
        return restrict(A.tocsr(), free).toarray()

    return (
        take(model.M),
        take(model.K + model.Kp),
        take(model.C + model.Kd),
        take(model.G),
        take(model.loss_fixed),
        take(model.loss_lateral),
        take(model.loss_circulatory),
    )


#: Loss weights of (F, K_lat, K_lat S), typed from docs/model.md ("One damping physics"):
#: L(ω, Ω) = i F + i (σ_B + σ)/2 K_lat + (σ_B − σ)/2 K_lat S, σ = sgn(ω − Ω), σ_B = 1.
ABOVE, BELOW, SYNCHRONOUS = (1j, 1j, 0.0), (1j, 0.0, 1.0), (1j, 0.5j, 0.5)


def test_thesis_pd_bearing_against_full_order_direct_solutions(thesis_0f8aaa9):
    """The PD baseline of commit 0f8aaa9 (before the magnetic bearing existed) against direct
    solutions of its full free-DOF equations, built here from the assembled matrices and the
    loss law of docs/model.md; nothing of the modal basis, the branch logic or the banded
    solver is shared. (This replaces 26 numbers copied from that commit's output.)

    * Eigenvalues at the operating speed: each side's quadratic problem
      [s² M + s(ΩG + C + K_d) + K + K_p + W] x = 0, made symmetric by the Cholesky factor of
      M = RᵀR and solved as a companion eigenproblem; the roots on their own side of the spin,
      lowest 12. The companion problem is solved by shift-invert Arnoldi (ARPACK through
      scipy.sparse.linalg.eigs, σ = 0, to machine precision): the 30 roots nearest zero of
      each side, which hold every root smaller than the largest of them; the test asserts that
      the 12th root lies below both sides' largest (so none is missed). It agrees with a dense
      QR solve of the same 672 × 672 matrices to 3e-11 (measured), at a quarter of the CPU
      (issue 23). The package's come from a modal basis, so they differ by its truncation (a
      deterministic model error, not round-off: 4e-7 measured with the default 48 modes, 8e-8
      with 96, 2e-10 with all 336, the reference's own ε·cond(M) ≈ 2e-16 × 7e6 = 1.5e-9): held
      to 1e-5 (the bound tests/test_stability.py states for the basis against the full state
      space) and, with 96 modes, to 1e-6.
    * Imbalance response over 40 speeds: the dense solve of Z(Ω) q = Ω² Q₁,
      Z = −Ω²M + iΩ(ΩG + C + K_d) + K + K_p + L(Ω, Ω) (synchronous: σ = 0), to
      100 ε κ₁(Z) relative to the response (two backward-stable solves; κ₁ LAPACK's estimate).

    The spin-up map of this model is checked against direct solves in tests/test_spinup.py."""
    model = thesis_0f8aaa9
    M, K, D, G, F, L, S = _free_matrices(model)
    n, speed = M.shape[0], model.speed
    R = la.cholesky(M)  # M = Rᵀ R
    Ri = la.solve_triangular(R, np.eye(n))
    roots, complete_below = [], []
    for (wf, wl, ws), sign in ((ABOVE, +1), (BELOW, -1)):
        Kw = Ri.T @ (K + wf * F + wl * L + ws * S) @ Ri
        Dw = Ri.T @ (D + speed * G) @ Ri
        companion = np.block([[np.zeros((n, n)), np.eye(n)], [-Kw, -Dw]])
        lam = sla.eigs(companion, k=30, sigma=0.0, return_eigenvectors=False, tol=0)
        complete_below.append(np.abs(lam).max())  # every root of smaller modulus is in lam
        roots.append(lam[(lam.imag > 0) & (sign * (lam.imag - speed) >= 0)])
    roots = np.concatenate(roots)
    reference = roots[np.argsort(np.abs(roots))][:12]
    assert reference.size == 12 and np.abs(reference).max() < min(complete_below)
    assert np.min(np.abs(reference.imag - speed)) > 1e-3 * speed  # no root near the line: sides are sharp
    np.testing.assert_allclose(modes(model, speed, 12).eigenvalues, reference, rtol=1e-5)
    np.testing.assert_allclose(modes(model, speed, 12, basis_size=96).eigenvalues, reference, rtol=1e-6)

    speeds = np.linspace(20.0, speed, 40)
    Q = imbalance_loads(model)[model.dofs.free, 0]
    q = imbalance_response(model, speeds, imbalance_loads(model))[:, 0]
    wf, wl, ws = SYNCHRONOUS
    for k, omega in enumerate(speeds):
        Z = -(omega**2) * M + 1j * omega * (D + omega * G) + K + wf * F + wl * L + ws * S
        lu, piv = la.lu_factor(Z)
        direct = la.lu_solve((lu, piv), omega**2 * Q)
        rcond, _ = la.lapack.zgecon(lu, la.norm(Z, 1))
        tol = 100 * np.finfo(float).eps / rcond
        assert np.linalg.norm(q[model.dofs.free, k] - direct) <= tol * np.linalg.norm(direct), omega


def _magnet_overrides(ks: float, ki: float, kp: float, kd: float) -> dict:
    return {
        f"bearings[{i}].{key}": value for i in (1, 2) for key, value in (("ks", ks), ("ki", ki), ("kp", kp), ("kd", kd))
    }


def test_explicit_ideal_magnet_keys_are_the_thesis_bearing_bit_for_bit(thesis):
    """k_s = 0, k_i = 1, collocated, no lag, spelled out: the same model, the same numbers."""
    ideal = build_model(
        with_overrides(
            baseline_design(),
            {
                **_magnet_overrides(0.0, 1.0, 1e7, 0.0),
                "bearings[1].sensor_offset": 0.0,
                "bearings[2].sensor_offset": 0.0,
            },
        )
    )
    assert np.array_equal(modes(ideal, ideal.speed, 8).eigenvalues, modes(thesis, thesis.speed, 8).eigenvalues)
    speeds = np.linspace(20.0, thesis.speed, 12)
    a = imbalance_response(ideal, speeds, imbalance_loads(ideal))
    b = imbalance_response(thesis, speeds, imbalance_loads(thesis))
    assert np.array_equal(a, b)


def test_equivalent_magnet_reproduces_the_pd_baseline(thesis):
    """k_i = 2, k_s = 2e6 and K_p = (1e7 + k_s)/k_i, K_d = 300/k_i make the same force law
    1e7 + 300 s as the PD keys K_p = 1e7, K_d = 300: modes, imbalance response and the spin-up
    map over the controller gains (mapped the same way) agree to round-off (1e-10)."""
    ks, ki = 2.0e6, 2.0
    pd = build_model(with_overrides(baseline_design(), {"bearings[1].kd": 300.0, "bearings[2].kd": 300.0}))
    magnet = build_model(with_overrides(baseline_design(), _magnet_overrides(ks, ki, (1e7 + ks) / ki, 300.0 / ki)))
    np.testing.assert_allclose(
        modes(magnet, magnet.speed, 10).eigenvalues, modes(pd, pd.speed, 10).eigenvalues, rtol=1e-10
    )
    speeds = np.linspace(20.0, pd.speed, 25)
    np.testing.assert_allclose(
        imbalance_response(magnet, speeds, imbalance_loads(magnet)),
        imbalance_response(pd, speeds, imbalance_loads(pd)),
        rtol=1e-8,
        atol=1e-18,
    )
    kp, kd = np.array([1e6, 3e6, 1e7]), np.array([0.0, 200.0, 800.0])
    map_pd = spinup_map(pd, kp, kd, speeds)
    map_magnet = spinup_map(magnet, (kp + ks) / ki, kd / ki, speeds)
    for field in ("shaft_peak", "actuator_displacement_peak", "actuator_force_peak"):
        np.testing.assert_allclose(getattr(map_magnet, field), getattr(map_pd, field), rtol=1e-10)


def test_spinup_coupling_of_a_lagged_noncollocated_magnet_matches_the_direct_solve():
    """Receptance coupling (Woodbury with B_aᵀ G B_s − k_s B_aᵀB_a) against the banded solve of
    the full model: orbits and carried forces to 1e-8 of their peaks (round-off, as in
    test_spinup.py), for the design's own PID controllers and for PD controllers of the map."""
    overrides = {}
    for i, offset in ((1, 0.04), (2, -0.03)):
        overrides.update(
            {
                f"bearings[{i}].{k}": v
                for k, v in (
                    ("ks", 8.5e5),
                    ("ki", 177.0),
                    ("kp", 1.6e4),
                    ("kd", 11.0),
                    ("integral_gain", 1e5),
                    ("derivative_cutoff", 500.0),
                    ("amplifier_bandwidth", 1000.0),
                    ("sensor_offset", offset),
                )
            }
        )
    model = build_model(with_overrides(baseline_design(), overrides))
    speeds = np.linspace(30.0, model.speed, 40)
    rec = actuator_receptance(model, speeds)
    fast = spinup_curves(rec, [a.controller for a in model.actuators])
    q = imbalance_response(model, speeds, imbalance_loads(model))[:, 0]
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    shaft = orbit_amplitude(q[dm.shaft(nodes, "v")], q[dm.shaft(nodes, "w")])
    assert np.abs(fast.shaft_orbit - shaft).max() <= 1e-8 * shaft.max()
    for k, a in enumerate(model.actuators):
        d = a.lateral_rows @ q
        f = a.carried_force(q, 1j * speeds)
        disp, force = orbit_amplitude(d[0], d[1]), orbit_amplitude(f[0], f[1])
        assert np.abs(fast.actuator_displacement[k] - disp).max() <= 1e-8 * disp.max()
        assert np.abs(fast.actuator_force[k] - force).max() <= 1e-8 * force.max()
    # a PD controller pair of the map, on the same magnets, lags and sensors
    smap = spinup_map(model, [2e4], [8.0], receptance=rec)
    direct = dict(overrides)
    direct.update({f"bearings[{i}].{k}": None for i in (1, 2) for k in ("integral_gain", "derivative_cutoff")})
    direct.update({f"bearings[{i}].{k}": v for i in (1, 2) for k, v in (("kp", 2e4), ("kd", 8.0))})
    pd_model = build_model(with_overrides(baseline_design(), direct))
    q = imbalance_response(pd_model, speeds, imbalance_loads(pd_model))[:, 0]
    shaft = orbit_amplitude(q[dm.shaft(nodes, "v")], q[dm.shaft(nodes, "w")])
    assert smap.shaft_peak[0, 0] == pytest.approx(shaft.max(), rel=1e-8)


# ------------------------------------------------------------------------------------------------
# Controllers, modal basis, design file


class _SisoLikePythonControl:
    """Stand-in for ``control.TransferFunction`` (SISO num/den as [[array]], dt = 0)."""

    def __init__(self, num, den):
        self.num, self.den, self.dt = [[np.array(num)]], [[np.array(den)]], 0


def test_pid_controller_and_duck_typed_transfer_functions_evaluate_the_pid_law():
    wd = 2 * np.pi * F_D
    pid = Controller.pid(KP, K_INT, KD, wd)
    for s in (3.0 + 40.0j, 1j * 250.0, -7.0 + 1.0j):
        law = KP + K_INT / s + KD * s / (1 + s / wd)
        assert pid(s) == pytest.approx(law, rel=1e-13)
        A, B, C, D, E = pid.realization()
        assert E * s + D + (C @ np.linalg.solve(s * np.eye(A.shape[0]) - A, B)).item() == pytest.approx(law, rel=1e-12)
    unfiltered = Controller.pid(KP, K_INT, KD)  # one degree improper: the ideal derivative in E
    A, B, C, D, E = unfiltered.realization()
    assert (E, D, A.shape) == (KD, KP, (1, 1)) and unfiltered.integrates
    assert pid.proportional_gain == pytest.approx(KP, rel=1e-12) and pid.basis_stiffness == pytest.approx(KP, rel=1e-12)
    duck = Controller.from_transfer_function(_SisoLikePythonControl(pid.numerator, pid.denominator))
    assert duck == pid
    design_pid = with_overrides(
        baseline_design(),
        {
            "bearings[1].integral_gain": K_INT,
            "bearings[1].kp": KP,
            "bearings[1].kd": KD,
            "bearings[1].derivative_cutoff": F_D,
        },
    )
    num, den = design_pid.bearings[1].transfer_function()
    np.testing.assert_allclose(num, pid.numerator, rtol=1e-15)
    np.testing.assert_allclose(den, pid.denominator, rtol=1e-15)
    with pytest.raises(ValueError, match="continuous-time"):
        Controller.from_transfer_function(type("Discrete", (), {"num": [1.0], "den": [1.0, 1.0], "dt": 0.01})())


def test_python_control_transfer_function_is_accepted_when_installed():
    ct = pytest.importorskip("control")
    s = ct.tf("s")
    wd = 2 * np.pi * F_D
    law = KP + K_INT / s + KD * s / (1 + s / wd)
    model = rotor(PID_KEYS)
    import dataclasses

    act = dataclasses.replace(model.actuators[0], controller=law)  # converted by Actuator
    assert isinstance(act.controller, Controller)
    assert act.controller(1j * 300.0) == pytest.approx(Controller.pid(KP, K_INT, KD, wd)(1j * 300.0), rel=1e-12)


def test_modal_basis_stays_positive_semidefinite_under_negative_magnet_stiffness():
    """C = 0 makes the open-loop stiffness negative; the basis keeps k_a = 0 (never negative), so
    dense eigh and sparse shift-invert (shift −1 rad²/s² below the lowest eigenvalue) agree.
    A steel tube (E = 210 GPa): the near-rigid one is too ill-conditioned for K + M (1e17)."""
    model = rotor(f"kp = 0.0\nks = {KS}\nki = {KI}", modulus=2.1e11)
    assert all(a.basis_stiffness == 0.0 for a in model.actuators)
    w2_dense, _ = modal_basis(model, 8, "dense")
    w2_sparse, _ = modal_basis(model, 8, "sparse")
    assert w2_dense.min() > -1e-6 * w2_dense.max()
    np.testing.assert_allclose(w2_sparse, w2_dense, rtol=1e-8, atol=1e-8 * w2_dense.max())


@pytest.mark.parametrize(
    "overrides, message",
    [
        ({"bearings[1].coil_turns": 200.0}, "bearings[1].pole_area: required key is missing"),
        (
            {
                "bearings[1].coil_turns": 200.0,
                "bearings[1].pole_area": 8e-4,
                "bearings[1].bias_current": 4.0,
                "bearings[1].air_gap": 1e-3,
                "bearings[1].ks": 1e5,
            },
            "bearings[1].ks: must be omitted when coil_turns/bias_current",
        ),
        (
            {"bearings[1].saturation_flux_density": 1.2},
            "bearings[1].pole_area: required key is missing (the saturation force",
        ),
        (
            {"bearings[1].sensor_offset": 9.0},
            "bearings[1].sensor_offset: puts the sensor at x = 12.21 m, outside the shaft",
        ),
        ({"bearings[1].ki": 0.0}, "bearings[1].ki: must be > 0 (got 0.0)"),
        ({"bearings[1].ks": -1.0}, "bearings[1].ks: must be >= 0 (got -1.0)"),
        ({"bearings[1].amplifier_bandwidth": 0.0}, "bearings[1].amplifier_bandwidth: must be > 0 (got 0.0)"),
        ({"bearings[1].pole_angle": 90.0}, "bearings[1].pole_angle: must be < 90 (got 90.0)"),
        (
            {
                "bearings[1].controller": {"numerator": [1.0], "denominator": [1.0, 1.0]},
                "bearings[1].kp": None,
                "bearings[1].kd": None,
                "bearings[1].derivative_cutoff": 100.0,
            },
            "bearings[1].derivative_cutoff: must be omitted when a controller is given",
        ),
    ],
)
def test_magnetic_bearing_keys_are_validated_with_the_field_value_and_allowed_range(overrides, message):
    with pytest.raises(DesignError) as error:
        with_overrides(baseline_design(), overrides)
    assert message in str(error.value)
