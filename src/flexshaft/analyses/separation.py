"""Amplification factor and separation margin of critical speeds (API 684 / API 617 rule).

Pure analysis of a response curve A(N) (amplitude against speed, any consistent units; speeds
[rad/s] in flexshaft). For each resonance peak at N_c with amplitude A_c, the half-power points
N_1 < N_c < N_2 are where the curve falls to A_c/√2, and the amplification factor is

    AF = N_c / (N_2 − N_1)                                   (half-power bandwidth method)

For a single-degree-of-freedom resonance AF ≈ Q = 1/(2ζ). The separation margin required of a
critical speed from the operating speed N_op depends on AF (API 617 7th ed. §2.6.2.10,
8th ed. §6.8.2.5; API 684 2nd ed. §2.8.2):

* AF < 2.5: the resonance is considered critically damped and needs no margin;
* critical below the operating speed: SM = min(16, 17 (1 − 1/(AF − 1.5))) [%];
* critical above the operating speed: SM = min(26, 10 + 17 (1 − 1/(AF − 1.5))) [%].

The actual margin is taken in percent of the operating speed, ``|N_c − N_op| / N_op``: API
states it against the minimum operating speed for criticals below the operating range and
against the maximum continuous speed for those above it; a driveline with one operating speed
has both equal to N_op.

Where the curve does not fall to A_c/√2 on a side before it rises again into a neighbouring
peak (or the data end), that half-power point is not defined. With one side found, the peak is
taken as symmetric (``AF = N_c / (2 |N_c − N_found|)``, exact to first order in ζ for one
mode); with neither, the flanking minima (or data ends) bound the bandwidth from below and
``AF = N_c / (N_right − N_left)`` is an upper bound, on the safe side for the required margin.

References
----------
API Standard 617, Axial and Centrifugal Compressors and Expander-compressors, 7th ed. (2002)
Ch. 1 §2.6.2.10, 8th ed. (2014) §6.8.2.5. API Recommended Practice 684, Tutorial on
Rotordynamics, 2nd ed. (2005). The same formulas are implemented in ROSS
(petrobras/ross, ``ross/api_report.py``, "API684 - SP6.8.2.1 / SP6.8.2.10").
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

__all__ = [
    "CRITICALLY_DAMPED_AF",
    "Position",
    "ResonancePeak",
    "Separation",
    "amplification_factor",
    "api684_separation",
    "required_separation_margin",
    "resolve_peak",
    "response_peaks",
    "separation_margin",
]

#: Below this amplification factor a resonance needs no separation margin (API 617/684).
CRITICALLY_DAMPED_AF = 2.5
_HALF_POWER = 1.0 / np.sqrt(2.0)

#: A critical speed below or above the operating speed.
Position = Literal["below", "above"]
#: How the half-power bandwidth was found (see the module docstring).
BandwidthMethod = Literal["two-sided", "one-sided", "bounded"]


# ------------------------------------------------------------------------------------------------
# API 684 / 617 rules


def amplification_factor(critical_speed: float, lower: float, upper: float) -> float:
    """AF = N_c / (N_2 − N_1) from the peak speed and the half-power speeds [any speed unit]."""
    if not (np.isfinite(critical_speed) and np.isfinite(lower) and np.isfinite(upper)) or not upper > lower:
        raise ValueError(f"half-power speeds must satisfy lower < upper (got lower = {lower!r}, upper = {upper!r})")
    return float(critical_speed / (upper - lower))


def required_separation_margin(amplification: float, position: Position) -> float:
    """Separation margin [fraction of the operating speed] API 617/684 require for an AF.

    Parameters
    ----------
    amplification : float
        Amplification factor AF [-], ≥ 0 (inf for an undamped resonance).
    position : {"below", "above"}
        The critical speed lies below or above the operating speed.

    Returns
    -------
    float
        0 for AF < 2.5; else ``min(16, 17(1 − 1/(AF − 1.5)))/100`` below and
        ``min(26, 10 + 17(1 − 1/(AF − 1.5)))/100`` above.
    """
    if not amplification >= 0.0:  # NaN fails too; inf (an undamped peak) takes the caps
        raise ValueError(f"amplification factor must be a number >= 0 (got {amplification!r})")
    if position not in ("below", "above"):
        raise ValueError(f"position must be 'below' or 'above' (got {position!r})")
    if amplification < CRITICALLY_DAMPED_AF:
        return 0.0
    base = 17.0 * (1.0 - 1.0 / (amplification - 1.5))
    percent = min(16.0, base) if position == "below" else min(26.0, 10.0 + base)
    return percent / 100.0


def separation_margin(critical_speed: float, operating_speed: float) -> float:
    """Actual separation margin |N_c − N_op| / N_op [fraction], from the speed N_op it is measured from
    (the operating speed, or an end of the operating speed range: :func:`api684_separation`)."""
    if not (np.isfinite(operating_speed) and operating_speed > 0.0):
        raise ValueError(f"operating speed must be a finite number > 0 (got {operating_speed!r})")
    return float(abs(critical_speed - operating_speed) / operating_speed)


@dataclass(frozen=True)
class Separation:
    """API 684 separation check of one critical speed.

    Attributes
    ----------
    critical_speed, operating_speed : float
        N_c and N_op [rad/s].
    amplification_factor : float
        AF [-].
    position : {"below", "above"}
        The critical speed lies below or above the operating speed.
    margin : float
        Actual margin [-]: |N_c − N_ref| / N_ref from the reference speed N_ref, 0 inside the
        operating speed range.
    required_margin : float
        Margin required for this AF [-].
    reference_speed : float or None
        N_ref [rad/s]: the lowest operating speed for a critical below, the highest for one
        above (both N_op without a speed range); None: N_op.
    """

    critical_speed: float
    operating_speed: float
    amplification_factor: float
    position: Position
    margin: float
    required_margin: float
    reference_speed: float | None = None

    @property
    def passed(self) -> bool:
        """The actual margin meets the required one."""
        return self.margin >= self.required_margin


def api684_separation(
    critical_speed: float, amplification: float, operating_speed: float, speed_range: tuple[float, float] | None = None
) -> Separation:
    """Actual and required separation margin of one critical speed [rad/s] with its AF [-].

    ``speed_range`` (lowest, highest) [rad/s] is the operating speed range (default: the
    operating speed alone). API measures the margin of a critical below the range from its
    lowest speed (the minimum operating speed) and of one above from its highest (the maximum
    continuous speed); a critical inside the range has no separation (margin 0: it passes only
    when its AF needs none).
    """
    low, high = (operating_speed, operating_speed) if speed_range is None else (float(v) for v in speed_range)
    if not (np.isfinite(low) and np.isfinite(high) and 0.0 < low <= operating_speed <= high):
        raise ValueError(
            f"speed_range must hold the operating speed {operating_speed!r}: 0 < lowest <= it <= highest "
            f"(got {speed_range!r})"
        )
    position: Position = "below" if critical_speed < operating_speed else "above"
    reference = low if position == "below" else high
    inside = low <= critical_speed <= high  # with one operating speed: only a critical at it
    return Separation(
        float(critical_speed),
        float(operating_speed),
        float(amplification),
        position,
        0.0 if inside else separation_margin(critical_speed, reference),
        required_separation_margin(amplification, position),
        float(reference),
    )


# ------------------------------------------------------------------------------------------------
# Peaks and half-power points of a sampled response curve


@dataclass(frozen=True)
class ResonancePeak:
    """A peak of a response curve with its half-power points.

    Attributes
    ----------
    speed : float
        N_c, speed of the peak [rad/s] (vertex of a parabola through 1/A² at the three samples
        around the sampled maximum).
    amplitude : float
        A_c, peak amplitude [unit of A].
    lower, upper : float or None
        Half-power speeds N_1, N_2 [rad/s]; None where the curve does not fall to A_c/√2 on
        that side before a minimum or the end of the data.
    lower_limit, upper_limit : float
        The half-power speed where found, else the flanking minimum or data end [rad/s].
    resolved : bool
        The sample intervals containing N_c and the half-power points found (both limits of a
        bounded peak) are at most bandwidth/n (n = the ``samples_per_band`` of
        :func:`response_peaks` or :func:`resolve_peak`).
    """

    speed: float
    amplitude: float
    lower: float | None
    upper: float | None
    lower_limit: float
    upper_limit: float
    resolved: bool = True

    @property
    def method(self) -> BandwidthMethod:
        """ "two-sided", "one-sided" (symmetric peak assumed) or "bounded" (upper bound of AF)."""
        found = (self.lower is not None) + (self.upper is not None)
        return ("bounded", "one-sided", "two-sided")[found]

    @property
    def bandwidth(self) -> float:
        """Half-power bandwidth N_2 − N_1 [rad/s] by :attr:`method`."""
        if self.lower is not None and self.upper is not None:
            return self.upper - self.lower
        if self.lower is not None:
            return 2.0 * (self.speed - self.lower)
        if self.upper is not None:
            return 2.0 * (self.upper - self.speed)
        return self.upper_limit - self.lower_limit

    @property
    def amplification_factor(self) -> float:
        """AF = N_c / bandwidth [-] (inf for a zero bandwidth)."""
        width = self.bandwidth
        return float(self.speed / width) if width > 0.0 else float("inf")


def _check_curve(speeds, amplitude) -> tuple[np.ndarray, np.ndarray]:
    s = np.asarray(speeds, dtype=float)
    a = np.asarray(amplitude, dtype=float)
    if s.ndim != 1 or a.shape != s.shape:
        raise ValueError(f"speeds and amplitude must be 1-D of equal length (got shapes {s.shape} and {a.shape})")
    if s.size < 3:
        raise ValueError(f"a response curve needs at least 3 samples (got {s.size})")
    if not (np.all(np.isfinite(s)) and np.all(np.isfinite(a))):
        raise ValueError("speeds and amplitude must be finite (got NaN or inf)")
    if np.any(a < 0.0):
        raise ValueError(f"amplitude must be >= 0 (got {a.min()!r})")
    if np.any(np.diff(s) <= 0.0):
        raise ValueError("speeds must be strictly increasing")
    return s, a


def _vertex(s: np.ndarray, a: np.ndarray, i: int) -> tuple[float, float]:
    """Peak speed and amplitude from a parabola through 1/A² at samples i−1, i, i+1.

    The sample itself is kept when the parabola would put the half-power level above a
    neighbour sample: the peak is then narrower than the sampling, and extrapolating it would
    invent an amplitude the samples do not show.
    """
    x = s[i - 1 : i + 2]
    if np.any(a[i - 1 : i + 2] <= 0.0):
        return float(s[i]), float(a[i])
    y = 1.0 / a[i - 1 : i + 2] ** 2
    c2, c1, c0 = _parabola(x - x[1], y)
    if not c2 > 0.0:
        return float(s[i]), float(a[i])
    dx = float(np.clip(-c1 / (2.0 * c2), x[0] - x[1], x[2] - x[1]))
    y_min = c0 + dx * (c1 + c2 * dx)
    if not 0.0 < y_min <= y[1] or 1.0 / np.sqrt(y_min) * _HALF_POWER > min(a[i - 1], a[i + 1]):
        return float(s[i]), float(a[i])
    return float(x[1] + dx), float(1.0 / np.sqrt(y_min))


def _parabola(x: np.ndarray, y: np.ndarray) -> tuple[float, float, float]:
    """Coefficients (c2, c1, c0) of the parabola ``c2 x² + c1 x + c0`` through three points
    with ``x[1] = 0`` (Newton's divided differences: the interpolant ``np.polyfit(x, y, 2)``
    finds by least squares, without its overhead)."""
    left = (y[1] - y[0]) / (x[1] - x[0])
    right = (y[2] - y[1]) / (x[2] - x[1])
    c2 = (right - left) / (x[2] - x[0])
    return float(c2), float(right - c2 * x[2]), float(y[1])


def _crossing(s0: float, a0: float, s1: float, a1: float, level: float) -> float:
    """Speed between samples (s0, a0 > level) and (s1, a1 <= level) where A = level."""
    if a1 > 0.0:  # interpolate 1/A², a smooth low-order function of speed near a resonance
        y0, y1, yl = a0**-2, a1**-2, level**-2
    else:
        y0, y1, yl = -a0, -a1, -level
    return float(s0 + (yl - y0) / (y1 - y0) * (s1 - s0))


def _half_power_side(s: np.ndarray, a: np.ndarray, i: int, level: float, step: int) -> tuple[float | None, float]:
    """Walk from the peak i in direction ``step`` to the half-power crossing.

    Returns (crossing or None, limit): the limit is the crossing, or the sample of the
    flanking minimum (the curve rises again above the level) or of the data end.
    """
    j = i
    while True:
        k = j + step
        if k < 0 or k >= s.size:
            return None, float(s[j])
        if a[k] <= level:
            crossing = _crossing(s[j], a[j], s[k], a[k], level)
            return crossing, crossing
        if a[k] > a[j]:  # rising again: a minimum above the half-power level at j
            return None, float(s[j])
        j = k


def _peak_at(s: np.ndarray, a: np.ndarray, i: int, samples_per_band: int) -> ResonancePeak:
    speed, amplitude = _vertex(s, a, i)
    level = amplitude * _HALF_POWER
    lower, lower_limit = _half_power_side(s, a, i, level, -1)
    upper, upper_limit = _half_power_side(s, a, i, level, +1)
    peak = ResonancePeak(speed, amplitude, lower, upper, lower_limit, upper_limit)
    return replace(peak, resolved=_coarsest_interval(s, peak) <= peak.bandwidth / samples_per_band * (1 + 1e-9))


def _coarsest_interval(s: np.ndarray, peak: ResonancePeak) -> float:
    """Largest sample interval among those that contain the speeds the AF is made of: N_c and
    the half-power points found, or both limits of a bounded peak (its band). A one-sided
    peak's other limit (a flanking minimum, or the data's end) is not one of them: counting it
    held such a peak unresolved whenever that limit lay outside the refinement's window
    (N_c ± the bandwidth), through every round of :func:`resolve_peak`."""
    if peak.method == "bounded":
        points = np.array([peak.lower_limit, peak.speed, peak.upper_limit])
    else:
        points = np.array([p for p in (peak.lower, peak.speed, peak.upper) if p is not None])
    j = np.clip(np.searchsorted(s, points, side="right") - 1, 0, s.size - 2)
    return float(np.max(s[j + 1] - s[j]))


def _peak_indices(a: np.ndarray) -> np.ndarray:
    """Interior local maxima: a[i−1] < a[i] >= a[i+1]."""
    inner = (a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:])
    return np.flatnonzero(inner) + 1


def response_peaks(speeds, amplitude, samples_per_band: int = 4) -> tuple[ResonancePeak, ...]:
    """Every interior peak of a sampled response curve with its half-power points.

    Parameters
    ----------
    speeds : array_like
        Strictly increasing speeds [rad/s].
    amplitude : array_like
        Response amplitude at each speed, ≥ 0 [any unit].
    samples_per_band : int
        A peak is flagged ``resolved`` when the sample intervals containing N_1, N_c and N_2
        are at most bandwidth/samples_per_band.

    Returns
    -------
    tuple of ResonancePeak
        In order of speed. A maximum at either end of the data is not a peak (the response
        may still rise beyond it). Half-power speeds are interpolated linearly in 1/A².
    """
    s, a = _check_curve(speeds, amplitude)
    return tuple(_peak_at(s, a, int(i), samples_per_band) for i in _peak_indices(a))


def resolve_peak(
    response: Callable[[np.ndarray], np.ndarray],
    speeds,
    amplitude,
    near: float,
    samples_per_band: int = 20,
    max_rounds: int = 12,
) -> ResonancePeak | None:
    """Refine the sampling of one peak until its half-power bandwidth is resolved.

    Parameters
    ----------
    response : callable
        ``response(speeds) -> amplitudes`` evaluates the curve at new speeds [rad/s].
    speeds, amplitude : array_like
        Initial samples of the curve (strictly increasing speeds [rad/s]).
    near : float
        Speed of the peak to follow [rad/s]; the peak nearest to it is refined.
    samples_per_band : int
        Required sample intervals across the bandwidth (20 gives AF within about 0.5 % of the
        exact value for a single-mode peak).
    max_rounds : int
        Refinement rounds before giving up (the peak is then returned with ``resolved=False``;
        its AF is a lower bound when the bandwidth was still shrinking).

    Returns
    -------
    ResonancePeak or None
        None when the refined curve has no peak near ``near`` (it was a sampling artefact).
    """
    s, a = _check_curve(speeds, amplitude)
    if samples_per_band < 4 or max_rounds < 1:
        raise ValueError(f"samples_per_band must be >= 4 and max_rounds >= 1 (got {samples_per_band}, {max_rounds})")
    peak = None
    for _ in range(max_rounds):
        indices = _peak_indices(a)
        if indices.size == 0:
            return None
        i = int(indices[np.argmin(np.abs(s[indices] - near))])
        peak = _peak_at(s, a, i, samples_per_band)
        if peak.resolved:
            return peak
        near = peak.speed
        width = peak.bandwidth if peak.bandwidth > 0.0 else s[i + 1] - s[i - 1]
        new = np.linspace(peak.speed - width, peak.speed + width, 2 * samples_per_band + 1)
        new = new[(new > 0.0) & ~np.isin(new, s)]
        values = np.asarray(response(new), dtype=float)
        if values.shape != new.shape or not np.all(np.isfinite(values)):
            raise ValueError("response(speeds) must return one finite amplitude per speed")
        s, order = np.unique(np.concatenate([s, new]), return_index=True)
        a = np.concatenate([a, values])[order]
    assert peak is not None
    return peak
