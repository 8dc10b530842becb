"""Three documented rules of the built driveline, each against a closed form derived here.

* **Elastic gearbox** (docs/model.md, "Forward end, [main_gearbox]"): the gearbox's torsional
  stiffness k_g goes from the forward θ to ground; only a gearbox without ``stiffness`` (rigid)
  holds the forward θ. A tube clamped laterally at its forward end, a torque T on its aft twist:
  the gearbox spring and the tube's torsion are in series, θ_aft = T (1/k_g + L/(G J)),
  J = π (D_o⁴ − D_i⁴)/32. Uniform torsion is interpolated exactly by the linear twist shape
  functions, the solve is well conditioned (G J/L = 2.90e4 N m/rad, k_g = 1.5e5 ≈ 5.2 G J/L,
  still well conditioned): 1e-9.

* **Fixed-frame loss** (docs/model.md, ``[analysis] internal_damping``): with ``"thesis"`` the
  loss is ``i sgn(ω)(F + K_lat)``, nothing at ω = 0, so a static load on the spinning shaft
  deflects it in its own plane only; with ``"rotating"`` the spinning shaft adds the circulatory
  ``K_lat S`` and the deflection turns sideways by atan η. A pinned-pinned Euler-Bernoulli tube
  (shear off, the default: docs/model.md:45-46; the P L³/(48 E I) check holds only then; all
  lateral stiffness is the tube's own, loss factor η on E and G) under a midspan force P in v:
  writing z = v + i w, S rotates (v, w) by −90° (docs/model.md:87-88), S ≡ −i, and at ω = 0,
  Ω > 0 the rotating loss is (σ_B − σ)/2 K_lat S = K_lat S (docs/model.md:95-96), so
  K (1 − iη) z = P, z = P (1 + iη)/(K (1 + η²)):
  thesis: v = P L³/(48 E I), w = 0;
  rotating: w / v = +η (the deflection turns in the direction of spin) and
  v = P L³/(48 E I)/(1 + η²).
  Cubic Hermite elements are exact at the nodes for point loads: 1e-9 on v (conditioning of
  a 8-element beam), 1e-12 · v on the thesis's w (v and w decoupled, w exactly zero up to
  round-off), 1e-9 on the ratio.

* **Segmented shaft** (docs/segmented-driveline.md, "One-laminate analyses"): "For a segmented
  shaft ``Model.shaft`` is the nominal ``[shaft]`` tube *without* its laminate, so these
  analyses are not evaluated"; a one-piece laminated shaft keeps its laminate.

Written for the mutations h85a-compliant-gearbox-holds-twist,
h85a-internal-damping-always-rotating and h85a-segmented-keeps-laminate of
scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import point_load
from flexshaft.design import loads_design

E, G, ETA = 2.0e11, 8.0e10, 0.02
D_O, D_I, LENGTH = 0.05, 0.04, 1.0


def _steel_tube(extra: str, fixed_start: str, fixed_end: str = "[]") -> str:
    return f"""
name = "steel tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 7800.0
loss_factor = {ETA}
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {D_O}
wall_thickness = {(D_O - D_I) / 2}
material = "steel"
fixed_start = {fixed_start}
fixed_end = {fixed_end}
[[bearings]]
name = "unloaded"
kind = "contact"
x = 0.0
stiffness = {{}}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 8
{extra}
"""


def test_an_elastic_gearbox_is_in_series_with_the_tube_torsion():
    k_g = 1.5e5
    model = build_model(
        loads_design(_steel_tube(f"[main_gearbox]\nstiffness = {k_g}\n", '["u", "v", "w", "beta", "gamma"]'))
    )
    torque = 200.0
    load = np.zeros(model.dofs.size)
    load[model.dofs.shaft(-1, "theta")] = torque
    q = static_response(model, load)
    polar = math.pi * (D_O**4 - D_I**4) / 32
    compliance = 1 / k_g + LENGTH / (G * polar)
    assert q[model.dofs.shaft(-1, "theta")] == pytest.approx(torque * compliance, rel=1e-9)
    assert q[model.dofs.shaft(0, "theta")] == pytest.approx(torque / k_g, rel=1e-9)


@pytest.mark.parametrize("law", ["thesis", "rotating"])
def test_a_static_load_turns_sideways_only_under_the_rotating_loss(law):
    model = build_model(
        loads_design(_steel_tube(f'[analysis]\ninternal_damping = "{law}"\n', '["u", "v", "w", "theta"]', '["v", "w"]'))
    )
    force = 1.0e3
    q = static_response(model, point_load(model, "shaft", (0.0, force, 0.0), x=LENGTH / 2))
    mid = model.dofs.node_at("shaft", LENGTH / 2)
    v, w = q[model.dofs.shaft(mid, "v")], q[model.dofs.shaft(mid, "w")]
    inertia = math.pi * (D_O**4 - D_I**4) / 64
    static = force * LENGTH**3 / (48 * E * inertia)
    if law == "thesis":
        assert v == pytest.approx(static, rel=1e-9)
        assert abs(w) <= 1e-12 * v
    else:
        assert w / v == pytest.approx(+ETA, rel=1e-9)
        assert v == pytest.approx(static / (1 + ETA**2), rel=1e-9)


PLY = """
[materials.ply]
kind = "lamina"
density = 1500.0
E_L = 120e9
E_T = 8e9
G_LT = 4e9
nu_LT = 0.3
X_t = 1e9
X_c = 8e8
Y_t = 4e7
Y_c = 1e8
S = 5e7
"""


def _laminated(segments: str) -> str:
    return f"""
name = "laminated tube"
{PLY}
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.06
wall_thickness = 0.002
material = "ply"
layup = "[45/-45]s"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
{segments}
[[bearings]]
name = "unloaded"
kind = "contact"
x = 1.0
stiffness = {{}}
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 6
"""


def test_a_segmented_shaft_carries_no_laminate_a_one_piece_one_does():
    one_piece = build_model(loads_design(_laminated("")))
    assert one_piece.shaft.laminate is not None
    segmented = build_model(
        loads_design(
            _laminated(
                '[[shaft.segments]]\nname = "a"\nx_start = 0.0\nx_end = 0.5\n'
                '[[shaft.segments]]\nname = "b"\nx_start = 0.5\nx_end = 1.0\nwall_thickness = 0.003\n'
            )
        )
    )
    assert segmented.shaft.laminate is None
    assert segmented.shaft.outer_diameter == pytest.approx(0.06, rel=1e-15)  # the nominal [shaft] tube
