"""What the verdict's recipe refuses before it computes anything, against the documented rules.

* **The "worst" imbalance placement's bays** (docs/limits.md, section 5): "The ``"worst"``
  imbalance placement enumerates all 2^(bays−1) sign patterns of the bay forces; it is limited
  to 10 bays (512 load cases ...)", and "``build_model`` applies the ``"model"`` estimate; ...
  ``assess`` the ``"assess"`` one at its resolution". So ``fs.assess`` of a design with 12
  bearings at distinct stations (11 bays, 2^10 = 1024 load cases) is refused with a DesignError
  naming ``loads.imbalance_placement`` before its first analysis, while 11 bearings (10 bays,
  512 cases, the documented maximum) reach it. The estimate of building the model alone
  (``"model"``) does not apply the rule: the model itself is not too large to build.
* **Every refused envelope point** (docs/limits.md, section 2, "Checks of several numbers"):
  ``envelope_problems`` lists "every ``[envelope]`` point the verdict would refuse (... a law
  taking a lamina out of the schema's bounds there ...)". Without a temperature table the
  baseline's lamina follows the matrix law E_T = G_LT = 0.1 GPa · exp(−(T − T_ref)/θ_E); with
  T_ref = 0 °C and θ_E = 5 K it falls below the schema's 1 kPa above
  T = 5 K · ln(0.1 GPa / 1 kPa) = 5 ln 1e5 = 57.56 °C (derived here). The points give their
  material temperature (``material_temperature = "given"``) on either side of it, 0.64 K
  above and 0.56 K below; by hand, at 58.2 °C E_T = 1e8 · e^(−11.64) = 1e8 · 8.807e-6 =
  880.7 Pa, refused, and at 57.0 °C E_T = 1e8 · e^(−11.4) = 1e8 · 1.1195e-5 = 1119.5 Pa,
  accepted: 12 % either side of the bound, no rounding decides (the matrix loss factors,
  0.12 · e^((T − T_ref)/θ_η) with θ_η = 60 K, are at most 0.12 · e^(58.2/60) = 0.32, below
  the schema's 1: the law takes nothing else out of bounds).
  An envelope of 58.2, 57.0 and 58.2 °C is refused at points 0 and 2, each named, not at 1.

No analysis is run (the first one is replaced by a stand-in that stops the recipe); each design
is validated from a dictionary: a few tens of ms of CPU in all.
"""

from __future__ import annotations

import copy
import tomllib

import pytest

import flexshaft as fs
import flexshaft.verdict.assess as assess_module
from flexshaft.design import DesignError, design_from_dict
from flexshaft.validation.runner import design_text
from flexshaft.verdict.assess import envelope_problems

#: The validation's Jeffcott rotor: a 1 m shaft of 8 elements, pinned ends, no envelope.
JEFFCOTT = tomllib.loads(design_text("jeffcott_internal_damping.toml"))


class _FirstAnalysis(Exception):
    """Raised by the stand-in for the first analysis: the recipe got past its refusals."""


def _worst_placement_with_bearings(count: int):
    """The Jeffcott rotor with ``count`` bearings at distinct stations on its 1 m span (count − 1
    bays) and the "worst" imbalance placement."""
    data = copy.deepcopy(JEFFCOTT)
    template = data["bearings"][0]
    data["bearings"] = [dict(template, name=f"b{k}", x=k / (count - 1)) for k in range(count)]
    data.setdefault("loads", {})["imbalance_placement"] = "worst"
    return design_from_dict(data)


def test_assess_refuses_more_than_ten_bays_of_the_worst_placement(monkeypatch):
    def first_analysis(*args, **kwargs):
        raise _FirstAnalysis

    monkeypatch.setattr(assess_module, "analyse_point", first_analysis)
    # 11 bearings, 10 bays, 2^9 = 512 load cases: accepted, the recipe reaches its first analysis
    with pytest.raises(_FirstAnalysis):
        fs.assess(_worst_placement_with_bearings(11), fs.SCREENING)
    # 12 bearings, 11 bays, 2^10 load cases: refused before it, naming the placement
    with pytest.raises(DesignError, match=r"loads\.imbalance_placement"):
        fs.assess(_worst_placement_with_bearings(12), fs.SCREENING)


def test_every_refused_envelope_point_is_listed():
    data = fs.baseline_design().model_dump()
    for material in data["materials"].values():
        material.pop("temperature_table", None)  # the matrix law then sets the lamina
    data["thermal"].update(matrix_reference_temperature_c=0.0, matrix_modulus_decay=5.0)
    data["envelope"] = {
        "points": [
            {"name": "hot_a", "material_temperature": "given", "material_temperature_c": 58.2},
            {"name": "just_below", "material_temperature": "given", "material_temperature_c": 57.0},
            {"name": "hot_b", "material_temperature": "given", "material_temperature_c": 58.2},
        ]
    }
    problems = envelope_problems(design_from_dict(data))
    assert [p.path for p in problems] == ["envelope.points[0]", "envelope.points[2]"]
    assert "'hot_a'" in problems[0].message and "'hot_b'" in problems[1].message
