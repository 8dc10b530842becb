"""Banded solver for repeated harmonic solves of one model.

``Z(ω, Ω) = −ω² M + iω(Ω G + C) + K + L(ω, Ω) + Σ_a [G_a(iω) B_aᵀB_s − k_s B_aᵀB_a]`` on the free
DOFs, with the hysteretic loss ``L`` of :mod:`flexshaft.analyses.loss` (the model's
internal-damping choice) and each magnetic bearing's feedback ``G_a = k_i A(s) C(s)`` from its
sensing rows B_s to its actuation rows B_a (:class:`~flexshaft.assembly.model.Actuator`); a
collocated bearing (B_s = B_a) adds ``(G_a(iω) − k_s) B_aᵀB_a`` on one symmetric pattern.

The free DOFs are renumbered once by reverse Cuthill-McKee on the union sparsity of every term;
shaft and boom nodes at the same station then sit together and the bandwidth stays small
(≈ 20 for the baseline). Every term is stored once as the data of one shared sparse pattern,
so ``Z`` at a new (ω, Ω) is a few vector operations on ``nnz`` numbers, scattered into LAPACK
band storage, factorised by ``zgbtrf`` and solved by ``zgbtrs``: O(n b²) per point.

Singularity (an undamped system excited at one of its resonances) is detected without a
per-point condition estimate: when the factor's pivots span more than :data:`PIVOT_SCREEN`,
one step of iterative refinement measures the forward error of the computed solution
(``Z dx = b − Z x``). A relative correction above :data:`FORWARD_ERROR_LIMIT` means the
response is not determined in double precision — the system is singular to working precision,
whatever the model's size — and :class:`SingularSystemError` is raised (the 1-norm condition
number, estimated only then, is quoted in the message). Otherwise the refined solution is
returned. A fixed reciprocal-condition threshold would not scale: a damped 400-element model
is regular but has rcond ≈ 5e-14 from its mesh alone.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.linalg import lapack
from scipy.sparse.csgraph import reverse_cuthill_mckee

from flexshaft.analyses.loss import frequency_coefficients
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["SingularSystemError", "BandedHarmonicSolver", "PIVOT_SCREEN", "FORWARD_ERROR_LIMIT"]

#: Smallest/largest |pivot| of the LU below which the solution is checked by refinement.
PIVOT_SCREEN = 1e-8
#: Relative size of the refinement correction above which Z counts as singular.
FORWARD_ERROR_LIMIT = 1e-6


class SingularSystemError(ArithmeticError, ValueError):
    """The dynamic stiffness is singular: an undamped system excited exactly at resonance.

    Also a ``ValueError``: the cause is the design or the arguments (no damping at a resonance,
    an unsupported rigid-body motion), so callers that report bad input report it too.
    """


def _term_matrices(model: Model, free: np.ndarray) -> dict[str, sp.csr_matrix]:
    terms = {
        "M": model.M,
        "K": model.K,
        "G": model.G,
        "C": model.C,
        "F": model.loss_fixed,
        "L": model.loss_lateral,
        "S": model.loss_circulatory,
    }
    out = {name: restrict(A.tocsr(), free).tocsr() for name, A in terms.items()}
    for k, a in enumerate(model.actuators):
        B = a.lateral_rows
        out[f"A{k}"] = restrict((B.T @ B).tocsr(), free).tocsr()
        if not a.collocated:  # actuation rows × sensing rows
            out[f"S{k}"] = restrict((B.T @ a.sensing_rows).tocsr(), free).tocsr()
    for A in out.values():
        A.eliminate_zeros()  # stored zeros (e.g. exact zero couplings of an element) would widen the band
    return out


class BandedHarmonicSolver:
    """Solve ``Z(ω, Ω) q = Q`` repeatedly for one model (see the module docstring)."""

    def __init__(self, model: Model):
        free = model.dofs.free
        self.free = free
        n = free.size
        self.n = n
        terms = _term_matrices(model, free)
        rows = np.concatenate([A.tocoo().row for A in terms.values()])
        cols = np.concatenate([A.tocoo().col for A in terms.values()])
        pattern = sp.coo_matrix((np.ones(rows.size), (rows, cols)), shape=(n, n)).tocsr()
        pattern = (pattern + pattern.T).tocsr()
        perm = reverse_cuthill_mckee(pattern, symmetric_mode=True)
        self.perm = perm
        self.inverse = np.argsort(perm)
        P = pattern[perm][:, perm].tocoo()
        self.kl = int(np.max(P.row - P.col, initial=0))
        self.ku = int(np.max(P.col - P.row, initial=0))
        # one shared pattern (the permuted union, row-major) and each term's data on it
        keys = np.unique(P.row.astype(np.int64) * n + P.col)
        self._rows, self._cols = keys // n, keys % n
        self._template = sp.csr_matrix((np.zeros(keys.size), (self._rows, self._cols)), shape=(n, n))
        self._template.sort_indices()
        self._band_index = (self.kl + self.ku + self._rows - self._cols) * n + self._cols
        self.data = {}
        for name, A in terms.items():
            coo = A[perm][:, perm].tocoo()
            positions = np.searchsorted(keys, coo.row.astype(np.int64) * n + coo.col)
            values = np.zeros(keys.size, dtype=complex)
            np.add.at(values, positions, coo.data)
            self.data[name] = values
        self.actuators = model.actuators
        self.internal_damping = model.internal_damping
        self.default_speed = model.speed

    @property
    def bandwidth(self) -> int:
        return self.kl + self.ku + 1

    def matrix_data(self, omega: float, speed: float) -> np.ndarray:
        """Values of Z(ω, Ω) on the shared pattern (permuted ordering)."""
        d = self.data
        loss = frequency_coefficients(self.internal_damping, omega, speed)
        z = d["K"] - omega**2 * d["M"] + 1j * omega * (speed * d["G"] + d["C"])
        if loss.fixed:
            z = z + loss.fixed * d["F"]
        if loss.lateral:
            z = z + loss.lateral * d["L"]
        if loss.circulatory:
            z = z + loss.circulatory * d["S"]
        s = 1j * omega
        for k, a in enumerate(self.actuators):
            if a.collocated:
                z = z + complex(a.law(s)) * d[f"A{k}"]
            else:
                z = z + complex(a.feedback_gain(s)) * d[f"S{k}"]
                if a.negative_stiffness:
                    z = z - a.negative_stiffness * d[f"A{k}"]
        return z

    def matrix(self, omega: float, speed: float) -> np.ndarray:
        """Band storage of Z(ω, Ω) in the ``zgbtrf`` layout (2 kl + ku + 1, n)."""
        ab = np.zeros((2 * self.kl + self.ku + 1, self.n), dtype=complex)
        ab.flat[self._band_index] = self.matrix_data(omega, speed)
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
        if not (np.isfinite(omega) and np.isfinite(speed)):
            raise ValueError(f"frequency and speed must be finite (got ω = {omega!r}, Ω = {speed!r})")
        b = np.asarray(rhs, dtype=complex)
        if not np.all(np.isfinite(b)):
            raise ValueError("the load vector contains NaN or inf")
        data = self.matrix_data(omega, speed)
        ab = np.zeros((2 * self.kl + self.ku + 1, self.n), dtype=complex)
        ab.flat[self._band_index] = data
        lu, piv, info = lapack.zgbtrf(ab, self.kl, self.ku, overwrite_ab=True)
        if info > 0:
            self._singular(omega, speed, None)
        bp = b[self.perm]
        x, _ = lapack.zgbtrs(lu, self.kl, self.ku, bp, piv)
        pivots = np.abs(lu[self.kl + self.ku])
        if not np.all(np.isfinite(x)) or pivots.min() < PIVOT_SCREEN * pivots.max():
            x = self._refine(data, lu, piv, bp, x, omega, speed)
        return x[self.inverse]

    def _refine(self, data, lu, piv, b, x, omega, speed):
        """One step of iterative refinement; raises when the correction is not small."""
        if not np.all(np.isfinite(x)):
            self._singular(omega, speed, lu, piv)
        Z = self._template.copy().astype(complex)
        Z.data[:] = data
        residual = b - Z @ x
        dx, _ = lapack.zgbtrs(lu, self.kl, self.ku, residual, piv)
        size = np.linalg.norm(x, axis=0)
        change = np.linalg.norm(dx, axis=0)
        if not np.all(np.isfinite(dx)) or np.any(change > FORWARD_ERROR_LIMIT * np.maximum(size, np.finfo(float).tiny)):
            self._singular(omega, speed, lu, piv)
        return x + dx

    def _singular(self, omega: float, speed: float, lu, piv=None) -> None:
        note = ""
        if lu is not None:
            anorm = np.abs(self.matrix(omega, speed)).sum(axis=0).max()
            rcond = lapack.zgbcon(self.kl, self.ku, lu, piv, anorm)[0]
            note = f"; reciprocal condition number {rcond:.1e}"
        raise SingularSystemError(
            f"dynamic stiffness is singular at ω = {omega:.6g} rad/s, Ω = {speed:.6g} rad/s "
            f"(an undamped resonance{note}); add damping or move the frequency"
        )
