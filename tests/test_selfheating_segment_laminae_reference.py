"""Self-heating on a shaft of two laminae: each element follows its own lamina's temperature
table, or the ``[thermal]`` law when its lamina has none, never the other lamina's table.

The embedded baseline's shaft split at 4 m into two segments, the aft one of a second lamina,
on a coarse mesh. A temperature table whose rows all hold the lamina's own values makes its
moduli independent of temperature (the table wins over the law and is interpolated between
rows: constant rows give a constant), while the law softens E_T and G_LT by
exp(−(T − T_ref)/θ_E) (baseline θ_E = 40 K, T_ref = 20 °C: by e⁻¹ at 60 °C). So between 20 °C
and 60 °C a tabled lamina's elements keep their complex moduli exactly (the same lamina at the
same rounded temperature gives the same numbers) and a law lamina's change, whichever lamina is
the ``[shaft]``'s. (Before: every element followed the ``[shaft]`` lamina's table or its absence.)
"""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from flexshaft.assembly import build_model
from flexshaft.design import baseline_text, loads_design
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.selfheating import _element_moduli
from flexshaft.units import celsius_to_kelvin

ROWS = [-60.0, -40.0, -20.0, 0.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0]


def _design(tabled: str, one_segment: bool = False):
    """The baseline with a second lamina ``t700_other`` on the aft segment (x > 4 m), or on the
    shaft's one segment (``one_segment``: the ``[shaft]`` lamina then used by no element);
    ``tabled`` names the lamina that carries a constant table (the other has none)."""
    text = baseline_text()
    assert "shaft_elements = 36" in text
    text = text.replace("shaft_elements = 36", "shaft_elements = 8", 1)
    start = text.index("[materials.t700_adiprene]")
    end = text.index("[materials.al6061_t6]")
    block = text[start:end]
    table_start = block.index("[materials.t700_adiprene.temperature_table]")
    plain = block[:table_start]
    plain = plain[: plain.rindex("\n# Storage moduli")] + "\n\n"  # the lamina without its table
    constant = (
        "[materials.NAME.temperature_table]\n"
        f"temperature_c = {ROWS}\n"
        f"E_T = {[0.10e9] * len(ROWS)}\nG_LT = {[0.10e9] * len(ROWS)}\n"
        f"loss_E_T = {[0.12] * len(ROWS)}\nloss_G_LT = {[0.12] * len(ROWS)}\n\n"
    )
    laminae = ""
    for name in ("t700_adiprene", "t700_other"):
        laminae += plain.replace("[materials.t700_adiprene]", f"[materials.{name}]", 1)
        if name == tabled:
            laminae += constant.replace("NAME", name)
    text = text[:start] + laminae + text[end:]
    shaft = re.search(r"\n\[shaft\]\n.*?(?=\n\[)", text, re.S)
    assert shaft is not None
    segments = (
        '\n[[shaft.segments]]\nname = "fore"\nx_start = 0.0\nx_end = 4.0\n'
        '[[shaft.segments]]\nname = "aft"\nx_start = 4.0\nx_end = 8.05\nmaterial = "t700_other"\n'
        'layup = "(55/-55/0/0)s"\n'
    )
    if one_segment:
        segments = (
            '\n[[shaft.segments]]\nname = "all"\nx_start = 0.0\nx_end = 8.05\nmaterial = "t700_other"\n'
            'layup = "(55/-55/0/0)s"\n'
        )
    return loads_design(text[: shaft.end()] + segments + text[shaft.end() :])


@pytest.mark.parametrize("tabled", ["t700_adiprene", "t700_other"], ids=["shaft-tabled", "segment-tabled"])
def test_each_element_follows_its_own_laminas_table_or_the_law(tabled):
    design = _design(tabled)
    model = build_model(design)
    assert [s.material for s in model.segments] == ["t700_adiprene", "t700_other"]
    options = thermal_options(design.thermal, design.shaft_material)
    law = options.matrix_law
    mid = 0.5 * (model.dofs.shaft_element_x[:, 0] + model.dofs.shaft_element_x[:, 1])
    aft = mid > 4.0
    assert 0 < aft.sum() < aft.size
    n = aft.size
    E20, G20 = _element_moduli(model, law, np.full(n, celsius_to_kelvin(20.0)))
    E60, G60 = _element_moduli(model, law, np.full(n, celsius_to_kelvin(60.0)))
    table_side = ~aft if tabled == "t700_adiprene" else aft
    # the tabled lamina's elements: its constant table, the same moduli at both temperatures
    assert np.array_equal(E60[table_side], E20[table_side]) and np.array_equal(G60[table_side], G20[table_side])
    # the law's lamina: E_T, G_LT by e^-1 at 60 °C soften the (fibre-dominated) laminate's axial
    # and shear moduli by a little (measured: E by 0.12 %, G by 0.3 %), far above round-off
    law_side = ~table_side
    assert np.all(E60[law_side].real < (1 - 5e-4) * E20[law_side].real)
    assert np.all(G60[law_side].real < (1 - 1e-3) * G20[law_side].real)


@pytest.mark.parametrize("tabled", ["t700_adiprene", "t700_other"], ids=["shaft-tabled", "segment-tabled"])
def test_a_one_segment_shaft_of_another_lamina_follows_that_lamina(tabled):
    """One [[shaft.segments]] entry of ``t700_other`` over the whole shaft: every element is of
    that lamina (the [shaft]'s is used by none), so its table, or the law, sets every element."""
    design = _design(tabled, one_segment=True)
    model = build_model(design)
    assert [s.material for s in model.segments] == ["t700_other"]
    law = thermal_options(design.thermal, design.shaft_material).matrix_law
    n = len(model.dofs.shaft_element_x)
    E20, G20 = _element_moduli(model, law, np.full(n, celsius_to_kelvin(20.0)))
    E60, G60 = _element_moduli(model, law, np.full(n, celsius_to_kelvin(60.0)))
    if tabled == "t700_other":  # its constant table: unchanged
        assert np.array_equal(E60, E20) and np.array_equal(G60, G20)
    else:  # no table of its own: the law, not the unused [shaft] lamina's table
        assert np.all(E60.real < (1 - 5e-4) * E20.real) and np.all(G60.real < (1 - 1e-3) * G20.real)


def test_laminae_of_equal_values_keep_their_own_laws():
    """Both laminae without a table and of equal values (the model builds one tube object for
    both), the caller's law carrying a constant table of its own (``options.matrix_law``): the
    ``[shaft]`` lamina's elements follow that table (unchanged between 20 and 60 °C), the other
    lamina's the law without it (softened), whichever element is computed first."""
    from flexshaft.thermal.matrix import LaminaTable

    design = _design("neither")
    model = build_model(design)
    tubes = [s.properties for s in model.segments]
    assert tubes[0] is tubes[1]  # the premise: one tube object for the two laminae
    table = LaminaTable(
        tuple(celsius_to_kelvin(t) for t in ROWS),
        tuple((name, (value,) * len(ROWS)) for name, value in (("E_T", 0.10e9), ("G_LT", 0.10e9))),
    )
    law = dataclasses.replace(thermal_options(design.thermal).matrix_law, table=table)
    mid = 0.5 * (model.dofs.shaft_element_x[:, 0] + model.dofs.shaft_element_x[:, 1])
    aft = mid > 4.0
    n = aft.size
    E20, _ = _element_moduli(model, law, np.full(n, celsius_to_kelvin(20.0)))
    E60, _ = _element_moduli(model, law, np.full(n, celsius_to_kelvin(60.0)))
    assert np.array_equal(E60[~aft], E20[~aft])
    assert np.all(E60[aft].real < (1 - 5e-4) * E20[aft].real)
