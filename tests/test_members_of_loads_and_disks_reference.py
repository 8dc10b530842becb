"""A disk and an end-mass load must lie on a member the design has.

Reference: the documented rule of docs/limits.md section 2 (checks of several numbers):
"every bearing, disk, sensor and load on its member."

* **A disk ahead of the shaft.** The Jeffcott design of ``tests/rotors.py`` has its shaft on
  [0, L]; a disk at x = −0.1 m lies before ``x_start`` and is refused at ``disks[0].x``. A disk
  at x = 0 (the start, on the shaft) is accepted, and then it is really on the shaft: the
  rigid-body translation u = 1 along y of every shaft node gives uᵀ M u = m_shaft + m_disk,
  with m_shaft = ρ π (D_o² − D_i²)/4 · L (hand sum, derived here: the consistent mass matrix
  reproduces the total mass of a rigid translation exactly).
* **A load on an absent end mass.** A design with a ``[tailboom]`` but no
  ``[tailboom.end_mass]`` has no end mass for a ``[[loads.point]]`` with ``on = "end_mass"``:
  it is refused at ``loads.point[0].on`` although the boom exists. With a
  ``[tailboom.end_mass]`` the same load is accepted and the design's static load carries it:
  the y resultant over the boom's translational DOFs is F (the end mass hangs on the boom tip
  node through a rigid offset, which moves the force, not its resultant).

Tolerances: sums of a few terms of order 1e1-1e3, exact up to rounding: 1e-12 relative.
"""

from __future__ import annotations

import numpy as np
import pytest
from boomed_rotor import shaft_and_boom
from rotors import DI, DO, M_DISK, L, jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load
from flexshaft.design import DesignError, loads_design

RHO = 0.1  # kg/m³, the Jeffcott steel's density in tests/rotors.py
F_Y = -300.0  # N


def _jeffcott_with_disk_at(x: float) -> str:
    text = jeffcott_text(0.0, 0.0)
    old = f'name = "disk"\nx = {L / 2}\n'
    assert old in text
    return text.replace(old, f'name = "disk"\nx = {x}\n')


def test_disk_ahead_of_the_shaft_start_is_refused() -> None:
    with pytest.raises(DesignError) as info:
        loads_design(_jeffcott_with_disk_at(-0.1))
    assert "disks[0].x:" in str(info.value)
    assert "outside the shaft" in str(info.value)


def test_disk_at_the_shaft_start_is_on_the_shaft_and_adds_its_mass() -> None:
    model = build_model(loads_design(_jeffcott_with_disk_at(0.0)))
    dm = model.dofs
    u = np.zeros(model.M.shape[0])
    u[dm.shaft(np.arange(dm.n_shaft_nodes), "v")] = 1.0
    m_shaft = RHO * np.pi * (DO**2 - DI**2) / 4.0 * L
    assert u @ (model.M @ u) == pytest.approx(m_shaft + M_DISK, rel=1e-12)


def _boom_design(end_mass: bool) -> str:
    table = "[tailboom.end_mass]\nmass = 40.0\noffset = [0.1, 0.2, 0.0]\n" if end_mass else ""
    return f"""
name = "an end-mass point load"
{shaft_and_boom(2.0)}{table}[[bearings]]
name = "fore"
kind = "contact"
x = 0.6
stiffness = {{ v = 1e7, w = 1e7 }}
[[bearings]]
name = "aft"
kind = "contact"
x = 1.9
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[loads]
eccentricity = 0.0
[[loads.point]]
name = "tip load"
on = "end_mass"
force = [0.0, {F_Y}, 0.0]
[mesh]
shaft_elements = 4
boom_elements = 3
"""


def test_end_mass_load_without_an_end_mass_is_refused_though_the_boom_exists() -> None:
    with pytest.raises(DesignError) as info:
        loads_design(_boom_design(end_mass=False))
    assert 'loads.point[0].on: is "end_mass" but the design has no [tailboom.end_mass]' in str(info.value)


def test_end_mass_load_with_an_end_mass_carries_its_force() -> None:
    model = build_model(loads_design(_boom_design(end_mass=True)))
    dm = model.dofs
    Q = external_static_load(model)
    qv = Q[dm.boom(np.arange(dm.n_boom_nodes), "v")]
    assert qv.sum() == pytest.approx(F_Y, rel=1e-12)
