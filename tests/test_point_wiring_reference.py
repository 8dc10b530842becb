"""What the operating point's recipe and the mode labels hand on, against closed forms and the
documented definitions (derived here):

* **The cool-down's residual stress.** A cured laminate cooled below its stress-free
  temperature (ΔT < 0): every in-plane direction of a laminate of several fibre angles has a
  thermal expansion strictly between the plies' α_L and α_T (each ply's fibres restrain the
  others), so every ply is stretched across its fibres and shortened along them relative to its
  free contraction: σ₂ > 0 (transverse tension) and σ₁ < 0, the classical sign of curing
  stresses (α_T ≫ α_L for carbon in a soft matrix). The ply check at a point colder than the
  stress-free temperature must carry that sign, and the report's detail must show the verdict's
  safety factors (the same peak torque: the torsional response's factor on the steady torque).
* **Heavily damped whirl modes are whirl modes.** A single-DOF oscillator per plane (the Jeffcott
  rotor of tests/rotors.py with a dashpot c = 2ζ√(km)) has s = −ζω_n ± iω_n√(1 − ζ²): at
  ζ = 0.7 a vibration mode with log decrement δ = 2πζ/√(1 − ζ²) ≈ 6.16, which the log-decrement
  check must see; at ζ = 1.5 two real roots, no vibration of the disk (the whirl modes left are
  the near-massless tube's own, far above ω_n).
* **A coupling hub spins with the shaft.** For the two rigid tilts of a spinning rotor (about
  y and about z through any point) the gyroscopic matrix couples them by the rotor's whole polar
  moment of inertia (angular momentum I_p Ω): the tubes' ρ J L, the disks' and the coupling
  hubs' I_p, summed by hand (tests/test_rigid_body_inertia.py's driveline: three tubes, two
  hubs, one disk). Shape functions reproduce rigid motion exactly: 1e-9.
* **Component labels** (docs/model.md, "Mode labels"): a mode is a shaft mode when the shaft
  holds more than 90 % of its kinetic energy, a boom mode below 10 %, else coupled; and the
  labeller on modal coordinates (the reduced analyses') gives the shares of the definition
  E_g = Re(φ_gᴴ (Mφ)_g) / Σ_g, every DOF of the model in one group.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import SMALLEST
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK, WN
from test_rigid_body_inertia import TEXT as DRIVELINE
from test_rigid_body_inertia import shaft_polar, shaft_vector

from flexshaft.analyses.classify import ModalLabeler, energy_shares, label_modes
from flexshaft.analyses.eigen import reduce
from flexshaft.assembly import build_model
from flexshaft.design import loads_design, tuned_design, with_overrides
from flexshaft.thermal.envelope import PointConditions
from flexshaft.verdict.operating_point import add_report_detail, analyse_point, lateral_modes, whirl_modes

COARSE = {"mesh.shaft_elements": 12, "mesh.boom_elements": 8}


def test_a_point_below_the_stress_free_temperature_carries_the_cool_downs_sign():
    design = with_overrides(tuned_design(), COARSE)
    material = design.materials[design.shaft.material]
    cold = material.stress_free_temperature - 100.0  # K: 100 K below the stress-free state
    conditions = PointConditions(point=None, ambient_temperature=cold, material_temperature=cold)  # type: ignore[arg-type]
    p = analyse_point(design, SMALLEST, conditions=conditions, detail=False)
    assert p.residual_temperature == cold
    for result in (p.strength_static, p.strength_total):
        sigma1, sigma2, _ = result.stress_parts["thermal"]
        assert sigma2 > 0 and sigma1 < 0, result.stress_parts["thermal"]
    # the report's detail (its strength with the load shares) shows the verdict's numbers: the
    # same peak torque (the torsional response's factor on the steady torque) and safety factors
    assert p.torque_factor > 1.0
    shown = add_report_detail(p)
    assert shown.strength_static.safety_factor == pytest.approx(p.strength_static.safety_factor, rel=1e-12)
    assert shown.strength_total.safety_factor == pytest.approx(p.strength_total.safety_factor, rel=1e-12)


@pytest.mark.parametrize(("zeta", "vibrating"), [(0.7, True), (1.5, False)])
def test_a_heavily_damped_whirl_mode_counts_and_an_overdamped_root_does_not(zeta, vibrating):
    c = zeta * 2 * np.sqrt(K_SHAFT * M_DISK)
    model = model_with(f'kind = "contact"\nstiffness = {{}}\ndamping = {{ v = {c}, w = {c} }}')
    found = lateral_modes(model, 0.0, 2)
    mask = whirl_modes(found)
    if vibrating:
        s = found.eigenvalues[mask]
        assert s.size == 2
        assert s == pytest.approx([-zeta * WN + 1j * WN * np.sqrt(1 - zeta**2)] * 2, rel=1e-4)
        delta = 2 * np.pi * zeta / np.sqrt(1 - zeta**2)
        assert -2 * np.pi * s.real / s.imag == pytest.approx([delta] * 2, rel=1e-4)
    else:  # the disk creeps back: its whirl modes are the near-massless tube's own, far above
        assert mask.any() and np.all(np.abs(found.eigenvalues[mask]) > 10 * WN)


@pytest.fixture(scope="module")
def driveline():
    """tests/test_rigid_body_inertia.py's driveline (three tubes, two coupling hubs, a disk, a boom)."""
    return build_model(loads_design(DRIVELINE))


def test_the_rigid_tilts_of_the_rotor_couple_by_its_whole_polar_inertia(driveline):
    model = driveline
    about_z = shaft_vector(model, {"v": lambda x: x - 1.7, "gamma": np.ones_like})
    about_y = shaft_vector(model, {"w": lambda x: x - 1.7, "beta": lambda x: -np.ones_like(x)})
    coupling = float(about_y @ (model.G @ about_z))
    assert abs(coupling) == pytest.approx(shaft_polar(), rel=1e-9)


def test_component_labels_follow_the_documented_energy_fractions(driveline):
    model = driveline
    dm = model.dofs
    i, j = dm.shaft(2, "v"), dm.boom(2, "v")
    M = model.M.toarray()
    assert M[i, j] == 0.0  # shaft and boom share no mass term: the energies add
    shapes = []
    for shaft_fraction in (0.95, 0.6, 0.4, 0.05):
        phi = np.zeros(dm.size, complex)
        phi[i] = np.sqrt(shaft_fraction / M[i, i])
        phi[j] = np.sqrt((1 - shaft_fraction) / M[j, j])
        shapes.append(phi)
    labels = label_modes(model, np.column_stack(shapes))
    assert list(labels.component) == ["shaft", "coupled", "coupled", "boom"]
    assert labels.shares.shaft == pytest.approx([0.95, 0.6, 0.4, 0.05], rel=1e-12)


def test_the_modal_labeller_partitions_the_kinetic_energy_as_the_definition(driveline):
    model = driveline
    basis = reduce(model, 24)
    rng = np.random.default_rng(7)
    Y = rng.standard_normal((basis.size, 5)) + 1j * rng.standard_normal((basis.size, 5))
    reduced = ModalLabeler(model, basis.Phi)(Y).shares
    full = energy_shares(model, model.dofs.expand(basis.Phi @ Y))
    for name in ("shaft_axial", "shaft_torsion", "shaft_lateral", "boom"):
        assert getattr(reduced, name) == pytest.approx(getattr(full, name), rel=1e-10, abs=1e-13), name


def test_a_sensor_beside_its_magnet_sees_the_boom_at_its_own_station():
    """The tuned driveline with its first magnet's sensor 0.06 m aft: the sensing rows measure
    the relative lateral displacement (shaft − boom) at the sensor's stations, x + δ on the shaft
    and x_b + δ on the boom (``sensor_boom_x``). A rigid motion of the boom alone in the x-y plane,
    v_b = y + (x_b − c) θ with γ_b = θ (γ = dv/dx, docs/model.md), is seen by the magnet's rows
    at x_b and by the sensor's at x_b + δ: the readings differ by −δθ (the boom side enters with
    the opposite sign of a translation of the shaft, which the rows read as +y)."""
    delta, y, theta, c = 0.06, 1e-4, 2e-3, 1.0
    design = with_overrides(tuned_design(), {**COARSE, "bearings[1].sensor_offset": delta})
    model = build_model(design)
    dm = model.dofs
    actuator = model.actuators[0]
    assert not actuator.collocated and design.bearings[1].sensor_boom_x == design.bearings[1].boom_x + delta
    shaft = shaft_vector(model, {"v": np.ones_like})
    assert (actuator.lateral_rows @ shaft)[0] == pytest.approx(1.0, rel=1e-12)  # v_shaft − v_boom
    xb = np.asarray(dm.boom_x, dtype=float)
    boom = np.zeros(dm.size)
    boom[dm.boom(np.arange(xb.size), "v")] = y + (xb - c) * theta
    boom[dm.boom(np.arange(xb.size), "gamma")] = theta
    at_magnet = -(y + (design.bearings[1].boom_x - c) * theta)
    assert (actuator.lateral_rows @ boom)[0] == pytest.approx(at_magnet, rel=1e-10)
    assert (actuator.sensing_rows @ boom)[0] == pytest.approx(at_magnet - delta * theta, rel=1e-10)
