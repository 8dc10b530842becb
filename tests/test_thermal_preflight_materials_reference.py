"""The thermal preflight checks the plies the shaft is made of: a segment's own, never an unused one.

:func:`flexshaft.thermal.preflight.thermal_guards` evaluates the matrix temperature law at the
ends of the self-heating's range on the laminae some shaft tube uses (its ``_used``: any tube of
``design.shaft.tubes``, a segment's own material included). The law (docs/model.md,
``[thermal] matrix_*``) scales E_T by f = exp(-(T - T_ref)/theta_E); a plane-stress orthotropic
ply is positive definite only while nu_LT^2 E_T f / E_L < 1 (the determinant of its normal
compliance, derived in tests/test_thermal_preflight_allowable_reference.py).

Worked by hand, with T_ref = 0 degC, theta_E = 5 K and the allowable at -50 degC (f = e^10 =
22026; the shaft's air is far warmer, f < 1 there):

* the baseline lamina t700_adiprene (E_L = 115 GPa, E_T = 0.1 GPa, nu_LT = 0.35):
  0.1225 * 0.1e9 * 22026 / 115e9 = 2.35 > 1, invalid at the allowable;
* with the allowable at -30 degC (f = e^6 = 403.4): 0.1225 * 0.1e9 * 403.4 / 115e9 = 0.043,
  valid; a stiffer-matrix ply (E_T = 5 GPa, otherwise the same) gives
  0.1225 * 5e9 * 403.4 / 115e9 = 2.15 > 1, invalid.

So a shaft of aluminium whose second segment is t700_adiprene must be reported at -50 degC
(the segment's ply is the shaft's), and a design that only lists the stiff ply, no tube made
of it, must not be refused for it at -30 degC.
"""

from __future__ import annotations

import copy
import math

from flexshaft.design import design_from_dict, embedded_design
from flexshaft.thermal.preflight import thermal_guards

E_L, E_T, NU_LT = 115e9, 0.1e9, 0.35
STIFF_E_T = 5e9
LAYUP = "(55/-55/0/0)s"


def baseline_data(**thermal) -> dict:
    data = copy.deepcopy(embedded_design("baseline").model_dump())
    for material in data["materials"].values():
        material.pop("temperature_table", None)  # the assumed law, not a table
    data["envelope"] = None  # the [thermal] table's own checks only
    data["thermal"].update(ambient_temperature_c=20.0, matrix_reference_temperature_c=0.0, matrix_modulus_decay=5.0)
    data["thermal"].update(thermal)
    return data


def test_the_hand_numbers():
    lamina = embedded_design("baseline").materials["t700_adiprene"]
    assert (lamina.E_L, lamina.E_T, lamina.nu_LT) == (E_L, E_T, NU_LT)
    assert NU_LT**2 * E_T * math.exp(10.0) / E_L > 1.0  # t700 invalid at -50 degC
    assert NU_LT**2 * E_T * math.exp(6.0) / E_L < 1.0  # t700 valid at -30 degC
    assert NU_LT**2 * STIFF_E_T * math.exp(6.0) / E_L > 1.0  # the stiff ply invalid at -30 degC


def test_a_segments_own_lamina_is_checked():
    data = baseline_data(allowable_temperature_c=-50.0)
    shaft = data["shaft"]
    shaft.update(material="al6061_t6", layup=None)
    half = 0.5 * (shaft["x_start"] + shaft["x_end"])
    shaft["segments"] = (
        {"name": "metal", "x_start": shaft["x_start"], "x_end": half},
        {"name": "fmc", "x_start": half, "x_end": shaft["x_end"], "material": "t700_adiprene", "layup": LAYUP},
    )
    problems = thermal_guards(design_from_dict(data))
    assert len(problems) == 1
    assert problems[0].path == "thermal.matrix_reference_temperature_c"
    assert "'t700_adiprene'" in problems[0].message and "at 223.15 K" in problems[0].message


def test_a_lamina_no_tube_uses_is_not_checked():
    data = baseline_data(allowable_temperature_c=-30.0)
    stiff = dict(data["materials"]["t700_adiprene"], E_T=STIFF_E_T)
    stiff.pop("G_23", None)
    data["materials"]["stiff_unused"] = stiff
    assert thermal_guards(design_from_dict(data)) == []
    # the same ply as the shaft's is reported: the law is invalid for it at -30 degC
    data["shaft"]["material"] = "stiff_unused"
    problems = thermal_guards(design_from_dict(data))
    assert len(problems) == 1 and "'stiff_unused'" in problems[0].message and "at 243.15 K" in problems[0].message
