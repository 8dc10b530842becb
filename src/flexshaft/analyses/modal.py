"""Damped natural frequencies, damping and mode shapes at one spin speed.

``(s² M + s (Ω G + C + K_d + D_eq) + K + K_p + K_eq) φ = 0`` (plus controller states), with the
hysteretic loss of every member at each mode's own frequency
(:mod:`flexshaft.analyses.loss`, :mod:`flexshaft.analyses.eigen`), the same physics as the
forced response. ``damped=False`` keeps only the gyroscopic terms (and at rest gives the
undamped natural frequencies of ``(K + K_p) φ = ω² M φ``).

Labels (kind, whirl, component) are those of :mod:`flexshaft.analyses.classify`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.classify import EnergyShares, circular_pairs, label_modes, whirl_ratio
from flexshaft.analyses.datasets import modes_dataset
from flexshaft.analyses.eigen import ReducedModel, lowest_modes, reduce, spectrum
from flexshaft.analyses.eigen_error import (
    EIGENVALUE_TOLERANCE,
    accuracy_text,
    accurate_basis,
    accurate_reduction,
    check_tolerance,
    eigenvalue_errors,
)
from flexshaft.analyses.guards import check_count, check_model, check_spin_speed, require_finite
from flexshaft.analyses.hysteretic_roots import damped_modes
from flexshaft.analyses.results import ResultMixin, dataframe, html_table, text_table
from flexshaft.assembly.dofs import DofMap
from flexshaft.assembly.model import Model
from flexshaft.parallel.threads import single_blas_thread
from flexshaft.plot.shapes import mode_shapes_figure
from flexshaft.units import hz_to_rpm, rad_s_to_hz, rad_s_to_rpm

__all__ = ["Modes", "modes", "whirl_ratio", "default_basis_size"]


def default_basis_size(n_modes: int) -> int:
    """Modal basis used for ``n_modes`` wanted modes (truncation error ≲ 1e-5 on the baseline)."""
    return max(4 * n_modes, 60)


#: Caption of the modes' tables.
_CAPTION = "f damped frequency, ζ damping ratio, δ log decrement; modes numbered from 1 by f (Python index + 1)"


def _log_decrement(zeta: np.ndarray) -> np.ndarray:
    return 2 * np.pi * zeta / np.sqrt(np.maximum(1 - zeta * zeta, 1e-300))


@dataclass(frozen=True)
class Modes(ResultMixin):
    """Eigen-solution at one speed: the lowest modes, numbered by damped frequency Im s / 2π
    (:attr:`frequencies`, the f of every table; mode ``k`` of the Python API is mode ``k + 1``
    of the command line and the report; :func:`~flexshaft.analyses.eigen.lowest_modes`). A
    divergent root (Im s = 0) comes first.

    Attributes
    ----------
    speed : float
        Spin speed Ω [rad/s].
    eigenvalues : ndarray
        s = −ζω_n + iω_d [rad/s] (one per mode, Im s > 0; a divergent root, see
        :attr:`divergent`, is real and positive).
    shapes : ndarray
        Mode shapes on the full DOF vector, (ndof, n_modes), unit maximum translation.
    kind : ndarray of str
        "lateral", "torsional" or "axial".
    whirl : ndarray of str
        "forward", "backward", "planar" (lateral modes) or "none".
    whirl_ratios : ndarray
        Whirl ratio in [−1, 1].
    component : ndarray of str
        "shaft", "boom" or "coupled".
    shares : EnergyShares
        Kinetic-energy shares by DOF group.
    internal_damping : str
        The internal-damping model used.
    error_estimate : ndarray or None
        Estimated relative error |s* − s|/|s| of each eigenvalue against the full (unreduced)
        eigenproblem (:mod:`flexshaft.analyses.eigen_error`; NaN for a divergent root).
    """

    speed: float
    eigenvalues: np.ndarray
    shapes: np.ndarray
    kind: np.ndarray
    whirl: np.ndarray
    whirl_ratios: np.ndarray
    component: np.ndarray
    shares: EnergyShares
    dofs: DofMap
    internal_damping: str = "rotating"
    error_estimate: np.ndarray | None = None

    plots = {"shapes": "plot_shapes"}

    def __repr__(self) -> str:
        rpm = rad_s_to_rpm(self.speed)
        freqs = ", ".join(f"{f:.3g}" for f in self.frequencies[:6])
        more = ", ..." if self.eigenvalues.size > 6 else ""
        return (
            f"Modes({self.eigenvalues.size} modes at {rpm:.0f} rpm: [{freqs}{more}] Hz, "
            f"internal damping {self.internal_damping!r}{accuracy_text(self)})"
        )

    #: Columns of :meth:`table` as printed (unit in each header).
    COLUMNS = ("mode", "f [Hz]", "f [rpm]", "ζ [-]", "δ [-]", "kind", "whirl", "component")

    def table(self) -> list[dict]:
        """One row per mode, numbered from 1 as the command line and the report number them:
        damped frequency [Hz] and as a spin speed [rpm], damping ratio, log decrement, kind,
        whirl, component and the shaft's share of the kinetic energy."""
        return [
            {
                "mode": k + 1,
                "frequency_Hz": float(self.frequencies[k]),
                "frequency_rpm": float(hz_to_rpm(self.frequencies[k])),
                "damping_ratio": float(self.damping_ratios[k]),
                "log_decrement": float(self.log_decrements[k]),
                "kind": str(self.kind[k]),
                "whirl": str(self.whirl[k]),
                "component": str(self.component[k]),
                "shaft_energy_fraction": float(self.shaft_fractions[k]),
            }
            for k in range(self.eigenvalues.size)
        ]

    def _rows(self) -> list[list]:
        return [
            [
                r["mode"],
                r["frequency_Hz"],
                r["frequency_rpm"],
                r["damping_ratio"],
                r["log_decrement"],
                r["kind"],
                "—" if r["whirl"] == "none" else r["whirl"],
                r["component"],
            ]
            for r in self.table()
        ]

    def _title(self) -> str:
        rpm = rad_s_to_rpm(self.speed)
        return f"{self.eigenvalues.size} modes at {rpm:.0f} rpm ({self.internal_damping} internal damping)"

    def __str__(self) -> str:
        """The per-mode table (``print(m)``), numbered from 1."""
        return text_table(self.COLUMNS, self._rows(), title=self._title(), caption=_CAPTION)

    def _repr_html_(self) -> str:
        return html_table(self.COLUMNS, self._rows(), title=self._title(), caption=_CAPTION)

    def to_dataframe(self):
        """:meth:`table` as a :class:`pandas.DataFrame` indexed by the mode number (from 1), SI
        and engineering units in the column names (pandas is imported here; xarray brings it)."""
        rows = self.table()
        return dataframe({key: [r[key] for r in rows] for key in rows[0]} if rows else {"mode": []}, index="mode")

    def to_dataset(self):
        """Frequencies, damping, labels and shaft/boom translations of every mode (xarray)."""

        return modes_dataset(self)

    def nearest(self, frequency: float, n: int = 6) -> np.ndarray:
        """Indices of the ``n`` modes whose damped frequency is nearest ``frequency`` [Hz], by
        frequency."""
        if int(n) != n or n < 1:
            raise ValueError(f"n must be an integer >= 1 (got {n!r})")
        order = np.argsort(np.abs(self.frequencies - frequency), kind="stable")[: int(n)]
        return np.sort(order)

    def plot_shapes(self, ax=None, *, modes=None, n: int = 6, near_rpm: float | None = None, bearings_x=(), **kwargs):
        """Two-plane shapes (v, w) of shaft and boom of the ``n`` modes nearest the spin
        frequency (``near_rpm`` [rpm] instead of this result's speed; the lowest ``n`` at rest), or
        of ``modes`` (0-based indices). ``bearings_x`` [m] marks the bearings. Returns the figure."""

        rpm = rad_s_to_rpm(self.speed) if near_rpm is None else float(near_rpm)
        f_spin = rpm / 60.0
        if modes is not None:
            chosen = np.atleast_1d(np.asarray(modes, dtype=int))
            if chosen.size == 0 or np.any((chosen < 0) | (chosen >= self.eigenvalues.size)):
                raise ValueError(f"modes must be indices in 0..{self.eigenvalues.size - 1} (got {modes!r})")
        elif f_spin > 0:
            chosen = self.nearest(f_spin, min(int(n), self.eigenvalues.size))
        else:
            chosen = np.arange(min(int(n), self.eigenvalues.size))
        dm = self.dofs
        ns, nb = np.arange(dm.n_shaft_nodes), np.arange(dm.n_boom_nodes)
        shaft, boom = [], []
        delta = self.log_decrements
        for k in chosen:
            phi = self.shapes[:, k]
            ratio = f"{self.frequencies[k] / f_spin:.2f}× spin, " if f_spin > 0 else ""
            label = (
                f"mode {k + 1}: {self.frequencies[k]:.2f} Hz ({ratio}{self.whirl[k]})\n"
                f"{self.kind[k]}, {self.component[k]}, δ = {delta[k]:.3g}"
            )
            shape = {"label": label, "v": phi[dm.shaft(ns, "v")], "w": phi[dm.shaft(ns, "w")]}
            if self.kind[k] in ("torsional", "axial"):  # its lateral v, w are round-off: draw what moves
                shape["along"] = (self.kind[k], phi[dm.shaft(ns, "theta" if self.kind[k] == "torsional" else "u")])
            shaft.append(shape)
            if dm.n_boom_nodes:
                boom.append({"v": phi[dm.boom(nb, "v")], "w": phi[dm.boom(nb, "w")]})
        if modes is None and f_spin > 0:
            title = (
                f"Mode shapes at {rad_s_to_rpm(self.speed):.0f} rpm: the {chosen.size} modes nearest the spin "
                f"frequency {f_spin:.1f} Hz"
            )
        else:
            title = f"Mode shapes at {rad_s_to_rpm(self.speed):.0f} rpm"
        kwargs.setdefault("title", title)
        return mode_shapes_figure(
            dm.shaft_x,
            shaft,
            dm.boom_x if dm.n_boom_nodes else None,
            boom or None,
            bearings_x=bearings_x,
            ax=ax,
            **kwargs,
        )

    @property
    def frequencies(self) -> np.ndarray:
        """Damped natural frequencies Im(s)/2π [Hz]."""
        return rad_s_to_hz(self.eigenvalues.imag)

    @property
    def undamped_frequencies(self) -> np.ndarray:
        """|s|/2π [Hz]."""
        return rad_s_to_hz(np.abs(self.eigenvalues))

    @property
    def damping_ratios(self) -> np.ndarray:
        """ζ = −Re(s)/|s| [-] (negative: unstable)."""
        return -self.eigenvalues.real / np.abs(self.eigenvalues)

    @property
    def log_decrements(self) -> np.ndarray:
        """Logarithmic decrement δ = 2πζ/√(1 − ζ²) [-]."""
        return _log_decrement(self.damping_ratios)

    @property
    def divergent(self) -> np.ndarray:
        """True for a divergent root: a real eigenvalue s > 0 (no oscillation, ζ = −1), e.g. a
        magnetic bearing whose negative stiffness beats its control stiffness."""
        return (self.eigenvalues.imag == 0) & (self.eigenvalues.real > 0)

    @property
    def shaft_fractions(self) -> np.ndarray:
        """Share of each mode's kinetic energy carried by the shaft."""
        return self.shares.shaft


def _solve(red: ReducedModel, speed: float, n_modes: int, damped: bool):
    """The ``n_modes`` lowest modes on ``red``: (the model solved, s, modal coordinates,
    estimated relative errors, NaN for a divergent root)."""
    if damped:
        s, Z = damped_modes(red, speed, n_modes)
    else:
        red = red.undamped()
        lam, Z, Z_div, div = spectrum(red, speed)
        s, Z = np.concatenate([lam, div.astype(complex)]), np.hstack([Z, Z_div.astype(complex)])
        order = lowest_modes(s, n_modes)
        s, Z = s[order], Z[:, order]
    oscillatory = s.imag > 0
    errors = np.full(s.size, np.nan)
    errors[oscillatory] = eigenvalue_errors(red, float(speed), s[oscillatory], Z[:, oscillatory])
    return red, s, Z, errors


def _normalise(dofs: DofMap, phi: np.ndarray) -> np.ndarray:
    trans = [dofs.shaft(np.arange(dofs.n_shaft_nodes), f) for f in ("u", "v", "w")]
    if dofs.n_boom_nodes:
        trans += [dofs.boom(np.arange(dofs.n_boom_nodes), f) for f in ("v", "w")]
    idx = np.concatenate(trans)
    k = np.argmax(np.abs(phi[idx]), axis=0)
    ref = phi[idx[k], np.arange(phi.shape[1])]
    ref = np.where(np.abs(ref) > 0, ref, 1.0)
    return phi / ref


@single_blas_thread
def modes(
    model: Model,
    speed: float = 0.0,
    n_modes: int = 10,
    damped: bool = True,
    basis_size: int | None = None,
    tolerance: float = EIGENVALUE_TOLERANCE,
) -> Modes:
    """Natural frequencies, damping and mode shapes at spin speed ``speed`` [rad/s].

    Parameters
    ----------
    model : Model
        Assembled model.
    speed : float
        Ω [rad/s], finite, >= 0 and at most :data:`~flexshaft.analyses.guards.MAX_SPEED`.
    n_modes : int
        Number of modes returned (>= 1), in increasing damped frequency
        (:func:`~flexshaft.analyses.eigen.lowest_modes`).
    damped : bool
        Include the bearing dampers, the actuator laws' damping and controller dynamics, and
        the hysteretic loss of every member (gyroscopic terms are always in).
    basis_size : int or None
        A plain modal basis of this size (the number of free DOFs gives the exact solution of
        the full problem); default: the enriched basis chosen for ``tolerance``, as the
        Campbell diagram's (:func:`~flexshaft.analyses.eigen_error.tracked_to_accuracy`).
    tolerance : float
        Relative eigenvalue accuracy against the full eigenproblem the default basis is chosen
        for; the estimate reached is :attr:`Modes.error_estimate`.
    """
    check_model(model)
    speed = check_spin_speed(speed)
    n_modes = check_count(n_modes, "n_modes")
    if basis_size is not None:
        basis_size = check_count(basis_size, "basis_size")
    tolerance = check_tolerance(tolerance)
    n_free = int(model.dofs.free.size)
    if basis_size is not None:
        red, s, Z, errors = _solve(reduce(model, basis_size), speed, n_modes, damped)
    else:
        size, enrich = accurate_basis(n_modes)
        largest = max(4 * default_basis_size(n_modes), 2 * size)
        while True:
            whole = size >= n_free
            red, s, Z, errors = _solve(
                accurate_reduction(model, min(size, n_free), 0 if whole else enrich), speed, n_modes, damped
            )
            worst = float(np.nanmax(errors, initial=0.0))
            if whole or not worst > tolerance or 2 * size > largest or red.size >= largest:
                break
            size, enrich = 2 * size, 2 * enrich
    full = model.dofs.expand(red.shapes(Z))
    nodes = np.arange(model.dofs.n_shaft_nodes)
    v, w = (full[model.dofs.shaft(nodes, f)] for f in ("v", "w"))
    shapes = _normalise(model.dofs, circular_pairs(s, full, v, w))  # a degenerate pair by whirl
    require_finite("eigenvalues", s)
    require_finite("mode shapes", shapes)
    labels = label_modes(model, shapes)
    return Modes(
        float(speed),
        s,
        shapes,
        labels.kind,
        labels.whirl,
        labels.whirl_ratio,
        labels.component,
        labels.shares,
        model.dofs,
        model.internal_damping,
        errors,
    )
