"""The design studies' grids at each resolution as docs/studies.md states them, and the
headline's spin-up peaks before and after tuning (:mod:`flexshaft.thesis.design_studies`).

References:

* docs/studies.md, "Time" table, read here from the file: ``report``: "α every 2.5°; 8 × 8
  two-angle (0, 15, 30, 45, 55, 60, 75, 90); 9 walls 1–6 mm; 13 K_p"; ``full``: "α every 1°;
  19 × 19 two-angle; 23 walls; 31 K_p". The K_p grids span 1e5 to 1e8 N/m (study 4's default,
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
    n_two = int(_find(r"(\d+) × \d+ two-angle", row))
    assert grid["two_angles"].size == n_two and grid["two_angles"][[0, -1]].tolist() == [0.0, 90.0]
    assert grid["walls"].size == int(_find(r"(\d+) walls", row))
    n_kp = int(_find(r"(\d+) K_p", row))
    np.testing.assert_allclose(grid["kp"], 10.0 ** (5 + 3 * np.arange(n_kp) / (n_kp - 1)), rtol=1e-12)


def test_headline_peaks_are_before_and_after_tuning():
    r = DesignStudies(design_name="d", resolution="report", operating_speed=300.0, peak_before=0.038, peak_after=0.004)
    out = headline(r)
    assert out["peak_deflection_before_m"] == 0.038
    assert out["peak_deflection_after_m"] == 0.004
