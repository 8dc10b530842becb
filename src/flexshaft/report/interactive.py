"""Interactive figures of an :class:`~flexshaft.verdict.assess.Assessment` (hover, zoom), drawn
by plotly.js in a browser (the offline page ``interactive.html`` that shows them:
:mod:`flexshaft.report.interactive_page`).

Each ``*_figure`` function returns a plotly.js figure as plain JSON data (``{"data": [...],
"layout": {...}}``): the verdict's normalised margins, the Campbell diagram with the operating
speed and the critical speeds, the spin-up orbit, the actuator excursion and force against their
limits (static + dynamic, as the verdict checks them) and the whirl log decrement over speed.
``flexshaft explore`` draws the same figures live;
:func:`~flexshaft.report.interactive_page.write_interactive_report` writes them beside
``report.html`` (``flexshaft run --interactive``) with plotly.js inlined, so the page
works offline and alone. The static report is unchanged and stays the default.

Numbers come from the assessment only (nothing is computed here); SI is converted to rpm, Hz
and mm here, at the edge, through :mod:`flexshaft.units`. plotly.js is the file the ``plotly``
wheel ships (the extra ``flexshaft[explore]``); no Python plotly API is used.
"""

from __future__ import annotations

import html
import math
from typing import Any

import numpy as np

from flexshaft.report.verdict import separation_readings, verdict_rows
from flexshaft.units import m_to_mm, rad_s_to_hz, rad_s_to_rpm, rpm_to_hz
from flexshaft.verdict.assess import Assessment, check_point
from flexshaft.verdict.gather import actuator_limits
from flexshaft.verdict.result import normalised_margin

__all__ = [
    "actuator_figure",
    "assessment_figures",
    "campbell_figure",
    "margins_figure",
    "spinup_figure",
    "stability_figure",
]

#: Status colours (the static report's margin figure uses the same meaning).
STATUS_COLOURS = {"pass": "#2e7d32", "fail": "#c62828", "not evaluated": "#9e9e9e"}
_PALETTE = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")
_WHIRL_DASH = {"forward": "solid", "backward": "dash", "planar": "dot", "none": "dashdot"}
_FONT = {"family": "DejaVu Sans, Helvetica, Arial, sans-serif", "size": 12}


# ------------------------------------------------------------------------------------------------
# Plain JSON numbers


def _values(array, digits: int = 6) -> list[float | None]:
    """A 1-D array as JSON numbers rounded to ``digits`` significant digits (NaN, ±inf → null)."""
    out = []
    for x in np.asarray(array, dtype=float).ravel():
        out.append(float(f"{x:.{digits}g}") if math.isfinite(x) else None)
    return out


def _layout(title: str, x_title: str, y_title: str, **extra: Any) -> dict:
    return {
        "title": {"text": title, "x": 0.01, "xanchor": "left", "font": {"size": 14}},
        "xaxis": {"title": {"text": x_title}, "zeroline": False},
        "yaxis": {"title": {"text": y_title}, "zeroline": False},
        "font": _FONT,
        "margin": {"l": 64, "r": 16, "t": 40, "b": 48},
        "legend": {"orientation": "h", "y": -0.22, "font": {"size": 11}},
        "hovermode": "closest",
        **extra,
    }


def _vertical(x: float, label: str, colour: str = "#444", dash: str = "dash") -> tuple[dict, dict]:
    """A vertical line across the plot at ``x`` and its label (layout shape and annotation)."""
    shape = {
        "type": "line",
        "xref": "x",
        "yref": "paper",
        "x0": x,
        "x1": x,
        "y0": 0,
        "y1": 1,
        "line": {"color": colour, "dash": dash, "width": 1.5},
    }
    note = {
        "x": x,
        "y": 1,
        "xref": "x",
        "yref": "paper",
        "text": label,
        "showarrow": False,
        "yanchor": "bottom",
        "font": {"size": 11, "color": colour},
    }
    return shape, note


def _limit_line(x0: float, x1: float, y: float, name: str, colour: str, axis: str = "") -> dict:
    """A horizontal limit drawn as a trace (so it is in the legend and hover)."""
    trace = {
        "type": "scatter",
        "mode": "lines",
        "x": [x0, x1],
        "y": [y, y],
        "name": name,
        "line": {"color": colour, "dash": "dash", "width": 1.5},
        "hovertemplate": f"{name}: %{{y:.4g}}<extra></extra>",
    }
    if axis:
        trace["xaxis"], trace["yaxis"] = "x" + axis, "y" + axis
    return trace


# ------------------------------------------------------------------------------------------------
# Figures


_AXIS_END = 3.0  # where the margin axis stops [-]


def margins_figure(a: Assessment) -> dict:
    """Every check's normalised margin (:func:`~flexshaft.verdict.result.normalised_margin`:
    negative fails) as a bar, green pass, red fail, grey not evaluated; a pass with nothing to
    measure (+inf) is a bar to the axis end, a check not evaluated (NaN) draws no bar (0)."""
    checks = a.verdict.checks
    rows = verdict_rows(a.verdict, compact=True)
    margins = [normalised_margin(c) for c in checks]
    # a pass with nothing to measure (+inf: no phase crossover, no critical speed) reaches the
    # axis end, not zero, which would read "at the limit"; not evaluated (NaN) draws no bar
    shown = [_AXIS_END if m == math.inf else (m if math.isfinite(m) else 0.0) for m in margins]
    text = [f"{row[3]} ({row[4]})" for row in rows]
    hover = [
        f"<b>{html.escape(row[0])}</b><br>value {html.escape(row[1])}, limit {html.escape(row[2])}"
        f"<br>margin {html.escape(row[3])}<br>{html.escape(row[5] or '')}"
        for row in rows
    ]
    return {
        "data": [
            {
                "type": "bar",
                "orientation": "h",
                "y": [c.title for c in checks],
                "x": _values(shown),
                "marker": {"color": [STATUS_COLOURS[c.status] for c in checks]},
                "text": text,
                "textposition": "auto",
                "hovertext": hover,
                "hoverinfo": "text",
                "name": "normalised margin",
            }
        ],
        "layout": _layout(
            f"Requirements: {'PASS' if a.verdict.passed else 'FAIL'} (normalised margin, < 0 fails)",
            "normalised margin [-]",
            "",
            yaxis={"autorange": "reversed", "automargin": True},
            # the margins span decades (a Tsai-Wu factor of 30 beside a 2 % excursion margin): the
            # axis stops at 3 (the label gives the value), zoom out to see the rest
            xaxis={"title": {"text": "normalised margin [-]"}, "range": [min(-1.0, 1.1 * min(shown)), _AXIS_END]},
            showlegend=False,
            margin={"l": 16, "r": 16, "t": 40, "b": 48},
        ),
    }


def campbell_figure(a: Assessment) -> dict | None:
    """Campbell diagram [Hz over rpm] of the tracked modes (whirl as line style), the 1× line,
    the operating speed (and its range) and the lateral critical speeds the separation check
    judges (peaks of the unbalance response, with their AF, and, when the check is on, their
    separation margin and API 684's required margin on hover and the required margin as a grey
    bar from the speed it is measured from, as in the report's diagram). None without a
    Campbell diagram."""
    camp = a.campbell
    if camp is None:
        return None
    rpm = rad_s_to_rpm(camp.speeds)
    freq = camp.frequencies
    logdec = camp.log_decrements
    data: list[dict[str, Any]] = []
    for k in range(freq.shape[1]):
        whirl = _dominant(camp.whirl[:, k])
        kind = _dominant(camp.kind[:, k]) if camp.kind is not None else "lateral"
        label = f"mode {k + 1} ({whirl if kind == 'lateral' else kind})"
        data.append(
            {
                "type": "scatter",
                "mode": "lines+markers",
                "x": _values(rpm),
                "y": _values(freq[:, k]),
                "name": label,
                "line": {"color": _PALETTE[k % len(_PALETTE)], "dash": _WHIRL_DASH.get(whirl, "solid"), "width": 1.5},
                "marker": {"size": 4},
                "customdata": _values(logdec[:, k], 4),
                "hovertemplate": f"{label}<br>%{{x:.0f}} rpm, %{{y:.2f}} Hz<br>log decrement %{{customdata}}"
                "<extra></extra>",
            }
        )
    top = float(rpm[-1])
    data.append(
        {
            "type": "scatter",
            "mode": "lines",
            "x": [0.0, top],
            "y": [0.0, rpm_to_hz(top)],
            "name": "1× spin",
            "line": {"color": "#000", "width": 1},
            "hoverinfo": "skip",
        }
    )
    criticals = a.evidence.critical_speeds or ()  # the verdict's (the separation check judges these)
    judged = bool(criticals) and a.design.requirements.separation != "off"
    readings = separation_readings(a.evidence, criticals) if judged else []
    if readings:
        # API 684's required separation of each critical: a grey bar at its frequency from the
        # speed its margin is measured from to the nearest speed it may have (the static
        # diagram's bars); first in the data, so drawn beneath the modes
        xs: list[float | None] = []
        ys: list[float | None] = []
        for c, (reference, bound, _margin, _required) in zip(criticals, readings):
            xs += [*_values([reference, bound]), None]
            ys += [*_values([rad_s_to_hz(c.speed)] * 2), None]
        data.insert(
            0,
            {
                "type": "scatter",
                "mode": "lines",
                "x": xs,
                "y": ys,
                "name": "separation API 684 requires",
                "line": {"color": "#9e9e9e", "width": 7},
                "opacity": 0.6,
                "hoverinfo": "skip",
            },
        )
    if criticals:
        hover = "critical %{x:.0f} rpm<br>AF %{customdata[0]}"
        custom = [[af] for af in _values([c.amplification_factor for c in criticals], 3)]
        if readings:
            hover += "<br>separation margin %{customdata[1]:.1%} (needs %{customdata[2]:.1%})"
            margins = _values([r[2] for r in readings], 4)
            required = _values([r[3] for r in readings], 4)
            custom = [[*row, m, r] for row, m, r in zip(custom, margins, required)]
        data.append(
            {
                "type": "scatter",
                "mode": "markers",
                "x": _values([rad_s_to_rpm(c.speed) for c in criticals]),
                "y": _values([rad_s_to_hz(c.speed) for c in criticals]),
                "name": "lateral critical speeds (unbalance peaks)",
                "marker": {"symbol": "x", "size": 11, "color": "#c62828", "line": {"width": 2}},
                "customdata": custom,
                "hovertemplate": hover + "<extra></extra>",
            }
        )
    op = rad_s_to_rpm(a.operating_speed)
    shapes, notes = _operating(a, op)
    return {
        "data": data,
        "layout": _layout(
            "Campbell diagram", "speed [rpm]", "frequency [Hz]", shapes=shapes, annotations=notes, hovermode="closest"
        ),
    }


def _operating(a: Assessment, op_rpm: float) -> tuple[list, list]:
    """The operating speed's line and, when the design gives one, its speed range as a band."""
    shape, note = _vertical(op_rpm, f"operating {op_rpm:.0f} rpm")
    shapes, notes = [shape], [note]
    low, high = a.design.operating.speed_limits
    if high > low:
        shapes.append(
            {
                "type": "rect",
                "xref": "x",
                "yref": "paper",
                "x0": rad_s_to_rpm(low),
                "x1": rad_s_to_rpm(high),
                "y0": 0,
                "y1": 1,
                "fillcolor": "#888",
                "opacity": 0.12,
                "line": {"width": 0},
            }
        )
    return shapes, notes


def _dominant(labels) -> str:
    values, counts = np.unique(np.asarray(labels, dtype=str), return_counts=True)
    return str(values[int(np.argmax(counts))]) if values.size else "none"


def spinup_figure(a: Assessment) -> dict:
    """Peak shaft orbit over the shaft and the orbit at each actuator station during the spin-up
    [mm over rpm, log scale], with the spin-up deflection limit when the design gives one."""
    spin = a.spinup
    model = a.model
    dm = model.dofs
    rpm = rad_s_to_rpm(spin.speeds)
    data = [
        {
            "type": "scatter",
            "mode": "lines",
            "x": _values(rpm),
            "y": _values(m_to_mm(spin.shaft_peak)),
            "name": "largest over the shaft",
            "line": {"color": "#000", "width": 2},
            "hovertemplate": "%{x:.0f} rpm: %{y:.4g} mm<extra>largest over the shaft</extra>",
        }
    ]
    for k, act in enumerate(model.actuators):
        node = dm.node_at("shaft", act.link.x_shaft)
        name = f"shaft at {act.name} (x = {act.link.x_shaft:.2f} m)"
        data.append(
            {
                "type": "scatter",
                "mode": "lines",
                "x": _values(rpm),
                "y": _values(m_to_mm(spin.envelope[node])),
                "name": name,
                "line": {"color": _PALETTE[k % len(_PALETTE)], "width": 1.5},
                "hovertemplate": f"%{{x:.0f}} rpm: %{{y:.4g}} mm<extra>{html.escape(name)}</extra>",
            }
        )
    limit = a.design.requirements.max_spinup_deflection
    if limit is not None:
        data.append(_limit_line(float(rpm[0]), float(rpm[-1]), m_to_mm(limit), "spin-up orbit limit", "#c62828"))
    op = rad_s_to_rpm(a.operating_speed)
    shapes, notes = _operating(a, op)
    layout = _layout(
        "Spin-up imbalance response (orbit major semi-axis)",
        "speed [rpm]",
        "orbit [mm]",
        shapes=shapes,
        annotations=notes,
    )
    layout["yaxis"]["type"] = "log"
    return {"data": data, "layout": layout}


def actuator_figure(a: Assessment) -> dict | None:
    """Each actuator's excursion, static offset + spin-up orbit [mm], against its auxiliary-bearing
    gap, and its force, static + spin-up [N], against its capacity (top and bottom panels): the
    sums the actuator checks judge, with each check's peak marked. None without actuators."""
    model = a.model
    if not model.actuators:
        return None
    # the envelope point where the excursion check governs: its spin-up and evidence
    point = a.point(check_point(a, "actuator_orbit"))
    spin = point.analyses.spinup
    rpm = rad_s_to_rpm(spin.speeds)
    evidence = {e.name: e for e in point.evidence.actuators}
    limits = actuator_limits(model)
    data = []
    x0, x1 = float(rpm[0]), float(rpm[-1])
    for k, act in enumerate(model.actuators):
        colour = _PALETTE[k % len(_PALETTE)]
        ev = evidence.get(act.name)
        offset = ev.static_offset if ev is not None else 0.0
        force0 = ev.static_force if ev is not None else 0.0
        excursion = m_to_mm(offset + np.asarray(spin.actuator_displacement[act.name]))
        force = force0 + np.asarray(spin.actuator_force[act.name])
        for axis, y, unit in (("", excursion, "mm"), ("2", force, "N")):
            data.append(
                {
                    "type": "scatter",
                    "mode": "lines",
                    "x": _values(rpm),
                    "y": _values(y),
                    "xaxis": "x" + axis,
                    "yaxis": "y" + axis,
                    "name": f"{act.name}: static + spin-up",
                    "legendgroup": act.name,
                    "showlegend": axis == "",
                    "line": {"color": colour, "width": 1.8},
                    "hovertemplate": f"{html.escape(act.name)}: %{{y:.4g}} {unit} at %{{x:.0f}} rpm<extra></extra>",
                }
            )
        if ev is not None:
            for axis, speed, value, unit in (
                ("", ev.orbit_speed, m_to_mm(ev.static_offset + ev.peak_orbit), "mm"),
                ("2", ev.force_speed, ev.static_force + ev.peak_force, "N"),
            ):
                data.append(
                    {
                        "type": "scatter",
                        "mode": "markers",
                        "x": _values([rad_s_to_rpm(speed)]),
                        "y": _values([value]),
                        "xaxis": "x" + axis,
                        "yaxis": "y" + axis,
                        "name": f"{act.name}: checked peak",
                        "legendgroup": act.name,
                        "showlegend": False,
                        "marker": {"color": colour, "size": 9, "symbol": "diamond"},
                        "hovertemplate": f"{html.escape(act.name)} peak checked: %{{y:.4g}} {unit} at "
                        "%{x:.0f} rpm<extra></extra>",
                    }
                )
        limit = limits[act.name]
        if limit.gap is not None:
            data.append(_limit_line(x0, x1, m_to_mm(limit.gap), f"{act.name}: gap", colour))
        if limit.force_capacity is not None:
            data.append(_limit_line(x0, x1, limit.force_capacity, f"{act.name}: force capacity", colour, axis="2"))
    op = rad_s_to_rpm(a.operating_speed)
    shapes, notes = _operating(a, op)  # lines and band across both panels (paper height)
    layout = _layout(
        "Actuators: excursion against the gap, force against the capacity",
        "",
        "excursion [mm]",
        shapes=shapes,
        annotations=notes,
        grid={"rows": 2, "columns": 1, "pattern": "independent", "roworder": "top to bottom"},
    )
    layout["xaxis"] = {"matches": "x2", "showticklabels": False}
    layout["xaxis2"] = {"title": {"text": "speed [rpm]"}}
    layout["yaxis2"] = {"title": {"text": "force [N]"}}
    return {"data": data, "layout": layout}


def stability_figure(a: Assessment) -> dict:
    """Log decrement over speed of every tracked mode of the whirl-stability analysis, the
    required log decrement and the modes the whirl-damping check judges at the operating speed."""
    st = a.stability
    rpm = rad_s_to_rpm(st.speeds)
    logdec = st.log_decrements
    data = []
    for k in range(logdec.shape[1]):
        whirl = _dominant(st.whirl[:, k])
        kind = _dominant(st.kind[:, k]) if st.kind is not None else "lateral"
        label = f"mode {k + 1} ({whirl if kind == 'lateral' else kind})"
        data.append(
            {
                "type": "scatter",
                "mode": "lines+markers",
                "x": _values(rpm),
                "y": _values(logdec[:, k], 4),
                "name": label,
                "line": {"color": _PALETTE[k % len(_PALETTE)], "dash": _WHIRL_DASH.get(whirl, "solid"), "width": 1.5},
                "marker": {"size": 4},
                "hovertemplate": f"{label}<br>%{{x:.0f}} rpm: log decrement %{{y:.4g}}<extra></extra>",
            }
        )
    required = a.design.requirements.required_log_decrement
    data.append(_limit_line(float(rpm[0]), float(rpm[-1]), required, "required log decrement", "#c62828"))
    judged = a.evidence.modes_at_operating or ()
    if judged:
        op = rad_s_to_rpm(a.operating_speed)
        data.append(
            {
                "type": "scatter",
                "mode": "markers",
                "x": [op] * len(judged),
                "y": _values([m.log_decrement for m in judged], 4),
                "text": [f"mode {m.label}, {rad_s_to_hz(m.frequency):.2f} Hz" for m in judged],
                "name": "checked at the operating speed",
                "marker": {"symbol": "diamond", "size": 9, "color": "#000"},
                "hovertemplate": "%{text}<br>log decrement %{y:.4g}<extra></extra>",
            }
        )
    op = rad_s_to_rpm(a.operating_speed)
    shapes, notes = _operating(a, op)
    onset = st.onset_speed
    if onset is not None and math.isfinite(onset):
        shape, note = _vertical(rad_s_to_rpm(onset), f"whirl onset {rad_s_to_rpm(onset):.0f} rpm", "#c62828")
        shapes.append(shape)
        notes.append(note)
    layout = _layout(
        "Whirl stability: log decrement of the tracked modes",
        "speed [rpm]",
        "log decrement [-]",
        shapes=shapes,
        annotations=notes,
    )
    return {"data": data, "layout": layout}


def assessment_figures(a: Assessment) -> dict[str, dict]:
    """Every interactive figure of the assessment by name (those that exist for its design)."""
    figures = {
        "margins": margins_figure(a),
        "campbell": campbell_figure(a),
        "spinup": spinup_figure(a),
        "actuators": actuator_figure(a),
        "stability": stability_figure(a),
    }
    return {name: figure for name, figure in figures.items() if figure is not None}
