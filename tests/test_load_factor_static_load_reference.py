"""The design's static load carries its load factor: every mass m takes the force m n g.

A steel tube (ρ = 7800 kg/m³, D_o = 60 mm, wall 4 mm, L = 1.5 m) with a 3.2 kg disk, loaded by
``[loads] load_factor = [0.5, -3.5, 2.0]`` [g] (docs/design-reference.md: every mass m carries
m·n·g). The consistent load of a uniform acceleration on a rigid translation sums, over the
nodes' translations, to the total mass times it: Σ Q_v = −3.5 g m, Σ Q_w = 2 g m and
Σ Q_u = 0.5 g m, with m = ρ π (D_o² − D_i²)/4 L + m_disk by hand and g = 9.80665 m/s² (standard
gravity, ISO 80000-3). A sum of a few nodal terms: 1e-12 relative.

Written for the mutation h33a-loads-static-without-load-factor of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load
from flexshaft.design import loads_design

RHO, DO, WALL, LENGTH, DISK = 7800.0, 0.06, 0.004, 1.5, 3.2
FACTOR = (0.5, -3.5, 2.0)

TEXT = f"""
name = "tube with a disk under a load factor"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = {RHO}
[shaft]
x_start = 0.0
x_end = {LENGTH}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "fore"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e7, w = 1e7 }}
[[bearings]]
name = "aft"
kind = "contact"
x = {LENGTH}
stiffness = {{ v = 1e7, w = 1e7 }}
[[disks]]
name = "disk"
x = 0.6
mass = {DISK}
[loads]
load_factor = [{FACTOR[0]}, {FACTOR[1]}, {FACTOR[2]}]
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 5
"""


def test_the_static_load_is_the_total_mass_times_the_load_factor():
    model = build_model(loads_design(TEXT))
    dm = model.dofs
    nodes = np.arange(dm.n_shaft_nodes)
    Q = external_static_load(model)
    mass = RHO * np.pi * (DO**2 - (DO - 2 * WALL) ** 2) / 4 * LENGTH + DISK
    for field, n in zip(("u", "v", "w"), FACTOR):
        assert Q[dm.shaft(nodes, field)].sum() == pytest.approx(n * 9.80665 * mass, rel=1e-12)
