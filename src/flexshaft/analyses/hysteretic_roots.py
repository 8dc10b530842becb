r"""Eigenvalues of the hysteretic problem: the roots consistent with their own side of the spin.

The problem. A mode s = −ζω_n + iω (ω = Im s > 0) meets every member's hysteretic loss at its
own frequency (:mod:`flexshaft.analyses.loss`), so the modal problem of
:mod:`flexshaft.analyses.eigen` is

.. math:: T(s)\,y = \big[s^2 I + s(Ω\tilde G + \tilde C) + Λ + \tilde K_a(s) + W(ω, Ω)\big]\,y = 0,
          \qquad W = w_F\,\tilde F + w_L\,\tilde K_{lat} + w_S\,\tilde K_{lat}\tilde S,

whose weights ``w`` depend on s only through the side of the synchronous line: with the
rotating-frame loss (``internal_damping = "rotating"``, Ω ≥ 0) they are
``W₊ = (i, i, 0)`` above the spin (σ = sgn(ω − Ω) = +1) and ``W₋ = (i, 0, 1)`` below it
(σ = −1); with the fixed-frame loss (``"thesis"``), and at Ω = 0, one set ``(i, i, 0)`` holds
for every ω > 0. So T is **piecewise linear**: on each side (a *branch*) it is a plain
quadratic eigenproblem with constant complex matrices, and the hysteretic eigenvalues are
exactly

.. math:: R(Ω) = \{s : \det T_{+}(s) = 0,\ \mathrm{Im}\,s ≥ Ω\} ∪
                 \{s : \det T_{-}(s) = 0,\ 0 < \mathrm{Im}\,s ≤ Ω\} ∪ R_{line}(Ω),

every root of each branch's linear problem that lies on that branch's own side (a root of
``T₊`` below the spin, or of ``T₋`` above it, is a root of the wrong problem and no eigenvalue;
so is any root with Im s ≤ 0, where the loss has the opposite sign). Each branch's linear
problem is the eigenproblem of a complex first-order matrix (:func:`branch_state_matrix`), so
R(Ω) is found without iterating on the loss sign: :func:`consistent_roots`. Nothing in R(Ω)
depends on which root an iteration happens to reach, so neither does anything computed from it.

Jeffcott rotor (the closed form this is tested against). Disk mass m, shaft stiffness k, loss
factor η, external damping c_e, r = v + i w: the forward branch roots solve
``m s² + c_e s + k(1 + iησ) = 0``, the backward ones ``m s² + c_e s + k(1 + iη) = 0`` on both
branches (derived in tests/test_damping.py). The conjugate of the σ = +1 equation is the
σ = −1 one, whose two roots sum to −c_e/m, so the forward roots are s₊ and
``s₋ = −c_e/m − s̄₊`` exactly: one frequency ω_d, real parts ``−(ηω_n + c_e/m)/2`` and
``+(ηω_n − c_e/m)/2`` to first order in η. Below ω_d only s₊ is consistent, above it only s₋;
the onset is Ω = ω_d when ηω_n > c_e/m.

Near the line. In general the two branch roots of one mode differ in frequency by O(η²)ω
(ω₊ ≠ ω₋; a few 1e-5 ω on the baseline). Where ω₋ < Ω < ω₊ both are consistent (a fold: the
mode has two eigenvalues); where ω₊ < Ω < ω₋ neither is, and the mode's eigenvalue lies on the
line itself: Im s = Ω with the set-valued sign sgn(0) ∈ [−1, 1], i.e. a root of
``T_μ = (1 − μ) T₋ + μ T₊`` for the μ ∈ [0, 1] that puts it at ω = Ω (:func:`line_root`;
regula falsi on μ). These on-line roots complete R(Ω): every mode has at least one eigenvalue
at every speed.

Following a mode over speed (:func:`~flexshaft.analyses.continuation.mode_root`) continues
**both** branches from the mode's previous eigenvalue (Newton's method on each branch's linear
problem, :func:`~flexshaft.analyses.eigen.newton`) and keeps the consistent one; in a fold the less
stable of the two (the verdict must not depend on which of two valid eigenvalues a
continuation followed); in the gap between, the on-line root. The tracking falls back to the
exact set R(Ω) when a continuation step cannot be trusted.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as la

from flexshaft.analyses.eigen import ReducedModel, candidates, lowest_modes, newton, spectrum
from flexshaft.analyses.loss import SYNCHRONOUS_TOLERANCE, LossCoefficients, frequency_coefficients

__all__ = [
    "Branch",
    "branches",
    "on_branch",
    "branch_state_matrix",
    "branch_roots",
    "consistent_roots",
    "consistent_values",
    "consistent_values_below",
    "consistent_from",
    "line_root",
    "lowest_roots",
    "mac_bounds",
    "damped_modes",
    "separated_vectors",
    "solved_below",
]

#: Smallest MAC between the starting vector and a branch root for the root to count as the
#: same mode's. The two branch roots of an isolated mode differ by a loss perturbation of
#: order η (MAC > 0.99 on the baseline); the eigenvectors of a double root (the forward and
#: backward whirl of an axisymmetric rotor on one branch) are any basis of its plane, which
#: round-off picks (a circular start vector has MAC 1/2 with either of a planar pair).
SAME_MODE_MAC = 0.25
_NO_LOSS = LossCoefficients(0.0, 0.0, 0.0)


@dataclass(frozen=True)
class Branch:
    """An interval of mode frequencies ``low <= ω <= high`` [rad/s] on which the loss weights
    are constant (``weights``: of F, K_lat and K_lat S, :mod:`flexshaft.analyses.loss`)."""

    low: float
    high: float
    weights: LossCoefficients


def branches(red: ReducedModel, speed: float) -> tuple[Branch, ...]:
    """The branches at spin speed Ω = ``speed`` >= 0 [rad/s], by increasing frequency: one for
    a loss-free model, the fixed-frame (thesis) loss and Ω = 0; two (below and above Ω) for the
    rotating-frame loss. The weights are those of
    :func:`~flexshaft.analyses.loss.frequency_coefficients` inside each interval."""
    if not red.has_loss:
        return (Branch(0.0, math.inf, _NO_LOSS),)
    if red.internal_damping == "thesis" or speed <= 0:
        return (Branch(0.0, math.inf, frequency_coefficients(red.internal_damping, 1.0, max(speed, 0.0))),)
    below = frequency_coefficients(red.internal_damping, 0.5 * speed, speed)
    above = frequency_coefficients(red.internal_damping, 2.0 * speed, speed)
    return (Branch(0.0, float(speed), below), Branch(float(speed), math.inf, above))


def on_branch(branch: Branch, omega, speed: float):
    """Whether frequencies ``omega`` [rad/s] lie on ``branch`` (closed, widened by the
    synchronous band of :data:`~flexshaft.analyses.loss.SYNCHRONOUS_TOLERANCE`), and > 0."""
    omega = np.asarray(omega, dtype=float)
    band = SYNCHRONOUS_TOLERANCE * np.maximum(np.maximum(np.abs(omega), abs(speed)), 1.0)
    return (omega > 0) & (omega >= branch.low - band) & (omega <= branch.high + band)


def branch_state_matrix(red: ReducedModel, speed: float, weights: LossCoefficients) -> np.ndarray:
    """First-order matrix of one branch's linear problem: the loss-free state matrix
    (:meth:`~flexshaft.analyses.eigen.ReducedModel.state_matrix`) with the complex loss
    stiffness ``w_F F̃ + w_L K̃_lat + w_S K̃_lat S̃`` added to its stiffness block."""
    A = red.state_matrix(speed)
    if not (weights.fixed or weights.lateral or weights.circulatory):
        return A
    nb = red.size
    A = A.astype(complex)
    A[nb : 2 * nb, :nb] -= weights.fixed * red.F + weights.lateral * red.L + weights.circulatory * red.S
    return A


def branch_roots(red: ReducedModel, speed: float, weights: LossCoefficients) -> tuple[np.ndarray, np.ndarray]:
    """Every oscillatory root (Im s > 10⁻⁶ |s|) of one branch's linear problem, sorted by |s|:
    ``(s [rad/s], Y)`` with unit modal coordinates (nb, k), on either side of the line."""
    lam, vec = la.eig(branch_state_matrix(red, speed, weights), check_finite=False)
    keep = _oscillatory(lam)
    vec = vec[: red.size, keep]
    norm = np.linalg.norm(vec, axis=0)
    return lam[keep], vec / np.where(norm > 0, norm, 1.0)


def _oscillatory(lam: np.ndarray) -> np.ndarray:
    """Indices of the oscillatory roots (Im s > 10⁻⁶ |s|) of ``lam``, by increasing |s|."""
    keep = np.flatnonzero(lam.imag > 1e-6 * np.abs(lam))
    return keep[np.argsort(np.abs(lam[keep]))]


def consistent_roots(red: ReducedModel, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """Every oscillatory eigenvalue of the hysteretic problem at one speed, R(Ω) of the module
    docstring: ``(s [rad/s], Y)`` sorted by |s|, unit modal coordinates (nb, k).

    One dense eigen-solve per branch; the roots on their own branch's side, plus the on-line
    roots of the modes whose two branch roots both lie on the wrong side (a lower-branch root
    above Ω paired by MAC with an upper-branch root below it, :func:`line_root`).
    """
    if not red.has_loss:
        return candidates(red, speed)
    return consistent_from(
        red, speed, [(branch, *branch_roots(red, speed, branch.weights)) for branch in branches(red, speed)]
    )


def consistent_values(red: ReducedModel, speed: float) -> np.ndarray:
    """The eigenvalues R(Ω) of :func:`consistent_roots` alone [rad/s], sorted by |s|, for less
    than the cost of every eigenvector.

    Each branch is solved without its vectors (:func:`solved_below`); the pairing of on-line
    roots reads those of the upper branch's roots below the line (the modes below the spin) and
    of the lower branch's roots above it that may match one of them (:func:`_may_pair`), each
    by inverse iteration on its second-order problem (:func:`_null_vectors`). A single branch
    (Ω = 0, the fixed-frame loss) pairs nothing: one eigenvalue solve without vectors.
    """
    return consistent_values_below(red, speed)[0]


def consistent_values_below(red: ReducedModel, speed: float, up_to: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`consistent_values` with the unit modal coordinates (nb, k) of the roots below
    ``up_to`` times the spin (Im s < up_to Ω, up_to >= 1: the lower branch's, by inverse
    iteration, the on-line ones, which its pairing solves anyway, and the upper branch's roots in
    the band Ω <= Im s < up_to Ω, by inverse iteration); the columns of the others may be zero.
    What the every-root check of a passive driveline estimates the error of
    (:mod:`flexshaft.analyses.root_stability`: the roots below the spin and a 1 % band above
    it)."""
    if not red.has_loss:
        return candidates(red, speed)
    parts = branches(red, speed)
    if len(parts) == 1:
        if speed > 0:  # the fixed-frame (thesis) loss: one branch, and roots below the spin
            return consistent_roots(red, speed)
        s = _branch_values(red, speed, parts[0].weights)
        s = s[on_branch(parts[0], s.imag, speed)]
        return s, np.zeros((red.size, s.size), complex)  # at rest no root is below the spin
    lower, upper = parts
    return consistent_from(red, speed, solved_below(red, speed, lower, upper, up_to=up_to)[0])


def solved_below(
    red: ReducedModel, speed: float, lower: Branch, upper: Branch, up_to: float = 1.0
) -> tuple[list, np.ndarray]:
    """The two branches' oscillatory roots as :func:`consistent_values_below` solves them,
    ``[(lower, s, Y), (upper, s, Y)]`` for :func:`consistent_from`, with the vectors it and the callers
    read only (zero columns else); and every eigenvalue of the upper branch's matrix (oscillatory
    or not: how far its neighbours lie, :func:`separated_vectors`).

    Both matrices are solved without vectors. The upper branch's roots below the spin (the wrong
    side: read by the pairing) and those on its own side below ``up_to`` Ω (the caller's band above
    the spin, :func:`consistent_values_below`) get theirs by inverse iteration
    (:func:`_null_vectors`); so do the
    lower branch's roots on its own side (Im s <= Ω: in R(Ω), whose vectors every caller reads;
    :func:`lowest_roots` fills only the upper branch's roots afterwards) and those of its roots
    above the line that the pairing could match to one of the upper roots below it
    (:func:`_may_pair`; none when there are no such upper roots). Where a lower root lies within
    :data:`_SEPARATED` of a neighbour or an inverse iteration fails, the dense solve with every
    vector (:func:`branch_roots`), branch by branch."""
    every = _branch_spectrum(red, speed, upper.weights)
    s_hi = every[_oscillatory(every)]
    wrong = np.flatnonzero(~on_branch(upper, s_hi.imag, speed) & (s_hi.imag < speed))
    # the pairing reads only the wrong side's; the caller, those of its band above the spin too
    band = on_branch(upper, s_hi.imag, speed) & (s_hi.imag < up_to * speed)
    read_hi = np.union1d(wrong, np.flatnonzero(band))
    Y_hi = np.zeros((red.size, s_hi.size), complex)
    Y_hi[:, read_hi] = _null_vectors(red, speed, upper.weights, s_hi[read_hi])
    if not np.isfinite(Y_hi).all():  # an inverse iteration failed: every vector from the dense solve
        s_hi, Y_hi = branch_roots(red, speed, upper.weights)
        every = s_hi
        wrong = np.flatnonzero(~on_branch(upper, s_hi.imag, speed) & (s_hi.imag < speed))
    spectrum_lo = _branch_spectrum(red, speed, lower.weights)
    s_lo = spectrum_lo[_oscillatory(spectrum_lo)]
    read = on_branch(lower, s_lo.imag, speed)  # its own side (Im s > 0 by _oscillatory)
    above = np.flatnonzero(~read & (s_lo.imag > speed))
    if wrong.size and above.size:
        read[above] = _may_pair(red, speed, lower.weights, s_lo[above], Y_hi[:, wrong])
    Y_lo = np.zeros((red.size, s_lo.size), complex)
    vectors = separated_vectors(red, speed, lower.weights, spectrum_lo, s_lo[read])
    if vectors is None:  # a close neighbour or a failed inverse iteration: the dense solve
        s_lo, Y_lo = branch_roots(red, speed, lower.weights)
    else:
        Y_lo[:, read] = vectors
    return [(lower, s_lo, Y_lo), (upper, s_hi, Y_hi)], every


def _may_pair(
    red: ReducedModel, speed: float, weights: LossCoefficients, roots: np.ndarray, Y: np.ndarray
) -> np.ndarray:
    """Which of ``roots`` (a branch's, weights ``weights``) may have a MAC of at least
    :data:`SAME_MODE_MAC` with one of the unit vectors ``Y`` (columns): a bound, from the roots
    alone, that excludes the others without their vectors.

    Why a bound and not a window in |s|: in the modal coordinates (mass-normalised basis,
    ``T(s) = s² I + s D + K``, K = Λ + the loss) the damping D of the bearing dampers couples the
    modes strongly (a damper seen by every mode: ``|D_kl|`` up to ``√(D_kk D_ll)``; on the tuned
    design a MAC of 0.11 between roots nearly three times apart in |s|), so no window in |s|
    follows from the physics.
    The bound: the unit null vector y of ``T(s)`` satisfies, row by row,
    ``|T_kk| |y_k| = |Σ_{l≠k} T_kl y_l|``, so ``|y_k| <= u_k`` for ``u_k = min(1, ‖E_k‖₂/|T_kk|)``
    (E = T off its diagonal, ``|E_kl| <= |s| |D_kl| + |K_kl|``) and, with |y| <= u componentwise,
    ``|y_k| <= (|E| u)_k / |T_kk|`` again (a few such steps); then ``|yᴴ v| <= Σ_k u_k |v_k|``.
    A root is excluded when that bound's square is below half of :data:`SAME_MODE_MAC` for
    every column: it can then match none, and, its MAC being below the threshold, it is neither
    the best match of a column nor a pair of :func:`consistent_from`'s, so the pairs found from the
    other roots' vectors are those from every vector. The factor of two covers a dense solve's
    vector that mixes two nearly double roots (each within its own bound) and the round-off of
    the roots. With an actuator channel that adds to T(s) (not bounded here), every root may
    pair. Cost: a few products of (roots, nb) by (nb, nb), 0.1-0.15 ms for the tuned design's
    ~50 roots above the line, which keeps 15-25 of them."""
    bound = mac_bounds(red, speed, weights, roots, Y)
    if bound is None:
        return np.ones(roots.size, bool)
    return np.any(bound**2 >= 0.5 * SAME_MODE_MAC, axis=1)


def mac_bounds(
    red: ReducedModel, speed: float, weights: LossCoefficients, roots: np.ndarray, Y: np.ndarray
) -> np.ndarray | None:
    """An upper bound of ``|yᴴ v|`` (roots, columns) for the unit null vector y of each of
    ``roots`` (one branch's, weights ``weights``) and each column v of ``Y``, from the roots
    alone (the bound of :func:`_may_pair`); None when an actuator channel adds to T(s)."""
    if any(a.law is not None or a.stiffness or a.damping for a in red.actuators):
        return None
    damping, stiffness = red._speed_parts(speed, weights)
    off_d = np.abs(damping)
    np.fill_diagonal(off_d, 0.0)
    off_k = np.abs(stiffness)
    np.fill_diagonal(off_k, 0.0)
    s = roots[:, None]
    diagonal = np.abs(s * s + s * np.diag(damping) + np.diag(stiffness))  # |T_kk(s)| (roots, nb)
    size = np.abs(s)
    with np.errstate(divide="ignore", invalid="ignore"):  # T_kk = 0: the bound stays 1
        u = np.fmin(1.0, (size * np.linalg.norm(off_d, axis=1) + np.linalg.norm(off_k, axis=1)) / diagonal)
        for _ in range(3):
            u = np.fmin(u, (size * (u @ off_d.T) + u @ off_k.T) / diagonal)
    return u @ np.abs(Y)


def _branch_spectrum(red: ReducedModel, speed: float, weights: LossCoefficients) -> np.ndarray:
    """Every eigenvalue of one branch's first-order matrix [rad/s], without vectors."""
    return la.eigvals(branch_state_matrix(red, speed, weights), check_finite=False, overwrite_a=True)


def _branch_values(red: ReducedModel, speed: float, weights: LossCoefficients) -> np.ndarray:
    """The roots of :func:`branch_roots` without their vectors [rad/s]."""
    lam = _branch_spectrum(red, speed, weights)
    return lam[_oscillatory(lam)]


def _null_vectors(red: ReducedModel, speed: float, weights: LossCoefficients, roots: np.ndarray) -> np.ndarray:
    """Unit modal coordinates y with ``T(s) y = 0`` (one branch's second-order problem,
    :meth:`~flexshaft.analyses.eigen.ReducedModel.newton_terms`) for each of ``roots``, eigenvalues
    of a dense solve: two steps of inverse iteration at the root, which is accurate to round-off,
    so the first step already holds the vector to about the root's error over its distance to
    the next root (a column of NaN where T(s) is singular to working precision)."""
    out = np.empty((red.size, roots.size), complex)
    for k, s in enumerate(roots):
        out[:, k] = _inverse_iteration(red, speed, weights, complex(s))[0]
    return out


def _inverse_iteration(
    red: ReducedModel, speed: float, weights: LossCoefficients, s: complex
) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray] | None]:
    """One column of :func:`_null_vectors` and the LU factors ``(lu, piv)`` of ``T(s)`` it
    solved with (None, and a column of NaN, where T(s) is singular to working precision)."""
    nb = red.size
    start = np.full(nb, nb**-0.5, complex)
    T, _ = red.newton_terms(s, speed, weights, start)
    lu, piv, info = la.lapack.zgetrf(T, overwrite_a=True)
    y = start
    for _ in range(2):
        if info != 0:  # singular to working precision, or a bad argument
            return np.full(nb, np.nan, complex), None
        y, info = la.lapack.zgetrs(lu, piv, y)
        y = y / np.linalg.norm(y)
    return y, (lu, piv)


def consistent_from(red: ReducedModel, speed: float, solved: list) -> tuple[np.ndarray, np.ndarray]:
    """R(Ω) and its vectors from every branch's oscillatory roots, ``solved``: ``(branch, s, Y)``
    by branch (:func:`consistent_roots`). The pairing of on-line roots reads the vectors of the
    roots on the wrong side of the line only; the others are passed through."""
    parts = [(branch, s, Y, on_branch(branch, s.imag, speed)) for branch, s, Y in solved]
    out_s = [s[ok] for _, s, _, ok in parts]
    out_y = [Y[:, ok] for _, _, Y, ok in parts]
    if len(parts) == 2:
        (lower, s_lo, Y_lo, ok_lo), (upper, s_hi, Y_hi, ok_hi) = parts
        above = np.flatnonzero(~ok_lo & (s_lo.imag > speed))  # lower-branch roots above the line
        below = np.flatnonzero(~ok_hi & (s_hi.imag < speed))  # upper-branch roots below it
        if above.size and below.size:
            mac = np.abs(Y_lo[:, above].conj().T @ Y_hi[:, below]) ** 2
            for i, j in zip(*np.nonzero(mac >= SAME_MODE_MAC)):
                if mac[i].argmax() != j or mac[:, j].argmax() != i:
                    continue  # pair only mutual best matches
                a, b = above[i], below[j]
                root = line_root(red, speed, lower.weights, upper.weights, (s_lo[a], Y_lo[:, a]), (s_hi[b], Y_hi[:, b]))
                if root is not None:
                    out_s.append(np.array([root[0]]))
                    out_y.append(root[1][:, None])
    s = np.concatenate(out_s)
    Y = np.hstack(out_y)
    order = np.argsort(np.abs(s), kind="stable")
    return s[order], Y[:, order]


def _mix(a: LossCoefficients, b: LossCoefficients, mu: float) -> LossCoefficients:
    """``(1 − μ) a + μ b`` weight by weight."""
    return LossCoefficients(
        (1 - mu) * a.fixed + mu * b.fixed,
        (1 - mu) * a.lateral + mu * b.lateral,
        (1 - mu) * a.circulatory + mu * b.circulatory,
    )


def line_root(
    red: ReducedModel, speed: float, lower: LossCoefficients, upper: LossCoefficients, low_root, high_root
) -> tuple[complex, np.ndarray] | None:
    """The on-line eigenvalue of a mode whose branch roots straddle the line the wrong way.

    ``low_root = (s₋, y₋)``: the mode's root of the lower branch (weights ``lower``), with
    Im s₋ > Ω; ``high_root = (s₊, y₊)``: its root of the upper branch, Im s₊ < Ω. Along
    ``T_μ = T(weights (1 − μ) lower + μ upper)`` the root moves from s₋ (μ = 0) to s₊ (μ = 1),
    so Im s(μ) − Ω changes sign: regula falsi (Illinois) on μ, each evaluation a Newton solve
    of the linear problem T_μ started from the interpolated root, until |Im s − Ω| is inside
    the synchronous band. Returns ``(s, y)`` with Im s = Ω, or None when the root cannot be
    followed in μ (an evaluation that does not converge).
    """
    (s_lo, y_lo), (s_hi, y_hi) = low_root, high_root
    phase = np.vdot(y_lo, y_hi)
    y_hi = y_hi * (np.conj(phase) / abs(phase) if abs(phase) > 0 else 1.0)
    band = SYNCHRONOUS_TOLERANCE * max(abs(speed), 1.0)
    a, b = 0.0, 1.0
    ga, gb = s_lo.imag - speed, s_hi.imag - speed
    side = 0
    for _ in range(60):
        mu = a + ga / (ga - gb) * (b - a)
        s, y, converged = newton(
            red, speed, (1 - mu) * s_lo + mu * s_hi, (1 - mu) * y_lo + mu * y_hi, weights=_mix(lower, upper, mu)
        )
        if not converged:
            return None
        g = s.imag - speed
        if abs(g) <= band or b - a <= 1e-15:
            return s, y
        if g > 0:
            a, ga = mu, g
            if side == +1:
                gb *= 0.5
            side = +1
        else:
            b, gb = mu, g
            if side == -1:
                ga *= 0.5
            side = -1
    return None


def _polish(
    red: ReducedModel, speed: float, s: np.ndarray, Y: np.ndarray, deferred: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray] | None:
    """The roots ``s`` of a dense eigen-solve refined by Newton's method on their own branch's
    problem: a dense solve of the first-order matrix is accurate to about ε‖A‖ in absolute
    terms, which a nearly massless member (‖A‖ of its stiff, light modes ~1e8 rad²/s² and
    more) turns into 1e-9 of a low mode; Newton on the nb × nb second-order problem brings
    each root to the convergence tolerance relative to its own |s|. A refined root is kept
    only when it converged on the same branch and is the same mode (MAC with the dense
    solve's vector at least :data:`SAME_MODE_MAC`); an on-line root (:func:`line_root`) and a
    root Newton cannot refine keep the dense solve's value.

    ``deferred`` (boolean, by root): roots of the last branch whose vectors :func:`lowest_roots`
    left to this refinement (``defer=True``): each gets its vector by :func:`_inverse_iteration`
    on the last branch's problem here, and when that is its own branch's, Newton's first step
    solves with the same LU factors (the matrix T(s) is the same: one factorisation a root where
    there were two; the numbers are those of :func:`separated_vectors` followed by this
    refinement, to the bit). None when one of those inverse iterations fails (the caller's
    dense solve with every vector, as :func:`lowest_roots` falls back to)."""
    s, Y = s.copy(), Y.copy()
    parts = branches(red, speed)
    for k in range(s.size):
        branch = next((b for b in parts if on_branch(b, s[k].imag, speed)), None)
        factor = None
        if deferred is not None and deferred[k]:
            Y[:, k], factor = _inverse_iteration(red, speed, parts[-1].weights, complex(s[k]))
            if not np.isfinite(Y[:, k]).all():
                return None
            if branch is not parts[-1]:
                factor = None
        if branch is None:
            continue
        root, vec, converged = newton(red, speed, s[k], Y[:, k], weights=branch.weights, factor=factor)
        same = abs(np.vdot(Y[:, k], vec)) ** 2 >= SAME_MODE_MAC * np.vdot(Y[:, k], Y[:, k]).real
        if converged and same and on_branch(branch, root.imag, speed):
            s[k], Y[:, k] = root, vec
    return s, Y


#: Smallest distance, relative to |s|, from a root to every other eigenvalue of its branch's
#: matrix for the root's vector to be found by inverse iteration (:func:`separated_vectors`).
#: Two steps leave a neighbour's share at about (e/g)², e the dense solve's relative error of the
#: root and g this gap, where the dense solve's own vector errs by about e/g; either start is
#: refined by Newton's method wherever a root is (:func:`_polish`, the tracking's). Closer
#: neighbours (a double root: the two whirls of an axisymmetric rotor without gyroscopic split,
#: for which inverse iteration from one start would return one vector twice) take their vectors
#: from the dense solve.
_SEPARATED = 1e-6


def lowest_roots(
    red: ReducedModel, speed: float, n_modes: int, window: float = 0.0, defer: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """R(Ω) of :func:`consistent_roots` with the vectors solved only where they are read: ``(s,
    Y)`` sorted by |s|, unit modal coordinates for the ``n_modes`` of
    :func:`~flexshaft.analyses.eigen.lowest_modes` and for the roots within ``window`` (relative
    to |s|) of one of them, zero columns for the others.

    Each branch's matrix is solved without its vectors (:func:`solved_below`: of two, the lower
    branch's roots below the spin and those :func:`consistent_from` may pair get theirs there); the
    upper roots wanted get theirs by inverse iteration (:func:`separated_vectors`). Where that
    cannot be trusted (a neighbour within :data:`_SEPARATED`), :func:`consistent_roots` as it is.
    ``defer=True`` leaves those upper vectors to :func:`_polish` (zero columns, after the
    :data:`_SEPARATED` check), which factors each root's T(s) once for its vector and its first
    Newton step (:func:`damped_modes`).
    """
    parts = branches(red, speed)
    if red.has_loss:
        if len(parts) == 2:
            solved, every = solved_below(red, speed, *parts)
            s, Y = consistent_from(red, speed, solved)
        else:
            every = _branch_spectrum(red, speed, parts[0].weights)
            s = every[_oscillatory(every)]
            s = s[on_branch(parts[0], s.imag, speed)]
            Y = np.zeros((red.size, s.size), complex)
        wanted = lowest_modes(s, n_modes)
        near = np.abs(s[:, None] - s[None, wanted]) <= window * np.abs(s[None, wanted])
        needed = np.zeros(s.size, bool)
        needed[wanted] = True
        needed |= near.any(axis=1)
        missing = np.flatnonzero(needed & ~np.any(Y, axis=0))  # roots of the last branch (above the spin)
        if defer:
            if _separated(every, s[missing]):
                return s, Y
            return consistent_roots(red, speed)
        vectors = separated_vectors(red, speed, parts[-1].weights, every, s[missing])
        if vectors is not None:
            Y[:, missing] = vectors
            return s, Y
    return consistent_roots(red, speed)


def separated_vectors(
    red: ReducedModel, speed: float, weights: LossCoefficients, every: np.ndarray, roots: np.ndarray
) -> np.ndarray | None:
    """Unit modal coordinates of ``roots``, eigenvalues of one branch's matrix (``every``: all of
    them), by :func:`_null_vectors`; None when a root lies within :data:`_SEPARATED` of another
    eigenvalue or an inverse iteration failed."""
    if not _separated(every, roots):
        return None
    vectors = _null_vectors(red, speed, weights, roots)
    return vectors if np.isfinite(vectors).all() else None


def _separated(every: np.ndarray, roots: np.ndarray) -> bool:
    """Whether each of ``roots`` lies farther than :data:`_SEPARATED` (relative to |s|) from
    every other eigenvalue of ``every`` (its branch's matrix: the root itself is one of them)."""
    for s in roots:
        gaps = np.sort(np.abs(every - s))  # the root itself first (the same number)
        if gaps.size > 1 and gaps[1] <= _SEPARATED * abs(s):
            return False
    return True


def damped_modes(red: ReducedModel, speed: float, n_modes: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``n_modes`` lowest damped modes at one speed, each at its own frequency.

    Returns ``(s, Y)`` in increasing damped frequency Im s (then |s|), Y modal coordinates:
    among the eigenvalues R(Ω) of :func:`consistent_roots` (a mode in a fold near the
    synchronous line has two), the ``n_modes`` of
    :func:`~flexshaft.analyses.eigen.lowest_modes` (lowest damped frequency among the 2n of
    lowest |s|: the modes every table numbers), refined by :func:`_polish`. Divergent roots
    (real s > 0, :func:`~flexshaft.analyses.eigen.spectrum`) are modes too: they are returned
    first, with Im s = 0 (ζ = −1) as computed from the loss-free state matrix (the hysteretic
    loss is defined for harmonic motion only and cannot hold a static divergence). A model that
    cannot diverge (:attr:`~flexshaft.analyses.eigen.ReducedModel.may_diverge` False: no real
    root s > 0 exists) skips that solve.
    """
    out_s, out_y = lowest_roots(red, speed, n_modes, defer=True)
    wanted = lowest_modes(out_s, n_modes)
    polished = _polish(red, speed, out_s[wanted], out_y[:, wanted], ~np.any(out_y[:, wanted], axis=0))
    if polished is None:  # an inverse iteration failed: every vector from the dense solves
        out_s, out_y = consistent_roots(red, speed)
        wanted = lowest_modes(out_s, n_modes)
        polished = _polish(red, speed, out_s[wanted], out_y[:, wanted])
        assert polished is not None  # nothing deferred
    out_s, out_y = polished
    if red.may_diverge:
        _, _, Y_div, div = spectrum(red, speed)
        if div.size:
            out_s = np.concatenate([out_s, div.astype(complex)])
            out_y = np.hstack([out_y, Y_div.astype(complex)])
    order = np.lexsort((np.abs(out_s), out_s.imag))[:n_modes]
    return out_s[order], out_y[:, order]
