r"""A-posteriori error of the reduced eigenvalues against the full (unreduced) eigenproblem.

A reduced eigenvalue s with modal coordinates y solves the Galerkin projection
``Φᵀ T(s) Φ y = 0`` of the full problem ``T(s) x = 0`` (M, Ω G, dampers, stiffness, loss and
actuators on every free DOF; the same matrix polynomial, loss weights and controller laws as
:meth:`~flexshaft.analyses.eigen.ReducedModel.newton_terms` in modal coordinates). Split the
free DOFs into the basis span Φ and a K_σ-orthogonal complement Ψ (``K_σ = K + K_a + σM``, σ
the basis shift). The exact eigenvalue s* makes the Schur complement
``S(s) = T₁₁ − T₁₂ T₂₂⁻¹ T₂₁`` singular; to first order in the distance from s,

.. math:: s^* − s ≈ δ = \frac{z^T T_{12} T_{22}^{-1} T_{21} y}{z^T T_{11}'(s)\, y}
                    = \frac{r_l^T\, Ψ T_{22}^{-1} Ψ^T\, r}{z^T T_r'(s)\, y},

with ``r = T(s) Φ y`` the full residual, ``r_l = T(s)ᵀ Φ z`` the left one (z the reduced left
eigenvector, ``T_r(s)ᵀ z = 0``; no complex conjugate: the bilinear form). The complement holds
only the modes above the basis, where T(s) is dominated by the static stiffness:
``T₂₂ = ΨᵀK_σΨ + Ψᵀ(T(s) − K_σ)Ψ``, and one Neumann term of its inverse gives, with
``u = K_σ⁻¹ r`` and ``v = K_σ⁻¹ r_l`` (Φᵀr = 0 = Φᵀr_l by the Galerkin condition, so these
are exactly the complement's static flexibility ``Ψ(ΨᵀK_σΨ)⁻¹Ψᵀ`` applied to r and r_l),

.. math:: δ ≈ \frac{2\, r_l^T u − v^T T(s)\, u}{z^T T_r'(s)\, y}.

What is neglected: the second Neumann term, relative size ``((|s|/ω_c)² + η)²`` with ω_c the
lowest frequency of the complement (above every basis frequency) and η the loss factor (the
complement's loss stiffness is η of its stiffness, not small with a lossy member: 2-3 % of the
correction at η = 0.2, tests/test_eigen_error_rotating_loss_reference.py), and the quadratic
term of the expansion in δ, relative size |δ|/gap. Both are small when the basis reaches well above the
modes tracked, which is what makes the estimate trustworthy: it is an estimate of the error
(tests/test_eigen_accuracy.py checks it within a factor 3 of the true error against full dense
eigensolutions), not a rigorous bound. ``|δ|/|s|`` is reported as the relative eigenvalue error.

Cost: per speed, two products of the basis with the modes' coordinates, about ten sparse
products with the free-DOF matrices, one solve with the K_σ factor for 4 columns a mode and an
nb × nb LU a mode (the left eigenvector, one step of inverse iteration). A basis of every free
DOF (nb = n, ``flexshaft modes --n-modes 500`` on the tuned design's 343) leaves no complement
Ψ: the reduced problem is the full one and δ = 0 exactly, returned without any of that (the
computed δ was round-off, 9e-27 of |s| at most there, for about 1 s of CPU).
"""

from __future__ import annotations

import contextlib
import functools
from collections.abc import Callable
from typing import NamedTuple, Protocol, TypeVar

import numpy as np
import scipy.linalg as la
import scipy.sparse as sp

from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO
from flexshaft.analyses.eigen import ReducedModel, reduce, viscous_model
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.analyses.loss import LossCoefficients, eigen_coefficients
from flexshaft.analyses.reduced_basis import FullOperators
from flexshaft.assembly.model import Model

__all__ = [
    "EIGENVALUE_TOLERANCE",
    "accuracy_text",
    "accurate_basis",
    "accurate_bases",
    "accurate_reduction",
    "check_tolerance",
    "eigenvalue_corrections",
    "eigenvalue_errors",
    "tracked_errors",
    "tracked_to_accuracy",
    "with_error_estimate",
]

_NO_LOSS = LossCoefficients(0.0, 0.0, 0.0)
#: Most bytes of the modes' dense matrices T_k that :func:`eigenvalue_corrections` holds at once.
_CHUNK_BYTES = 32 * 2**20
#: Most bytes of the largest temporaries of the columns :func:`tracked_errors` estimates at once
#: (a core's cache: larger groups were slower on a loaded machine, :func:`tracked_errors`).
_GROUP_BYTES = 2**20


class _Curves(Protocol):
    """Tracked curves: eigenvalues (n_speeds, n_modes) and the modal coordinates per speed."""

    @property
    def eigenvalues(self) -> np.ndarray: ...

    @property
    def states(self) -> list: ...


_C = TypeVar("_C", bound=_Curves)


def eigenvalue_errors(
    red: ReducedModel, speed: float, s: np.ndarray, Y: np.ndarray, viscous: LossCoefficients | None = None
) -> np.ndarray:
    """Estimated relative error ``|s* − s| / |s|`` of each reduced eigenvalue (module docstring).

    Parameters
    ----------
    red : ReducedModel
        The reduced model the eigenvalues were computed on (with its full operators).
    speed : float
        Spin speed Ω [rad/s].
    s : ndarray
        Reduced eigenvalues [rad/s], (m,), Im s > 0.
    Y : ndarray
        Their modal coordinates (nb, m).
    viscous : LossCoefficients or None
        The viscous internal-damping weights of the problem solved (None: the hysteretic loss
        at each mode's own frequency, or none when the model has no loss).

    Returns
    -------
    ndarray
        (m,) estimated relative errors [-] (NaN where the reduced model carries no full
        operators, e.g. one assembled by hand).
    """
    s = np.asarray(s, dtype=complex)
    return _relative(eigenvalue_corrections(red, speed, s, Y, viscous), s)


def _relative(delta: np.ndarray, s: np.ndarray) -> np.ndarray:
    """The relative eigenvalue error ``|δ| / |s|`` of corrections δ to eigenvalues s."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.abs(delta) / np.abs(s)


def eigenvalue_corrections(
    red: ReducedModel, speed: float, s: np.ndarray, Y: np.ndarray, viscous: LossCoefficients | None = None
) -> np.ndarray:
    """The estimated correction δ ≈ s* − s [rad/s] of each reduced eigenvalue (see
    :func:`eigenvalue_errors` for the parameters)."""
    s = np.asarray(s, dtype=complex).ravel()
    return _corrections(red, np.full(s.size, float(speed)), s, Y, None if viscous is None else [viscous] * s.size)


def _corrections(
    red: ReducedModel, speeds: np.ndarray, s: np.ndarray, Y: np.ndarray, viscous: list[LossCoefficients] | None
) -> np.ndarray:
    """:func:`eigenvalue_corrections` of columns at speeds of their own: ``speeds[k]`` and (the
    viscous method) ``viscous[k]`` are column k's. Every step is column by column (each mode's
    left vector its own solve, the sparse products and the K_σ solve per column), so the columns
    of several speeds go through each product and solve at once, as those of one speed do."""
    Y = np.asarray(Y, dtype=complex).reshape(red.size, s.size)
    ops = red.full
    if ops is None or any(a.rows_full is None for a in red.actuators) or s.size == 0:
        return np.full(s.size, np.nan + 0j)
    products = _products(red)
    if not products.consistent:
        return np.full(s.size, np.nan + 0j)
    if red.size >= ops.size:  # the basis spans every free DOF: no complement Ψ, so δ = 0 exactly
        return np.zeros(s.size, complex)
    loss: list[LossCoefficients | None] = [None] * s.size if viscous is None else list(viscous)
    weights = [_weights(red, float(speed), sk, v) for speed, sk, v in zip(speeds, s, loss)]
    models: dict[LossCoefficients, tuple[ReducedModel, np.ndarray | None]] = {}  # each weights' viscous model
    dTY = np.empty_like(Y)
    Z = np.empty_like(Y)
    # the modes' matrices T_k (nb x nb each) a chunk at a time: all at once they held
    # m·nb²·16 bytes (646 MB for `flexshaft modes --n-modes 500`, 343 modes of a 343-vector
    # basis); each mode's left vector is its own solve, the same in any chunk
    chunk = max(1, int(_CHUNK_BYTES // (16 * red.size * red.size)))
    for start in range(0, s.size, chunk):
        part = range(start, min(start + chunk, s.size))
        Ts = np.empty((len(part), red.size, red.size), dtype=complex)
        for i, k in enumerate(part):
            own = loss[k]
            if own is not None and own not in models:
                models[own] = viscous_model(red, own)
            model, extra = (red, None) if own is None else models[own]
            T, dTY[:, k] = model.newton_terms(complex(s[k]), float(speeds[k]), weights[k], Y[:, k])
            Ts[i] = T if extra is None else T + extra
        Z[:, part.start : part.stop] = _left_vectors(Ts, Y[:, part.start : part.stop])
    den = (Z * dTY).sum(axis=0)
    coefficients = _coefficients(ops, s, speeds, weights, viscous)
    keep = products.present
    r = _apply(products.stacked, coefficients[keep], _real_times(red.Phi, Y))
    r_left = _apply(products.stacked_transposed, coefficients[keep], _real_times(red.Phi, Z))
    gains = _actuator_gains(red, s)
    for rows_out, rows_in, gain in gains:  # the channels' terms ``B_outᵀ gain B_in``
        r += rows_out.T @ (((rows_in @ red.Phi) @ Y) * gain)
        r_left += rows_in.T @ (((rows_out @ red.Phi) @ Z) * gain)
    both = _complement(ops, red, np.hstack([r, r_left]))
    u, v = both[:, : s.size], both[:, s.size :]
    Tu = _apply(products.stacked, coefficients[keep], u)
    for rows_out, rows_in, gain in gains:
        Tu += rows_out.T @ ((rows_in @ u) * gain)
    numerator = 2 * (r_left * u).sum(axis=0) - (v * Tu).sum(axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return numerator / den


def tracked_errors(
    red: ReducedModel, speeds: np.ndarray, eigenvalues: np.ndarray, states: list, viscous=None
) -> np.ndarray:
    """:func:`eigenvalue_errors` of tracked curves: (n_speeds, n_modes) from the eigenvalues
    (n_speeds, n_modes) and the modal coordinates of each speed; ``viscous(speed)`` gives the
    viscous method's weights (None: hysteretic or loss-free).

    The columns of several speeds go through the estimate's products and solves at once
    (:func:`_corrections`, column by column: the numbers of one speed at a time, to round-off),
    as many speeds as keep a column's largest temporaries, its matrix T(s) (nb² complex numbers)
    or its stacked products with the full matrices (7 n_free), within :data:`_GROUP_BYTES`: each
    call's fixed work (the products', the K_σ solve's and the stacked solve's) is paid once a
    group, and the temporaries stay in a core's cache. Measured on the tuned design's whirl
    stability (21 speeds, 10 modes, nb 56, 343 free DOFs, one BLAS thread, best of 5): 19.0-22.9
    ms one speed at a time, 16.7-20.2 ms two at a time (the budget's), 16.1-19.9 ms three; four
    to six at a time (2-3 MB of temporaries) as fast on a quiet machine but 30-32 ms at four on
    a loaded one, 25 ms eight at a time, 21-22 ms all 21 at once.
    """
    speeds = np.asarray(speeds, dtype=float)
    eigenvalues = np.asarray(eigenvalues, dtype=complex)
    n_speeds, n_modes = eigenvalues.shape
    out = np.empty(eigenvalues.shape)
    n_free = red.full.size if red.full is not None else 0
    column = 16 * max(red.size * red.size, len(_ORDER) * n_free, 1)
    group = max(1, int(_GROUP_BYTES // (column * max(n_modes, 1))))
    for start in range(0, n_speeds, group):
        at = speeds[start : start + group]
        s = eigenvalues[start : start + at.size].ravel()
        Y = np.hstack([np.asarray(states[start + i], dtype=complex).reshape(red.size, n_modes) for i in range(at.size)])
        loss = None
        if viscous is not None:
            loss = [w for w in (viscous(float(speed)) for speed in at) for _ in range(n_modes)]
        delta = _corrections(red, np.repeat(at, n_modes), s, Y, loss)
        out[start : start + at.size] = _relative(delta, s).reshape(at.size, n_modes)
    return out


#: Relative eigenvalue accuracy |s* − s|/|s| against the full (unreduced) eigenproblem that the
#: Campbell diagram and the whirl stability choose their basis for, by default. 1e-6 puts the
#: basis error three orders below the 0.1 % the benchmarks and the tests hold frequencies to,
#: and below a damping ratio's 1e-4·1e-2 resolution (ζ = −Re s/|s|: an error of 1e-6|s| moves ζ
#: by at most 1e-6).
EIGENVALUE_TOLERANCE = 1e-6


def accurate_basis(n_modes: int) -> tuple[int, int]:
    """First (basis size, enriched modes) of :func:`tracked_to_accuracy` for ``n_modes`` tracked
    modes: twice as many undamped modes as tracked (the tracked ones at rest and as many above,
    where a speed's coupling moves them), the lowest ``n_modes`` enriched with their static
    corrections. Measured (tests/test_eigen_accuracy.py): 2e-10 on the 100-element ROSS shaft
    (14 modes), 3e-11 and 1e-8 on the baseline and tuned designs (12 modes), where the plain
    40-56-mode bases err by 5e-5, 6e-7 and 2e-3."""
    return max(2 * n_modes, 16), max(n_modes, 8)


def accurate_bases(n_modes: int) -> list[tuple[int, int]]:
    """Every (basis size, enriched modes) :func:`tracked_to_accuracy` may try for ``n_modes``
    tracked modes, in order: :func:`accurate_basis`'s, then doubled while twice the size stays
    within four times the plain default basis, 4·max(4n, 40) vectors (the loop also stops once
    a basis, corrections included, holds that many). The command bounds read the largest
    (:mod:`flexshaft.cli.bounds`)."""
    size, enrich = accurate_basis(n_modes)
    largest = _largest_basis(n_modes)
    bases = [(size, enrich)]
    while 2 * size <= largest:
        size, enrich = 2 * size, 2 * enrich
        bases.append((size, enrich))
    return bases


def _largest_basis(n_modes: int) -> int:
    """Four times the plain default basis, max(4n, 40), and at least twice the first size."""
    return max(4 * max(4 * n_modes, 40), 2 * accurate_basis(n_modes)[0])


def tracked_to_accuracy(
    model: Model,
    speeds: np.ndarray,
    n_modes: int,
    track: Callable[[ReducedModel, np.ndarray, _C | None], _C],
    basis_size: int | None = None,
    tolerance: float = EIGENVALUE_TOLERANCE,
    transform: Callable[[ReducedModel], ReducedModel] | None = None,
    viscous: Callable[[float], LossCoefficients] | None = None,
    reduced: ReducedModel | None = None,
    estimate: bool = True,
) -> tuple[ReducedModel, _C, np.ndarray | None]:
    """Tracked curves on a basis chosen for ``tolerance``, with their estimated errors.

    ``track(red, at, start)`` follows the modes on a reduced model over the speeds ``at``, going
    on from ``start`` (its curves at ``at[0]`` alone, tracked already) when given; each point's
    relative error against the full eigenproblem is estimated a posteriori
    (:mod:`flexshaft.analyses.eigen_error`).
    With ``reduced`` or ``basis_size`` given that basis is used as it is (the plain modal basis
    of ``basis_size`` modes) and the estimate only reported. Otherwise the enriched basis of
    :func:`accurate_basis` is tried first and doubled while the largest estimate exceeds
    ``tolerance``, until the basis (corrections included) holds four times the plain default
    4·max(4n, 40) vectors or the whole model; the result reports what
    was reached (the estimate, not a promise). ``transform`` is applied to each reduced model
    (e.g. :meth:`~flexshaft.analyses.eigen.ReducedModel.undamped`), ``viscous(speed)`` gives the
    viscous method's weights for the estimate. ``estimate=False`` skips the estimate on a
    basis the caller gave (errors None), for a caller that uses no eigenvalue of its own
    output's accuracy statement (a study that keeps only onsets over a grid); the basis chosen
    for ``tolerance`` needs it.

    A basis that is not the last to try is screened at ``speeds[0]`` before the whole track (a
    tracking reaches each speed from the earlier ones only): an estimate above ``tolerance``
    there is one of the whole track's, which would reject the basis, so it is rejected at once;
    a basis that passes is tracked on from that speed's curves and keeps their estimate. The
    basis chosen and the results are those of whole tracks; a basis that fails from rest on (the
    enriched first basis of the thesis shafts at 1e-6: 1.2e-6 to 3e-6 at every speed) costs one
    speed instead of all, and one that passes costs nothing more.

    Returns
    -------
    red, tracked, errors
        The reduced model used, the curves, and (n_speeds, n_modes) estimated relative errors
        (None when not estimated).
    """
    n_free = int(model.dofs.free.size)

    def run(red: ReducedModel, with_errors: bool = True) -> tuple[ReducedModel, _C, np.ndarray | None]:
        red = transform(red) if transform is not None else red
        tracked = track(red, speeds, None)
        if not with_errors:
            return red, tracked, None
        errors = tracked_errors(red, speeds, tracked.eigenvalues, tracked.states, viscous)
        return red, tracked, errors

    def screened(red: ReducedModel) -> tuple[ReducedModel, _C, np.ndarray] | None:
        """The whole track on a basis that passes the first speed's screen, else None."""
        red = transform(red) if transform is not None else red
        first = track(red, speeds[:1], None)
        errors = tracked_errors(red, speeds[:1], first.eigenvalues, first.states, viscous)
        if float(np.nanmax(errors, initial=0.0)) > tolerance:
            return None
        tracked = track(red, speeds, first)
        rest = tracked_errors(red, speeds[1:], tracked.eigenvalues[1:], tracked.states[1:], viscous)
        return red, tracked, np.concatenate([errors, rest])

    if reduced is not None:
        return run(reduced, estimate)
    if basis_size is not None:
        return run(reduce(model, basis_size), estimate)
    largest = _largest_basis(n_modes)
    bases = accurate_bases(n_modes)

    for k, (size, enrich) in enumerate(bases):
        whole = size >= n_free
        red = accurate_reduction(model, min(size, n_free), 0 if whole else enrich)
        last = whole or k == len(bases) - 1 or red.size >= largest
        if last:
            return run(red)
        passed = screened(red)
        if passed is not None and float(np.nanmax(passed[2], initial=0.0)) <= tolerance:
            return passed
    raise AssertionError("unreachable: the last basis to try is tracked whole and returned")


def accurate_reduction(model: Model, size: int, enrich: int) -> ReducedModel:
    """:func:`~flexshaft.analyses.eigen.reduce` for :func:`tracked_to_accuracy`: up to
    :data:`~flexshaft.analyses.dense_spectrum.WHOLE_DENSE_BASIS_UP_TO` free DOFs the dense basis
    read off the model's whole spectrum, solved once for every basis of the model (an
    assessment's modes, stability and every-root check share it); above, a basis of under a
    quarter of the free DOFs by sparse shift-invert Lanczos (4x faster than the dense solve at
    604 DOFs and 28 modes, the same ω² to 3e-10; a basis error it leaves is in the estimate like
    any other), the dense solver when ARPACK does not converge."""
    n_free = int(model.dofs.free.size)
    if WHOLE_DENSE_BASIS_UP_TO < n_free and 4 * size < n_free:
        try:
            return reduce(model, size, "sparse", enrich=enrich)
        except RefusedInputError:  # ARPACK's failure: the dense solver says what is wrong
            pass
    return reduce(model, size, enrich=enrich)


def check_tolerance(tolerance: float) -> float:
    """A relative eigenvalue accuracy: a finite number in (0, 1) (else ValueError)."""
    if isinstance(tolerance, bool) or not isinstance(tolerance, (int, float, np.floating, np.integer)):
        raise ValueError(f"tolerance must be a number in (0, 1) (got {tolerance!r})")
    value = float(tolerance)
    if not (np.isfinite(value) and 0 < value < 1):
        raise ValueError(f"tolerance must be a relative accuracy in (0, 1) (got {tolerance!r})")
    return value


def accuracy_text(result) -> str:
    """ ", eigenvalues within ~X of the full model (estimated)" for a result with an
    ``error_estimate`` (empty without one)."""
    err = getattr(result, "error_estimate", None)
    if err is None or not np.size(err) or not np.any(np.isfinite(err)):
        return ""
    return f", eigenvalues within {float(np.nanmax(err)):.1e} of the full model (estimated)"


def with_error_estimate(ds, result):
    """``ds`` with the result's ``eigenvalue_error`` (speed, mode) and its tolerance attribute."""
    err = getattr(result, "error_estimate", None)
    if err is None:
        return ds
    ds["eigenvalue_error"] = (
        ("speed", "mode"),
        np.asarray(err, dtype=float),
        {"units": "1", "long_name": "estimated relative eigenvalue error against the full (unreduced) model"},
    )
    if getattr(result, "tolerance", None) is not None:
        ds.attrs["eigenvalue_tolerance"] = float(result.tolerance)
    if getattr(result, "basis_size", None) is not None:
        ds.attrs["basis_size"] = int(result.basis_size)
    return ds


def _weights(red: ReducedModel, speed: float, s: complex, viscous: LossCoefficients | None) -> LossCoefficients:
    """The hysteretic loss weights of the root s (those of its own side of the synchronous line,
    as :func:`~flexshaft.analyses.eigen.newton` holds them), or none."""
    if viscous is not None or not red.has_loss or not (np.isfinite(s.imag) and s.imag > 0):
        return _NO_LOSS
    return eigen_coefficients(red.internal_damping, float(s.imag), speed)


def _left_vectors(Ts: np.ndarray, Y: np.ndarray) -> np.ndarray:
    """Unit columns z_k with ``T_kᵀ z_k ≈ 0`` for each T_k singular to the Newton tolerance:
    one step of inverse iteration from y_k (the solve amplifies the null direction by
    1/σ_min); per mode, with the smallest singular vector, when a T_k is exactly singular."""
    try:
        Z = np.linalg.solve(np.swapaxes(Ts, 1, 2), Y.T[:, :, None])[:, :, 0].T
    except np.linalg.LinAlgError:  # one exactly singular T_k fails the stack: each on its own
        Z = np.full_like(Y, np.nan)
        for j in range(Ts.shape[0]):
            with contextlib.suppress(np.linalg.LinAlgError):
                Z[:, j] = np.linalg.solve(Ts[j].T, Y[:, j])
    for k in np.flatnonzero(~np.all(np.isfinite(Z), axis=0) | ~np.any(Z, axis=0)):
        Z[:, k] = la.svd(Ts[k].T)[2][-1].conj()
    return Z / np.linalg.norm(Z, axis=0)


def _complement(ops: FullOperators, red: ReducedModel, r: np.ndarray) -> np.ndarray:
    """``K_σ⁻¹ r`` with the basis part removed: ``Ψ(ΨᵀK_σΨ)⁻¹Ψᵀ r`` exactly (Φ is M-orthonormal
    and K-diagonal, so ``ΦᵀK_σΦ = Λ + σ``); the Galerkin condition makes the removed part
    round-off."""
    u = ops.flexibility(r)
    return u - _real_times(red.Phi, _real_times(red.Phi.T, r) / (red.w2 + ops.shift)[:, None])


def _real_times(A, X: np.ndarray) -> np.ndarray:
    """``A @ X`` for a real (dense or sparse) A and complex X, as one real product on the
    interleaved real and imaginary parts (numpy and scipy would copy A to complex first)."""
    X = np.ascontiguousarray(X, dtype=complex)
    out = np.asarray(A @ X.view(float))
    return np.ascontiguousarray(out).view(complex)


#: Order of the matrices in the coefficient rows: T(s) = Σ coefficient_X · X.
_ORDER = ("M", "G", "D", "K", "F", "L", "S")


class _ColumnWeights(NamedTuple):
    """The viscous method's weights of each column (:class:`LossCoefficients` field by field)."""

    fixed: np.ndarray
    lateral: np.ndarray
    circulatory: np.ndarray


def _coefficients(
    ops: FullOperators, s: np.ndarray, speed: np.ndarray, weights: list[LossCoefficients], viscous
) -> np.ndarray:
    """(7, m) scalars c_X with ``T(s_k) = Σ_X c_X[k] X`` (order :data:`_ORDER`) at the columns'
    speeds ``speed`` (m,); ``viscous``: the viscous method's weights of each column (None:
    the hysteretic ``weights``)."""
    c = np.zeros((len(_ORDER), s.size), dtype=complex)
    c[0] = s * s
    c[1] = speed * s
    c[2] = s if ops.damped else 0.0
    c[3] = 1.0
    if viscous is not None:
        viscous = _ColumnWeights(*(np.array([getattr(v, name) for v in viscous]) for name in _ColumnWeights._fields))
        c[4] = viscous.fixed * s
        c[5] = viscous.lateral * s
        c[6] = viscous.circulatory
    else:
        c[4] = [complex(w.fixed) for w in weights]
        c[5] = [complex(w.lateral) for w in weights]
        c[6] = [complex(w.circulatory) for w in weights]
    return c


class _Products:
    """The full matrices X of :data:`_ORDER` that are not zero, stacked (k n, n), and their
    transposes: ``T(s) x`` is one sparse product and a weighted sum of its k blocks."""

    def __init__(self, red: ReducedModel):
        ops = red.full
        assert ops is not None
        mats = [getattr(ops, name) for name in _ORDER]
        self.consistent = _projects(red, ops)
        self.present = np.array([A.nnz > 0 for A in mats])
        mats = [A for A, p in zip(mats, self.present) if p]
        self.stacked = sp.vstack(mats).tocsr()
        self.stacked_transposed = sp.vstack([A.T for A in mats]).tocsr()


def _projects(red: ReducedModel, ops: FullOperators) -> bool:
    """True when the reduced matrices are the projections of the full ones, to 1e-6 of their
    largest entry (the basis is K-orthogonal only to about ε ω_nb²/ω_1²: 1.1e-8 measured on a
    30-element shaft). A caller may change a reduced model (e.g. the gain map adds K_d B̃ᵀB̃ to
    C̃, a change of the order of C̃ itself); then the full operators do not describe its problem
    and the estimate is not given (NaN) rather than wrong."""
    Phi = red.Phi
    pairs = [(ops.K, np.diag(red.w2)), (ops.G, red.G), (ops.D if ops.damped else None, red.C)]
    pairs += [(ops.F, red.F), (ops.L, red.L), (ops.S, red.S)]
    for A, reduced in pairs:
        projected = np.zeros_like(reduced) if A is None else Phi.T @ (A @ Phi)
        scale = max(float(np.max(np.abs(projected), initial=0.0)), float(np.max(np.abs(reduced), initial=0.0)))
        if float(np.max(np.abs(projected - reduced), initial=0.0)) > 1e-6 * scale:
            return False
    return True


@functools.lru_cache(maxsize=2)  # one sweep's reduced model (keyed by identity; as large as the model)
def _products(red: ReducedModel) -> _Products:
    return _Products(red)


def _apply(stacked, coefficients: np.ndarray, X: np.ndarray) -> np.ndarray:
    """``Σ_X c_X[k] X x_k`` for the columns x_k of X: one sparse product (``T(s_k) x_k``
    without the actuator channels)."""
    n = X.shape[0]
    products = _real_times(stacked, X).reshape(coefficients.shape[0], n, X.shape[1])
    out = products[0] * coefficients[0]
    for k in range(1, coefficients.shape[0]):
        out += products[k] * coefficients[k]
    return out


def _actuator_gains(red: ReducedModel, s: np.ndarray) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """(B_out, B_in, gain per mode) of each actuator channel not already in the full matrices:
    the law's gain minus what K and D hold, as in
    :meth:`~flexshaft.analyses.eigen.ReducedModel.newton_terms`."""
    out = []
    for act in red.actuators:
        if act.law is not None:
            law = act.law
            gain = np.array([complex(law(sk)) for sk in s]) - act.basis_stiffness - s * act.damping_in_basis
        elif act.stiffness or act.damping:
            gain = act.stiffness + s * act.damping
        else:
            continue
        assert act.rows_full is not None
        rows_in = act.rows_full if act.sensing_full is None else act.sensing_full
        out.append((act.rows_full, rows_in, np.asarray(gain, dtype=complex)))
    return out
