"""Critical speeds of a rigid rotor on three springs under the worst-case imbalance placement: the
rocking critical only the anti-phase case excites is found, against the rigid rotor's closed
forms (derived here).

A rigid tube (E = 2.1e15 Pa: its bending modes lie far above the speeds scanned) of mass m_t and
length 1 m with a 20 kg disk of diametral inertia 240 kg m² at its middle, on springs k = 1e6 N/m
at x = 0, 0.5 and 1 m, with dashpots c at the two ends. The bearings make two bays; the
``"worst"`` placement puts e M/2 at each bay's middle (x = 0.25 and 0.75 m, M = m_t + 20 kg the
rotating mass) in phase (case 1) and in anti-phase (case 2). The structure is symmetric about
the middle, so

* case 1 excites only the translation: M ẍ + 2c ẋ + 3k x = F, ω_t = √(3k/M), ζ_t = c/√(3kM);
* case 2 excites only the rocking about the middle: I θ̈ + (c/2) θ̇ + (k/2) θ = moment, with
  I = 240 + m_t/12 + ρ I_A (the tube's rotatory inertia), ω_r = √(k/(2I)),
  ζ_r = (c/2)/(2√(kI/2)).

Both forcings grow as Ω², so each peak lies at ω/√(1 − 2ζ²) (the maximum of
ρ²/√((1 − ρ²)² + (2ζρ)²)). With ζ_t = 0.05 and the operating speed ω_t/1.2, the rocking critical
(ω_r ≈ 0.2 Ω_op) and the translation (1.2 Ω_op) both lie in the search's 0.02-1.3 Ω_op; a search
that looked at the in-phase case only would miss the rocking one.

Tolerance 1e-3: the tube's polar inertia (0.045 kg m², no disk polar inertia) couples the planes
at speed and moves the rocking frequency by ~I_p/(2I) ≈ 1e-4; the translation holds to the
tube's flexibility (~1e-6). The 4-element tube is rigid: the mesh does not matter.
"""

from __future__ import annotations

import math

import pytest

from flexshaft.analyses.criticals import lateral_critical_speeds
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import loads_design

KB, RHO, M_DISK, I_DISK = 1.0e6, 7800.0, 20.0, 240.0
DO, DI = 0.1, 0.08
M_TUBE = RHO * math.pi / 4 * (DO**2 - DI**2)
M_TOTAL = M_TUBE + M_DISK
I_TOTAL = I_DISK + M_TUBE / 12 + RHO * math.pi / 64 * (DO**4 - DI**4)
W_TRANS, W_ROCK = math.sqrt(3 * KB / M_TOTAL), math.sqrt(KB / (2 * I_TOTAL))
ZETA_TRANS = 0.05
C = ZETA_TRANS * math.sqrt(3 * KB * M_TOTAL)
ZETA_ROCK = (C / 2) / (2 * math.sqrt(KB * I_TOTAL / 2))


def _spring(name: str, x: float, c: float) -> str:
    damping = f"damping = {{ v = {c}, w = {c} }}\n" if c else ""
    return f'[[bearings]]\nname = "{name}"\nkind = "contact"\nx = {x}\nstiffness = {{ v = {KB}, w = {KB} }}\n{damping}'


def three_spring_rotor(name: str, dampers: tuple[float, float, float], disk_inertia: float, elements: int) -> str:
    """The rigid rotor of this file: a stiff 1 m tube on springs KB at 0, 0.5 and 1 m (dashpots
    ``dampers`` [N s/m], none where 0), a disk M_DISK of diametral inertia ``disk_inertia`` at
    midspan, the worst imbalance placement; also tests/test_hidden_resonance_other_load_case_reference.py's."""
    springs = "".join(_spring(n, x, c) for n, x, c in zip(("left", "middle", "right"), (0.0, 0.5, 1.0), dampers))
    return f"""
name = "{name}"
[materials.stiff]
kind = "isotropic"
E = 2.1e15
G = 8e14
density = {RHO}
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = 1.0
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "stiff"
fixed_start = ["u", "theta"]
{springs}
[[disks]]
name = "disk"
x = 0.5
mass = {M_DISK}
diametral_inertia = {disk_inertia}
[operating]
speed_rpm = {W_TRANS / 1.2 * 30 / math.pi}
power = 0.0
[loads]
eccentricity = 1e-5
imbalance_placement = "worst"
[mesh]
shaft_elements = {elements}
"""


TEXT = three_spring_rotor("rigid rotor on three springs", (C, 0.0, C), I_DISK, 4)


@pytest.mark.parametrize("n_points", [61, 2401])
def test_the_search_finds_the_critical_of_every_imbalance_case(n_points):
    """At 61 speeds (spacing ~4.8 rad/s) the rocking peak (half-power band 2 ζ_r ω_r ≈ 1.1 rad/s)
    can fall between the samples and is found from the synchronous roots too
    (tests/test_hidden_resonances.py); at 2401 (spacing ~0.12 rad/s, its band over more than the
    four intervals below which the roots are searched) the scan's own envelope over both cases
    must show it."""
    model = build_model(loads_design(TEXT))
    assert imbalance_loads(model).shape[1] == 2  # in phase and anti-phase
    found = lateral_critical_speeds(model, n_points=n_points)
    rocking = W_ROCK / math.sqrt(1 - 2 * ZETA_ROCK**2)
    translation = W_TRANS / math.sqrt(1 - 2 * ZETA_TRANS**2)
    assert [c.speed for c in found] == pytest.approx([rocking, translation], rel=1e-3)
