"""Torsion of single members, checked against closed forms (derived here): the hysteretic loss of
the boom and of a metal shaft, and the twist a rigid main gearbox holds.

* **Loss of one member.** A torsion mode whose strain energy lies in one member of loss factor η
  has every stiffness term of that member multiplied by (1 + iη) (Kelvin's complex moduli
  E* = E(1 + iη), G* = G(1 + iη), the loss a fixed fraction of the elastic stiffness), so the
  mode's shape is the undamped one and its equation m q̈ + k(1 + iη) q = 0 gives
  s² = −ω₀²(1 + iη), ω₀² = k/m the undamped eigenvalue of the same model. The root with Im s > 0
  is s = iω₀√(1 + iη) (principal root), whose real part −ω₀ Im√(1 + iη) ≈ −ηω₀/2 is negative:
  the loss takes energy out. At rest the shaft's rotating-frame loss acts as a stationary one
  (sign(ω − Ω) = +1 at Ω = 0 for ω > 0). The relation holds for the discrete model exactly, so
  it is checked on the full problem (a basis of every free DOF), at 1e-8: the models have fewer
  than 100 DOFs and stiffness ratios of about 1e6 between their highest and these modes, so the
  eigenvalues carry about 1e-10 relative round-off.
* **A rigid main gearbox** holds the forward end's twist. A uniform shaft (G, ρ, polar second
  moment I_p, length L) held in twist at x = 0 with a disk of polar inertia J_d at x = L:
  G I_p θ'' = ρ I_p θ̈ with θ(0) = 0 and G I_p θ'(L) = J_d ω² θ(L), so with β = ω √(ρ/G),
  βL tan(βL) = ρ I_p L / J_d (first root in (0, π/2)). Held at the aft end instead, the disk
  would sit on the held node and the shaft alone would give βL = π/2. The linear torsion
  elements converge at second order: 16 and 32 elements, Richardson-extrapolated, at 1e-6.

The models are built from design files, so the path through ``build_model`` is the one checked.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import flexshaft as fs
from flexshaft.design import loads_design

E, G, RHO = 71e9, 27e9, 2800.0
ETA = 0.02
DO, WALL, SHAFT_L = 0.1, 0.01, 0.5


def _lossy_design(boom_elements: int = 6) -> str:
    """A short metal shaft clamped at x = 0 (but for its twist, held by the clamp too) beside a
    uniform elliptical cantilever boom, one material of loss factor ETA, an unloaded bearing."""
    return f"""
name = "lossy members"
[materials.al]
kind = "isotropic"
E = {E}
G = {G}
density = {RHO}
loss_factor = {ETA}
[shaft]
x_start = 0.0
x_end = {SHAFT_L}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "al"
fixed_start = ["u", "v", "w", "theta", "beta", "gamma"]
[tailboom]
length = 6.0
root_semi_axes = [0.3, 0.2]
tip_semi_axes = [0.3, 0.2]
wall_thickness = 0.003
material = "al"
shaft_clearance = 0.05
[[bearings]]
name = "unloaded"
kind = "contact"
x = 0.0
stiffness = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 4
boom_elements = {boom_elements}
"""


def _twist_share(model, shapes: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """Kinetic-energy share of each mode (column of ``shapes``) in the DOFs ``twist``."""
    M = model.M.toarray()
    phi = shapes.real
    return np.einsum("ik,ij,jk->k", phi[twist], M[np.ix_(twist, twist)], phi[twist]) / np.einsum(
        "ik,ij,jk->k", phi, M, phi
    )


@pytest.mark.parametrize("member", ["boom", "shaft"])
def test_a_torsion_mode_of_one_lossy_member_has_s_squared_minus_omega0_squared_times_one_plus_i_eta(member):
    model = fs.build_model(loads_design(_lossy_design()))
    dm = model.dofs
    if member == "boom":
        twist = dm.boom(np.arange(dm.n_boom_nodes), "theta")
    else:
        twist = dm.shaft(np.arange(dm.n_shaft_nodes), "theta")
    n = int(dm.free.size)
    undamped = fs.modes(model, n_modes=n, damped=False, basis_size=n)
    shares = _twist_share(model, undamped.shapes, twist)
    torsion = [k for k in np.argsort(np.abs(undamped.eigenvalues)) if shares[k] > 0.999]
    assert torsion, shares
    omega0 = float(np.abs(undamped.eigenvalues[torsion[0]]))
    damped = fs.modes(model, n_modes=n, damped=True, basis_size=n)
    s = damped.eigenvalues[np.argmin(np.abs(damped.eigenvalues - 1j * omega0))]
    expected = 1j * omega0 * np.sqrt(1 + 1j * ETA)
    assert abs(s - expected) <= 1e-8 * abs(expected), (s, expected)
    assert s.real < -0.4 * ETA * omega0  # it decays, at about η ω₀ / 2


def _gearbox_design(elements: int, disk_polar: float) -> str:
    return f"""
name = "shaft held in twist by its gearbox"
[materials.steel]
kind = "isotropic"
E = 2.0e11
G = 8.0e10
density = 7800.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "v", "w", "beta", "gamma"]
[main_gearbox]
[[disks]]
name = "tip"
x = 1.0
mass = 1.0
polar_inertia = {disk_polar}
diametral_inertia = 0.001
[[bearings]]
name = "unloaded"
kind = "contact"
x = 0.0
stiffness = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = {elements}
"""


def _first_torsion(elements: int, disk_polar: float) -> float:
    model = fs.build_model(loads_design(_gearbox_design(elements, disk_polar)))
    dm = model.dofs
    n = int(dm.free.size)
    found = fs.modes(model, n_modes=12, damped=False, basis_size=n)
    twist = dm.shaft(np.arange(dm.n_shaft_nodes), "theta")
    shares = _twist_share(model, found.shapes, twist)
    torsion = [k for k in np.argsort(np.abs(found.eigenvalues)) if shares[k] > 0.999]
    assert torsion, shares
    return float(np.abs(found.eigenvalues[torsion[0]]))


def test_a_rigid_main_gearbox_holds_the_forward_twist():
    Do, Di, L, Gs, rho = 0.05, 0.04, 1.0, 8.0e10, 7800.0
    Ip = math.pi * (Do**4 - Di**4) / 32
    J_d = rho * Ip * L  # the disk's polar inertia equals the shaft's own
    beta_L = brentq(lambda x: x * math.tan(x) - rho * Ip * L / J_d, 1e-9, math.pi / 2 - 1e-12, xtol=1e-15)
    exact = beta_L / L * math.sqrt(Gs / rho)
    coarse, fine = _first_torsion(16, J_d), _first_torsion(32, J_d)
    assert (4 * fine - coarse) / 3 == pytest.approx(exact, rel=1e-6)
    # held at the aft end the disk would not move: the bare shaft's π/2, 45 % higher
    assert exact < 0.6 * math.pi / (2 * L) * math.sqrt(Gs / rho)
