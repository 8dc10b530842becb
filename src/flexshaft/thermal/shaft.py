"""Finite-difference temperature of the shaft along x (thesis §2.8.2, eqs. 2.61-2.65).

Vertex-centred finite volumes on the shaft nodes: node i owns half of each adjacent element.
Per node, with wall area A_w = π(D_o² − D_i²)/4 (eq. 2.62), perimeter π D_o (eq. 2.64),
element lengths L_e and element heat P_e::

    Σ_neighbours k A_w (T_j − T_i)/L_e − h π D_o ℓ_i (T_i − T_∞) + ½ Σ_adjacent P_e = 0,
    ℓ_i = ½ Σ_adjacent L_e,

i.e. ``K_THR T = q + K_conv T_∞`` (eq. 2.65), with both end nodes held at the boom temperature
(Dirichlet). On a uniform mesh this is the standard three-point scheme, second-order accurate
(tested against the cosh fin solution). The heat that leaves through the ends is the residual
of the end nodes' balance, so generated = convected + end flows holds to round-off.

Convection from the rotating tube in still air inside the boom fairing:
``h = Nu k_air / D_o`` with Re_ω = Ω D_o² / ν (Becker / Kays & Bjorklund by default, Kendoush as
the thesis's eq. 2.63), air at the boom temperature. Conduction along the wall uses the axial
conductivity of the laminate, Σ t_k (k_L cos² α_k + k_T sin² α_k) / t.

The conductivity, wall area, perimeter and h may differ per element (a segmented shaft: each
segment's tube); a node then owns half of each adjacent element's conductance and surface. A
coupling joint is one node: the coupling is assumed to conduct like the tube with no contact
resistance (assumed: its flanges are metal and short).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_banded

from flexshaft.thermal.air import air_properties
from flexshaft.thermal.correlations import Nusselt, RotatingMethod, rotating_cylinder_nusselt

__all__ = [
    "FIBRE_CONDUCTIVITY",
    "TRANSVERSE_CONDUCTIVITY",
    "laminate_axial_conductivity",
    "rotating_shaft_convection",
    "ShaftTemperature",
    "solve_shaft_temperature",
]

#: Assumed ply conductivities [W/(m K)]: carbon fibre ~9 W/(m K) × V_f 0.6 plus the matrix along
#: the fibres; polyurethane matrix ~0.2 W/(m K) lifted to ~0.5 across the fibres.
FIBRE_CONDUCTIVITY = 5.0
TRANSVERSE_CONDUCTIVITY = 0.5


def laminate_axial_conductivity(
    laminate, k_L: float = FIBRE_CONDUCTIVITY, k_T: float = TRANSVERSE_CONDUCTIVITY
) -> float:
    """Axial in-plane conductivity of the wall [W/(m K)]: plies conduct in parallel along x,
    each with k_xx = k_L cos²α + k_T sin²α; ``None`` laminate (isotropic) is not handled here."""
    a = np.asarray(laminate.angles)
    t = np.asarray(laminate.thicknesses)
    return float(np.sum(t * (k_L * np.cos(a) ** 2 + k_T * np.sin(a) ** 2)) / t.sum())


def rotating_shaft_convection(
    diameter: float, speed: float, air_temperature: float, method: RotatingMethod = "becker", pressure: float = 101325.0
) -> tuple[float, Nusselt]:
    """Convection coefficient h [W/(m^2 K)] of a tube of ``diameter`` [m] spinning at ``speed``
    [rad/s] in still air at ``air_temperature`` [K]; returns (h, Nusselt)."""
    air = air_properties(air_temperature, pressure)
    Re = max(abs(speed), 1e-12) * diameter**2 / air.kinematic_viscosity
    nu = rotating_cylinder_nusselt(Re, air.prandtl, method)
    return nu.value * air.conductivity / diameter, nu


@dataclass(frozen=True)
class ShaftTemperature:
    """Steady shaft temperature and its energy balance.

    Attributes
    ----------
    x : ndarray
        Node stations (n,) [m].
    temperature : ndarray
        Node temperatures (n,) [K].
    element_power : ndarray
        Heat generated per element (n − 1,) [W].
    air_temperature, end_temperatures : float, (float, float)
        T_∞ [K] and the Dirichlet end temperatures [K].
    heat_transfer_coefficient : float
        h [W/(m^2 K)] (the convecting-surface-weighted mean when it differs per element).
    convected : ndarray
        Heat convected from each node's control volume (n,) [W].
    end_flows : (float, float)
        Heat leaving through the forward and aft ends into the boom [W].
    element_heat_transfer : ndarray or None
        h of each element (n − 1,) [W/(m^2 K)].
    """

    x: np.ndarray
    temperature: np.ndarray
    element_power: np.ndarray
    air_temperature: float
    end_temperatures: tuple[float, float]
    heat_transfer_coefficient: float
    convected: np.ndarray
    end_flows: tuple[float, float]
    element_heat_transfer: np.ndarray | None = None

    @property
    def element_temperature(self) -> np.ndarray:
        """Mean of each element's end-node temperatures (n − 1,) [K]."""
        return 0.5 * (self.temperature[:-1] + self.temperature[1:])

    @property
    def peak_rise(self) -> float:
        """max T − T_∞ [K]."""
        return float(self.temperature.max() - self.air_temperature)

    @property
    def generated(self) -> float:
        """Total heat generated [W]."""
        return float(self.element_power.sum())

    @property
    def balance_error(self) -> float:
        """(generated − convected − end flows) / generated [-] (0 to round-off)."""
        out = self.convected.sum() + sum(self.end_flows)
        return float((self.generated - out) / self.generated) if self.generated else float(out)


def solve_shaft_temperature(
    x,
    element_power,
    conductivity: float | np.ndarray,
    wall_area: float | np.ndarray,
    perimeter: float | np.ndarray,
    heat_transfer_coefficient: float | np.ndarray,
    air_temperature: float,
    end_temperatures=None,
) -> ShaftTemperature:
    """Solve ``K_THR T = q + K_conv T_∞`` with Dirichlet ends.

    Parameters
    ----------
    x : array_like
        Node stations (n ≥ 3,) [m], increasing.
    element_power : array_like
        Heat generated per element (n − 1,) [W].
    conductivity : float or array_like
        Axial wall conductivity k [W/(m K)], one value or one per element (n − 1,).
    wall_area : float or array_like
        Conducting area π(D_o² − D_i²)/4 [m^2], one value or one per element.
    perimeter : float or array_like
        Convecting perimeter π D_o [m], one value or one per element.
    heat_transfer_coefficient : float or array_like
        h [W/(m^2 K)], one value or one per element.
    air_temperature : float
        T_∞ [K].
    end_temperatures : (float, float) or None
        Forward and aft end temperatures [K]; T_∞ when None.
    """
    x = np.asarray(x, dtype=float)
    P = np.asarray(element_power, dtype=float)
    L = np.diff(x)
    if x.ndim != 1 or x.size < 3 or np.any(L <= 0):
        raise ValueError("x must be at least 3 increasing stations [m]")
    if P.shape != L.shape:
        raise ValueError(f"element_power must have one value per element ({L.size}), got shape {P.shape}")
    per_element = {}
    for name, v, low in (
        ("conductivity", conductivity, 0.0),
        ("wall_area", wall_area, 0.0),
        ("perimeter", perimeter, 0.0),
        ("heat_transfer_coefficient", heat_transfer_coefficient, None),
    ):
        try:
            values = np.broadcast_to(np.asarray(v, dtype=float), L.shape)
        except ValueError:
            raise ValueError(
                f"{name} must be one value or one per element ({L.size}), got shape {np.shape(v)}"
            ) from None
        if not (np.all(np.isfinite(values)) and (np.all(values > low) if low is not None else np.all(values >= 0))):
            raise ValueError(f"{name} must be finite and {'> 0' if low is not None else '>= 0'}, got {v!r}")
        per_element[name] = values
    Ta, Tb = (air_temperature, air_temperature) if end_temperatures is None else map(float, end_temperatures)

    n = x.size
    cond = per_element["conductivity"] * per_element["wall_area"] / L  # (n−1,) [W/K]
    surface = per_element["heat_transfer_coefficient"] * per_element["perimeter"] * L  # h P L per element [W/K]
    conv = np.zeros(n)  # (n,) [W/K]: half of each adjacent element's surface
    conv[:-1] += surface / 2
    conv[1:] += surface / 2
    h, area = per_element["heat_transfer_coefficient"], per_element["perimeter"] * L
    h_mean = float(h[0]) if np.all(h == h[0]) else float(np.sum(h * area) / np.sum(area))
    src = np.zeros(n)
    src[:-1] += P / 2
    src[1:] += P / 2

    # interior unknowns 1..n−2; tridiagonal in banded form
    m = n - 2
    diag = cond[:-1] + cond[1:] + conv[1:-1]
    ab = np.zeros((3, m))
    ab[0, 1:] = -cond[1:-1]
    ab[1] = diag
    ab[2, :-1] = -cond[1:-1]
    rhs = src[1:-1] + conv[1:-1] * air_temperature
    rhs[0] += cond[0] * Ta
    rhs[-1] += cond[-1] * Tb
    T = np.empty(n)
    T[0], T[-1] = Ta, Tb
    T[1:-1] = solve_banded((1, 1), ab, rhs)

    convected = conv * (T - air_temperature)
    # end flows: what each end node's control volume receives and does not convect
    q0 = src[0] + cond[0] * (T[1] - T[0]) - convected[0]
    qn = src[-1] + cond[-1] * (T[-2] - T[-1]) - convected[-1]
    return ShaftTemperature(
        x,
        T,
        P,
        float(air_temperature),
        (Ta, Tb),
        h_mean,
        convected,
        (float(q0), float(qn)),
        np.array(per_element["heat_transfer_coefficient"]),
    )
