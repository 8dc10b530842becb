"""Nusselt-number correlations, one named function each, with their validity ranges.

Cross-flow over a cylinder (tailboom in the rotor downwash):

* :func:`hilpert_nusselt` — Hilpert (1933) power law with the constants of Incropera & DeWitt
  Table 7.2 (written here: ``ht`` does not carry it);
* :func:`churchill_bernstein_nusselt` — Churchill & Bernstein (1977), through
  ``ht.conv_external.Nu_cylinder_Churchill_Bernstein`` (named explicitly: ``ht``'s dispatcher
  picks another method by default).

Free convection from a horizontal cylinder (parked): :func:`churchill_chu_nusselt`, through
``ht.conv_free_immersed.Nu_horizontal_cylinder_Churchill_Chu``.

Cylinder rotating in still air (the drive shaft):

* :func:`rotating_cylinder_nusselt_becker` — Nu = 0.133 Re_ω^{2/3} Pr^{1/3}, Re_ω = Ω D²/ν
  (Becker 1963; Kays & Bjorklund 1958 data; quoted by Incropera & DeWitt, ch. 7 problems),
  Re_ω < 4.3e5, 0.7 < Pr < 670;
* :func:`rotating_cylinder_nusselt_kendoush` — Nu = 0.6366 (Re_ω Pr)^{1/2} (Kendoush 1996, the
  thesis's eq. 2.63 reference; constant 2/π from his approximate boundary-layer solution, as
  recalled from the paper's abstract, not re-derived here — treat as unverified; so is its
  Reynolds number: a penetration-theory estimate gives (2/π)(Re Pr)^{1/2} with the surface
  speed's Re = Ω D²/(2ν), which would make h √2 lower than coded, docs/testing.md).

:func:`forced_cylinder_nusselt` and :func:`rotating_cylinder_nusselt` dispatch by name. Every
function returns a :class:`Nusselt` carrying the value and whether the inputs lay inside the
correlation's stated range, so callers can flag an extrapolation instead of failing.

References
----------
Hilpert, R. (1933). Forsch. Geb. Ingenieurwes. 4, 215-224.
Churchill, S. W., Bernstein, M. (1977). J. Heat Transfer 99, 300-306.
Churchill, S. W., Chu, H. H. S. (1975). Int. J. Heat Mass Transfer 18, 1049-1053.
Becker, K. M. (1963). Int. J. Heat Mass Transfer 6, 1053-1062.
Kays, W. M., Bjorklund, I. S. (1958). Trans. ASME 80, 70-77.
Kendoush, A. A. (1996). Int. J. Heat Fluid Flow 17, 439-441.
Incropera, F. P., DeWitt, D. P. (1990/2002). Fundamentals of Heat and Mass Transfer, §7.4, §9.6.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from ht.conv_external import Nu_cylinder_Churchill_Bernstein
from ht.conv_free_immersed import Nu_horizontal_cylinder_Churchill_Chu

__all__ = [
    "Nusselt",
    "HILPERT_TABLE",
    "hilpert_nusselt",
    "churchill_bernstein_nusselt",
    "churchill_chu_nusselt",
    "rotating_cylinder_nusselt_becker",
    "rotating_cylinder_nusselt_kendoush",
    "forced_cylinder_nusselt",
    "rotating_cylinder_nusselt",
    "ForcedMethod",
    "RotatingMethod",
]

ForcedMethod = Literal["hilpert", "churchill_bernstein"]
RotatingMethod = Literal["becker", "kendoush"]

#: Hilpert constants, Incropera & DeWitt Table 7.2: (Re_min, Re_max, C, m); Nu = C Re^m Pr^{1/3}.
HILPERT_TABLE: tuple[tuple[float, float, float, float], ...] = (
    (0.4, 4.0, 0.989, 0.330),
    (4.0, 40.0, 0.911, 0.385),
    (40.0, 4000.0, 0.683, 0.466),
    (4000.0, 40000.0, 0.193, 0.618),
    (40000.0, 400000.0, 0.027, 0.805),
)


@dataclass(frozen=True)
class Nusselt:
    """A Nusselt number [-] and whether the correlation was used inside its range."""

    value: float
    method: str
    in_range: bool
    note: str = ""


def _check(name: str, value: float) -> float:
    value = float(value)
    if not value > 0 or value != value or value == float("inf"):
        raise ValueError(f"{name} must be finite and > 0, got {value!r}")
    return value


def hilpert_nusselt(Re: float, Pr: float) -> Nusselt:
    """Hilpert: Nu_D = C Re_D^m Pr^{1/3} for cross-flow over a circular cylinder.

    Constants from :data:`HILPERT_TABLE` (0.4 ≤ Re ≤ 4e5, Pr ≥ 0.7, properties at the film
    temperature). Outside the table the nearest row is extrapolated and ``in_range`` is False.
    """
    Re, Pr = _check("Re", Re), _check("Pr", Pr)
    lo, hi = HILPERT_TABLE[0][0], HILPERT_TABLE[-1][1]
    row = next((r for r in HILPERT_TABLE if r[0] <= Re <= r[1]), HILPERT_TABLE[0] if Re < lo else HILPERT_TABLE[-1])
    _, _, C, m = row
    in_range = lo <= Re <= hi and Pr >= 0.7
    note = (
        ""
        if in_range
        else f"Re = {Re:.3g}, Pr = {Pr:.3g} outside Hilpert's 0.4 ≤ Re ≤ 4e5, Pr ≥ 0.7; nearest row extrapolated"
    )
    return Nusselt(C * Re**m * Pr ** (1.0 / 3.0), "hilpert", in_range, note)


def churchill_bernstein_nusselt(Re: float, Pr: float) -> Nusselt:
    """Churchill-Bernstein for cross-flow over a cylinder, valid for Re Pr > 0.2 (``ht``)."""
    Re, Pr = _check("Re", Re), _check("Pr", Pr)
    in_range = Re * Pr > 0.2
    note = "" if in_range else f"Re Pr = {Re * Pr:.3g} below the 0.2 limit"
    return Nusselt(float(Nu_cylinder_Churchill_Bernstein(Re, Pr)), "churchill_bernstein", in_range, note)


def churchill_chu_nusselt(Pr: float, Gr: float) -> Nusselt:
    """Churchill-Chu free convection from an isothermal horizontal cylinder (``ht``).

    Valid 1e-5 ≤ Ra_D = Gr Pr ≤ 1e12.
    """
    Pr, Gr = _check("Pr", Pr), _check("Gr", Gr)
    Ra = Gr * Pr
    in_range = 1e-5 <= Ra <= 1e12
    note = "" if in_range else f"Ra = {Ra:.3g} outside 1e-5..1e12"
    return Nusselt(float(Nu_horizontal_cylinder_Churchill_Chu(Pr, Gr)), "churchill_chu", in_range, note)


def rotating_cylinder_nusselt_becker(Re_omega: float, Pr: float) -> Nusselt:
    """Cylinder rotating in still air: Nu_D = 0.133 Re_ω^{2/3} Pr^{1/3}, Re_ω = Ω D²/ν.

    Becker (1963) / Kays & Bjorklund (1958); valid Re_ω < 4.3e5, 0.7 < Pr < 670.
    """
    Re, Pr = _check("Re_omega", Re_omega), _check("Pr", Pr)
    in_range = Re < 4.3e5 and 0.7 <= Pr <= 670
    note = "" if in_range else f"Re_ω = {Re:.3g}, Pr = {Pr:.3g} outside Re_ω < 4.3e5, 0.7 ≤ Pr ≤ 670"
    return Nusselt(0.133 * Re ** (2.0 / 3.0) * Pr ** (1.0 / 3.0), "becker", in_range, note)


def rotating_cylinder_nusselt_kendoush(Re_omega: float, Pr: float) -> Nusselt:
    """Kendoush (1996) approximate laminar solution, Nu_D = 0.6366 (Re_ω Pr)^{1/2}, Re_ω = Ω D²/ν.

    The thesis's eq. 2.63 cites it; its validity range is not stated in the thesis (laminar
    boundary layer assumed, so flagged in range for Re_ω < 4.3e5 like Becker's data).
    """
    Re, Pr = _check("Re_omega", Re_omega), _check("Pr", Pr)
    in_range = Re < 4.3e5
    note = "" if in_range else f"Re_ω = {Re:.3g} beyond the laminar range assumed"
    return Nusselt(0.6366 * (Re * Pr) ** 0.5, "kendoush", in_range, note)


_FORCED = {"hilpert": hilpert_nusselt, "churchill_bernstein": churchill_bernstein_nusselt}
_ROTATING = {"becker": rotating_cylinder_nusselt_becker, "kendoush": rotating_cylinder_nusselt_kendoush}


def forced_cylinder_nusselt(Re: float, Pr: float, method: ForcedMethod = "churchill_bernstein") -> Nusselt:
    """Cross-flow Nusselt number by correlation name (``"hilpert"`` or ``"churchill_bernstein"``)."""
    try:
        return _FORCED[method](Re, Pr)
    except KeyError:
        raise ValueError(f"forced-convection method must be one of {sorted(_FORCED)}, got {method!r}") from None


def rotating_cylinder_nusselt(Re_omega: float, Pr: float, method: RotatingMethod = "becker") -> Nusselt:
    """Rotating-cylinder Nusselt number by correlation name (``"becker"`` or ``"kendoush"``)."""
    try:
        return _ROTATING[method](Re_omega, Pr)
    except KeyError:
        raise ValueError(f"rotating-cylinder method must be one of {sorted(_ROTATING)}, got {method!r}") from None
