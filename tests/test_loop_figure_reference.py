"""The magnetic-bearing loops' figure (plot/loops.py) and report section (report/run_sections.py,
``loops_section``) on hand-built loops.

References, derived by hand:

* the open loop from the sensitivity, L = (1 − S)/S (S = 1/(1 + L)): S = 0.5 gives L = 1 (0°),
  S = 2 gives L = −1/2 (180°), S = (1 + i)/2 gives L = (1 − i)/(1 + i) = −i (−90°);
* a phase margin φ is drawn where ∠L = φ − 180°: 36° at −144°; the required 30° at −150°;
* the zone limits 3, 4, 5 between zones A | B, B | C, C | D.

Agg, no file; CPU milliseconds.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace as NS

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from flexshaft.plot.loops import loop_sensitivity_figure  # noqa: E402
from flexshaft.report import run_sections  # noqa: E402

F = np.array([1.0, 10.0, 100.0])


def _lines(ax, label):
    return [ln for ln in ax.get_lines() if ln.get_label() == label]


def test_sensitivity_and_open_loop_phase_of_each_loop():
    loops = {"a (v)": (F, np.array([0.5, 2.0, 0.5 + 0.5j])), "b (w)": (F, np.array([0.5, 1.5, 0.5]))}
    fig = loop_sensitivity_figure(
        loops,
        peaks={"a (v)": (10.0, 2.1), "b (w)": (10.0, 1.6)},
        phase_margins={"a (v)": (50.0, 36.0), "b (w)": (60.0, 45.0)},
        required_peak=4.0,
        required_phase_margin_deg=30.0,
        zone_limits=(3.0, 4.0, 5.0),
    )
    top, bottom = fig.axes[0], fig.axes[1]
    (a_mag,) = _lines(top, "a (v)")
    np.testing.assert_allclose(a_mag.get_ydata(), [0.5, 2.0, math.sqrt(0.5)], rtol=1e-12)
    (a_phase,) = _lines(bottom, "a (v)")
    np.testing.assert_allclose(a_phase.get_ydata(), [0.0, 180.0, -90.0], atol=1e-9)
    (required,) = _lines(top, "required |S|max ≤ 4")
    np.testing.assert_array_equal(required.get_ydata(), [4.0, 4.0])
    (required_pm,) = _lines(bottom, "required phase margin ≥ 30°")
    np.testing.assert_array_equal(required_pm.get_ydata(), [-150.0, -150.0])
    # every loop marked; the worst written: a's peak 2.1 and a's margin 36° (at −144°)
    marks = [ln for ln in bottom.get_lines() if ln.get_marker() == "o"]
    assert sorted((float(m.get_xdata()[0]), float(m.get_ydata()[0])) for m in marks) == [(50.0, -144.0), (60.0, -135.0)]
    assert [t.get_text() for t in top.texts if t.get_text().startswith("|S|max")] == ["|S|max 2.1 at 10 Hz (a (v))"]
    assert [t.get_text() for t in bottom.texts] == ["phase margin 36° at 50 Hz (a (v))"]
    zones = {t.get_text(): t.get_position()[1] for t in top.texts if "|" in t.get_text() and "S" not in t.get_text()}
    assert zones == {"A | B": 3.0, "B | C": 4.0, "C | D": 5.0}
    # the two notes sit over the curves (on the tuned design the phase margin's crossed the
    # other loops' phase): each on a light box that hides most of what is behind it
    for note in [*(t for t in top.texts if t.get_text().startswith("|S|max")), *bottom.texts]:
        box = note.get_bbox_patch()
        assert box is not None and box.get_facecolor()[:3] == (1.0, 1.0, 1.0) and box.get_alpha() >= 0.8


def test_a_bad_loop_is_refused_naming_it():
    with pytest.raises(ValueError, match=r"loops\['a'\]: 3 frequencies but 2"):
        loop_sensitivity_figure({"a": (F, np.array([0.5, 0.5]))})
    with pytest.raises(ValueError, match=r"loops\['a'\] frequencies: must be > 0 Hz"):
        loop_sensitivity_figure({"a": (np.array([0.0, 1.0, 2.0]), np.ones(3))})


def test_the_report_section_reads_the_checks_point_and_the_requirements(tmp_path):
    """Two points; the sensitivity-peak check governs at "hot": its loops are tabulated (the
    margins as computed) and drawn, with the requirements |S|max ≤ 3.5 and 40° from
    [requirements] and ISO 14839-3's limits 3, 4, 5."""
    margins = NS(
        peak_sensitivity=2.2,
        zone="A",
        peak_frequency=41.0,
        gain_margin_upper_db=math.inf,
        gain_margin_lower_db=-math.inf,
        phase_margin_deg=38.0,
        phase_margin_frequency=42.0,
    )
    loop = NS(
        actuator="amb_1", axis="w", speed=2 * math.pi * 80.0, margins=margins, frequencies=F, sensitivity=np.ones(3)
    )
    hot = NS(name="hot", analyses=NS(bearing_loops=(loop,)))
    cold = NS(name="cold", analyses=NS(bearing_loops=()))
    a = NS(
        points=[cold, hot],
        point={"cold": cold, "hot": hot}.__getitem__,
        governing_point="cold",
        verdict=NS(check=lambda key: NS(location={"point": "hot"})),
        design=NS(requirements=NS(max_sensitivity_peak=3.5, min_gain_margin_db=6.0, min_phase_margin_deg=40.0)),
    )
    figs = run_sections.Figures(Path(tmp_path))
    section = run_sections.loops_section(a, figs)
    (table,) = section.tables
    assert table.rows == [["amb_1 (w)", 2.2, "A", 41.0, math.inf, -math.inf, 38.0, 42.0]]
    assert "at hot, where the sensitivity-peak check governs" in section.figures[0].caption
    assert "4800 rpm" in section.figures[0].caption  # 80 Hz · 60
    (job,) = figs.jobs
    assert job.kwargs["required_peak"] == 3.5 and job.kwargs["required_phase_margin_deg"] == 40.0
    assert tuple(job.kwargs["zone_limits"]) == (3.0, 4.0, 5.0)
    assert job.kwargs["peaks"] == {"amb_1 (w)": (41.0, 2.2)} and job.kwargs["phase_margins"] == {
        "amb_1 (w)": (42.0, 38.0)
    }
    cold_only = NS(**{**vars(a), "verdict": NS(check=lambda key: NS(location={"point": "cold"}))})
    assert run_sections.loops_section(cold_only, run_sections.Figures(Path(tmp_path))) is None  # no loops there


@pytest.mark.parametrize("f_peak", [2.0, 90.0])
def test_the_notes_stay_inside_their_axes(f_peak):
    """A peak and a crossover near the low or the high end of the frequency axis: each note's
    drawn box lies inside its axes (audit a2: a peak near the top frequency wrote its note past
    the axes, over the zone labels)."""
    f = np.array([1.0, 10.0, 100.0])
    fig = loop_sensitivity_figure(
        {"a (v)": (f, np.array([0.5, 1.0, 2.0]))},
        peaks={"a (v)": (f_peak, 2.0)},
        phase_margins={"a (v)": (f_peak, 40.0)},
        zone_limits=(3.0, 4.0, 5.0),
    )
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes[:2]:
        (note,) = [t for t in ax.texts if t.get_text().startswith(("|S|max", "phase margin"))]
        box, frame = note.get_window_extent(renderer), ax.get_window_extent(renderer)
        assert frame.x0 <= box.x0 and box.x1 <= frame.x1, (note.get_text(), box, frame)
