"""Heat of the hysteretic shaft: which motions the rotating material actually cycles.

Derived references (kinematics of a whirling shaft, independent of flexshaft.thermal.heat):

* axes: spin from +y towards +z; with v = Re(V e^{i Omega t}), W = -i V gives v = cos(Omega t),
  w = sin(Omega t) for V = 1, an orbit turning with the spin (forward), W = +i V one against it;
* a circular FORWARD whirl at the spin speed Omega is, in the frame that turns with the shaft,
  a frozen deflection: no fibre's strain changes, so the rotating-frame loss is 0;
* a circular BACKWARD whirl at Omega is seen by the turning material at 2 Omega with the same
  amplitude, so its mean power (2 Omega / 2) X^H K'' X is twice the fixed-frame (thesis) value
  (Omega / 2) X^H K'' X (mean power of a harmonic hysteretic force: omega/2 Re(X^H K'' X));
* a STEADY twist (the transmitted torque) is the same in every fibre at every instant: the
  rotation does not cycle it, so neither loss model turns it into heat;
* the loss is quadratic in the amplitude: of two imbalance load cases, one twice the other,
  the heat reported (the worst case) is 4 times the smaller one's.

The ratios hold exactly for any K'' (ratios of one quadratic form), so a coarse 6-element
aluminium tube with a loss factor suffices; tolerance 1e-12 (rounding).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.dofs import SHAFT_FIELDS
from flexshaft.design import design_from_dict
from flexshaft.thermal.heat import heat_sources


def lossy_tube(loads: dict) -> dict:
    """The design of the lossy aluminium tube (2 m, 50 x 2 mm, η = 0.02, pinned at 3000 rpm) with
    ``loads`` (also tests/test_heat_load_multiple_reference.py)."""
    return {
        "name": "lossy tube",
        "materials": {"al": {"kind": "isotropic", "E": 70e9, "G": 26e9, "density": 2700.0, "loss_factor": 0.02}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": loads,
        "mesh": {"shaft_elements": 6},
    }


@pytest.fixture(scope="module")
def model():
    return build_model(design_from_dict(lossy_tube({"eccentricity": 0.0})))


def field_vector(model, values: dict) -> np.ndarray:
    """Global complex vector with each shaft node's field ``f`` = values[f](x_node)."""
    q = np.zeros(model.dofs.size, dtype=complex)
    dofs = model.dofs.element_dofs("shaft")  # (nel, 12): [u v w theta beta gamma] x 2
    ends = model.dofs.shaft_element_x
    for node in (0, 1):
        for field, shape in values.items():
            q[dofs[:, 6 * node + SHAFT_FIELDS.index(field)]] = shape(ends[:, node])
    return q


def bow(x):
    return np.sin(np.pi * x / 2.0) * 1e-4  # a bending shape [m]


def test_forward_whirl_is_frozen_and_backward_whirl_cycles_at_twice_the_speed(model):
    zero = np.zeros(model.dofs.size)
    forward = field_vector(model, {"v": bow, "w": lambda x: -1j * bow(x)})  # W = -i V
    backward = field_vector(model, {"v": bow, "w": lambda x: 1j * bow(x)})  # W = +i V
    thesis_f = heat_sources(model, "thesis", forward, zero).vibration.sum()
    thesis_b = heat_sources(model, "thesis", backward, zero).vibration.sum()
    assert thesis_f > 0 and thesis_b == pytest.approx(thesis_f, rel=1e-12)  # same orbit radius
    rotating_f = heat_sources(model, "rotating", forward, zero).vibration.sum()
    rotating_b = heat_sources(model, "rotating", backward, zero).vibration.sum()
    assert abs(rotating_f) <= 1e-12 * thesis_f
    assert rotating_b == pytest.approx(2.0 * thesis_b, rel=1e-12)


def test_a_steady_twist_is_not_cycled_by_the_rotation(model):
    zero = np.zeros(model.dofs.size, dtype=complex)
    twist = field_vector(model, {"theta": lambda x: 1e-3 * x, "u": lambda x: 1e-5 * x}).real
    bend = field_vector(model, {"v": bow}).real
    for loss_model in ("thesis", "rotating"):
        assert np.all(heat_sources(model, loss_model, zero, twist).static == 0.0)
        # the bending part of the same static deflection is what heats, alone
        both = heat_sources(model, loss_model, zero, twist + bend).static
        np.testing.assert_allclose(both, heat_sources(model, loss_model, zero, bend).static, rtol=1e-12)
        assert both.sum() > 0


def test_the_worst_imbalance_load_case_is_reported(model):
    zero = np.zeros(model.dofs.size)
    case = field_vector(model, {"v": bow, "w": lambda x: 1j * bow(x)})
    for loss_model in ("thesis", "rotating"):
        one = heat_sources(model, loss_model, case, zero).vibration
        for order in ((1.0, 2.0), (2.0, 1.0)):
            cases = np.column_stack([s * case for s in order])
            np.testing.assert_allclose(heat_sources(model, loss_model, cases, zero).vibration, 4.0 * one, rtol=1e-12)
