"""The thermal preflight checks the matrix law at both ends of the self-heating's range.

:func:`flexshaft.thermal.preflight.thermal_guards` must find a ply the matrix temperature law
makes invalid at either end of the self-heating's range, the shaft's air and the allowable
temperature, in either order (its module docstring: an allowable below the air, which the
self-heating itself never reaches, contradicts the material data and is checked too). The law
(docs/model.md, ``[thermal] matrix_*``) scales E_T by f = exp(-(T - T_ref)/theta_E). A
plane-stress orthotropic ply is positive definite only while its normal compliance [[1/E_L,
-nu_LT/E_L], [-nu_LT/E_L, 1/E_T]] has a positive determinant, (1 - nu_LT^2 E_T/E_L)/(E_L E_T) >
0, i.e. nu_LT^2 E_T / E_L < 1 (derived here).

Worked by hand for the baseline lamina t700_adiprene (E_L = 115 GPa, E_T = 0.1 GPa, nu_LT =
0.35), with T_ref = 0 degC and theta_E = 5 K: at an allowable temperature of -50 degC, f = e^10
= 22026 and nu_LT^2 E_T f / E_L = 0.1225 * 0.1e9 * 22026 / 115e9 = 2.35 > 1: invalid. At the
shaft's air (the boom's hover skin, above the 20 degC ambient set here, so f < 1) the ply is
softer than at T_ref and valid (the limit would need air below -45.7 degC). The law is therefore
invalid only at the allowable end, here below the air: a check at the air alone misses it.
"""

from __future__ import annotations

import copy
import math

from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.preflight import thermal_guards

E_L, E_T, NU_LT = 115e9, 0.1e9, 0.35


def baseline_with(**thermal) -> object:
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    for material in data["materials"].values():
        material.pop("temperature_table", None)  # the assumed law, not a table
    data["envelope"] = None  # the [thermal] table's own checks (this law fails at the hot soak too)
    data["thermal"].update(ambient_temperature_c=20.0, **thermal)
    return design_from_dict(data)


def test_a_law_invalid_only_at_the_allowable_temperature_is_reported():
    lamina = embedded_design("baseline").materials["t700_adiprene"]
    assert (lamina.E_L, lamina.E_T, lamina.nu_LT) == (E_L, E_T, NU_LT)  # the values worked above
    factor = math.exp(50.0 / 5.0)
    assert NU_LT**2 * E_T * factor / E_L > 1.0  # invalid at -50 degC
    assert NU_LT**2 * E_T * math.exp(45.0 / 5.0) / E_L < 1.0  # still valid at -45 degC (air is far above)

    design = baseline_with(matrix_reference_temperature_c=0.0, matrix_modulus_decay=5.0, allowable_temperature_c=-50.0)
    problems = thermal_guards(design)
    assert len(problems) == 1
    assert problems[0].path == "thermal.matrix_reference_temperature_c"
    assert "'t700_adiprene'" in problems[0].message and "at 223.15 K" in problems[0].message

    # the same law with the allowable temperature above the air: both ends valid, no problem
    fine = baseline_with(matrix_reference_temperature_c=0.0, matrix_modulus_decay=5.0, allowable_temperature_c=100.0)
    assert thermal_guards(fine) == []
