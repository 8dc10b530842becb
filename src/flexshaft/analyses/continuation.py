"""Newton's method for several modes at once: one continuation step of every tracked mode.

A tracking (:func:`~flexshaft.analyses.campbell.track_modes`) continues each of its modes from
the previous speeds with :func:`~flexshaft.analyses.eigen.newton` (the viscous model) or
:func:`~flexshaft.analyses.hysteretic_roots.mode_root` (the hysteretic loss). At one speed
every mode's problem is the same matrix polynomial ``T(s)`` with one of at most two sets of
loss weights (the two sides of the synchronous line), so the modes' iterations differ only in
``s`` and ``y``: :func:`newton_many` runs them side by side, each mode's step exactly the
one :func:`~flexshaft.analyses.eigen.newton` takes (the same update, tolerance, iteration limit
and outcome), with the modes' ``nb × nb`` systems solved as one stack. A mode leaves the stack
when it converges, so each mode takes the iterations it would take alone.

:func:`mode_roots` is :func:`~flexshaft.analyses.hysteretic_roots.mode_root` for every mode:
the first branch's Newton (the branch of the mode's own side of the line) runs for all modes
at once, and a mode whose root there is consistent and farther from the line than its
first-order distance to the other branch's root is taken, as
:func:`~flexshaft.analyses.hysteretic_roots.mode_root` takes it; any other mode (near the
line, where both branches are solved, a fold or an on-line root is possible) is solved by
:func:`~flexshaft.analyses.hysteretic_roots.mode_root` itself.

Cost: the LUs are the same as one mode at a time; what goes is each mode's own Python and call
overhead per step (measured: the whirl stability of the thesis's three shafts 4-10 % faster at
41 speeds and 8 modes, nb 77; a screening assessment of the tuned design 4 %,
benchmarks/assessment_speed.py). The eigenvalues agree with the one-mode-at-a-time iteration
to round-off (1e-16 relative, measured on the same cases).
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.eigen import NEWTON_MAX_STEPS, NEWTON_TOLERANCE, ReducedModel, newton, viscous_model
from flexshaft.analyses.hysteretic_roots import SAME_MODE_MAC, branch_distance, branches, mode_root, on_branch
from flexshaft.analyses.loss import LossCoefficients

__all__ = ["mode_roots", "newton_many"]

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
    """:func:`~flexshaft.analyses.hysteretic_roots.mode_root` of each mode ``(s[k], Y[:, k])``
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
