"""How sure a Monte-Carlo probability is: exceedance counts and their exact binomial bounds.

N samples with k exceedances estimate P(exceed) as k/N. With k = 0 that estimate is 0 and its
standard error √(p(1−p)/N) is 0 too ("0 ± 0"), which says nothing about how small P really is.
The honest number is an upper confidence bound: the exact (Clopper–Pearson) one-sided bound
p_u, the largest P under which k or fewer exceedances in N samples still have probability
1 − confidence,

    Σ_{i=0..k} C(N, i) p_uⁱ (1 − p_u)^(N−i) = 1 − confidence,

i.e. p_u = B⁻¹(confidence; k + 1, N − k), the quantile of the beta distribution (Clopper &
Pearson 1934). For k = 0 it is the closed form p_u = 1 − (1 − confidence)^(1/N): with
N = 200 and 95 %, P < 0.0149 (the "rule of three", 3/N, approximates it for large N).

References
----------
Clopper, C. J., Pearson, E. S. (1934). The use of confidence or fiducial limits illustrated in
the case of the binomial. Biometrika 26(4), 404-413.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.stats import beta

__all__ = ["CONFIDENCE", "Exceedance", "clopper_pearson_upper"]

#: Confidence of the reported upper bounds.
CONFIDENCE = 0.95


def clopper_pearson_upper(events: int, samples: int, confidence: float = CONFIDENCE) -> float:
    """Exact one-sided upper confidence bound [-] of a binomial probability from ``events``
    successes in ``samples`` trials (module docstring); 1 when every trial is an event."""
    if isinstance(events, bool) or isinstance(samples, bool) or int(events) != events or int(samples) != samples:
        raise ValueError(f"events and samples must be whole numbers, got {events!r}, {samples!r}")
    events, samples = int(events), int(samples)
    if samples < 1 or not 0 <= events <= samples:
        raise ValueError(f"need 0 <= events <= samples and samples >= 1, got {events} of {samples}")
    if not (math.isfinite(confidence) and 0.0 < confidence < 1.0):
        raise ValueError(f"confidence must lie strictly between 0 and 1, got {confidence!r}")
    if events == samples:
        return 1.0
    if events == 0:  # the closed form (exact as well; the beta quantile agrees to round-off)
        return 1.0 - (1.0 - confidence) ** (1.0 / samples)
    return float(beta.ppf(confidence, events + 1, samples - events))


@dataclass(frozen=True)
class Exceedance:
    """``events`` samples of ``samples`` exceeded a limit."""

    events: int
    samples: int

    @property
    def probability(self) -> float:
        """The estimate k/N [-] (NaN without samples)."""
        return self.events / self.samples if self.samples else float("nan")

    @property
    def standard_error(self) -> float:
        """√(p(1−p)/N) [-]: 0 when no sample (or every one) exceeds; see :attr:`upper_bound`."""
        p = self.probability
        return math.sqrt(max(p * (1.0 - p), 0.0) / self.samples) if self.samples else float("nan")

    def upper_bound(self, confidence: float = CONFIDENCE) -> float:
        """Exact one-sided upper confidence bound [-] (:func:`clopper_pearson_upper`); NaN
        without samples."""
        return clopper_pearson_upper(self.events, self.samples, confidence) if self.samples else float("nan")

    def describe(self, confidence: float = CONFIDENCE) -> str:
        """``"0 of 200 samples: P < 0.0149 (95 % upper bound)"`` or ``"3 of 200 samples: P =
        0.015, < 0.0383 (95 % upper bound)"``."""
        if not self.samples:
            return "no samples"
        bound = f"{self.upper_bound(confidence):.3g} ({100 * confidence:g} % upper bound)"
        if self.events == 0:
            return f"0 of {self.samples} samples: P < {bound}"
        return f"{self.events} of {self.samples} samples: P = {self.probability:.3g}, < {bound}"

    def to_dict(self, confidence: float = CONFIDENCE) -> dict:
        """Plain values for JSON: events, samples, probability, standard error, upper bound."""
        return {
            "events": self.events,
            "samples": self.samples,
            "probability": self.probability,
            "standard_error": self.standard_error,
            "upper_bound": self.upper_bound(confidence),
            "confidence": confidence,
        }
