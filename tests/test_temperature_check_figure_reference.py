"""The report's shaft-temperature figure shows what the temperature check reads, at the point
where it governs (plot/thermal.py, report/run_sections.py).

docs/requirements.md: the temperature check judges "the largest shaft temperature" against the
matrix allowable, and a hot-soaked start "begins hotter than its running equilibrium". Before,
the figure drew only the governing point's rise above the air (about 1 mK on the tuned design
at cold_day) while the check read 88.8 °C at hot_soak_start.

References (derived by hand): °C = K − 273.15 (ISO 80000-5); an equilibrium of 320, 330 and
325 K at x = 0, 1, 2 m reads 46.85, 56.85 and 51.85 °C; a material temperature of 361.95 K
reads 88.8 °C, an allowable of 373.15 K 100.0 °C. Drawn data are those doubles after one
subtraction: 1e-9 °C. The section's figure job is only recorded (never drawn) on hand-built
stand-ins of two points whose values all differ, so a value taken from the wrong point shows.
"""

from __future__ import annotations

from types import SimpleNamespace as NS

import numpy as np
import pytest
from test_report_sections_tables_reference import _shaft, _thermal
from test_run_sections_figures_reference import temperature_verdict

from flexshaft.plot.thermal import shaft_temperature_check_figure
from flexshaft.report.run_sections import Figures, thermal_section

X = np.array([0.0, 1.0, 2.0])
T = np.array([320.0, 330.0, 325.0])  # K


def _drawn(**kwargs):
    import matplotlib.pyplot as plt

    fig = shaft_temperature_check_figure(
        X,
        {"rotating loss model": [0.1, 0.3, 0.2]},
        [0.5, 1.5],
        {"rotating loss model": [1.0, 2.0]},
        temperature=(X, T),
        **kwargs,
    )
    top, middle, bottom = fig.axes
    lines = [
        (np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float), line.get_label())
        for line in top.lines
    ]
    texts = [t.get_text() for t in top.texts]
    out = lines, texts, top.get_ylim(), [line.get_ydata() for line in middle.lines], top.get_title()
    plt.close(fig)
    return out


def test_top_panel_draws_the_equilibrium_the_material_temperature_and_the_allowable_in_celsius():
    lines, texts, (lo, hi), middle, title = _drawn(
        checked=361.95, allowable=373.15, material_temperature=361.95, point="hot_soak_start"
    )
    (x, y, _), start, allowable = lines
    np.testing.assert_allclose(x, X, atol=1e-12)
    np.testing.assert_allclose(y, [46.85, 56.85, 51.85], atol=1e-9)
    assert start[1] == pytest.approx([88.8, 88.8], abs=1e-9) and "88.8 °C" in start[2]
    assert allowable[1] == pytest.approx([100.0, 100.0], abs=1e-9) and "100.0 °C" in allowable[2]
    assert texts == ["checked 88.8 °C ≤ 100.0 °C"]
    assert lo < 46.85 and hi > 100.0  # every line inside the axes
    assert "hot_soak_start" in title
    np.testing.assert_allclose(middle[0], [0.1, 0.3, 0.2])  # the rise panel below, unchanged


def test_without_allowable_or_material_temperature_only_the_equilibrium_and_the_value():
    lines, texts, _, _, title = _drawn(checked=330.0)
    assert len(lines) == 1 and texts == ["checked 56.9 °C"] and "(" not in title


def _point(name, temperature, checked, material):
    thermal = NS(shaft_temperature=NS(x=X, temperature=temperature))
    return NS(
        name=name,
        analyses=NS(thermal=thermal, conditions=NS(material_temperature=material)),
        evidence=NS(max_temperature=checked, allowable_temperature=373.15),
    )


def test_section_hands_the_figure_the_point_where_the_check_governs(tmp_path):
    """Two points: cold_day governs the design, the temperature check governs at hot_soak_start
    (its value 361.95 K, the material temperature there); the figure gets hot_soak_start's
    equilibrium, value and material temperature, not cold_day's."""
    cold = _point("cold_day", T - 30.0, 300.15, 250.0)
    hot = _point("hot_soak_start", T, 361.95, 361.95)
    points = {p.name: p for p in (cold, hot)}
    a = NS(
        points=(cold, hot),
        governing_point="cold_day",
        point=points.__getitem__,
        verdict=temperature_verdict(361.95, 11.2),
        thermal=_thermal({"rotating": _shaft()}, None),
    )
    figs = Figures(tmp_path)
    section = thermal_section(a, figs)
    (job,) = [j for j in figs.jobs if j.stem == "shaft_temperature"]
    assert job.function is shaft_temperature_check_figure
    x, temperature = job.kwargs["temperature"]
    np.testing.assert_array_equal(temperature, T)
    assert job.kwargs["checked"] == 361.95 and job.kwargs["material_temperature"] == 361.95
    assert job.kwargs["allowable"] == 373.15 and job.kwargs["point"] == "hot_soak_start"
    (ref,) = [f for f in section.figures if str(f.path_png).endswith("shaft_temperature.png")]
    assert "at hot_soak_start, where the temperature check governs" in ref.caption
