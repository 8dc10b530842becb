"""The quantities the validation cases compare, each computed by flexshaft's public API.

A quantity is a function ``f(design, **arguments) -> ndarray`` of a validated design (or of
plain numbers, ``design`` None) returning SI values in the order of the published ones:
natural frequencies [rad/s], a bearing stiffness [N/m], a residual unbalance [kg m], a
Nusselt number [-]. Each
function names the analysis it calls; none of them holds a published number
(:mod:`flexshaft.validation.cases` does) or a closed form (:mod:`flexshaft.validation.reference`
does), so the comparison is always flexshaft against something else.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from flexshaft.design import Design

if TYPE_CHECKING:
    from flexshaft.analyses.stability import DampingModel
    from flexshaft.thermal.correlations import ForcedMethod

__all__ = [
    "QUANTITIES",
    "actuator_stiffness",
    "balance_tolerance",
    "cylinder_crossflow_nusselt",
    "lateral_damped_frequencies",
    "lateral_frequency_pairs",
    "lateral_natural_frequencies",
    "quantity",
    "synchronous_critical_speeds",
    "torsional_block_frequencies",
    "torsional_natural_frequencies",
    "whirl_frequencies",
    "whirl_onset_speed",
]


def _exact_modes(design: Design, speed_rpm: float, count: int):
    """Damped modes at ``speed_rpm`` on the complete free DOF set (no truncated modal basis:
    the cases are small, and the comparison is then with the finite-element model itself)."""
    from flexshaft.analyses import modes
    from flexshaft.assembly import build_model
    from flexshaft.units import rpm_to_rad_s

    model = build_model(design)
    free = int(model.dofs.free.size)
    return modes(model, rpm_to_rad_s(speed_rpm), n_modes=min(free, 3 * count + 8), basis_size=free)


def _of_kind(result, kind: str, count: int) -> np.ndarray:
    s = result.eigenvalues[result.kind == kind]
    if s.size < count:
        raise ValueError(f"the model has {s.size} {kind} modes below the solved range, {count} are compared")
    return s[:count]


def _lateral(design: Design, speed_rpm: float, count: int, stride: int) -> np.ndarray:
    """Eigenvalues s of every ``stride``-th of the lowest ``count × stride`` lateral modes
    (``stride = 2``: one mode of each degenerate pair of an isotropic rotor at rest)."""
    if stride not in (1, 2):
        raise ValueError(f"stride must be 1 or 2 (got {stride!r})")
    return _of_kind(_exact_modes(design, speed_rpm, count * stride), "lateral", count * stride)[::stride]


def lateral_natural_frequencies(design: Design, *, speed_rpm: float, count: int, stride: int = 1) -> np.ndarray:
    """Undamped natural frequencies |s| [rad/s] of the lowest lateral modes at the spin speed
    ``speed_rpm`` [rpm], in the order of :func:`flexshaft.analyses.modes` (by damped frequency,
    which is the order of |s| for these lightly damped cases): ``count`` of them, every
    ``stride``-th."""
    return np.abs(_lateral(design, speed_rpm, count, stride))


def lateral_damped_frequencies(design: Design, *, speed_rpm: float, count: int, stride: int = 1) -> np.ndarray:
    """Damped natural frequencies Im s [rad/s] of the lowest lateral modes (increasing) at
    ``speed_rpm`` [rpm], ``count`` of them, every ``stride``-th (:func:`flexshaft.analyses.modes`)."""
    return _lateral(design, speed_rpm, count, stride).imag


def lateral_frequency_pairs(design: Design, *, speed_rpm: float, count: int) -> np.ndarray:
    """|s| and Im s [rad/s] of each of the lowest ``count`` degenerate lateral pairs of an
    isotropic rotor at ``speed_rpm`` [rpm], interleaved: (|s_1|, Im s_1, |s_2|, Im s_2, ...)."""
    s = _lateral(design, speed_rpm, count, 2)
    return np.column_stack([np.abs(s), s.imag]).ravel()


def whirl_frequencies(design: Design, *, speed_rpm: float, count: int) -> np.ndarray:
    """Natural frequencies [rad/s] of the lowest ``count`` lateral modes at ``speed_rpm`` [rpm],
    listed backward whirl first, then forward, within each pair (the lowest ``2 count``
    modes taken in pairs), as a closed form of a spinning shaft states them."""
    result = _exact_modes(design, speed_rpm, 2 * count)
    lateral = result.kind == "lateral"
    s, whirl = np.abs(result.eigenvalues[lateral])[: 2 * count], result.whirl[lateral][: 2 * count]
    out = []
    for pair in range(count):
        a, b = 2 * pair, 2 * pair + 1
        by_whirl = dict(zip(whirl[[a, b]], s[[a, b]]))
        if set(by_whirl) != {"backward", "forward"}:
            raise ValueError(f"lateral pair {pair + 1} is not a backward/forward pair (whirl {whirl[[a, b]]})")
        out += [by_whirl["backward"], by_whirl["forward"]]
    return np.asarray(out)


def torsional_natural_frequencies(design: Design, *, count: int, skip_rigid: bool = True) -> np.ndarray:
    """Natural frequencies [rad/s] of the lowest ``count`` torsional modes at rest; with
    ``skip_rigid`` the free rigid-body twist (0 rad/s) is left out first."""
    result = _exact_modes(design, 0.0, count + 1)
    s = np.abs(result.eigenvalues[result.kind == "torsional"])
    if skip_rigid:
        s = s[s > 1e-3 * s.max()]
    if s.size < count:
        raise ValueError(f"the model has {s.size} elastic torsional modes, {count} are compared")
    return s[:count]


def _blocks(design: Design, fields: tuple[str, ...]):
    """The model of ``design`` and its stiffness, mass and gyroscopic matrices restricted to the
    free shaft DOFs of ``fields`` ("v", "w", "beta", "gamma" lateral; "theta" torsion), after
    checking that these DOFs do not couple with the other free DOFs (an isotropic shaft without
    tailboom: bending, torsion and axial motion are independent)."""
    from flexshaft.assembly import build_model

    model = build_model(design)
    dofs = model.dofs
    if dofs.boom_x.size:
        raise ValueError("the quantity takes a shaft without tailboom")
    nodes = np.arange(dofs.n_shaft_nodes)
    wanted = np.unique(np.concatenate([dofs.shaft(nodes, f) for f in fields]))
    free = np.asarray(dofs.free)
    own, other = free[np.isin(free, wanted)], free[~np.isin(free, wanted)]
    blocks = []
    for matrix in (model.K, model.M, model.G):
        if other.size and abs(matrix[np.ix_(own, other)]).max() > 0.0:
            raise ValueError(f"the DOFs {fields} couple with the others: the quantity needs them independent")
        blocks.append(matrix[np.ix_(own, own)].toarray())
    return model, own, blocks


def synchronous_critical_speeds(design: Design, *, harmonic: float, count: int, whirl: str = "both") -> np.ndarray:
    """The lowest ``count`` spin speeds Ω [rad/s] at which a lateral natural frequency of the
    undamped rotor equals ``harmonic`` × Ω, ascending; ``whirl`` "forward" or "backward" keeps
    the modes of that whirl direction only.

    With the motion q = x e^{iωt} and Ω = ω/h, the undamped equations M q'' + Ω G q' + K q = 0
    of the assembled model (:func:`flexshaft.assembly.build_model`) become the linear pencil
    K x = ω² (M − i G/h) x (G skew, so M − iG/h is Hermitian): its real positive eigenvalues are
    the critical speeds Ω = ω/h exactly, without a speed grid (Nelson & McVaugh's "whirl speed"
    problem, their whirl ratio 1/h). Only the lateral DOFs enter (checked to be uncoupled from
    the others). The whirl direction of each solution is read from its shaft orbits
    (:func:`flexshaft.analyses.classify.whirl_ratio`).
    """
    from scipy.linalg import eig

    from flexshaft.analyses.classify import whirl_ratio

    if harmonic <= 0.0 or whirl not in ("both", "forward", "backward"):
        raise ValueError(
            f"harmonic must be > 0 and whirl 'both', 'forward' or 'backward' (got {harmonic!r}, {whirl!r})"
        )
    model, own, (K, M, G) = _blocks(design, ("v", "w", "beta", "gamma"))
    lam, vectors = eig(K, M - 1j * G / harmonic)
    real = np.isfinite(lam) & (np.abs(lam.imag) <= 1e-9 * np.abs(lam)) & (lam.real > 0.0)
    lam, vectors = lam.real[real], vectors[:, real]
    shapes = np.zeros((model.dofs.size, lam.size), dtype=complex)
    shapes[own] = vectors
    ratio = whirl_ratio(model.dofs, shapes)
    keep = np.ones(lam.size, bool) if whirl == "both" else (ratio > 0.0 if whirl == "forward" else ratio < 0.0)
    speeds = np.sort(np.sqrt(lam[keep]) / harmonic)
    if speeds.size < count:
        raise ValueError(
            f"the model has {speeds.size} {whirl} critical speeds for ω = {harmonic:g} Ω, {count} are compared"
        )
    return speeds[:count]


def torsional_block_frequencies(design: Design, *, count: int) -> np.ndarray:
    """The lowest ``count`` torsional natural frequencies [rad/s] of a shaft restrained in twist,
    from the torsional block of the assembled stiffness and mass (K_θθ φ = ω² M_θθ φ), checked to
    be uncoupled from bending and axial motion; for a long shaft whose many bending modes lie
    below its torsional ones."""
    from scipy.linalg import eigh

    _, _, (K, M, _) = _blocks(design, ("theta",))
    lam = eigh(K, M, eigvals_only=True)
    if lam.size < count or lam[0] <= 0.0:
        raise ValueError("the torsional block must be restrained in twist and hold the compared modes")
    return np.sqrt(lam[:count])


def actuator_stiffness(design: Design, *, bearing: str, frequency: float) -> np.ndarray:
    """Real part [N/m] of the collocated force law ``k_i A(iω) C(iω) − k_s`` of the active
    bearing ``bearing`` at the frequency ``frequency`` [rad/s]: its equivalent stiffness, with
    k_i and k_s from the magnet geometry (:class:`flexshaft.assembly.model.Actuator`)."""
    from flexshaft.assembly import build_model

    model = build_model(design)
    actuator = next((a for a in model.actuators if a.name == bearing), None)
    if actuator is None:
        raise ValueError(f"no active bearing {bearing!r} in the design")
    return np.asarray([complex(actuator.law(1j * frequency)).real])


def whirl_onset_speed(
    design: Design,
    *,
    max_speed: float,
    n_speeds: int,
    n_modes: int,
    damping_model: DampingModel,
    reference_frequency: float | None = None,
) -> np.ndarray:
    """Onset speed [rad/s] of the whirl instability from the stability analysis over the speeds
    0..``max_speed`` [rad/s] (``n_speeds`` of them; the onset is refined between them), with the
    internal-damping model ``damping_model`` ("viscous": the thesis's chapter-4 model at
    ``reference_frequency`` [rad/s]; "hysteretic") (:func:`flexshaft.analyses.stability`)."""
    from flexshaft.analyses import stability
    from flexshaft.assembly import build_model

    result = stability(
        build_model(design),
        np.linspace(0.0, max_speed, n_speeds),
        n_modes=n_modes,
        damping_model=damping_model,
        reference_frequency=reference_frequency,
    )
    if result.onset_speed is None:
        raise ValueError(f"no whirl instability below {max_speed:g} rad/s")
    return np.asarray([result.onset_speed])


def balance_tolerance(design: None, *, rotor_mass: float, grade_mm_s: float, speed_rpm: float) -> np.ndarray:
    """Permissible residual unbalance U_per = e_per m [kg m] of a rotor of mass ``rotor_mass``
    [kg] of balance grade ``grade_mm_s`` [mm/s] at ``speed_rpm`` [rpm]
    (:func:`flexshaft.assembly.balance.permissible_unbalance`, ISO 21940-11)."""
    from flexshaft.assembly.balance import permissible_unbalance
    from flexshaft.units import rpm_to_rad_s

    return np.asarray([permissible_unbalance(grade_mm_s, rpm_to_rad_s(speed_rpm), rotor_mass)])


def cylinder_crossflow_nusselt(design: None, *, reynolds: float, prandtl: float, method: ForcedMethod) -> np.ndarray:
    """Mean Nusselt number [-] of a cylinder in cross-flow at Re_D = ``reynolds``, Pr =
    ``prandtl`` by the correlation ``method`` the tailboom's hover convection uses
    (:func:`flexshaft.thermal.correlations.forced_cylinder_nusselt`)."""
    from flexshaft.thermal.correlations import forced_cylinder_nusselt

    return np.asarray([forced_cylinder_nusselt(reynolds, prandtl, method).value])


#: Every quantity a case may name.
QUANTITIES: dict[str, Callable[..., np.ndarray]] = {
    "lateral_natural_frequencies": lateral_natural_frequencies,
    "lateral_damped_frequencies": lateral_damped_frequencies,
    "lateral_frequency_pairs": lateral_frequency_pairs,
    "whirl_frequencies": whirl_frequencies,
    "torsional_natural_frequencies": torsional_natural_frequencies,
    "torsional_block_frequencies": torsional_block_frequencies,
    "synchronous_critical_speeds": synchronous_critical_speeds,
    "actuator_stiffness": actuator_stiffness,
    "balance_tolerance": balance_tolerance,
    "cylinder_crossflow_nusselt": cylinder_crossflow_nusselt,
    "whirl_onset_speed": whirl_onset_speed,
}


def quantity(name: str) -> Callable[..., np.ndarray]:
    """The quantity function called ``name`` (ValueError naming the known ones otherwise)."""
    try:
        return QUANTITIES[name]
    except KeyError:
        raise ValueError(f"unknown validation quantity {name!r}; known: {', '.join(sorted(QUANTITIES))}") from None
