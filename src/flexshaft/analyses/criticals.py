"""Lateral critical speeds: the peaks of the unbalance response and their amplification factors.

:func:`lateral_critical_speeds` scans the unbalance response up to a top speed (the
:class:`~flexshaft.resolution.Resolution`'s ``scan_top`` × the operating speed, beyond the largest
margin API 684 can ask above the operating speed, 26 %) and refines each peak at the shaft
station where it is largest until its half-power bandwidth is resolved
(:func:`flexshaft.analyses.separation.resolve_peak`). A resonance narrower than the scan's
spacing can fall between two samples, or share one bump with a broader neighbour whose
refinement follows the broader one: the roots of the synchronous problem on the scan's projected
model (:mod:`flexshaft.analyses.synchronous_roots`) say where each resonance is and how wide; one
whose band spans fewer than four of the scan's intervals, that no peak found holds and around
which the projected envelope has a maximum of its own is refined from samples across its band
(:func:`_hidden_resonances`) and kept when full solves show it a maximum of the envelope, so that
the critical speeds and the spin-up's largest orbit do not depend on where the scan's samples
fall (tests/test_hidden_resonances.py). :func:`scan_critical_speeds` reuses a scan
already computed (the spin-up response of an assessment) and says why there is none when the
response cannot be scanned; :func:`label_critical_speeds` names the Campbell mode of each peak.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from flexshaft.analyses.banded import SingularSystemError, solver_for
from flexshaft.analyses.campbell import Campbell
from flexshaft.analyses.local_projection import golden_maximum
from flexshaft.analyses.modal import modes
from flexshaft.analyses.peak_projection import PeakBasis, ProjectedOrbit
from flexshaft.analyses.response import imbalance_response, orbit_amplitude
from flexshaft.analyses.results import dataframe, html_table
from flexshaft.analyses.separation import resolve_peak, response_peaks
from flexshaft.analyses.synchronous_roots import synchronous_roots
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
#: Directions of the scan's responses kept for the synchronous roots: a mode present below this
#: fraction of the largest response is not one the scan's imbalance excites.
_SEED_RANK = 1e-8
_UNRESOLVED = "half-power bandwidth not resolved: AF is a lower bound"
#: Speeds of a scan whose responses span the projected model of the synchronous roots when the
#: scan has no reduced basis (an all-full scan).
_SEED_SPEEDS = 64
#: A root whose half-power band spans more scan intervals than this is left to the scan: its peak
#: shows as a local maximum of the samples (the refinement then resolves it).
_SHOWN_SAMPLES = 4.0
#: Where the projected orbit is evaluated around a root, in |Im Ω| from Re Ω (its half-power
#: points at ±1), an eighth of it apart: a maximum of its own lies inside, and one on a taller
#: neighbour's rising flank, whose dip after it is a few tenths of |Im Ω| wide (0.3-0.5 |Im Ω|
#: for two Jeffcott resonances 1.8-2 |Im Ω| apart), still shows as a sample above its
#: neighbours (half-|Im Ω| steps stepped over it: hunt h94b).
_AROUND_ROOT = np.linspace(-2.0, 2.0, 33)
#: Where a seed's refinement starts around its maximum, in powers of two near |Im Ω| (the
#: lattice of :func:`_seed_samples`): across the band, and an eighth to either side so that the
#: samples hold the maximum the projected orbit showed, however shallow its dip beside a taller
#: neighbour (the scan's samples on that neighbour's flank can be above the maximum itself).
_SEED_STEPS = np.array([-4.0, -2.0, -1.0, -0.125, 0.0, 0.125, 1.0, 2.0, 4.0])


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


def _orbit_function(model, loads, node, case, speeds, k, projected, start, responses) -> Callable:
    """``response(speeds) -> orbit`` of shaft node ``node`` under load case ``case``: a projected
    model of the peak near scan sample ``k`` checked by full solves, or full solves."""

    def orbit_at(new_speeds):
        if np.size(new_speeds) == 0:
            return np.zeros(0)
        q = imbalance_response(model, new_speeds, loads[:, case : case + 1])
        return _shaft_orbits(model, q)[node, 0]

    rows = (int(model.dofs.shaft(node, "v")), int(model.dofs.shaft(node, "w")))
    if not (projected and np.all(np.isin(rows, model.dofs.free))):
        return orbit_at
    # the refinement on a projected model of the peak, checked by full solves
    near = slice(max(k - 1, 0), k + 2)
    seed: PeakBasis | np.ndarray | None = start  # the scan's basis, else its responses near the peak
    if seed is None and responses is not None:
        seed = responses[model.dofs.free, case, near]
    return ProjectedOrbit(model, loads[:, case], rows, speeds[near], basis=seed)


def _refine(model: Model, response, speeds, curve, near: float, node: int) -> LateralCritical | None:
    """The peak of ``curve`` nearest ``near`` refined (:func:`resolve_peak`); None when the
    refined curve has no peak there (a sampling artefact)."""
    station = float(model.dofs.shaft_x[node])
    try:
        peak = resolve_peak(response, speeds, curve, near=near)
    except SingularSystemError:  # an undamped resonance: the response is infinite at the peak
        return _singular(near, station)
    if peak is None:
        return None
    location: dict[str, Any] = {"station": station, "af_method": peak.method, "peak_orbit": float(peak.amplitude)}
    amplification = peak.amplification_factor
    if not peak.resolved:
        if _undamped_at(model, peak.speed):
            amplification = float("inf")
            location["detail"] = "undamped resonance: the mode at the peak has no damping, the response is unbounded"
        else:
            location["detail"] = _UNRESOLVED
    return LateralCritical(peak.speed, amplification, location)


def _singular(speed: float, station: float) -> LateralCritical:
    detail = "undamped resonance: the response is singular at the peak"
    return LateralCritical(speed, float("inf"), {"station": station, "detail": detail})


def _known(critical: LateralCritical, out: list[LateralCritical]) -> bool:
    """``critical`` is one of ``out`` already (the same speed to 1e-6)."""
    return any(abs(critical.speed - c.speed) <= 1e-6 * critical.speed for c in out)


def _peak_orbit(critical: LateralCritical) -> float:
    return float(critical.location.get("peak_orbit", np.inf if not np.isfinite(critical.amplification_factor) else 0.0))


def _bandwidth(critical: LateralCritical) -> float:
    """Half-power bandwidth N_c/AF of a refined peak [rad/s] (0 for an undamped one)."""
    af = critical.amplification_factor
    return critical.speed / af if np.isfinite(af) and af > 0 else 0.0


def _same_peak(a: LateralCritical, b: LateralCritical) -> bool:
    """Two refinements of one peak: their speeds within a 20th of the wider one's bandwidth
    (the resolution of :func:`resolve_peak`'s vertex, 20 samples a band)."""
    return abs(a.speed - b.speed) <= max(_bandwidth(a), _bandwidth(b)) / 20.0


def _envelope_peak(model: Model, loads: np.ndarray, critical: LateralCritical) -> bool:
    """A seeded peak, refined on one node's orbit, is a maximum of the envelope too (the largest
    orbit over the shaft's nodes and the load cases, which defines a critical speed): full
    solves a 20th of its bandwidth to either side (the refinement's resolution, far beyond its
    vertex's error) are not above it there. A root the imbalance barely excites can make a
    bump at a node where the envelope, set by another node, only rises. A maximum on a taller
    neighbour's rising flank falls only a few tenths of its half-bandwidth after it before the
    neighbour's flank rises above it (a quarter of the bandwidth reached there: hunt h94b). An
    undamped peak (its response singular) is kept."""
    if not np.isfinite(critical.amplification_factor):
        return True
    step = max(_bandwidth(critical) / 20.0, 1e-9 * critical.speed)
    speeds = critical.speed + np.array([-step, 0.0, step])
    try:
        envelope = _shaft_orbits(model, imbalance_response(model, speeds, loads)).max(axis=(0, 1))
    except SingularSystemError:
        return True
    return bool(envelope[1] >= envelope[[0, 2]].max())


def _near_sample(critical: LateralCritical, spacing: float) -> float:
    """How far an undamped peak, reported at the scan sample nearest its root, may lie from
    that root [rad/s]: a scan spacing (0 for a damped peak)."""
    return spacing if not np.isfinite(critical.amplification_factor) else 0.0


@dataclass(frozen=True)
class _Seed:
    """Where to look for a peak the scan stepped over (:func:`_hidden_resonances`): the speed of
    the projected orbit's maximum near the root and the root's |Im| [rad/s], the node and load
    case, the unresolved peak it may replace."""

    speed: float
    width: float
    node: int
    case: int
    replaces: LateralCritical | None


def _seed_samples(seed: _Seed) -> np.ndarray:
    """Speeds [rad/s] across a seed root's half-power band, its maximum ± (1, 2, 4) |Im Ω|, the
    maximum itself and ± |Im Ω|/8 (:data:`_SEED_STEPS`): the refinement starts from a bandwidth
    it can measure (one sample at the vertex gives the half-power interpolation nothing between
    it and the scan's far samples, and an estimate orders of magnitude too small) and from a
    sample above its neighbours at the maximum (which :func:`resolve_peak` follows). They lie
    on a lattice: |Im Ω| rounded to a power of two, the speed to a 64th of that, so that two
    bases whose maxima agree to ~1e-7 of |Im Ω| (the scan's reduced basis, the span of its full
    responses) start the same refinement."""
    step = 2.0 ** np.round(np.log2(max(seed.width, 1e-9 * seed.speed)))
    centre = np.round(seed.speed / (step / 64.0)) * (step / 64.0)
    return centre + _SEED_STEPS * step


def _hidden_resonances(model, loads, speeds, envelope, found, span: PeakBasis | None) -> list[_Seed]:
    """Each resonance the scan may have stepped over: a root Ω_k of the projected synchronous
    problem (:func:`~flexshaft.analyses.synchronous_roots.synchronous_roots`, on the scan's
    reduced basis, else on its responses) that no peak ``found`` holds (none within its
    half-power band Re Ω_k ± |Im Ω_k|), whose band is narrower than :data:`_SHOWN_SAMPLES`
    scan intervals, and around which the projected model's orbit (the largest over the shaft's
    nodes and the load cases, at Re Ω_k + (−2 … 2) |Im Ω_k|, :data:`_AROUND_ROOT`) has a maximum
    of its own (a sample above its neighbours, though a taller neighbour may set the window's
    edge or peak inside it; the maximum nearest Re Ω_k is the root's). That
    is a peak narrower than the samples' spacing (it falls between two of them), or one whose
    broader neighbour swamps it on the samples (two bumps sampled as one); a root the imbalance
    does not excite shows no such maximum. A peak found but left unresolved whose nearest root
    is this one is the same resonance, its refinement stalled: the seed ``replaces`` it when it
    refines to a larger peak. The seed's speed: that maximum of the projected model's orbit,
    located between the samples either side of it (:func:`_window_maximum`); its node and
    case: the largest orbit there."""
    if span is None or speeds.size < 2:
        return []
    solver = solver_for(model)
    free = model.dofs.free
    V, terms = span.basis, span.terms
    roots = synchronous_roots(solver, terms, float(speeds[0]), float(speeds[-1]))
    spacing = np.diff(speeds)
    local = np.full(model.dofs.size, -1, dtype=np.intp)
    local[free] = np.arange(free.size)
    n = np.arange(model.dofs.n_shaft_nodes)
    rows = np.stack([local[model.dofs.shaft(n, "v")], local[model.dofs.shaft(n, "w")]])  # (2, nodes)
    inputs = V.conj().T @ np.asarray(loads, dtype=complex)[free]  # (r, cases)

    def orbits_at(grid: np.ndarray) -> np.ndarray:
        """The projected model's shaft orbits (nodes, cases, speeds) [m]."""
        Z = np.tensordot(solver.term_weights(grid, grid), terms, axes=1)  # (speeds, r, r)
        y = np.linalg.solve(Z, np.broadcast_to(inputs, (grid.size, *inputs.shape)))  # (speeds, r, cases)
        q = np.einsum("nr,src->ncs", V, y * (grid * grid)[:, None, None])
        q = np.concatenate([q, np.zeros((1, *q.shape[1:]))])  # row -1: a fixed DOF's zero
        return orbit_amplitude(q[rows[0]], q[rows[1]])

    out: list[_Seed] = []
    for root in roots:
        speed, width = float(root.real), max(abs(float(root.imag)), 1e-9 * float(root.real))
        j = int(np.clip(np.searchsorted(speeds, speed) - 1, 0, spacing.size - 1))
        if width >= _SHOWN_SAMPLES * spacing[j]:
            continue
        replaces = None
        nearest = min(found, key=lambda c: abs(c.speed - speed), default=None)
        if nearest is not None and nearest.location.get("detail") == _UNRESOLVED:
            if np.argmin(np.abs(roots.real - nearest.speed)) == np.argmin(np.abs(roots.real - speed)):
                replaces = nearest
        # a peak found holds it: within its band, or within a sample of an undamped one (those
        # are reported at the scan sample nearest their root)
        if replaces is None and any(abs(speed - c.speed) <= max(width, _near_sample(c, spacing[j])) for c in found):
            continue
        if any(abs(speed - s.speed) <= width for s in out):
            continue
        grid = speed + width * _AROUND_ROOT
        try:
            orbit = orbits_at(grid)
        except np.linalg.LinAlgError:
            continue
        level = orbit.max(axis=(0, 1))
        if not np.all(np.isfinite(level)):
            continue
        # its own maximum: a sample above its neighbours, even where a taller resonance nearby
        # sets the window's edge or peaks inside it (that one has its root: the maximum nearest
        # Re Ω is this root's; docs/requirements.md: each local maximum of the envelope is a
        # critical speed)
        own = np.flatnonzero((level[1:-1] > level[:-2]) & (level[1:-1] >= level[2:])) + 1
        if own.size == 0:  # no maximum of its own there
            continue
        k = int(own[np.argmin(np.abs(grid[own] - speed))])
        at = _window_maximum(lambda x: orbits_at(np.array([x]))[:, :, 0], grid[k - 1 : k + 2], width)
        peak = orbits_at(np.array([at]))[:, :, 0]
        node, case = np.unravel_index(int(np.argmax(peak)), peak.shape)
        out.append(_Seed(at, width, int(node), int(case), replaces))
    return out


def _window_maximum(orbit: Callable[[float], np.ndarray], bracket: np.ndarray, width: float) -> float:
    """The speed [rad/s] of the largest orbit (over nodes and cases) between ``bracket``'s ends,
    a sample above them in its middle: the loop margins' golden-section search
    (:func:`~flexshaft.analyses.local_projection.golden_maximum`, on log Ω) to 1e-4 of
    ``width``, the middle sample when the search ends lower (a maximum beside a taller
    neighbour's flank can lie a few tenths of |Im Ω| from Re Ω, which the refinement must start
    from) or the bracket reaches Ω ≤ 0."""
    middle = float(bracket[1])
    if not bracket[0] > 0.0:
        return middle
    search = golden_maximum(lambda value: value.real, np.log(bracket[0]), np.log(bracket[2]), 1e-4 * width / middle)
    try:
        speed = next(search)
        while True:
            speed = search.send(complex(orbit(speed).max()))
    except StopIteration as stop:
        log_speed, level = stop.value
    except np.linalg.LinAlgError:  # the projected problem singular there (an undamped root)
        return middle
    return float(np.exp(log_speed)) if level >= float(orbit(middle).max()) else middle


def _seed_span(model: Model, loads, start: PeakBasis | None, basis, responses) -> PeakBasis | None:
    """The projected model the synchronous roots are solved on: the scan's reduced basis (the
    peaks' own :class:`PeakBasis` when they start from it), else the span of its responses
    (:func:`_response_columns`); None without either."""
    if start is not None:
        return start
    free = model.dofs.free
    if basis is not None:
        columns = np.asarray(basis, dtype=complex)
    elif responses is not None:
        columns = _response_columns(np.asarray(responses, dtype=complex)[free], np.asarray(loads)[free])
    else:
        return None
    if not np.any(columns):  # no imbalance: nothing to excite a resonance
        return None
    return PeakBasis(model, columns, rank_tolerance=_SEED_RANK)


def _response_columns(q: np.ndarray, loads: np.ndarray) -> np.ndarray:
    """Columns spanning the scan's responses q (n_free, cases, speeds) at fewer cost: the
    responses to the loads' independent directions (q L⁺: a ``worst`` placement's 16 cases are
    combinations of 5 bay forces) at :data:`_SEED_SPEEDS` speeds spread over the scan. Every
    response holds every excited mode (in proportion to its distance from resonance), so a
    subset of the speeds spans them; the whole scan of a 16-case driveline (4176 columns at
    SCREENING, 10416 at REPORT) took 0.6-2 s to orthonormalise for a rank of 46."""
    u, sigma, vh = np.linalg.svd(loads, full_matrices=False)
    keep = sigma > _SEED_RANK * sigma[0] if sigma.size and sigma[0] > 0 else np.zeros(sigma.size, bool)
    q = np.einsum("ncs,ck->nks", q, vh[keep].conj().T / sigma[keep])
    step = max(1, -(-q.shape[2] // _SEED_SPEEDS))
    return q[:, :, ::step].reshape(q.shape[0], -1)


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
        responses = np.asarray(imbalance_response(model, speeds, loads))
        orbits = _shaft_orbits(model, responses)
    else:
        speeds, orbits = scan
    envelope = orbits.max(axis=(0, 1))
    start = PeakBasis(model, basis) if projected and basis is not None else None
    out: list[LateralCritical] = []
    for rough in response_peaks(speeds, envelope):
        k = int(np.argmin(np.abs(speeds - rough.speed)))
        node, case = np.unravel_index(int(np.argmax(orbits[:, :, k])), orbits.shape[:2])
        response = _orbit_function(model, loads, int(node), int(case), speeds, k, projected, start, responses)
        found = _refine(model, response, speeds, orbits[node, case], rough.speed, int(node))
        if found is not None and not _known(found, out):
            out.append(found)
    for seed in _hidden_resonances(
        model, loads, speeds, envelope, out, _seed_span(model, loads, start, basis, responses)
    ):
        k = int(np.clip(np.searchsorted(speeds, seed.speed), 1, speeds.size - 1))
        response = _orbit_function(model, loads, seed.node, seed.case, speeds, k, projected, start, responses)
        new = _seed_samples(seed)
        new = new[(new > speeds[k - 1]) & (new < speeds[k])]
        try:
            values = np.asarray(response(new), dtype=float)
        except SingularSystemError:
            values = np.full(new.size, np.inf)
        if np.all(np.isfinite(values)):
            curve_speeds = np.concatenate([speeds[:k], new, speeds[k:]])
            curve = np.concatenate([orbits[seed.node, seed.case, :k], values, orbits[seed.node, seed.case, k:]])
            found = _refine(model, response, curve_speeds, curve, seed.speed, seed.node)
        else:  # an undamped resonance the scan stepped over
            found = _singular(seed.speed, float(model.dofs.shaft_x[seed.node]))
        if found is None or not _envelope_peak(model, loads, found):
            continue
        if seed.replaces is not None:  # a better refinement of a peak left unresolved
            if _peak_orbit(found) > _peak_orbit(seed.replaces):
                out.remove(seed.replaces)
                out.append(found)
        elif not _known(found, out) and not any(_same_peak(found, c) for c in out):
            out.append(found)
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
    """The label of the tracked mode whose 1× critical speed is within 3 % of ``speed`` (a
    diagram drawn with further harmonics has crossings of 2×, 3×, ... too: not this peak's)."""
    synchronous = [c for c in campbell.critical_speeds if c.harmonic == 1.0] if campbell is not None else []
    if not synchronous:
        return ""
    nearest = min(synchronous, key=lambda c: abs(c.speed - speed))
    if abs(nearest.speed - speed) > _LABEL_TOLERANCE * speed:
        return ""
    return f"{nearest.mode + 1} ({nearest.whirl})"
