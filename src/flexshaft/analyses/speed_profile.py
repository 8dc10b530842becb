"""The speed of a run-up or run-down over time, Ω(t) [rad/s], and its rate Ω̇ [rad/s²]: a table
of speeds at times (piecewise linear), a constant acceleration (with a dwell), or a function.
:func:`flexshaft.analyses.transient.transient_response` integrates the response along it.
"""

from __future__ import annotations

import bisect
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

import numpy as np

__all__ = ["SpeedProfile"]


@dataclass(frozen=True)
class SpeedProfile:
    """Spin speed Ω(t) ≥ 0 [rad/s] over ``0 ≤ t ≤ duration`` [s].

    Either piecewise linear through ``(times, speeds)`` (constant acceleration on each
    segment; the integrator lands on every breakpoint), or a callable ``speed(t)`` with its
    derivative ``acceleration(t)`` [rad/s²] (central differences when not given).
    Build one with :meth:`constant_acceleration`, :meth:`table` or :meth:`from_callable`.
    """

    duration: float
    times: np.ndarray | None = None
    speeds: np.ndarray | None = None
    speed_function: Callable[[float], float] | None = None
    acceleration_function: Callable[[float], float] | None = None

    @classmethod
    def table(cls, times, speeds) -> SpeedProfile:
        """Piecewise-linear Ω through ``speeds`` [rad/s] at ``times`` [s] (from t = 0)."""
        t = np.asarray(times, dtype=float).ravel()
        s = np.asarray(speeds, dtype=float).ravel()
        if t.size < 2 or t.size != s.size:
            raise ValueError(
                f"speed table: need >= 2 (time, speed) pairs of equal length, got {t.size} times and {s.size} speeds"
            )
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(s))):
            raise ValueError("speed table: times and speeds must be finite")
        if t[0] != 0.0 or np.any(np.diff(t) <= 0):
            raise ValueError(f"speed table: times must start at 0 s and increase strictly, got {t.tolist()}")
        if np.any(s < 0):
            raise ValueError(f"speed table: speeds must be >= 0 rad/s (one spin direction), got min {s.min()!r}")
        return cls(duration=float(t[-1]), times=t, speeds=s)

    @classmethod
    def constant_acceleration(cls, start: float, stop: float, acceleration: float, dwell: float = 0.0) -> SpeedProfile:
        """From ``start`` to ``stop`` [rad/s] at ``|acceleration|`` [rad/s²] (run-down when
        stop < start), then ``dwell`` [s] at ``stop``."""
        if not (np.isfinite(acceleration) and acceleration != 0):
            raise ValueError(f"acceleration must be finite and nonzero rad/s², got {acceleration!r}")
        if not (np.isfinite(dwell) and dwell >= 0):
            raise ValueError(f"dwell must be >= 0 s, got {dwell!r}")
        ramp = abs(stop - start) / abs(acceleration)
        if ramp <= 0:
            raise ValueError(f"start and stop speeds are equal ({start!r} rad/s): nothing to ramp")
        times, speeds = [0.0, ramp], [start, stop]
        if ramp + dwell > ramp:  # a dwell below the ramp's round-off (1e-300 s) adds no time
            times.append(ramp + dwell)
            speeds.append(stop)
        return cls.table(times, speeds)

    @classmethod
    def from_callable(
        cls, speed: Callable[[float], float], duration: float, acceleration: Callable[[float], float] | None = None
    ) -> SpeedProfile:
        """Any smooth Ω(t) [rad/s] on [0, duration] [s], optionally with dΩ/dt [rad/s²]."""
        if not (np.isfinite(duration) and duration > 0):
            raise ValueError(f"duration must be > 0 s, got {duration!r}")
        probe = np.array([float(speed(t)) for t in np.linspace(0.0, duration, 257)])
        if not np.all(np.isfinite(probe)) or np.any(probe < 0):
            raise ValueError("speed(t) must be finite and >= 0 rad/s on [0, duration]")
        return cls(duration=float(duration), speed_function=speed, acceleration_function=acceleration)

    @property
    def breakpoints(self) -> np.ndarray:
        """Times [s] the integrator must land on (segment ends of a table)."""
        return self.times if self.times is not None else np.array([0.0, self.duration])

    @property
    def max_speed(self) -> float:
        """Largest speed [rad/s] (sampled for a callable)."""
        if self.speeds is not None:
            return float(self.speeds.max())
        return float(max(self.speed(t) for t in np.linspace(0.0, self.duration, 1025)))

    def _segment(self, t: float) -> int:
        return min(max(bisect.bisect_right(self._knots, t) - 1, 0), len(self._knots) - 2)

    @cached_property
    def _knots(self) -> list[float]:
        assert self.times is not None  # a table's
        return self.times.tolist()

    @cached_property
    def _slopes(self) -> list[float]:
        assert self.times is not None and self.speeds is not None  # a table's
        return (np.diff(self.speeds) / np.diff(self.times)).tolist()

    def speed(self, t: float) -> float:
        """Ω(t) [rad/s]."""
        if self.speeds is not None:
            if t >= self.duration:  # the table's last speed exactly (as speeds_at's interpolation)
                return float(self.speeds[-1])
            k = self._segment(t)
            return float(self.speeds[k] + self._slopes[k] * (max(t, 0.0) - self._knots[k]))
        assert self.speed_function is not None  # not a table: from_callable
        return float(self.speed_function(t))

    def speeds_at(self, times) -> np.ndarray:
        """Ω at many times [rad/s] (vectorised for a table)."""
        t = np.asarray(times, dtype=float)
        if self.speeds is not None:
            return np.interp(t, self._knots, self.speeds)
        return np.array([self.speed(x) for x in t.ravel()]).reshape(t.shape)

    def accelerations_at(self, times) -> np.ndarray:
        """dΩ/dt at many times [rad/s²] (vectorised for a table: the segment of each time as
        :meth:`acceleration` takes it, right-continuous at a breakpoint)."""
        t = np.asarray(times, dtype=float)
        if self.speeds is not None:
            knots = np.asarray(self._knots)
            segment = np.clip(np.searchsorted(knots, t, side="right") - 1, 0, knots.size - 2)
            return np.asarray(self._slopes)[segment]
        return np.array([self.acceleration(x) for x in t.ravel()]).reshape(t.shape)

    def acceleration(self, t: float) -> float:
        """dΩ/dt [rad/s²] (of the segment containing t; right-continuous at a breakpoint)."""
        if self.speeds is not None:
            return self._slopes[self._segment(t)]
        if self.acceleration_function is not None:
            return float(self.acceleration_function(t))
        h = 1e-6 * self.duration
        a, b = max(t - h, 0.0), min(t + h, self.duration)
        return (self.speed(b) - self.speed(a)) / (b - a)
