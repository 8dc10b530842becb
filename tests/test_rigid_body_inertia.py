"""Mass and inertia of an assembled model against a hand sum over its parts.

For a rigid-body displacement vector u of the model's DOFs (every node translated, or every node
turned about one axis), uᵀ M u is twice the kinetic energy at unit velocity, i.e. the total mass
or the moment of inertia about that axis. Each part's share is summed here from its geometry,
independently of the element code:

* tubes: ρ A L, ρ A ∫(x − x0)² dx + ρ I L (rotary inertia), ρ J L for the spin axis;
* disks and coupling hubs: m, m d² + I_d, I_p (a hub lumped on the two flanges of its joint);
* the tapered elliptical boom: ρ t ∮ds (mass per length), ρ t ∮y² ds, ρ t ∮(y² + z²) ds, with
  ∮ds = 4a E(1 − b²/a²) (complete elliptic integral, scipy.special.ellipe) and the second moments
  by adaptive quadrature, integrated along the taper with scipy.integrate.quad;
* the end mass: m and m × (squared distance of its centre from the axis) + its own inertia.

The shape functions reproduce rigid motion exactly (Hermite cubics and linear functions), and
the boom's Gauss rule (6 points) on a smooth taper and its periodic 128-point perimeter rule are
accurate to ~1e-12: 1e-9 relative is asserted. Bearing masses are for the mass breakdown only
and never enter M (docs/design-reference.md), so they are left out of the sums.

Shaft: three tubes (aluminium, a (30/-30)s composite, steel) joined by two couplings, one disk.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import ellipe

from flexshaft.assembly import build_model
from flexshaft.design import loads_design

RHO_AL, RHO_CFRP, RHO_STEEL, RHO_BOOM = 2700.0, 1650.0, 7850.0, 2800.0
TUBES = [  # (x_start, x_end, D_o, wall, density)
    (0.0, 1.0, 0.10, 0.003, RHO_AL),
    (1.0, 2.4, 0.09, 0.004, RHO_CFRP),
    (2.4, 3.0, 0.06, 0.005, RHO_STEEL),
]
HUBS = [  # (x, m, I_d, I_p)
    (1.0, 1.5, 2.0e-3, 3.5e-3),
    (2.4, 0.8, 0.9e-3, 1.6e-3),
]
DISK = (2.0, 3.0, 0.011, 0.021)  # (x, m, I_d, I_p)
BOOM_L, ROOT, TIP, BOOM_T = 3.0, (0.30, 0.22), (0.15, 0.12), 0.002
END_MASS, END_OFFSET, END_INERTIA = 40.0, (0.1, 0.3, -0.2), (1.0, 2.0, 3.0)

TEXT = f"""
name = "rigid-body inertia check"
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = {RHO_AL}
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = {RHO_STEEL}
[materials.cfrp]
kind = "lamina"
density = {RHO_CFRP}
E_L = 115e9
E_T = 0.1e9
G_LT = 0.1e9
nu_LT = 0.35
X_t = 2185e6
X_c = 2000e6
Y_t = 5.1e6
Y_c = 5.5e6
S = 20e6
[materials.boom]
kind = "isotropic"
E = 71e9
G = 27e9
density = {RHO_BOOM}
[shaft]
x_start = 0.0
x_end = 3.0
outer_diameter = 0.10
wall_thickness = 0.003
material = "al"
fixed_start = ["theta"]
[[shaft.segments]]
name = "tube_1"
x_start = 0.0
x_end = 1.0
[[shaft.segments]]
name = "tube_2"
x_start = 1.0
x_end = 2.4
outer_diameter = 0.09
wall_thickness = 0.004
material = "cfrp"
layup = "(30/-30)s"
[[shaft.segments]]
name = "tube_3"
x_start = 2.4
x_end = 3.0
outer_diameter = 0.06
wall_thickness = 0.005
material = "steel"
[[couplings]]
name = "c1"
x = 1.0
angular_stiffness = 2300.0
axial_stiffness = 2.0e5
torsional_stiffness = 1.0e5
lateral_stiffness = 1.0e7
mass = {HUBS[0][1]}
diametral_inertia = {HUBS[0][2]}
polar_inertia = {HUBS[0][3]}
[[couplings]]
name = "c2"
x = 2.4
angular_stiffness = 2300.0
axial_stiffness = "rigid"
torsional_stiffness = "rigid"
mass = {HUBS[1][1]}
diametral_inertia = {HUBS[1][2]}
polar_inertia = {HUBS[1][3]}
[[disks]]
name = "disk"
x = {DISK[0]}
mass = {DISK[1]}
diametral_inertia = {DISK[2]}
polar_inertia = {DISK[3]}
[tailboom]
length = {BOOM_L}
root_semi_axes = [{ROOT[0]}, {ROOT[1]}]
tip_semi_axes = [{TIP[0]}, {TIP[1]}]
wall_thickness = {BOOM_T}
material = "boom"
shaft_clearance = 0.05
[tailboom.end_mass]
mass = {END_MASS}
offset = [{END_OFFSET[0]}, {END_OFFSET[1]}, {END_OFFSET[2]}]
inertia = [{END_INERTIA[0]}, {END_INERTIA[1]}, {END_INERTIA[2]}]
[[bearings]]
name = "fwd"
kind = "contact"
x = 0.5
stiffness = {{ u = 1e8, v = 1e8, w = 1e8 }}
mass = 5.0
[[bearings]]
name = "aft"
kind = "contact"
x = 2.9
stiffness = {{ v = 1e8, w = 1e8 }}
mass = 5.0
[operating]
speed_rpm = 3000.0
power = 1.0e5
[mesh]
shaft_elements = 15
boom_elements = 9
"""


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(TEXT))


def quadratic(model, u) -> float:
    M = model.M.toarray()
    return float(u @ M @ u)


def shaft_vector(model, fields: dict) -> np.ndarray:
    """Rigid field on every shaft node: ``fields[f](x)`` for each DOF field f."""
    dm = model.dofs
    u = np.zeros(dm.size)
    nodes = np.arange(dm.n_shaft_nodes)
    for f, value in fields.items():
        u[dm.shaft(nodes, f)] = value(np.asarray(dm.shaft_x, dtype=float))
    return u


def boom_vector(model, fields: dict) -> np.ndarray:
    dm = model.dofs
    u = np.zeros(dm.size)
    nodes = np.arange(dm.n_boom_nodes)
    for f, value in fields.items():
        u[dm.boom(nodes, f)] = value(np.asarray(dm.boom_x, dtype=float))
    return u


def tube_section(D, t):
    Di = D - 2 * t
    A = math.pi * (D**2 - Di**2) / 4
    I = math.pi * (D**4 - Di**4) / 64
    return A, I, 2 * I


# ------------------------------------------------------------------ hand sums
def shaft_mass() -> float:
    tubes = sum(rho * tube_section(D, t)[0] * (x1 - x0) for x0, x1, D, t, rho in TUBES)
    return tubes + sum(h[1] for h in HUBS) + DISK[1]


def shaft_polar() -> float:
    tubes = sum(rho * tube_section(D, t)[2] * (x1 - x0) for x0, x1, D, t, rho in TUBES)
    return tubes + sum(h[3] for h in HUBS) + DISK[3]


def shaft_diametral(x_ref: float) -> float:
    """Moment of inertia about a transverse axis through (x_ref, 0, 0)."""
    total = 0.0
    for x0, x1, D, t, rho in TUBES:
        A, I, _ = tube_section(D, t)
        total += rho * A * ((x1 - x_ref) ** 3 - (x0 - x_ref) ** 3) / 3 + rho * I * (x1 - x0)
    for x, m, Id, _ in [*HUBS, DISK]:
        total += m * (x - x_ref) ** 2 + Id
    return total


def semi_axes(x):
    s = x / BOOM_L
    return (1 - s) * ROOT[0] + s * TIP[0], (1 - s) * ROOT[1] + s * TIP[1]


def perimeter(a, b):
    return 4 * a * ellipe(1 - (b / a) ** 2)  # a ≥ b here


def ring_moment(a, b, which):
    """∮ y² ds, ∮ z² ds or ∮ (y² + z²) ds on the ellipse y = a sin ψ, z = b cos ψ."""
    weight = {"y": lambda p: (a * math.sin(p)) ** 2, "z": lambda p: (b * math.cos(p)) ** 2}
    weight["yz"] = lambda p: weight["y"](p) + weight["z"](p)
    f = weight[which]
    return quad(lambda p: f(p) * math.hypot(a * math.cos(p), b * math.sin(p)), 0, 2 * math.pi, epsabs=0, epsrel=1e-13)[
        0
    ]


def boom_integral(f) -> float:
    return quad(lambda x: f(*semi_axes(x)), 0.0, BOOM_L, epsabs=0, epsrel=1e-13)[0]


# ------------------------------------------------------------------ tests
def test_total_shaft_mass_in_each_translation(model):
    for field in ("u", "v", "w"):
        u = shaft_vector(model, {field: np.ones_like})
        assert quadratic(model, u) == pytest.approx(shaft_mass(), rel=1e-9), field


def test_shaft_spin_axis_inertia(model):
    u = shaft_vector(model, {"theta": np.ones_like})
    assert quadratic(model, u) == pytest.approx(shaft_polar(), rel=1e-9)


@pytest.mark.parametrize("x_ref", [0.0, 1.7])
def test_shaft_inertia_about_transverse_axes(model, x_ref):
    # γ = dv/dx and β = −dw/dx (docs/model.md): a rigid turn about z is v = s (x − x_ref), γ = s;
    # about y it is w = s (x − x_ref), β = −s.
    about_z = shaft_vector(model, {"v": lambda x: x - x_ref, "gamma": np.ones_like})
    about_y = shaft_vector(model, {"w": lambda x: x - x_ref, "beta": lambda x: -np.ones_like(x)})
    assert quadratic(model, about_z) == pytest.approx(shaft_diametral(x_ref), rel=1e-9)
    assert quadratic(model, about_y) == pytest.approx(shaft_diametral(x_ref), rel=1e-9)


def test_boom_and_end_mass_translation(model):
    boom = RHO_BOOM * BOOM_T * boom_integral(perimeter)
    for field in ("v", "w"):
        u = boom_vector(model, {field: np.ones_like})
        assert quadratic(model, u) == pytest.approx(boom + END_MASS, rel=1e-9), field


def test_boom_torsional_inertia_about_its_axis(model):
    # ρ t ∮ (y² + z²) ds along the boom, plus the end mass at distance² e_y² + e_z² and its I_xx
    boom = RHO_BOOM * BOOM_T * boom_integral(lambda a, b: ring_moment(a, b, "yz"))
    end = END_MASS * (END_OFFSET[1] ** 2 + END_OFFSET[2] ** 2) + END_INERTIA[0]
    u = boom_vector(model, {"theta": np.ones_like})
    assert quadratic(model, u) == pytest.approx(boom + end, rel=1e-9)


def test_boom_inertia_about_a_vertical_and_a_lateral_axis(model):
    # about z through the root: ∫ρA x² + ρ t ∮y² ds (I_z, rotary) + end mass at (L + e_x, e_y)
    mass_x2 = RHO_BOOM * BOOM_T * quad(lambda x: perimeter(*semi_axes(x)) * x**2, 0, BOOM_L, epsrel=1e-13)[0]
    about_z = mass_x2 + RHO_BOOM * BOOM_T * boom_integral(lambda a, b: ring_moment(a, b, "y"))
    about_z += END_MASS * ((BOOM_L + END_OFFSET[0]) ** 2 + END_OFFSET[1] ** 2) + END_INERTIA[2]
    u = boom_vector(model, {"v": lambda x: x, "gamma": np.ones_like})
    assert quadratic(model, u) == pytest.approx(about_z, rel=1e-9)
    about_y = mass_x2 + RHO_BOOM * BOOM_T * boom_integral(lambda a, b: ring_moment(a, b, "z"))
    about_y += END_MASS * ((BOOM_L + END_OFFSET[0]) ** 2 + END_OFFSET[2] ** 2) + END_INERTIA[1]
    u = boom_vector(model, {"w": lambda x: x, "beta": lambda x: -np.ones_like(x)})
    assert quadratic(model, u) == pytest.approx(about_y, rel=1e-9)


def test_the_whole_model_translates_with_its_total_mass(model):
    boom = RHO_BOOM * BOOM_T * boom_integral(perimeter)
    u = shaft_vector(model, {"v": np.ones_like}) + boom_vector(model, {"v": np.ones_like})
    assert quadratic(model, u) == pytest.approx(shaft_mass() + boom + END_MASS, rel=1e-9)
    # and the rigid translation stores no elastic energy (a bearing links shaft and boom)
    K = model.K.toarray()
    assert abs(u @ K @ u) <= 1e-12 * np.abs(K).max()
