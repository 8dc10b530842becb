"""Reference: how many modes the verdict's Campbell diagram tracks (hunt h40a).

:func:`flexshaft.verdict.point_tasks.campbell_mode_count` tracks at least the resolution's
``campbell_modes`` and every undamped mode at rest below 1.1 × the Campbell ceiling, plus two;
the ceiling is the diagram's top speed (the grid's last, ``scan_top`` × Ω_op) times the highest
excitation order (1/rev here: no rotor is given).

The model: a pinned-pinned steel tube (D 50 mm, wall 5 mm, L = 1 m, ρ 7850 kg/m³, E 210 GPa),
whose bending frequencies are Rayleigh's beam (Euler-Bernoulli with rotary inertia, EI w'''' +
ρA ẅ − ρI ẅ'' = 0; pinned ends give sin(nπx/L) exactly, and with it)

    ω_n² = EI k⁴ / (ρA (1 + k² r²)),  k = nπ/L,  r² = I/A,

each twice (the v and w planes), between Euler-Bernoulli's (r = 0) and that; torsion and the
axial mode (fixed at one end) lie at (π/2L)√(G/ρ) = 5015 and (π/2L)√(E/ρ) = 8125 rad/s. At
Ω_op = 2400 rad/s and a two-speed diagram to 1.3 Ω_op the ceiling is 3120 rad/s and the count
reaches up to 1.1 × 3120 = 3432 rad/s: ω₁ ≈ 817 and ω₂ ≈ 3255 rad/s lie below it (ω₂ above the
ceiling itself: only the 10 % finds it), ω₃ ≈ 7300 above: four modes, plus two = 6 with
``campbell_modes = 2``. Each frequency is at least 4 % from each threshold, far more than the
10-element mesh's error (1e-4 on ω₂) or the Rayleigh/Euler-Bernoulli spread (0.4 %).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.resolution import REPORT
from flexshaft.verdict.point_tasks import campbell_ceiling, campbell_mode_count

E, RHO, L, DO, T = 210e9, 7850.0, 1.0, 0.05, 0.005
OMEGA = 2400.0

TEXT = f"""
name = "pinned-pinned tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = {RHO}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {T}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "none"
kind = "contact"
x = 0.5
stiffness = {{}}
[operating]
speed = {OMEGA}
power = 0.0
[mesh]
shaft_elements = 10
"""


def _bending(n: int, rotary: bool) -> float:
    di = DO - 2 * T
    area, inertia = math.pi * (DO**2 - di**2) / 4, math.pi * (DO**4 - di**4) / 64
    k = n * math.pi / L
    return math.sqrt(E * inertia * k**4 / (RHO * area * (1.0 + (k * k * inertia / area if rotary else 0.0))))


def test_the_campbell_diagram_tracks_every_mode_below_a_tenth_above_its_ceiling_plus_two():
    resolution = dataclasses.replace(REPORT, campbell_speeds=2, campbell_modes=2)
    model = build_model(loads_design(TEXT))
    ceiling = resolution.scan_top * OMEGA  # the grid's top speed times the 1/rev order
    assert campbell_ceiling(model, resolution) == ceiling
    wanted = 1.1 * ceiling
    # the reference's placement: two bending pairs below 1.1 × the ceiling, the second above it
    for rotary in (False, True):
        w1, w2, w3 = (_bending(n, rotary) for n in (1, 2, 3))
        assert w1 < 0.96 * ceiling and 1.04 * ceiling < w2 < 0.96 * wanted and w3 > 1.04 * wanted
    torsion = math.pi / (2 * L) * math.sqrt(80e9 / RHO)
    assert torsion > 1.04 * wanted
    assert campbell_mode_count(model, resolution) == 2 * 2 + 2


def test_without_a_diagram_the_ceiling_is_the_operating_speed():
    """No Campbell speeds: the ceiling is Ω_op = 2400 rad/s and 1.1 × 2400 = 2640 holds only the
    first bending pair (ω₂ ≈ 3255): 2 + 2 = 4 modes, and at least ``campbell_modes`` = 5."""
    model = build_model(loads_design(TEXT))
    assert campbell_ceiling(model, dataclasses.replace(REPORT, campbell_speeds=0)) == OMEGA
    assert _bending(2, True) > 1.2 * 1.1 * OMEGA
    assert campbell_mode_count(model, dataclasses.replace(REPORT, campbell_speeds=0, campbell_modes=2)) == 4
    assert campbell_mode_count(model, dataclasses.replace(REPORT, campbell_speeds=0, campbell_modes=5)) == 5
    assert np.isclose(_bending(1, False), 817.0, rtol=2e-3)
