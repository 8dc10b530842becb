"""``compare``: the tuned FMC design against the current segmented aluminium driveline.

One comparison of the two embedded designs (a session fixture, tests/conftest.py: about 11 s of
CPU, shared with tests/test_reproduction.py) feeds every test: both
verdicts pass, the inventories match the design files (tube masses from ρ A L by hand), the
dataset has both designs, and the report folder is one self-contained page whose figures all
decode (and render in headless Chromium when it is installed).
"""

from __future__ import annotations

import base64
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.comparison import PART_KINDS, Comparison, driveline_inventory
from flexshaft.design import design_from_dict, embedded_design

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def comparison(embedded_comparison) -> Comparison:
    """``compare()`` of the two embedded designs (tests/conftest.py: computed once per session,
    tests/test_reproduction.py judges the tuned design's verdict from the same run)."""
    return embedded_comparison


@pytest.fixture(scope="module")
def report(comparison, tmp_path_factory) -> Path:
    from flexshaft.report.compare import write_compare_report

    folder = tmp_path_factory.mktemp("compare")
    return write_compare_report(comparison, folder)


def tube_mass(density, outer, wall, length):
    return density * math.pi * (outer**2 - (outer - 2 * wall) ** 2) / 4 * length


def test_both_embedded_drivelines_pass_their_requirements(comparison):
    tuned, current = comparison.runs
    assert comparison.labels == ("tuned", "current")
    assert tuned.verdict.passed and current.verdict.passed, (tuned.verdict.summary, current.verdict.summary)
    assert current.verdict.check("metal_strength").status == "pass"
    assert current.verdict.check("coupling_angle").status == "pass"
    assert current.verdict.check("tsai_wu").status == "not evaluated"  # no plies in aluminium
    assert tuned.verdict.check("tsai_wu").status == "pass"
    assert comparison.check("coupling_angle", 0) is None  # the one-piece shaft has no couplings
    keys = comparison.check_keys
    assert keys.index("metal_strength") == keys.index("tsai_wu") + 1 and keys[-1] == "coupling_angle"


def test_inventories_match_the_design_files(comparison):
    fmc, aluminium = comparison.inventories
    assert fmc.count == {"segments": 1, "couplings": 0, "hangers": 2, "dampers": 0, "actuators": 2}
    assert aluminium.count == {"segments": 5, "couplings": 4, "hangers": 4, "dampers": 1, "actuators": 0}
    # tube masses by hand: FMC 1650 kg/m³, 101.6 x 3.75 mm over 8.05 m; 6061-T6 2700 kg/m³, 101.6 x 1.651 mm
    assert fmc.mass["segments"] == pytest.approx(tube_mass(1650.0, 0.1016, 0.00375, 8.05), rel=1e-12)
    assert aluminium.mass["segments"] == pytest.approx(tube_mass(2700.0, 0.1016, 1.651e-3, 8.05), rel=1e-12)
    assert aluminium.mass["couplings"] == pytest.approx(4 * 1.0)
    assert aluminium.mass["hangers"] == pytest.approx(4 * 1.4) and aluminium.mass["dampers"] == pytest.approx(1.2)
    assert fmc.mass["actuators"] == pytest.approx(2 * 7.0) and fmc.mass["hangers"] == pytest.approx(2 * 1.4)
    assert not fmc.mass_not_given and not aluminium.mass_not_given
    assert fmc.total_count == 5 and aluminium.total_count == 14


def test_inventory_roles_and_missing_masses():
    """A gearbox bearing is not a driveline part; a part without a mass is listed."""
    data = {
        "name": "t",
        "materials": {"al": {"kind": "isotropic", "E": 70e9, "G": 26e9, "density": 2700.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
        },
        "bearings": [
            {"name": "g", "kind": "contact", "role": "gearbox", "x": 2.0, "stiffness": {"v": 1e8, "w": 1e8}},
            {"name": "h", "kind": "contact", "x": 0.9, "stiffness": {"v": 1e8, "w": 1e8}, "mass": 2.0},
            {"name": "d", "kind": "contact", "role": "damper", "x": 1.5, "damping": {"v": 10.0}, "stiffness": {}},
        ],
        "couplings": [
            {
                "name": "c",
                "x": 1.0,
                "angular_stiffness": 10.0,
                "axial_stiffness": "rigid",
                "torsional_stiffness": "rigid",
            }
        ],
        "operating": {"speed_rpm": 3000.0, "power": 1e3},
    }
    inventory = driveline_inventory(build_model(design_from_dict(data)))
    assert inventory.count == {"segments": 2, "couplings": 1, "hangers": 1, "dampers": 1, "actuators": 0}
    assert inventory.mass["hangers"] == 2.0
    assert inventory.mass_not_given == ("coupling c", "damper d")


def test_metrics_and_dataset(comparison):
    metrics = {m.key: m for m in comparison.metrics()}
    assert metrics["count_total"].values == (5.0, 14.0)
    assert metrics["coupling_angle"].values[0] is None and metrics["coupling_angle"].values[1] > 0
    assert metrics["whirl_onset"].lower_bounds == (True, True)  # stable up to 1.5 x the operating speed
    ds = comparison.to_dataset()
    assert ds.sizes["design"] == 2 and list(ds["part_kind"].values) == list(PART_KINDS)
    np.testing.assert_array_equal(ds["part_count"].sel(design="current").values, [5, 4, 4, 1, 0])
    status = dict(zip(ds["check"].values, ds["check_status"].sel(design="tuned").values))
    meanings = ds["check_status"].attrs["flag_meanings"].split()
    assert meanings[status["coupling_angle"]] == "not_listed"
    assert meanings[status["tsai_wu"]] == "pass"


def test_report_is_one_page_whose_figures_decode(report, comparison):
    text = report.read_text(encoding="utf-8")
    images = re.findall(r'<img src="data:image/png;base64,([^"]+)"', text)
    assert len(images) == 5
    for encoded in images:
        data = base64.b64decode(encoded, validate=True)
        assert data.startswith(PNG)
        width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
        assert width > 300 and height > 200
    assert "http://" not in text and "https://" not in text
    for label in comparison.labels:
        assert f"{label} status" in text
    data = json.loads((report.parent / "results.json").read_text())
    assert set(data["designs"]) == {"tuned", "current"}
    assert (report.parent / "comparison.nc").is_file()
    for stem in (
        "compare_campbell",
        "compare_spinup",
        "compare_safety_factor",
        "compare_static_deflection",
        "compare_mass",
    ):
        assert (report.parent / f"{stem}.png").is_file() and (report.parent / f"{stem}.svg").is_file()


def test_report_renders_in_headless_chromium(report, tmp_path):
    from chromium_probe import chromium_or_skip, image_load_title

    chromium = chromium_or_skip()
    assert image_load_title(chromium, report, tmp_path) == "IMAGES-OK:5"


def test_cli_compare_writes_the_report(comparison, tmp_path, monkeypatch):
    """`flexshaft compare` with no argument compares tuned with current (the analysis itself is
    the module's comparison, so that the test does not run it twice)."""
    from typer.testing import CliRunner

    import flexshaft.comparison as module
    from flexshaft.cli import app

    calls = []

    def fake(a, b, labels=None, progress=None):
        calls.append((a.name, b.name, labels))
        return comparison

    monkeypatch.setattr(module, "compare", fake)
    out = tmp_path / "cmp"
    result = CliRunner().invoke(app, ["compare", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert calls == [(embedded_design("tuned").name, embedded_design("current").name, ("tuned", "current"))]
    assert (out / "report.html").is_file()
    assert "parts: total" in result.output and "current: PASS" in result.output


def test_an_assessment_goes_in_as_it_is(comparison, monkeypatch):
    """A design already assessed at the comparison's resolution is taken as it is (the tutorial
    compares its assessment ``a`` with the baseline): nothing is assessed again, and the pair
    holds the same assessments, inventories and temperatures as the comparison of the two
    designs. An assessment at another resolution is refused before anything is computed, naming
    the argument and both resolutions."""
    import flexshaft.comparison as module
    from flexshaft.resolution import REPORT, SCREENING

    def no_assessment(*args, **kwargs):
        raise AssertionError("assess() must not be called for an assessment")

    monkeypatch.setattr(module, "assess", no_assessment)
    tuned, current = comparison.runs
    pair = module.compare(tuned, current, labels=comparison.labels, resolution=REPORT)
    assert pair.runs[0] is tuned and pair.runs[1] is current
    assert pair.inventories == comparison.inventories
    assert pair.boom_temperatures == comparison.boom_temperatures
    with pytest.raises(ValueError, match=r"design_b: an assessment at the report resolution .* at the screening"):
        module.compare("tuned", current, resolution=SCREENING)
