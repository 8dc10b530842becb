"""Damped eigen-solutions on a modal basis, every mode at its own frequency.

Every eigen-analysis (modes at one speed, Campbell diagram, whirl stability) uses this module,
so they share one damping physics (:mod:`flexshaft.analyses.loss`) and one set of mode labels.

Reduction. The free DOFs are projected once on the lowest ``nb`` undamped, non-spinning modes
Φ of ``(K + K_a) φ = ω² M φ`` (mass-normalised; K_a the actuators' basis stiffness), computed
densely for small models and by sparse shift-invert Lanczos (ARPACK) beyond
:data:`SPARSE_BASIS_ABOVE` free DOFs. In modal coordinates ``q = Φ y`` the first-order
problem at spin speed Ω is, with controller states ``x`` for transfer-function actuators,

    ÿ = −(Λ + Σ_a B̃_aᵀ(D_a − k_a)B̃_a) y − (Ω G̃ + C̃) ẏ − Σ_a B̃_aᵀ C_a x_a
    ẋ_a = A_a x_a + B_a B̃_a y

(``B̃_a = B_a Φ`` the actuator's lateral rows, ``(A_a, B_a, C_a, D_a)`` a minimal realization
of its law on each of the two lateral directions); this loss-free matrix, or the one of the
thesis's viscous internal-damping model, gives the candidates.

Solution. A dense eigen-solve of the loss-free state matrix gives every candidate at a speed
(:func:`candidates`). Each wanted mode is refined to the eigenvalue of its own loss-consistent
problem by Newton's method on the nonlinear eigenproblem in modal coordinates

    T(s) y = [s² I + s (Ω G̃ + C̃) + Λ + L̃(ω, Ω) + Σ_a B̃_aᵀ (C_a(s) − k_a) B̃_a] y = 0,

with the hysteretic loss ``L̃`` of :mod:`flexshaft.analyses.loss` at the mode's own frequency
ω = Im(s)

(``u = T(s)⁻¹ T'(s) y``, ``s ← s − yᴴy / yᴴu``, ``y ← u/‖u‖``: quadratic convergence, one
nb × nb LU per step). A mode that sits exactly on the synchronous line, where the
rotating-frame loss switches sign, is settled with σ = 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as la
import scipy.sparse.linalg as spla

from flexshaft.analyses.loss import LossCoefficients, eigen_coefficients, whirl_sign
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict

__all__ = ["SPARSE_BASIS_ABOVE", "ReducedModel", "modal_basis", "reduce", "candidates", "refine", "newton", "damped_modes"]

#: Free-DOF count above which the modal basis is computed by sparse shift-invert.
SPARSE_BASIS_ABOVE = 900
#: Relative convergence of the refined eigenvalue (|Δs| / |s|; a damping ratio of 1e-4 is
#: then resolved to 1e-6 of itself).
_TOL = 1e-10
_MAX_ITER = 30
_NO_LOSS = LossCoefficients(0.0, 0.0, 0.0)


def modal_basis(model: Model, basis_size: int, method: str = "auto") -> tuple[np.ndarray, np.ndarray]:
    """Lowest undamped, non-spinning modes on the free DOFs: (ω² [rad²/s²], Φ) mass-normalised.

    Parameters
    ----------
    basis_size : int
        Number of modes (capped at the number of free DOFs).
    method : {"auto", "dense", "sparse"}
        ``"auto"``: dense ``eigh`` up to :data:`SPARSE_BASIS_ABOVE` free DOFs, else sparse
        shift-invert Lanczos with a shift of −1 rad²/s² (so a free rigid-body motion is found
        too).
    """
    free = model.dofs.free
    M = restrict(model.M, free).tocsc()
    K = restrict((model.K + model.Kp).tocsr(), free).tocsc()
    n = M.shape[0]
    nb = int(min(basis_size, n))
    if nb < 1:
        raise ValueError(f"basis_size must be >= 1 (got {basis_size})")
    sparse = method == "sparse" or (method == "auto" and n > SPARSE_BASIS_ABOVE and nb < n // 2)
    if not sparse:
        return la.eigh(K.toarray(), M.toarray(), subset_by_index=[0, nb - 1])
    w2, Phi = spla.eigsh(K, k=nb, M=M, sigma=-1.0, which="LM")
    order = np.argsort(w2)
    w2, Phi = w2[order], Phi[:, order]
    Phi = Phi / np.sqrt(np.einsum("ij,ij->j", Phi, M @ Phi))  # exact mass normalisation
    return w2, Phi


@dataclass(frozen=True)
class _ActuatorStates:
    rows: np.ndarray  # B̃_a (2, nb)
    A: np.ndarray  # (2 m, 2 m) block-diagonal over the two directions
    B: np.ndarray  # (2 m, 2)
    C: np.ndarray  # (2, 2 m)
    stiffness: float  # D_a − k_a on the lateral rows
    law: object = None  # the Controller of a transfer-function actuator (None: PD, already in Λ and C)
    basis_stiffness: float = 0.0


@dataclass(frozen=True)
class ReducedModel:
    """A model projected on its modal basis (see the module docstring).

    Attributes
    ----------
    Phi : ndarray
        Basis on the free DOFs (n_free, nb).
    w2 : ndarray
        Basis eigenvalues ω² [rad²/s²].
    G, C, F, L, S : ndarray
        Projected gyroscopic, viscous (bearing dampers + PD derivative gains), fixed-frame loss,
        lateral shaft loss and circulatory loss matrices (nb, nb).
    internal_damping : str
        The model's internal-damping model.
    """

    Phi: np.ndarray
    w2: np.ndarray
    G: np.ndarray
    C: np.ndarray
    F: np.ndarray
    L: np.ndarray
    S: np.ndarray
    internal_damping: str
    actuators: tuple[_ActuatorStates, ...]
    has_loss: bool

    @property
    def size(self) -> int:
        """Number of modal coordinates nb."""
        return self.w2.size

    @property
    def n_states(self) -> int:
        """Size of the first-order state: 2 nb plus the controller states."""
        return 2 * self.size + sum(a.A.shape[0] for a in self.actuators)

    def state_matrix(self, speed: float, viscous: LossCoefficients = _NO_LOSS) -> np.ndarray:
        """First-order matrix at spin speed Ω [rad/s], loss-free or with the real weights of
        :func:`~flexshaft.analyses.loss.viscous_equivalent` (damping on F and K_lat,
        stiffness on K_lat S)."""
        loss = viscous
        nb = self.size
        N = self.n_states
        stiffness = np.diag(self.w2)
        if loss.circulatory:
            stiffness = stiffness + loss.circulatory * self.S
        damping = speed * self.G + self.C
        if loss.fixed:
            damping = damping + loss.fixed * self.F
        if loss.lateral:
            damping = damping + loss.lateral * self.L
        A = np.zeros((N, N))
        A[:nb, nb : 2 * nb] = np.eye(nb)
        A[nb : 2 * nb, nb : 2 * nb] = -damping
        start = 2 * nb
        for act in self.actuators:
            if act.stiffness:
                stiffness = stiffness + act.stiffness * (act.rows.T @ act.rows)
            m = act.A.shape[0]
            if m:
                block = slice(start, start + m)
                A[nb : 2 * nb, block] = -act.rows.T @ act.C
                A[block, :nb] = act.B @ act.rows
                A[block, block] = act.A
                start += m
        A[nb : 2 * nb, :nb] = -stiffness
        return A

    def shapes(self, y: np.ndarray) -> np.ndarray:
        """Free-DOF displacement shapes Φ y of modal coordinates ``y`` (columns)."""
        return self.Phi @ y[: self.size]

    def dynamic_matrices(self, s: complex, speed: float, loss: LossCoefficients) -> tuple[np.ndarray, np.ndarray]:
        """``T(s)`` and ``dT/ds`` of the second-order problem with the complex loss weights
        ``loss`` (controller laws as C(s))."""
        damping = speed * self.G + self.C
        nb = self.size
        T = s * damping
        T.flat[:: nb + 1] += s * s + self.w2
        if loss.fixed:
            T = T + loss.fixed * self.F
        if loss.lateral:
            T = T + loss.lateral * self.L
        if loss.circulatory:
            T = T + loss.circulatory * self.S
        dT = damping.astype(complex)
        dT.flat[:: nb + 1] += 2 * s
        for act in self.actuators:
            if act.law is not None:
                BtB = act.rows.T @ act.rows
                T = T + (complex(act.law(s)) - act.basis_stiffness) * BtB
                dT = dT + complex(act.law.derivative(s)) * BtB
        return T, dT


def reduce(model: Model, basis_size: int, method: str = "auto") -> ReducedModel:
    """Project ``model`` on its lowest ``basis_size`` undamped modes."""
    free = model.dofs.free
    w2, Phi = modal_basis(model, basis_size, method)

    def proj(A):
        return Phi.T @ (restrict(A.tocsr(), free) @ Phi)

    actuators = []
    for a in model.actuators:
        rows = np.asarray(a.lateral_rows.tocsr()[:, free] @ Phi)
        ctrl = a.controller
        if ctrl.is_pd:
            actuators.append(_ActuatorStates(rows, np.zeros((0, 0)), np.zeros((0, 2)), np.zeros((2, 0)), 0.0))
            continue
        Ac, Bc, Cc, Dc = ctrl.state_space()
        I2 = np.eye(2)
        actuators.append(_ActuatorStates(rows, np.kron(I2, Ac), np.kron(I2, Bc), np.kron(I2, Cc),
                                         Dc - ctrl.basis_stiffness, ctrl, ctrl.basis_stiffness))
    return ReducedModel(
        Phi=Phi, w2=w2, G=proj(model.G), C=proj(model.C + model.Kd), F=proj(model.loss_fixed),
        L=proj(model.loss_lateral), S=proj(model.loss_circulatory), internal_damping=model.internal_damping,
        actuators=tuple(actuators), has_loss=model.has_loss,
    )


def candidates(red: ReducedModel, speed: float, viscous: LossCoefficients = _NO_LOSS) -> tuple[np.ndarray, np.ndarray]:
    """Every oscillatory eigenpair of the (loss-free or viscous) state matrix, sorted by |s|.

    Returns ``(s, Y)``: eigenvalues with Im(s) > 0 [rad/s] and their modal coordinates y
    (unit columns, (nb, k)).
    """
    lam, vec = la.eig(red.state_matrix(speed, viscous), check_finite=False)
    keep = lam.imag > 1e-6 * np.abs(lam)  # oscillatory roots only (ζ < 1 − 5e-13)
    lam, vec = lam[keep], vec[: red.size, keep]
    order = np.argsort(np.abs(lam))
    vec = vec[:, order]
    norm = np.linalg.norm(vec, axis=0)
    return lam[order], vec / np.where(norm > 0, norm, 1.0)


_getrf, _getrs = la.get_lapack_funcs(("getrf", "getrs"), dtype=complex)


def refine(red: ReducedModel, speed: float, s: complex, y: np.ndarray, tol: float = _TOL) -> tuple[complex, np.ndarray]:
    """The loss-consistent eigenpair nearest ``(s, y)`` (Newton; see the module docstring).

    ``y`` are modal coordinates (nb,). Returns the refined ``(s, y)`` with ‖y‖ = 1.
    """
    s, y, _ = newton(red, speed, s, y, tol)
    return s, y


def newton(red: ReducedModel, speed: float, s: complex, y: np.ndarray, tol: float = _TOL,
           viscous: LossCoefficients | None = None) -> tuple[complex, np.ndarray, bool]:
    """:func:`refine` that also says whether the iteration converged.

    With ``viscous`` weights (:func:`~flexshaft.analyses.loss.viscous_equivalent`) the problem
    is the thesis's linear viscous one instead of the hysteretic one.
    """
    if viscous is not None:
        damping = red.C + viscous.fixed * red.F + viscous.lateral * red.L
        stiffness = viscous.circulatory * red.S
        red = ReducedModel(red.Phi, red.w2, red.G, damping, red.F, red.L, red.S, red.internal_damping,
                           red.actuators, False)
        red_S = stiffness
    forced_sigma = None
    previous_sigma = None
    flips = 0
    y = np.asarray(y, dtype=complex)
    y = y / np.linalg.norm(y)
    for _ in range(_MAX_ITER):
        omega = abs(s.imag)
        if omega <= 0:
            break
        sigma = whirl_sign(omega, speed) if forced_sigma is None else forced_sigma
        if previous_sigma is not None and sigma != previous_sigma and forced_sigma is None:
            flips += 1
            if flips >= 2:  # no consistent side of the synchronous line: the mode sits on it
                forced_sigma = sigma = 0.0
        previous_sigma = sigma
        if viscous is None:
            T, dT = red.dynamic_matrices(s, speed, eigen_coefficients(red.internal_damping, omega, speed, sigma))
        else:
            T, dT = red.dynamic_matrices(s, speed, _NO_LOSS)
            T = T + red_S
        lu, piv, info = _getrf(T)
        if info > 0:  # s is an eigenvalue to machine precision
            return s, y, True
        u, _ = _getrs(lu, piv, dT @ y)
        denominator = np.vdot(y, u)
        if not np.isfinite(denominator) or denominator == 0:
            return s, y, True
        s_new = s - np.vdot(y, y) / denominator
        y = u / np.linalg.norm(u)
        if abs(s_new - s) <= tol * abs(s_new):
            return s_new, y, True
        s = s_new
    return s, y, False


def damped_modes(red: ReducedModel, speed: float, n_modes: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``n_modes`` lowest damped modes at one speed, each at its own frequency.

    Returns ``(s, Y)`` sorted by |s| (undamped natural frequency), Y modal coordinates.
    """
    lam, Y = candidates(red, speed)
    n = min(n_modes, lam.size)
    out_s = np.empty(n, complex)
    out_y = np.empty((red.size, n), complex)
    for k in range(n):
        out_s[k], out_y[:, k] = refine(red, speed, lam[k], Y[:, k])
    order = np.argsort(np.abs(out_s))
    return out_s[order], out_y[:, order]
