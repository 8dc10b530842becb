"""One-line figures from the API: every result's ``.plot()`` and the figure functions behind it.

Checked on the axes' content (labels with units, number of lines and markers, positions of
markers in data units, geometry of labels after a real draw), never on pixels. The references
are independent where a number is involved: the modes nearest the spin frequency are picked
again here from the frequencies, a Jeffcott rotor's closed-form receptance gives the Bode
phase, a forward orbit's signed area gives the drawing sense, and the shaft's static
equilibrium checks the bearing reactions the report shows.
"""

from __future__ import annotations

import io

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from matplotlib.figure import Figure  # noqa: E402

from flexshaft.analyses import campbell, imbalance_response, modes, stability  # noqa: E402
from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import orbit_amplitude, static_response  # noqa: E402
from flexshaft.analyses.shaft_strength import shaft_safety_factor, static_load_parts  # noqa: E402
from flexshaft.analyses.spinup import spinup_map  # noqa: E402
from flexshaft.assembly import build_model  # noqa: E402
from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load  # noqa: E402
from flexshaft.design import baseline_design, with_overrides  # noqa: E402
from flexshaft.plot.campbell import campbell_figure  # noqa: E402
from flexshaft.plot.labels import place_point_labels, spread  # noqa: E402
from flexshaft.plot.output import FigureJob, one_collection, render_figures  # noqa: E402
from flexshaft.plot.response import bode_figure, orbit_ellipse, orbit_figure  # noqa: E402
from flexshaft.plot.studies import gain_map_figure  # noqa: E402
from flexshaft.units import rad_s_to_rpm  # noqa: E402
from flexshaft.verdict.result import Check, Verdict  # noqa: E402

RPM = 60.0 / (2.0 * np.pi)


@pytest.fixture(scope="module")
def model():
    # the baseline on a coarse mesh: same physics and bearings, seconds instead of minutes
    return build_model(with_overrides(baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 8}))


@pytest.fixture(scope="module")
def response(model):
    speeds = np.linspace(0.05, 1.1, 40) * model.speed
    return imbalance_response(model, speeds, imbalance_loads(model))


def drawn(fig: Figure) -> Figure:
    fig.canvas.draw()  # text extents need a renderer
    return fig


def boxes_overlap(a, b) -> bool:
    return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1


def visible_axes(fig: Figure):
    return [a for a in fig.axes if a.get_visible() and a.get_label() != "<colorbar>"]


# -- modes ------------------------------------------------------------------------------------


def test_modes_plot_shows_the_modes_nearest_the_spin_frequency(model):
    m = modes(model, model.speed, n_modes=12)
    fig = m.plot(bearings_x=[b.x_shaft for b in model.bearings])
    assert isinstance(fig, Figure)
    panels = visible_axes(fig)
    assert len(panels) == 6
    f_spin = model.speed / (2 * np.pi)
    expected = sorted(np.argsort(np.abs(m.frequencies - f_spin))[:6])  # picked again here
    titles = [a.get_title() for a in panels]
    for k, title in zip(expected, titles):
        assert title.startswith(f"mode {k + 1}: {m.frequencies[k]:.2f} Hz"), title
    assert all(a.get_xlabel() == "axial position x [m]" for a in panels[-3:])
    assert panels[0].get_ylabel() == "normalised [-]"
    # v, w of the shaft and of the boom, and one ▲ per bearing
    bearing_marks = [ln for ln in panels[0].get_lines() if ln.get_marker() == "^"]
    assert len(bearing_marks) == 1 and len(bearing_marks[0].get_xdata()) == len(model.bearings)
    assert len([ln for ln in panels[0].get_lines() if ln.get_linestyle() == "--"]) == 2  # boom v, w
    assert "nearest the spin frequency" in fig.get_suptitle()


def test_modes_plot_explicit_modes_into_given_axes(model):
    m = modes(model, 0.0, n_modes=4)
    fig = Figure()
    axes = fig.subplots(2, 1)
    assert m.plot(ax=axes, modes=[0, 3]) is fig
    assert axes[1].get_title().startswith("mode 4:")
    with pytest.raises(ValueError, match="ax: this figure draws 2 panel"):
        m.plot(ax=axes[0], modes=[0, 1])
    with pytest.raises(ValueError, match="kind must be one of"):
        m.plot("bode")
    with pytest.raises(ValueError, match="modes must be indices"):
        m.plot(modes=[7])


# -- Campbell ----------------------------------------------------------------------------------


def test_campbell_plot_colours_damping_and_labels_criticals_apart(model):
    c = campbell(model, np.linspace(0.0, 1.25 * model.speed, 13), n_modes=8)
    op_rpm = rad_s_to_rpm(model.speed)
    fig = drawn(c.plot(operating_rpm=op_rpm, main_rotor_hz={"4/rev": 17.6}))
    ax = fig.axes[0]
    assert ax.get_xlabel() == "spin speed Ω [rpm]" and ax.get_ylabel() == "natural frequency [Hz]"
    bar = fig.axes[1]
    assert bar.get_ylabel() == "log decrement δ [-]"
    assert len([t for t in bar.get_yticklabels() if t.get_text()]) >= 4
    # every tracked point coloured by its log decrement (markers thinned to <= 40 per curve)
    colours = np.concatenate([np.asarray(coll.get_array()) for coll in ax.collections])
    assert colours.size == np.isfinite(c.frequencies).sum()
    # one open circle per critical speed on the 1x line
    circles = [ln for ln in ax.get_lines() if ln.get_marker() == "o" and ln.get_markerfacecolor() == "none"]
    assert len(circles) == 1
    xs, ys = circles[0].get_data()
    np.testing.assert_allclose(xs, [k.speed_rpm for k in c.critical_speeds])
    np.testing.assert_allclose(ys, xs / 60.0)
    # the main rotor's 4/rev is geared to the shaft: a ray through (operating speed, 17.6 Hz)
    rotor = [ln for ln in ax.get_lines() if ln.get_label() == "main rotor 4/rev"]
    assert len(rotor) == 1
    np.testing.assert_allclose(np.interp(op_rpm, *rotor[0].get_data()), 17.6)
    labels = [t for t in ax.texts if t.get_text().endswith(" rpm")]
    assert labels, "critical speeds are labelled"
    boxes = [t.get_window_extent() for t in labels]
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            assert not boxes_overlap(boxes[i], boxes[j]), (labels[i].get_text(), labels[j].get_text())
    legend = fig.legends[0]
    names = [t.get_text() for t in legend.get_texts()]
    assert "forward whirl" in names and "critical speed" in names and "operating speed 4800 rpm" in names
    # the legend sits in a band below the axes: it hides no curve
    assert legend.get_window_extent().y1 <= ax.get_window_extent().y0


def test_excitation_ray_names_on_the_right_edge_do_not_overprint():
    """Rays that leave the diagram on its right edge close together (here the main rotor's 4/rev
    at 25.0 Hz and a 0.3x order at 30.0 Hz at 6000 rpm, about 20 px apart on a 150-Hz axis) keep
    their names apart: their text boxes, drawn, do not overlap."""
    speeds = np.linspace(0.0, 6000.0, 31)
    f = np.column_stack([np.full(31, 150.0), np.full(31, 60.0)])
    whirl = np.array([["forward", "backward"]] * 31)
    fig = drawn(
        campbell_figure(
            speeds,
            f,
            whirl,
            operating_rpm=4800.0,
            main_rotor_hz={"4/rev": 20.0},  # geared: 25 Hz at 6000 rpm
            excitation_orders={"tail rotor 1/rev": 0.3, "tail rotor 0.31/rev": 0.31},  # 30 and 31 Hz
        )
    )
    ax = fig.axes[0]
    names = [t for t in ax.texts if t.get_text() in ("MR 4/rev", "tail rotor 1/rev", "tail rotor 0.31/rev")]
    assert len(names) == 3
    boxes = [t.get_window_extent() for t in names]
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            assert not boxes_overlap(boxes[i], boxes[j]), (names[i].get_text(), names[j].get_text())


def test_campbell_without_damping_keeps_one_colour_per_mode():
    speeds = np.linspace(0.0, 6000.0, 31)
    f = np.column_stack([20 + 0.001 * speeds, 20 - 0.001 * speeds, np.full(31, 50.0)])
    whirl = np.array([["forward", "backward", "none"]] * 31)
    kind = np.array([["lateral", "lateral", "torsional"]] * 31)
    fig = campbell_figure(speeds, f, whirl, kind=kind)
    assert len(fig.axes) == 1  # no colour bar without damping
    names = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "torsional (no 1× critical)" in names  # torsional modes named, drawn dotted
    with pytest.raises(ValueError, match="log_decrement: expected shape"):
        campbell_figure(speeds, f, whirl, log_decrement=np.zeros((31, 2)))
    with pytest.raises(ValueError, match="main_rotor_hz"):
        campbell_figure(speeds, f, whirl, main_rotor_hz={"1/rev": -1.0})


# -- responses ---------------------------------------------------------------------------------


def test_imbalance_response_bode_at_a_station(model, response):
    fig = response.plot(kind="bode", station=4.42, operating_rpm=4800.0, gap=0.25e-3)
    amp, phase = fig.axes
    assert amp.get_ylabel() == "amplitude [mm]" and amp.get_yscale() == "log"
    assert phase.get_ylabel() == "phase [deg]" and phase.get_xlabel() == "spin speed Ω [rpm]"
    node = model.dofs.node_at("shaft", 4.42)
    curve = [ln for ln in amp.get_lines() if ln.get_label().startswith(f"x = {model.dofs.shaft_x[node]:.2f} m, v")]
    assert len(curve) == 1
    np.testing.assert_allclose(curve[0].get_xdata(), rad_s_to_rpm(response.spin_speeds))
    np.testing.assert_allclose(curve[0].get_ydata(), np.abs(np.asarray(response)[model.dofs.shaft(node, "v"), 0]) * 1e3)
    assert any("gap 0.25 mm" in ln.get_label() for ln in amp.get_lines())
    both = response.plot("bode", station=[2.0, 6.0], direction="both")
    assert len(both.axes[0].get_lines()) == 4  # two stations × (v, w)
    with pytest.raises(ValueError, match="station must be a shaft position"):
        response.plot("bode", station=40.0)
    with pytest.raises(ValueError, match="direction must be"):
        response.plot("bode", direction="x")


def test_bode_phase_of_a_jeffcott_rotor():
    # closed form: imbalance response r^2 / (1 - r^2 + 2 i zeta r); phase 0 below, -90 deg at,
    # -180 deg above the critical
    r = np.linspace(0.05, 3.0, 300)
    zeta = 0.05
    q = 1e-4 * r**2 / (1 - r**2 + 2j * zeta * r)
    fig = bode_figure(r * 3000.0, {"disk": q})
    phase = fig.axes[1].get_lines()[0]
    x, y = phase.get_data()
    assert y[0] == pytest.approx(np.degrees(-np.arctan2(2 * zeta * r[0], 1 - r[0] ** 2)), abs=1e-9)
    assert np.interp(3000.0, x, y) == pytest.approx(-90.0, abs=0.5)
    assert y[-1] == pytest.approx(-180.0 + np.degrees(np.arctan2(2 * zeta * 3.0, 3.0**2 - 1)), abs=1e-6)
    assert fig.axes[0].get_lines()[0].get_ydata().max() == pytest.approx(1e-4 / (2 * zeta) * 1e3, rel=0.01)


def test_orbits_at_the_operating_speed(model, response):
    fig = response.plot(kind="orbit", station={"amb_1": 3.21, "amb_2": 5.63}, speed_rpm=4800.0, gap=0.25e-3)
    panels = visible_axes(fig)
    assert len(panels) == 2 and [a.get_title() for a in panels] == ["amb_1", "amb_2"]
    i = int(np.argmin(np.abs(rad_s_to_rpm(response.spin_speeds) - 4800.0)))
    q = np.asarray(response)
    for a, x in zip(panels, (3.21, 5.63)):
        node = model.dofs.node_at("shaft", x)
        v, w = q[model.dofs.shaft(node, "v"), 0, i], q[model.dofs.shaft(node, "w"), 0, i]
        ellipse = a.get_lines()[0]
        radius = np.hypot(*ellipse.get_data()).max()
        unit = a.get_xlabel()[-3:-1]  # mm, or μm when the panel (orbit and gap) spans less than 0.1 mm
        assert a.get_xlabel() == f"w (lateral) [{unit}]" and a.get_ylabel() == f"v (vertical) [{unit}]"
        scale = {"mm": 1e3, "μm": 1e6}[unit]
        assert radius == pytest.approx(orbit_amplitude(v, w) * scale, rel=2e-3)  # 121 points on the ellipse
        assert a.get_aspect() == 1.0
    with pytest.raises(ValueError, match="expected a \\(v, w\\) pair"):
        orbit_figure({"a": (1.0,)})


def test_orbit_drawing_sense_and_gap_circle():
    # forward whirl of the imbalance (v = F, w = -iF) seen along +x: clockwise, negative signed area in (w, v)
    v, w = orbit_ellipse(1.0, -1j)
    assert 0.5 * np.sum(w[:-1] * v[1:] - w[1:] * v[:-1]) == pytest.approx(-np.pi, rel=1e-3)
    fig = orbit_figure({"amb": (0.2e-3, -0.2e-3j)}, {"amb": 0.25e-3})
    lines = visible_axes(fig)[0].get_lines()
    gap = [ln for ln in lines if ln.get_linestyle() == "--"]
    assert len(gap) == 1 and np.hypot(*gap[0].get_data()).max() == pytest.approx(0.25)
    assert any("80 % of gap 0.25 mm" in t.get_text() for t in visible_axes(fig)[0].texts)
    small = orbit_figure({"amb": (1e-7, -1e-7j)}, 0.25e-3)  # a tiny orbit: the panel shows the orbit, not the gap
    assert not [ln for ln in visible_axes(small)[0].get_lines() if ln.get_linestyle() == "--"]


# -- stability ---------------------------------------------------------------------------------


def test_stability_plot_marks_the_onset(model):
    s = stability(model, np.linspace(0.0, 1.2 * model.speed, 13), n_modes=8)
    assert s.onset_speed is not None  # the baseline turns unstable below its operating speed
    fig = s.plot(operating_rpm=4800.0, required=0.1)
    ax = fig.axes[0]
    assert ax.get_ylabel() == "log decrement δ [-]" and ax.get_xlabel() == "spin speed Ω [rpm]"
    onset = [ln for ln in ax.get_lines() if ln.get_marker() == "X"]
    assert len(onset) == 1
    assert onset[0].get_xdata()[0] == pytest.approx(rad_s_to_rpm(s.onset_speed))
    assert onset[0].get_ydata()[0] == 0.0
    assert any(
        t.get_text().startswith(f"onset {rad_s_to_rpm(s.onset_speed):.0f} rpm\nmode {s.unstable_mode + 1}")
        for t in ax.texts
    )
    assert any(ln.get_label() == "required δ ≥ 0.1" for ln in ax.get_lines())
    re = s.plot("real_part")
    assert re.axes[0].get_ylabel() == "Re(s) [1/s]"
    assert [ln for ln in re.axes[0].get_lines() if ln.get_marker() == "X"]


# -- strength ----------------------------------------------------------------------------------


def test_strength_plot_annotation_clears_the_title(model, response):
    strength = shaft_safety_factor(model, static_load_parts(model), np.asarray(response)[:, 0, -1])
    fig = drawn(strength.plot())
    ax = fig.axes[0]
    assert ax.get_xlabel() == "axial position x [m]" and ax.get_ylabel() == "Tsai-Wu safety factor R [-]"
    note = [t for t in ax.texts if t.get_text().endswith(f"R = {strength.safety_factor:.3g} at x = {strength.x:.3g} m")]
    assert len(note) == 1
    box = note[0].get_window_extent()
    assert not boxes_overlap(box, ax.title.get_window_extent())
    inside = ax.get_window_extent()
    assert inside.x0 <= box.x0 and box.x1 <= inside.x1 and inside.y0 <= box.y0 and box.y1 <= inside.y1
    marker = [ln for ln in ax.get_lines() if ln.get_label() == "critical point"][0]
    assert marker.get_xdata()[0] == strength.x
    shares = strength.plot("load_shares")
    assert len(shares.axes[0].patches) == len(strength.load_shares)


# -- spin-up map -------------------------------------------------------------------------------


def test_spinup_map_plot_legend_hides_no_marker(model):
    smap = spinup_map(model, [1e5, 1e6, 1e7, 3e7], [0.0, 100.0, 1000.0], speeds=np.linspace(50.0, model.speed, 25))
    fig = drawn(smap.plot(other={"design": (1e7, 0.0)}))
    ax = fig.axes[0]
    star = [ln for ln in ax.get_lines() if ln.get_marker() == "*"]
    assert len(star) == 1
    kp, kd, _ = smap.best()
    assert f"K_p = {kp:.3g} N/m, K_d = {kd:.3g} N s/m" in star[0].get_label()
    legend = ax.get_legend().get_window_extent()
    strip = fig.axes[1]  # K_d = 0 has a strip of its own under the log axis: the design's ring is there
    assert [t.get_text() for t in strip.get_yticklabels()] == ["0"]
    assert any(ln.get_marker() == "o" for ln in strip.get_lines())
    for panel in (ax, strip):
        for line in panel.get_lines():
            px, py = panel.transData.transform(np.column_stack(line.get_data()))[0]
            assert not (legend.x0 <= px <= legend.x1 and legend.y0 <= py <= legend.y1), line.get_label()
    bar = fig.axes[-1]
    assert bar.get_ylabel() == "max spin-up shaft orbit [mm]"
    assert len([t for t in bar.get_yticklabels() if t.get_text()]) >= 4
    force = smap.plot("actuator_force")
    assert force.axes[-1].get_ylabel() == "max actuator force [N]"


def test_log_colour_bar_within_one_decade_has_four_ticks():
    values = np.array([[20.0, 40.0], [80.0, 140.0]]) * 1e-3
    fig = drawn(gain_map_figure([1e6, 1e7], [0.0, 100.0], values, "orbit [mm]", scale=1e3))
    ticks = [t.get_text() for t in fig.axes[-1].get_yticklabels() if t.get_text()]
    assert len(ticks) >= 4 and all("10^" not in t and "times" not in t for t in ticks), ticks


# -- verdict -----------------------------------------------------------------------------------


def test_verdict_plot_margin_bars():
    checks = (
        Check("tsai_wu", "Tsai-Wu safety factor", "ratio", "at least", "pass", 3.0, 1.5, 1.5),
        Check("whirl_onset", "whirl onset speed", "speed", "at least", "fail", 300.0, 578.0, -278.0),
        Check("actuator_orbit", "actuator orbit", "length", "at most", "pass", 1e-4, 2.5e-4, 1.5e-4),
        Check("temperature", "shaft temperature", "temperature", "at most", "not evaluated", note="no laminate"),
    )
    fig = Verdict(checks).plot()
    ax = fig.axes[0]
    bars = list(ax.patches)
    assert len(bars) == 4
    widths = [b.get_width() for b in bars]
    assert widths[0] == pytest.approx(1.0) and widths[1] == pytest.approx(-278.0 / 578.0)
    assert widths[2] == pytest.approx(0.6)
    colours = [matplotlib.colors.to_hex(b.get_facecolor()) for b in bars]
    assert colours[0] == colours[2] == matplotlib.colors.to_hex("tab:green")
    assert colours[1] == matplotlib.colors.to_hex("tab:red")
    assert colours[3] == matplotlib.colors.to_hex("0.75")
    assert [t.get_text() for t in ax.get_yticklabels()] == [c.title for c in checks]
    texts = [t.get_text() for t in ax.texts]
    assert "+100%  (+1.5)" in texts and "-48%  (-2655 rpm)" in texts and "not evaluated" in texts
    assert ax.get_xlabel().startswith("margin / limit [%]")


# -- batch rendering and helpers ---------------------------------------------------------------


def test_render_figures_serial_and_in_worker_processes(tmp_path, model):
    m = modes(model, model.speed, n_modes=6)
    from flexshaft.report.run_sections import plot_result

    jobs = [
        FigureJob("shapes", plot_result, (m, "shapes")),
        FigureJob("bode", bode_figure, (np.arange(3.0), {"a": np.array([1e-4, 2e-4j, -1e-4])})),
    ]
    serial = render_figures(jobs, tmp_path / "serial")
    forked = render_figures(jobs, tmp_path / "forked", processes=2, svg=True)
    for done in (serial, forked):
        assert list(done) == ["shapes", "bode"]
        for r in done.values():
            assert r.paths["png"].read_bytes().startswith(b"\x89PNG") and r.seconds > 0
    assert "svg" not in serial["bode"].paths and forked["bode"].paths["svg"].is_file()
    with pytest.raises(ValueError, match="stems must be unique"):
        render_figures(jobs + jobs[:1], tmp_path)
    with pytest.raises(ValueError, match="processes must be"):
        render_figures(jobs, tmp_path, processes=0)


def test_one_collection_frees_the_released_figure_and_restores_the_collector():
    import gc
    import weakref

    from flexshaft.plot.output import write_png

    def draw() -> weakref.ref:
        fig = bode_figure(np.arange(3.0), {"a": np.array([1e-4, 2e-4j, -1e-4])})
        write_png(fig, io.BytesIO())
        return weakref.ref(fig)

    assert gc.isenabled()
    with one_collection():
        assert not gc.isenabled()
        released = draw()
        assert released() is not None  # its cycles wait for the block's end
    assert gc.isenabled() and released() is None  # freed by the one young collection
    gc.disable()
    try:
        with one_collection():  # the caller's setting is left alone, nothing collected
            kept = draw()
        assert not gc.isenabled() and kept() is not None
    finally:
        gc.enable()
        gc.collect()


def test_label_helpers_do_not_overprint():
    assert np.all(np.diff(np.sort(spread([0.0, 0.5, 1.0, 10.0], 2.0))) >= 2.0 - 1e-9)
    fig = Figure(figsize=(5, 4))
    ax = fig.add_subplot()
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 10)
    x = [5.0, 5.1, 5.2, 5.3]
    texts = place_point_labels(ax, x, x, [f"{v:.1f} rpm" for v in x], fontsize=8)
    drawn(fig)
    boxes = [t.get_window_extent() for t in texts]
    assert all(not boxes_overlap(boxes[i], boxes[j]) for i in range(4) for j in range(i + 1, 4))


# -- bearing reactions (the numbers of the report's bearing table) -----------------------------


def test_bearing_reactions_balance_the_static_shaft_loads(model):
    # independent reference: equilibrium of the shaft as a free body. The bearings carry the
    # vertical and lateral loads applied to the shaft (its manoeuvre inertia, point and line
    # loads); the internal loss and the circulatory terms are self-equilibrated.
    loads = external_static_load(model) + torque_load(model)
    q_static = static_response(model, loads)
    q_speed = imbalance_response(model, [model.speed], imbalance_loads(model))[:, :, 0]
    reactions = bearing_reactions(model, q_static, q_speed)
    assert list(reactions) == [b.name for b in model.bearings]
    nodes = np.arange(model.dofs.n_shaft_nodes)
    for k, field in ((1, "v"), (2, "w")):
        applied = loads[model.dofs.shaft(nodes, field)].sum()
        carried = sum(r.static_force[k] for r in reactions.values())
        # round-off of the sparse solve only (forces ~1e3 N)
        assert carried == pytest.approx(applied, rel=1e-8, abs=1e-6)
    amb = reactions["amb_1"]
    assert amb.gap == pytest.approx(0.25e-3) and amb.kind == "active"
    v, w = amb.orbit
    node_rows = model.bearings[1].rows @ q_speed
    assert v == node_rows[1, amb.worst_case] and w == node_rows[2, amb.worst_case]
    with pytest.raises(ValueError, match="q_static must have shape"):
        bearing_reactions(model, q_static[:-1], q_speed)


def test_log_axis_labels_are_plain_text_with_the_values_of_matplotlibs_own():
    """Reference: matplotlib's default log formatter (LogFormatterSciNotation) on the same axis;
    flexshaft's labels say the same in plain text (no mathtext to parse)."""
    from matplotlib.ticker import LogFormatterSciNotation

    from flexshaft.plot.style import log_scale, new_figure, plain_log_label

    fig, axes = new_figure(1, 1, (4.0, 3.0))
    ax = axes[0, 0]
    ax.plot([1e-4, 3e2], [1.0, 2.0])
    log_scale(ax, "x")
    fig.canvas.draw()
    ticks = [t for t in ax.xaxis.get_majorticklocs() if 1e-4 <= t <= 3e2]
    ours = [ax.xaxis.get_major_formatter()(t) for t in ticks]
    reference = LogFormatterSciNotation(10.0)
    reference.set_axis(ax.xaxis)
    theirs = [reference(t) for t in ticks]
    exponents = [round(np.log10(t)) for t in ticks]
    superscript = dict(zip("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    # the decades the locator picks vary with the versions (every one with numpy 2, every second
    # with numpy 1.26): any three, negative and positive exponents among them
    assert len(ticks) >= 3 and min(exponents) < 0 < max(exponents)
    assert theirs == [f"$\\mathdefault{{10^{{{e}}}}}$" for e in exponents]
    assert ours == ["10" + "".join(superscript[c] for c in str(e)) for e in exponents]
    assert plain_log_label("$\\mathdefault{2\\times10^{-3}}$") == "2×10⁻³"
    assert plain_log_label("$\\mathdefault{10^{2.30}}$") == "$\\mathdefault{10^{2.30}}$"  # left to mathtext


@pytest.mark.parametrize("facecolor", ["white", "none"])
def test_png_files_hold_the_pixels_agg_drew(tmp_path, facecolor):
    """Reference: the figure's Agg buffer at the same resolution (``canvas.draw`` and
    ``buffer_rgba``, matplotlib's public API). The PNG save_figure writes, decoded by Pillow,
    holds the same pixels exactly and the resolution, through matplotlib's own canvas (no
    canvas of flexshaft's overriding a print method): RGB for an opaque figure (its alpha is
    255 everywhere), RGBA when the figure's face is transparent. The figure's dpi is kept."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    from flexshaft.plot.output import save_figure
    from flexshaft.plot.style import new_figure

    fig, axes = new_figure(1, 2, (5.0, 2.5))
    assert type(fig.canvas) is FigureCanvasAgg
    fig.set_facecolor(facecolor)
    axes[0, 0].plot([0.0, 1.0, 2.0], [0.0, 1.0, 0.5], label="a")
    axes[0, 1].contourf(np.random.default_rng(0).random((8, 8)), cmap="viridis")
    axes[0, 0].legend()
    own_dpi = fig.dpi
    ours = save_figure(fig, tmp_path, "ours", svg=False, dpi=97.0)["png"]
    assert fig.dpi == own_dpi
    fig.set_dpi(97.0)
    fig.canvas.draw()
    reference = np.asarray(fig.canvas.buffer_rgba())
    with Image.open(ours) as mine:
        assert mine.size == (reference.shape[1], reference.shape[0])
        assert mine.mode == ("RGB" if facecolor == "white" else "RGBA")
        np.testing.assert_array_equal(np.asarray(mine.convert("RGBA")), reference)
        assert mine.info["dpi"] == pytest.approx((97.0, 97.0), abs=1e-2)  # pixels per metre, rounded


def test_png_of_a_figure_without_an_agg_canvas_goes_through_savefig(tmp_path):
    """A bare ``Figure()`` (matplotlib's base canvas) is written by ``savefig``; reference:
    the same figure on an Agg canvas, drawn at the same resolution: the same pixels. A canvas
    derived from Agg (an interactive backend's) also goes through ``savefig``, which draws with
    Agg's own method, not the window's."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from PIL import Image

    from flexshaft.plot.output import save_figure

    fig = Figure(figsize=(3.0, 2.0))
    assert not isinstance(fig.canvas, FigureCanvasAgg)
    fig.add_subplot().plot([0.0, 1.0], [1.0, 0.0])
    path = save_figure(fig, tmp_path, "bare", svg=False, dpi=80.0)["png"]

    class WindowCanvas(FigureCanvasAgg):  # an interactive backend's canvas: its draw updates a window
        def draw(self):
            raise AssertionError("the window's draw was called")

    WindowCanvas(fig)
    assert save_figure(fig, tmp_path, "window", svg=False, dpi=80.0)["png"].stat().st_size > 0
    FigureCanvasAgg(fig)
    fig.set_dpi(80.0)
    fig.canvas.draw()
    with Image.open(path) as mine:
        np.testing.assert_array_equal(np.asarray(mine.convert("RGBA")), np.asarray(fig.canvas.buffer_rgba()))


@pytest.mark.parametrize("shape, cstride", [((6, 23), 4), ((5, 21), 4), ((4, 9), 1)])
def test_response_surface_facets_draw_as_plot_surface(shape, cstride):
    """Reference: matplotlib's ``Axes3D.plot_surface(rstride=1, cstride=...)`` of the same grid,
    drawn in an identical figure: the vectorised facets give the same pixels, with the stride
    dividing the columns evenly (21 - 1 = 5 × 4), unevenly (23 - 1 = 5 × 4 + 2) and 1."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from flexshaft.plot.studies import _surface

    rng = np.random.default_rng(3)
    X, Y = np.meshgrid(np.linspace(0.0, 2.0, shape[0]), np.linspace(0.0, 5e3, shape[1]), indexing="ij")
    Z = rng.random(shape) * 3.0

    def drawn(draw) -> np.ndarray:
        fig = Figure(figsize=(4.0, 3.0), dpi=80)
        FigureCanvasAgg(fig)
        ax = fig.add_subplot(projection="3d")
        draw(ax)
        fig.canvas.draw()
        return np.asarray(fig.canvas.buffer_rgba()).copy()

    ours = drawn(lambda ax: _surface(ax, X, Y, Z, cstride, 3.0))
    theirs = drawn(
        lambda ax: ax.plot_surface(
            X, Y, Z, cmap="viridis", vmin=0.0, vmax=3.0, rstride=1, cstride=cstride, linewidth=0, antialiased=False
        )
    )
    np.testing.assert_array_equal(ours, theirs)


def test_in_view_locators_draw_the_ticks_matplotlib_draws():
    """Reference: the same figure with matplotlib's own AutoLocator / LogLocator put back (the
    linear and log scales' defaults): the same pixels (matplotlib draws only the ticks inside
    the view); ours locate no tick outside the view, theirs do."""
    from matplotlib.ticker import AutoLocator, LogLocator

    from flexshaft.plot.style import log_scale, new_figure, styled

    x = np.linspace(0.13, 9.71, 50)

    @styled
    def drawn(ours: bool):
        fig, axes = new_figure(2, 1, (4.0, 4.0))
        top, bottom = axes[0, 0], axes[1, 0]
        top.plot(x, 3.7 * np.sin(x) + 0.3)
        bottom.plot(x, 2e-4 * np.exp(x))
        log_scale(bottom)
        if not ours:
            for ax in (top, bottom):
                ax.xaxis.set_major_locator(AutoLocator())
            top.yaxis.set_major_locator(AutoLocator())
            bottom.yaxis.set_major_locator(LogLocator(10.0))
            bottom.yaxis.set_minor_locator(LogLocator(10.0, subs=(2.0, 5.0)))
        fig.set_dpi(80)
        fig.canvas.draw()
        return fig, np.asarray(fig.canvas.buffer_rgba()).copy()

    (ours, our_pixels), (_, their_pixels) = drawn(True), drawn(False)
    np.testing.assert_array_equal(our_pixels, their_pixels)
    beyond = 0
    for ax, log in zip(ours.axes, (False, True)):
        for axis, default in ((ax.xaxis, AutoLocator()), (ax.yaxis, LogLocator(10.0) if log else AutoLocator())):
            lo, hi = sorted(axis.get_view_interval())
            for locs in (axis.get_majorticklocs(), axis.get_minorticklocs()):
                assert np.all((locs >= lo * (1 - 1e-9) - 1e-12) & (locs <= hi * (1 + 1e-9)))
            default.set_axis(axis)
            beyond += int(np.sum((default() < lo) | (default() > hi)))
    assert beyond > 0  # matplotlib's own locators would have built Tick objects never drawn


def test_wall_figure_shows_the_spinup_peak_panel_only_with_actuators():
    """The wall study's spin-up peak gets its own panel with its smallest value marked; a
    design without actuators (all NaN) keeps the two panels."""
    from flexshaft.plot.studies import wall_thickness_figure

    walls = np.array([1.0, 2.0, 3.0, 4.0]) * 1e-3
    sf, f1 = np.array([10.0, 20.0, 30.0, 40.0]), np.array([5.0, 4.9, 4.8, 4.7])
    fig = wall_thickness_figure(walls, sf, sf, f1, np.array([3.0, 0.9, 0.4, 0.7]) * 1e-3)
    assert len(fig.axes) == 3
    labels = [t.get_text() for t in fig.axes[2].get_legend().get_texts()]
    assert labels[1] == "smallest: 0.4 mm at 3 mm wall"
    assert len(wall_thickness_figure(walls, sf, sf, f1, np.full(4, np.nan)).axes) == 2
