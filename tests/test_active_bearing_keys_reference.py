"""An active bearing's design keys against what they mean, derived by hand.

* **The filtered PD law** (``kp``, ``kd``, ``derivative_cutoff`` f_d [Hz], no integral gain):
  ``C(s) = k_p + k_d s/(1 + s/ω_d)`` with ω_d = 2π f_d (the derivative filter of Åström &
  Murray, *Feedback Systems*, 2008, ch. 10; docs of ActiveBearing). Only the derivative is
  filtered: C(0) = k_p and C(s) → k_p + k_d ω_d as s → ∞, the one pole at −ω_d. A filter on the
  whole law, (k_p + k_d s)/(1 + s/ω_d), would give k_d ω_d at high frequency instead. The
  fraction is evaluated here by hand at a few s; a few operations on numbers of order 1 to 1e7:
  relative 1e-12.
* **A non-collocated sensor on a bearing mounted on the tailboom** measures the shaft relative
  to the boom at the sensor's station: shaft station x + δ, boom station x_b + δ
  (``sensor_offset`` δ). So the boom must reach x_b + δ: a sensor whose boom station lies
  behind the boom's tip is refused, and the boom's mesh has a node at x_b + δ (where the sensor
  is read), as it has at every bearing station.

Written for the mutations h18a-bearings-pd-filter-on-whole-law and
h18a-bearings-sensor-boom-station-collocated of scripts/mutations.toml. No model is assembled
for the law; the sensor's node needs one tiny model (4 shaft, 4 boom elements).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design
from flexshaft.design.bearings import ActiveBearing

KP, KD, FD = 2.0e6, 900.0, 400.0  # k_p [A/m], k_d [A s/m], f_d [Hz]


def test_filtered_pd_keys_give_kp_plus_a_filtered_derivative():
    bearing = ActiveBearing(kind="active", name="amb", x=0.5, kp=KP, kd=KD, derivative_cutoff=FD)
    num, den = bearing.transfer_function()
    wd = 2.0 * math.pi * FD
    for s in (0.0, 1j * 50.0, 1j * wd, -30.0 + 400.0j, 1j * 1.0e5):
        value = sum(c * s ** (len(num) - 1 - k) for k, c in enumerate(num)) / sum(
            c * s ** (len(den) - 1 - k) for k, c in enumerate(den)
        )
        assert value == pytest.approx(KP + KD * s / (1.0 + s / wd), rel=1e-12)
    # high-frequency gain k_p + k_d ω_d: ratio of the leading coefficients
    assert num[0] / den[0] == pytest.approx(KP + KD * wd, rel=1e-12)


BOOM_LENGTH, X_BEARING = 1.8, 1.0


def boomed_design(sensor_offset: float) -> str:
    return f"""
name = "active bearing on a tailboom"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.1
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
[tailboom]
length = {BOOM_LENGTH}
root_semi_axes = [0.2, 0.2]
tip_semi_axes = [0.2, 0.2]
wall_thickness = 0.003
material = "steel"
shaft_clearance = 0.05
[[bearings]]
name = "amb"
kind = "active"
x = {X_BEARING}
kp = 1.0e6
kd = 500.0
sensor_offset = {sensor_offset}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 4
boom_elements = 4
"""


def test_a_sensor_behind_the_boom_tip_is_refused():
    """x_b + δ = 1.0 + 0.85 = 1.85 m on a 1.8 m boom (the shaft, 2 m long, still reaches it)."""
    with pytest.raises(DesignError, match="sensor's boom station"):
        loads_design(boomed_design(0.85))


def test_the_boom_has_a_node_where_the_sensor_is_read():
    """δ = 0.13 m: x_b + δ = 1.13 m is none of the boom's uniform stations (multiples of 0.45 m)
    nor the bearing's 1.0 m; the mesh puts a node there (to round-off of the station sum)."""
    delta = 0.13
    model = build_model(loads_design(boomed_design(delta)))
    assert np.min(np.abs(np.asarray(model.dofs.boom_x) - (X_BEARING + delta))) < 1e-12
    assert np.min(np.abs(np.asarray(model.dofs.shaft_x) - (X_BEARING + delta))) < 1e-12
