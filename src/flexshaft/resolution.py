"""How finely a design is judged: every grid size and range of the recipe, in one place.

:func:`flexshaft.verdict.assess.assess` analyses a design at a :class:`Resolution`; the size
estimate of ``flexshaft check`` (:func:`flexshaft.assembly.size.problem_size`) counts the same
grids, so the two cannot disagree. No other module writes these numbers down.

Presets (:data:`RESOLUTIONS`, by name):

* :data:`SCREENING`: the optimizer's coarse evaluation: 261 spin speeds (0.5 % of the operating
  speed apart; the critical-speed peaks are still refined between them) and 21 whirl speeds
  (the onset is still solved between them), one point of the bearing loops' frequency grid per
  lightly damped closed-loop pole instead of three (the margins are still refined between
  the grid points; on the embedded designs they agree with three's to 2e-8); only what the
  checks read;
* :data:`VERDICT`: the report's grids, only what the checks read (the verdict of
  ``flexshaft run``, at two thirds of its CPU time: benchmarks/optimizer.py);
* :data:`REPORT`: ``flexshaft run``: 651 spin speeds (0.2 % apart), 41 whirl speeds, a Campbell
  diagram of 60 speeds and everything the report shows besides the checks (modes at rest,
  the leave-one-out load shares of the strength, the classical-shell buckling comparison, the
  thermal design sweeps);
* :data:`FINE`: twice the report's density, to check that its numbers have converged.

Speed ranges are fractions of the operating speed Ω_op (1 rad/s when it is zero): the spin-up
scan runs from a slow start to 30 % over Ω_op, or over the highest speed of the design's
``[operating] speed_range`` (the largest separation margin API 684 requires above the maximum
continuous speed is 26 %), and it is also the range searched for lateral critical speeds; the whirl
stability runs from rest to 1.5 Ω_op, beyond the onset margins a requirement asks for.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["FINE", "REPORT", "RESOLUTIONS", "SLOW_START", "Resolution", "SCREENING", "VERDICT"]

#: Where every spin-up scan starts [fraction of the operating speed]: slow enough that the
#: response there is quasi-static (the assessment, the thesis studies, Monte-Carlo).
SLOW_START = 0.02


@dataclass(frozen=True)
class Resolution:
    """Grid sizes and ranges of one assessment (see the module docstring).

    Attributes
    ----------
    name : str
    spinup_speeds : int
        Spin speeds of the imbalance response, ``scan_bottom`` to ``scan_top`` × Ω_op.
    whirl_speeds : int
        Speeds of the whirl-stability analysis, rest to ``whirl_top`` × Ω_op.
    campbell_speeds : int
        Speeds of the Campbell diagram, rest to ``scan_top`` × Ω_op; 0: no Campbell diagram.
    report_detail : bool
        Also compute what only the report shows (modes at rest, the strength's leave-one-out
        load shares, the classical-shell buckling, the thermal design sweeps and both loss
        models); no check reads them, so the verdict does not depend on it.
    modes : int
        Modes at rest and at the operating speed, and modes tracked by the whirl stability.
    campbell_modes : int
        Modes tracked by the Campbell diagram.
    scan_bottom, scan_top : float
        Spin-up scan range [fraction of Ω_op]; ``scan_top`` is also the highest speed searched
        for lateral critical speeds.
    whirl_top : float
        Top of the whirl-stability speeds [fraction of Ω_op].
    loop_peak_samples : int
        Frequency points of the magnetic-bearing loops' grid at each lightly damped closed-loop
        pole: 3 (its top and half width) or 1 (its top; the refinement brackets the peak
        between the neighbouring points instead):
        :func:`~flexshaft.analyses.bearing_loops.bearing_loops`'s ``peak_samples``.
    """

    name: str
    spinup_speeds: int
    whirl_speeds: int
    campbell_speeds: int
    report_detail: bool
    modes: int = 10
    campbell_modes: int = 12
    scan_bottom: float = SLOW_START
    scan_top: float = 1.30
    whirl_top: float = 1.5
    loop_peak_samples: int = 3

    def __post_init__(self) -> None:
        counts = {
            "spinup_speeds": self.spinup_speeds,
            "whirl_speeds": self.whirl_speeds,
            "modes": self.modes,
            "campbell_modes": self.campbell_modes,
        }
        for name, value in counts.items():
            if int(value) != value or value < 2:
                raise ValueError(f"{name} must be an integer >= 2 (got {value!r})")
        if self.loop_peak_samples not in (1, 3):
            raise ValueError(f"loop_peak_samples must be 1 or 3 (got {self.loop_peak_samples!r})")
        if int(self.campbell_speeds) != self.campbell_speeds or self.campbell_speeds == 1 or self.campbell_speeds < 0:
            raise ValueError(f"campbell_speeds must be 0 (no Campbell diagram) or >= 2 (got {self.campbell_speeds!r})")
        if not 0.0 < self.scan_bottom < 1.0 < self.scan_top or not self.whirl_top > 1.0:
            raise ValueError(
                f"ranges must satisfy 0 < scan_bottom < 1 < scan_top and whirl_top > 1 (got scan_bottom "
                f"{self.scan_bottom!r}, scan_top {self.scan_top!r}, whirl_top {self.whirl_top!r})"
            )

    def spin_speeds(self, operating_speed: float, highest: float = 1.0) -> np.ndarray:
        """The spin-up scan [rad/s] of a design turning at ``operating_speed`` [rad/s] whose
        highest operating speed is ``highest`` × it (``[operating] speed_range``): to
        ``scan_top`` × the highest speed (API measures a critical above the range from it)."""
        top = self.scan_top * max(float(highest), 1.0)
        return np.linspace(self.scan_bottom, top, self.spinup_speeds) * _reference(operating_speed)

    def stability_speeds(self, operating_speed: float) -> np.ndarray:
        """Speeds of the whirl-stability analyses [rad/s] (the onset is solved between them)."""
        return np.linspace(0.0, self.whirl_top * _reference(operating_speed), self.whirl_speeds)

    def campbell_grid(self, operating_speed: float) -> np.ndarray:
        """Speeds of the Campbell diagram [rad/s] (empty without one)."""
        return np.linspace(0.0, self.scan_top * _reference(operating_speed), self.campbell_speeds)


def _reference(operating_speed: float) -> float:
    """The speed the ranges scale [rad/s]: Ω_op, or 1 rad/s for a design at rest."""
    return max(float(operating_speed), 1.0)


SCREENING = Resolution(
    "screening", spinup_speeds=261, whirl_speeds=21, campbell_speeds=0, report_detail=False, loop_peak_samples=1
)
VERDICT = Resolution("verdict", spinup_speeds=651, whirl_speeds=41, campbell_speeds=0, report_detail=False)
REPORT = Resolution("report", spinup_speeds=651, whirl_speeds=41, campbell_speeds=60, report_detail=True)
FINE = Resolution("fine", spinup_speeds=1301, whirl_speeds=81, campbell_speeds=120, report_detail=True)

#: The presets by name.
RESOLUTIONS = {r.name: r for r in (SCREENING, VERDICT, REPORT, FINE)}
