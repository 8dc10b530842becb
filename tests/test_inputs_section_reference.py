"""The report's inputs section states the design as the engineer wrote it: the title's numbers in
the units it names, and the table of values marked "assumed" or "calibrated" with each value
under "value", its marker under "marked" and the 1-based line an editor shows.

References (derived, by hand): a stand-in design with values chosen here, each title number
worked out with its unit factor written below; a four-line TOML text whose marked lines are
counted by hand. No model, no analysis: well under 0.1 s.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

from flexshaft.report.inputs import inputs_section, report_title


def _design(kinds: tuple[str, ...]) -> SimpleNamespace:
    """A stand-in design: Ø 101.6 mm × 3.75 mm wall, 4800 rpm, 150 kW, no tailboom."""
    return SimpleNamespace(
        shaft=SimpleNamespace(layup="(45/-45)s", material="T700/epoxy", outer_diameter=0.1016, wall_thickness=3.75e-3),
        bearings=[SimpleNamespace(kind=k) for k in kinds],
        tailboom=None,
        # the schema keeps the speed in rad/s: 4800 rpm = 4800 · 2π/60 = 502.6548 rad/s
        operating=SimpleNamespace(speed_rad_s=4800.0 * 2.0 * math.pi / 60.0, power=150.0e3),
    )


def test_the_title_states_each_number_in_the_unit_it_names():
    # Ø 0.1016 m · 1e3 = 101.6 mm; wall 3.75e-3 m · 1e3 = 3.75 mm; 502.6548 rad/s · 60/(2π) = 4800 rpm;
    # 150e3 W / 1e3 = 150 kW; one of the three bearings is active (singular "bearing")
    title = report_title(_design(("passive", "active", "passive")))
    assert title == (
        "(45/-45)s T700/epoxy shaft, Ø 101.6 mm × 3.75 mm wall, 4800 rpm, 150 kW, on rigid supports, 1 active bearing"
    )
    # two active of three: plural, and the count is of the active ones (not the other two)
    assert title_count(report_title(_design(("active", "passive", "active")))) == "2 active bearings"


def title_count(title: str) -> str:
    return title.rsplit(", ", 1)[1]


TEXT = """name = "stand-in"
[shaft]
outer_diameter = 0.1016  # m (assumed)
wall_thickness = 0.00375  # m, measured
loss_factor = 0.012  # calibrated to the test rig
"""


def test_the_marked_inputs_table_has_each_value_under_its_column_and_its_editor_line():
    """Lines 3 and 5 (1-based, as an editor counts them) are marked; line 4's comment marks
    nothing."""
    section = inputs_section(None, TEXT, "stand-in.toml")
    (table,) = section.tables
    assert list(table.columns) == ["key", "value", "marked", "comment", "line"]
    assert [list(r) for r in table.rows] == [
        ["shaft.outer_diameter", "0.1016", "assumed", "m (assumed)", 3],
        ["shaft.loss_factor", "0.012", "calibrated", "calibrated to the test rig", 5],
    ]
    assert section.paragraphs[1].startswith("2 input values are marked")
    (block,) = section.blocks
    assert block.text == TEXT and block.summary == "Design file (stand-in.toml, 5 lines)"
