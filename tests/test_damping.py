"""One damping physics for every analysis (flexshaft.analyses.loss) against closed forms.

Jeffcott-like rotor (tests/rotors.py): in complex coordinates r = v + i w the disk obeys
m r̈ + c_e ṙ + k r + (loss) = f. A harmonic response r = F e^{iωt} + B e^{−iωt} has a forward
part F and a backward part B. In the rotating frame (r_rot = r e^{−iΩt}) they turn at ω − Ω
and −(ω + Ω); a hysteretic material gives the force i η k sgn(ν) per component of rotating
frequency ν, so (derived here, independent of the package):

* forward:  [k(1 + iη sgn(ω − Ω)) − mω² + i c_e ω] F = f_F       (rotating model)
* backward: [k(1 + iη) − mω² + i c_e ω] B̄ = f̄_B                  (cycled at ω + Ω: 2Ω when ω = Ω)
* thesis (fixed-frame complex stiffness): k(1 + iη) for both.

So synchronous forward whirl (imbalance) is not damped by the shaft at all, while backward
whirl is; a static load on the spinning shaft meets k(1 − iη): the shaft deflects towards the
spin direction by atan η. Tolerances: the shaft's own mass (7e-6 of the disk) and the
Euler-Bernoulli mesh (exact for the static midspan stiffness) leave relative errors of order
1e-5; 1e-4 is asserted.
"""

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott

from flexshaft.analyses import frequency_response, imbalance_response, modes, static_response
from flexshaft.analyses.campbell import campbell
from flexshaft.assembly import build_model
from flexshaft.design import baseline_design, loads_design, with_overrides

ETA = 0.02
REL = 1e-4


def forward_load(model, force=1.0):
    """Forward rotating load f e^{iωt} at the disk: Q_v = f, Q_w = −i f."""
    v, w = disk_dofs(model)
    Q = np.zeros(model.dofs.size, complex)
    Q[v], Q[w] = force, -1j * force
    return Q


def backward_load(model, force=1.0):
    """Backward rotating load: Q_v = f, Q_w = +i f."""
    v, w = disk_dofs(model)
    Q = np.zeros(model.dofs.size, complex)
    Q[v], Q[w] = force, 1j * force
    return Q


def forward_amplitude(model, q):
    v, w = disk_dofs(model)
    return (q[v] + 1j * q[w]) / 2  # V_F


def backward_amplitude(model, q):
    v, w = disk_dofs(model)
    return (q[v] - 1j * q[w]) / 2  # V_B


@pytest.mark.parametrize("ratio", [0.5, 0.9, 1.0, 1.3, 2.0])
def test_synchronous_forward_whirl_is_not_damped_by_internal_loss(ratio):
    c_e = 2 * 0.01 * M_DISK * WN
    model = jeffcott(ETA, c_e)
    speed = ratio * WN
    q = frequency_response(model, forward_load(model), speed, speed=speed)
    expected = 1.0 / (K_SHAFT - M_DISK * speed**2 + 1j * c_e * speed)  # no η: frozen strain
    assert forward_amplitude(model, q) == pytest.approx(expected, rel=REL)
    assert abs(backward_amplitude(model, q)) < 1e-9 * abs(expected)


def test_imbalance_response_at_the_critical_speed_is_limited_by_external_damping_only():
    c_e = 2 * 0.005 * M_DISK * WN
    model = jeffcott(ETA, c_e)
    Q = forward_load(model) / WN**2  # per Ω²
    q = imbalance_response(model, [WN], Q)[:, 0]
    assert abs(forward_amplitude(model, q)) == pytest.approx(1.0 / (c_e * WN), rel=REL)
    # the fixed-frame (thesis) model damps it with η as well
    thesis = jeffcott(ETA, c_e, "thesis")
    qt = imbalance_response(thesis, [WN], Q)[:, 0]
    assert abs(forward_amplitude(thesis, qt)) == pytest.approx(1.0 / abs(1j * ETA * K_SHAFT + 1j * c_e * WN), rel=REL)


def test_internal_loss_alone_leaves_the_synchronous_response_undamped():
    """No external damping: the rotating model gives the undamped Jeffcott response
    f/(k − mΩ²); the fixed-frame (thesis) model wrongly damps it, f/(k(1 + iη) − mΩ²).
    At Ω = 0.99 ω_n the resonance amplifies the 1e-5 modelling error 50 times: 1e-3."""
    speed = 0.99 * WN
    rotating, thesis = jeffcott(ETA, 0.0), jeffcott(ETA, 0.0, "thesis")
    q = frequency_response(rotating, forward_load(rotating), speed, speed=speed)
    assert forward_amplitude(rotating, q) == pytest.approx(1 / (K_SHAFT - M_DISK * speed**2), rel=1e-3)
    q = frequency_response(thesis, forward_load(thesis), speed, speed=speed)
    assert forward_amplitude(thesis, q) == pytest.approx(1 / (K_SHAFT * (1 + 1j * ETA) - M_DISK * speed**2), rel=1e-3)


@pytest.mark.parametrize("ratio", [0.5, 1.0, 1.5])
def test_backward_whirl_is_damped_at_omega_plus_speed(ratio):
    model = jeffcott(ETA, 0.0)
    speed = ratio * WN
    omega = speed  # material cycled at 2Ω
    q = frequency_response(model, backward_load(model), omega, speed=speed)
    expected = 1.0 / (K_SHAFT * (1 + 1j * ETA) - M_DISK * omega**2)
    assert backward_amplitude(model, q) == pytest.approx(expected, rel=REL)


def test_forward_whirl_below_the_spin_meets_negative_loss():
    model = jeffcott(ETA, 0.0)
    speed, omega = 1.5 * WN, 0.7 * WN
    q = frequency_response(model, forward_load(model), omega, speed=speed)
    expected = 1.0 / (K_SHAFT * (1 - 1j * ETA) - M_DISK * omega**2)
    assert forward_amplitude(model, q) == pytest.approx(expected, rel=REL)


def test_static_load_on_the_spinning_shaft_deflects_towards_the_spin_by_atan_eta():
    model = jeffcott(ETA, 0.0)
    v, w = disk_dofs(model)
    Q = np.zeros(model.dofs.size)
    Q[v] = 100.0
    q = static_response(model, Q, speed=0.8 * WN)
    r = q[v] + 1j * q[w]
    assert r == pytest.approx(100.0 / (K_SHAFT * (1 - 1j * ETA)), rel=REL)
    assert np.degrees(np.angle(r)) == pytest.approx(np.degrees(np.arctan(ETA)), rel=REL)
    assert static_response(model, Q, speed=0.0)[w] == 0.0  # at rest: no circulatory term


@pytest.mark.parametrize("internal_damping", ["rotating", "thesis"])
def test_jeffcott_eigenvalues_are_the_consistent_hysteretic_roots(internal_damping):
    """Forward: m s² + c_e s + k(1 + iη σ) = 0 with σ = sgn(ω − Ω) (rotating) or 1 (thesis);
    backward: the conjugate of m s² + c_e s + k(1 − iη) = 0 (its loss sign is always +).
    Both forward roots have the frequency ω_d (the σ = −1 equation is the conjugate of the
    σ = +1 one, whose roots sum to −c_e/m), so the consistent forward root switches at Ω = ω_d;
    speeds 1e-3 either side of it are included (the test rotor's frequencies carry a round-off
    of about 1e-5, tests/test_stability.py::basis_round_off)."""
    c_e = 2 * 0.003 * M_DISK * WN
    model = jeffcott(ETA, c_e, internal_damping)
    roots = np.roots([M_DISK, c_e, K_SHAFT * (1 + 1j * ETA)])
    w_d = roots[np.argmax(roots.imag)].imag
    for ratio in (0.0, 0.6, 0.999, 1.001, 1.4, 2.5):
        speed = ratio * w_d
        m = modes(model, speed, n_modes=2)
        sigma = -1.0 if internal_damping == "rotating" and speed > w_d else 1.0
        roots = np.roots([M_DISK, c_e, K_SHAFT * (1 + 1j * ETA * sigma)])
        forward = roots[np.argmax(roots.imag)]
        roots = np.roots([M_DISK, c_e, K_SHAFT * (1 - 1j * ETA)])
        backward = np.conj(roots[np.argmin(roots.imag)])
        got = np.sort_complex(m.eigenvalues)
        assert got == pytest.approx(np.sort_complex(np.array([forward, backward])), rel=REL), ratio
        if sigma < 0:  # distinct: the labels name them
            assert m.eigenvalues[list(m.whirl).index("forward")] == pytest.approx(forward, rel=REL)
            assert forward.real > 0  # supercritical forward whirl driven unstable by the shaft's loss


def pinned_tube(eta: float, elements: int = 40) -> str:
    return f"""
name = "pinned-pinned hysteretic tube"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
loss_factor = {eta}
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.06
wall_thickness = 0.004
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "axial_stop"
kind = "contact"
x = 2.0
stiffness = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {elements}
"""


def test_uniform_hysteretic_beam_modes_have_damping_ratio_half_the_loss_factor():
    """Every mode of a uniformly hysteretic structure: s² + ω_n²(1 + iη) = 0, so
    s = i ω_n √(1 + iη) and ζ = sin(½ atan η) = η/2 (1 + O(η²)). The relation holds mode by
    mode on any mesh (both sides are the discrete model's): 20 elements, whose lowest 12 modes
    still hold lateral, twist and axial modes (CPU budget, issue 23)."""
    eta = 0.05
    model = build_model(loads_design(pinned_tube(eta, elements=20)))
    undamped = modes(model, 0.0, n_modes=12, damped=False)
    damped = modes(model, 0.0, n_modes=12)
    for wn, s, kind in zip(np.abs(undamped.eigenvalues), damped.eigenvalues, damped.kind):
        exact = 1j * wn * np.sqrt(1 + 1j * eta)
        assert s == pytest.approx(exact, rel=1e-9), kind  # eigen-solver accuracy
        assert -s.real / abs(s) == pytest.approx(eta / 2, rel=eta**2)
    assert {"lateral", "torsional", "axial"} <= set(damped.kind)  # all kinds carry the loss


def test_boom_modes_have_damping_ratio_half_the_boom_loss_factor():
    """The baseline's boom modes (the issue: ζ ≈ 0.0009 from a shared reference frequency)."""
    # with the aft hanger axially free: when both hangers hold the shaft axially (eq. 2.29), the
    # vertical boom modes stretch the shaft, which stores a few % of their energy at its own far
    # smaller loss factor, and ζ = η/2 no longer holds exactly
    design = with_overrides(baseline_design(), {"bearings[3].stiffness": {"v": 1e8, "w": 1e8}})
    eta = design.materials[design.tailboom.material].loss_factor
    m = modes(build_model(design), design.operating.speed_rad_s, n_modes=4)
    assert np.all(m.component == "boom")
    # the boom holds > 99 % of these modes' energy; the bearings and shaft carry the rest
    assert np.allclose(m.damping_ratios, eta / 2, rtol=0.02)


def test_frequency_response_half_power_bandwidth_equals_the_modal_damping():
    """Two analyses of one model agree on its damping: FRF bandwidth against modes(). The
    baseline on 12 shaft and 8 boom elements (CPU budget, issue 23): both sides are the same
    model's, its first boom mode and the neighbour 23 % above move by 3e-4 from the design's
    mesh, and the width's bias stays 0.11 % (measured on both meshes)."""
    design = with_overrides(baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 8})
    model = build_model(design)
    m = modes(model, 0.0, n_modes=1)
    f0 = m.eigenvalues[0].imag
    dm = model.dofs
    Q = np.zeros(dm.size)
    Q[dm.boom(-1, "w")] = 1.0
    omegas = np.linspace(0.97, 1.03, 1201) * f0
    amp = np.abs(frequency_response(model, Q, omegas, speed=0.0)[dm.boom(-1, "w")])
    k = np.argmax(amp)
    above = omegas[amp >= amp[k] / np.sqrt(2)]
    # hysteretic single mode: ω² = ω_n²(1 ± η) at half power, so Δω/ω_n = η (to O(η²)) = 2ζ
    bandwidth = (above[-1] - above[0]) / omegas[k]
    assert bandwidth / 2 == pytest.approx(m.damping_ratios[0], rel=0.02)  # grid 5e-5·ω, O(η²) and
    # the neighbouring vertical mode 20 % away bias the width by < 2 %


def no_boom_shaft() -> str:
    text = pinned_tube(0.01).replace('fixed_start = ["u", "v", "w", "theta"]', 'fixed_start = ["u", "v", "w"]')
    return text.replace("[operating]\nspeed_rpm = 0.0", "[operating]\nspeed_rpm = 3000.0")


def test_twist_and_axial_modes_are_labelled_and_make_no_critical_speed():
    """40 speeds (a step of 168 rad/s, a thirtieth of the twist mode's 5030 rad/s) find the
    same ten lateral critical speeds as 80 and keep the twist modes (the free rigid twist and
    the elastic one) tracked over the whole range (CPU budget, issue 23)."""
    design = loads_design(no_boom_shaft())
    model = build_model(design)
    m = modes(model, model.speed, n_modes=14)
    kinds = dict(zip(m.kind, m.whirl))
    assert "torsional" in m.kind and kinds["torsional"] == "none"
    lateral = m.kind == "lateral"
    assert set(m.whirl[lateral]) <= {"forward", "backward"}
    assert set(m.whirl[~lateral]) == {"none"}
    speeds = np.linspace(0.0, 1.3 * m.eigenvalues[m.kind != "lateral"].imag.max(), 40)
    c = campbell(model, speeds, n_modes=14)
    assert len(c.critical_speeds) == 10  # the lateral criticals in range (the same on 80 speeds)
    for crit in c.critical_speeds:
        k = int(np.argmin(np.abs(speeds - crit.speed)))
        assert c.kind[k, crit.mode] == "lateral"
    torsional = [j for j in range(14) if np.all(c.kind[:, j] == "torsional")]
    assert torsional  # the twist mode is tracked, but crosses the 1× line without a critical speed
    assert not [crit for crit in c.critical_speeds if crit.mode in torsional]


def test_thesis_model_never_destabilises():
    from flexshaft.analyses.stability import stability

    model = jeffcott(ETA, 0.0, "thesis")
    res = stability(model, np.linspace(0, 4, 41) * WN, n_modes=2)
    assert res.onset_speed is None
    assert np.all(res.damping_ratios > 0)
