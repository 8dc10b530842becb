r"""Synchronous resonance speeds of a projected model: the peaks a spin-up scan can step over.

The unbalance response ``Z(Ω, Ω) q = Ω² Q₁`` (Z the dynamic stiffness at ω = Ω,
:mod:`flexshaft.analyses.banded`) peaks near the real parts of the complex roots Ω_k of
``det Z(Ω, Ω) = 0``. For one lightly damped mode ``Z ≈ k − m Ω² + i c Ω`` the roots are
``Ω = ±ω_d + i ζ ω_n``: the peak sits at Re Ω_k and its half-power bandwidth is ``2 |Im Ω_k|``
(2ζω_n). A scan whose spacing exceeds that bandwidth can step over the peak: the samples on
either side only see its flanks, and when a second, broader resonance lies close by the two show
as one bump whose refinement follows the broader one.

:func:`synchronous_roots` finds those roots on a Galerkin model ``Z_r(Ω) = Vᴴ Z(Ω, Ω) V`` (V an
orthonormal basis of the scan's responses, so it holds the modes the imbalance excites), a sum
``Σ_j w_j(Ω) A_j`` of the solver's projected terms with scalar weights
(:meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.term_weights`). Along ω = Ω the weights
are polynomials of degree at most two in Ω (mass −Ω², gyroscopic iΩ², damping iΩ, stiffness
and loss constants, a PD law kp + i kd Ω) except a controller law with poles (a filtered
derivative, a lag), which is rational. Each weight is fitted by a quadratic in Ω on a window of
the scan; the window is halved until every fit agrees with the weights to :data:`FIT_TOLERANCE`
of each weight's size (one window for a PD-controlled driveline, the fit is then exact), and the
quadratic eigenvalue problem ``(B₀ + x B₁ + x² B₂) u = 0`` of each window (x the window's
centred and scaled speed) is solved in its companion linearisation by QZ. A root of the
projected model is an approximation of the full model's (the basis spans its mode to the
accuracy it spans the scan's responses); the caller treats it as a place to look, checked by full
solves (:func:`flexshaft.analyses.criticals.lateral_critical_speeds`).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg

from flexshaft.analyses.banded import BandedHarmonicSolver

__all__ = ["FIT_TOLERANCE", "synchronous_roots"]

#: Largest error of a window's quadratic fit of each weight, relative to that weight's largest
#: magnitude on the window. A root moves by about the relative error of the weights that make
#: it (each term's share of ``Z`` is perturbed by that fraction): 1e-8 of a speed is far below
#: the narrowest bandwidth a refinement resolves (a 20th of ``2 |Im Ω|``, with ζ ≥ 1e-6).
FIT_TOLERANCE = 1e-8
#: Halvings of the scan before a window is taken with the fit it has (64 windows at most).
_MAX_DEPTH = 6
#: Points at which a window's fit is checked (the fit passes through three of them).
_CHECK_POINTS = 9


def synchronous_roots(solver: BandedHarmonicSolver, terms: np.ndarray, low: float, high: float) -> np.ndarray:
    """Roots Ω of ``det Σ_j w_j(Ω, Ω) A_j = 0`` whose real part lies in ``[low, high]``.

    Parameters
    ----------
    solver : BandedHarmonicSolver
        The model's solver: the weights w_j of its non-zero terms.
    terms : ndarray
        The projected terms ``A_j = Vᴴ T_j V`` (n_terms, r, r), in the order of
        :meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.term_weights`.
    low, high : float
        The speed range [rad/s], 0 < low < high.

    Returns
    -------
    ndarray
        Complex roots [rad/s], in order of their real parts; a damped resonance has Im Ω > 0.
    """
    if not 0.0 < low < high:
        raise ValueError(f"the speed range must satisfy 0 < low < high (got {low!r}, {high!r})")
    terms = np.asarray(terms, dtype=complex)
    out = [root for a, b, fit in _windows(solver, float(low), float(high)) for root in _window_roots(terms, a, b, fit)]
    roots = np.array(out, dtype=complex)
    return roots[np.argsort(roots.real, kind="stable")]


def _windows(solver: BandedHarmonicSolver, low: float, high: float, depth: int = 0):
    """``(a, b, coefficients)`` of each window of [low, high] on which the weights' quadratic
    fit (coefficients (3, n_terms) of 1, x, x² with x = (Ω − mid)/half) holds."""
    mid, half = 0.5 * (low + high), 0.5 * (high - low)
    nodes = np.cos(np.pi * (np.arange(3) + 0.5) / 3.0)  # Chebyshev points: a well-conditioned fit
    at = mid + half * nodes
    fit = np.linalg.solve(np.vander(nodes, 3, increasing=True), solver.term_weights(at, at))
    x = np.linspace(-1.0, 1.0, _CHECK_POINTS)
    exact = solver.term_weights(mid + half * x, mid + half * x)
    error = np.abs(np.vander(x, 3, increasing=True) @ fit - exact).max(axis=0)
    size = np.abs(exact).max(axis=0)
    if depth >= _MAX_DEPTH or np.all(error <= FIT_TOLERANCE * np.maximum(size, np.finfo(float).tiny)):
        yield low, high, fit
        return
    yield from _windows(solver, low, mid, depth + 1)
    yield from _windows(solver, mid, high, depth + 1)


def _window_roots(terms: np.ndarray, low: float, high: float, fit: np.ndarray) -> list[complex]:
    """The roots of one window's quadratic eigenvalue problem with real part in [low, high]."""
    r = terms.shape[1]
    B0, B1, B2 = (np.tensordot(fit[m], terms, axes=1) for m in range(3))
    scale = max(float(np.abs(B).max()) for B in (B0, B1, B2))
    if not scale > 0.0:
        return []
    B0, B1, B2 = B0 / scale, B1 / scale, B2 / scale
    eye, zero = np.eye(r), np.zeros((r, r))
    A = np.block([[zero, eye], [-B0, -B1]])
    E = np.block([[eye, zero], [zero, B2]])
    x = scipy.linalg.eig(A, E, right=False, check_finite=False)
    mid, half = 0.5 * (low + high), 0.5 * (high - low)
    roots = mid + half * x[np.isfinite(x)]
    keep = (roots.real >= low) & (roots.real <= high)
    return list(roots[keep])
