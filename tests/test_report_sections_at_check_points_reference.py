"""The run report's whirl-stability and thermal sections show the numbers the verdict judges
when those checks govern at another envelope point than the governing one.

docs/requirements.md ("Where the points show"): "A figure drawn at another point says so in its
caption", and the report shows what the verdict uses. The embedded tuned design over its four
envelope points at the report's resolution (the session's ``assess(tuned_design(), REPORT)``,
tests/conftest.py ``embedded_comparison``: no extra analysis) is governed by ``cold_day``, while
its whirl-damping and temperature checks govern at ``hot_soak_start`` (the matrix is soft there:
the soaked material temperature).

* Log-decrement figure: its design curves, interpolated to the operating speed and taken over the
  modes the check judges (the figure's own ``judged`` mask), have the smallest log decrement the
  whirl-damping check reports, to rtol 1e-3: the curves are tracked roots on a 180-rpm grid, the
  check the modes at the operating speed itself (eigenvalues to 1e-6, a smooth δ(Ω) between two
  samples; measured 2e-7). The governing point's curves give 1.6 % more, so the tolerance tells
  the two points apart 16 times over.
* Thermal section: its self-heating analyses are the governing point's (named); the temperature
  check's own value, in °C (T − 273.15), and its point are stated beside them.
* Spin-up: the imbalance section's response is the governing point's (its figure says so); the
  spin-up deflection check, governing at ``hot_soak_start`` too, is stated with its value in mm
  (m × 1000, three significant figures as the verdict table prints it).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from flexshaft.design import tuned_design
from flexshaft.report.results_json import results_json
from flexshaft.report.run_sections import Figures, imbalance_section, stability_section, thermal_section
from flexshaft.resolution import REPORT
from flexshaft.units import rad_s_to_rpm


@pytest.fixture(scope="module")
def tuned(embedded_comparison):
    run = embedded_comparison.runs[0]
    assert run.design == tuned_design() and run.resolution == REPORT
    # the premise: both checks govern away from the governing point
    assert run.governing_point == "cold_day"
    assert run.verdict.check("whirl_damping").location["point"] == "hot_soak_start"
    assert run.verdict.check("temperature").location["point"] == "hot_soak_start"
    assert run.verdict.check("spinup_deflection").location["point"] == "hot_soak_start"
    return run


def test_the_log_decrement_figure_is_drawn_where_the_whirl_damping_check_governs(tuned, tmp_path):
    figs = Figures(tmp_path)
    section = stability_section(tuned, None, figs, rad_s_to_rpm(tuned.model.speed))
    job = next(j for j in figs.jobs if j.stem == "stability_log_decrement")
    rpm, curves, _, op_rpm = job.args[:4]
    (name, judged), *_ = job.kwargs["judged"].items()
    at_op = np.array([np.interp(op_rpm, rpm, column) for column in np.asarray(curves[name]).T])
    check = tuned.verdict.check("whirl_damping")
    assert at_op[judged].min() == pytest.approx(check.value, rel=1e-3)
    governing = np.array([np.interp(op_rpm, rpm, c) for c in np.asarray(tuned.stability.log_decrements).T])
    assert abs(governing[judged].min() / check.value - 1.0) > 1e-2  # the other point's curves differ
    caption = next(f.caption for f in section.figures if Path(f.path_png).stem == "stability_log_decrement")
    assert "hot_soak_start" in caption


def test_the_thermal_section_states_the_temperature_checks_own_value_and_point(tuned, tmp_path):
    text = " ".join(thermal_section(tuned, Figures(tmp_path)).paragraphs)
    check = tuned.verdict.check("temperature")
    assert f"at {tuned.governing_point}" in text  # the self-heating shown is the governing point's
    assert f"governs at hot_soak_start: {check.value - 273.15:.1f} °C" in text


def test_the_spin_up_paragraph_states_the_deflection_checks_own_value_and_point(tuned, tmp_path):
    op_rpm = rad_s_to_rpm(tuned.model.speed)
    section = imbalance_section(tuned, Figures(tmp_path), results_json(tuned), op_rpm)
    check = tuned.verdict.check("spinup_deflection")
    assert f"governs at hot_soak_start: {check.value * 1e3:.3g} mm" in section.paragraphs[0]
    assert f"at the governing point {tuned.governing_point}" in section.figures[0].caption
