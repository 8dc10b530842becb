"""The benchmark case shared by ``ross_model.py`` (ROSS venv) and ``compare_ross.py`` (flexshaft).

Pure Python on purpose (no numpy, no flexshaft, no ross) so that both environments import it.

Model: a uniform steel tube on two isotropic, damped bearings at its ends; no disk.
Euler-Bernoulli bending with rotary inertia and gyroscopic terms, no shear (ROSS:
``shear_effects=False, rotary_inertia=True, gyroscopic=True``; flexshaft:
``shear_deformation = false``, the default).

Axis conventions (both right-handed; the map is a cyclic permutation, i.e. a proper rotation):

=============  =========================  ==============================
quantity       ROSS 2.3.0                 flexshaft
=============  =========================  ==============================
axial          z  (DOF index 2)           x, ``u``
lateral 1      x  (DOF index 0)           y, ``v``
lateral 2      y  (DOF index 1)           z, ``w``
rotation       alpha about x (3)          ``beta`` about y
rotation       beta about y (4)           ``gamma`` about z
torsion        theta about z (5)          ``theta`` about x
spin           about +z (x -> y)          about +x (y -> z)
=============  =========================  ==============================

Both codes write the rotating imbalance of magnitude m·e as the complex amplitudes
(lateral 1, lateral 2) = Ω²·m·e·(1, −i), i.e. a force turning from lateral 1 towards lateral 2,
the direction of spin: the same physical load in both.

Axial and torsional DOFs: flexshaft holds the forward end in axial motion and twist
(``fixed_start = ["u", "theta"]``); a ROSS ``BearingElement`` has no torsional stiffness, so the
ROSS shaft is free-free in twist (and axially, kzz = 0). For this straight, unloaded, uniform
shaft these DOFs are exactly uncoupled from bending in both codes, so lateral responses are
unaffected; modes are compared on lateral (bending) modes only.
"""

from __future__ import annotations

import math

# Geometry and material (steel; ROSS's own ``steel`` has E = 211 GPa, G_s = 81.2 GPa, 7810).
LENGTH = 1.5  # m
OUTER_DIAMETER = 0.05  # m
INNER_DIAMETER = 0.03  # m
E = 211.0e9  # Pa
G = 81.2e9  # Pa
DENSITY = 7810.0  # kg/m^3

# Bearings at both ends, isotropic.
BEARING_STIFFNESS = 1.0e7  # N/m
BEARING_DAMPING = 1.0e3  # N s/m

# Loads and sweeps.
ELEMENTS = (20, 50, 100)
UNBALANCE = 1.0e-4  # kg m at the mid node, phase 0
N_SPEEDS_UNBALANCE = 500
N_FREQ = 500
N_SPEEDS_CAMPBELL = 50
N_CAMPBELL_FREQ = 8  # lowest lateral damped natural frequencies compared
# Maximum speed: ~2.1x the second critical speed (second lateral pair at 185 Hz = 1164 rad/s).
SPEED_MAX = 2500.0  # rad/s
FRF_SPEED = 1000.0  # rad/s, spin speed of the frequency-response case
FRF_FORCE = 1.0  # N, lateral-1 force at the mid node
# The frequency grid starts above 0: ROSS's shaft is free-free in twist, so its dynamic
# stiffness is singular at ω = 0 (ROSS then silently returns H = 0).
FREQ_MIN = SPEED_MAX / N_FREQ  # rad/s
FREQ_MAX = SPEED_MAX  # rad/s

TOLERANCE = 1.0e-3  # 0.1 %


def linspace(a: float, b: float, n: int) -> list[float]:
    return [a + (b - a) * i / (n - 1) for i in range(n)]


def unbalance_speeds() -> list[float]:
    return linspace(0.0, SPEED_MAX, N_SPEEDS_UNBALANCE)


def frf_frequencies() -> list[float]:
    return linspace(FREQ_MIN, FREQ_MAX, N_FREQ)


def campbell_speeds() -> list[float]:
    return linspace(0.0, SPEED_MAX, N_SPEEDS_CAMPBELL)


def parameters() -> dict:
    """Everything that defines the case, for the JSON dumps."""
    return {
        "length_m": LENGTH,
        "outer_diameter_m": OUTER_DIAMETER,
        "inner_diameter_m": INNER_DIAMETER,
        "E_Pa": E,
        "G_Pa": G,
        "density_kg_m3": DENSITY,
        "bearing_stiffness_N_m": BEARING_STIFFNESS,
        "bearing_damping_N_s_m": BEARING_DAMPING,
        "bearings": "at both end nodes, isotropic (x/y = v/w), no axial/torsional stiffness in ROSS",
        "disk": None,
        "beam_theory": "Euler-Bernoulli + rotary inertia + gyroscopic, no shear",
        "unbalance_kg_m": UNBALANCE,
        "unbalance_node": "mid",
        "speed_max_rad_s": SPEED_MAX,
        "n_speeds_unbalance": N_SPEEDS_UNBALANCE,
        "frf_speed_rad_s": FRF_SPEED,
        "frf_force_N": FRF_FORCE,
        "frf_freq_min_rad_s": FREQ_MIN,
        "frf_freq_max_rad_s": FREQ_MAX,
        "n_freq": N_FREQ,
        "n_speeds_campbell": N_SPEEDS_CAMPBELL,
        "n_campbell_frequencies": N_CAMPBELL_FREQ,
        "area_m2": math.pi * (OUTER_DIAMETER**2 - INNER_DIAMETER**2) / 4,
        "I_m4": math.pi * (OUTER_DIAMETER**4 - INNER_DIAMETER**4) / 64,
    }
