"""The design studies' section (report/studies_section.py) beside
tests/test_studies_section_reference.py: the quietest wall's headline row, and the numbers handed
to the forced-response, gain and stability-map figures.

References (derived, by hand) on that file's stand-in studies: 1 m = 1000 mm; rpm = 60·Ω/(2π),
so Ω = 2π·N/60 rad/s is N rpm; the design's gains are (K_p, K_d) = (1e6 N/m, 500 N s/m). The
figures are only recorded as jobs (never drawn). CPU about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from test_studies_section_reference import _rad_s, _studies

from flexshaft.report.studies_section import studies_section_and_jobs


def _job(jobs, stem):
    (job,) = [j for j in jobs if j.stem == stem]
    return job


def test_quietest_wall_row_in_mm():
    """Spin-up peaks 5, 2, 7 mm at walls 2, 3, 4 mm: the quietest is 3 mm with a 2 mm orbit."""
    walls = [0.002, 0.003, 0.004]
    wall = xr.Dataset(
        {
            "spinup_peak_deflection": ("wall_thickness", [0.005, 0.002, 0.007]),
            "safety_factor": ("wall_thickness", [np.nan] * 3),  # no figure: only the row is read
        },
        coords={"wall_thickness": walls},
    )
    section, _ = studies_section_and_jobs(_studies(wall=wall), "out")
    rows = {r[0]: r[1] for r in section.tables[0].rows}
    assert rows["3. wall thickness (smallest spin-up peak under the design's gains)"] == "3 mm (2 mm orbit)"


def test_figures_get_speeds_in_rpm_and_the_designs_kp():
    """Forced response sampled at Ω = 2π·2000/60 and 2π·4000/60 rad/s: 2000 and 4000 rpm, the
    walls 2.5 mm and 3.5 mm in the legend; the stability map's onsets 5000 and 7000 rpm; the gain
    study marks the design's K_p, 1e6 N/m."""
    speeds = np.array([_rad_s(2000.0), _rad_s(4000.0)])
    forced = xr.Dataset(
        {"shaft_peak": (("wall_thickness", "speed"), [[1e-3, 2e-3], [3e-3, 4e-3]])},
        coords={"wall_thickness": [0.0025, 0.0035], "speed": speeds},
    )
    stability = xr.Dataset(
        {
            "damping_ratio": (("kp", "kd"), [[0.01, 0.02]]),
            "onset_speed": (("kp", "kd"), [[_rad_s(5000.0), _rad_s(7000.0)]]),
        },
        coords={"kp": [1e6], "kd": [500.0, 1000.0]},
    )
    gain = xr.Dataset(
        {"safety_factor": ("kp", [2.0, 3.0]), "actuator_displacement": ("kp", [1e-4, 2e-4])}, coords={"kp": [5e5, 2e6]}
    )
    _, jobs = studies_section_and_jobs(
        _studies(forced_response=forced, stability_map=stability, gain=gain, tuned=None), "out"
    )
    rpm, curves, op_rpm = _job(jobs, "study_forced_response").args
    assert rpm == pytest.approx([2000.0, 4000.0], rel=1e-12) and op_rpm == pytest.approx(6000.0, rel=1e-12)
    assert list(curves) == ["wall 2.5 mm", "wall 3.5 mm"] and list(curves["wall 3.5 mm"]) == [3e-3, 4e-3]
    kp, kd, zeta, onset, best = _job(jobs, "study_stability_margin").args
    assert np.ravel(onset) == pytest.approx([5000.0, 7000.0], rel=1e-12) and best == (3e6, 2000.0)
    *_, design_kp = _job(jobs, "study_gain").args
    assert design_kp == 1e6
