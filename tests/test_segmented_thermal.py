"""Shaft heat and temperature of segmented drivelines (issue 27).

``flexshaft thermal`` exited 4 on every segmented driveline, the embedded ``current`` included
("operands could not be broadcast ... (50,12) ... (54,12,12)"): the heat generation paired
consecutive nodes into elements (54 "elements" of which 4 were the zero-length coupling joints)
and gave every element the ``[shaft]`` tube. Now each element is one of
``DofMap.element_dofs`` with its own segment's tube, and the temperature's stations are the
element ends with each coupling's two nodes counted once.

References, independent of the per-element bookkeeping of flexshaft.thermal.heat:

* a coupling rigid in every direction is no coupling: the shaft with one is the one-piece
  shaft with a node at the same station (a zero-mass disk), whose heat and temperature are
  checked against the time integral and the fin solution in tests/test_thermal.py;
* energy balance on the assembled model: the heat of the loss model equals the dissipation of
  the global response in the shaft's assembled loss stiffness K''
  (``model.shaft_loss_stiffness``, built segment by segment by the assembly): ``(Ω/2) qᴴK''q``
  for the thesis's model, and for the rotating one the axial-torsional part at Ω plus the
  backward whirl part at 2Ω, ``(Ω/2) q_aᴴK''q_a + Ω q_bᴴK''q_b``, the static deflection
  ``(Ω/2) q_sᵀK''_lat q_s`` (thesis) and twice that (rotating);
* the finite-volume temperature conserves energy: generated = convected + end flows.
"""

from __future__ import annotations

import copy

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.heat import element_tubes, heat_sources, thermal_stations
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.shaft import rotating_shaft_convection

X_COUPLING = 2.0  # m, a station of the baseline's shaft away from its bearings


def variant(name: str, change):
    data = copy.deepcopy(embedded_design(name).model_dump())
    change(data)
    return build_model(design_from_dict(data))


def rigid_coupling(data):
    data["couplings"] = [
        {
            "name": "rigid",
            "x": X_COUPLING,
            "angular_stiffness": "rigid",
            "axial_stiffness": "rigid",
            "torsional_stiffness": "rigid",
            "lateral_stiffness": "rigid",
        }
    ]


def marker_disk(data):
    data["disks"] = list(data.get("disks") or []) + [{"name": "marker", "x": X_COUPLING, "mass": 0.0}]


def thicker_middle_tube(data):
    """The current driveline with its third tube's wall doubled and of another diameter."""
    data["shaft"]["segments"][2].update(wall_thickness=3.302e-3, outer_diameter=0.09)


def options(model):
    return thermal_options(model.design.thermal)


@pytest.mark.parametrize("name", ["current"])
def test_the_embedded_segmented_driveline_has_heat_and_temperature(name):
    """The reproducer: heat sources and temperature of ``current`` (was a broadcast error)."""
    model = build_model(embedded_design(name))
    nel = len(model.dofs.shaft_element_nodes)
    for loss_model in ("thesis", "rotating"):
        result = shaft_thermal(model, options(model), loss_model)
        assert result.sources.total.shape == (nel,)
        assert result.temperature.x.shape == (nel + 1,) and np.all(np.diff(result.temperature.x) > 0)
        assert np.all(result.sources.total >= 0) and result.sources.total.sum() > 0
        assert abs(result.temperature.balance_error) <= balance_tolerance(model, result)


def balance_tolerance(model, result):
    """Round-off of the energy balance relative to the heat: its n node terms are differences
    of conductances times temperatures, each of the size h P L T_∞ summed (the heat itself is
    1e-5 of that here), so 2 n ε Σ(h P L) T_∞ / generated."""
    t = result.temperature
    ends = model.dofs.shaft_element_x
    surface = sum(np.pi * tube.outer_diameter * (b - a) for tube, (a, b) in zip(element_tubes(model), ends))
    scale = t.heat_transfer_coefficient * surface * t.air_temperature
    return 2 * t.x.size * np.finfo(float).eps * scale / t.generated


@pytest.mark.parametrize("loss_model", ["thesis", "rotating"])
def test_a_rigid_coupling_is_the_one_piece_shaft(loss_model):
    """Same mesh, same physics: heat per element and temperatures agree to round-off (1e-10
    relative: two factorisations of the same system, tied DOFs against a shared node)."""
    coupled, plain = variant("baseline", rigid_coupling), variant("baseline", marker_disk)
    assert len(coupled.dofs.shaft_joints) == 1 and np.array_equal(thermal_stations(coupled), plain.dofs.shaft_x)
    a, b = heat_sources(coupled, loss_model), heat_sources(plain, loss_model)
    np.testing.assert_allclose(a.total, b.total, rtol=1e-10, atol=1e-10 * b.total.max())
    ta = shaft_thermal(coupled, options(coupled), loss_model)
    tb = shaft_thermal(plain, options(plain), loss_model)
    np.testing.assert_allclose(ta.temperature.temperature, tb.temperature.temperature, rtol=1e-12)


def global_split(model, q):
    """(axial-torsional, backward) parts of global shaft vectors q (the module docstring):
    V_b = (V − iW)/2, W_b = i V_b; and (γ, −β) split the same way."""
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    axial = np.zeros_like(q)
    for f in ("u", "theta"):
        axial[dm.shaft(nodes, f)] = q[dm.shaft(nodes, f)]
    back = np.zeros_like(q)
    V, W = q[dm.shaft(nodes, "v")], q[dm.shaft(nodes, "w")]
    back[dm.shaft(nodes, "v")] = (V - 1j * W) / 2
    back[dm.shaft(nodes, "w")] = 1j * (V - 1j * W) / 2
    a, b = q[dm.shaft(nodes, "gamma")], -q[dm.shaft(nodes, "beta")]
    back[dm.shaft(nodes, "gamma")] = (a - 1j * b) / 2
    back[dm.shaft(nodes, "beta")] = -1j * (a - 1j * b) / 2
    return axial, back


@pytest.mark.parametrize("change", [lambda d: None, thicker_middle_tube], ids=["current", "thicker middle tube"])
def test_segmented_heat_is_the_dissipation_in_the_assembled_loss_stiffness(change):
    """Energy balance on the assembled model (module docstring), both loss models, to 1e-10
    (sums of the same products in another order)."""
    from flexshaft.analyses.response import imbalance_response, static_response

    model = variant("current", change)
    Omega = model.speed
    Kpp = model.shaft_loss_stiffness
    q_imb = imbalance_response(model, [Omega], imbalance_loads(model))[..., 0]
    q_imb = q_imb.reshape(model.dofs.size, -1)
    q_st = static_response(model, torque_load(model) + external_static_load(model))

    def power(q, omega, K=Kpp):
        return 0.5 * omega * float(np.real(np.vdot(q, K @ q)))

    def rounding(q, K=Kpp):
        """ε |q|ᵀ|K||q| / |qᴴKq|: the cancellation of a quadratic form summed in another order
        (1.4e-7 for the static deflection of the hinged tubes, whose segments mostly pivot)."""
        return 4 * np.finfo(float).eps * float(np.abs(q) @ (abs(K) @ np.abs(q))) / abs(np.vdot(q, K @ q))

    thesis = heat_sources(model, "thesis")
    rotating = heat_sources(model, "rotating")
    worst = int(np.argmax([power(q_imb[:, c], Omega) for c in range(q_imb.shape[1])]))
    q = q_imb[:, worst]
    assert thesis.vibration.sum() == pytest.approx(power(q, Omega), rel=rounding(q))
    per_case, tolerance = [], []
    for c in range(q_imb.shape[1]):
        axial, back = global_split(model, q_imb[:, c])
        per_case.append(power(axial, Omega) + power(back, 2 * Omega))
        tolerance.append(rounding(axial) + rounding(back))
    assert rotating.vibration.sum() == pytest.approx(max(per_case), rel=max(tolerance))
    lateral = model.loss_lateral
    static = power(q_st, Omega, lateral)
    assert thesis.static.sum() == pytest.approx(static, rel=rounding(q_st, lateral))
    assert rotating.static.sum() == pytest.approx(2 * static, rel=rounding(q_st, lateral))


def test_each_segment_convects_and_conducts_with_its_own_tube():
    """The thicker, narrower middle tube: its elements carry its own diameter's h (the
    rotating-cylinder correlation at D = 0.09 m) and section, and the temperature still
    conserves energy."""
    model = variant("current", thicker_middle_tube)
    tubes = element_tubes(model)
    diameters = np.array([t.outer_diameter for t in tubes])
    assert set(np.round(diameters, 6)) == {0.09, 0.1016}
    result = shaft_thermal(model, options(model), "rotating")
    T_air = result.temperature.air_temperature
    opts = options(model)
    for D in (0.09, 0.1016):
        h, _ = rotating_shaft_convection(D, model.speed, T_air, opts.shaft_convection, opts.environment.air_pressure)
        assert np.all(result.temperature.element_heat_transfer[np.isclose(diameters, D)] == pytest.approx(h))
    assert abs(result.temperature.balance_error) <= balance_tolerance(model, result)


def test_self_heating_of_a_segmented_fmc_shaft_is_the_one_piece_shafts():
    """Each laminated element softens with its own temperature: with a rigid coupling the fixed
    point is the one-piece shaft's (loads × 30 so that it takes several iterations), to 1e-9 K
    (the same iterates up to round-off). Was: self-heating assumed one [shaft] laminate and
    counted nodes − 1 elements."""
    from flexshaft.thermal.selfheating import self_heating

    coupled, plain = variant("baseline", rigid_coupling), variant("baseline", marker_disk)
    runs = [self_heating(m, options(m), imbalance_scale=30.0, static_scale=30.0) for m in (coupled, plain)]
    assert runs[0].status == runs[1].status == "converged" and runs[0].iterations == runs[1].iterations > 1
    np.testing.assert_allclose(runs[0].element_temperature, runs[1].element_temperature, rtol=0, atol=1e-9)
