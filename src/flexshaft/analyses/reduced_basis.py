"""The modal basis of an eigen-analysis (:func:`modal_basis`: the lowest undamped,
non-spinning modes by shift-invert), the full (unreduced) operators, and the basis enriched
with static-correction vectors so that the reduced eigenvalues reach a stated accuracy.

Why enrich. The undamped, non-spinning modes Φ of :func:`modal_basis`
diagonalise M and K but not the speed-dependent gyroscopic matrix ΩG, the dampers C + K_d, the
hysteretic loss matrices F, K_lat, K_lat S or the actuators' forces: the exact mode at speed Ω
has components on every higher undamped mode, ``q_j ≈ −φ_jᵀ X φ y s/(ω_j² + s²)`` for a
coupling X, which a truncated basis drops. On a 100-element shaft the default 56-mode basis is
good to 5e-5 and 224 modes to 2e-7 (benchmarks/compare_ross.py): the truncation error falls
only as the square of the highest kept frequency. For the far modes (ω_j ≫ |s|) that
component is quasi-static, ``q ≈ −K⁻¹ X Φ y s``, so the span of ``K_σ⁻¹ X Φ_t`` for each
coupling X and the lowest ``n_t`` basis modes Φ_t (the modal truncation augmentation of
Dickens, Nakagawa and Wittbrodt 1997, i.e. residual-flexibility or static-correction
vectors) holds it for **every** speed and every loss weight at once: X is one of the constant
matrices the speed and the weights only scale. Added to Φ, it takes the same shaft to 2e-10
with 44 vectors (measured in tests/test_eigen_accuracy.py against the full dense
eigensolution).

The enriched basis stays a modal one (what :class:`~flexshaft.analyses.eigen.ReducedModel`
assumes: M-orthonormal, K diagonal): the correction vectors are M-orthogonalised against Φ
(so, Φ being exact eigenvectors, K-orthogonal to it too), orthonormalised among themselves and
rotated to the Ritz vectors of (K + K_a, M) on their own span. The lowest ``nb`` basis vectors
are therefore still the exact lowest undamped modes; the added ones carry Ritz values above
ω_nb² and no physical meaning of their own.

References
----------
Dickens, J. M., Nakagawa, J. M., Wittbrodt, M. J. (1997). A critique of mode acceleration and
modal truncation augmentation methods for modal response analysis. Computers & Structures 62,
985-998.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import scipy.linalg as la
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO, dense_spectrum
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.assembly.model import Model
from flexshaft.assembly.size import HARD_MEMORY_BYTES, SPARSE_BASIS_ABOVE
from flexshaft.assembly.sparse import restrict

__all__ = ["BASIS_SHIFT", "FullOperators", "full_operators", "enrich_basis", "modal_basis"]

#: A correction direction is dropped when the Gram matrix of the unit corrections (projected out
#: of the basis) has an eigenvalue below this fraction of its largest along it: the direction
#: is then within 1e-5 of the span of the others, its M-orthonormalised version would carry
#: the round-off of its computation amplified 1e5 times, and what it adds to the span is
#: below the 1e-10 level the accuracy test resolves.
_INDEPENDENT = 1e-10


@dataclass(frozen=True, eq=False)
class _Matrices:
    """The free-DOF matrices of one model and the LU of ``K_σ``."""

    M: sp.csr_matrix
    G: sp.csr_matrix
    D: sp.csr_matrix
    K: sp.csr_matrix
    F: sp.csr_matrix
    L: sp.csr_matrix
    S: sp.csr_matrix
    factor: spla.SuperLU


@functools.lru_cache(maxsize=2)  # one sweep's model (and one more): a factor is as large as the model
def _matrices(model: Model, shift: float) -> _Matrices:
    free = model.dofs.free

    def on_free(A: sp.csr_matrix) -> sp.csr_matrix:
        return restrict(A.tocsr(), free).tocsr()

    M = on_free(model.M)
    K = on_free(model.K + model.Kp)
    return _Matrices(
        M=M,
        G=on_free(model.G),
        D=on_free(model.C + model.Kd),
        K=K,
        F=on_free(model.loss_fixed),
        L=on_free(model.loss_lateral),
        S=on_free(model.loss_circulatory),
        factor=spla.splu((K + shift * M).tocsc()),
    )


@dataclass(frozen=True, eq=False)
class FullOperators:
    """The unreduced matrices on the free DOFs (sparse), as the reduced model projects them.

    ``K`` holds the actuators' basis stiffness K_a (:attr:`~flexshaft.assembly.model.Model.Kp`)
    and ``D`` the dampers with the laws' derivative part (``C + K_d``), as Λ and C̃ of the
    reduced model do; ``shift`` σ [rad²/s²] and the sparse LU of ``K_σ = K + σM`` (positive
    definite, :func:`modal_basis`) give the static flexibility.
    ``damped`` is False for :meth:`~flexshaft.analyses.eigen.ReducedModel.undamped` (no D).

    A handle on the model: the matrices and the factor are built when first used and kept for
    the last two models only, so the reduced models a cache holds do not hold them (a factor
    costs as much memory as the model).
    """

    model: Model
    shift: float
    damped: bool = True

    @property
    def _m(self) -> _Matrices:
        return _matrices(self.model, self.shift)

    @property
    def M(self) -> sp.csr_matrix:
        return self._m.M

    @property
    def G(self) -> sp.csr_matrix:
        return self._m.G

    @property
    def D(self) -> sp.csr_matrix:
        return self._m.D

    @property
    def K(self) -> sp.csr_matrix:
        return self._m.K

    @property
    def F(self) -> sp.csr_matrix:
        return self._m.F

    @property
    def L(self) -> sp.csr_matrix:
        return self._m.L

    @property
    def S(self) -> sp.csr_matrix:
        return self._m.S

    @property
    def size(self) -> int:
        """Number of free DOFs n."""
        return int(self.model.dofs.free.size)

    def flexibility(self, b: np.ndarray) -> np.ndarray:
        """``K_σ⁻¹ b`` for real or complex columns ``b`` (n, p)."""
        factor = self._m.factor
        b = np.asarray(b)
        if np.iscomplexobj(b):
            parts = factor.solve(np.ascontiguousarray(np.hstack([b.real, b.imag])))
            p = b.shape[1]
            return parts[:, :p] + 1j * parts[:, p:]
        return factor.solve(np.ascontiguousarray(b))


def full_operators(model: Model, shift: float) -> FullOperators:
    """The full operators of ``model`` with the shift σ = ``shift`` [rad²/s²] (a handle: the
    matrices are built on first use)."""
    return FullOperators(model, float(shift))


def enrich_basis(
    ops: FullOperators, w2: np.ndarray, Phi: np.ndarray, n_targets: int, actuator_rows: list[np.ndarray]
) -> tuple[np.ndarray, np.ndarray]:
    """The basis Φ with the static corrections of its lowest ``n_targets`` modes: ``(ω², V)``.

    Parameters
    ----------
    ops : FullOperators
        The model's full matrices (:func:`full_operators`).
    w2, Phi : ndarray
        The lowest undamped modes (ω² [rad²/s²], mass-normalised columns on the free DOFs).
    n_targets : int
        How many of the lowest modes get correction vectors ``K_σ⁻¹ X φ`` (X = G, the dampers,
        each non-zero loss matrix).
    actuator_rows : list of ndarray
        (2, n) rows on the free DOFs where an actuator acts or senses: each adds its static
        flexibility ``K_σ⁻¹ Bᵀ`` (the actuators' forces lie in the span of Bᵀ).

    Returns
    -------
    w2, V : ndarray
        Ritz values [rad²/s²] in increasing order and the M-orthonormal basis (n, nb + added):
        the first columns are Φ itself (module docstring).
    """
    n = ops.size
    targets = Phi[:, : max(0, min(int(n_targets), Phi.shape[1]))]
    blocks = []
    for X in (ops.G, ops.D, ops.F, ops.L, ops.S):
        if X.nnz and targets.shape[1]:
            blocks.append(np.asarray(X @ targets))
    for rows in actuator_rows:
        blocks.append(np.asarray(rows, dtype=float).T)
    if not blocks or Phi.shape[1] >= n:
        return w2, Phi
    E = ops.flexibility(np.hstack(blocks))
    E = _orthonormal_complement(ops.M, Phi, E)
    if E.shape[1] == 0:
        return w2, Phi
    KE = np.asarray(ops.K @ E)
    Kr = E.T @ KE
    w2_e, Q = la.eigh(0.5 * (Kr + Kr.T))
    V = np.hstack([Phi, E @ Q])
    w2_all = np.concatenate([w2, w2_e])
    order = np.argsort(w2_all, kind="stable")
    V = V[:, order]
    return w2_all[order], V / np.sqrt(np.einsum("ij,ij->j", V, ops.M @ V))


def _orthonormal_complement(M: sp.csr_matrix, Phi: np.ndarray, E: np.ndarray) -> np.ndarray:
    """Columns spanning E's part M-orthogonal to Φ, M-orthonormal; dependent ones dropped.

    Two passes of classical Gram-Schmidt against Φ (the second removes what round-off of the
    first left), each column scaled to unit M-norm first (the corrections' scales differ by
    orders of magnitude), then the eigen-decomposition of the Gram matrix EᵀME keeps the
    directions whose eigenvalue exceeds :data:`_INDEPENDENT` of the largest (a symmetric orthonormalisation
    that needs no pivoting)."""
    for _ in range(2):
        E = E - Phi @ (Phi.T @ (M @ E))
        norms = np.sqrt(np.maximum(np.einsum("ij,ij->j", E, M @ E), 0.0))
        E = E[:, norms > 0] / norms[norms > 0]
    gram = E.T @ (M @ E)
    d, U = la.eigh(0.5 * (gram + gram.T))
    keep = d > _INDEPENDENT * max(float(d.max(initial=0.0)), 1.0)
    E = E @ (U[:, keep] / np.sqrt(d[keep]))
    E = E - Phi @ (Phi.T @ (M @ E))  # the last round-off against Φ
    return E


#: Shift −σ of the modal basis's shift-invert [rad²/s²]: below the spectrum of K + K_a >= 0 (the
#: model's cached whole spectrum, :func:`~flexshaft.analyses.dense_spectrum.dense_spectrum`, is
#: computed at it: a reader of that cache passes the same shift).
BASIS_SHIFT = 1.0


def modal_basis(model: Model, basis_size: int, method: str = "auto") -> tuple[np.ndarray, np.ndarray]:
    """Lowest undamped, non-spinning modes on the free DOFs: (ω² [rad²/s²], Φ) mass-normalised.

    Parameters
    ----------
    basis_size : int
        Number of modes (capped at the number of free DOFs).
    method : {"auto", "dense", "sparse"}
        ``"auto"``: dense up to :data:`SPARSE_BASIS_ABOVE` free DOFs, else sparse shift-invert
        Lanczos. Both solve the shift-inverted problem with the shift σ = −1 rad²/s²
        (so a free rigid-body motion is found too): the largest ``μ = 1/(ω² + 1)`` of
        ``M φ = μ (K + K_a + M) φ``. The shift lies below the lowest eigenvalue because the
        basis stiffness ``K + K_a`` is positive semi-definite: member and contact-bearing
        stiffness are, and each actuator adds ``k_a BᵀB`` with ``k_a >= 0`` (a magnet's
        negative stiffness is left to the state matrix,
        :attr:`~flexshaft.assembly.model.Actuator.basis_stiffness`).

    Notes
    -----
    Why shift-invert, also densely. The Cholesky reduction of ``K φ = ω² M φ`` on M errs by
    about ``n ε ‖K‖ ‖M⁻¹‖`` in ω², which is the largest eigenvalue, not the wanted lowest ones:
    a nearly massless member (the Jeffcott idealisation, density 1e-6 kg/m³) makes ``‖M⁻¹‖``
    huge and gave the Jeffcott frequency 17 % low. The inverted problem reduces on
    ``K_σ = K + K_a + M``, whose error ``n ε ‖M‖ ‖K_σ⁻¹‖`` in μ is relative to the largest μ,
    the lowest modes: on the embedded designs that bound is 2e-10 of f1² where the direct
    problem's is 0.1 (the two solutions differ by at most 8e-9 in ω², tests/
    test_massless_members.py). A mode far above the lowest keeps a relative accuracy of about
    ``ε (ω_i² + 1)/(ω_1² + 1)``: 1e-10 over a supported driveline's basis, but with a free
    rigid-body motion (ω_1 = 0) the elastic modes of a nearly massless free member (1e13
    rad²/s²) keep three digits.
    """
    if isinstance(basis_size, bool) or not isinstance(basis_size, (int, np.integer)) or basis_size < 1:
        raise ValueError(f"basis_size must be an integer >= 1 (got {basis_size!r})")
    if method not in ("auto", "dense", "sparse"):
        raise ValueError(f"method must be 'auto', 'dense' or 'sparse' (got {method!r})")
    free = model.dofs.free
    n = free.size
    if n == 0:
        raise ValueError("the model has no free degrees of freedom")
    nb = int(min(basis_size, n))
    sparse = method == "sparse" or (method == "auto" and n > SPARSE_BASIS_ABOVE and nb < n // 2)
    if not sparse and 5 * 8.0 * n * n > HARD_MEMORY_BYTES:  # K, M, their copies and the vectors
        raise RefusedInputError(
            f"a dense modal basis of {nb} modes on {n:,} free DOFs needs about "
            f"{5 * 8.0 * n * n / 1024**3:.3g} GiB (allowed: {HARD_MEMORY_BYTES / 1024**3:g} GiB); "
            f"ask for fewer than {n // 2:,} basis modes (the sparse solver) or a coarser mesh"
        )
    if sparse and nb >= n - 1:
        raise ValueError(f"the sparse modal basis needs basis_size < {n - 1:,} free DOFs (got {basis_size!r})")
    M = restrict(model.M, free).tocsc()
    K = restrict((model.K + model.Kp).tocsr(), free).tocsc()
    try:
        if sparse:
            # a fixed start vector: ARPACK's own is random, which made two bases of one model
            # differ at round-off (1e-10 in ω²), so results were not reproducible bit for bit
            start = np.random.default_rng(0).standard_normal(n)
            w2, Phi = spla.eigsh(K, k=nb, M=M, sigma=-BASIS_SHIFT, which="LM", v0=start)
        elif n <= WHOLE_DENSE_BASIS_UP_TO and nb <= dense_spectrum(model, BASIS_SHIFT)[2]:
            mu, Phi, _ = dense_spectrum(model, BASIS_SHIFT)  # every mode, once per model: bases share it
            mu, Phi = mu[n - nb :], Phi[:, n - nb :]
            w2 = 1.0 / mu - BASIS_SHIFT
        else:
            dense_M = M.toarray()
            mu, Phi = la.eigh(dense_M, K.toarray() + BASIS_SHIFT * dense_M, subset_by_index=[n - nb, n - 1])
            w2 = 1.0 / mu - BASIS_SHIFT
    except (la.LinAlgError, RuntimeError):  # (RuntimeError: SuperLU's "Factor is exactly singular")
        raise RefusedInputError(
            "the modal basis cannot be computed: K + M is not positive definite to working "
            "precision, so some free rigid-body motion carries almost no mass or inertia (a "
            "free member of density near 1e-6 kg/m³): support that motion or raise the density"
        ) from None
    order = np.argsort(w2)
    w2, Phi = w2[order], Phi[:, order]
    Phi = Phi / np.sqrt(np.einsum("ij,ij->j", Phi, M @ Phi))  # exact mass normalisation
    return w2, Phi
