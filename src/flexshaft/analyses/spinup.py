"""Fast spin-up response over many actuator gains (thesis §3, study 6; docs/studies.md).

The spin-up study solves the synchronous imbalance response

    Z(Ω) q = Ω² Q₁,   Z(Ω) = Z₀(Ω) + Σ_a B_aᵀ [G_a(iΩ) B_s − k_s B_a]          (eq. 2.40)

at hundreds of speeds Ω for each of hundreds of gain pairs (K_p, K_d), where
``G_a = k_i A(s) C_a(s)`` is each magnetic bearing's feedback (controller C_a, current gain
k_i, amplifier lag A) from its sensing rows B_s to its actuation rows B_a and k_s its
negative stiffness (:class:`~flexshaft.assembly.model.Actuator`; the thesis's PD bearing is
``G = K_p + s K_d``, ``k_s = 0``, ``B_s = B_a``). Only the actuator term changes with the
gains, and it has rank 2 per actuator. So the structure **without** the actuators, Z₀(Ω), is
solved once per speed (banded LU, :class:`~flexshaft.analyses.banded.BandedHarmonicSolver`)
for the imbalance load and for the unit actuator forces B_aᵀ; every gain pair then costs a
2n_a × 2n_a solve per speed (Sherman-Morrison-Woodbury / receptance coupling). With
``W = Z₀⁻¹B_aᵀ``, ``q₀`` the response without actuators and the carried forces
``e = G d_s − k_s d_a``:

    e = (I + G S_s − k_s S)⁻¹ (G g_s − k_s g),    q = q₀ − W e,

``S = B_a W``, ``S_s = B_s W`` (receptances at the magnets and the sensors), ``g = B_a q₀``,
``g_s = B_s q₀``. Collocated bearings (every thesis case) take the original fast path with
``D = diag(G − k_s)``:

    d = (I + S D)⁻¹ g,    q = q₀ − W D d.

This is exact, not a truncated basis: it agrees with the direct solve to round-off (the
tests compare at sampled gains). Z₀ is regular because the hanger bearings hold the shaft and
the composite and boom carry hysteretic loss; a singular Z₀ is reported, not bypassed.

Cost on the baseline (336 free DOFs, 2 actuators): 400 banded solves once (~0.1 s), then the
4 × 4 systems and the orbit envelopes for all gains in batched numpy, one BLAS thread.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.guards import (
    RefusedInputError,
    check_count,
    check_finite_array,
    check_model,
    check_speed,
    check_spin_speed,
    require_finite,
)
from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.analyses.receptance import ActuatorReceptance, actuator_receptance
from flexshaft.analyses.response import orbit_amplitude
from flexshaft.analyses.results import ResultMixin, new_arrays, new_dataset
from flexshaft.assembly.model import Controller, Model
from flexshaft.parallel.threads import single_blas_thread
from flexshaft.plot.driveline import actuator_figure, imbalance_response_figure
from flexshaft.plot.studies import gain_map_figure
from flexshaft.resolution import SLOW_START
from flexshaft.units import rad_s_to_rpm

__all__ = [
    "ActuatorReceptance",
    "SpinupCurves",
    "SpinupMap",
    "actuator_receptance",
    "clustered_receptance",
    "spinup_curves",
    "spinup_map",
    "spinup_speeds",
]


def spinup_speeds(model: Model, n_speeds: int = 400, start: float = SLOW_START, stop: float = 1.0) -> np.ndarray:
    """``n_speeds`` spin speeds from ``start`` to ``stop`` times the operating speed [rad/s].

    Raises
    ------
    ValueError
        For a model at rest (``operating.speed_rpm = 0``): a spin-up to it is empty (this used to
        give a grid up to 1 rad/s); pass the speeds of the analysis explicitly.
    """
    check_model(model)
    n_speeds = check_count(n_speeds, "n_speeds")
    start, stop = check_speed(start, "start", "(fraction)"), check_speed(stop, "stop", "(fraction)")
    if start > stop:
        raise ValueError(f"start must not exceed stop (got start = {start!r}, stop = {stop!r})")
    if not model.speed > 0:
        raise RefusedInputError(
            "the design's operating speed is 0 (operating.speed_rpm = 0): a spin-up to it has no speeds; "
            "give the design an operating speed > 0, or the speeds [rad/s] of the analysis"
        )
    check_spin_speed(stop * model.speed, "stop × the operating speed")
    return np.linspace(start, stop, n_speeds) * model.speed


def _per_speed_product(A: np.ndarray, X: np.ndarray) -> np.ndarray:
    """``A[None] @ X`` for A (n_speeds, n, k) and X (n_gains, n_speeds, k, nc), as one matrix
    product per speed over all gains and cases (n_speeds BLAS calls instead of
    n_gains × n_speeds small ones); (n_gains, n_speeds, n, nc)."""
    ng, ns, k, nc = X.shape
    product = A @ X.transpose(1, 2, 0, 3).reshape(ns, k, ng * nc)  # (ns, n, ng nc)
    return product.reshape(ns, A.shape[1], ng, nc).transpose(2, 0, 1, 3)


def _coupled(rec: ActuatorReceptance, feedback: np.ndarray):
    """Responses for the actuators' feedback values ``G = k_i A C`` (n_gains, n_speeds, n_act) [N/m].

    Returns shaft orbits (n_gains, n_speeds, n_nodes, n_cases) [m], actuator relative orbits
    at the magnets (n_gains, n_speeds, n_act, n_cases) [m] and the carried force orbits
    (n_gains, n_speeds, n_act, n_cases) [N], or None for the force when every bearing is
    collocated (then it is |G − k_s| times the relative orbit).
    """
    ks = rec.negative_stiffness
    if rec.collocated:
        gains = feedback - ks if ks is not None and np.any(ks) else feedback
        D = np.repeat(gains, 2, axis=-1)  # (ng, ns, 2 n_act): the same law on v and w
        nb = D.shape[-1]
        system = np.eye(nb) + rec.receptance[None] * D[:, :, None, :]  # I + S D
        d = np.linalg.solve(
            system, np.broadcast_to(rec.actuator_free[None], system.shape[:2] + rec.actuator_free.shape[1:])
        )
        shaft = rec.shaft_free[None] - _per_speed_product(rec.shaft_per_force, D[..., None] * d)  # (ng, ns, n_out, nc)
        n_nodes = shaft.shape[2] // 2
        shaft_orbit = orbit_amplitude(shaft[:, :, :n_nodes], shaft[:, :, n_nodes:])
        act_orbit = orbit_amplitude(d[:, :, 0::2], d[:, :, 1::2])
        return shaft_orbit, act_orbit, None
    assert rec.sensor_receptance is not None and rec.sensor_free is not None  # set when not collocated
    G = np.repeat(feedback, 2, axis=-1)[..., None]  # (ng, ns, 2 n_act, 1)
    K = np.repeat(ks, 2)[:, None] if ks is not None else 0.0  # (2 n_act, 1); None: no k_s, as above
    system = np.eye(G.shape[-2]) + G * rec.sensor_receptance[None] - K * rec.receptance[None]
    forcing = G * rec.sensor_free[None] - K * rec.actuator_free[None]
    e = np.linalg.solve(system, forcing)  # carried forces (ng, ns, 2 n_act, nc)
    shaft = rec.shaft_free[None] - _per_speed_product(rec.shaft_per_force, e)
    d = rec.actuator_free[None] - rec.receptance[None] @ e
    n_nodes = shaft.shape[2] // 2
    return (
        orbit_amplitude(shaft[:, :, :n_nodes], shaft[:, :, n_nodes:]),
        orbit_amplitude(d[:, :, 0::2], d[:, :, 1::2]),
        orbit_amplitude(e[:, :, 0::2], e[:, :, 1::2]),
    )


def _dynamic_gains(controllers, speeds: np.ndarray) -> np.ndarray:
    """C_a(iΩ) per speed and actuator, (n_speeds, n_act)."""
    s = 1j * np.asarray(speeds)
    return np.stack([np.asarray(c(s), dtype=complex) * np.ones_like(s) for c in controllers], axis=-1)


@dataclass(frozen=True)
class SpinupCurves(ResultMixin):
    """Spin-up response of one controller setting.

    Attributes
    ----------
    speeds : ndarray
        Ω [rad/s], (n_speeds,).
    shaft_orbit : ndarray
        Orbit major semi-axis at every shaft node, worst load case, (n_nodes, n_speeds) [m].
    shaft_x : ndarray
        Node stations [m].
    actuator_displacement : ndarray
        Relative orbit at each actuator, worst load case, (n_act, n_speeds) [m].
    actuator_force : ndarray
        Carried force orbit ``G d_s − k_s d_a`` at each actuator, worst load case,
        (n_act, n_speeds) [N] (``|C(iΩ)|`` × relative orbit for the thesis's PD bearing).
    actuator_names : tuple of str
    """

    speeds: np.ndarray
    shaft_orbit: np.ndarray
    shaft_x: np.ndarray
    actuator_displacement: np.ndarray
    actuator_force: np.ndarray
    actuator_names: tuple[str, ...]

    plots = {"response": "plot_response", "actuators": "plot_actuators"}

    def plot_response(self, ax=None, **kwargs):
        """Largest shaft orbit and the actuator orbits against speed [rpm] (log amplitude);
        keywords (``operating_rpm``, ``gap`` [m]) go to
        :func:`flexshaft.plot.driveline.imbalance_response_figure`."""

        curves = {"max over the shaft": self.shaft_peak}
        curves.update({f"at {name} (relative)": d for name, d in zip(self.actuator_names, self.actuator_displacement)})
        kwargs.setdefault("log_y", True)
        kwargs.setdefault("title", "Spin-up response (orbit major semi-axis)")
        return imbalance_response_figure(rad_s_to_rpm(self.speeds), curves, ax=ax, **kwargs)

    def plot_actuators(self, ax=None, **kwargs):
        """Actuator relative orbit [mm] and force [N] against speed [rpm] (two panels)."""

        if not self.actuator_names:
            raise ValueError("this driveline has no actuators")
        return actuator_figure(
            rad_s_to_rpm(self.speeds),
            dict(zip(self.actuator_names, self.actuator_displacement)),
            dict(zip(self.actuator_names, self.actuator_force)),
            ax=ax,
            **kwargs,
        )

    @property
    def shaft_peak(self) -> np.ndarray:
        """Largest shaft orbit over the nodes at each speed [m]."""
        return self.shaft_orbit.max(axis=0)

    def __repr__(self) -> str:
        k = int(np.argmax(self.shaft_peak))
        return (
            f"SpinupCurves({self.speeds.size} speeds to {rad_s_to_rpm(self.speeds[-1]):.0f} rpm, peak shaft orbit "
            f"{self.shaft_peak[k] * 1e3:.3g} mm at {rad_s_to_rpm(self.speeds[k]):.0f} rpm)"
        )

    def to_dataset(self):
        """Shaft orbit envelope and actuator orbit/force over speed (xarray)."""
        return new_dataset(
            {
                "shaft_orbit": (
                    ("x_shaft", "speed"),
                    self.shaft_orbit,
                    {"units": "m", "long_name": "shaft orbit major semi-axis, worst load case"},
                ),
                "actuator_displacement": (
                    ("actuator", "speed"),
                    self.actuator_displacement,
                    {"units": "m", "long_name": "relative orbit at the actuator"},
                ),
                "actuator_force": (
                    ("actuator", "speed"),
                    self.actuator_force,
                    {"units": "N", "long_name": "actuator force amplitude"},
                ),
            },
            {
                "speed": ("speed", self.speeds, {"units": "rad/s", "long_name": "spin speed"}),
                "x_shaft": ("x_shaft", self.shaft_x, {"units": "m", "long_name": "shaft node station"}),
                "actuator": ("actuator", list(self.actuator_names), {"long_name": "active bearing"}),
            },
            "spin-up response",
        )


@single_blas_thread
def spinup_curves(rec: ActuatorReceptance, controllers) -> SpinupCurves:
    """Spin-up curves for actuator laws ``controllers`` (one per actuator, or one for all).

    ``controllers`` are :class:`~flexshaft.assembly.model.Controller` objects (anything with
    ``num``/``den``, e.g. a python-control ``TransferFunction``) or ``(kp, kd)`` pairs: the
    controller C(s) of each bearing [N/m, N s/m for the thesis's bearing; A/m, A s/m for a
    magnet], evaluated at s = iΩ; each bearing's k_i, amplifier lag, k_s and sensor position
    are those of the model.
    """
    if isinstance(controllers, (Controller, tuple)) and not (
        isinstance(controllers, tuple) and controllers and isinstance(controllers[0], (Controller, tuple))
    ):
        controllers = [controllers] * rec.n_actuators
    if not isinstance(rec, ActuatorReceptance):
        raise ValueError(
            f"rec must be an ActuatorReceptance (actuator_receptance(model, speeds)), got {type(rec).__name__}"
        )
    for c in controllers:
        if isinstance(c, tuple):
            check_finite_array("controller gains (kp, kd)", c, "N/m, N s/m")
    laws = [
        c
        if isinstance(c, Controller)
        else Controller.from_transfer_function(c)
        if hasattr(c, "num")
        else Controller.pd(*c)
        for c in controllers
    ]
    for law in laws:
        check_finite_array("controller coefficients", law.numerator + law.denominator)
    if len(laws) != rec.n_actuators:
        raise ValueError(f"expected {rec.n_actuators} controllers (one per actuator), got {len(laws)}")
    gains = rec.feedback(_dynamic_gains(laws, rec.speeds)[None])
    shaft, act, force = _coupled(rec, gains)
    if force is None:
        ks = rec.negative_stiffness
        law = gains[0] - ks if ks is not None and np.any(ks) else gains[0]
        act = act[0].max(axis=-1).T  # worst case, (act, speeds)
        force = np.abs(law.T) * act
    else:
        force = force[0].max(axis=-1).T  # worst load case, (act, speeds)
        act = act[0].max(axis=-1).T
    require_finite("spin-up shaft orbit", shaft)
    require_finite("spin-up actuator force", force)
    return SpinupCurves(
        speeds=rec.speeds,
        shaft_orbit=shaft[0].max(axis=-1).T,
        shaft_x=rec.shaft_x,
        actuator_displacement=act,
        actuator_force=force,
        actuator_names=rec.actuator_names,
    )


def clustered_receptance(model: Model, controllers, speeds, n_peaks: int = 3, n_fine: int = 33) -> ActuatorReceptance:
    """:func:`actuator_receptance` on ``speeds`` plus ``n_fine`` speeds between the neighbours
    of each of the ``n_peaks`` largest resonance peaks of the spin-up curve under
    ``controllers`` (each speed solved once).

    A lightly damped resonance falls between evenly spaced samples, so their largest value is
    below the true peak (by 11 % on the tuned design's 1 mm wall with 201 speeds); the clusters
    resolve it (within 0.5 % with 100 speeds, 3 peaks and 17 fine speeds each,
    tests/test_spinup.py).
    """
    n_peaks, n_fine = check_count(n_peaks, "n_peaks"), check_count(n_fine, "n_fine")
    rec = actuator_receptance(model, speeds)
    curve = spinup_curves(rec, controllers).shaft_peak
    inner = np.flatnonzero((curve[1:-1] >= curve[:-2]) & (curve[1:-1] >= curve[2:])) + 1
    peaks = inner[np.argsort(curve[inner])[::-1][:n_peaks]]
    grid = rec.speeds
    extra = [np.linspace(grid[k - 1], grid[k + 1], n_fine) for k in peaks]
    new = np.setdiff1d(np.concatenate([grid, *extra]), grid)
    return rec.merged(actuator_receptance(model, new)) if new.size else rec


@dataclass(frozen=True)
class SpinupMap(ResultMixin):
    """Peaks of the spin-up response over a (K_p, K_d) grid, the same law on every actuator.

    Every peak is the largest value over the speeds (and the load cases) of the grid point.

    Attributes
    ----------
    kp, kd : ndarray
        Gains [N/m], [N s/m].
    speeds : ndarray
        Spin-up speeds [rad/s].
    shaft_peak : ndarray
        Largest shaft orbit over nodes and speeds, (n_kp, n_kd) [m].
    shaft_peak_speed : ndarray
        Speed at which it occurs, (n_kp, n_kd) [rad/s].
    actuator_displacement_peak : ndarray
        Largest relative orbit at each actuator, (n_kp, n_kd, n_act) [m].
    actuator_force_peak : ndarray
        Largest actuator force amplitude, (n_kp, n_kd, n_act) [N].
    """

    kp: np.ndarray
    kd: np.ndarray
    speeds: np.ndarray
    shaft_peak: np.ndarray
    shaft_peak_speed: np.ndarray
    actuator_displacement_peak: np.ndarray
    actuator_force_peak: np.ndarray
    actuator_names: tuple[str, ...]

    plots = {
        "shaft_peak": "plot_shaft_peak",
        "actuator_displacement": "plot_actuator_displacement",
        "actuator_force": "plot_actuator_force",
    }

    def _plot_map(self, values, label: str, scale: float, title: str, ax, kwargs):

        if "best" not in kwargs:
            kp, kd, _ = self.best()
            kwargs["best"] = (kp, kd)
        kwargs.setdefault("title", title)
        return gain_map_figure(self.kp, self.kd, values, label, scale=scale, ax=ax, **kwargs)

    def plot_shaft_peak(self, ax=None, **kwargs):
        """Peak spin-up shaft orbit [mm] over (K_p, K_d), the smallest marked ★ (keywords to
        :func:`flexshaft.plot.studies.gain_map_figure`, e.g. ``other={"design": (kp, kd)}``)."""
        return self._plot_map(
            self.shaft_peak,
            "max spin-up shaft orbit [mm]",
            1e3,
            "Maximum spin-up shaft deflection vs control gains",
            ax,
            kwargs,
        )

    def plot_actuator_displacement(self, ax=None, **kwargs):
        """Peak relative orbit at the actuators [mm] (largest over them) over (K_p, K_d)."""
        return self._plot_map(
            self.actuator_displacement_peak.max(axis=-1),
            "max actuator displacement [mm]",
            1e3,
            "Maximum shaft displacement at the actuators vs control gains",
            ax,
            kwargs,
        )

    def plot_actuator_force(self, ax=None, **kwargs):
        """Peak actuator force [N] (largest over the actuators) over (K_p, K_d)."""
        return self._plot_map(
            self.actuator_force_peak.max(axis=-1),
            "max actuator force [N]",
            1.0,
            "Maximum actuator force vs control gains",
            ax,
            kwargs,
        )

    def best(self, max_actuator_displacement: float | None = None, max_actuator_force: float | None = None):
        """Gains ``(kp, kd, shaft_peak)`` of the smallest peak deflection within the limits."""
        ok = np.ones(self.shaft_peak.shape, bool)
        if max_actuator_displacement is not None:
            ok &= self.actuator_displacement_peak.max(axis=-1) <= max_actuator_displacement
        if max_actuator_force is not None:
            ok &= self.actuator_force_peak.max(axis=-1) <= max_actuator_force
        if not ok.any():
            raise ValueError("no gain pair satisfies the actuator limits")
        i, j = np.unravel_index(np.argmin(np.where(ok, self.shaft_peak, np.inf)), ok.shape)
        return float(self.kp[i]), float(self.kd[j]), float(self.shaft_peak[i, j])

    def to_dataset(self):
        """The map as an :class:`xarray.Dataset` with CF-style attributes."""
        return self.to_arrays().to_dataset()

    def to_arrays(self) -> LabelledArrays:
        """The content of :meth:`to_dataset` as plain labelled arrays (no xarray import)."""
        dims = ("kp", "kd")
        return new_arrays(
            {
                "shaft_peak": (dims, self.shaft_peak, {"units": "m", "long_name": "peak shaft orbit over speed"}),
                "shaft_peak_speed": (
                    dims,
                    self.shaft_peak_speed,
                    {"units": "rad/s", "long_name": "speed of the peak shaft orbit"},
                ),
                "actuator_displacement_peak": (
                    dims + ("actuator",),
                    self.actuator_displacement_peak,
                    {"units": "m", "long_name": "peak relative orbit at the actuator"},
                ),
                "actuator_force_peak": (
                    dims + ("actuator",),
                    self.actuator_force_peak,
                    {"units": "N", "long_name": "peak actuator force amplitude"},
                ),
            },
            {
                "kp": ("kp", self.kp, {"units": "N/m", "long_name": "proportional gain"}),
                "kd": ("kd", self.kd, {"units": "N s/m", "long_name": "derivative gain"}),
                "actuator": ("actuator", list(self.actuator_names), {"long_name": "active bearing"}),
            },
            "spin-up map over the actuator gains",
            speed_min=float(self.speeds[0]),
            speed_max=float(self.speeds[-1]),
            speed_units="rad/s",
            n_speeds=int(self.speeds.size),
        )


@single_blas_thread
def spinup_map(
    model: Model,
    kp,
    kd,
    speeds=None,
    loads_per_speed_squared=None,
    *,
    receptance: ActuatorReceptance | None = None,
    block: int = 32,
    progress=None,
) -> SpinupMap:
    """Peak spin-up response over a grid of PD gains applied to every actuator.

    Parameters
    ----------
    model : Model
        The driveline (its own actuator gains are ignored).
    kp, kd : array_like
        Proportional [N/m] and derivative [N s/m] gains.
    speeds : array_like, optional
        Spin speeds [rad/s]; default :func:`spinup_speeds` (400 up to the operating speed).
    loads_per_speed_squared : ndarray, optional
        Imbalance Q₁ [N s²]; default from the design.
    receptance : ActuatorReceptance, optional
        Reuse a precomputed :func:`actuator_receptance` (then ``speeds`` and loads are its own).
    block : int
        Gain pairs evaluated together (memory ~ block × n_speeds × n_nodes × 16 bytes × 4).
    progress : callable, optional
        Called with (done, total) gain pairs.
    """
    check_model(model)
    kp = check_finite_array("kp", np.atleast_1d(np.asarray(kp, dtype=float)), "N/m")
    kd = check_finite_array("kd", np.atleast_1d(np.asarray(kd, dtype=float)), "N s/m")
    if kp.ndim != 1 or kd.ndim != 1:
        raise ValueError("kp and kd must be 1-D sequences of gains")
    block = check_count(block, "block")
    if receptance is None:
        speeds = spinup_speeds(model) if speeds is None else speeds
        receptance = actuator_receptance(model, speeds, loads_per_speed_squared)
    rec = receptance
    s = 1j * rec.speeds
    pairs = np.stack(np.meshgrid(kp, kd, indexing="ij"), axis=-1).reshape(-1, 2)
    n_pairs = pairs.shape[0]
    shaft_peak = np.empty(n_pairs)
    peak_speed = np.empty(n_pairs)
    act_disp = np.empty((n_pairs, rec.n_actuators))
    act_force = np.empty((n_pairs, rec.n_actuators))
    for start in range(0, n_pairs, block):
        chunk = pairs[start : start + block]
        law = chunk[:, 0:1] + s[None, :] * chunk[:, 1:2]  # (ng, ns)
        gains = rec.feedback(np.repeat(law[..., None], rec.n_actuators, axis=-1))
        shaft, act, force = _coupled(rec, gains)
        per_speed = shaft.max(axis=(2, 3))  # (ng, ns)
        k = np.argmax(per_speed, axis=1)
        sl = slice(start, start + chunk.shape[0])
        shaft_peak[sl] = per_speed[np.arange(k.size), k]
        peak_speed[sl] = rec.speeds[k]
        act_worst = act.max(axis=3)  # (ng, ns, n_act)
        act_disp[sl] = act_worst.max(axis=1)
        if force is None and rec.plant is not None and np.all(rec.plant == 1.0) and not np.any(rec.negative_stiffness):
            act_force[sl] = (np.abs(law)[..., None] * act_worst).max(axis=1)
        elif force is None:
            ks = rec.negative_stiffness
            act_force[sl] = (np.abs(gains - ks) * act_worst).max(axis=1)
        else:
            act_force[sl] = force.max(axis=(1, 3))
        if progress is not None:
            progress(min(start + block, n_pairs), n_pairs)
    shape = (kp.size, kd.size)
    require_finite("spin-up map shaft peak", shaft_peak)
    require_finite("spin-up map actuator force", act_force)
    return SpinupMap(
        kp=kp,
        kd=kd,
        speeds=rec.speeds,
        shaft_peak=shaft_peak.reshape(shape),
        shaft_peak_speed=peak_speed.reshape(shape),
        actuator_displacement_peak=act_disp.reshape(shape + (-1,)),
        actuator_force_peak=act_force.reshape(shape + (-1,)),
        actuator_names=rec.actuator_names,
    )
