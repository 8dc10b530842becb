"""The HTML report of ``flexshaft run`` (figures come from :mod:`flexshaft.plot`).

It consumes results (never builds models) and imports matplotlib only when a figure is drawn,
so ``import flexshaft.report`` stays light. Typical use::

    from flexshaft.report import Section, FigureRef, campbell_figure, save_figure, write_report

    paths = save_figure(campbell_figure(speeds_rpm, freqs_hz, whirl), out, "campbell")
    write_report(out, "Baseline", [Section("Modes", figures=[FigureRef(paths["png"], "Campbell")])])
"""

from __future__ import annotations

from flexshaft.plot.driveline import (
    actuator_figure,
    bode_figure,
    campbell_figure,
    deflected_shape_figure,
    imbalance_response_figure,
    mode_shapes_figure,
    orbit_figure,
    safety_factor_figure,
    save_figure,
)
from flexshaft.plot.output import FigureJob, render_figures
from flexshaft.report.html import FigureRef, Section, Table, format_cell, render_report, write_report

__all__ = [
    "campbell_figure",
    "imbalance_response_figure",
    "deflected_shape_figure",
    "safety_factor_figure",
    "mode_shapes_figure",
    "actuator_figure",
    "bode_figure",
    "orbit_figure",
    "save_figure",
    "FigureJob",
    "render_figures",
    "Section",
    "Table",
    "FigureRef",
    "format_cell",
    "render_report",
    "write_report",
]
