"""Campbell diagram: damped eigenvalues against speed, tracked into continuous mode curves.

At each speed the loss-free state matrix on the modal basis gives every candidate
(:mod:`flexshaft.analyses.eigen`); candidates are matched to the curves of the previous speed
by the modal assurance criterion (an optimal assignment, :func:`assignment`, with a small
frequency-distance penalty), so a curve keeps its identity through veerings and crossings;
each tracked mode is then refined to its loss-consistent eigenvalue (every member's hysteretic
loss at the mode's own frequency, the model's internal-damping model), so frequencies, damping
ratios and log decrements are those of the forced response's physics. Each point carries its
kind and whirl labels (:mod:`flexshaft.analyses.classify`). Critical speeds are the
intersections of the **lateral** curves with the excitation lines ``ω = kΩ`` (linear
interpolation).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.classify import ModalLabeler, degenerate_groups
from flexshaft.analyses.continuation import mode_root, mode_roots, newton_many, predicted_start
from flexshaft.analyses.datasets import curves_dataset
from flexshaft.analyses.eigen import ReducedModel, candidates, lowest_modes
from flexshaft.analyses.eigen_error import (
    EIGENVALUE_TOLERANCE,
    accuracy_text,
    check_tolerance,
    tracked_to_accuracy,
    with_error_estimate,
)
from flexshaft.analyses.guards import (
    RefusedInputError,
    check_count,
    check_finite_array,
    check_model,
    check_spin_speeds,
    require_finite,
)
from flexshaft.analyses.hysteretic_roots import consistent_roots, lowest_roots
from flexshaft.analyses.loss import LossCoefficients
from flexshaft.analyses.results import ResultMixin, dataframe, html_table
from flexshaft.analyses.screened_match import mac, match_cost, screened_match
from flexshaft.assembly.model import Model
from flexshaft.parallel.threads import single_blas_thread
from flexshaft.plot.campbell import campbell_figure
from flexshaft.units import rad_s_to_hz, rad_s_to_rpm

__all__ = [
    "Campbell",
    "CriticalSpeed",
    "EigenvalueCurves",
    "TrackedModes",
    "campbell",
    "critical_speeds",
    "assignment",
    "check_speeds",
    "default_basis_size",
    "mac",
    "rest_degenerate",
    "track_modes",
]


def default_basis_size(n_modes: int) -> int:
    """Plain modal basis of a sweep over speed for ``n_modes`` tracked modes (an explicit
    ``basis_size``; the default is the enriched basis of :func:`tracked_to_accuracy`)."""
    return max(4 * n_modes, 40)


def assignment(cost: np.ndarray) -> np.ndarray:
    """Column of each row of a finite (p, q) ``cost`` (p ≤ q), distinct columns, least total cost.

    When the rows' own cheapest columns are distinct they are the answer (no assignment costs
    less than the sum of the row minima); this is the usual case between close speeds. Otherwise
    the linear assignment problem is solved exactly by scipy.sparse.csgraph's minimum-weight
    full bipartite matching on the complete graph (costs shifted to >= 1: a stored zero would be
    a missing edge; the shift adds the same p times it to every assignment).
    """
    best = np.argmin(cost, axis=1)
    if np.unique(best).size == best.size:
        return best
    import scipy.sparse as sp
    from scipy.sparse.csgraph import min_weight_full_bipartite_matching

    rows, cols = min_weight_full_bipartite_matching(sp.csr_array(cost - cost.min() + 1.0))
    idx = np.empty(cost.shape[0], dtype=int)
    idx[rows] = cols
    return idx


@dataclass(frozen=True)
class CriticalSpeed:
    """Intersection of a tracked lateral mode with the excitation line ω = harmonic·Ω."""

    speed: float  # [rad/s]
    mode: int  # tracked-mode index (0-based)
    harmonic: float
    whirl: str

    @property
    def speed_rpm(self) -> float:
        return rad_s_to_rpm(self.speed)


class EigenvalueCurves:
    """Derived quantities of an ``eigenvalues`` array (n_speeds, n_modes) of s [rad/s]."""

    speeds: np.ndarray
    eigenvalues: np.ndarray
    whirl: np.ndarray

    @property
    def frequencies(self) -> np.ndarray:
        """Damped natural frequencies Im(s)/2π [Hz]."""
        return rad_s_to_hz(self.eigenvalues.imag)

    @property
    def real_parts(self) -> np.ndarray:
        """Re(s) [1/s]; positive is unstable."""
        return self.eigenvalues.real

    @property
    def damping_ratios(self) -> np.ndarray:
        """ζ = −Re(s)/|s| [-]."""
        return -self.eigenvalues.real / np.abs(self.eigenvalues)

    @property
    def log_decrements(self) -> np.ndarray:
        """δ = 2π ζ/√(1 − ζ²) [-]."""
        z = self.damping_ratios
        return 2 * np.pi * z / np.sqrt(np.maximum(1 - z * z, 1e-300))

    #: Columns of :meth:`mode_summary`.
    SUMMARY_COLUMNS = ("mode", "f first [Hz]", "f last [Hz]", "kind", "whirl last", "min δ [-]", "at [rpm]")

    def mode_summary(self) -> list[list]:
        """One row per tracked mode, numbered from 1 as the modes at the first speed: its damped
        frequency at the first and the last speed [Hz], kind and whirl at the last speed, and its
        smallest log decrement with the speed where it occurs [rpm]."""
        kind = getattr(self, "kind", None)
        whirl = self.whirl
        delta = self.log_decrements
        rows = []
        for m in range(self.eigenvalues.shape[1]):
            k = int(np.argmin(delta[:, m]))
            rows.append(
                [
                    m + 1,
                    float(self.frequencies[0, m]),
                    float(self.frequencies[-1, m]),
                    "—" if kind is None else str(kind[-1, m]),
                    "—" if str(whirl[-1, m]) == "none" else str(whirl[-1, m]),
                    float(delta[k, m]),
                    float(rad_s_to_rpm(self.speeds[k])),
                ]
            )
        return rows


@dataclass(frozen=True)
class TrackedModes:
    """Curves over speed: eigenvalues, modal state vectors and labels per point."""

    speeds: np.ndarray
    eigenvalues: np.ndarray  # (n_speeds, n_modes)
    states: list  # per speed: (n_states, n_modes) refined state vectors
    kind: np.ndarray  # (n_speeds, n_modes)
    whirl: np.ndarray
    whirl_ratios: np.ndarray
    component: np.ndarray
    #: (n_modes,) bool, at a first speed of rest only: the mode shares its eigenvalue with
    #: another root, tracked or not (:func:`rest_degenerate`); None at a first speed above rest.
    degenerate: np.ndarray | None = None


#: Smallest MAC between a mode's shapes at neighbouring speeds that continuation accepts.
_CONTINUATION_MAC = 0.9


def track_modes(
    model: Model,
    red: ReducedModel,
    speeds,
    n_modes: int,
    solve: Callable[[float], tuple[np.ndarray, np.ndarray]] | None = None,
    refine_loss: bool = True,
    viscous: Callable[[float], LossCoefficients] | None = None,
    start: TrackedModes | None = None,
) -> TrackedModes:
    """Follow ``n_modes`` eigenvalue curves over ``speeds`` [rad/s].

    The first speed fixes the identities and their numbering: the ``n_modes`` roots of
    :func:`~flexshaft.analyses.eigen.lowest_modes`, refined and numbered by damped frequency, as
    :func:`~flexshaft.analyses.modal.modes` numbers the modes at that speed (column k is mode
    k + 1 of its tables). Each later speed is first tried by continuation: every mode's
    eigenvalue and shape are extrapolated from the previous speeds
    (:func:`~flexshaft.analyses.continuation.predicted_start`) and converged on its own problem;
    with ``refine_loss`` (the hysteretic loss) that is
    :func:`~flexshaft.analyses.continuation.mode_root`, which continues both sides of the
    synchronous line and keeps the root consistent with its side. The step is accepted when
    every mode converged, kept its shape (MAC ≥ 0.9 with the previous speed) and no two modes
    landed on the same eigenvalue. Otherwise ``solve(speed) -> (s, Y)`` gives all eigenvalues
    at the speed (default: with ``refine_loss`` the exact loss-consistent set, with the vectors
    of the roots the match can pick, :func:`~flexshaft.analyses.screened_match.screened_match`,
    or every vector, :func:`~flexshaft.analyses.hysteretic_roots.consistent_roots`; else the
    loss-free state matrix), matched to the previous curves by maximum MAC with a small
    frequency-distance penalty (optimal assignment). ``viscous(speed)`` gives the weights of the
    thesis's viscous internal-damping model instead (:func:`~flexshaft.analyses.loss.viscous_equivalent`):
    candidates and continuation then solve that linear problem. Without ``refine_loss`` and
    ``viscous`` (the undamped Campbell diagram) every speed is matched.

    ``start``: this call's curves at ``speeds[0]`` alone, tracked already (on ``red`` with the
    same options): its first speed is taken as it is and the tracking continues from it, with
    the same result as tracking from scratch (each speed is reached from the earlier ones only).

    Labels at rest (``speeds[0] == 0`` with later speeds). A mode at rest that shares its
    eigenvalue with another root (:func:`rest_degenerate`: the two whirls of an axisymmetric
    mode without gyroscopic coupling) may whirl either way; it takes the whirl ratio and label
    of its continuation at ``speeds[1]``, where the spin has split the pair. A mode alone at its
    eigenvalue (anisotropic supports: the two bending planes are uncoupled at rest) keeps its
    own, planar, as :func:`~flexshaft.analyses.modal.modes` labels it at rest.
    """
    speeds = np.asarray(speeds, dtype=float)
    hysteretic = refine_loss and viscous is None
    # the first solve (no curves yet) reads the vectors of the tracked roots and of rest_degenerate's
    # neighbours only (within 1e-4 of the refined roots; 1e-2 of the solve's is ample)
    opening: Callable[[float], tuple[np.ndarray, np.ndarray]] | None = None
    screen = hysteretic and solve is None  # the default solve's match, from the vectors it can pick
    if viscous is not None:
        solve = lambda speed: candidates(red, speed, viscous(speed))  # noqa: E731
    elif hysteretic:
        if solve is None:
            opening = lambda speed: lowest_roots(red, speed, n_modes, 100 * _NEIGHBOUR_WINDOW)  # noqa: E731
        solve = solve or (lambda speed: consistent_roots(red, speed))
    solve = solve or (lambda speed: candidates(red, speed))
    opening = opening or solve
    labeler = ModalLabeler(model, red.Phi)
    eig = np.zeros((speeds.size, n_modes), dtype=complex)
    states: list[np.ndarray] = []
    kinds, whirls, ratios, comps = [], [], [], []
    degenerate: np.ndarray | None = None
    prev = None
    for k, speed in enumerate(speeds):
        if k == 0 and start is not None:
            eig[0] = start.eigenvalues[0]
            states.append(start.states[0])
            prev = (eig[0], states[0])
            kinds.append(start.kind[0])
            whirls.append(start.whirl[0])
            ratios.append(start.whirl_ratios[0])
            comps.append(start.component[0])
            degenerate = start.degenerate
            continue
        step = None
        if (refine_loss or viscous is not None) and k >= 1:
            step = _continue(red, speeds, eig, states, k, n_modes, None if viscous is None else viscous(speed))
        untracked = None
        if step is None:
            step, untracked = _match(red, opening if prev is None else solve, speed, prev, n_modes, hysteretic, screen)
        s_k, Y_k = step
        if k == 0:  # numbered by damped frequency, as the modes' tables (the refinement moved them)
            first = np.lexsort((np.abs(s_k), s_k.imag))
            s_k, Y_k = s_k[first], Y_k[:, first]
            if speed == 0.0:
                degenerate = rest_degenerate(red, s_k, untracked, hysteretic)
        Y_k = labeler.circular(s_k, Y_k)  # a degenerate pair by whirl, not by round-off
        prev = (s_k, Y_k)
        eig[k] = s_k
        states.append(Y_k)
    # every speed's labels at once (they steer nothing above): one product of each projected
    # matrix with all the columns instead of one a speed
    labelled = 0 if start is None else 1  # the speeds labelled already: the start's
    if labelled < speeds.size:
        labels = labeler(np.hstack(states[labelled:]))
        kinds += list(labels.kind.reshape(-1, n_modes))
        whirls += list(labels.whirl.reshape(-1, n_modes))
        ratios += list(labels.whirl_ratio.reshape(-1, n_modes))
        comps += list(labels.component.reshape(-1, n_modes))
    kind, whirl, ratio = np.array(kinds), np.array(whirls), np.array(ratios)
    if speeds.size > 1 and speeds[0] == 0.0 and degenerate is not None:
        # a degenerate pair at rest may whirl either way: labelled by its continuation
        ratio[0] = np.where(degenerate, ratio[1], ratio[0])
        whirl[0] = np.where(degenerate & (kind[0] == "lateral"), whirl[1], whirl[0])
    return TrackedModes(speeds, eig, states, kind, whirl, ratio, np.array(comps), degenerate)


#: Relative distance within which an untracked root at rest is refined to be compared with a
#: lone tracked mode by :data:`~flexshaft.analyses.classify.DEGENERATE` (a dense eigen-solve's
#: root is far more accurate than this; the refinement is skipped for every other root).
_NEIGHBOUR_WINDOW = 1e-4


def rest_degenerate(red: ReducedModel, s: np.ndarray, untracked, hysteretic: bool) -> np.ndarray:
    """Which tracked modes at rest (eigenvalues ``s``) share their eigenvalue with another root.

    The criterion of :func:`~flexshaft.analyses.classify.circular_pairs`: a group of eigenvalues
    within :data:`~flexshaft.analyses.classify.DEGENERATE` of each other, among the tracked modes
    and the untracked roots of the same solve (``untracked``: ``(s, Y)`` of the roots not
    tracked, or None). The untracked ones count because ``n_modes`` may cut a degenerate pair:
    its tracked member is then the eigen-solver's arbitrary combination of the two whirls, whose
    own label is round-off. Only the untracked roots within :data:`_NEIGHBOUR_WINDOW` of a lone
    tracked mode are compared, refined as the tracked ones were (with the hysteretic loss by
    :func:`~flexshaft.analyses.continuation.mode_root`).
    """
    s = np.asarray(s)
    paired = np.zeros(s.size, dtype=bool)
    for group in degenerate_groups(s):
        paired[group] = True
    if untracked is None or paired.all():
        return paired
    lam, Y = untracked
    near = np.flatnonzero(
        np.any(np.abs(lam[:, None] - s[None, ~paired]) <= _NEIGHBOUR_WINDOW * np.abs(s[None, ~paired]), axis=1)
    )
    if near.size == 0:
        return paired
    others = lam[near].copy()
    if hysteretic:
        for i, j in enumerate(near):
            root, _, found = mode_root(red, 0.0, lam[j], Y[:, j])
            if found:
                others[i] = root
    every = np.concatenate([s, others])
    for group in degenerate_groups(every):
        paired[group[group < s.size]] = True
    return paired


def _continue(red, speeds, eig, states, k, n_modes, viscous=None):
    """Continuation step to speeds[k]; None when it cannot be trusted."""
    speed = speeds[k]
    predicted, start = predicted_start(speeds, eig, states, k)
    Y_prev = states[k - 1]
    if viscous is None:
        s_k, Y_k, converged = mode_roots(red, speed, predicted, start)
    else:
        s_k, Y_k, converged = newton_many(red, speed, predicted, start, viscous=viscous)
    macs = np.abs(np.einsum("ij,ij->j", Y_prev.conj(), Y_k)) ** 2
    if not np.all(converged) or np.any(macs < _CONTINUATION_MAC):
        return None
    gaps = np.abs(s_k[:, None] - s_k[None, :])
    np.fill_diagonal(gaps, np.inf)
    if np.any(gaps < 1e-7 * np.abs(s_k)[:, None]):
        return None
    return s_k, Y_k


def _match(red, solve, speed, prev, n_modes, hysteretic, screen=False):
    """All eigenvalues at ``speed`` matched to the previous curves. With the hysteretic loss
    each matched root is then polished by Newton's method on its mode's branches, the least
    stable of its consistent roots where a fold near the synchronous line has two
    (:func:`~flexshaft.analyses.continuation.mode_root`). Returns ``((s, Y), untracked)``:
    without previous curves also the roots not taken, ``(s, Y)`` unpolished (else None).
    ``screen``: the match from the vectors of the roots it can pick when that is certain
    (:func:`~flexshaft.analyses.screened_match.screened_match`), else from ``solve``'s."""
    screened = screened_match(red, speed, prev[0], prev[1]) if screen and prev is not None else None
    lam, Y, idx = screened if screened is not None else (*solve(speed), None)
    if lam.size < n_modes:  # the model has fewer modes than asked for: the request's limit, not a fault
        raise RefusedInputError(
            f"only {lam.size} oscillatory modes at {speed:.6g} rad/s for {n_modes} tracked; "
            "ask for fewer modes or a larger basis (a finer mesh has more modes)"
        )
    untracked: tuple[np.ndarray, np.ndarray] | None = None
    if prev is None:
        idx = lowest_modes(lam, n_modes)
        rest = np.setdiff1d(np.arange(lam.size), idx)
        untracked = (lam[rest], Y[:, rest])
    elif idx is None:
        idx = assignment(match_cost(prev[0], prev[1], lam, Y))
    s_k, Y_k = lam[idx].copy(), Y[:, idx].copy()
    if hysteretic:  # Newton polishes the dense eigen-solve's root (a fold: the less stable root)
        roots, vecs, found = mode_roots(red, speed, s_k, Y_k)
        s_k[found], Y_k[:, found] = roots[found], vecs[:, found]
    return (s_k, Y_k), untracked


@dataclass(frozen=True)
class Campbell(EigenvalueCurves, ResultMixin):
    """Tracked damped eigenvalues over speed.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s], (n_speeds,).
    eigenvalues : ndarray
        s [rad/s], (n_speeds, n_modes); column k is one tracked mode.
    whirl : ndarray of str
        "forward", "backward", "planar" or "none" (not lateral) per point.
    whirl_ratios : ndarray
        Whirl ratio in [−1, 1] per point.
    critical_speeds : tuple of CriticalSpeed
        Lateral modes crossing the excitation lines, by speed.
    kind : ndarray of str
        "lateral", "torsional" or "axial" per point.
    component : ndarray of str
        "shaft", "boom" or "coupled" per point.
    internal_damping : str
        Internal-damping model of the eigenvalues.
    error_estimate : ndarray or None
        Estimated relative error |s* − s|/|s| of each eigenvalue against the full (unreduced)
        eigenproblem, (n_speeds, n_modes) (:mod:`flexshaft.analyses.eigen_error`).
    tolerance : float or None
        The accuracy the basis was chosen for (None: a basis size given by the caller).
    basis_size : int or None
        Number of basis vectors used.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    whirl: np.ndarray
    whirl_ratios: np.ndarray
    critical_speeds: tuple[CriticalSpeed, ...]
    kind: np.ndarray | None = None
    component: np.ndarray | None = None
    internal_damping: str = "rotating"
    error_estimate: np.ndarray | None = None
    tolerance: float | None = None
    basis_size: int | None = None

    plots = {"campbell": "plot_campbell"}

    def __repr__(self) -> str:
        ns, nm = self.eigenvalues.shape
        top = rad_s_to_rpm(self.speeds[-1]) if ns else 0.0
        return (
            f"Campbell({nm} modes × {ns} speeds to {top:.0f} rpm, {len(self.critical_speeds)} critical speeds, "
            f"internal damping {self.internal_damping!r}{accuracy_text(self)})"
        )

    def to_dataset(self):
        """Tracked frequencies, damping and labels over speed, the critical speeds and each
        eigenvalue's estimated error (xarray)."""

        return with_error_estimate(curves_dataset(self, "Campbell diagram"), self)

    def _repr_html_(self) -> str:
        crit = [[c.speed_rpm, c.mode + 1, c.harmonic, c.whirl] for c in self.critical_speeds]
        out = html_table(self.SUMMARY_COLUMNS, self.mode_summary(), title=repr(self))
        if crit:
            out += html_table(("speed [rpm]", "mode", "harmonic", "whirl"), crit, title="critical speeds")
        return out

    def to_dataframe(self):
        """The critical speeds, one row each: speed [rpm] and [rad/s], tracked mode (numbered
        from 1), excitation order and whirl (pandas, imported here; xarray brings it). The
        curves themselves: :meth:`to_dataset`."""
        crit = self.critical_speeds
        return dataframe(
            {
                "speed_rpm": [c.speed_rpm for c in crit],
                "speed_rad_s": [c.speed for c in crit],
                "mode": [c.mode + 1 for c in crit],
                "harmonic": [c.harmonic for c in crit],
                "whirl": [c.whirl for c in crit],
            }
        )

    def plot_campbell(
        self,
        ax=None,
        *,
        operating_rpm: float | None = None,
        max_critical_rpm: float | None = None,
        damping: bool = True,
        **kwargs,
    ):
        """Campbell diagram in rpm and Hz: whirl as line style and marker, the log decrement as
        colour (``damping=False``: one colour per mode), the critical speeds (up to
        ``max_critical_rpm``) labelled. Keywords (``main_rotor_hz``, ``harmonics``) go to
        :func:`flexshaft.plot.campbell.campbell_figure`."""

        crit = [
            c.speed_rpm for c in self.critical_speeds if max_critical_rpm is None or c.speed_rpm <= max_critical_rpm
        ]
        harmonics = sorted({c.harmonic for c in self.critical_speeds} | {1.0})
        kwargs.setdefault("harmonics", harmonics)
        return campbell_figure(
            rad_s_to_rpm(self.speeds),
            self.frequencies,
            self.whirl,
            crit,
            operating_rpm,
            log_decrement=self.log_decrements if damping else None,
            kind=self.kind,
            ax=ax,
            **kwargs,
        )


@single_blas_thread
def campbell(
    model: Model,
    speeds,
    n_modes: int = 10,
    basis_size: int | None = None,
    harmonics=(1.0,),
    damped: bool = True,
    tolerance: float = EIGENVALUE_TOLERANCE,
) -> Campbell:
    """Damped eigenvalues at each speed, tracked into continuous mode curves.

    Parameters
    ----------
    speeds : array_like
        Ω [rad/s], increasing, finite, >= 0, at most :data:`~flexshaft.analyses.guards.MAX_SPEED`.
    n_modes : int
        Number of tracked modes (the lowest at the first speed).
    basis_size : int or None
        A plain modal basis of this size (larger is more exact); default: the enriched basis
        chosen for ``tolerance``.
    harmonics : sequence of float
        Excitation orders k for the critical speeds (ω = kΩ).
    damped : bool
        Include bearing dampers, actuator damping and the members' hysteretic loss.
    tolerance : float
        Relative eigenvalue accuracy against the full (unreduced) eigenproblem the basis is
        chosen for when ``basis_size`` is None (:func:`tracked_to_accuracy`); the estimate
        reached is :attr:`Campbell.error_estimate`.
    """
    check_model(model)
    speeds = check_speeds(speeds)
    n_modes = check_count(n_modes, "n_modes")
    if basis_size is not None:
        basis_size = check_count(basis_size, "basis_size")
    harmonics = check_finite_array("harmonics", np.atleast_1d(np.asarray(harmonics, dtype=float)), "-")
    if harmonics.ndim != 1 or np.any(harmonics <= 0):
        raise ValueError(f"harmonics must be excitation orders > 0 (got {harmonics!r})")
    tolerance = check_tolerance(tolerance)
    red, tracked, errors = tracked_to_accuracy(
        model,
        speeds,
        n_modes,
        lambda r, at, start: track_modes(model, r, at, n_modes, refine_loss=damped, start=start),
        basis_size,
        tolerance,
        transform=None if damped else ReducedModel.undamped,
    )
    require_finite("Campbell eigenvalues", tracked.eigenvalues)
    crit = critical_speeds(speeds, tracked.eigenvalues, tracked.whirl, tracked.kind, harmonics)
    return Campbell(
        speeds,
        tracked.eigenvalues,
        tracked.whirl,
        tracked.whirl_ratios,
        crit,
        tracked.kind,
        tracked.component,
        model.internal_damping,
        errors,
        None if basis_size is not None else tolerance,
        red.size,
    )


def check_speeds(speeds) -> np.ndarray:
    """Speeds [rad/s] as a 1-D float array: finite, >= 0, at most
    :data:`~flexshaft.analyses.guards.MAX_SPEED`, strictly increasing (else ValueError)."""
    return check_spin_speeds(speeds, "speeds", increasing=True)


def critical_speeds(speeds, eigenvalues, whirl, kind, harmonics=(1.0,)) -> tuple[CriticalSpeed, ...]:
    """Crossings of the lateral curves with ω = kΩ, sorted by speed.

    A crossing takes its whirl from the lower sample, except above rest: a crossing between
    ``speeds[0] = 0`` and ``speeds[1]`` is at a spin, and a lone mode's planar orbit at rest
    (no gyroscopic coupling) says nothing of its whirl there; it takes the whirl of the first
    spinning sample (the label a degenerate pair carries at rest anyway, :func:`track_modes`).
    """
    speeds = check_finite_array("speeds", speeds, "rad/s")
    eigenvalues = check_finite_array("eigenvalues", eigenvalues, "rad/s")
    harmonics = check_finite_array("harmonics", np.atleast_1d(np.asarray(harmonics, dtype=float)), "-")
    if eigenvalues.ndim != 2 or eigenvalues.shape[0] != speeds.size:
        raise ValueError(f"eigenvalues must be (speeds, modes) = ({speeds.size}, n) (got {eigenvalues.shape})")
    out = []
    for h in harmonics:
        for m in range(eigenvalues.shape[1]):
            g = eigenvalues[:, m].imag - h * speeds
            for i in np.flatnonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0):
                j = i if kind is None or kind[i, m] == "lateral" else i + 1
                if kind is not None and kind[j, m] != "lateral":
                    continue
                if speeds[j] == 0.0 and (kind is None or kind[j + 1, m] == "lateral"):
                    j += 1  # above rest: the whirl of the first spinning sample
                t = g[i] / (g[i] - g[i + 1])
                out.append(
                    CriticalSpeed(float(speeds[i] + t * (speeds[i + 1] - speeds[i])), m, float(h), str(whirl[j, m]))
                )
            # a curve on the line at a sample speed (g = 0 there: no sign change on either side);
            # at rest g = 0 is a divergent root (Im s = 0), no resonance
            for i in np.flatnonzero((g == 0) & (speeds > 0)):
                if kind is None or kind[i, m] == "lateral":
                    out.append(CriticalSpeed(float(speeds[i]), m, float(h), str(whirl[i, m])))
    return tuple(sorted(out, key=lambda c: c.speed))
