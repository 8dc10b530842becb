r"""The frequency grid of the magnetic-bearing loops (:mod:`flexshaft.analyses.bearing_loops`).

|S| = det Z_o/det Z_c peaks only near the closed-loop poles: a lightly damped pole
s = −ζω_n + iω_d makes a peak at ω_d of half-power width 2ζω_n, far narrower than any
affordable logarithmic grid. The grid (:func:`frequency_grid`) is therefore a coarse logarithmic
one over the frequency range (200 points by default: 2.2 % steps over 0.1 Hz-2 kHz) plus, for
every closed-loop pole with ζ < :data:`RESOLVED_DAMPING` in the range, the points ω_d and
ω_d ± ζ ω_n/2 (:data:`AROUND`): each such peak is sampled at its top and at its half width (the
screening resolution samples the top only). Above the highest pole given (the poles of a
truncated basis), the undamped natural frequencies (:func:`natural_frequencies`) stand for the
poles with a nominal ζ = 1e-3. The margins are refined between its points
(:mod:`flexshaft.analyses.loop_margins`).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO, dense_spectrum
from flexshaft.analyses.eigen import BASIS_SHIFT
from flexshaft.assembly.model import Model

__all__ = ["AROUND", "RESOLVED_DAMPING", "frequency_grid", "natural_frequencies"]

#: Closed-loop poles below this damping ratio get grid points at their peak (module docstring);
#: above it the coarse grid resolves the peak (half-power width 2ζ ≥ 40 % of the frequency).
RESOLVED_DAMPING = 0.2
#: Offsets k of the grid points ω_d + k ζ ω_n around a lightly damped pole, by the number of
#: points per pole (``peak_samples``): its top and half width, or its top only.
AROUND = {3: (-0.5, 0.0, 0.5), 1: (0.0,)}


def natural_frequencies(model: Model, low: float, high: float) -> np.ndarray:
    """Undamped natural frequencies of (K + K_a, M) in (low, high] [rad/s], ascending (dense:
    up to :data:`~flexshaft.analyses.dense_spectrum.WHOLE_DENSE_BASIS_UP_TO` free DOFs read off
    the model's whole spectrum, which its modal bases have computed already; above, only those
    eigenvalues computed; empty above 900 free DOFs)."""
    free = model.dofs.free
    if free.size <= WHOLE_DENSE_BASIS_UP_TO:
        w2 = np.sort(1.0 / dense_spectrum(model, BASIS_SHIFT)[0] - BASIS_SHIFT)
        return np.sqrt(np.clip(w2[(w2 > low * low) & (w2 <= high * high)], 0.0, None))
    if free.size > 900:
        return np.zeros(0)
    import scipy.linalg as la

    K = (model.K + model.Kp)[free][:, free].toarray()
    M = model.M[free][:, free].toarray()
    # scipy-stubs types the eigvals_only overloads without the generalized drivers, which scipy accepts
    w2 = la.eigh(K, M, eigvals_only=True, subset_by_value=(low * low, high * high), driver="gvx")  # type: ignore[call-overload]
    return np.sqrt(np.clip(w2, 0.0, None))


def frequency_grid(model: Model, frequency_range, n_points: int, poles: np.ndarray, around=AROUND[3]) -> np.ndarray:
    """Logarithmic grid [rad/s] with points at the peaks of the lightly damped ``poles``
    (module docstring); above the highest pole given, at the undamped natural frequencies with
    a nominal width of 1e-3 (poles of a truncated basis)."""
    low, high = 2 * np.pi * frequency_range[0], 2 * np.pi * frequency_range[1]
    grid = [np.geomspace(low, high, n_points)]
    poles = np.asarray(poles, dtype=complex)
    poles = poles[(poles.imag > 0) & np.isfinite(poles)]
    top = float(np.max(np.abs(poles), initial=0.0))
    if top < high:
        natural = natural_frequencies(model, top, high)
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
