"""The design studies' section (report/studies_section.py): the numbers handed to the wall and
spin-up gain-map figures, and the Table 3.3 row of an optimum off the fixed table angles.

References (derived here, by hand, on hand-built stand-in studies of
tests/test_studies_section_reference.py):

* 1 m = 1000 mm: the gain maps' shaft orbit and actuator displacement are labelled in mm, so
  the value drawn, ``scale · values`` (plot/gain_maps.py: "multiplied by ``scale`` for display"),
  is 1000 × the dataset's metres; the actuator force is in N (scale 1).
* The tuned gains are the map's smallest peak deflection (docs/studies.md: "The tuned gains are
  the map's smallest peak deflection (within `actuator_gap` if given) after refining ..."): the
  star marks the tuned pair (3e6 N/m, 2000 N s/m) and the ring labelled "design" the design's
  (1e6 N/m, 500 N s/m).
* The wall study's ``safety_factor`` is the safety factor with imbalance and
  ``safety_factor_no_imbalance`` without (the label of docs/studies.md's headline row
  "3. wall thickness, with imbalance", whose R is the ``safety_factor`` column); imbalance
  adds load, so the no-imbalance curve lies above. The figure takes them in the order
  (with_imbalance, without_imbalance) of plot/studies.wall_thickness_figure.
* The one-angle optimum is the angle of the largest safety factor (docs/studies.md, "Why the
  one-angle optimum is near 45°"; the safety factor is the strength reserve R, larger is safer):
  computed here from the stand-in's column with numpy, and Table 3.3 must carry its row (derived
  here: the table's stated purpose, thesis Table 3.3's critical loading of each angle, includes
  the optimum's; docs/studies.md does not say so).

Figures are only recorded as jobs (never drawn). CPU about 0.5 s, nearly all of it xarray's first
use in the process.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from test_studies_section_reference import _studies

from flexshaft.report.studies_section import studies_section_and_jobs

# the table's configured angles (a setting, not a result: the thesis text lost its numbers)
from flexshaft.thesis.design_studies import TABLE_ANGLES

DESIGN_GAINS = (1e6, 500.0)
TUNED_GAINS = (3e6, 2000.0)


def _job(jobs, stem):
    (job,) = [j for j in jobs if j.stem == stem]
    return job


def _spinup_map():
    kp, kd = [1e6, 3e6], [500.0, 2000.0, 4000.0]
    return xr.Dataset(
        {
            "shaft_peak": (("kp", "kd"), [[0.038, 0.02, 0.01], [0.009, 0.004, 0.006]]),
            "actuator_displacement_peak": (("kp", "kd"), [[5e-4, 4e-4, 3e-4], [2e-4, 1e-4, 1.5e-4]]),
            "actuator_force_peak": (("kp", "kd"), [[300.0, 250.0, 200.0], [120.0, 90.0, 95.0]]),
        },
        coords={"kp": kp, "kd": kd},
    )


def test_gain_maps_drawn_in_mm_and_newtons_with_the_tuned_star():
    """Shaft orbit 0.038 m drawn as 38 mm, actuator displacement 5e-4 m as 0.5 mm, force 300 N as
    300 N; every map marks the tuned gains with the star and the design's gains as "design"."""
    ds = _spinup_map()
    _, jobs = studies_section_and_jobs(_studies(spinup_map=ds), "out")
    # Products of exact decimal inputs by 1000: rel 1e-12 allows the last-bit rounding of the scaling.
    for stem, var, to_display in (
        ("study_map_deflection", "shaft_peak", 1e3),
        ("study_map_actuator_displacement", "actuator_displacement_peak", 1e3),
        ("study_map_actuator_force", "actuator_force_peak", 1.0),
    ):
        job = _job(jobs, stem)
        kp, kd, values, label = job.args
        drawn = np.asarray(values) * job.kwargs.get("scale", 1.0)
        assert drawn == pytest.approx(ds[var].values * to_display, rel=1e-12), stem
        assert ("[mm]" in label) == (to_display == 1e3), (stem, label)
        assert tuple(job.kwargs["best"]) == TUNED_GAINS, stem
        assert tuple(job.kwargs["other"]["design"]) == DESIGN_GAINS, stem


def test_wall_figure_with_imbalance_first():
    """Walls 2, 3, 4 mm: R with imbalance 1.2, 2.1, 1.8 and without 2.0, 3.0, 2.6 (above, as
    imbalance only adds load); the figure's with-imbalance argument is the lower curve."""
    with_imb, without = [1.2, 2.1, 1.8], [2.0, 3.0, 2.6]
    wall = xr.Dataset(
        {
            "safety_factor": ("wall_thickness", with_imb),
            "safety_factor_no_imbalance": ("wall_thickness", without),
            "natural_frequency_1": ("wall_thickness", [40.0, 45.0, 48.0]),
            "spinup_peak_deflection": ("wall_thickness", [0.005, 0.002, 0.007]),
        },
        coords={"wall_thickness": [0.002, 0.003, 0.004]},
    )
    _, jobs = studies_section_and_jobs(_studies(wall=wall), "out")
    walls, first, second, freq, peak = _job(jobs, "study_wall").args
    assert list(first) == with_imb and list(second) == without


def test_ply_table_has_a_row_for_an_optimum_off_the_table_angles():
    """Safety factors over 15..75° with the largest, 3.3, at 40° (not one of the table angles):
    the optimum's row (40°, R 3.3) is in Table 3.3 beside the six table angles."""
    alpha = [15.0, 30.0, 40.0, 45.0, 55.0, 60.0, 75.0]
    sf = [1.1, 1.4, 3.3, 2.9, 1.7, 1.6, 1.3]
    n = len(alpha)
    ply = xr.Dataset(
        {
            "safety_factor": ("alpha", sf),
            "dominant_stress": ("alpha", [1] * n),
            "critical_ply_angle": ("alpha", [-a for a in alpha]),
            "critical_x": ("alpha", [0.1 * (k + 1) for k in range(n)]),
            "sigma1": ("alpha", [1e6 * (k + 1) for k in range(n)]),
            "sigma2": ("alpha", [2e5 * (k + 1) for k in range(n)]),
            "tau12": ("alpha", [3e5 * (k + 1) for k in range(n)]),
        },
        coords={"alpha": alpha},
    )
    i = int(np.argmax(sf))  # no tie: 3.3 is the only largest value
    best, best_sf = alpha[i], sf[i]
    assert best not in TABLE_ANGLES
    section, _ = studies_section_and_jobs(
        _studies(ply_angle=ply, optimal_angle=best, optimal_angle_safety_factor=best_sf), "out"
    )
    (table,) = [t for t in section.tables if t.caption.startswith("Most critical loading")]
    assert [row[0] for row in table.rows] == sorted([*TABLE_ANGLES, best])
    (row,) = [row for row in table.rows if row[0] == best]
    # α = 40° is the third sample: σ1 3 MPa, σ2 0.6 MPa, τ12 0.9 MPa at x = 0.3 m (exact decimals).
    assert row[1:7] == pytest.approx([best_sf, -best, 0.3, 3.0, 0.6, 0.9], rel=1e-12)
