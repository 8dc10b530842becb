"""What the thermal analyses refuse in a schema-valid design's ``[thermal]`` table.

The schema bounds each field on its own; some combinations pass the bounds and are then
refused by a thermal analysis. :func:`thermal_guards` evaluates what those analyses evaluate
first, cheaply, and returns the problems, each naming the fields that set it:

* the tailboom's hover and parked skin temperatures, whose film temperatures must stay within
  the air properties' 200-600 K (an ambient of 176 °C with 1e4 W/m² of sun, or a sky at
  400 °C, have no such skin temperature);
* the shaft's air (the boom's hover skin temperature, or the ambient without a tailboom),
  where the spinning shaft's convection is evaluated;
* the matrix temperature law over the self-heating's range, from the shaft's air to the
  allowable temperature, checked at both ends in either order: the ply must stay valid there
  (a reference of 400 °C with θ_E = 5 K multiplied E_T by 1e31 at the shaft's air and made the
  ply indefinite). The law is monotone (θ_E ≥ 5 K), so the ends bound the range. An allowable
  below the air, which the self-heating never reaches (it stops at once as a runaway), is
  checked too: a law that makes the ply invalid at the matrix's own allowable contradicts the
  material data, whatever the air.
* a lamina's own temperature table, which replaces the law for it as in every analysis
  (:func:`~flexshaft.thermal.matrix.matrix_law_for`): the table is not extrapolated, so it
  must cover the self-heating's range (the schema makes it reach the allowable; the shaft's
  air may lie below its first row), and the ply must stay valid at the range's ends and at
  every row inside it. Between rows E_T and E_L are log-linear in T, so ν_LT² E_T/E_L is
  monotone there and the ends and the rows bound it; the moduli stay positive by
  construction.

With :func:`flexshaft.analyses.preflight.model_guards` (the model's build checks and the solves
every command starts from) it is what ``flexshaft check`` needs so that a design it accepts
runs: ``model_guards(design) + thermal_guards(design)``. The thermal layer builds no model, so
the two are joined above it.
"""

from __future__ import annotations

from typing import Any

from flexshaft.design.problems import Problem

__all__ = ["thermal_guards"]

_ENVIRONMENT = (
    "thermal.ambient_temperature_c",
    "sky_temperature_c",
    "solar_constant",
    "solar_fraction",
    "solar_area_fraction",
    "emissivity",
    "solar_absorptivity",
)


def thermal_guards(design: Any) -> list[Problem]:
    """Problems of the design's ``[thermal]`` table that only its evaluation shows (see the
    module docstring); empty when the thermal analyses can run."""
    import numpy as np

    from flexshaft.laminate import Lamina, Laminate, equivalent_moduli
    from flexshaft.thermal.air import AIR_TEMPERATURE_RANGE
    from flexshaft.thermal.analysis import shaft_air_temperature
    from flexshaft.thermal.matrix import matrix_law_for
    from flexshaft.thermal.options import thermal_options
    from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperatures

    options = thermal_options(design.thermal)
    if design.tailboom is not None:
        try:
            tailboom_temperatures(
                boom_equivalent_diameter(design.tailboom), options.environment, options.boom_convection
            )
        except ValueError as error:
            return [Problem("thermal", f"{error} ({', '.join(_ENVIRONMENT)})")]
    air = shaft_air_temperature(design.tailboom, options)
    low, high = AIR_TEMPERATURE_RANGE
    if not low <= air <= high:
        return [
            Problem(
                "thermal",
                f"the shaft's air (the tailboom's hover skin temperature) would be {air:.6g} K, outside the "
                f"{low:g}-{high:g} K where the air properties are evaluated ({', '.join(_ENVIRONMENT)})",
            )
        ]
    problems = []
    for name, material in design.materials.items():
        if material.kind != "lamina" or not _used(design, name):
            continue
        law = matrix_law_for(material, options.matrix_law)
        lamina = Lamina.from_loss_factors(
            E_L=material.E_L,
            E_T=material.E_T,
            G_LT=material.G_LT,
            nu_LT=material.nu_LT,
            density=material.density,
            loss_E_L=material.loss_E_L,
            loss_E_T=material.loss_E_T,
            loss_G_LT=material.loss_G_LT,
        )
        ends = sorted({min(air, law.allowable_temperature), max(air, law.allowable_temperature)})
        temperatures = ends
        if law.table is not None:
            rows = law.table.temperatures
            field = f"materials.{name}.temperature_table"
            if not (rows[0] <= ends[0] and ends[-1] <= rows[-1]):
                problems.append(
                    Problem(
                        f"{field}.temperature_c",
                        f"must cover the self-heating's range {ends[0]:.6g}-{ends[-1]:.6g} K (the shaft's air and "
                        f"the allowable temperature) for material {name!r}; the table runs from {rows[0]:.6g} to "
                        f"{rows[-1]:.6g} K and is not extrapolated ({', '.join(_ENVIRONMENT)} set the air)",
                    )
                )
                continue
            temperatures = sorted({*ends, *(t for t in rows if ends[0] < t < ends[-1])})
        for temperature in temperatures:
            try:
                equivalent_moduli(Laminate(np.array([0.0]), np.array([1.0]), law.lamina(lamina, temperature)))
            except ValueError as error:
                if law.table is not None:
                    problems.append(
                        Problem(
                            f"materials.{name}.temperature_table",
                            f"makes material {name!r} an invalid ply at {temperature:.6g} K, within the "
                            f"self-heating's range {ends[0]:.6g}-{ends[-1]:.6g} K (the shaft's air and the allowable "
                            f"temperature): {error}",
                        )
                    )
                    break
                problems.append(
                    Problem(
                        "thermal.matrix_reference_temperature_c",
                        f"the matrix temperature law makes material {name!r} an invalid ply at "
                        f"{temperature:.6g} K, an end of the self-heating's range (the shaft's air and the allowable "
                        f"temperature): {error}; thermal.matrix_reference_temperature_c and "
                        "thermal.matrix_modulus_decay set it",
                    )
                )
                break
    return problems


def _used(design: Any, material: str) -> bool:
    """Whether some shaft tube is made of ``material``."""
    return any(tube.material == material for tube in design.shaft.tubes)
