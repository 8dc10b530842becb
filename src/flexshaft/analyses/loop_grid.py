r"""The frequency grid of the magnetic-bearing loops (:mod:`flexshaft.analyses.bearing_loops`).

|S| = det Z_o/det Z_c peaks only near the closed-loop poles: a lightly damped pole
s = −ζω_n + iω_d makes a peak at ω_d of half-power width 2ζω_n, far narrower than any
affordable logarithmic grid. The grid (:func:`frequency_grid`) is therefore a coarse logarithmic
one over the frequency range (200 points by default: 5.1 % steps over 0.1 Hz-2 kHz) plus, for
every closed-loop pole with ζ < :data:`RESOLVED_DAMPING` in the range, the points ω_d and
ω_d ± ζ ω_n/2 (:data:`AROUND`): each such peak is sampled at its top and at its half width (the
screening resolution samples the top only). Above the highest pole given (the poles of a
truncated basis), the undamped natural frequencies (:func:`natural_frequencies`) stand for the
poles with a nominal ζ = 1e-3. The margins are refined between its points
(:mod:`flexshaft.analyses.loop_margins`).

Only the natural frequencies of modes the loops can see stand in (``visible``: the blocks of
:meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.coupled`): the dynamic stiffness Z(ω, Ω)
of a driveline splits into uncoupled blocks (the shaft's torsion and axial motion: on the tuned
design 38 of its 343 free DOFs, no term of Z couples them to the lateral DOFs), and each loop's
T = G sᵀ Z_c⁻¹ a involves only the blocks its actuation and sensing rows a, s touch: with Z_c
block diagonal, sᵀ Z_c⁻¹ a = s_Bᵀ Z_B⁻¹ a_B over those blocks B, so det Z_c's factor from any
other block cancels from S = det Z_o/det Z_c (Z_o differs from Z_c in the loop's own rows only)
and the natural frequencies of that block are no poles of any loop's S. Their grid points (10
of the tuned design's 74 above 271 Hz) would be mere samples of a smooth stretch, which the
logarithmic grid is there to sample.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO, dense_spectrum
from flexshaft.analyses.reduced_basis import BASIS_SHIFT
from flexshaft.assembly.model import Model

__all__ = ["AROUND", "RESOLVED_DAMPING", "VISIBLE", "frequency_grid", "natural_frequencies"]

#: Closed-loop poles below this damping ratio get grid points at their peak (module docstring);
#: above it the coarse grid resolves the peak (half-power width 2ζ ≥ 40 % of the frequency).
RESOLVED_DAMPING = 0.2
#: Offsets k of the grid points ω_d + k ζ ω_n around a lightly damped pole, by the number of
#: points per pole (``peak_samples``): its top and half width, or its top only.
AROUND = {3: (-0.5, 0.0, 0.5), 1: (0.0,)}
#: A mode of the whole spectrum is one of the visible blocks' when its largest component on
#: their DOFs is at least this fraction of its largest: a mode of another block has only
#: round-off there (the eigensolver's backward error, below 1e-10 on the embedded designs),
#: one of a visible block no component elsewhere (ratio 1); two modes of different blocks
#: with one eigenvalue to round-off may come out as any rotation of the two, and then at least
#: one of the pair keeps a component of order one there, so their common frequency stays.
VISIBLE = 1e-6


def natural_frequencies(model: Model, low: float, high: float, visible: np.ndarray | None = None) -> np.ndarray:
    """Undamped natural frequencies of (K + K_a, M) in (low, high] [rad/s], ascending (dense:
    up to :data:`~flexshaft.analyses.dense_spectrum.WHOLE_DENSE_BASIS_UP_TO` free DOFs read off
    the model's whole spectrum, which its modal bases have computed already; above, only those
    eigenvalues computed; empty above 900 free DOFs). ``visible`` (a mask of the free DOFs, a
    union of uncoupled blocks of Z: the banded solver's
    :meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.coupled`): only the modes of those
    blocks (the whole spectrum's modes with a component there, :data:`VISIBLE`; the subset
    solve on those DOFs)."""
    free = model.dofs.free
    if free.size <= WHOLE_DENSE_BASIS_UP_TO:
        mu, Phi, _ = dense_spectrum(model, BASIS_SHIFT)
        w2 = 1.0 / mu - BASIS_SHIFT
        keep = (w2 > low * low) & (w2 <= high * high)
        if visible is not None and keep.any():
            shapes = np.abs(Phi[:, keep])
            seen = shapes[np.asarray(visible, dtype=bool)].max(axis=0, initial=0.0)
            keep[keep] = seen >= VISIBLE * shapes.max(axis=0)
        return np.sqrt(np.clip(np.sort(w2[keep]), 0.0, None))
    if free.size > 900:
        return np.zeros(0)
    import scipy.linalg as la

    if visible is not None:
        free = free[np.asarray(visible, dtype=bool)]
    K = (model.K + model.Kp)[free][:, free].toarray()
    M = model.M[free][:, free].toarray()
    # scipy-stubs types the eigvals_only overloads without the generalized drivers, which scipy accepts
    w2 = la.eigh(K, M, eigvals_only=True, subset_by_value=(low * low, high * high), driver="gvx")  # type: ignore[call-overload]
    return np.sqrt(np.clip(w2, 0.0, None))


def frequency_grid(
    model: Model, frequency_range, n_points: int, poles: np.ndarray, around=AROUND[3], visible: np.ndarray | None = None
) -> np.ndarray:
    """Logarithmic grid [rad/s] with points at the peaks of the lightly damped ``poles``
    (module docstring); above the highest pole given, at the undamped natural frequencies with
    a nominal width of 1e-3 (poles of a truncated basis), those of the blocks of free DOFs
    ``visible`` only when given (:func:`natural_frequencies`)."""
    low, high = 2 * np.pi * frequency_range[0], 2 * np.pi * frequency_range[1]
    grid = [np.geomspace(low, high, n_points)]
    poles = np.asarray(poles, dtype=complex)
    poles = poles[(poles.imag > 0) & np.isfinite(poles)]
    top = float(np.max(np.abs(poles), initial=0.0))
    if top < high:
        natural = natural_frequencies(model, top, high, visible)
        natural = natural[(natural > top) & (natural < high)]
        poles = np.concatenate([poles, natural * (-1e-3 + 1j)])
    natural = np.abs(poles)
    zeta = -poles.real / np.where(natural > 0, natural, 1.0)
    light = (np.abs(zeta) < RESOLVED_DAMPING) & (poles.imag > low) & (poles.imag < high)
    if light.any():
        width = np.maximum(np.abs(zeta[light]) * natural[light], 1e-9 * natural[light])
        grid.append((poles.imag[light][:, None] + np.outer(width, around)).ravel())
    out = np.unique(np.concatenate(grid))
    out = out[(out >= low) & (out <= high)]
    # points closer than 1e-7 relative (the same pole of both lateral planes) are one: a
    # near-duplicate would split a local maximum between two points and narrow its bracket
    return out[np.concatenate([[True], np.diff(out) > 1e-7 * out[1:]])]
