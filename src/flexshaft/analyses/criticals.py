"""Lateral critical speeds: the peaks of the unbalance response and their amplification factors.

:func:`lateral_critical_speeds` scans the unbalance response up to a top speed (the
:class:`~flexshaft.resolution.Resolution`'s ``scan_top`` × the operating speed, beyond the largest
margin API 684 can ask above the operating speed, 26 %) and refines each peak at the shaft
station where it is largest until its half-power bandwidth is resolved
(:func:`flexshaft.analyses.separation.resolve_peak`). :func:`scan_critical_speeds` reuses a scan
already computed (the spin-up response of an assessment) and says why there is none when the
response cannot be scanned; :func:`label_critical_speeds` names the Campbell mode of each peak.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from flexshaft.analyses.banded import SingularSystemError
from flexshaft.analyses.campbell import Campbell
from flexshaft.analyses.modal import modes
from flexshaft.analyses.peak_projection import PeakBasis, ProjectedOrbit
from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.results import dataframe, html_table
from flexshaft.analyses.separation import resolve_peak, response_peaks
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.assembly.model import Model
from flexshaft.resolution import REPORT
from flexshaft.units import rad_s_to_rpm

__all__ = [
    "CriticalSpeeds",
    "LateralCritical",
    "label_critical_speeds",
    "lateral_critical_speeds",
    "scan_critical_speeds",
]

#: Modes solved at a peak to tell an undamped resonance from an unresolved one.
_UNDAMPED_CHECK_MODES = 12
#: Largest distance [fraction of the speed] between a peak and the Campbell critical speed that labels it.
_LABEL_TOLERANCE = 0.03


@dataclass(frozen=True)
class LateralCritical:
    """A lateral critical speed [rad/s] with its amplification factor [-] and where it peaks.

    ``location`` names the shaft station of the peak response [m] and, when known, the mode,
    the AF method, the refined peak orbit [m] and a detail.
    """

    speed: float
    amplification_factor: float
    location: Mapping[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class CriticalSpeeds:
    """The lateral critical speeds of a scan of the unbalance response.

    Attributes
    ----------
    criticals : tuple of LateralCritical or None
        In order of speed; None when the response could not be scanned (``note`` says why).
    search_top : float
        Highest speed searched [rad/s].
    note : str
        Why there are no criticals (empty otherwise).
    """

    criticals: tuple[LateralCritical, ...] | None
    search_top: float
    note: str = ""

    def to_dataframe(self):
        """One row per critical speed: speed [rpm] and [rad/s], amplification factor, shaft
        station of the peak [m], Campbell mode and detail (pandas, imported here; xarray brings
        it); empty when there are none or the scan failed (see :attr:`note`)."""
        found = self.criticals or ()
        return dataframe(
            {
                "speed_rpm": [rad_s_to_rpm(c.speed) for c in found],
                "speed_rad_s": [c.speed for c in found],
                "amplification_factor": [c.amplification_factor for c in found],
                "station_m": [c.location.get("station") for c in found],
                "mode": [c.location.get("mode", "") for c in found],
                "detail": [c.location.get("detail", "") for c in found],
            }
        )

    def _repr_html_(self) -> str:
        found = self.criticals or ()
        rows = [
            [rad_s_to_rpm(c.speed), c.amplification_factor, c.location.get("station"), c.location.get("mode", "")]
            for c in found
        ]
        title = f"{len(found)} lateral critical speeds up to {rad_s_to_rpm(self.search_top):.0f} rpm"
        return html_table(("speed [rpm]", "AF [-]", "x [m]", "mode"), rows, title=title, caption=self.note)

    def labelled(self, campbell: Campbell | None) -> CriticalSpeeds:
        """The same criticals, each named by its Campbell mode (:func:`label_critical_speeds`)."""
        if self.criticals is None:
            return self
        return CriticalSpeeds(label_critical_speeds(self.criticals, campbell), self.search_top, self.note)


def _shaft_orbits(model: Model, q: np.ndarray) -> np.ndarray:
    """Orbit amplitude [m] at every shaft node: (nodes, cases, speeds) from (ndof, cases, speeds)."""
    dm = model.dofs
    n = np.arange(dm.n_shaft_nodes)
    return orbit_amplitude(q[dm.shaft(n, "v")], q[dm.shaft(n, "w")])


def lateral_critical_speeds(
    model: Model,
    campbell: Campbell | None = None,
    top: float = REPORT.scan_top,
    n_points: int = REPORT.spinup_speeds,
    scan=None,
    projected: bool = True,
    responses: np.ndarray | None = None,
    basis: np.ndarray | None = None,
) -> tuple[LateralCritical, ...]:
    """Peaks of the unbalance response with their amplification factors.

    Parameters
    ----------
    model : Model
        Assembled model (its design's imbalance placement and eccentricity).
    campbell : Campbell, optional
        When given, each peak is labelled with the tracked mode whose 1× critical speed is
        nearest (within 3 %).
    top : float
        Highest speed scanned, as a multiple of the operating speed.
    n_points : int
        Samples of the initial scan (``REPORT.scan_bottom`` to ``top`` of the operating speed).
    scan : tuple of ndarray, optional
        ``(speeds, orbits)`` of a scan already computed (orbits (nodes, cases, speeds) [m], e.g.
        an assessment's spin-up response), used instead of a new one.
    projected : bool
        Refine each peak on a small projected model of the response around it, checked by full
        solves (:mod:`flexshaft.analyses.peak_projection`); False: a full solve at every
        refinement speed (the reference the tests compare with).
    responses : ndarray, optional
        The scan's complex responses (ndof, cases, speeds) [m, rad] with ``scan``: each peak's
        projected model starts from those at the three scan speeds around it instead of solving
        them again (from a projected scan, :mod:`flexshaft.analyses.sweep_projection`, they
        agree with the full solutions to ~1e-11; the model is checked by full solves all the
        same).
    basis : ndarray, optional
        The scan's reduced basis (n_free, r) with ``scan`` (a projected scan's
        :attr:`~flexshaft.analyses.spinup_response.SpinupResponse.basis`): every peak's projected
        model starts from it instead, orthonormalised and projected once for all the peaks
        (:class:`~flexshaft.analyses.peak_projection.PeakBasis`). It spans the scan's responses to
        the sweep's tolerance, so a round's check by full solves usually passes at once, where
        three responses needed an enrichment first.

    Returns
    -------
    tuple of LateralCritical
        In order of speed; AF from the half-power bandwidth of the orbit at the shaft station
        where the peak is largest, for the worst imbalance case there.
    """
    loads = imbalance_loads(model)
    if scan is None:
        speeds = np.linspace(REPORT.scan_bottom, top, n_points) * model.speed
        orbits = _shaft_orbits(model, imbalance_response(model, speeds, loads))
    else:
        speeds, orbits = scan
    envelope = orbits.max(axis=(0, 1))
    start = PeakBasis(model, basis) if projected and basis is not None else None
    out: list[LateralCritical] = []
    for rough in response_peaks(speeds, envelope):
        k = int(np.argmin(np.abs(speeds - rough.speed)))
        node, case = np.unravel_index(int(np.argmax(orbits[:, :, k])), orbits.shape[:2])

        def orbit_at(new_speeds, node=node, case=case):
            q = imbalance_response(model, new_speeds, loads[:, case : case + 1])
            return _shaft_orbits(model, q)[node, 0]

        response: Callable[[np.ndarray], np.ndarray] = orbit_at
        rows = (int(model.dofs.shaft(int(node), "v")), int(model.dofs.shaft(int(node), "w")))
        if projected and np.all(np.isin(rows, model.dofs.free)):
            # the refinement on a projected model of the peak, checked by full solves
            near = slice(max(k - 1, 0), k + 2)
            seed: PeakBasis | np.ndarray | None = start  # the scan's basis, else its responses near the peak
            if seed is None and responses is not None:
                seed = responses[model.dofs.free, case, near]
            response = ProjectedOrbit(model, loads[:, case], rows, speeds[near], basis=seed)

        station = float(model.dofs.shaft_x[node])
        try:
            peak = resolve_peak(response, speeds, orbits[node, case], near=rough.speed)
        except SingularSystemError:  # an undamped resonance: the response is infinite at the peak
            out.append(
                LateralCritical(
                    rough.speed,
                    float("inf"),
                    {"station": station, "detail": "undamped resonance: the response is singular at the peak"},
                )
            )
            continue
        if peak is None or any(abs(peak.speed - c.speed) <= 1e-6 * peak.speed for c in out):
            continue
        location: dict[str, Any] = {"station": station, "af_method": peak.method, "peak_orbit": float(peak.amplitude)}
        amplification = peak.amplification_factor
        if not peak.resolved:
            if _undamped_at(model, peak.speed):
                amplification = float("inf")
                location["detail"] = (
                    "undamped resonance: the mode at the peak has no damping, the response is unbounded"
                )
            else:
                location["detail"] = "half-power bandwidth not resolved: AF is a lower bound"
        out.append(LateralCritical(peak.speed, amplification, location))
    return label_critical_speeds(tuple(sorted(out, key=lambda c: c.speed)), campbell)


def label_critical_speeds(criticals, campbell: Campbell | None) -> tuple[LateralCritical, ...]:
    """The resolved peaks of :func:`lateral_critical_speeds` labelled with the tracked mode of
    ``campbell`` whose 1× critical speed is within 3 % (an assessment computes the peaks and
    the Campbell diagram in parallel and labels them afterwards)."""
    out = []
    for c in criticals:
        mode = _campbell_label(campbell, c.speed) if "af_method" in c.location else ""
        out.append(LateralCritical(c.speed, c.amplification_factor, {**c.location, "mode": mode}) if mode else c)
    return tuple(out)


def scan_critical_speeds(
    model: Model,
    speeds: np.ndarray,
    orbits: np.ndarray | None,
    top: float = REPORT.scan_top,
    responses: np.ndarray | None = None,
    basis: np.ndarray | None = None,
) -> CriticalSpeeds:
    """The lateral critical speeds up to ``top`` × the operating speed, from a spin-up scan
    (speeds [rad/s], orbits (nodes, cases, speeds) [m]) when it reaches that high, else from a
    new scan; none, with a note, when the unbalance response is singular or the operating
    speed is zero. ``responses``: the scan's complex responses (ndof, cases, speeds) [m, rad],
    which start each peak's projected model instead of three full solves; ``basis``: the scan's
    reduced basis, which starts them instead (:func:`lateral_critical_speeds`)."""
    speed = float(model.speed)
    search_top = top * speed
    if speed <= 0.0:
        return CriticalSpeeds(None, search_top, "the operating speed is zero")
    scan = None
    if orbits is not None and speeds[-1] >= search_top * (1 - 1e-9):
        scan = (np.asarray(speeds), np.asarray(orbits))
    try:
        responses = None if scan is None or responses is None else np.asarray(responses)
        basis = None if scan is None else basis
        found = lateral_critical_speeds(model, top=top, scan=scan, responses=responses, basis=basis)
        return CriticalSpeeds(found, search_top)
    except SingularSystemError as exc:
        return CriticalSpeeds(None, search_top, f"the unbalance response could not be scanned: {exc}")


def _undamped_at(model: Model, speed: float) -> bool:
    """True when the synchronous mode at ``speed`` [rad/s] has no damping (|ζ| < 1e-9): its
    peak is infinite however finely the speed is sampled."""
    m = modes(model, speed, n_modes=_UNDAMPED_CHECK_MODES)
    lateral = m.kind == "lateral"
    if not np.any(lateral):
        return False
    k = int(np.argmin(np.where(lateral, np.abs(m.eigenvalues.imag - speed), np.inf)))
    return bool(abs(m.damping_ratios[k]) < 1e-9)


def _campbell_label(campbell: Campbell | None, speed: float) -> str:
    if campbell is None or not campbell.critical_speeds:
        return ""
    nearest = min(campbell.critical_speeds, key=lambda c: abs(c.speed - speed))
    if abs(nearest.speed - speed) > _LABEL_TOLERANCE * speed:
        return ""
    return f"{nearest.mode + 1} ({nearest.whirl})"
