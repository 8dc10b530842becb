"""The report's figures agree with the verdict (issue 25, point 6): read back from the artists.

The figures are drawn by the very jobs the report plans (:func:`flexshaft.report.driveline.
plan_run_report`), and their data read back from matplotlib's artists, against the verdict:

* the actuator figure draws static + spin-up (what the actuator checks judge), each actuator's
  gap and force capacity, and marks the checked peaks: the marked excursion and force are the
  check's findings at the point the figure shows (the point where the excursion check governs),
  and the curve's largest value up to the operating speed is that finding;
* the Campbell diagram tracks every mode up to 1.3 × the operating speed × the highest
  excitation order the checks use (every undamped natural frequency of (K + K_a, M) below it,
  from a dense eigen-solution: the reference), marks the verdict's critical speeds (the
  separation check's unbalance-response peaks) at their speeds, and draws the tail rotor's
  excitation orders at their slopes.

Tolerances: the artists hold the numbers the figure functions were given, converted to rpm,
mm or Hz: equal to round-off (1e-9 relative).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la

from flexshaft.analyses.torsional import torsional_excitations
from flexshaft.design import design_from_dict, tuned_design, with_overrides
from flexshaft.report.driveline import plan_run_report
from flexshaft.resolution import REPORT
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict.assess import assess

#: The tuned design on a coarse mesh (the figures' wiring does not depend on it; the run is faster:
#: 1.6 s of CPU instead of 2.4 s with 18 and 12 elements). Its dense reference still has 17
#: modes below the Campbell ceiling (18 with 18 and 12 elements), and the actuator checks still
#: govern at the cold day.
SMALL = {"mesh.shaft_elements": 8, "mesh.boom_elements": 4}


@pytest.fixture(scope="module")
def assessed():
    """The REPORT assessment over two of the envelope's points, hot-soak start then the cold day
    (CPU budget, issue 23: each point is a whole assessment): the actuator checks govern at the
    second, so the figure must find its point rather than show the first, and the other checks
    govern at either."""
    data = with_overrides(tuned_design(), SMALL).model_dump()
    points = {p["name"]: p for p in data["envelope"]["points"]}
    data["envelope"]["points"] = [points["hot_soak_start"], points["cold_day"]]
    result = assess(design_from_dict(data), REPORT)
    assert result.verdict.check("actuator_orbit").location["point"] == "cold_day"
    return result


@pytest.fixture(scope="module")
def jobs(assessed, tmp_path_factory):
    plan = plan_run_report(assessed, tmp_path_factory.mktemp("report"))
    return {job.stem: job for job in plan.jobs}


def _draw(job):
    return job.function(*job.args, **job.kwargs)


def _lines(ax, label_part: str):
    return [line for line in ax.get_lines() if label_part in str(line.get_label())]


def test_actuator_figure_draws_what_the_actuator_checks_judge(assessed, jobs):
    fig = _draw(jobs["actuators"])
    top, bottom = fig.axes[:2]
    orbit, force = assessed.verdict.check("actuator_orbit"), assessed.verdict.check("actuator_force")
    point = orbit.location["point"]
    # the spin-up checks end at the highest operating speed, shaded on both panels
    low, high = assessed.point(point).evidence.operating_range
    top_rpm = rad_s_to_rpm(high)
    for panel, check, scale in ((top, orbit, 1e3), (bottom, force, 1.0)):
        (band,) = [p for p in panel.patches if str(p.get_label()).startswith("operating speed range")]
        assert band.get_x() == pytest.approx(rad_s_to_rpm(low), rel=1e-12)
        assert band.get_x() + band.get_width() == pytest.approx(top_rpm, rel=1e-12)
        findings = {f.location["actuator"]: f for f in check.findings if f.location["point"] == point}
        assert findings  # the figure shows the excursion check's point; the force has findings there too
        for name, finding in findings.items():
            (peak,) = _lines(panel, f"{name}: checked peak")
            x, y = peak.get_xdata()[0], peak.get_ydata()[0]
            assert y == pytest.approx(finding.value * scale, rel=1e-9)
            assert x == pytest.approx(rad_s_to_rpm(finding.location["speed"]), rel=1e-9)
            (curve,) = _lines(panel, f"{name}: static + spin-up")
            xs, ys = np.asarray(curve.get_xdata()), np.asarray(curve.get_ydata())
            assert ys[xs <= top_rpm * (1 + 1e-12)].max() == pytest.approx(finding.value * scale, rel=1e-9)
            limit = [
                line.get_ydata()[0] for line in panel.get_lines() if str(line.get_label()).startswith(("gap", "force"))
            ]
            assert min(abs(v - finding.limit * scale) for v in limit) <= 1e-9 * finding.limit * scale
        # the axis shows the limit and the peak
        assert panel.get_ylim()[1] >= max(f.limit for f in findings.values()) * scale
    # the excursion the figure marks highest is the verdict's worst
    (worst,) = [f for f in orbit.findings if f.location["point"] == point and f.value == orbit.value]
    assert orbit.value == max(f.value for f in orbit.findings)
    assert worst.location["actuator"] in str([line.get_label() for line in top.get_lines()])


def test_campbell_covers_every_mode_the_checks_use_and_marks_the_verdicts_criticals(assessed, jobs):
    fig = _draw(jobs["campbell"])
    ax = fig.axes[0]
    model = assessed.model
    orders = [1.0] + [e.ratio for e in torsional_excitations(model.design)]
    ceiling_hz = 1.3 * model.speed * max(orders) / (2 * np.pi)
    # reference: every undamped natural frequency of (K + K_a, M) at rest below the ceiling
    free = model.dofs.free
    w2 = la.eigh((model.K + model.Kp)[free][:, free].toarray(), model.M[free][:, free].toarray(), eigvals_only=True)
    natural = np.sqrt(np.clip(w2, 0, None)) / (2 * np.pi)
    wanted = natural[natural < ceiling_hz]
    tracked_at_rest = np.sort(assessed.campbell.frequencies[0])
    assert tracked_at_rest.size >= wanted.size and tracked_at_rest.max() > ceiling_hz
    assert ax.get_ylim()[1] > ceiling_hz
    # the verdict's critical speeds, at their speeds on the 1× line
    (squares,) = _lines(ax, "critical speed of the verdict")
    expected = sorted(rad_s_to_rpm(c.speed) for c in assessed.evidence.critical_speeds)
    assert sorted(squares.get_xdata()) == pytest.approx(expected, rel=1e-9)
    assert np.asarray(squares.get_ydata()) == pytest.approx(np.asarray(squares.get_xdata()) / 60.0, rel=1e-9)
    # the tail rotor's torsional excitation orders, as rays of their slope
    for e in torsional_excitations(model.design):
        if e.source != "tail_rotor":
            continue
        (ray,) = _lines(ax, e.name)
        x, y = np.asarray(ray.get_xdata()), np.asarray(ray.get_ydata())
        assert (y[-1] - y[0]) / (x[-1] - x[0]) == pytest.approx(e.ratio / 60.0, rel=1e-9)
    # every main-rotor k/rev the torsional check uses, its governing one included (the tuned
    # design's main rotor 2/rev: was drawn only as 1/rev and N/rev), as a ray of slope k·n_MR/n
    # (the main rotor geared to the shaft: 4800 rpm against the design's main_rotor_speed_rpm)
    main = [e for e in torsional_excitations(model.design) if e.source == "main_rotor"]
    assert [e.order for e in main] == list(range(1, model.design.operating.main_rotor_blades + 1))
    governing = assessed.verdict.check("torsional_separation").location["case"]
    assert governing in [e.name for e in main]
    once = model.design.operating.main_rotor_speed_rpm / rad_s_to_rpm(model.speed)
    for e in main:
        (ray,) = _lines(ax, e.name)
        x, y = np.asarray(ray.get_xdata()), np.asarray(ray.get_ydata())
        assert (y[-1] - y[0]) / (x[-1] - x[0]) == pytest.approx(e.order * once / 60.0, rel=1e-9)


def test_the_margins_figure_draws_a_pass_without_a_finite_margin_as_passed():
    """A loop without a phase crossover has no finite gain margin: the check passes with no
    number (the verdict's table prints its limit, the optimizer's normalised margin is +inf).
    The report's margins figure draws it as passed, a green bar to the axis end, not as 'not
    evaluated' (which only a check that could not be computed is)."""
    from matplotlib.colors import to_rgba

    from flexshaft.verdict.result import Check, Verdict

    verdict = Verdict(
        (
            Check("loop_gain_margin", "loop gain margin", "decibel", "at least", "pass", limit=6.0),
            Check("loop_phase_margin", "loop phase margin", "angle", "at least", "not evaluated"),
        )
    )
    fig = verdict.plot_margins()
    ax = fig.axes[0]
    texts = [t.get_text() for t in ax.texts]
    assert texts.count("not evaluated") == 1 and any(t.startswith("∞: no finite margin") for t in texts)
    gain_bar = max(ax.patches, key=lambda p: p.get_y())  # the first check is drawn on top
    assert gain_bar.get_facecolor()[:3] == pytest.approx(to_rgba("tab:green")[:3])
    assert gain_bar.get_x() == 0.0 and gain_bar.get_width() >= 0.5  # the axis runs to at least +50 %
