"""The design studies' grids at each resolution as docs/studies.md states them, and the
headline's spin-up peaks before and after tuning (:mod:`flexshaft.thesis.design_studies`).

References:

* docs/studies.md, "Time" table, read here from the file: ``report``: "α every 2.5°; 8 × 8
  two-angle (0, 15, 30, 45, 55, 60, 75, 90); 9 walls 1–6 mm; 13 K_p"; ``full``: "α every 1°;
  from 0° to 90°, both ends included; 19 × 19 two-angle, 0° to 90° every 5°; 23 walls; 31 K_p"
  (the full grid's contract: the whole quadrant; a ±α pair at 180° − α is the mirror laminate
  of the pair at α, its coupling terms of opposite sign and its torque senses swapped, which
  the studies' outputs do not tell apart). The K_p grids span 1e5 to 1e8 N/m (study 4's default,
  :func:`~flexshaft.thesis.gain.proportional_gain_study`) even in log10: 13 gains are 4 per
  decade, K_p,i = 10^(5 + i/4); the report's two-angle grid holds the thesis's optimum
  (module constant ``THESIS["best_two_angle_deg"]``, 55° and 0°);
* the headline reports each spin-up peak as the study found it (:class:`DesignStudies`:
  ``peak_before`` the design's gains, ``peak_after`` the tuned ones): hand-set 38 mm and 4 mm
  (the thesis's numbers, module constant ``THESIS``) come back as 0.038 and 0.004 m.

Tolerances: grid values to 1e-12 relative (one power or product each); the headline exactly.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import xarray as xr

from flexshaft.thesis.design_studies import STUDY_GRIDS, THESIS, DesignStudies, headline

DOCS = Path(__file__).resolve().parents[1] / "docs" / "studies.md"


def _row(resolution: str) -> str:
    for line in DOCS.read_text(encoding="utf-8").splitlines():
        if line.startswith(f"| `{resolution}` |"):
            return line
    raise AssertionError(f"no {resolution} row in {DOCS}")


def _find(pattern: str, row: str) -> str:
    m = re.search(pattern, row)
    assert m, f"docs/studies.md row changed: no match for {pattern!r} in {row!r}"
    return m.group(1)


def test_report_grids_are_those_the_docs_state():
    row = _row("report")
    grid = STUDY_GRIDS["report"]
    step = float(_find(r"α every ([\d.]+)°", row))
    angles = grid["angles"]
    np.testing.assert_allclose(np.diff(angles), step, rtol=1e-12)
    # the grid's ends are the code's convention (the docs give only the step): from one step
    # to the last below 90 deg, 2.5 ... 87.5
    assert angles[0] == step and angles[-1] < 90.0 <= angles[-1] + step
    listed = [float(a) for a in _find(r"two-angle \(([\d, ]+)\)", row).split(",")]
    assert len(listed) == 8 and grid["two_angles"].tolist() == listed
    # the thesis's two-angle optimum (module constant THESIS, "best_two_angle_deg") is a grid point
    assert set(THESIS["best_two_angle_deg"]) <= set(grid["two_angles"].tolist())
    n_kp = int(_find(r"(\d+) K_p", row))
    np.testing.assert_allclose(grid["kp"], 10.0 ** (5 + 3 * np.arange(n_kp) / (n_kp - 1)), rtol=1e-12)
    assert n_kp == 13  # 4 per decade: the decades 1e5, 1e6, 1e7, 1e8 are grid points
    n_walls = int(_find(r"(\d+) walls 1–6 mm", row))
    walls = grid["walls"]
    assert walls.size == n_walls and walls.min() == 1e-3 and walls.max() == 6e-3


def test_full_grids_are_those_the_docs_state():
    row = _row("full")
    grid = STUDY_GRIDS["full"]
    step = float(_find(r"α every ([\d.]+)°", row))
    np.testing.assert_allclose(np.diff(grid["angles"]), step, rtol=1e-12)
    # the whole quadrant, both ends, as the row states (h41b-studies-full-angles-without-90)
    stated = re.search(r"α every [\d.]+° from (\d+)° to (\d+)°, both ends included", row)
    assert stated, row
    ends = [float(a) for a in stated.groups()]
    assert ends == [0.0, 90.0]
    assert grid["angles"][[0, -1]].tolist() == ends and grid["angles"].size == round(90.0 / step) + 1
    n_two = int(_find(r"(\d+) × \d+ two-angle", row))
    two_step = float(_find(r"two-angle, 0° to 90° every (\d+)°", row))
    assert grid["two_angles"].size == n_two == round(90.0 / two_step) + 1
    np.testing.assert_allclose(grid["two_angles"], np.arange(n_two) * two_step, rtol=0, atol=1e-12)
    assert grid["walls"].size == int(_find(r"(\d+) walls", row))
    n_kp = int(_find(r"(\d+) K_p", row))
    np.testing.assert_allclose(grid["kp"], 10.0 ** (5 + 3 * np.arange(n_kp) / (n_kp - 1)), rtol=1e-12)


def test_headline_peaks_are_before_and_after_tuning():
    r = DesignStudies(design_name="d", resolution="report", operating_speed=300.0, peak_before=0.038, peak_after=0.004)
    out = headline(r)
    assert out["peak_deflection_before_m"] == 0.038
    assert out["peak_deflection_after_m"] == 0.004


def test_headline_reads_the_thesis_layups_at_their_own_angles():
    """The headline's ``ply_angle_safety_factor_at_55_deg`` is the ply-angle study's value at
    α = 55° (the thesis's ±55°), and ``two_angle_safety_factor_at_55_0`` the two-angle map's
    at (α, β) = (55°, 0°), the thesis's (55/−55/0/0)s. Hand-built studies whose safety factor
    is a different number at every grid point, R(α) = α/10 and R(α, β) = α + β/100, so that
    55° reads 5.5 and (55°, 0°) reads 55.0 exactly (h41b-studies-sf-at-45-not-55,
    h41b-studies-two-angle-at-55-55)."""
    angles = np.array([0.0, 15.0, 30.0, 45.0, 55.0, 60.0, 75.0, 90.0])
    ply = xr.Dataset({"safety_factor": ("alpha", angles / 10.0)}, coords={"alpha": angles})
    pair = xr.Dataset(
        {"safety_factor": (("alpha", "beta"), angles[:, None] + angles[None, :] / 100.0)},
        coords={"alpha": angles, "beta": angles},
    )
    r = DesignStudies(design_name="d", resolution="report", operating_speed=300.0, ply_angle=ply, two_angle=pair)
    out = headline(r)
    assert out["ply_angle_safety_factor_at_55_deg"] == 5.5
    assert out["two_angle_safety_factor_at_55_0"] == 55.0


def test_headline_quietest_wall_is_a_thickness_and_its_peak_an_orbit():
    """``quietest_spinup_wall_m`` is the wall [m] of the smallest spin-up peak and
    ``quietest_spinup_peak_m`` that peak [m]: walls 1, 2, 3 mm with peaks 5, 1, 4 mm give
    2e-3 m and 1e-3 m (h41b-studies-quietest-wall-is-peak)."""
    walls = np.array([1e-3, 2e-3, 3e-3])
    wall = xr.Dataset(
        {"spinup_peak_deflection": ("wall_thickness", np.array([5e-3, 1e-3, 4e-3]))}, coords={"wall_thickness": walls}
    )
    out = headline(DesignStudies(design_name="d", resolution="report", operating_speed=300.0, wall=wall))
    assert out["quietest_spinup_wall_m"] == 2e-3
    assert out["quietest_spinup_peak_m"] == 1e-3
