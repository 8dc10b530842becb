"""Damped eigen-solutions on a modal basis, every mode at its own frequency.

Every eigen-analysis (modes at one speed, Campbell diagram, whirl stability) uses this module,
so they share one damping physics (:mod:`flexshaft.analyses.loss`) and one set of mode labels.

Reduction. The free DOFs are projected once on the lowest ``nb`` undamped, non-spinning modes
Φ of ``(K + K_a) φ = ω² M φ`` (mass-normalised; K_a the actuators' basis stiffness, never
negative, so the basis problem is positive semi-definite even when a magnetic bearing's
negative stiffness makes the open-loop structure unstable), computed densely for small
models and by sparse shift-invert Lanczos (ARPACK) beyond :data:`SPARSE_BASIS_ABOVE` free
DOFs. In modal coordinates ``q = Φ y`` every actuator is one or two channels
``B̃_outᵀ · L(s) · B̃_in`` (:class:`~flexshaft.assembly.model.Actuator`): the collocated law
``G − k_s`` on the magnet's rows ``B̃_a`` (``−k_s`` alone when the sensor is elsewhere) and,
for a non-collocated sensor, ``G(s) = k_i A(s) C(s)`` from the sensing rows ``B̃_s`` to
``B̃_a``. Each law is realised as ``L(s) = E s + D + C_L (sI − A_L)⁻¹ B_L``
(:meth:`~flexshaft.assembly.model.Controller.realization`, minimal, on each of the two
lateral directions); with controller states ``x`` the first-order problem at spin speed Ω is

    ÿ = −(Λ + Σ B̃_outᵀ(D − k_a)B̃_in) y − (Ω G̃ + C̃ + Σ B̃_outᵀ E B̃_in) ẏ − Σ B̃_outᵀ C_L x
    ẋ = A_L x + B_L B̃_in y

(k_a, and E of a collocated law, are already in Λ and C̃ = Φᵀ(C + K_d)Φ); this loss-free
matrix, or the one of the thesis's viscous internal-damping model, gives the candidates.
A PD bearing has no states: its K_p is in Λ and its K_d in C̃, exactly the thesis's model.

Solution. A dense eigen-solve of the loss-free state matrix gives every candidate at a speed
(:func:`candidates`). With the hysteretic loss, the problem

    T(s) y = [s² I + s (Ω G̃ + C̃) + Λ + L̃(ω, Ω) + Σ B̃_outᵀ (L(s) − k_a − s E_basis) B̃_in] y = 0,

with the loss ``L̃`` of :mod:`flexshaft.analyses.loss` at the mode's own frequency ω = Im(s),
is linear on each side of the synchronous line (its weights depend on s only through
sgn(ω − Ω)); :mod:`flexshaft.analyses.hysteretic_roots` finds the roots consistent with their
own side. :func:`newton` solves one side: Newton's method with the loss weights held fixed
(``u = T(s)⁻¹ T'(s) y``, ``s ← s − yᴴy / yᴴu``, ``y ← u/‖u‖``: quadratic convergence, one
nb × nb LU per step).

Divergence. A real eigenvalue s > 0 (a non-oscillatory, aperiodic instability: a magnetic
bearing with too little control stiffness against its k_s) is not an oscillatory candidate;
:func:`spectrum` returns it separately,
:func:`~flexshaft.analyses.hysteretic_roots.damped_modes` reports it as a mode with Im s = 0 and
the stability analysis as divergence.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as la

from flexshaft.analyses.loss import LossCoefficients, eigen_coefficients
from flexshaft.analyses.reduced_basis import BASIS_SHIFT, FullOperators, enrich_basis, full_operators, modal_basis
from flexshaft.assembly.controller import Controller
from flexshaft.assembly.model import Model
from flexshaft.assembly.size import SPARSE_BASIS_ABOVE  # the basis threshold lives with the size estimate
from flexshaft.assembly.sparse import restrict

__all__ = [
    "DIVERGENCE_TOLERANCE",
    "SPARSE_BASIS_ABOVE",
    "ReducedModel",
    "reduce",
    "spectrum",
    "candidates",
    "divergent_roots",
    "newton",
    "NEWTON_MAX_STEPS",
    "NEWTON_TOLERANCE",
    "viscous_model",
    "lowest_modes",
]

#: A real eigenvalue above this fraction of the largest basis frequency is a divergent root.
DIVERGENCE_TOLERANCE = 1e-6
#: Relative convergence of the refined eigenvalue (|Δs| / |s|; a damping ratio of 1e-4 is
#: then resolved to 1e-6 of itself).
NEWTON_TOLERANCE = 1e-10
#: Most Newton steps of :func:`newton` (and of its batched form,
#: :func:`flexshaft.analyses.continuation.newton_many`) before it gives up.
NEWTON_MAX_STEPS = 30
_NO_LOSS = LossCoefficients(0.0, 0.0, 0.0)


@dataclass(frozen=True)
class _ActuatorStates:
    """One actuator channel ``B̃_outᵀ · law · B̃_in`` in modal coordinates.

    A collocated channel has ``in_rows is rows``. The law is ``E s + D + C (sI − A)⁻¹ B`` on
    each lateral direction; ``stiffness`` and ``damping`` are the parts of ``D`` and ``E`` not
    already in the basis (Λ) and in the projected damping matrix.
    """

    rows: np.ndarray  # B̃_out (2, nb): where the force acts
    A: np.ndarray  # (2 m, 2 m) block-diagonal over the two directions
    B: np.ndarray  # (2 m, 2)
    C: np.ndarray  # (2, 2 m)
    stiffness: float  # D − k_basis on B̃_outᵀ B̃_in
    law: Controller | None = None  # the law's Controller when it has states (then T(s) uses law(s) directly)
    basis_stiffness: float = 0.0
    in_rows: np.ndarray | None = None  # B̃_in (2, nb): what the law measures (None: = rows)
    damping: float = 0.0  # E not already in the projected damping (non-collocated channels)
    damping_in_basis: float = 0.0  # E already in the projected damping (collocated channels: model.Kd)
    rows_full: np.ndarray | None = None  # B_out (2, n_free) on the free DOFs (the error estimate's)
    sensing_full: np.ndarray | None = None  # B_in (2, n_free) (None: = rows_full)

    @property
    def sensing(self) -> np.ndarray:
        return self.rows if self.in_rows is None else self.in_rows

    @functools.cached_property
    def coupling(self) -> np.ndarray:
        """``B̃_outᵀ B̃_in`` (nb, nb), computed once."""
        return self.rows.T @ self.sensing


@dataclass(frozen=True, eq=False)
class ReducedModel:
    """A model projected on its modal basis (see the module docstring). Equality is identity, so
    that it keys the cache of its speed parts.

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
    full : FullOperators or None
        The unreduced matrices the basis projects (for the a-posteriori error estimate of
        :mod:`flexshaft.analyses.eigen_error`); None when the reduced model was built otherwise.
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
    full: FullOperators | None = None

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
                stiffness = stiffness + act.stiffness * act.coupling
            if act.damping:
                A[nb : 2 * nb, nb : 2 * nb] -= act.damping * act.coupling
            m = act.A.shape[0]
            if m:
                block = slice(start, start + m)
                A[nb : 2 * nb, block] = -act.rows.T @ act.C
                A[block, :nb] = act.B @ act.sensing
                A[block, block] = act.A
                start += m
        A[nb : 2 * nb, :nb] = -stiffness
        return A

    @property
    def may_diverge(self) -> bool:
        """False when no real root s > 0 is possible: every actuator channel collocated, without
        states and with non-negative stiffness and damping. Then M > 0, symmetric stiffness and
        damping ≥ 0 and skew gyroscopic and circulatory terms leave no real positive root (for a
        real eigenvector φ: s² φᵀMφ + s φᵀDφ + φᵀKφ = 0 has no root s > 0)."""
        return any(
            a.A.size or a.in_rows is not None or a.stiffness < 0 or a.damping < 0 or a.damping_in_basis < 0
            for a in self.actuators
        )

    def undamped(self) -> ReducedModel:
        """The gyroscopic-only model: no viscous damping, no loss, no controller dynamics (the
        laws' static stiffness stays; actuators with states are left out)."""
        keep = tuple(dataclasses.replace(a, damping=0.0, damping_in_basis=0.0) for a in self.actuators if not a.A.size)
        full = None if self.full is None else dataclasses.replace(self.full, damped=False)
        return ReducedModel(
            self.Phi, self.w2, self.G, 0 * self.C, self.F, self.L, self.S, self.internal_damping, keep, False, full
        )

    def shapes(self, y: np.ndarray) -> np.ndarray:
        """Free-DOF displacement shapes Φ y of modal coordinates ``y`` (columns)."""
        return self.Phi @ y[: self.size]

    def _speed_parts(self, speed: float, loss: LossCoefficients) -> tuple[np.ndarray, np.ndarray]:
        """The parts of ``T(s)`` that do not depend on s, for one speed and loss weights: the
        damping ``ΩG + C`` (complex, as dT/ds needs it) and the stiffness ``Λ + Σ loss``, cached
        (:func:`_speed_parts`): Newton's method calls with the same speed and weights for every
        mode and step (two weights per speed with the rotating loss model)."""
        return _speed_parts(self, float(speed), complex(loss.fixed), complex(loss.lateral), complex(loss.circulatory))

    def newton_terms(
        self, s: complex, speed: float, loss: LossCoefficients, y: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray]:
        """``T(s)`` and ``dT/ds · y`` of the second-order problem with the complex loss weights
        ``loss`` (controller laws as C(s)): what a Newton step needs. dT/ds is not formed: its
        product with ``y`` is the damping's, ``2 s y`` and each channel's rank-two term."""
        damping, stiffness = self._speed_parts(speed, loss)
        T = damping * s
        T += stiffness
        T.ravel()[:: self.size + 1] += s * s  # a view: T is a new contiguous array
        for act in self.actuators:
            if act.law is not None:  # the law's dynamics: C(s) minus what Λ and C̃ already hold
                gain = complex(act.law(s)) - act.basis_stiffness - s * act.damping_in_basis
            elif act.stiffness or act.damping:
                gain = act.stiffness + s * act.damping
            else:
                continue
            T += gain * act.coupling
        return T, self.newton_slope(s, speed, loss, y)

    def newton_slope(self, s: complex, speed: float, loss: LossCoefficients, y: np.ndarray) -> np.ndarray:
        """``dT/ds · y`` of :meth:`newton_terms` alone (a Newton step whose T(s) is factored
        already): the damping's product, ``2 s y`` and each channel's rank-two term."""
        damping, _ = self._speed_parts(speed, loss)
        dTy = damping @ y
        dTy += (2 * s) * y
        for act in self.actuators:
            if act.law is not None:
                slope = complex(act.law.derivative(s)) - act.damping_in_basis
            elif act.stiffness or act.damping:
                slope = act.damping
            else:
                continue
            dTy += slope * (act.rows.T @ (act.sensing @ y))
        return dTy


def _channel(
    rows: np.ndarray,
    sensing: np.ndarray | None,
    law: Controller,
    basis_stiffness: float,
    full: tuple[np.ndarray | None, np.ndarray | None] = (None, None),
) -> _ActuatorStates:
    """The channel ``rowsᵀ · law · sensing`` (collocated when ``sensing`` is None: then
    ``basis_stiffness`` is in Λ and the law's ideal-derivative part in the projected damping,
    :attr:`Model.Kp` and :attr:`Model.Kd`)."""
    Ac, Bc, Cc, Dc, Ec = law.realization()
    I2 = np.eye(2)
    collocated = sensing is None
    has_states = Ac.shape[0] > 0
    return _ActuatorStates(
        rows,
        np.kron(I2, Ac),
        np.kron(I2, Bc),
        np.kron(I2, Cc),
        Dc - basis_stiffness,
        law if has_states else None,
        basis_stiffness,
        sensing,
        damping=0.0 if collocated else Ec,
        damping_in_basis=Ec if collocated else 0.0,
        rows_full=full[0],
        sensing_full=full[1],
    )


def reduce(model: Model, basis_size: int, method: str = "auto", enrich: int = 0) -> ReducedModel:
    """Project ``model`` on its lowest ``basis_size`` undamped modes (cached for the immutable
    model, so a second analysis of it reuses the basis).

    ``enrich > 0`` adds the static corrections of the lowest ``enrich`` modes and of the
    actuators (:func:`~flexshaft.analyses.reduced_basis.enrich_basis`): the basis then holds
    the speed-, damping- and loss-induced coupling to the truncated modes, and the reduced
    eigenvalues converge far faster with ``basis_size`` (:mod:`flexshaft.analyses.reduced_basis`).
    """
    if isinstance(enrich, bool) or not isinstance(enrich, (int, np.integer)) or enrich < 0:
        raise ValueError(f"enrich must be an integer >= 0 (got {enrich!r})")
    return _reduced(model, int(basis_size), method, int(enrich))


@functools.lru_cache(maxsize=16)  # a model's bases of a few sizes; a sweep's last models
def _reduced(model: Model, basis_size: int, method: str, enrich: int = 0) -> ReducedModel:
    return _reduce(model, basis_size, method, enrich)


@functools.lru_cache(maxsize=64)  # the speeds and loss weights of one stability or Campbell sweep
def _speed_parts(
    red: ReducedModel, speed: float, fixed: complex, lateral: complex, circulatory: complex
) -> tuple[np.ndarray, np.ndarray]:
    """:meth:`ReducedModel._speed_parts` of ``red`` at ``speed`` [rad/s] with the loss weights."""
    damping = speed * red.G + red.C
    stiffness = np.diag(red.w2).astype(complex)
    if fixed:
        stiffness = stiffness + fixed * red.F
    if lateral:
        stiffness = stiffness + lateral * red.L
    if circulatory:
        stiffness = stiffness + circulatory * red.S
    return damping.astype(complex), stiffness


def _reduce(model: Model, basis_size: int, method: str, enrich: int = 0) -> ReducedModel:
    free = model.dofs.free
    w2, Phi = modal_basis(model, basis_size, method)
    full = full_operators(model, BASIS_SHIFT)
    out_rows = [np.asarray(a.lateral_rows.tocsr()[:, free].toarray()) for a in model.actuators]
    in_rows = [None if a.collocated else np.asarray(a.sensing_rows.tocsr()[:, free].toarray()) for a in model.actuators]
    if enrich:
        w2, Phi = enrich_basis(full, w2, Phi, enrich, out_rows + [r for r in in_rows if r is not None])

    def proj(A):
        return Phi.T @ (restrict(A.tocsr(), free) @ Phi)

    actuators = []
    for a, b_out, b_in in zip(model.actuators, out_rows, in_rows):
        rows = b_out @ Phi
        actuators.append(_channel(rows, None, a.collocated_law, a.basis_stiffness, (b_out, None)))
        sensed = a.sensed_law
        if b_in is not None and sensed is not None:  # set together: a non-collocated sensor
            actuators.append(_channel(rows, b_in @ Phi, sensed, 0.0, (b_out, b_in)))
    return ReducedModel(
        Phi=Phi,
        w2=w2,
        G=proj(model.G),
        C=proj(model.C + model.Kd),
        F=proj(model.loss_fixed),
        L=proj(model.loss_lateral),
        S=proj(model.loss_circulatory),
        internal_damping=model.internal_damping,
        actuators=tuple(actuators),
        has_loss=model.has_loss,
        full=full,
    )


def spectrum(
    red: ReducedModel, speed: float, viscous: LossCoefficients = _NO_LOSS
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Eigen-solution of the (loss-free or viscous) state matrix at one speed.

    Returns ``(s, Y, Y_div, s_div)``: the oscillatory eigenvalues (Im s > 0 [rad/s]) sorted
    by |s| with their modal coordinates (unit columns, (nb, k)), and the **divergent** roots'
    modal coordinates (real unit columns, (nb, j)) and values ``s_div``: real eigenvalues
    s > 0 [1/s] (an aperiodic instability, e.g. a magnetic bearing whose negative stiffness
    k_s exceeds its control stiffness), largest first. A real root counts as divergent above
    :data:`DIVERGENCE_TOLERANCE` × the largest basis frequency (round-off of the zero roots
    of a free rigid-body motion is far below).
    """
    lam, vec = la.eig(red.state_matrix(speed, viscous), check_finite=False)
    keep = lam.imag > 1e-6 * np.abs(lam)  # oscillatory roots only (ζ < 1 − 5e-13)
    scale = float(np.sqrt(max(np.max(red.w2, initial=0.0), 1.0)))
    real = (np.abs(lam.imag) <= 1e-6 * np.abs(lam)) & (lam.real > DIVERGENCE_TOLERANCE * scale)
    div, div_vec = lam[real].real, vec[: red.size, real]
    order = np.argsort(-div)
    div, div_vec = div[order], div_vec[:, order]
    lam, vec = lam[keep], vec[: red.size, keep]
    order = np.argsort(np.abs(lam))
    vec = vec[:, order]
    norm = np.linalg.norm(vec, axis=0)
    dnorm = np.linalg.norm(div_vec, axis=0)
    return (
        lam[order],
        vec / np.where(norm > 0, norm, 1.0),
        div_vec.real / np.where(dnorm > 0, dnorm, 1.0) if div.size else div_vec.real,
        div,
    )


def candidates(red: ReducedModel, speed: float, viscous: LossCoefficients = _NO_LOSS) -> tuple[np.ndarray, np.ndarray]:
    """Every oscillatory eigenpair of the (loss-free or viscous) state matrix, sorted by |s|.

    Returns ``(s, Y)``: eigenvalues with Im(s) > 0 [rad/s] and their modal coordinates y
    (unit columns, (nb, k)). Divergent (real, unstable) roots are left out: see
    :func:`spectrum` and :func:`divergent_roots`.
    """
    lam, Y, _, _ = spectrum(red, speed, viscous)
    return lam, Y


def divergent_roots(red: ReducedModel, speed: float, viscous: LossCoefficients = _NO_LOSS) -> np.ndarray:
    """Real unstable eigenvalues s > 0 [1/s] of the state matrix at one speed, largest first
    (empty when there is none). See :func:`spectrum`."""
    return spectrum(red, speed, viscous)[3]


_gesv = la.lapack.zgesv  # = la.get_lapack_funcs("gesv", dtype=complex), typed
_getrs = la.lapack.zgetrs


def _unit(v: np.ndarray) -> np.ndarray:
    """``v / ‖v‖`` (the 2-norm as numpy.linalg.norm computes it, without its dispatch)."""
    re, im = v.real, v.imag
    return v / np.sqrt(re.dot(re) + im.dot(im))


def viscous_model(red: ReducedModel, viscous: LossCoefficients) -> tuple[ReducedModel, np.ndarray]:
    """The reduced model of the viscous internal-damping method and its extra stiffness: the
    damping ``C̃ + w_F F̃ + w_L L̃`` in place of C̃, and ``w_S S̃`` to add to ``T(s)``
    (:func:`~flexshaft.analyses.loss.viscous_equivalent`'s real weights)."""
    damping = red.C + viscous.fixed * red.F + viscous.lateral * red.L
    model = ReducedModel(
        red.Phi, red.w2, red.G, damping, red.F, red.L, red.S, red.internal_damping, red.actuators, False, red.full
    )
    return model, viscous.circulatory * red.S


def newton(
    red: ReducedModel,
    speed: float,
    s: complex,
    y: np.ndarray,
    tol: float = NEWTON_TOLERANCE,
    viscous: LossCoefficients | None = None,
    weights: LossCoefficients | None = None,
    factor: tuple[np.ndarray, np.ndarray] | None = None,
) -> tuple[complex, np.ndarray, bool]:
    """Newton's method on ``T(s) y = 0`` from ``(s, y)``: ``(s, y, converged)`` with ‖y‖ = 1.

    The loss weights are held fixed for the whole iteration, so the problem solved is linear
    in the weights and the iteration converges to one eigenvalue of it (no switching of the
    loss sign between steps): ``weights`` when given (a branch of
    :mod:`flexshaft.analyses.hysteretic_roots`), else the hysteretic weights of the starting
    point's own side of the synchronous line, ``eigen_coefficients(ω = Im s₀)``. With
    ``viscous`` weights (:func:`~flexshaft.analyses.loss.viscous_equivalent`) the problem is
    the thesis's linear viscous one instead. Only a root with Im s > 0 counts as converged: the
    hysteretic weights hold for ω = Im s > 0, and a root of the same matrix polynomial with
    Im s < 0 is no eigenvalue of the hysteretic problem (there the loss has the opposite sign).

    ``factor``: the LU factors ``(lu, piv)`` (LAPACK's getrf, nonsingular) of ``T(s)`` at the
    starting s with ``weights``, which a caller's inverse iteration at s holds already: the
    first step solves with them instead of factoring the same matrix again (getrf and getrs are
    what gesv does, so the step is the same to the bit). Not with ``viscous``.
    """
    if factor is not None and (viscous is not None or weights is None):
        raise ValueError("newton: factor needs the loss weights it was factored with, not viscous ones")
    extra: np.ndarray | None
    if viscous is not None:
        red, extra = viscous_model(red, viscous)
        loss = _NO_LOSS
    else:
        extra = None
        if weights is None:
            omega = abs(s.imag)
            if not (math.isfinite(omega) and omega > 0):
                return s, y, False
            weights = eigen_coefficients(red.internal_damping, omega, speed)
        loss = weights
    y = _unit(np.asarray(y, dtype=complex))
    for _ in range(NEWTON_MAX_STEPS):
        if factor is not None:  # T(s) at the start, factored by the caller
            u, info = _getrs(*factor, red.newton_slope(s, speed, loss, y))
            factor = None
        else:
            T, dTy = red.newton_terms(s, speed, loss, y)
            if extra is not None:
                T += extra
            _, _, u, info = _gesv(T, dTy, overwrite_a=True, overwrite_b=True)
        if info > 0:  # s is an eigenvalue to machine precision
            return s, y, s.imag > 0
        denominator = np.vdot(y, u)
        if not np.isfinite(denominator) or denominator == 0:
            return s, y, s.imag > 0
        s_new = s - np.vdot(y, y) / denominator
        y = _unit(u)
        if abs(s_new - s) <= tol * abs(s_new):
            return s_new, y, s_new.imag > 0
        s = s_new
    return s, y, False


#: A stable root with Im s below this fraction of |s| (damping ratio above 0.995) is overdamped:
#: :func:`lowest_modes` takes it only when the vibration modes are fewer than asked for.
OVERDAMPED_IM_FRACTION = 0.1


def lowest_modes(s: np.ndarray, n: int) -> np.ndarray:
    """Indices of the ``n`` modes of lowest damped frequency Im s among the ``2 n`` of lowest
    |s|, in increasing Im s (then |s|): the modes every table lists and numbers.

    Numbered by damped frequency, the frequency the tables print: a heavily damped mode
    (ζ = 0.14 in the tuned design) has a damped frequency below a lighter one's of smaller |s|.
    Chosen by damped frequency too, so that a list of n modes is the start of a longer one
    (the whirl stability's 10 modes are the Campbell diagram's first 10 of 12), unless a mode
    beyond the ``2 n`` of lowest |s| is damped below them. Only among those: a root all but
    critically damped (Im s a millionth of |s|, as the viscous internal-damping model gives the
    stiff axial DOFs) is no vibration mode of the band, however low its Im s.

    Parameters
    ----------
    s : ndarray
        Eigenvalues [rad/s] (a divergent root is real: Im s = 0 puts it first).
    n : int
        Modes wanted (all of them when there are fewer).
    """
    s = np.asarray(s)
    # Overdamped roots (stable, Im s below a tenth of |s|: ζ > 0.995) are no vibration mode of
    # the band either: the viscous internal-damping model makes every shaft mode above
    # 2 ω_ref / η one, whirling at about half the spin, Im s ≈ Ω/2, below the modes of the band.
    # They come last, so that they never take a vibration mode's place (which once dropped the
    # least stable whirl root and with it the onset); a divergent root (Re s > 0) is never one.
    overdamped = (s.real < 0) & (np.abs(s.imag) < OVERDAMPED_IM_FRACTION * np.abs(s))
    pool = np.lexsort((np.abs(s), overdamped))[: 2 * n]
    return pool[np.lexsort((np.abs(s[pool]), s[pool].imag, overdamped[pool]))[:n]]
