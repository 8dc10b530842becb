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

import numpy as np

from flexshaft.design import Design

__all__ = [
    "QUANTITIES",
    "actuator_stiffness",
    "balance_tolerance",
    "cylinder_crossflow_nusselt",
    "lateral_damped_frequencies",
    "lateral_frequency_pairs",
    "lateral_natural_frequencies",
    "quantity",
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
    ``speed_rpm`` [rpm], in increasing order: ``count`` of them, every ``stride``-th
    (:func:`flexshaft.analyses.modes`)."""
    return np.abs(_lateral(design, speed_rpm, count, stride))


def lateral_damped_frequencies(design: Design, *, speed_rpm: float, count: int, stride: int = 1) -> np.ndarray:
    """Damped natural frequencies Im s [rad/s] of the lowest lateral modes (ordered by |s|) at
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
    damping_model: str,
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
    (:func:`flexshaft.studies.imbalance_samples.balance_grade_eccentricity`, ISO 21940-11)."""
    from flexshaft.studies.imbalance_samples import balance_grade_eccentricity
    from flexshaft.units import rpm_to_rad_s

    return np.asarray([balance_grade_eccentricity(grade_mm_s, rpm_to_rad_s(speed_rpm)) * rotor_mass])


def cylinder_crossflow_nusselt(design: None, *, reynolds: float, prandtl: float, method: str) -> np.ndarray:
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
