"""The design studies' gain maps of the actuators (report/studies_section.py) with two magnetic
bearings: each cell shows the largest peak over the actuators.

Reference (the API contract in the code, by hand): thesis figures 3.15 and 3.16 are the
"Maximum shaft displacement at the actuator location vs. control gains" and the "Maximum
actuator force vs. control gains" (their captions; the thesis has one actuator per figure, so
it says nothing of several); with several actuators ``SpinupMap.plot_actuator_displacement``'s
docstring (code) shows the "largest over them", and analyses/spinup.py's docstrings give
``actuator_displacement_peak`` and ``actuator_force_peak`` as the largest value at *each*
actuator, shape (n_kp, n_kd, n_act): the value of a cell is the larger of the two actuators'
(picked by hand below). 1 m = 1000 mm (the displacement map's scale).
Figures are only recorded as jobs (never drawn). CPU about 0.5 s, nearly all xarray's first use.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from test_studies_section_reference import _studies

from flexshaft.report.studies_section import studies_section_and_jobs


def _job(jobs, stem):
    (job,) = [j for j in jobs if j.stem == stem]
    return job


def test_actuator_maps_show_the_larger_actuator_of_two():
    """Two actuators, 1 × 2 gain cells. Displacement [m]: cell 1 (4e-4, 6e-4), cell 2 (3e-4,
    1e-4): the map reads 0.6 and 0.3 mm. Force [N]: cell 1 (200, 150), cell 2 (90, 120): the
    map reads 200 and 120 N. The larger actuator differs between cells, so neither actuator
    alone gives the map."""
    kp, kd = [1e6], [500.0, 2000.0]
    ds = xr.Dataset(
        {
            "shaft_peak": (("kp", "kd"), [[0.02, 0.01]]),
            "actuator_displacement_peak": (("kp", "kd", "actuator"), [[[4e-4, 6e-4], [3e-4, 1e-4]]]),
            "actuator_force_peak": (("kp", "kd", "actuator"), [[[200.0, 150.0], [90.0, 120.0]]]),
        },
        coords={"kp": kp, "kd": kd, "actuator": ["amb_1", "amb_2"]},
    )
    _, jobs = studies_section_and_jobs(_studies(spinup_map=ds), "out")
    # exact decimals scaled by 1000: rel 1e-12 allows the last-bit rounding of the product
    for stem, expected in (
        ("study_map_actuator_displacement", [[0.6, 0.3]]),
        ("study_map_actuator_force", [[200.0, 120.0]]),
    ):
        job = _job(jobs, stem)
        values = np.asarray(job.args[2]) * job.kwargs.get("scale", 1.0)
        assert values == pytest.approx(np.array(expected), rel=1e-12), stem
