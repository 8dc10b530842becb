"""Checks of derived numbers while a model is built; each refuses with a DesignError naming fields.

The schema bounds each number on its own (:mod:`flexshaft.design.quantities`); these checks
cover what only combinations of numbers decide:

* **Support stiffness against the shaft's element stiffness.** A bearing much stiffer than one
  shaft element is rigid to the model but makes ``K`` ill-conditioned, and the lowest
  eigenvalues lose digits as ``ε · k/k_element``. Measured on the baseline (36 elements,
  ``k_element = E I / h³ = 7.9e6 N/m`` with ``h`` = shaft length / ``mesh.shaft_elements``):
  a hanger stiffness of 1e12 N/m (1.3e5 ``k_element``) moves f1 by 4e-7, 1e14 N/m (1.3e7) by
  3e-5 and 1e16 N/m (1.3e9) by 0.8 %, about 3e-12 per ``k_element``. A support is refused
  above :data:`RIGID_RATIO` = 1e8 ``k_element`` (error about 3e-4): a stiffer support is no
  more rigid, it only costs digits. The same holds
  for the rotational directions (``E I / h``), the axial one (``E A / h``) and for an actuator's
  proportional gain ``k_i K_p`` and negative stiffness ``k_s``.
* **Actuator gains from the magnet geometry** (``k_i ∝ N² A i₀ / g²``) must stay within the
  ranges the schema allows for given gains.
* **The controller law** ``k_i A(s) C(s)``: its state-space realization and its value at
  ``s = iω`` over the frequencies of the analyses must be finite (coefficients beyond
  ~1e100 or corner frequencies near zero overflow), and its poles within
  :data:`MAX_CONTROLLER_POLE` of the origin. A faster pole is a constant gain at every
  analysed frequency (its phase lag ω/p is below 1e-6 up to 1e6 rad/s) and costs the
  eigen-analysis its digits: the pole is a state of the first-order problem, whose eigenvalues
  err by about ε|p|. Measured on the baseline with ``C(s) = 1e7/(s/p + 1)`` on both bearings:
  the damped eigenvalues differ from those of ``C = 1e7`` by 4e-12 at p = 1e12 rad/s and
  4e-14 at 1e14 (the physical ω/p), and by 100 % at 1e16 (a ``denominator = [1e-30, 1]``
  gave a spurious divergent root at rest). The law's static gain counts as a support
  stiffness (below): ``denominator = [1, 1e-30]`` gave C(0) = 1e37 N/m.
* **Every assembled matrix is finite.**
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly.controller import Controller
from flexshaft.design import DesignError, Problem
from flexshaft.design.quantities import MAX_CONTROLLER_COEFFICIENT
from flexshaft.elements import magnetic

__all__ = [
    "MAX_CONTROLLER_POLE",
    "RIGID_RATIO",
    "check_actuator_law",
    "check_bearing_stiffness",
    "check_finite_model",
    "check_magnet",
    "element_stiffness",
    "magnet_gains",
]

#: Largest support stiffness in units of one shaft element's stiffness (see the module docstring).
RIGID_RATIO = 1e8
#: Largest |pole| of a feedback law [rad/s] (160 GHz; see the module docstring).
MAX_CONTROLLER_POLE = 1e12
#: Largest |k_i| [N/A] and k_s [N/m] (the schema's ranges for given gains).
_MAX_CURRENT_GAIN = 1e6
_MAX_NEGATIVE_STIFFNESS = 1e12
_DIRECTIONS = ("u", "v", "w", "beta", "gamma")
_SOURCE = "<design>"


def element_stiffness(design, shaft) -> dict[str, float]:
    """Stiffness of one nominal shaft element by direction: axial ``E A / h`` [N/m], lateral
    ``E I / h³`` [N/m] and rotational ``E I / h`` [N m/rad], with the storage modulus of the
    equivalent shaft ``shaft`` (:class:`~flexshaft.assembly.model.ShaftProperties`) and
    ``h`` = shaft length / ``mesh.shaft_elements`` [m]."""
    h = (design.shaft.x_end - design.shaft.x_start) / design.mesh.shaft_elements
    E = float(np.real(shaft.youngs_modulus))
    do, di = shaft.outer_diameter, shaft.inner_diameter
    area = np.pi * (do * do - di * di) / 4.0
    inertia = np.pi * (do**4 - di**4) / 64.0
    lateral, rotational = E * inertia / h**3, E * inertia / h
    return {"u": E * area / h, "v": lateral, "w": lateral, "beta": rotational, "gamma": rotational}


def _too_stiff(path: str, value: float, reference: float, unit: str, what: str) -> Problem:
    return Problem(
        path,
        f"{value:g} {unit} is {value / reference:.3g} times the {what} of one shaft element "
        f"({reference:.3g} {unit}); a support stiffer than {RIGID_RATIO:g} times it is no more rigid "
        f"but costs the eigen-solution its digits (got {value!r}; allowed: at most "
        f"{RIGID_RATIO * reference:.3g} {unit} for this shaft and mesh.shaft_elements = "
        f"{{elements}}, see docs/limits.md)",
    )


def check_bearing_stiffness(design, shaft) -> None:
    """Refuse supports stiffer than :data:`RIGID_RATIO` shaft elements (module docstring)."""
    reference = element_stiffness(design, shaft)
    what = {
        "u": "axial stiffness E A/h",
        "v": "bending stiffness E I/h³",
        "w": "bending stiffness E I/h³",
        "beta": "rotational stiffness E I/h",
        "gamma": "rotational stiffness E I/h",
    }
    problems = []
    for index, bearing in enumerate(design.bearings):
        if bearing.kind == "contact":
            for direction, value in bearing.stiffness.items():
                unit = "N m/rad" if direction in ("beta", "gamma") else "N/m"
                if value > RIGID_RATIO * reference[direction]:
                    problems.append(
                        _too_stiff(
                            f"bearings[{index}].stiffness.{direction}",
                            value,
                            reference[direction],
                            unit,
                            what[direction],
                        )
                    )
        else:
            current_gain, negative_stiffness = _magnet_gains(bearing)
            gains = {"kp": (bearing.kp or 0.0) * current_gain, "ks": negative_stiffness}
            labels = {"kp": " (k_i kp)", "ks": ""}
            law = None if bearing.controller is None else _realizable(bearing)
            if law is not None:  # its static gain is its support stiffness
                with np.errstate(all="ignore"):
                    static = abs(law.proportional_gain) * current_gain
                gains["controller"] = static if np.isfinite(static) else np.inf
                labels["controller"] = " (k_i times the size of the static gain of C(s), either sign)"
            for name, value in gains.items():
                if value > RIGID_RATIO * reference["v"]:
                    problems.append(
                        _too_stiff(f"bearings[{index}].{name}", value, reference["v"], "N/m", what["v"] + labels[name])
                    )
    if problems:
        elements = design.mesh.shaft_elements
        raise DesignError([Problem(p.path, p.message.replace("{elements}", str(elements))) for p in problems], _SOURCE)


def magnet_gains(bearing) -> tuple[float, float]:
    """k_i [N/A] and k_s [N/m] of an active bearing: given (defaults 1 and 0) or from its magnet
    geometry (:mod:`flexshaft.elements.magnetic`): what the model is built with
    (:func:`check_magnet` then holds them to their ranges)."""
    if not getattr(bearing, "uses_magnet_geometry", False):  # (a bearing-like object may lack it)
        return (1.0 if bearing.ki is None else float(bearing.ki)), (0.0 if bearing.ks is None else float(bearing.ks))
    geometry = (bearing.coil_turns, bearing.pole_area, bearing.bias_current, bearing.air_gap, bearing.pole_angle_rad)
    return magnetic.current_gain(*geometry), magnetic.force_slope(*geometry)


def _magnet_gains(bearing) -> tuple[float, float]:
    """:func:`magnet_gains` for the support check; geometry gains outside the ranges
    :func:`check_magnet` allows are left to it (it names the geometry): 1 and 0 here."""
    try:
        k_i, k_s = magnet_gains(bearing)
    except (ValueError, OverflowError, TypeError):
        return 1.0, 0.0
    if not (
        np.isfinite(k_i)
        and 0.0 < k_i <= _MAX_CURRENT_GAIN
        and np.isfinite(k_s)
        and 0.0 <= k_s <= _MAX_NEGATIVE_STIFFNESS
    ):
        return 1.0, 0.0
    return float(k_i), float(k_s)


def _realizable(bearing) -> Controller | None:
    """The bearing's controller C(s), or None when its realization is refused anyway by
    :func:`check_actuator_law` (which then gives the more basic reason)."""
    law = Controller(*(tuple(float(c) for c in part) for part in bearing.transfer_function()))
    with np.errstate(all="ignore"):
        try:
            parts = law.realization()
        except (ValueError, np.linalg.LinAlgError, ZeroDivisionError):
            return None
        largest = max((float(np.max(np.abs(part), initial=0.0)) for part in parts), default=0.0)
    return law if np.isfinite(largest) and largest <= MAX_CONTROLLER_COEFFICIENT else None


def check_magnet(design, index: int, current_gain: float, negative_stiffness: float) -> None:
    """Refuse magnet gains outside the ranges allowed for given gains (k_i in (0, 1e6] N/A,
    k_s in [0, 1e12] N/m), naming the geometry fields they come from."""
    bearing = design.bearings[index]
    fields = "coil_turns, pole_area, bias_current, air_gap" if bearing.uses_magnet_geometry else None
    problems = []
    for name, value, low_ok, high in (
        ("ki", current_gain, lambda v: v > 0, _MAX_CURRENT_GAIN),
        ("ks", negative_stiffness, lambda v: v >= 0, _MAX_NEGATIVE_STIFFNESS),
    ):
        if not (np.isfinite(value) and low_ok(value) and value <= high):
            unit = "N/A" if name == "ki" else "N/m"
            if fields is None:
                path, origin = f"bearings[{index}].{name}", f"got {value!r}"
            else:
                path, origin = f"bearings[{index}].coil_turns", f"{name} = {value:.6g} {unit} from {fields}"
            allowed = "in (0, 1e6] N/A" if name == "ki" else "in [0, 1e12] N/m"
            problems.append(
                Problem(
                    path, f"gives the magnet gain {name} = {value:.6g} {unit} ({origin}; allowed: {name} {allowed})"
                )
            )
    if problems:
        raise DesignError(problems, _SOURCE)


def check_actuator_law(design, index: int, actuator, speed: float) -> None:
    """Refuse a feedback law ``k_i A(s) C(s)`` whose realization or frequency values overflow.

    The law is evaluated at ``s = iω`` for ω from 1 rad/s to 100 × the largest of the operating
    speed and 1e3 rad/s (and at ω = 0 unless it integrates); the realization's entries must
    stay below :data:`~flexshaft.design.quantities.MAX_CONTROLLER_COEFFICIENT` and its poles
    within :data:`MAX_CONTROLLER_POLE`.
    """
    bearing = design.bearings[index]
    reason = _law_problem(actuator, speed)
    if reason is not None:
        path = f"bearings[{index}].controller" if bearing.controller is not None else f"bearings[{index}]"
        fields = (
            "controller coefficients" if bearing.controller is not None else "kp, kd, integral_gain, derivative_cutoff"
        )
        raise DesignError(
            [
                Problem(
                    path,
                    f"the feedback law k_i A(s) C(s) {reason} (allowed: a law finite over the "
                    f"analysed frequencies, with realization entries below "
                    f"{MAX_CONTROLLER_COEFFICIENT:g} and poles within {MAX_CONTROLLER_POLE:g} rad/s: "
                    f"rescale the {fields}, amplifier_bandwidth or ki)",
                )
            ],
            _SOURCE,
        )


#: Verdicts of :func:`_law_problem` by law and speed: a sweep builds the same bearings again
#: and again (a layup or wall study: 100 models), and the check costs 0.6 ms a bearing.
_LAW_PROBLEMS: dict = {}


def _law_problem(actuator, speed: float) -> str | None:
    """Why the actuator's law fails :func:`check_actuator_law` at ``speed``, or None."""
    key = (
        actuator.controller,
        actuator.amplifier_bandwidth,
        actuator.current_gain,
        actuator.negative_stiffness,
        actuator.collocated,
        float(speed),
    )
    try:
        hash(key)
    except TypeError:  # a controller built by hand with array coefficients: not remembered
        return _check_laws(actuator, speed)
    if key not in _LAW_PROBLEMS:
        if len(_LAW_PROBLEMS) > 1024:
            _LAW_PROBLEMS.clear()
        _LAW_PROBLEMS[key] = _check_laws(actuator, speed)
    return _LAW_PROBLEMS[key]


def _check_laws(actuator, speed: float) -> str | None:
    laws = [actuator.feedback, actuator.collocated_law]
    omegas = np.geomspace(1.0, 100.0 * max(speed, 1e3), 7)
    reason = None
    with np.errstate(all="ignore"):
        for law in laws:
            try:
                parts = law.realization()
            except (ValueError, np.linalg.LinAlgError, ZeroDivisionError) as error:
                reason = f"has no state-space realization ({error})"
                break
            largest = max((float(np.max(np.abs(part), initial=0.0)) for part in parts), default=0.0)
            if not np.isfinite(largest) or largest > MAX_CONTROLLER_COEFFICIENT:
                reason = f"has a state-space realization with entries up to {largest:.3g}"
                break
            poles = np.linalg.eigvals(parts[0]) if parts[0].size else np.zeros(0)
            if poles.size and np.max(np.abs(poles)) > MAX_CONTROLLER_POLE:
                fastest = poles[np.argmax(np.abs(poles))]
                reason = (
                    f"has a pole at s = {fastest:.3g} rad/s, beyond {MAX_CONTROLLER_POLE:g} rad/s: a pole that "
                    "fast is a constant gain at every analysed frequency and costs the eigen-analysis its "
                    "digits (drop the near-zero leading coefficients of the denominator)"
                )
                break
            values = np.concatenate([law(1j * omegas), law.derivative(1j * omegas)])
            if not law.integrates:
                values = np.append(values, law(0.0))
            if not np.all(np.isfinite(values)):
                reason = f"is not finite at some frequency s = iω, 1 to {omegas[-1]:.3g} rad/s"
                break
    return reason


def check_finite_model(model) -> None:
    """Refuse a model with a non-finite matrix entry (a last guard behind the bounds above)."""
    matrices = {
        "mass": model.M,
        "stiffness": model.K,
        "damping": model.C,
        "gyroscopic": model.G,
        "shaft loss stiffness": model.shaft_loss_stiffness,
        "boom loss stiffness": model.boom_loss_stiffness,
    }
    bad = [name for name, matrix in matrices.items() if matrix is not None and not np.all(np.isfinite(matrix.data))]
    if bad:
        raise DesignError(
            [
                Problem(
                    "design",
                    f"the assembled {', '.join(bad)} matrix has non-finite entries: some "
                    "combination of the design's numbers overflows double precision "
                    "(see docs/limits.md)",
                )
            ],
            _SOURCE,
        )
