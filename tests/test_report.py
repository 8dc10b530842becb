"""Report layer: every figure function on synthetic data, the HTML page, and a headless render.

The render test opens the written ``report.html`` in headless Chromium (Debian package,
installed by ``scripts/install_chromium.sh``) and checks that every embedded image decodes
and that a full-page screenshot is not blank. It is skipped when Chromium is missing, except
under CI (environment variable ``CI`` set), where it fails instead.
"""

from __future__ import annotations

import datetime as dt
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from chromium_probe import chromium_or_skip, image_load_title, run_chromium

from flexshaft.plot.stability import log_decrement_figure
from flexshaft.plot.verdict import margins_figure
from flexshaft.report import (
    FigureRef,
    Section,
    Table,
    actuator_figure,
    bode_figure,
    campbell_figure,
    deflected_shape_figure,
    format_cell,
    imbalance_response_figure,
    mode_shapes_figure,
    orbit_figure,
    render_report,
    safety_factor_figure,
    save_figure,
    write_report,
)

GAP = 0.5e-3  # auxiliary-bearing radial gap [m]
OPERATING_RPM = 4800.0


def _jeffcott_amplitude(speeds_rpm: np.ndarray, critical_rpm: float, damping_ratio: float, e: float) -> np.ndarray:
    """Unbalance response of a Jeffcott rotor, e r^2 / |1 - r^2 + 2 i zeta r| [m]."""
    r = speeds_rpm / critical_rpm
    return e * r**2 / np.abs(1.0 - r**2 + 2j * damping_ratio * r)


def _synthetic_figures(folder: Path) -> list[tuple[str, dict[str, Path]]]:
    """Build one figure with each function from synthetic arrays and save them."""
    speeds = np.linspace(0.0, 8000.0, 161)  # [rpm]
    omega_hz = speeds / 60.0
    # two gyroscopically split pairs and one planar mode that appears only above 2000 rpm
    f_pair1 = np.column_stack([20.0 + 0.08 * omega_hz, 20.0 - 0.08 * omega_hz])
    f_pair2 = np.column_stack([70.0 + 0.2 * omega_hz, 70.0 - 0.2 * omega_hz])
    f_planar = np.where(speeds >= 2000.0, 110.0, np.nan)
    freqs = np.column_stack([f_pair1, f_pair2, f_planar])
    whirl = np.empty(freqs.shape, dtype=object)
    whirl[:, [0, 2]], whirl[:, [1, 3]], whirl[:, 4] = "forward", "backward", "planar"
    whirl[:10, :4] = "planar"  # at rest the pairs are planar
    critical = [60.0 * 20.0 / (1 - 0.08), 60.0 * 70.0 / (1 - 0.2)]  # 1x crossings of forward modes
    # log decrement: forward modes lose damping with speed, the first one turns unstable
    delta = np.column_stack(
        [
            0.08 - 0.1 * speeds / 8000.0,
            np.full(161, 0.06),
            0.2 - 0.1 * speeds / 8000.0,
            np.full(161, 0.15),
            np.full(161, 0.3),
        ]
    )
    yield_fig = [
        (
            "campbell",
            campbell_figure(
                speeds,
                freqs,
                whirl,
                critical,
                OPERATING_RPM,
                harmonics=(1, 2),
                log_decrement=delta,
                main_rotor_hz={"4/rev": 17.6},
            ),
        )
    ]
    onset = 8000.0 * 0.8
    yield_fig.append(
        (
            "stability",
            log_decrement_figure(
                speeds,
                {"design": delta},
                {"design": onset},
                OPERATING_RPM,
                onset_text={"design": "mode 1, forward whirl"},
                required=0.1,
            ),
        )
    )

    amplitudes = {
        "max shaft": _jeffcott_amplitude(speeds, critical[0], 0.05, 0.2e-3),
        "amb_1": 0.4 * _jeffcott_amplitude(speeds, critical[0], 0.05, 0.2e-3),
        "amb_2": 0.3 * _jeffcott_amplitude(speeds, critical[1], 0.08, 0.2e-3),
    }
    yield_fig.append(("imbalance", imbalance_response_figure(speeds, amplitudes, OPERATING_RPM, GAP, log_y=True)))
    r = speeds / critical[0]
    receptance = 0.2e-3 * r**2 / (1.0 - r**2 + 0.1j * r)  # Jeffcott rotor, zeta = 0.05 [m]
    yield_fig.append(
        (
            "bode",
            bode_figure(speeds[1:], {"disk, v": receptance[1:], "disk, w": -1j * receptance[1:]}, OPERATING_RPM, GAP),
        )
    )
    yield_fig.append(
        (
            "orbits",
            orbit_figure({"amb_1": (0.2e-3, -0.15e-3j), "amb_2": (1e-6, 2e-6 + 1e-6j)}, {"amb_1": GAP, "amb_2": GAP}),
        )
    )

    length = 8.0  # [m]
    x = np.linspace(0.0, length, 41)
    boom_x = np.linspace(0.0, length, 21)
    boom_v = -2e-3 * (boom_x / length) ** 2 * (3 - boom_x / length)  # cantilever tip load shape [m]
    shaft_v = np.interp(x, boom_x, boom_v) - 0.4e-3 * np.sin(np.pi * x / 2.0) ** 2
    shaft_w = 0.2e-3 * np.sin(np.pi * x / length)
    yield_fig.append(
        (
            "deflection",
            deflected_shape_figure(
                x, shaft_v, shaft_w, boom_x, boom_v, 0.5 * boom_v, bearings_x=(0.0, 2.0, 4.0, 6.0, 8.0)
            ),
        )
    )

    safety = 3.0 + 1.5 * np.cos(2 * np.pi * x / 4.0) + 0.2 * x
    yield_fig.append(
        ("safety", safety_factor_figure(x, safety, label="ply 3 (+55°), φ = 120°, σ2 dominates <check escaping>"))
    )

    shapes = [
        {
            "label": f"mode {k}, {20.0 * k**2:.1f} Hz, forward",
            "v": np.sin(k * np.pi * x / length),
            "w": -1j * np.sin(k * np.pi * x / length),
        }
        for k in (1, 2, 3)
    ]
    shapes.append({"label": "mode 4, planar", "v": np.zeros_like(x), "w": np.sin(4 * np.pi * x / length)})
    boom_shapes = [{"v": 0.2 * s["v"][::2], "w": 0.2 * s["w"][::2]} for s in shapes]
    yield_fig.append(("modes", mode_shapes_figure(x, shapes, boom_x, boom_shapes)))

    displacement = {"amb_1": amplitudes["amb_1"], "amb_2": amplitudes["amb_2"]}
    force = {name: 2e6 * d for name, d in displacement.items()}  # PD stiffness 2 MN/m [N]
    yield_fig.append(("actuators", actuator_figure(speeds, displacement, force, GAP, operating_rpm=OPERATING_RPM)))
    yield_fig.append(
        (
            "verdict",
            margins_figure(
                ["safety factor", "whirl onset", "temperature"],
                [0.8, -0.3, np.nan],
                ["pass", "fail", "not evaluated"],
                ["+1.2", "-1440 rpm", ""],
            ),
        )
    )
    return [(stem, save_figure(fig, folder, stem)) for stem, fig in yield_fig]


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict:
    folder = tmp_path_factory.mktemp("results")
    saved = _synthetic_figures(folder)
    captions = {
        "campbell": "Campbell diagram <forward & backward>",
        "stability": "Log decrement and onset",
        "imbalance": "Imbalance response",
        "bode": "Bode plot",
        "orbits": "Orbits at the bearings",
        "verdict": "Verdict margins",
        "deflection": "Static deflection",
        "safety": "Safety factor",
        "modes": "Mode shapes at 4800 rpm",
        "actuators": "Actuators",
    }
    sections = [
        Section(
            "Design summary",
            paragraphs=["Baseline FMC shaft on a flexible tailboom. Escaping check: a < b & c > d."],
            tables=[
                Table(
                    "Critical speeds",
                    ["mode", "speed [rpm]", "whirl", "passed"],
                    [
                        [1, 1304.3478, "forward", True],
                        [2, 5250.0, "forward", False],
                        [3, float("nan"), None, np.bool_(True)],
                    ],
                )
            ],
        ),
        Section("Dynamics", figures=[FigureRef(paths["png"], captions[stem]) for stem, paths in saved[:6]]),
        Section(
            "Strength and actuators", figures=[FigureRef(paths["png"], captions[stem]) for stem, paths in saved[6:]]
        ),
    ]
    path = write_report(
        folder,
        "flexshaft report: baseline",
        sections,
        design_name="baseline <v1>",
        generated=dt.datetime(2024, 5, 1, 12, 30),
    )
    return {"folder": folder, "saved": saved, "path": path, "n_figures": len(saved)}


def test_figures_are_written_as_png_and_svg(report: dict) -> None:
    for stem, paths in report["saved"]:
        assert paths["png"].name == f"{stem}.png" and paths["svg"].name == f"{stem}.svg"
        assert paths["png"].read_bytes().startswith(b"\x89PNG")
        assert paths["png"].stat().st_size > 20_000, stem  # a real plot, not an empty canvas
        assert b"<svg" in paths["svg"].read_bytes()[:2000]


def test_report_is_one_self_contained_escaped_page(report: dict) -> None:
    page = report["path"].read_text(encoding="utf-8")
    assert report["path"].name == "report.html"
    assert all(src.startswith("data:image/png;base64,") for src in re.findall(r'src="([^"]*)"', page))
    assert all(href.startswith("#") for href in re.findall(r'href="([^"]*)"', page))
    text = re.sub(r"data:image/png;base64,[A-Za-z0-9+/=]+", "", page).replace("http-equiv", "")
    assert not re.search(r"https?:|//|url\(|@import", text, re.IGNORECASE)
    assert "<script" not in page and "<link" not in page and "<iframe" not in page
    images = re.findall(r'<img src="data:image/png;base64,[A-Za-z0-9+/=]+" alt="([^"]+)"', page)
    assert len(images) == report["n_figures"]
    assert "Campbell diagram &lt;forward &amp; backward&gt;" in images
    assert "a &lt; b &amp; c &gt; d" in page and "baseline &lt;v1&gt;" in page
    assert "2024-05-01 12:30" in page and "flexshaft" in page
    for i, title in enumerate(["Design summary", "Dynamics", "Strength and actuators"], 1):
        assert f'<a href="#section-{i}">{title}</a>' in page and f'id="section-{i}"' in page
    assert '<td class="num">1304</td>' in page and "<td>forward</td>" in page
    assert "<td>yes</td>" in page and "<td>no</td>" in page and "True" not in page
    assert '<td class="num">NaN</td>' in page and "<td>—</td>" in page


def test_images_are_shown_at_their_physical_size(tmp_path: Path) -> None:
    # 96 CSS px per inch whatever the PNG's resolution: an 8 in × 4.8 in figure is 768 × 461 px
    figure_paths = []
    for dpi in (100, 120, 150):
        fig = imbalance_response_figure([0.0, 1.0], {"a": [1e-3, 2e-3]})
        figure_paths.append(save_figure(fig, tmp_path, f"dpi{dpi}", svg=False, dpi=dpi))
    assert all("svg" not in p for p in figure_paths) and not list(tmp_path.glob("*.svg"))
    page = render_report(
        "t", [Section("s", figures=[FigureRef(p["png"], f"c{k}") for k, p in enumerate(figure_paths)])]
    )
    assert page.count('width="768" height="461"') == 3
    assert "(dpi100.png)" in page and ".svg" not in page  # no SVG file, none named


def test_format_cell() -> None:
    assert format_cell(3.14159265) == "3.142"
    assert format_cell(np.float32(1.5e-7)) == "1.5e-07"
    assert format_cell(12345678) == "12345678" and format_cell(np.int64(7)) == "7"
    assert format_cell(float("inf")) == "∞" and format_cell(-np.inf) == "−∞"
    assert format_cell(1 + 2j) == "1+2j" and format_cell(False) == "no" and format_cell("x") == "x"
    assert format_cell(np.bool_(True)) == "yes" and format_cell(None) == "—"


def test_bad_inputs_are_refused_with_the_field_named(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="row 0 has 1 values"):
        Table("t", ["a", "b"], [[1]])
    with pytest.raises(FileNotFoundError, match="missing.png"):
        render_report("t", [Section("s", figures=[FigureRef(tmp_path / "missing.png", "c")])])
    with pytest.raises(ValueError, match="frequencies_hz and whirl"):
        campbell_figure([0.0, 1.0], np.ones((3, 2)), [["forward"] * 2] * 3)
    with pytest.raises(ValueError, match="whirl: unknown labels"):
        campbell_figure([0.0, 1.0], np.ones((2, 1)), [["fwd"], ["forward"]])
    with pytest.raises(ValueError, match=r"amplitudes\['amb_1'\]"):
        imbalance_response_figure([0.0, 1.0, 2.0], {"amb_1": [1.0, 2.0]})
    with pytest.raises(ValueError, match="stem"):
        save_figure(None, tmp_path, "../escape")


def test_import_does_not_load_matplotlib() -> None:
    code = "import sys, flexshaft.report; sys.exit(1 if 'matplotlib' in sys.modules else 0)"
    assert subprocess.run([sys.executable, "-c", code], timeout=60).returncode == 0


def test_report_renders_in_headless_chromium(report: dict, tmp_path: Path) -> None:
    chromium = chromium_or_skip()
    assert image_load_title(chromium, report["path"], tmp_path) == f"IMAGES-OK:{report['n_figures']}"

    screenshot = tmp_path / "report.png"
    shot = run_chromium(
        chromium,
        tmp_path,
        "--window-size=1400,3000",
        "--hide-scrollbars",
        f"--screenshot={screenshot}",
        report["path"].as_uri(),
    )
    assert shot.returncode == 0, shot.stderr[-2000:]
    assert screenshot.stat().st_size > 50_000
    import matplotlib.image

    pixels = matplotlib.image.imread(screenshot)
    assert pixels.shape[:2] == (3000, 1400)
    assert pixels[..., :3].std() > 0.05  # text and plots, not a blank page
    if os.environ.get("FLEXSHAFT_KEEP_SCREENSHOT"):
        shutil.copy(screenshot, os.environ["FLEXSHAFT_KEEP_SCREENSHOT"])
