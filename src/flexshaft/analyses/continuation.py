"""Newton's method for several modes at once: one continuation step of every tracked mode.

A tracking (:func:`~flexshaft.analyses.campbell.track_modes`) continues each of its modes from
the previous speeds with :func:`~flexshaft.analyses.eigen.newton` (the viscous model) or
:func:`mode_root` (the hysteretic loss). At one speed
every mode's problem is the same matrix polynomial ``T(s)`` with one of at most two sets of
loss weights (the two sides of the synchronous line), so the modes' iterations differ only in
``s`` and ``y``: :func:`newton_many` runs them side by side, each mode's step exactly the
one :func:`~flexshaft.analyses.eigen.newton` takes (the same update, tolerance, iteration limit
and outcome), with the modes' ``nb × nb`` systems solved as one stack. A mode leaves the stack
when it converges, so each mode takes the iterations it would take alone.

:func:`mode_roots` is :func:`mode_root` for every mode:
the first branch's Newton (the branch of the mode's own side of the line) runs for all modes
at once, and a mode whose root there is consistent and farther from the line than its
first-order distance to the other branch's root is taken, as
:func:`mode_root` takes it; any other mode (near the
line, where both branches are solved, a fold or an on-line root is possible) is solved by
:func:`mode_root` itself.

Cost: the LUs are the same as one mode at a time; what goes is each mode's own Python and call
overhead per step (measured: the whirl stability of the thesis's three shafts 4-10 % faster at
41 speeds and 8 modes, nb 77; a screening assessment of the tuned design 4 %,
benchmarks/assessment_speed.py). The eigenvalues agree with the one-mode-at-a-time iteration
to round-off (1e-16 relative, measured on the same cases).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.eigen import NEWTON_MAX_STEPS, NEWTON_TOLERANCE, ReducedModel, newton, viscous_model
from flexshaft.analyses.hysteretic_roots import SAME_MODE_MAC, Branch, branch_roots, branches, line_root, on_branch
from flexshaft.analyses.loss import LossCoefficients

__all__ = ["EXTRAPOLATED_SHAPE_MAC", "branch_distance", "mode_root", "mode_roots", "newton_many", "predicted_start"]

#: Smallest MAC between a mode's shapes at the last two speeds for which :func:`predicted_start`
#: extrapolates the shape (else Newton starts from the last shape).
EXTRAPOLATED_SHAPE_MAC = 0.9

_NO_LOSS = LossCoefficients(0.0, 0.0, 0.0)


def newton_many(
    red: ReducedModel,
    speed: float,
    s: np.ndarray,
    Y: np.ndarray,
    weights: LossCoefficients | None = None,
    viscous: LossCoefficients | None = None,
    tol: float = NEWTON_TOLERANCE,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`~flexshaft.analyses.eigen.newton` from each ``(s[k], Y[:, k])`` on one problem:
    the branch ``weights`` (held fixed) or the ``viscous`` model's. Returns ``(s, Y,
    converged)`` as arrays (m,), (nb, m) unit columns, (m,) bool."""
    s = np.array(s, dtype=complex).ravel()
    m = s.size
    given = red
    if viscous is not None:
        red, extra = viscous_model(red, viscous)
        loss = _NO_LOSS
    else:
        if weights is None:
            raise ValueError("newton_many needs the branch weights or the viscous weights")
        extra, loss = None, weights
    Y = np.array(Y, dtype=complex).reshape(red.size, m)
    Y = Y / np.sqrt((Y.real**2 + Y.imag**2).sum(axis=0))
    converged = np.zeros(m, dtype=bool)
    if m == 0:
        return s, Y, converged
    damping, stiffness = red._speed_parts(float(speed), loss)
    nb = red.size
    active = np.arange(m)
    for _ in range(NEWTON_MAX_STEPS):
        sa, ya = s[active], Y[:, active]
        T = damping[None, :, :] * sa[:, None, None]
        T += stiffness
        T.reshape(active.size, -1)[:, :: nb + 1] += (sa * sa)[:, None]
        dTy = damping @ ya
        dTy += (2 * sa) * ya
        for act in red.actuators:
            if act.law is not None:
                gain = act.law(sa) - act.basis_stiffness - sa * act.damping_in_basis
                slope = act.law.derivative(sa) - act.damping_in_basis
            elif act.stiffness or act.damping:
                gain, slope = act.stiffness + sa * act.damping, np.full(sa.size, act.damping, dtype=complex)
            else:
                continue
            T += np.asarray(gain, dtype=complex)[:, None, None] * act.coupling
            dTy += slope * (act.rows.T @ (act.sensing @ ya))
        if extra is not None:
            T += extra
        try:
            u = np.linalg.solve(T, dTy.T[:, :, None])[:, :, 0].T
        except np.linalg.LinAlgError:  # some step hit an eigenvalue exactly: each mode alone
            w = None if viscous is not None else weights
            for j, k in enumerate(active):
                s[k], Y[:, k], converged[k] = newton(given, speed, sa[j], ya[:, j], tol, viscous=viscous, weights=w)
            return s, Y, converged
        denominator = np.einsum("ij,ij->j", ya.conj(), u)
        yy = np.einsum("ij,ij->j", ya.conj(), ya)
        stop = ~np.isfinite(denominator) | (denominator == 0)
        with np.errstate(divide="ignore", invalid="ignore"):
            s_new = sa - yy / denominator
            u_unit = u / np.sqrt((u.real**2 + u.imag**2).sum(axis=0))
        done = ~stop & (np.abs(s_new - sa) <= tol * np.abs(s_new))
        step = ~stop
        s[active[step]] = s_new[step]
        Y[:, active[step]] = u_unit[:, step]
        finished = stop | done
        converged[active[finished]] = s[active[finished]].imag > 0
        active = active[~finished]
        if not active.size:
            break
    return s, Y, converged


def mode_roots(
    red: ReducedModel, speed: float, s: np.ndarray, Y: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`mode_root` of each mode ``(s[k], Y[:, k])``
    at ``speed`` (module docstring): ``(s, Y, found)`` arrays."""
    s0 = np.array(s, dtype=complex).ravel()
    Y0 = np.array(Y, dtype=complex).reshape(red.size, s0.size)
    parts = branches(red, speed)
    first = np.zeros(s0.size, dtype=int)
    if len(parts) == 2:
        first[~on_branch(parts[0], s0.imag, speed)] = 1
    out_s, out_Y, found = s0.copy(), Y0.copy(), np.zeros(s0.size, dtype=bool)
    for b, branch in enumerate(parts):
        idx = np.flatnonzero(first == b)
        if not idx.size:
            continue
        roots, vecs, ok = newton_many(red, speed, s0[idx], Y0[:, idx], weights=branch.weights)
        y = Y0[:, idx]
        norms = (y.real**2 + y.imag**2).sum(axis=0)
        same = ok & (np.abs(np.einsum("ij,ij->j", y.conj(), vecs)) ** 2 >= SAME_MODE_MAC * norms)
        own = same & on_branch(branch, roots.imag, speed)
        if len(parts) == 1:
            keep = own
        else:
            distance = branch_distance(red, branch.weights, parts[1 - b].weights, roots, vecs)
            keep = own & (np.abs(roots.imag - speed) > 10 * distance)
        out_s[idx[keep]], out_Y[:, idx[keep]] = roots[keep], vecs[:, keep]
        found[idx[keep]] = True
    for k in np.flatnonzero(~found):  # near the line, or no consistent root: the mode alone
        out_s[k], out_Y[:, k], found[k] = mode_root(red, speed, complex(s0[k]), Y0[:, k])
    return out_s, out_Y, found


def mode_root(red: ReducedModel, speed: float, s: complex, y: np.ndarray) -> tuple[complex, np.ndarray, bool]:
    """The eigenvalue at ``speed`` of the mode near ``(s, y)`` (continuation of both branches).

    Each branch's linear problem is solved by Newton's method from ``(s, y)``, the branch of
    ``Im s`` first; a branch root counts when it converged (Im s > 0) on its own side of the
    line and is the same mode (MAC with ``y`` at least :data:`SAME_MODE_MAC`). One such root:
    that one; two (a fold): the less stable; none, with the two branch roots straddling the
    line the wrong way: the on-line root (:func:`line_root`). Returns ``(s, y, found)``. When
    both branches are solved and Newton's method on one of them reaches another mode (a close
    neighbour, such as the backward whirl of a rotor without gyroscopic split), that branch's
    root of this mode is taken from its exact roots (:func:`_branch_mode`): which of a fold's
    two eigenvalues is kept must not depend on the one the continuation arrived at.

    The other branch is skipped when the first root is consistent and farther from the line
    than ten times the first-order distance between the two branch roots,
    ``|yᴴ (W_other − W_this) y| / (2|s|)`` (the perturbation of a root of
    ``s² + s D + K`` by a change ΔW of K), which cannot then be consistent.
    """
    parts = branches(red, speed)
    if len(parts) == 2 and not on_branch(parts[0], s.imag, speed):
        parts = parts[::-1]
    found = []
    for i, branch in enumerate(parts):
        root, vec, converged = newton(red, speed, s, y, weights=branch.weights)
        same = converged and abs(np.vdot(y, vec)) ** 2 >= SAME_MODE_MAC * np.vdot(y, y).real
        found.append((branch, root, vec, same))
        if i == 0 and len(parts) == 2 and same and on_branch(branch, root.imag, speed):
            distance = branch_distance(red, branch.weights, parts[1].weights, np.array([root]), vec[:, None])[0]
            if abs(root.imag - speed) > 10 * distance:
                return root, vec, True
    if len(found) == 2:  # near the line: a branch whose Newton reached another mode gets its exact roots
        found = [f if f[3] else _branch_mode(red, speed, f[0], y) for f in found]
    consistent = [(root, vec) for branch, root, vec, same in found if same and on_branch(branch, root.imag, speed)]
    if consistent:
        root, vec = max(consistent, key=lambda rv: rv[0].real)
        return root, vec, True
    if len(found) == 2 and found[0][3] and found[1][3]:
        found.sort(key=lambda f: f[0].low)
        (lower, s_lo, y_lo, _), (upper, s_hi, y_hi, _) = found
        if s_lo.imag > speed > s_hi.imag:
            pair = line_root(red, speed, lower.weights, upper.weights, (s_lo, y_lo), (s_hi, y_hi))
            if pair is not None:
                return pair[0], pair[1], True
    return s, y, False


def branch_distance(
    red: ReducedModel, weights: LossCoefficients, other: LossCoefficients, roots: np.ndarray, vectors: np.ndarray
) -> np.ndarray:
    """First-order distance [rad/s] from each root ``roots[k]`` of the branch with loss weights
    ``weights`` (unit modal coordinates ``vectors[:, k]``) to the same mode's root on the branch
    with weights ``other``: ``|yᴴ (W_other − W) y| / (2|s|)``, the perturbation of a root of
    ``s² + s D + K`` by a change ΔW of K (:func:`mode_root`'s test for skipping the other branch)."""
    delta = (
        (other.fixed - weights.fixed) * (red.F @ vectors)
        + (other.lateral - weights.lateral) * (red.L @ vectors)
        + (other.circulatory - weights.circulatory) * (red.S @ vectors)
    )
    return np.abs(np.einsum("ij,ij->j", vectors.conj(), delta)) / (2 * np.abs(roots))


def _branch_mode(red: ReducedModel, speed: float, branch: Branch, y: np.ndarray):
    """This mode's root on ``branch`` from the branch's exact roots, when Newton's method from the
    mode's previous eigenvalue reached another mode (a close neighbour: the backward whirl of a
    rotor without gyroscopic split lies 1e-6 of ω from the forward root at the line): the
    branch root of largest MAC with ``y`` (at least :data:`SAME_MODE_MAC`), refined by Newton's
    method. Returns ``(branch, s, Y, same)`` like :func:`mode_root`'s candidates; ``same`` is
    False when no branch root is this mode's."""
    s, Y = branch_roots(red, speed, branch.weights)
    y = np.asarray(y, dtype=complex)
    mac = np.abs(Y.conj().T @ y) ** 2 / np.vdot(y, y).real if s.size else np.zeros(0)
    if not s.size or mac.max() < SAME_MODE_MAC:
        return branch, s[0] if s.size else 0j, y, False
    k = int(np.argmax(mac))
    root, vec, converged = newton(red, speed, s[k], Y[:, k], weights=branch.weights)
    if not (converged and abs(np.vdot(Y[:, k], vec)) ** 2 >= SAME_MODE_MAC):
        root, vec = s[k], Y[:, k]
    return branch, root, vec, True


def predicted_start(speeds, eig, states, k):
    """Newton's starting point at speeds[k] for every mode ``(s, Y)``: the eigenvalues
    extrapolated from the previous speeds (quadratic through three, linear through two, the
    last one alone at k = 1) and the shapes extrapolated linearly from the last two (each
    column of speeds[k − 2] turned to the phase of its successor first), where a mode's two
    shapes agree (MAC at least :data:`EXTRAPOLATED_SHAPE_MAC`; else the last shape). What converges
    is the root Newton's method reaches from there, to its tolerance, as from the last speed's
    point: the better start saves a step where the curve bends (16 % of the steps of the
    thesis shafts' and the embedded designs' stability and Campbell tracking)."""
    speed = speeds[k]
    Y_prev = states[k - 1]
    if k == 1:
        return eig[0], Y_prev
    x0, x1, x2 = speeds[k - 3 : k] if k >= 3 else (None, *speeds[k - 2 : k])
    if x0 is None:
        predicted = eig[k - 1] + (speed - x2) / (x2 - x1) * (eig[k - 1] - eig[k - 2])
    else:  # Lagrange's quadratic through the last three speeds
        predicted = (
            (speed - x1) * (speed - x2) / ((x0 - x1) * (x0 - x2)) * eig[k - 3]
            + (speed - x0) * (speed - x2) / ((x1 - x0) * (x1 - x2)) * eig[k - 2]
            + (speed - x0) * (speed - x1) / ((x2 - x0) * (x2 - x1)) * eig[k - 1]
        )
    Y_old = states[k - 2]
    inner = np.einsum("ij,ij->j", Y_old.conj(), Y_prev)
    norms = (np.abs(Y_old) ** 2).sum(axis=0) * (np.abs(Y_prev) ** 2).sum(axis=0)
    same = np.abs(inner) ** 2 >= EXTRAPOLATED_SHAPE_MAC * norms
    phase = np.where(same, inner / np.where(same, np.abs(inner), 1.0), 0.0)
    t = (speed - x2) / (x2 - x1)
    start = np.where(same, Y_prev + t * (Y_prev - Y_old * phase), Y_prev)
    return predicted, start
