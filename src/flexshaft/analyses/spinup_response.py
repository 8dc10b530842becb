"""The steady imbalance response over a spin-up: orbits along the shaft and at the actuators.

:func:`spinup_response` solves the synchronous response to the design's imbalance at every
speed of a scan and keeps, at each speed, the worst load case (the largest shaft orbit over the
nodes): its orbit along the shaft and the relative orbit and carried force at each active
bearing. By default the scan comes from a greedy reduced basis over speed, full banded solves at
a few dozen speeds with an error estimate at every speed
(:func:`~flexshaft.analyses.sweep_projection.imbalance_sweep`: the outputs agree with the
all-full sweep to ``SWEEP_TOLERANCE`` of their peaks); ``projected=False`` solves every speed in
full (one banded solve per speed for all load cases,
:func:`~flexshaft.analyses.response.imbalance_response`), the reference the tests compare with.
"""

from __future__ import annotations

import html
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.banded import SingularSystemError
from flexshaft.analyses.reactions import actuator_response, worst_case_orbits
from flexshaft.analyses.response import imbalance_response
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.units import m_to_mm, rad_s_to_rpm

__all__ = ["SpinupResponse", "spinup_response", "with_speeds"]


@dataclass(frozen=True)
class SpinupResponse:
    """The imbalance response over a speed scan, SI units.

    Attributes
    ----------
    speeds : ndarray
        Spin speeds Ω [rad/s] (n_speeds,), increasing; an assessment's are its resolution's scan
        and each refined lateral critical speed (:func:`with_speeds`).
    response : ndarray
        Complex amplitudes (ndof, n_cases, n_speeds) [m, rad] of every load case.
    orbits : ndarray
        Orbit amplitude (major semi-axis) at every shaft node (n_nodes, n_cases, n_speeds) [m].
    worst_case : ndarray
        The load case with the largest shaft orbit at each speed (n_speeds,).
    envelope : ndarray
        Orbit of the worst case at every shaft node (n_nodes, n_speeds) [m].
    actuator_displacement, actuator_force : mapping of str to ndarray
        Relative orbit [m] and carried force [N] of each active bearing in the worst case
        (n_speeds,).
    error_estimate : ndarray or None
        Estimated error of the checked outputs at each speed relative to their peaks over the
        scan [-] (n_speeds,; 0 where solved in full), when the scan was projected
        (:mod:`flexshaft.analyses.sweep_projection`); None for the all-full sweep.
    basis : ndarray or None
        The projected scan's reduced basis (n_free, r) on the free DOFs, orthonormal, whose span
        holds the responses (it starts the critical speeds' peak models,
        :func:`~flexshaft.analyses.criticals.scan_critical_speeds`); None for the all-full sweep.
    """

    speeds: np.ndarray
    response: np.ndarray
    orbits: np.ndarray
    worst_case: np.ndarray
    envelope: np.ndarray
    actuator_displacement: Mapping[str, np.ndarray]
    actuator_force: Mapping[str, np.ndarray]
    error_estimate: np.ndarray | None = None
    basis: np.ndarray | None = None

    def __repr__(self) -> str:
        """One line: the scan and its peaks (the arrays are in the attributes)."""
        if not self.speeds.size:
            return "SpinupResponse(no speeds)"
        k = int(np.argmax(self.shaft_peak))
        orbit, force = self.actuator_displacement, self.actuator_force
        actuators = ", ".join(
            f"{name} {m_to_mm(np.max(orbit[name])):.3g} mm, {np.max(force[name]):.4g} N" for name in orbit
        )
        return (
            f"SpinupResponse({self.speeds.size} speeds {rad_s_to_rpm(self.speeds[0]):.0f} to "
            f"{rad_s_to_rpm(self.speeds[-1]):.0f} rpm, peak shaft orbit {m_to_mm(self.shaft_peak[k]):.3g} mm at "
            f"{rad_s_to_rpm(self.speeds[k]):.0f} rpm" + (f"; actuators {actuators})" if actuators else ")")
        )

    def _repr_html_(self) -> str:
        return f"<p>{html.escape(repr(self))}</p>"

    @property
    def shaft_peak(self) -> np.ndarray:
        """Largest orbit over the shaft at each speed [m] (n_speeds,)."""
        return self.envelope.max(axis=0)

    def up_to(self, speed: float) -> np.ndarray:
        """Indices of the speeds up to ``speed`` [rad/s] (the spin-up proper when it is the
        operating speed)."""
        return np.flatnonzero(self.speeds <= speed * (1 + 1e-9))


def spinup_response(model: Model, speeds: np.ndarray, projected: bool = True) -> SpinupResponse:
    """The worst-case imbalance response of ``model`` at ``speeds`` [rad/s] (see the module
    docstring); ``projected=False``: a full banded solve at every speed."""
    speeds = np.asarray(speeds, dtype=float)
    estimate = basis = None
    if projected:
        sweep = imbalance_sweep(model, speeds, imbalance_loads(model))
        q, estimate, basis = sweep.response, sweep.error_estimate, sweep.basis
    else:
        q = imbalance_response(model, speeds, imbalance_loads(model))  # (ndof, ncases, nspeeds)
    return _response(model, speeds, np.asarray(q), estimate, basis)


def _response(model: Model, speeds: np.ndarray, q: np.ndarray, estimate, basis) -> SpinupResponse:
    orbits, case = worst_case_orbits(model, q)
    idx = np.arange(speeds.size)
    envelope = orbits[:, case, idx]
    displacement, force = actuator_response(model, q[:, case, idx], speeds)
    return SpinupResponse(speeds, q, orbits, case, envelope, displacement, force, estimate, basis)


def with_speeds(model: Model, response: SpinupResponse, speeds) -> SpinupResponse:
    """``response`` with the full solutions at ``speeds`` [rad/s] added in order (speeds it has
    already, or where the response is singular, skipped; their error estimate 0).

    An assessment adds each lateral critical speed's refined peak
    (:func:`~flexshaft.analyses.criticals.scan_critical_speeds`): a resonance narrower than the
    scan's spacing peaks between its samples, and the actuators' orbit and force, read from the
    samples, would miss it (on the thesis baseline at the screening scan, 4.6 times too small).
    The actuators' peak of a sharp resonance is the shaft's to within a small fraction of the
    bandwidth (the mode dominates both), so the shaft's peak speed samples it.
    """
    extra = np.setdiff1d(np.asarray(speeds, dtype=float), response.speeds)
    extra = extra[np.isfinite(extra) & (extra > 0.0)]
    if not extra.size:
        return response
    loads = imbalance_loads(model)
    try:  # one sweep; speed by speed only when one of them is singular, to skip it
        solved, kept = [np.asarray(imbalance_response(model, extra, loads))], list(extra)
    except SingularSystemError:
        solved, kept = [], []
        for speed in extra:
            try:
                solved.append(np.asarray(imbalance_response(model, [speed], loads)))
            except SingularSystemError:  # an undamped resonance: reported by the critical speeds
                continue
            kept.append(speed)
    if not kept:
        return response
    every = np.concatenate([response.speeds, kept])
    order = np.argsort(every, kind="stable")
    q = np.concatenate([np.asarray(response.response), *solved], axis=2)[:, :, order]
    estimate = response.error_estimate
    if estimate is not None:
        estimate = np.concatenate([estimate, np.zeros(len(kept))])[order]
    return _response(model, every[order], q, estimate, response.basis)
