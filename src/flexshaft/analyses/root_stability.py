r"""Stability of every root of the closed-loop driveline at a few speeds, not only the tracked modes.

The whirl-stability analysis (:mod:`flexshaft.analyses.stability`) follows the lowest few modes
over speed. An instability elsewhere in the spectrum escapes it: a magnetic-bearing loop whose
amplifier and derivative-filter lags turn a shaft bending pair at 620-750 Hz unstable, or an
integrator gain so large that a controller root sits at 13 kHz with Re s > 0. Here every root of
the closed-loop first-order system is examined at each of a few speeds (the verdict's: rest, the
operating speed and the speed the whirl-onset requirement must reach).

Method (at each speed Ω):

1. **Basis.** The free DOFs are projected on *all* their undamped modes (the exact model, up to
   :data:`FULL_BASIS_LIMIT` free DOFs; above it the lowest :data:`FULL_BASIS_LIMIT` modes, and
   :attr:`RootStability.highest_frequency` says where the check stops). The torsional subspace
   (the shaft's twist and the drive train, decoupled from everything else:
   :func:`~flexshaft.analyses.torsional.torsional_system`) is left out when its basis modes are
   pure: it carries no gyroscopic, rotating or control term, only fixed-frame loss, and its
   modes are :func:`~flexshaft.analyses.torsional.torsional_modes`.
2. **Every root of the loss-free closed loop**: the dense eigen-solution of the first-order
   state matrix (:meth:`~flexshaft.analyses.eigen.ReducedModel.state_matrix`: gyroscopic terms,
   bearing dampers, every actuator law with its controller, amplifier and filter states).
3. **The hysteretic loss**, at each root's own frequency ω = Im s
   (:mod:`flexshaft.analyses.loss`). Above the spin (ω > Ω) the loss is
   ``i sgn(ω) (F + K_lat)``, an imaginary positive semi-definite stiffness: it removes energy
   from every harmonic motion, so to first order it can only move a root to the left. A root
   above the spin that is stable without the loss is stable with it. The roots that can change
   side are the roots below the spin (0 < ω < Ω, where the rotating-frame loss of forward whirl
   turns circulatory), each refined to its loss-consistent value by Newton's method
   (:func:`~flexshaft.analyses.eigen.newton`; ``mode_root`` of
   :mod:`flexshaft.analyses.hysteretic_roots`, on its own side of the line), and the roots
   above the spin unstable without the loss (the loss may stabilise them). Those take the
   first-order shift of the loss (its projection on the root's left and right eigenvectors);
   one that half and one and a half times that shift both leave stable is settled by it, the
   others are solved by Newton's method on the upper branch's linear problem, least stable
   first, until :data:`MAX_SOLVED_UNSTABLE` are confirmed unstable (the rest keep their
   first-order value, ``refined`` False). On the small basis of a passive driveline (below)
   every root is solved exactly instead, one complex eigen-solution per branch
   (``consistent_values``: the eigenvectors only where the pairing of on-line roots needs
   them).
   A driveline whose actuator laws are all collocated, without states and with non-negative
   stiffness and damping (the thesis's ideal PD bearing) is *passive*: no root above the spin
   can be unstable (the energy argument of :func:`_is_passive`), so only the roots below the
   spin are judged, on a basis chosen for their accuracy (:func:`_passive_bases`: the lowest
   modes enriched with their static corrections, :mod:`flexshaft.analyses.reduced_basis`) and
   enlarged until the a-posteriori estimate of their error against the full model
   (:mod:`flexshaft.analyses.eigen_error`) is within ``tolerance``
   (:data:`~flexshaft.analyses.eigen_error.EIGENVALUE_TOLERANCE`): the estimate is reported
   (:attr:`RootStability.error_estimate`). A plain modal basis of every mode below twice the
   top speed, used before, left the heavily damped roots of the tuned design's PD bearings
   2e-3 from the full model's (ζ off by 6e-4); this basis holds them to 1e-7 at about half
   its cost (tests/test_root_stability.py).
4. **Divergence**: a real root s > 0 of the state matrix (a magnet whose negative stiffness
   exceeds its control stiffness) is unstable at every loss. A passive driveline has none when
   its basis stiffness is non-negative (every ω² >= 0: for a real root s and its real
   eigenvector φ, ``s² φᵀφ + s φᵀDφ + φᵀKφ = 0`` with D and K positive semi-definite has no
   root s > 0, :func:`_is_passive`): with the loss its roots are solved on its branches (step
   3), so its loss-free state matrix, whose real roots were all that was read, is not solved.

A root is unstable when its damping ratio ζ = −Re s/|s| is below
−:data:`~flexshaft.analyses.stability.STABILITY_TOLERANCE` (oscillatory) or it is a divergent
real root.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import scipy.linalg as la

from flexshaft.analyses.continuation import mode_root
from flexshaft.analyses.eigen import DIVERGENCE_TOLERANCE, ReducedModel, newton, reduce
from flexshaft.analyses.eigen_error import (
    EIGENVALUE_TOLERANCE,
    accurate_basis,
    accurate_reduction,
    check_tolerance,
    eigenvalue_errors,
)
from flexshaft.analyses.guards import check_model, check_spin_speeds, require_finite
from flexshaft.analyses.hysteretic_roots import branches, consistent_values_below, on_branch
from flexshaft.analyses.loss import eigen_coefficients
from flexshaft.analyses.modal import default_basis_size
from flexshaft.analyses.stability import STABILITY_TOLERANCE
from flexshaft.analyses.torsional import torsional_system
from flexshaft.assembly.model import Model
from flexshaft.parallel.threads import single_blas_thread

__all__ = [
    "FULL_BASIS_LIMIT",
    "MAX_SOLVED_UNSTABLE",
    "RootStability",
    "UnstableRoot",
    "closed_loop_poles",
    "root_stability",
]

#: Most free DOFs of the exact (full-basis) check; a larger model is checked on its lowest
#: FULL_BASIS_LIMIT modes (a dense eigen-solution of twice that size per speed).
FULL_BASIS_LIMIT = 900
#: Unstable roots above the spin solved with the loss at each speed before the rest keep their
#: first-order value (an unstable design can have hundreds: the verdict needs the worst few).
MAX_SOLVED_UNSTABLE = 4
#: A basis mode with more than this share of its mass-weighted norm on the torsional DOFs is
#: torsional; one between it and 1 − it mixes the subspaces (then none is left out).
_PURE = 1e-9
#: The torsional subspace is left out only when every projected matrix couples it to the rest by
#: less than this fraction of the matrix's largest entry (the dense basis's round-off leaves
#: 1e-10-1e-9 on the embedded designs; a physical coupling is of order 1).
_DECOUPLED = 1e-7


@dataclass(frozen=True)
class UnstableRoot:
    """One unstable root: speed Ω [rad/s], root s [rad/s] (real for a divergence), ``kind``
    ``"oscillatory"`` or ``"divergence"``, and whether the loss-consistent value was solved
    (``refined``; False: for a divergence, the loss-free value; for a root below the spin that
    Newton did not settle, the loss-free value; above the spin, the first-order estimate)."""

    speed: float
    root: complex
    kind: str
    refined: bool

    @property
    def frequency(self) -> float:
        """Im s [rad/s] (0 for a divergence)."""
        return float(abs(self.root.imag))

    @property
    def damping_ratio(self) -> float:
        """ζ = −Re s/|s| [-] (−1 for a divergence)."""
        return float(-self.root.real / abs(self.root)) if self.root != 0 else 0.0


@dataclass(frozen=True)
class RootStability:
    """Every root of the closed loop at a few speeds (module docstring).

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s], (n_speeds,).
    least_damped : ndarray
        The least-damped root at each speed [rad/s] (complex; a divergent root is real); for a
        passive check, of the roots up to :attr:`highest_frequency` (those its basis resolves).
    n_roots : ndarray
        Roots examined at each speed (oscillatory roots with Im s > 0 and the real roots of the
        loss-free state matrix; a passive check with the loss, which solves no loss-free state
        matrix (module docstring, step 4), counts its loss-consistent roots).
    n_refined : ndarray
        Of those, the roots whose loss-consistent value was solved at each speed (every root of
        a model without loss).
    unstable : tuple of UnstableRoot
        Every unstable root, by speed then frequency.
    roots : tuple of ndarray
        Every oscillatory root (Im s > 0) at each speed [rad/s]: loss-consistent where solved,
        with the first-order loss shift where that settled it, loss-free otherwise (the roots
        above the spin that are stable without the loss).
    basis_size : int
        Modes of the basis (the free DOFs, torsional ones left out when decoupled).
    exact : bool
        True when every root is covered: by the basis holding every (non-torsional) mode, or
        by the passive argument above the spin (``method``).
    highest_frequency : float
        Highest undamped natural frequency of the basis's modes [rad/s] (the passive basis's
        static corrections left out: their Ritz values have no physical meaning): roots of
        modes above it are not checked when ``exact`` is False, and not resolved by the
        passive basis (the bearing loops' grid stands natural frequencies in for them).
    method : {"full", "passive"}
        ``"full"``: every root of the model (up to :data:`FULL_BASIS_LIMIT` free DOFs);
        ``"passive"``: collocated laws without states, the roots below the spin solved and the
        rest stable by the energy argument of :func:`_is_passive`.
    error_estimate : float or None
        ``"passive"``: the largest estimated relative error |s* − s|/|s| against the full model
        of the roots judged (those below the spin, at every speed; 0 when there are none or the
        basis holds every mode); None for ``"full"`` (the basis is the model).
    tolerance : float or None
        The accuracy the passive basis was chosen for (None for ``"full"``).
    """

    speeds: np.ndarray
    least_damped: np.ndarray
    n_roots: np.ndarray
    n_refined: np.ndarray
    unstable: tuple[UnstableRoot, ...]
    roots: tuple[np.ndarray, ...]
    basis_size: int
    exact: bool
    highest_frequency: float
    method: str = "full"
    error_estimate: float | None = None
    tolerance: float | None = None

    @property
    def stable(self) -> bool:
        """No unstable root at any speed analysed."""
        return not self.unstable

    @property
    def onset_speed(self) -> float | None:
        """Lowest analysed speed with an unstable root [rad/s] (None: stable at every one).
        The true onset lies at or below it (above the previous speed analysed)."""
        return min((r.speed for r in self.unstable), default=None)

    def roots_at(self, speed: float) -> np.ndarray:
        """Every oscillatory root at the analysed speed nearest ``speed`` [rad/s]."""
        return self.roots[int(np.argmin(np.abs(self.speeds - speed)))]

    def resolved_roots_at(self, speed: float) -> np.ndarray:
        """:meth:`roots_at` without a passive check's roots above :attr:`highest_frequency`
        (its static corrections' Ritz roots: no physical meaning; :func:`_resolved`)."""
        s = self.roots_at(speed)
        return s[_resolved(s, self.method, self.highest_frequency)]

    @property
    def unstable_counts(self) -> np.ndarray:
        """Unstable roots found at each analysed speed (n_speeds,)."""
        return np.array([sum(r.speed == v for r in self.unstable) for v in self.speeds], dtype=int)

    def worst_at(self, speed: float) -> UnstableRoot | None:
        """The least-damped unstable root at the analysed ``speed`` (None when stable there)."""
        roots = [r for r in self.unstable if r.speed == speed]
        return min(roots, key=lambda r: r.damping_ratio, default=None)

    def coverage(self) -> str:
        """How the roots were found and how accurate they are, in one sentence (the report's)."""
        if self.method == "passive":
            estimate = "" if self.error_estimate is None else f" within {self.error_estimate:.1e}"
            tolerance = "" if self.tolerance is None else f" (estimated; the basis chosen for {self.tolerance:.0e})"
            return (
                f"passive bearing laws: the roots below the spin solved with the loss on a {self.basis_size}-vector "
                f"basis,{estimate} of the full model{tolerance}; the rest stable by the energy argument"
            )
        if self.exact:
            return f"every root of the model ({self.basis_size} modes, no reduction)"
        return (
            f"the roots of the lowest {self.basis_size} modes (to {self.highest_frequency / (2 * np.pi):.4g} Hz); "
            "roots above are not checked"
        )

    @property
    def least_damping_ratio(self) -> np.ndarray:
        """ζ of :attr:`least_damped` at each speed [-]."""
        s = self.least_damped
        return np.where(s.imag == 0, np.where(s.real > 0, -1.0, 1.0), -s.real / np.where(s == 0, 1.0, np.abs(s)))


def _lateral_basis(model: Model, red: ReducedModel) -> ReducedModel:
    """``red`` without its torsional basis modes when they span a decoupled subspace (module
    docstring, step 1); ``red`` itself otherwise."""
    try:
        twist = torsional_system(model).dofs
    except ValueError:  # coupled, or no free twist
        return red
    position = np.searchsorted(model.dofs.free, twist)
    norm = np.einsum("ij,ij->j", red.Phi, red.Phi)
    share = np.einsum("ij,ij->j", red.Phi[position], red.Phi[position]) / norm
    torsional = share > 1.0 - _PURE
    if not torsional.any() or np.any((share > _PURE) & ~torsional):
        return red
    keep = ~torsional
    for A in (red.G, red.C, red.F, red.L, red.S):
        scale = np.abs(A).max(initial=0.0)
        if scale and np.abs(A[np.ix_(keep, torsional)]).max(initial=0.0) > _DECOUPLED * scale:
            return red
    for act in red.actuators:
        if np.abs(act.rows[:, torsional]).max(initial=0.0) > _DECOUPLED * np.abs(act.rows).max(initial=1.0):
            return red
        if act.in_rows is not None and np.abs(act.in_rows[:, torsional]).max(initial=0.0) > _DECOUPLED * np.abs(
            act.in_rows
        ).max(initial=1.0):
            return red

    def sub(A: np.ndarray) -> np.ndarray:
        return np.ascontiguousarray(A[np.ix_(keep, keep)])

    actuators = tuple(
        dataclasses.replace(
            a, rows=a.rows[:, keep], in_rows=None if a.in_rows is None else np.ascontiguousarray(a.in_rows[:, keep])
        )
        for a in red.actuators
    )
    return dataclasses.replace(
        red,
        Phi=red.Phi[:, keep],
        w2=red.w2[keep],
        G=sub(red.G),
        C=sub(red.C),
        F=sub(red.F),
        L=sub(red.L),
        S=sub(red.S),
        actuators=actuators,
    )


@single_blas_thread
def closed_loop_poles(model: Model, speed: float) -> np.ndarray:
    """The oscillatory roots (Im s > 0) of the loss-free closed loop at ``speed`` [rad/s]: step 2
    of the module docstring alone (one dense eigen-solution, no loss)."""
    check_model(model)
    n_free = model.dofs.free.size
    red = _lateral_basis(model, reduce(model, min(n_free, FULL_BASIS_LIMIT)))
    lam: np.ndarray = la.eigvals(red.state_matrix(float(speed)), check_finite=False, overwrite_a=True)
    return lam[lam.imag > 1e-6 * np.abs(lam)]


def _damping_ratio(s: np.ndarray) -> np.ndarray:
    magnitude = np.abs(s)
    return -s.real / np.where(magnitude > 0, magnitude, 1.0)


def _loss_shift(red: ReducedModel, speed: float, s: np.ndarray, left: np.ndarray, right: np.ndarray) -> np.ndarray:
    """First-order change of each root ``s`` [rad/s] when the hysteretic loss is added at its own
    frequency (module docstring, step 3): ``Δs = −u_vᴴ L̃(ω, Ω) v_y / (uᴴ v)`` with u, v the left
    and right eigenvectors of the loss-free state matrix (u_v its velocity rows, v_y its
    displacement rows) and L̃ the loss stiffness of :func:`~flexshaft.analyses.loss.eigen_coefficients`."""
    nb = red.size
    U, V = left[nb : 2 * nb], right[:nb]
    norm = np.einsum("ij,ij->j", left.conj(), right)
    parts = {name: np.einsum("ij,ij->j", U.conj(), getattr(red, name) @ V) for name in ("F", "L", "S")}
    shift = np.zeros(s.size, complex)
    for k in range(s.size):
        w = eigen_coefficients(red.internal_damping, float(s[k].imag), speed)
        shift[k] = -(w.fixed * parts["F"][k] + w.lateral * parts["L"][k] + w.circulatory * parts["S"][k])
    return shift / np.where(norm != 0, norm, 1.0)


def _left_vectors(state: np.ndarray, roots: np.ndarray) -> np.ndarray:
    """Left eigenvectors u (uᴴ A = s uᴴ) of the state matrix for the given ``roots`` (one dense
    left eigen-solution, each root matched to its nearest eigenvalue)."""
    lam, left = la.eig(state, left=True, right=False, check_finite=False)
    index = np.argmin(np.abs(lam[:, None] - roots[None, :]), axis=0)
    return left[:, index]


def _hysteretic(
    red: ReducedModel, speed: float, state: np.ndarray, s: np.ndarray, right: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The loss-free roots ``s`` (right eigenvectors ``right``) of the full basis with the
    hysteretic loss where it can change a root's side (module docstring, step 3); returns the
    roots and which were solved with the loss (all of them without a loss: the loss-free roots
    are then the loss-consistent ones)."""
    if not red.has_loss:
        return s, np.ones(s.size, bool)
    done = np.zeros(s.size, bool)
    nb = red.size
    zeta = _damping_ratio(s)
    below = np.flatnonzero(s.imag < speed)  # the rotating loss of forward whirl can destabilise them
    for k in below:
        root, _, found = mode_root(red, speed, complex(s[k]), right[:nb, k])
        if found and np.isfinite(root) and root.imag > 0:
            s[k], done[k] = root, True
    above = np.flatnonzero((s.imag >= speed) & (zeta < -STABILITY_TOLERANCE) & ~done)
    if not above.size:
        return s, done
    # above the spin the loss only damps: a root unstable without it is settled by the
    # first-order estimate when half and one and a half times its shift leave it stable; the
    # rest are solved on the upper branch, most unstable first, until MAX_SOLVED_UNSTABLE are
    # confirmed (the others keep their first-order value: refined = False)
    left = _left_vectors(state, s[above])
    estimate = _loss_shift(red, speed, s[above], left, right[:, above])
    half, more = (_damping_ratio(s[above] + f * estimate) for f in (0.5, 1.5))
    clear = (half > STABILITY_TOLERANCE) & (more > STABILITY_TOLERANCE)
    s[above] += estimate
    upper = branches(red, speed)[-1]
    confirmed = 0
    for k in above[~clear][np.argsort(_damping_ratio(s[above[~clear]]))]:
        if confirmed >= MAX_SOLVED_UNSTABLE:
            break
        root, _, converged = newton(red, speed, complex(s[k]), right[:nb, k], weights=upper.weights)
        if converged and on_branch(upper, root.imag, speed):
            s[k], done[k] = root, True
        confirmed += _damping_ratio(s[k : k + 1])[0] < -STABILITY_TOLERANCE
    return s, done


@single_blas_thread
def root_stability(model: Model, speeds, tolerance: float = EIGENVALUE_TOLERANCE) -> RootStability:
    """Every root of the closed-loop driveline at each of ``speeds`` [rad/s] (module docstring).

    Parameters
    ----------
    model : Model
    speeds : array_like
        Spin speeds Ω [rad/s], finite, >= 0 (e.g. rest, the operating speed and the speed the
        onset requirement must reach).
    tolerance : float
        Relative accuracy against the full model that a passive driveline's basis is chosen for
        (its roots below the spin; module docstring, step 3).
    """
    check_model(model)
    tolerance = check_tolerance(tolerance)
    speeds = np.atleast_1d(check_spin_speeds(speeds, "speeds"))
    if speeds.ndim != 1 or speeds.size == 0:
        raise ValueError(f"speeds must be a non-empty 1-D array of spin speeds [rad/s] (got {speeds!r})")
    n_free = model.dofs.free.size
    error: float | None = None
    modes = reduce(model, min(n_free, default_basis_size(10)))
    if _is_passive(modes):
        red, passive_roots, error, highest = _passive_roots(model, modes, speeds, tolerance)
        method = "passive"
    else:
        red = _lateral_basis(model, reduce(model, min(n_free, FULL_BASIS_LIMIT)))
        passive_roots, method = {}, "full"
        highest = float(np.sqrt(max(np.max(red.w2, initial=0.0), 0.0)))
    exact = method == "passive" or n_free <= FULL_BASIS_LIMIT
    nb = red.size
    scale = float(np.sqrt(max(np.max(red.w2, initial=0.0), 1.0)))
    least, counts, refined_counts, unstable, all_roots = [], [], [], [], []
    passive = method == "passive" and red.has_loss
    # a passive driveline's roots are its branches' (below); its loss-free roots would be read
    # for a divergence only, which a non-negative stiffness excludes (step 4): not solved then
    loss_free = not passive or bool(np.min(red.w2, initial=0.0) < 0)
    for speed in speeds:
        speed = float(speed)
        state = red.state_matrix(speed) if loss_free else None
        right: np.ndarray | None = None
        if state is None:
            lam = np.zeros(0, complex)
        elif passive:  # every root is solved on its branches below: the loss-free vectors are unused
            lam = np.asarray(la.eigvals(state, check_finite=False), dtype=complex)
        else:
            lam, right = la.eig(state, check_finite=False)
        require_finite("closed-loop roots", lam)
        oscillatory = lam.imag > 1e-6 * np.abs(lam)
        real = np.abs(lam.imag) <= 1e-6 * np.abs(lam)
        divergent = real & (lam.real > DIVERGENCE_TOLERANCE * scale)
        if passive:
            # every hysteretic root exactly, one complex eigen-solution per branch
            s = passive_roots[speed]
            require_finite("closed-loop roots", s)
            done = np.ones(s.size, bool)
        else:
            assert state is not None and right is not None
            s, done = _hysteretic(red, speed, state, lam[oscillatory].copy(), right[:, oscillatory])
        zeta = _damping_ratio(s)
        for k in np.flatnonzero(zeta < -STABILITY_TOLERANCE):
            unstable.append(UnstableRoot(speed, complex(s[k]), "oscillatory", bool(done[k])))
        for root in np.sort(lam[divergent].real)[::-1]:
            unstable.append(UnstableRoot(speed, complex(root), "divergence", False))
        # a passive check's least-damped root among those its basis resolves: above its highest
        # mode the static corrections' Ritz roots (kHz, zeta ~ 1e-4) carry no physical meaning
        resolved = _resolved(s, method, highest)
        if divergent.any():
            least.append(complex(lam[divergent].real.max()))
        elif resolved.any():
            least.append(complex(s[resolved][np.argmin(zeta[resolved])]))
        else:
            least.append(complex(0.0))
        counts.append(int(s.size + real.sum()))
        all_roots.append(s)
        refined_counts.append(int(done.sum()))
    unstable.sort(key=lambda r: (r.speed, r.frequency))
    return RootStability(
        speeds=speeds,
        least_damped=np.array(least, dtype=complex),
        n_roots=np.array(counts),
        n_refined=np.array(refined_counts),
        unstable=tuple(unstable),
        roots=tuple(all_roots),
        basis_size=nb,
        exact=exact,
        highest_frequency=highest,
        method=method,
        error_estimate=error,
        tolerance=tolerance if method == "passive" else None,
    )


def _resolved(s: np.ndarray, method: str, highest: float) -> np.ndarray:
    """Which roots ``s`` the check's basis resolves: all of a full check's; a passive check's up
    to the highest frequency of its modes (above it, its static corrections' Ritz roots)."""
    if method != "passive":
        return np.ones(s.size, bool)
    return np.abs(s) <= highest * (1 + 1e-9)


def _is_passive(modes: ReducedModel) -> bool:
    """Whether every actuator law is collocated, without states, with non-negative stiffness
    and damping (:attr:`~flexshaft.analyses.eigen.ReducedModel.may_diverge` False).

    The loss-free closed loop is then ``M ÿ + (D + Ω G) ẏ + K y = 0`` with M > 0, D and K
    symmetric positive semi-definite and G skew: its energy ½(ẏᵀMẏ + yᵀKy) never grows (its
    rate is −ẏᵀDẏ), so no root has Re s > 0; above the spin the hysteretic loss adds the
    imaginary stiffness i(F + K_lat) of a positive semi-definite K'', which dissipates energy in
    every harmonic motion. Only the roots below the spin can turn unstable (the rotating loss
    turns circulatory there). Any Galerkin projection keeps these properties, so the argument
    holds on every basis: ``modes`` is the model's modal basis of the modal analyses' size."""
    return not modes.may_diverge


def _passive_bases(model: Model, modes: ReducedModel, top_speed: float) -> list[tuple[int, int]]:
    """The (modes, enriched modes) bases the passive check tries, in order (module docstring).

    The first: twice as many modes as lie below the top speed (at least 16; :func:`accurate_basis
    <flexshaft.analyses.eigen_error.accurate_basis>`'s rule for the modes it tracks), the lowest
    of them as many as lie below it (at least 8) enriched with their static corrections; on the
    embedded designs at 1e-6 it is the one kept (5e-8 at most, at every envelope point). Then
    both doubled while the basis holds at most four times the plain modal basis of the modes
    below the top speed, 4·max(4n, 60) vectors (the bound of
    :func:`~flexshaft.analyses.eigen_error.tracked_to_accuracy`), ending with every mode (no
    correction: the full model's roots) when the model has no more free DOFs than that; the
    last basis's estimate is reported whatever it is."""
    n_free = int(model.dofs.free.size)
    below = int(np.sum(np.sqrt(np.clip(modes.w2, 0.0, None)) < max(top_speed, 1.0)))
    size, enrich = accurate_basis(below)
    largest = 4 * max(4 * below, 60)
    out = []
    while size < n_free and size + enrich <= largest:
        out.append((size, enrich))
        size, enrich = 2 * size, 2 * enrich
    if n_free <= largest:
        out.append((n_free, 0))
    return out or [(min(n_free, largest), 0)]


#: The roots of a passive driveline judged at a speed: those below the spin and within this
#: factor above it (a root the basis error could move across the spin).
_JUDGED_BAND = 1.01


def _judged(s: np.ndarray, speed: float) -> np.ndarray:
    """The roots of a passive driveline that can be unstable at ``speed``: below the spin (a
    1 % band above it included, :data:`_JUDGED_BAND`)."""
    return np.flatnonzero(s.imag < _JUDGED_BAND * speed)


def _passive_roots(
    model: Model, modes: ReducedModel, speeds: np.ndarray, tolerance: float
) -> tuple[ReducedModel, dict[float, np.ndarray], float, float]:
    """The passive check's basis and roots: every loss-consistent root at each speed on the
    first basis of :func:`_passive_bases` whose roots below the spin are within ``tolerance``
    of the full model's (estimated), the last basis else; returns the basis, the roots by
    speed, the largest estimate and the highest frequency of the basis's modes [rad/s].

    The speeds are solved from the highest down (the most roots below the spin), so a basis
    that fails is left at its first failing speed."""
    n_free = int(model.dofs.free.size)
    bases = _passive_bases(model, modes, float(speeds.max()))
    order = sorted({float(v) for v in speeds}, reverse=True)
    for k, (size, enrich) in enumerate(bases):
        last = k == len(bases) - 1
        enriched = accurate_reduction(model, size, enrich)
        red = _lateral_basis(model, enriched)
        roots: dict[float, np.ndarray] = {}
        worst = 0.0
        for speed in order:
            s, Y = consistent_values_below(red, speed, _JUDGED_BAND)  # the judged roots' vectors
            judged = _judged(s, speed)
            if judged.size and size < n_free:
                errors = eigenvalue_errors(red, speed, s[judged], Y[:, judged])
                worst = max(worst, float(np.max(np.where(np.isfinite(errors), errors, np.inf))))
            roots[speed] = s
            if worst > tolerance and not last:
                break
        else:
            # the first ``size`` vectors of an enriched basis are the modes (reduced_basis)
            return red, roots, worst, float(np.sqrt(max(np.max(enriched.w2[:size]), 0.0)))
    raise AssertionError("unreachable: the last basis is always kept")
