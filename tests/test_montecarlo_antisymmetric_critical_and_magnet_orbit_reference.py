"""Monte-Carlo spin-up: the peak search finds an antisymmetric critical, and a non-collocated
bearing's orbit is read at its magnet.

* **The second critical of a pinned-pinned tube.** A uniform steel tube (E = 210 GPa,
  ρ = 7800 kg/m³, D = 20 mm, wall 2 mm, L = 3 m) pinned at both ends, no disk, the material loss
  η = 0.01 in the fixed frame (``internal_damping = "thesis"``, which damps synchronous whirl).
  Its bending criticals are those of the Euler-Bernoulli beam, ω_n = (nπ/L)² √(EI/(ρA))
  (Timoshenko & Young, derived here from the pinned-pinned mode sin(nπx/L)); the second
  (n = 2, antisymmetric about mid-span) is ω₂ = 4 ω₁ = 145.7 rad/s. The spin-up grid
  0.75 … 1.25 ω₂ (steps of 0.1 ω₂) straddles it 5 % from its nearest points; the unit
  responses add speeds around every local peak (docstring of ``unit_responses``: "Add speeds
  around every local peak of the response"), so one lands within the golden-section width of the
  resonance, and a sample with its unbalance at the quarter span (where sin(2πx/L) = 1, the
  mode's antinode) peaks there. The stations of the one bay are symmetric about mid-span: a
  search blind to the antisymmetric mode leaves the nearest speed 5 % off.

  Tolerance 2e-3: the 8 cubic elements stiffen the mode by ≈ (kh)⁴/1440 = 2.6e-4 (kh = π/4);
  rotary inertia and the gyroscopic stiffening of forward synchronous whirl net ≈ +½(2π r_g/L)²
  = 0.9e-4 (r_g = √(D² + d²)/4 = 6.4 mm; no shear: Euler-Bernoulli elements); the hysteretic
  peak sits η²/2 = 5e-5 above ω₂; measured 4.2e-4 in all (1.8e-4 with 16 elements), 25 times
  smaller than the 5 % of an unrefined grid.

* **The orbit at the magnet.** tests/jeffcott_bearing.py's near-massless pinned-pinned shaft
  (L = 1 m) with its disk and a PD magnetic bearing at mid-span, the bearing's sensor 0.125 m aft
  (x = 0.625 m). With the unbalance at mid-bay (the disk, x = 0.5 m) every load on the shaft (the
  disk's inertia, the unbalance, the bearing's force) acts at mid-span, so the massless shaft
  takes the static shape of a pinned-pinned beam under a mid-span point load,
  y(x)/y(L/2) = x(3L² − 4x²)/L³ for x ≤ L/2 (beam tables; derived here from EI y'''' = 0 with
  y = y'' = 0 at the ends), largest at mid-span. The bearing's relative orbit at the magnet
  (bearing housing fixed to ground) is therefore the shaft's largest orbit, ``shaft_peak``,
  while the sensor reads y(0.375)/y(0.5) = 0.9140625 of it. Both outputs are complex64 sums
  of the same solves: rel 1e-5 (round-off 6e-8 of complex64; Euler-Bernoulli elements, the
  shaft's mass 3.5e-6 of the disk's: the node orbits follow the shape to 1e-7, measured).
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, model_with

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.montecarlo.samples import ImbalanceDraws, sample_outputs, unit_responses

E, RHO, ETA = 210e9, 7800.0, 0.01
D, WALL, L = 0.02, 0.002, 3.0

TUBE = f"""
name = "pinned-pinned tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = {RHO}
loss_factor = {ETA}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "idle"
kind = "contact"
x = {L / 2}
stiffness = {{}}
damping = {{}}
[operating]
speed_rpm = 0.0
power = 0.0
[analysis]
internal_damping = "thesis"
[mesh]
shaft_elements = 8
"""


def _pinned_pinned_critical(n: int) -> float:
    d = D - 2 * WALL
    inertia, area = np.pi * (D**4 - d**4) / 64, np.pi * (D**2 - d**2) / 4
    return (n * np.pi / L) ** 2 * np.sqrt(E * inertia / (RHO * area))


def test_the_peak_search_finds_the_antisymmetric_second_critical():
    model = build_model(loads_design(TUBE))
    w2 = _pinned_pinned_critical(2)
    grid = w2 * np.array([0.75, 0.85, 0.95, 1.05, 1.15, 1.25])
    units = unit_responses(model, speeds=grid, placement="uniform")
    assert units.n_bays == 1
    assert np.min(np.abs(units.speeds / w2 - 1.0)) < 2e-3
    draws = ImbalanceDraws(np.array([[1e-4]]), np.array([[0.0]]), np.array([[0.25]]))  # quarter span
    out = sample_outputs(model, units, draws, strength=False)
    assert out["shaft_peak_speed"][0] == pytest.approx(w2, rel=2e-3)


def test_a_non_collocated_bearings_orbit_is_read_at_its_magnet():
    model = model_with(f"{ACTIVE}\nsensor_offset = 0.125")
    (bearing,) = model.actuators
    assert not bearing.collocated
    units = unit_responses(model, speeds=np.array([100.0, 200.0, 300.0]), placement="mid_bay", refine=False)
    n = units.n_bays
    draws = ImbalanceDraws(np.full((1, n), 1e-3), np.zeros((1, n)), np.full((1, n), 0.5))
    out = sample_outputs(model, units, draws, strength=False)
    assert out[f"actuator_orbit_{bearing.name}"][0] == pytest.approx(out["shaft_peak"][0], rel=1e-5)
