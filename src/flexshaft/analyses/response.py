"""Harmonic, synchronous (imbalance) and static response (thesis §2.3–2.5).

``q = H(ω) Q`` is never formed as an inverse: each frequency is one banded LU solve
(:class:`~flexshaft.analyses.banded.BandedHarmonicSolver`) for all load cases at once.
"""

from __future__ import annotations

import html
import warnings

import numpy as np

from flexshaft.analyses.banded import PIVOT_SCREEN, BandedHarmonicSolver, SingularSystemError, solver_for
from flexshaft.analyses.datasets import response_dataset
from flexshaft.analyses.guards import (
    check_finite_array,
    check_model,
    check_spin_speed,
    check_spin_speeds,
    require_finite,
)
from flexshaft.analyses.loss import frequency_coefficients
from flexshaft.analyses.refinement import checked_solve
from flexshaft.analyses.results import ResultMixin, StationWarning, html_table
from flexshaft.assembly.dofs import DofMap
from flexshaft.assembly.model import Model
from flexshaft.assembly.sparse import restrict
from flexshaft.parallel.point_label import labelled
from flexshaft.plot.response import bode_figure, orbit_figure
from flexshaft.units import rad_s_to_rpm

__all__ = [
    "HarmonicResponse",
    "SingularSystemError",
    "frequency_response",
    "imbalance_response",
    "orbit_amplitude",
    "static_actuator_forces",
    "static_response",
]


class HarmonicResponse(np.ndarray, ResultMixin):
    """Complex amplitudes on the full DOF vector [m, rad], an ndarray with its context.

    Shape ``(ndof, [ncases,] nfrequencies)`` (or without the trailing axis for one scalar
    frequency). Indexing, arithmetic and ufuncs give plain ndarrays; the object itself carries
    ``frequencies`` (excitation ω per trailing index [rad/s]), ``spin_speeds`` (Ω [rad/s]),
    ``dofs`` (the model's :class:`~flexshaft.assembly.dofs.DofMap`), ``excitation``
    ("harmonic" or "imbalance") and ``internal_damping``, and offers ``.plot()`` and
    ``.to_dataset()``.
    """

    _CONTEXT = ("frequencies", "spin_speeds", "dofs", "excitation", "internal_damping")
    # the context (None on an array viewed as a HarmonicResponse without it: repr falls back)
    frequencies: np.ndarray
    spin_speeds: np.ndarray
    dofs: DofMap
    excitation: str
    internal_damping: str
    plots = {"bode": "plot_bode", "orbit": "plot_orbit"}

    def __new__(cls, values, frequencies, spin_speeds, dofs: DofMap, excitation: str, internal_damping: str):
        obj = np.asarray(values).view(cls)
        obj.frequencies = np.atleast_1d(np.asarray(frequencies, dtype=float))
        obj.spin_speeds = np.atleast_1d(np.asarray(spin_speeds, dtype=float))
        obj.dofs, obj.excitation, obj.internal_damping = dofs, excitation, internal_damping
        return obj

    def __array_finalize__(self, obj) -> None:
        for name in self._CONTEXT:
            setattr(self, name, getattr(obj, name, None))

    def __getitem__(self, key):
        return np.asarray(self)[key]

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        inputs = tuple(np.asarray(x) if isinstance(x, HarmonicResponse) else x for x in inputs)
        if "out" in kwargs:
            kwargs["out"] = tuple(np.asarray(x) if isinstance(x, HarmonicResponse) else x for x in kwargs["out"])
        return getattr(ufunc, method)(*inputs, **kwargs)

    def __reduce__(self):  # pickles as a plain array
        return np.asarray(self).__reduce__()

    def __repr__(self) -> str:
        if self.dofs is None:
            return repr(np.asarray(self))
        f = rad_s_to_rpm(self.frequencies) if self.excitation == "imbalance" else self.frequencies / (2 * np.pi)
        unit = "rpm" if self.excitation == "imbalance" else "Hz"
        span = f"{f.min():.4g}–{f.max():.4g} {unit}" if f.size > 1 else f"{f[0]:.4g} {unit}"
        return (
            f"HarmonicResponse({self.excitation}, shape {self.shape}, {f.size} frequencies {span}, "
            f"peak |q| {np.abs(np.asarray(self)).max():.3g} m or rad, internal damping {self.internal_damping!r})"
        )

    __str__ = __repr__

    def _repr_html_(self) -> str:
        if self.dofs is None:
            return f"<pre>{html.escape(repr(np.asarray(self)))}</pre>"
        return html_table(("HarmonicResponse", ""), _summary(self))

    def to_dataset(self):
        """Translations of every node by load case and frequency (see :mod:`flexshaft.analyses.datasets`)."""

        return response_dataset(self)

    # -- figures ---------------------------------------------------------------------------

    def _cube(self) -> np.ndarray:
        """The amplitudes as (ndof, ncases, nfrequencies)."""
        q = np.asarray(self)
        if q.ndim == 3:
            return q
        if q.ndim == 2:
            return q[:, None, :] if q.shape[1] == self.frequencies.size else q[:, :, None]
        return q[:, None, None]

    def _abscissa(self) -> tuple[np.ndarray, str]:
        if self.excitation == "imbalance":
            return rad_s_to_rpm(self.spin_speeds), "spin speed Ω [rpm]"
        return self.frequencies / (2 * np.pi), "excitation frequency [Hz]"

    def _stations(self, stations, q: np.ndarray) -> dict[str, int]:
        """``{label: shaft node}`` of the requested stations [m] (default: the node of the
        largest orbit)."""
        dm = self.dofs
        n = np.arange(dm.n_shaft_nodes)
        if stations is None:
            amp = orbit_amplitude(q[dm.shaft(n, "v")], q[dm.shaft(n, "w")])
            node = int(np.unravel_index(np.argmax(amp), amp.shape)[0])
            return {f"x = {dm.shaft_x[node]:.2f} m (largest orbit)": node}
        if isinstance(stations, dict):
            items = list(stations.items())
        else:
            xs = np.atleast_1d(np.asarray(stations, dtype=float))
            items = [(None, x) for x in xs]
        out = {}
        lo, hi = dm.shaft_x[0], dm.shaft_x[-1]
        for name, x in items:
            if not np.isfinite(x) or not lo - 1e-9 <= x <= hi + 1e-9:
                raise ValueError(f"station must be a shaft position within [{lo:g}, {hi:g}] m (got {x!r})")
            node = dm.node_at("shaft", float(x))
            if abs(dm.shaft_x[node] - x) > 1e-9 * max(hi - lo, 1.0):
                warnings.warn(
                    labelled(
                        f"station {x:g} m is not a shaft node: shown at the nearest node, x = {dm.shaft_x[node]:g} m "
                        "(the response is computed at the nodes; mesh.shaft_elements sets them)"
                    ),
                    StationWarning,
                    stacklevel=4,
                )
            out[name or f"x = {dm.shaft_x[node]:.2f} m"] = node
        return out

    def plot_bode(self, ax=None, *, station=None, direction: str = "v", case: int | None = None, **kwargs):
        """Amplitude and phase against speed (imbalance) or frequency at shaft ``station`` [m]
        (a float, a sequence, or ``{label: x}``; default the node of the largest orbit), for
        ``direction`` "v" (vertical), "w" (lateral) or "both". ``case``: the load case (default
        the one with the largest response there). Other keywords (``operating_rpm``, ``gap``
        [m], ``title``) go to :func:`flexshaft.plot.response.bode_figure`."""

        if direction not in ("v", "w", "both"):
            raise ValueError(f"direction must be 'v', 'w' or 'both' (got {direction!r})")
        q = self._cube()
        if q.shape[2] < 2:
            raise ValueError("a Bode plot needs a response at several speeds or frequencies (this one has 1)")
        if case is not None and not (int(case) == case and 0 <= case < q.shape[1]):
            raise ValueError(f"case must be an integer in 0..{q.shape[1] - 1} (got {case!r})")
        dm = self.dofs
        curves = {}
        for label, node in self._stations(station, q).items():
            k = (
                case
                if case is not None
                else int(np.argmax(orbit_amplitude(q[dm.shaft(node, "v")], q[dm.shaft(node, "w")]).max(axis=-1)))
            )
            suffix = f", case {k + 1}" if q.shape[1] > 1 else ""
            for field in ("v", "w") if direction == "both" else (direction,):
                curves[f"{label}, {field}{suffix}"] = q[dm.shaft(node, field), k]
        x, x_label = self._abscissa()
        if self.excitation != "imbalance":
            kwargs.setdefault("title", "Frequency response (Bode)")
        return bode_figure(x, curves, x_label=x_label, ax=ax, **kwargs)

    def plot_orbit(
        self, ax=None, *, station=None, speed_rpm: float | None = None, case: int | None = None, gap=None, **kwargs
    ):
        """Shaft orbits (v, w) at ``station`` [m] (a float, a sequence, or ``{label: x}``; default
        the node of the largest orbit) at the analysed point nearest ``speed_rpm`` [rpm]
        (spin speed for an imbalance response, else excitation frequency × 60; default the last).
        ``gap`` [m] (a float or ``{label: gap}``) draws the auxiliary-bearing clearance."""

        q = self._cube()
        x, _ = self._abscissa()
        rpm = x if self.excitation == "imbalance" else x * 60.0
        i = q.shape[2] - 1 if speed_rpm is None else int(np.argmin(np.abs(rpm - float(speed_rpm))))
        dm = self.dofs
        orbits = {}
        for label, node in self._stations(station, q[..., i : i + 1]).items():
            v, w = q[dm.shaft(node, "v"), :, i], q[dm.shaft(node, "w"), :, i]
            k = case if case is not None else int(np.argmax(orbit_amplitude(v, w)))
            orbits[label] = (v[k], w[k])
        what = "spin speed" if self.excitation == "imbalance" else "excitation"
        kwargs.setdefault("title", f"Shaft orbits at {what} {rpm[i]:.0f} rpm")
        return orbit_figure(orbits, gap, ax=ax, **kwargs)


def _summary(q: HarmonicResponse) -> list[list[str]]:
    """The rows of a response's notebook table (what its repr says, one line each)."""
    f = rad_s_to_rpm(q.frequencies) if q.excitation == "imbalance" else q.frequencies / (2 * np.pi)
    unit = "rpm" if q.excitation == "imbalance" else "Hz"
    return [
        ["excitation", q.excitation],
        ["shape", str(q.shape)],
        ["frequencies", f"{f.size}, {f.min():.4g} to {f.max():.4g} {unit}"],
        ["peak |q| [m or rad]", f"{np.abs(np.asarray(q)).max():.3g}"],
        ["internal damping", q.internal_damping],
    ]


def _solve_many(model: Model, loads, points, solver: BandedHarmonicSolver | None = None) -> np.ndarray:
    """Solve at (ω, Ω, load scale) points; returns (ndof, ..., npoints)."""
    solver = solver or solver_for(model)
    Q = np.asarray(loads)
    rhs = Q[solver.free].astype(complex)
    points = list(points)
    out = np.zeros(Q.shape + (len(points),), dtype=complex)
    # a block of solutions side by side, then written to the trailing point axis at once:
    # one point's column of (ndof, ..., npoints) touches a cache line per DOF; a block of
    # _BLOCK points fills whole lines, and costs only _BLOCK solutions of memory
    block = np.empty((_BLOCK,) + rhs.shape, dtype=complex)
    scales = np.array([scale for _, _, scale in points], dtype=float).reshape((-1,) + (1,) * rhs.ndim)
    start = 0
    for k, x in enumerate(solver.sweep([(omega, speed) for omega, speed, _ in points], rhs)):
        block[k - start] = x
        if k - start == _BLOCK - 1 or k == len(points) - 1:
            done = block[: k - start + 1] * scales[start : k + 1]
            out[solver.free, ..., start : k + 1] = np.moveaxis(done, 0, -1)
            start = k + 1
    return out


#: Points of a harmonic sweep written to the output together (see :func:`_solve_many`).
_BLOCK = 32


def frequency_response(model: Model, loads, omega, speed: float | None = None) -> HarmonicResponse:
    """Complex amplitudes q(ω) for harmonic loads ``Q e^{iωt}`` at spin speed Ω.

    Parameters
    ----------
    loads : ndarray
        Load vector(s) on the full DOF vector, (ndof,) or (ndof, ncases) [N, N m].
    omega : float or array_like
        Excitation frequencies [rad/s].
    speed : float or None
        Spin speed Ω [rad/s] (the model's operating speed when None).

    Returns
    -------
    HarmonicResponse
        Same shape as ``loads`` for scalar ω, else with a trailing axis over ω [m, rad].

    Raises
    ------
    SingularSystemError
        When Z(ω) is singular (an undamped resonance).
    """
    check_model(model)
    speed = check_spin_speed(model.speed if speed is None else speed)
    try:
        omegas = np.atleast_1d(np.asarray(omega, dtype=float))
    except (TypeError, ValueError):
        raise ValueError(f"excitation frequencies must be numbers [rad/s] (got {omega!r})") from None
    if not np.all(np.isfinite(omegas)) or np.any(omegas < 0):
        raise ValueError(f"excitation frequencies must be finite and >= 0 rad/s (got {omega!r})")
    _check_loads(model, loads)
    out = _solve_many(model, loads, [(w, speed, 1.0) for w in omegas])
    require_finite("harmonic response", out)
    out = out[..., 0] if np.ndim(omega) == 0 else out
    return HarmonicResponse(
        out, omegas, np.full(omegas.size, float(speed)), model.dofs, "harmonic", model.internal_damping
    )


def _check_loads(model: Model, loads) -> None:
    """Load vector(s) on the full DOF vector: finite, (ndof,) or (ndof, ncases)."""
    Q = check_finite_array("loads", loads, "N, N m")
    if Q.ndim not in (1, 2) or Q.shape[0] != model.dofs.size:
        raise ValueError(f"loads must have shape ({model.dofs.size},) or ({model.dofs.size}, ncases) (got {Q.shape})")


def imbalance_response(model: Model, speeds, loads_per_speed_squared) -> HarmonicResponse:
    """Synchronous response to a rotating load ``Ω² Q₁ e^{iΩt}`` at each speed Ω.

    Parameters
    ----------
    speeds : array_like
        Spin speeds Ω [rad/s]; the excitation frequency equals the speed.
    loads_per_speed_squared : ndarray
        Q₁ (ndof,) or (ndof, ncases) [N s²], e.g. from
        :func:`flexshaft.assembly.loads.imbalance_loads`.

    Returns
    -------
    HarmonicResponse
        (ndof, [ncases,] nspeeds) complex amplitudes [m, rad].
    """
    check_model(model)
    speeds = check_spin_speeds(speeds)
    _check_loads(model, loads_per_speed_squared)
    out = _solve_many(model, loads_per_speed_squared, [(s, s, s * s) for s in speeds])
    require_finite("imbalance response", out)
    return HarmonicResponse(out, speeds, speeds, model.dofs, "imbalance", model.internal_damping)


def _static_parts(model: Model, speed: float):
    """Static stiffness (storage + finite actuator laws + circulatory loss at ω = 0) and the
    integrating actuators, which instead hold their sensed displacement at zero."""

    if model.all_pd and all(a.basis_stiffness == a.collocated_law.kp for a in model.actuators):
        K = model.K + model.Kp  # PD laws with K_p >= 0: the basis stiffness is the static one
    else:
        K = model.K + model.actuator_matrix(
            [
                0.0 if a.integrates else (a.collocated_law.static_gain if a.collocated else -a.negative_stiffness)
                for a in model.actuators
            ]
        )
        for a in model.actuators:
            if not a.collocated and not a.integrates:
                K = K + a.feedback.static_gain * (a.lateral_rows.T @ a.sensing_rows)
    circulatory = frequency_coefficients(model.internal_damping, 0.0, speed).circulatory
    if circulatory:
        K = K + circulatory * model.loss_circulatory
    return K.tocsr(), [a for a in model.actuators if a.integrates]


def static_response(model: Model, loads, speed: float | None = None, *, within: np.ndarray | None = None) -> np.ndarray:
    """Static displacement of the spinning driveline under constant loads [m, rad].

    ``(K + K_a(0) + L(0, Ω)) q = Q`` with the storage stiffness K, the actuators' static
    stiffness and the loss at zero frequency: nothing for the fixed-frame loss, but for the
    ``"rotating"`` internal-damping model the circulatory ``K_lat S`` of the spinning shaft,
    whose material is cycled at Ω by a constant deflection (the deflection then turns slightly
    sideways; :mod:`flexshaft.analyses.loss`).

    Actuators. A bearing with finite static gain adds ``B_aᵀ G(0) B_s − k_s B_aᵀ B_a`` (a PD
    law: ``K_p``; the magnet's negative stiffness counts, so an open-loop magnet may make the
    static problem singular, reported as such). A bearing whose controller integrates (PID:
    C(0) infinite) is the static equilibrium of its integrator: it holds its sensed
    displacement at zero, ``B_s q = 0``, with whatever force ``λ`` on the shaft that takes (up
    to its saturation, not checked here); the problem is then solved with the constraint as
    ``[[K, −B_aᵀ], [B_s, 0]] [q; λ] = [Q; 0]`` (the carried forces −λ are returned by
    :func:`static_actuator_forces`).

    Parameters
    ----------
    loads : ndarray
        Load vector(s) on the full DOF vector (ndof,) or (ndof, ncases) [N, N m].
    speed : float or None
        Spin speed Ω [rad/s] (the model's operating speed when None).
    within : ndarray of bool, optional
        Solve on these free DOFs only (a mask in the model's free-DOF order), zero elsewhere:
        exact when they are whole blocks the stiffness does not couple to the rest and the loads
        are zero outside them (e.g. :meth:`~flexshaft.analyses.banded.BandedHarmonicSolver.coupled`:
        the lateral blocks of a driveline whose torsion is free, so that the whole problem is
        singular while the lateral one is not).
    """
    return _static_solve(model, loads, speed, within)[0]


def static_actuator_forces(model: Model, loads, speed: float | None = None) -> dict[str, np.ndarray]:
    """Static force carried by each actuator (v, w) [N] under ``loads`` (see
    :func:`static_response`); for an integrating actuator its constraint force λ."""
    q, forces = _static_solve(model, loads, speed)
    out = {}
    for a in model.actuators:
        out[a.name] = forces[a.name] if a.name in forces else np.real(a.carried_force(q, 0.0))
    return out


def _static_solve(model: Model, loads, speed: float | None, within: np.ndarray | None = None):
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    check_model(model)
    free = model.dofs.free
    speed = check_spin_speed(model.speed if speed is None else speed)
    _check_loads(model, loads)
    if within is not None:
        within = np.asarray(within, dtype=bool)
        if within.shape != free.shape:
            raise ValueError(f"within must be a mask of the {free.size} free DOFs (got shape {within.shape})")
        if np.any(np.asarray(loads)[free[~within]] != 0):
            raise ValueError("within must hold every loaded DOF: the loads are not zero outside it")
        free = free[within]
    Q = np.asarray(loads)
    if np.iscomplexobj(Q) and np.any(Q.imag != 0):
        raise ValueError("static loads must be real [N, N m] (got complex values)")
    Q = Q.real.astype(float)
    K, holding = _static_parts(model, speed)
    A = restrict(K, free)
    rhs = Q[free]
    if holding:
        Ba = sp.vstack([a.lateral_rows.tocsr()[:, free] for a in holding]).tocsr()
        Bs = sp.vstack([a.sensing_rows.tocsr()[:, free] for a in holding]).tocsr()
        A = sp.bmat([[A, -Ba.T], [Bs, None]]).tocsr()
        rhs = np.concatenate([rhs, np.zeros((Ba.shape[0],) + rhs.shape[1:])])
    singular = (
        "static stiffness is singular{}: the model has an unconstrained rigid-body motion (a direction "
        "no bearing, fixed DOF or coupling holds), or a magnetic bearing's negative stiffness k_s cancels "
        "its static control stiffness"
    )
    try:
        lu = spla.splu(A.tocsc())
    except RuntimeError as exc:
        raise SingularSystemError(singular.format("")) from exc
    x = lu.solve(rhs)
    pivots = np.abs(lu.U.diagonal())
    if not np.all(np.isfinite(x)) or not pivots.min() >= PIVOT_SCREEN * pivots.max():
        # a pivot of round-off size: regular but ill-conditioned, or singular to working
        # precision (a rigid-body motion leaves a pivot of ε‖K‖ instead of 0, and the solution
        # grew as 1/ε: up to 2e12 m for 100 N on a free-free driveline)
        refined = checked_solve(A, rhs.reshape(rhs.shape[0], -1))
        if refined is None:
            raise SingularSystemError(singular.format(" to working precision"))
        x = refined.reshape(rhs.shape)
    out = np.zeros(Q.shape)
    out[free] = x[: free.size]
    require_finite("static response", out)
    # λ is the force on the shaft (K q = Q + B_aᵀ λ); the bearing carries −λ
    forces = {a.name: -x[free.size + 2 * k : free.size + 2 * k + 2] for k, a in enumerate(holding)}
    return out, forces


def orbit_amplitude(a, b) -> np.ndarray:
    """Largest excursion of the orbit ``(Re(a e^{iφ}), Re(b e^{iφ}))`` over φ: the major
    semi-axis ``√((|a|² + |b|² + |a² + b²|)/2)`` [same unit as a, b], computed as the mean
    radius of the orbit's forward and backward circles, ``(|a + ib| + |a − ib|)/2`` (squared it
    is the same: ``|a ± ib|²`` sum to ``2(|a|² + |b|²)`` and their product is ``|a² + b²|``)."""
    a, b = np.asarray(a), np.asarray(b)
    ib = b * 1j
    return 0.5 * (np.abs(a + ib) + np.abs(a - ib))
