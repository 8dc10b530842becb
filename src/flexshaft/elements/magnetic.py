r"""Radial active magnetic bearing: linearised magnet force, current gain, saturation force.

Model (Schweitzer & Maslen 2009, ch. 2-3). One control axis of a heteropolar radial bearing is
a pair of opposed horseshoe electromagnets ("differential driving mode"). Each horseshoe has
two poles of face area ``A_a`` inclined by the pole angle α to the force axis (α = 22.5° for
the usual 8-pole stator), ``N`` turns and two air gaps in series. With infinitely permeable
iron and no fringing or leakage, one horseshoe at gap ``g`` carrying current ``i`` pulls with

.. math:: f = k\,\frac{i^2}{g^2},\qquad k = \tfrac14 \mu_0 N^2 A_a \cos α .

The opposed pair is driven by the bias current ``i_0`` plus and minus the control current
``i`` and sees the gaps ``g_0 ∓ x`` (x the shaft's displacement towards the first magnet), so

.. math:: f = k\left[\frac{(i_0 + i)^2}{(g_0 - x)^2} - \frac{(i_0 - i)^2}{(g_0 + x)^2}\right]
          ≈ k_i\, i + k_s\, x,\qquad k_i = \frac{4 k i_0}{g_0^2},\quad k_s = \frac{4 k i_0^2}{g_0^3}

(linearised about x = 0, i = 0). ``k_s > 0`` is the open-loop *negative* stiffness: the
magnets pull the shaft further off centre; ``k_s = k_i i_0 / g_0``. The gaps ``g_0 ∓ x`` take
the shaft's displacement as the gaps' change, as the textbook's forms (and ROSS) do; with the
poles inclined by α each gap changes by ``x cos α``, which would scale ``k_s`` by cos²α rather
than cos α: at α = 22.5° the coded ``k_s`` is 8 % higher, the more destabilising side.

Saturation. The gap flux density of a horseshoe is ``B = μ0 N i / (2 g)``; the iron saturates
at ``B_sat``. The largest net force of the pair is reached with one magnet at ``B_sat`` and
the other off:

.. math:: f_{sat} = \frac{B_{sat}^2 A_a \cos α}{μ_0}

(two pole faces, each pulling ``B² A_a / (2 μ0)``; about 40 N/cm² of pole face per
(B_sat/1 T)²). With the bias at half saturation, ``B_0 = B_sat/2`` (the usual choice, which
gives the largest linear range), ``f_sat = k_s g_0``.

References
----------
Schweitzer, G., Maslen, E. H. (eds.) (2009). *Magnetic Bearings: Theory, Design, and
Application to Rotating Machinery*. Springer. Ch. 2 (principle of active magnetic suspension,
differential driving mode, k_i and k_s) and ch. 3 (actuators: force of a horseshoe magnet,
load capacity limited by saturation). The same k_i and k_s expressions are used by ROSS
(``ross.MagneticBearingElement``).
"""

from __future__ import annotations

import math

__all__ = ["MU_0", "bias_flux_density", "current_gain", "force_slope", "magnet_constant", "saturation_force"]

#: Permeability of free space μ0 [H/m] (the pre-2019 exact value; the SI 2019 value differs by 1e-10).
MU_0 = 4e-7 * math.pi


def _check_positive(**values: float) -> None:
    for name, value in values.items():
        if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
            raise ValueError(f"{name} must be a finite number > 0 (got {value!r})")


def _check_angle(pole_angle: float) -> None:
    if not (math.isfinite(pole_angle) and 0.0 <= pole_angle < math.pi / 2):
        raise ValueError(f"pole_angle must lie in [0, π/2) rad (got {pole_angle!r})")


def magnet_constant(turns: float, pole_area: float, pole_angle: float = 0.0) -> float:
    """``k = ¼ μ0 N² A_a cos α`` of one horseshoe magnet [N m²/A²] (f = k i²/g²).

    Parameters
    ----------
    turns : float
        Coil turns N of one horseshoe magnet [-].
    pole_area : float
        Face area A_a of one pole [m²].
    pole_angle : float
        Angle α between a pole's axis and the force axis [rad] (π/8 for an 8-pole stator).
    """
    _check_positive(turns=turns, pole_area=pole_area)
    _check_angle(pole_angle)
    return 0.25 * MU_0 * turns**2 * pole_area * math.cos(pole_angle)


def current_gain(turns: float, pole_area: float, bias_current: float, air_gap: float, pole_angle: float = 0.0) -> float:
    """Force-current factor ``k_i = 4 k i_0 / g_0²`` of the differential pair [N/A].

    ``bias_current`` i_0 [A], ``air_gap`` nominal gap g_0 [m]; the rest as in
    :func:`magnet_constant`.
    """
    _check_positive(bias_current=bias_current, air_gap=air_gap)
    return 4.0 * magnet_constant(turns, pole_area, pole_angle) * bias_current / air_gap**2


def force_slope(turns: float, pole_area: float, bias_current: float, air_gap: float, pole_angle: float = 0.0) -> float:
    """Force-displacement factor ``k_s = 4 k i_0² / g_0³`` [N/m] (open-loop negative stiffness)."""
    _check_positive(bias_current=bias_current, air_gap=air_gap)
    return 4.0 * magnet_constant(turns, pole_area, pole_angle) * bias_current**2 / air_gap**3


def bias_flux_density(turns: float, bias_current: float, air_gap: float) -> float:
    """Gap flux density of the bias current ``B_0 = μ0 N i_0 / (2 g_0)`` [T] (two gaps in series)."""
    _check_positive(turns=turns, bias_current=bias_current, air_gap=air_gap)
    return MU_0 * turns * bias_current / (2.0 * air_gap)


def saturation_force(saturation_flux_density: float, pole_area: float, pole_angle: float = 0.0) -> float:
    """Largest force of one control axis ``f_sat = B_sat² A_a cos α / μ0`` [N].

    ``saturation_flux_density`` B_sat [T]; ``pole_area`` A_a [m²] of one pole face;
    ``pole_angle`` α [rad].
    """
    _check_positive(saturation_flux_density=saturation_flux_density, pole_area=pole_area)
    _check_angle(pole_angle)
    return saturation_flux_density**2 * pole_area * math.cos(pole_angle) / MU_0
