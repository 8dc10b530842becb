"""Banded solver for repeated harmonic solves of one model.

``Z(ω, Ω) = −ω² M + iω(Ω G + C) + K + L(ω, Ω) + Σ_a [G_a(iω) B_aᵀB_s − k_s B_aᵀB_a]`` on the free
DOFs, with the hysteretic loss ``L`` of :mod:`flexshaft.analyses.loss` (the model's
internal-damping choice) and each magnetic bearing's feedback ``G_a = k_i A(s) C(s)`` from its
sensing rows B_s to its actuation rows B_a (:class:`~flexshaft.assembly.model.Actuator`); a
collocated bearing (B_s = B_a) adds ``(G_a(iω) − k_s) B_aᵀB_a`` on one symmetric pattern.

The free DOFs are renumbered once on the union sparsity of every term (:func:`band_ordering`:
each uncoupled block on its own, shaft and boom nodes interleaved by station, or reverse
Cuthill-McKee where that is narrower); the half band of the baseline is 19. Every term is
stored once as the data of one shared sparse pattern, so ``Z`` at a new (ω, Ω) is one real
product over ``nnz`` numbers (a sweep's points a few at a time, one product for them),
scattered into LAPACK band storage, factorised and solved by ``zgbsv``: O(n b²) per point.
Only the blocks a right-hand side loads are factorised: an uncoupled block with no load has
the exact solution zero (the shaft's torsion, 38 of the tuned design's 343 free DOFs, under a
lateral load: an imbalance, a magnet's force), and the band LU of the others is the one it
would be inside the whole matrix, entry for entry (partial pivoting never crosses an uncoupled
block, whose coupling entries are exact zeros).

Singularity (an undamped system excited at one of its resonances) is detected without a
per-point condition estimate: when the factor's pivots span more than :data:`PIVOT_SCREEN`,
iterative refinement (``Z dx = b − Z x``) measures and removes the forward error of the
computed solution. An ill-conditioned but regular system (a fine mesh near a lightly damped
resonance: κ ≈ 1e12 at 800 elements) is refined until the correction is below
:data:`FORWARD_ERROR_LIMIT` (its response is then known to three digits at least); the
corrections of a system singular to working precision stay of order one (they do not
contract: each step must at least halve them), whatever the model's size, and
:class:`SingularSystemError` is raised (the 1-norm condition number, estimated only then, is
quoted in the message). A fixed reciprocal-condition threshold would not scale: a damped
400-element model is regular but has rcond ≈ 5e-14 from its mesh alone.

Near an undamped resonance the system is regular and the solution accurate, but it is set by
the distance to the resonance: with ``|ω − ω_r| = δ ω`` the amplitude grows as 1/δ. The
sensitivity ``κ_ω = ω ‖Z⁻¹ (∂Z/∂ω) q‖ / ‖q‖`` (about ``1/|δ + iζ|`` for a mode of damping
ratio ζ; ∂Z/∂ω taken as ``−2ωM + i(ΩG + C)``, one more solve with the factor) is computed
whenever the pivots are screened, and above ``1/``:data:`RESONANCE_TOLERANCE` a
:class:`ResonanceWarning` says so: such a response changes completely when ω moves by less
than the accuracy of the natural frequencies the eigen-analyses report (an undamped
gyroscopic frequency from ``modes(damped=False)`` on its default basis lies about 3e-8 from
the full model's, where the response of 100 N was 3.6e3 m).
"""

from __future__ import annotations

import functools
import hashlib
import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.linalg import lapack
from scipy.sparse.csgraph import connected_components, reverse_cuthill_mckee

from flexshaft.analyses.guards import RefusedInputError
from flexshaft.analyses.loss import frequency_coefficient_arrays
from flexshaft.assembly.model import Model
from flexshaft.parallel.point_label import labelled

__all__ = [
    "SingularSystemError",
    "ResonanceWarning",
    "RESONANCE_TOLERANCE",
    "BandedHarmonicSolver",
    "band_ordering",
    "PIVOT_SCREEN",
    "FORWARD_ERROR_LIMIT",
    "solver_for",
]

#: Smallest/largest |pivot| of the LU below which the solution is checked by refinement.
PIVOT_SCREEN = 1e-8
#: Relative size a refinement correction must fall below for the solution to be accepted: the
#: response is then determined to three digits at least. A regular but ill-conditioned system
#: (κ ≈ 1e12 for a fine mesh near a lightly damped resonance) keeps corrections of about κ·ε
#: (1e-4) that refinement in working precision cannot remove; a singular one has corrections
#: of order 1.
FORWARD_ERROR_LIMIT = 1e-3
#: Complex columns multiplied by each term at once in :meth:`BandedHarmonicSolver.project_pairs`
#: (32: a product of the 343-DOF tuned model is 175 kB, in cache; all 216 columns of the bearing
#: loops' first projection at once take 1.6-2.5x the time).
_PROJECTION_COLUMNS = 32
#: Points of a sweep whose values of Z are computed by one matrix product
#: (:meth:`BandedHarmonicSolver.sweep`): on the 343-DOF tuned model the product costs 11 µs a
#: point one point at a time, 2.3 µs 8 at once (340 kB of values, beside the 283 kB band
#: buffer); a whole 288-point, 4-column sweep took 168 µs a point with 1 point a product,
#: 159-162 µs with 4 to 16 and 164 µs with 32 (1.4 MB of values).
_SWEEP_CHUNK = 8
#: Largest number of refinement steps (each must at least halve the correction; an
#: ill-conditioned regular system contracts by about κ·ε per step).
REFINEMENT_STEPS = 12
#: Relative change of the excitation frequency that may change a response completely before
#: :class:`ResonanceWarning` is given (κ_ω above its inverse): the accuracy of the eigen-analyses'
#: natural frequencies on their default modal basis (truncation error ≲ 1e-5 on the baseline).
RESONANCE_TOLERANCE = 1e-5


class SingularSystemError(ArithmeticError, RefusedInputError):
    """The dynamic stiffness is singular: an undamped system excited exactly at resonance.

    Also a ``ValueError``: the cause is the design or the arguments (no damping at a resonance,
    an unsupported rigid-body motion), so callers that report bad input report it too.
    """


class ResonanceWarning(RuntimeWarning):
    """A harmonic response within :data:`RESONANCE_TOLERANCE` of an (almost) undamped
    resonance: regular and accurate for the frequency given, but set by its distance to the
    resonance, which is below the accuracy of the model's natural frequencies."""


def _term_triplets(model: Model, local: np.ndarray) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Every term of Z as (row, column, value) on the free DOFs (``local`` maps a global DOF to
    its free index, −1 when fixed); stored zeros are dropped (they would widen the band)."""
    terms = {
        "M": model.M,
        "K": model.K,
        "G": model.G,
        "C": model.C,
        "F": model.loss_fixed,
        "L": model.loss_lateral,
        "S": model.loss_circulatory,
    }
    for k, a in enumerate(model.actuators):
        terms[f"A{k}"] = a.lateral_gram  # B_aᵀ B_a, kept by the actuator
        if not a.collocated:  # actuation rows × sensing rows
            terms[f"S{k}"] = a.lateral_rows.T @ a.sensing_rows
    out = {}
    for name, A in terms.items():
        coo = A.tocoo()
        r, c = local[coo.row], local[coo.col]
        keep = (r >= 0) & (c >= 0) & (coo.data != 0)
        out[name] = (r[keep], c[keep], coo.data[keep])
    return out


def _half_bandwidth(pattern: sp.csr_matrix, order: np.ndarray) -> int:
    """Largest |i − j| of the pattern's entries with its rows and columns in ``order``."""
    coo = pattern[order][:, order].tocoo()
    return int(np.max(np.abs(coo.row - coo.col), initial=0))


def band_ordering(pattern: sp.csr_matrix, stations: np.ndarray | None = None) -> np.ndarray:
    """An ordering of a symmetric pattern's rows for a small band.

    Each connected block of the pattern is ordered on its own and the blocks follow one another,
    so that an uncoupled block (the shaft's torsion) does not widen the others' band. A block
    takes the narrower of two orderings: reverse Cuthill-McKee, and, when ``stations`` (rows ×
    keys, the first key most significant: station, component, field) are given, the order along
    the driveline. On the baseline the latter interleaves the shaft and tailboom nodes by station
    and gives a half band of 19 where reverse Cuthill-McKee gives 24: the band LU costs
    ∝ kl (kl + ku), 40 % less.
    """
    return _ordered_blocks(pattern, stations)[0]


def _ordered_blocks(pattern: sp.csr_matrix, stations: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """:func:`band_ordering`'s ordering and each row's connected block (its label, in the
    ordering's order: non-decreasing, the blocks following one another)."""
    n_blocks, label = connected_components(pattern, directed=False)
    blocks = [np.flatnonzero(label == b) for b in range(n_blocks)]
    order = []
    for rows in blocks:
        sub = pattern[rows][:, rows].tocsr()
        candidates = [rows[reverse_cuthill_mckee(sub, symmetric_mode=True)]]
        if stations is not None:
            keys = np.asarray(stations)[rows]
            candidates.append(rows[np.lexsort(keys.T[::-1])])
        order.append(min(candidates, key=lambda o: _half_bandwidth(pattern, o)))
    perm = np.concatenate(order) if order else np.zeros(0, dtype=np.int64)
    return perm, label[perm].astype(np.int64)


@dataclass(frozen=True)
class _BandStructure:
    """What a solver's set-up derives from the union sparsity of the terms alone: the band
    ordering and the permuted union pattern (row-major, its entries as keys ``row · n + col``)
    with its half bands."""

    perm: np.ndarray
    inverse: np.ndarray
    keys: np.ndarray
    rows: np.ndarray
    cols: np.ndarray
    kl: int
    ku: int
    template: sp.csr_matrix
    block: np.ndarray  # the uncoupled block of each row, in the permuted ordering (non-decreasing)


#: Band structures by union sparsity. A sweep over materials, gains or walls builds many models
#: on one mesh: their terms' union pattern, so the ordering, is the same (a term's own entries
#: may differ: an exactly zero coupling of one layup is not stored).
_STRUCTURES: dict = {}


def _band_structure(n: int, terms: dict, stations: np.ndarray) -> _BandStructure:
    """The :class:`_BandStructure` of ``terms`` (name -> (rows, cols, values) on n free DOFs)."""
    union = np.unique(np.concatenate([r * n + c for r, c, _ in terms.values()]))
    key = (n, hashlib.blake2b(union.tobytes() + np.ascontiguousarray(stations).tobytes(), digest_size=20).digest())
    band = _STRUCTURES.get(key)
    if band is None:
        rows, cols = union // n, union % n
        both = np.concatenate([rows, cols]), np.concatenate([cols, rows])
        pattern = sp.csr_matrix((np.ones(2 * rows.size), both), shape=(n, n))
        perm, block = _ordered_blocks(pattern, stations)  # block: each row's, in the band ordering
        inverse = np.argsort(perm)
        keys = np.sort(inverse[rows] * n + inverse[cols])  # the permuted pattern, row-major
        rows, cols = keys // n, keys % n
        template = sp.csr_matrix((np.zeros(keys.size), (rows, cols)), shape=(n, n))
        template.sort_indices()
        for array in (perm, inverse, keys, rows, cols, block):
            array.setflags(write=False)
        band = _BandStructure(
            perm,
            inverse,
            keys,
            rows,
            cols,
            int(np.max(rows - cols, initial=0)),
            int(np.max(cols - rows, initial=0)),
            template,
            block,
        )
        if len(_STRUCTURES) >= 16:
            _STRUCTURES.clear()
        _STRUCTURES[key] = band
    return band


class BandedHarmonicSolver:
    """Solve ``Z(ω, Ω) q = Q`` repeatedly for one model (see the module docstring)."""

    def __init__(self, model: Model):
        free = model.dofs.free
        self.free = free
        n = free.size
        self.n = n
        local = np.full(model.dofs.size, -1, dtype=np.int64)
        local[free] = np.arange(n)
        terms = _term_triplets(model, local)
        band = _band_structure(n, terms, model.dofs.stations[free])
        self.perm, self.inverse = band.perm, band.inverse
        self._rows, self._cols, self.kl, self.ku = band.rows, band.cols, band.kl, band.ku
        self._template = band.template  # shared: copied before use
        self._block = band.block
        self.data = {}
        for name, (r, c, v) in terms.items():  # each term's data on the shared pattern
            values = np.zeros(band.keys.size, dtype=complex)
            np.add.at(values, np.searchsorted(band.keys, band.inverse[r] * n + band.inverse[c]), v)
            self.data[name] = values
        self.actuators = model.actuators
        self.internal_damping = model.internal_damping
        self.default_speed = model.speed
        ldab = 2 * self.kl + self.ku + 1
        self._buffer = np.zeros((ldab, n), dtype=complex, order="F")
        # the buffer's memory as one vector (a view: it is Fortran-contiguous) and each pattern
        # entry's place in it: a scatter into contiguous memory, not through a strided iterator
        self._buffer_memory = self._buffer.reshape(-1, order="F")
        self._memory_index = (self.kl + self.ku + self._rows - self._cols) + self._cols * ldab
        self._names = list(self.data)
        self._slot = {name: k for k, name in enumerate(self._names)}
        # the terms with a non-zero entry: a model without material loss (or without dampers)
        # has all-zero loss terms, which need not be multiplied and added at every point
        self._used = np.array([k for k, name in enumerate(self._names) if np.any(self.data[name])], dtype=np.intp)
        self._stack = np.array([self.data[self._names[k]] for k in self._used]).reshape(
            self._used.size, self._rows.size
        )
        # Every stored term is real (mass, stiffness, damping, loss and feedback patterns; the
        # complex weights carry the frequency dependence): Z's values are then one real
        # (nnz, n_terms) × (n_terms, 2) product (2 per point of a sweep's chunk) written straight
        # into complex memory, reading half the bytes of a complex stack.
        self._real_stack = None
        if not np.any(self._stack.imag):
            self._real_stack = np.ascontiguousarray(self._stack.real.T)  # (nnz, n_terms)

    @property
    def bandwidth(self) -> int:
        return self.kl + self.ku + 1

    def coefficients(self, omega: float, speed: float) -> np.ndarray:
        """Weights of the stored terms in Z(ω, Ω) (one per row of the term stack)."""
        return self.coefficient_table([omega], [speed])[0]

    def coefficient_table(self, omegas, speeds) -> np.ndarray:
        """Weights of the stored terms at many points (ω, Ω): (n_points, n_terms), computed
        array-wise once per sweep."""
        omegas = np.asarray(omegas, dtype=float)
        speeds = np.asarray(speeds, dtype=float)
        fixed, lateral, circulatory = frequency_coefficient_arrays(self.internal_damping, omegas, speeds)
        slot = self._slot
        w = np.zeros((omegas.size, len(self._names)), dtype=complex)
        w[:, slot["K"]] = 1.0
        w[:, slot["M"]] = -omegas * omegas
        w[:, slot["G"]] = 1j * omegas * speeds
        w[:, slot["C"]] = 1j * omegas
        w[:, slot["F"]] = fixed
        w[:, slot["L"]] = lateral
        w[:, slot["S"]] = circulatory
        s = 1j * omegas
        for k, a in enumerate(self.actuators):
            if a.collocated:
                w[:, slot[f"A{k}"]] = a.law(s)
            else:
                w[:, slot[f"S{k}"]] = a.feedback_gain(s)
                w[:, slot[f"A{k}"]] = -a.negative_stiffness
        return w

    def term_weights(self, omegas, speeds) -> np.ndarray:
        """Weights of the non-zero terms at many points (ω, Ω): (n_points, n_terms), the
        columns of :meth:`coefficient_table` that :meth:`project` returns terms for."""
        return self.coefficient_table(omegas, speeds)[:, self._used]

    def project_pairs(self, left: np.ndarray, right: np.ndarray) -> np.ndarray:
        """Products ``Uᴴ T_k W`` of the non-zero terms T_k of Z for m pairs of bases: ``left`` U
        (m, n_free, a) and ``right`` W (m, n_free, b) in the free-DOF ordering; returns
        (m, n_terms, a, b), the terms in the order of :meth:`term_weights`. Each term is
        multiplied on its own entries (a real product when the terms are real, the usual case),
        once per column of W."""
        m, n, b = right.shape
        real = self._real_stack is not None
        out = np.empty((m, self._used.size, left.shape[2], b), dtype=complex)
        step = max(1, _PROJECTION_COLUMNS // b)  # bases a pass: its products stay in cache
        for first in range(0, m, step):
            R, U = right[first : first + step], left[first : first + step]
            k = R.shape[0]
            W = np.ascontiguousarray(R[:, self.perm, :].transpose(1, 0, 2)).reshape(n, k * b)
            Uh = U[:, self.perm, :].conj().transpose(0, 2, 1)  # (k, a, n)
            for j, T in enumerate(self._own_terms):
                # a complex array's memory is its (real, imaginary) pairs: (n, 2 k b) reals
                TW = (T @ W.view(np.float64)).view(complex) if real else T @ W
                out[first : first + k, j] = Uh @ TW.reshape(n, k, b).transpose(1, 0, 2)
        return out

    def _own_entries(self) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
        """``(values, rows, cols)`` of each non-zero term on its own entries, in the solver's
        (permuted) ordering: the shared pattern holds the union of all terms (an actuator's term
        has a dozen of its thousands). Real values when every term is real."""
        real = self._real_stack is not None
        out = []
        for j in range(self._used.size):
            values = self._stack[j].real if real else self._stack[j]
            keep = values != 0
            out.append((values[keep], self._rows[keep], self._cols[keep]))
        return out

    @functools.cached_property
    def _own_terms(self) -> list[sp.csr_matrix]:
        """Each non-zero term as a CSR matrix of its own entries (:meth:`_own_entries`, permuted
        ordering), made at the first use."""
        out = []
        for values, rows, cols in self._own_entries():
            T = sp.csr_matrix((values, (rows, cols)), shape=(self.n, self.n))
            T.sort_indices()
            out.append(T)
        return out

    def project(self, bases: np.ndarray) -> np.ndarray:
        """Galerkin projections ``Vᴴ T_k V`` of the non-zero terms T_k of Z on each basis V.

        ``bases`` (m, n_free, r) in the free-DOF ordering; returns (m, n_terms, r, r), with
        ``Vᴴ Z(ω, Ω) V = Σ_k w_k Vᴴ T_k V`` for ``w`` a row of :meth:`term_weights`.
        """
        return self.project_pairs(bases, bases)

    @property
    def term_names(self) -> list[str]:
        """Names of the non-zero terms ("M", "K", "G", "C", "F", "L", "S", "A<k>", "S<k>"), in
        the order of :meth:`term_weights`, :meth:`project` and :meth:`term_matrix`."""
        return [self._names[k] for k in self._used]

    @functools.cached_property
    def term_stack(self) -> sp.csr_matrix:
        """Every non-zero term of Z on its own entries (:meth:`_own_entries`), stacked (n_terms
        n_free, n_free) in the order of :attr:`term_names` and the free-DOF ordering; real when
        every term is (built once)."""
        parts = self._own_entries()
        rows = np.concatenate([self.perm[r] + j * self.n for j, (_, r, _) in enumerate(parts)])
        cols = np.concatenate([self.perm[c] for _, _, c in parts])
        values = np.concatenate([v for v, _, _ in parts])
        return sp.csr_matrix((values, (rows, cols)), shape=(len(parts) * self.n, self.n))

    def term_matrix(self, weights) -> sp.csr_matrix:
        """``Σ_k w_k T_k`` over the non-zero terms T_k of Z, in the free-DOF ordering (CSR), for
        ``weights`` (n_terms,) in the order of :attr:`term_names` (a row of :meth:`term_weights`
        gives Z(ω, Ω) itself); for weights (m, n_terms), the m sums stacked vertically
        (m n_free, n_free)."""
        w = np.asarray(weights)
        if w.shape[-1:] != (self._used.size,) or w.ndim > 2:
            raise ValueError(f"weights must have shape ([m,] {self._used.size}) (got {w.shape})")
        w2 = np.atleast_2d(w)
        data = w2 @ self._stack  # (m, nnz)
        m = w2.shape[0]
        rows = (self.perm[self._rows][None, :] + self.n * np.arange(m)[:, None]).ravel()
        cols = np.broadcast_to(self.perm[self._cols], (m, self._cols.size)).ravel()
        return sp.csr_matrix((data.ravel(), (rows, cols)), shape=(m * self.n, self.n))

    def matrix_data(self, omega: float, speed: float, weights: np.ndarray | None = None) -> np.ndarray:
        """Values of Z(ω, Ω) on the shared pattern (permuted ordering); ``weights``: its row
        of :meth:`coefficient_table`, when already computed."""
        w = self.coefficients(omega, speed) if weights is None else weights
        w = w[self._used]
        if self._real_stack is None:
            return w @ self._stack
        out = np.empty(self._real_stack.shape[0], dtype=complex)
        # a complex vector's memory is its (real, imaginary) pairs: w as (n_used, 2) reals, and out
        np.matmul(self._real_stack, w.view(np.float64).reshape(-1, 2), out=out.view(np.float64).reshape(-1, 2))
        return out

    def matrix(self, omega: float, speed: float) -> np.ndarray:
        """Band storage of Z(ω, Ω) in the ``zgbtrf`` layout (2 kl + ku + 1, n)."""
        ab = np.zeros((2 * self.kl + self.ku + 1, self.n), dtype=complex, order="F")
        ab.reshape(-1, order="F")[self._memory_index] = self.matrix_data(omega, speed)  # a view: F-contiguous
        return ab

    def sparse_matrix(self, omega: float, speed: float) -> sp.csr_matrix:
        """Z(ω, Ω) as a CSR matrix in the solver's (permuted) ordering."""
        Z = self._template.copy().astype(complex)
        Z.data[:] = self.matrix_data(omega, speed)
        return Z

    def solve(self, omega: float, rhs: np.ndarray, speed: float | None = None) -> np.ndarray:
        """Free-DOF solution for right-hand side(s) ``rhs`` (n_free,) or (n_free, k).

        Raises
        ------
        SingularSystemError
            When Z(ω, Ω) is singular to working precision (see the module docstring).
        ValueError
            When ω, Ω or the right-hand side is not finite, or ω < 0.
        """
        speed = self.default_speed if speed is None else speed
        return next(self.sweep([(omega, speed)], rhs))

    def sweep(self, points, rhs: np.ndarray):
        """Yield the free-DOF solution at each (ω, Ω) of ``points`` for one right-hand side
        ``rhs`` (n_free,) or (n_free, k), checked and reordered once (see :meth:`solve`)."""
        b = np.asarray(rhs, dtype=complex)
        if not np.all(np.isfinite(b)):
            raise ValueError("the load vector contains NaN or inf")
        bp = np.asfortranarray(b[self.perm])
        points = [(float(omega), float(speed)) for omega, speed in points]
        for omega, speed in points:
            if not (math.isfinite(omega) and math.isfinite(speed)):
                raise ValueError(f"frequency and speed must be finite (got ω = {omega!r}, Ω = {speed!r})")
        table = self.coefficient_table([p[0] for p in points], [p[1] for p in points])
        span = self.loaded_span(bp)
        for first in range(0, len(points), _SWEEP_CHUNK):
            chunk = table[first : first + _SWEEP_CHUNK]
            values = self._chunk_data(chunk)
            for j, (omega, speed) in enumerate(points[first : first + _SWEEP_CHUNK]):
                yield self._solve_permuted(omega, speed, bp, values[:, j], span)[self.inverse]

    def _chunk_data(self, table: np.ndarray) -> np.ndarray:
        """Values of Z on the shared pattern (permuted ordering) at each row of ``table``
        (:meth:`coefficient_table`'s rows): (nnz, n_points), one matrix product for them all (the
        columns of :meth:`matrix_data`)."""
        w = table[:, self._used]
        if self._real_stack is None:
            return (w @ self._stack).T
        # (n_used, 2 n_points) reals: each point's weights as (real, imaginary) column pairs, and
        # the (nnz, 2 n_points) real product read as (nnz, n_points) complex
        pairs = np.ascontiguousarray(w.T).view(np.float64)
        return (self._real_stack @ pairs).view(complex)

    def coupled(self, rows: np.ndarray) -> np.ndarray:
        """Mask of the free DOFs (in the model's free-DOF order) in the uncoupled blocks of Z
        that hold any of ``rows`` (free-DOF indices): what a load on those rows or a response
        read there involves (the bearing loops' grid, :mod:`flexshaft.analyses.loop_grid`)."""
        block = self._block[self.inverse]
        return np.isin(block, block[np.asarray(rows, dtype=np.intp)])

    def loaded_span(self, bp: np.ndarray) -> tuple[int, int]:
        """The rows ``lo:hi`` (solver ordering) of the uncoupled blocks that the right-hand side
        ``bp`` (in that ordering) loads, from the first to the last: the solution is zero
        elsewhere (the module docstring). Every row for a zero right-hand side."""
        loaded = np.flatnonzero(np.any(bp.reshape(self.n, -1) != 0, axis=1))
        if loaded.size == 0:
            return 0, self.n
        lo = int(np.searchsorted(self._block, self._block[loaded[0]], side="left"))
        hi = int(np.searchsorted(self._block, self._block[loaded[-1]], side="right"))
        return lo, hi

    def _solve_permuted(
        self, omega: float, speed: float, bp: np.ndarray, data: np.ndarray, span: tuple[int, int]
    ) -> np.ndarray:
        """Z(ω, Ω) x = bp in the solver's ordering: one ``zgbsv`` (band LU and solve) of the rows
        ``span`` (:meth:`loaded_span`), zero elsewhere; ``data``: Z's values on the shared pattern
        (:meth:`matrix_data`)."""
        lo, hi = span
        ab = self._buffer
        # the matrix's rows only: the first kl (the LU's fill-in) "need not be set on entry"
        # (LAPACK zgbsv/zgbtrf), zgbtrf zeroes them itself; the band's entries outside the
        # pattern hold the previous point's factor and are zeroed
        ab[self.kl :].fill(0.0)
        self._buffer_memory[self._memory_index] = data
        part = hi - lo < self.n
        lu, piv, x, info = lapack.zgbsv(
            self.kl,
            self.ku,
            ab[:, lo:hi] if part else ab,
            bp[lo:hi] if part else bp,
            overwrite_ab=True,
            overwrite_b=False,
        )
        if part:  # the unloaded blocks' solution: exactly zero
            whole = np.zeros(bp.shape, dtype=complex)
            whole[lo:hi] = x
            x = whole
        if info > 0:
            self._singular(omega, speed, None)
        pivots = np.abs(lu[self.kl + self.ku])
        if not np.isfinite(x).all() or pivots.min() < PIVOT_SCREEN * pivots.max():
            x = self._refine(data, lu, piv, bp, x, omega, speed, (lo, hi))
            if omega > 0:
                self._check_resonance(lu, piv, x, omega, speed, (lo, hi))
        return x

    def _check_resonance(self, lu, piv, x: np.ndarray, omega: float, speed: float, span: tuple[int, int]) -> None:
        """Warn when the solution's sensitivity to ω exceeds ``1/RESONANCE_TOLERANCE`` (see the
        module docstring); ``lu``, ``piv``: the factor of the rows ``span`` (x is zero elsewhere)."""
        size = np.linalg.norm(x.reshape(self.n, -1), axis=0)
        if not np.any(size > 0):
            return
        Zw = self._template.copy().astype(complex)
        Zw.data[:] = -2 * omega * self.data["M"] + 1j * (speed * self.data["G"] + self.data["C"])
        lo, hi = span
        dx, _ = lapack.zgbtrs(lu, self.kl, self.ku, (Zw @ x)[lo:hi], piv)
        change = np.linalg.norm(dx.reshape(hi - lo, -1), axis=0)
        kappa = omega * float(np.max(np.where(size > 0, change / np.where(size > 0, size, 1.0), 0.0)))
        if kappa * RESONANCE_TOLERANCE > 1:
            import warnings

            warnings.warn(
                ResonanceWarning(
                    labelled(
                        f"the response at ω = {omega:.6g} rad/s, Ω = {speed:.6g} rad/s lies within about "
                        f"{1 / kappa:.1e} (relative) of an undamped resonance: moving ω by that fraction "
                        f"changes it completely, and the natural frequencies are known to about "
                        f"{RESONANCE_TOLERANCE:g}; add damping or move the frequency"
                    )
                ),
                stacklevel=2,
            )

    def _refine(self, data, lu, piv, b, x, omega, speed, span):
        """Iterative refinement (at most :data:`REFINEMENT_STEPS` steps) of the rows ``span``
        (``lu``, ``piv``: their factor; x is zero elsewhere): returns the refined solution once a
        correction falls below :data:`FORWARD_ERROR_LIMIT` of it; a singular system's corrections
        do not shrink, and it is reported."""
        if not np.all(np.isfinite(x)):
            self._singular(omega, speed, lu, piv, span)
        Z = self._template.copy().astype(complex)
        Z.data[:] = data
        lo, hi = span
        previous = np.inf
        for _ in range(REFINEMENT_STEPS):
            dx, _ = lapack.zgbtrs(lu, self.kl, self.ku, (b - Z @ x)[lo:hi], piv)
            if not np.all(np.isfinite(dx)):
                break
            x = x.copy()
            x[lo:hi] += dx
            change = float(
                np.max(np.linalg.norm(dx, axis=0) / np.maximum(np.linalg.norm(x, axis=0), np.finfo(float).tiny))
            )
            if change <= FORWARD_ERROR_LIMIT:
                return x
            if change > 0.5 * previous:  # the corrections do not contract: singular to working precision
                break
            previous = change
        self._singular(omega, speed, lu, piv, span)

    def _singular(self, omega: float, speed: float, lu, piv=None, span: tuple[int, int] | None = None) -> None:
        note = ""
        if lu is not None:
            lo, hi = (0, self.n) if span is None else span
            anorm = np.abs(self.matrix(omega, speed)[:, lo:hi]).sum(axis=0).max()
            rcond = lapack.zgbcon(self.kl, self.ku, lu, piv, anorm)[0]
            note = f"; reciprocal condition number {rcond:.1e}"
        raise SingularSystemError(
            f"dynamic stiffness is singular at ω = {omega:.6g} rad/s, Ω = {speed:.6g} rad/s "
            f"(an undamped resonance{note}); add damping or move the frequency"
        )


@functools.lru_cache(maxsize=8)  # the models of a run and of a sweep point's analyses
def solver_for(model: Model, passive: bool = False) -> BandedHarmonicSolver:
    """The model's :class:`BandedHarmonicSolver`, built once for the (immutable) model;
    ``passive``: the solver of the model without its actuators (:meth:`Model.passive`), which
    the spin-up studies solve on several speed grids."""
    return BandedHarmonicSolver(model.passive() if passive else model)
