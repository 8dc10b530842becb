"""Published closed forms that some validation cases evaluate for their published value.

Each function states the formula as its source prints it; the case that uses it cites where
(:mod:`flexshaft.validation.cases`). Nothing here calls flexshaft's models.
"""

from __future__ import annotations

import math

__all__ = ["gibert_spinning_beam", "rayleigh_cantilever_tip_mass", "rotating_damping_onset"]


def gibert_spinning_beam(
    *, length: float, diameter: float, modulus: float, density: float, speed: float, modes: int
) -> tuple[float, ...]:
    """Backward and forward natural frequencies [rad/s] of a spinning, simply supported solid
    Euler beam, for modes n = 1..``modes``: (backward 1, forward 1, backward 2, ...).

    R.-J. Gibert's solution as code_aster's validation manual V2.02.141 §2.1 states it:
    ω_b/ω_0 = sqrt(λ² + 1) − λ, ω_f/ω_0 = sqrt(λ² + 1) + λ, with
    ω_0 = (nπ/L)² sqrt(EI/(ρS)), λ = Ω I_x / (2 sqrt(EI ρS)), I_x = ρ S D²/8, I = π D⁴/64.
    The beam has no rotary inertia (only the gyroscopic moment of the polar inertia I_x).

    Parameters
    ----------
    length, diameter : float
        L and D [m].
    modulus, density : float
        E [Pa] and ρ [kg/m³].
    speed : float
        Ω [rad/s].
    modes : int
        Number of modes n.
    """
    area = math.pi * diameter**2 / 4.0
    inertia = math.pi * diameter**4 / 64.0
    polar = density * area * diameter**2 / 8.0
    lam = 0.5 * speed * polar / math.sqrt(modulus * inertia * density * area)
    out: list[float] = []
    for n in range(1, modes + 1):
        omega0 = (n * math.pi / length) ** 2 * math.sqrt(modulus * inertia / (density * area))
        root = math.sqrt(lam**2 + 1.0)
        out += [omega0 * (root - lam), omega0 * (root + lam)]
    return tuple(out)


def rayleigh_cantilever_tip_mass(
    *, length: float, outer_diameter: float, wall_thickness: float, modulus: float, density: float, tip_mass: float
) -> float:
    """First bending frequency [Hz] of a cantilevered tube with a point mass at its free end,
    by the Rayleigh formula of the VPCS guide's sheet SDLL15/89 (code_aster V2.02.015 §2.1):
    f1 = (1/2π) sqrt(3 E I / (L³ (m_c + 0.24 M))), M the tube's mass.

    Parameters
    ----------
    length, outer_diameter, wall_thickness : float
        L, D_o, t [m].
    modulus, density : float
        E [Pa], ρ [kg/m³].
    tip_mass : float
        m_c [kg].
    """
    inner = outer_diameter - 2.0 * wall_thickness
    inertia = math.pi * (outer_diameter**4 - inner**4) / 64.0
    beam_mass = density * math.pi * (outer_diameter**2 - inner**2) / 4.0 * length
    return math.sqrt(3.0 * modulus * inertia / (length**3 * (tip_mass + 0.24 * beam_mass))) / (2.0 * math.pi)


def rotating_damping_onset(*, stiffness: float, mass: float, external_damping: float, internal_damping: float) -> float:
    """Onset speed [rad/s] of the whirl instability of a Jeffcott rotor with rotating (internal)
    viscous damping ``internal_damping`` c_i and stationary damping ``external_damping`` c_e
    [N s/m], on a shaft of ``stiffness`` k [N/m] carrying ``mass`` m [kg].

    In complex coordinates r = v + i w the rotor obeys m r'' + (c_e + c_i) r' + (k − i c_i Ω) r = 0,
    the rotor model ``M r'' + D r' + (K − j D λ Ω) r = 0`` of Bently & Hatch's Appendix 6 (eq. A6-1)
    with D = c_e + c_i and λ = c_i/(c_e + c_i). Its eigenvalue s1 (eq. A6-7) has the growth rate
    ``−D/(2M) + sqrt((−E + sqrt(E² + (DλΩ/M)²))/2)``, E = K/M − (D/2M)², which vanishes where
    λΩ = sqrt(K/M): Ω = sqrt(k/m) (1 + c_e/c_i).
    """
    lam = internal_damping / (external_damping + internal_damping)
    return math.sqrt(stiffness / mass) / lam
