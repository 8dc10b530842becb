"""The design's ``[thermal]`` table reaches the thermal computations: no dead keys, one damping
physics (``[analysis] internal_damping``), unit conversions at the edge, and a data-only design
layer that the thermal package reads but never builds from."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

import flexshaft as fs
from flexshaft.design import DesignError, baseline_text, loads_design
from flexshaft.design.thermal_schema import Thermal
from flexshaft.thermal.heat import heat_sources
from flexshaft.thermal.options import ThermalOptions, environment_from, matrix_law_from, thermal_options
from flexshaft.thermal.study import thermal_results
from flexshaft.units import ZERO_CELSIUS, celsius_to_kelvin, kelvin_to_celsius

SRC = Path(fs.__file__).parent


@pytest.fixture(scope="module")
def baseline():
    design = fs.baseline_design()
    return design, fs.build_model(design)


# ------------------------------------------------------------------ no dead keys
#: One perturbation per [thermal] field, each a plausible alternative value.
PERTURBATIONS = {
    "rotorcraft_mass": 8000.0,
    "rotor_radius": 8.0,
    "emissivity": 0.9,
    "solar_absorptivity": 0.8,
    "solar_constant": 1200.0,
    "solar_fraction": 0.8,
    "solar_zenith_deg": 30.0,
    "sky_temperature_c": 0.0,
    "air_density": 1.1,
    "ambient_temperature_c": 30.0,
    "solar_area_fraction": 0.5,
    "boom_convection": "churchill_bernstein",
    "shaft_convection": "kendoush",
    "fibre_conductivity": 8.0,
    "transverse_conductivity": 1.0,
    "matrix_reference_temperature_c": 30.0,
    "matrix_modulus_decay": 20.0,
    "matrix_loss_growth": 30.0,
    "allowable_temperature_c": 90.0,
}


#: Keys of the assumed matrix law, which a lamina's temperature table replaces.
LAW_FIELDS = ("matrix_modulus_decay", "matrix_loss_growth")


def _outputs(design, model) -> dict[str, float]:
    r = thermal_results(design, model, self_heat=True)
    sh = r.self_heating
    return {
        "boom hover [K]": r.tailboom["hover"].temperature,
        "boom parked [K]": r.tailboom["parked"].temperature,
        "shaft rise, thesis loss [K]": r.shaft["thesis"].peak_rise,
        "shaft rise, rotating loss [K]": r.shaft["rotating"].peak_rise,
        "self-heating rise [K]": sh.max_temperature - sh.thermal.temperature.air_temperature,
        "max shaft temperature [K]": r.max_shaft_temperature,
        "allowable [K]": r.allowable_temperature,
        "margin [K]": r.temperature_margin,
    }


def test_every_thermal_field_is_perturbed():
    # A new [thermal] field must be added to PERTURBATIONS (and wired) before this passes.
    assert set(PERTURBATIONS) == set(Thermal.model_fields)


@pytest.fixture(scope="module")
def reference_outputs(baseline):
    return _outputs(*baseline)


@pytest.mark.parametrize("field", sorted(PERTURBATIONS))
def test_perturbing_a_thermal_field_changes_a_thermal_output(field, baseline, reference_outputs):
    # The computations are deterministic, so round-off differences are ~1e-15 relative; a change
    # above 1e-6 relative is the field acting. The smallest measured effect on the baseline is the
    # transverse ply conductivity on the shaft rise (2e-5 relative): conduction along the wall is
    # weak against the spinning shaft's convection (conduction length ~8 mm). Every field of the
    # table changes something on the baseline; none is listed as legitimately inert.
    # The law's two scales act where the shaft lamina has no temperature table (the table replaces
    # the law): they are perturbed on the baseline without its table.
    design, model = baseline
    if field in LAW_FIELDS:
        design = fs.with_overrides(design, {"materials.t700_adiprene.temperature_table": None})
        model = fs.build_model(design)
        reference_outputs = _outputs(design, model)
    perturbed = fs.with_overrides(design, {f"thermal.{field}": PERTURBATIONS[field]})
    assert getattr(perturbed.thermal, field) != getattr(design.thermal, field)
    out = _outputs(perturbed, model)
    changes = {k: abs(out[k] - v) / abs(v) for k, v in reference_outputs.items()}
    assert max(changes.values()) > 1e-6, f"{field} changed nothing: {changes}"


def test_loss_model_is_not_a_thermal_key():
    text = baseline_text().replace("[thermal]\n", '[thermal]\nloss_model = "thesis"\n')
    with pytest.raises(DesignError, match=r"thermal\.loss_model: unknown key"):
        loads_design(text)


# ------------------------------------------------------------------ one damping physics
def test_shaft_heat_follows_the_design_internal_damping(baseline):
    design, model = baseline
    assert design.analysis.internal_damping == "rotating"
    r = thermal_results(design, model)
    assert r.loss_model == "rotating"
    assert heat_sources(model).loss_model == "rotating"
    assert r.max_shaft_temperature == r.shaft["rotating"].max_temperature
    assert r.max_shaft_temperature_source == "reference_properties"

    thesis = fs.with_overrides(design, {"analysis.internal_damping": "thesis"})
    thesis_model = fs.build_model(thesis)
    assert heat_sources(thesis_model).loss_model == "thesis"
    rt = thermal_results(thesis, thesis_model)
    assert rt.loss_model == "thesis"
    assert rt.max_shaft_temperature == rt.shaft["thesis"].max_temperature
    # an explicit choice overrides the design's, for a comparison
    assert thermal_results(design, model, loss_model="thesis").loss_model == "thesis"


def test_loss_model_needs_a_design_or_an_explicit_choice(baseline):
    import dataclasses

    _, model = baseline
    bare = dataclasses.replace(model, design=None)
    with pytest.raises(ValueError, match="loss_model"):
        heat_sources(bare)
    with pytest.raises(ValueError, match="loss_model must be"):
        heat_sources(model, "magic")


# ------------------------------------------------------------------ allowable temperature
def test_allowable_temperature_drives_the_runaway_check_and_the_results(baseline):
    design, model = baseline
    ok = thermal_results(design, model, self_heat=True)
    assert ok.self_heating.status == "converged"
    assert ok.allowable_temperature_c == pytest.approx(100.0, abs=1e-12)
    assert ok.max_shaft_temperature_c == pytest.approx(kelvin_to_celsius(ok.max_shaft_temperature))
    assert ok.temperature_margin == pytest.approx(ok.allowable_temperature - ok.max_shaft_temperature)
    assert ok.max_shaft_temperature_source == "self_heating"
    # an allowable below the shaft's air (the boom's hover skin, 44 °C): no equilibrium below it
    cold = fs.with_overrides(design, {"thermal.allowable_temperature_c": 40.0})
    bad = thermal_results(cold, model, self_heat=True)
    assert bad.self_heating.status == "runaway"
    assert bad.temperature_margin < 0 and bad.self_heating.margin < 0
    assert bad.allowable_temperature == pytest.approx(celsius_to_kelvin(40.0))


# ------------------------------------------------------------------ conversions at the edge
def test_builders_convert_celsius_and_degrees_to_si():
    # Independent references: 0 °C = 273.15 K (SI definition); G = S_c f cos θ_s (eq. 2.58)
    # with cos 60° = 1/2 exactly.
    table = Thermal(
        ambient_temperature_c=0.0,
        sky_temperature_c=-10.0,
        solar_zenith_deg=60.0,
        matrix_reference_temperature_c=25.0,
        allowable_temperature_c=120.0,
    )
    env = environment_from(table)
    assert env.ambient_temperature == 273.15 and ZERO_CELSIUS == 273.15
    assert env.sky_temperature == pytest.approx(263.15, abs=1e-12)
    assert env.solar_irradiation == pytest.approx(0.5 * 1353.0, rel=1e-12)
    law = matrix_law_from(table)
    assert law.reference_temperature == pytest.approx(298.15, abs=1e-12)
    assert law.allowable_temperature == pytest.approx(393.15, abs=1e-12)
    opts = thermal_options(table)
    assert opts.allowable_temperature == law.allowable_temperature


def test_ply_conductivities_keep_their_directions():
    """k along the fibres and k across them reach the options each under its own name (a carbon
    ply conducts several times better along its fibres: swapping them changes the wall's axial
    conductivity by that factor)."""
    opts = thermal_options(Thermal(fibre_conductivity=8.0, transverse_conductivity=0.7))
    assert (opts.fibre_conductivity, opts.transverse_conductivity) == (8.0, 0.7)


def test_runtime_options_refuse_bad_values_naming_the_field():
    with pytest.raises(ValueError, match="boom_convection"):
        ThermalOptions(boom_convection="dittus_boelter")
    with pytest.raises(ValueError, match="fibre_conductivity"):
        ThermalOptions(fibre_conductivity=float("nan"))
    from flexshaft.thermal.matrix import MatrixTemperatureLaw

    with pytest.raises(ValueError, match="modulus_decay"):
        MatrixTemperatureLaw(modulus_decay=0.0)
    from flexshaft.thermal.environment import ThermalEnvironment

    with pytest.raises(ValueError, match="solar_area_fraction"):
        ThermalEnvironment(solar_area_fraction=1.5)


def test_baseline_ambient_follows_its_stated_source():
    # baseline.toml: ambient from Swinbank's clear-sky relation T_sky = 0.0552 T_amb^1.5
    # (Swinbank 1963; Duffie & Beckman eq. 3.9.2) at the thesis's T_sky = 285 K. The file rounds
    # T_amb to 0.1 K, so T_sky is reproduced within 0.1 K.
    env = thermal_options(fs.baseline_design().thermal).environment
    assert 0.0552 * env.ambient_temperature**1.5 == pytest.approx(env.sky_temperature, abs=0.1)


# ------------------------------------------------------------------ CLI edge
def test_thermal_command_reports_the_verdict_numbers():
    from flexshaft.cli import app

    result = CliRunner().invoke(app, ["thermal", "--json", "--loss-model", "thesis"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["loss_model"] == "thesis"
    assert data["allowable_temperature_c"] == 100.0
    assert data["max_shaft_temperature_c"] == pytest.approx(data["max_shaft_temperature_K"] - 273.15, abs=1e-3)
    assert data["temperature_margin_K"] > 0


# ------------------------------------------------------------------ layering
def _imports(path: Path) -> list[tuple[str, list[str]]]:
    """(module, imported names) of every import statement in a source file."""
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out += [(alias.name, []) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module:
            out.append((node.module, [alias.name for alias in node.names]))
    return out


def test_design_is_a_data_leaf_that_never_imports_the_physics():
    allowed = ("flexshaft.design", "flexshaft.units")  # the full layer check: tests/test_layers.py
    for path in sorted((SRC / "design").glob("*.py")):
        for module, _ in _imports(path):
            if module.startswith("flexshaft"):
                assert module.startswith(allowed), f"{path.name} imports {module}"


def test_thermal_never_loads_or_makes_designs_nor_imports_a_higher_layer():
    """The heat models take models and plain values; only thermal/study.py, the thermal study of
    a design, varies the design (its wall-thickness sweep) and builds its models."""
    higher = ("flexshaft.verdict", "flexshaft.sweep", "flexshaft.report", "flexshaft.cli", "flexshaft.design.io")
    makers = {"baseline_design", "load_design", "loads_design", "design_from_dict", "with_overrides", "build_model"}
    for path in sorted((SRC / "thermal").glob("*.py")):
        for module, names in _imports(path):
            assert not module.startswith(higher), f"thermal/{path.name} imports {module}"
            if path.name == "study.py":
                continue
            assert not makers & set(names), f"thermal/{path.name} imports {makers & set(names)} from {module}"
            if module == "flexshaft.design":
                pytest.fail(f"thermal/{path.name} imports the design package's loaders ({names})")


def test_zero_celsius_is_written_once():
    # 273.15 appears in the design, thermal and thermal-study sources only as the constant of
    # flexshaft.units; everything else converts with its functions.
    files = [*(SRC / "design").glob("*.py"), *(SRC / "thermal").glob("*.py"), SRC / "units.py"]
    hits = sorted(p.relative_to(SRC) for p in files if "273.15" in p.read_text())
    assert hits == [Path("units.py")]
