"""The whirl column of ``flexshaft modes``: every documented label of a lateral mode is printed.

Reference (documented rule, docs/model.md "Labels"): a lateral mode whirls "forward" (r = +1
circular), "backward" (r = −1) or is "planar" (|r| < 0.1); the other kinds (torsional, axial)
carry "none", which the table prints as a dash. So a gyroscopically split pair of a spinning
rotor prints its lower branch as backward and its upper one as forward, a mode of anisotropic
supports as planar, and only the torsional mode as a dash.

The rows are hand-made (the modes table is fed the rows of ``Modes.table()``): their rev/min,
ζ and δ columns are inputs the table echoes (made consistent here, 60 × Hz and δ = 2πζ/√(1 − ζ²)
of ζ = 0.01, but not what is checked); what is checked is docs/model.md's labels and the 1-based
numbering. The numbers are round so that the printed cells (4 significant figures) compare as
exact strings.
"""

from __future__ import annotations

import math

from rich.console import Console

from flexshaft.cli.tables import modes_table


def _cells(table) -> list[list[str]]:
    """The body rows of a rendered rich table, cell by cell."""
    console = Console(width=200, record=True, highlight=False)
    console.print(table)
    lines = console.export_text().splitlines()
    return [[c.strip() for c in line.split("│")[1:-1]] for line in lines if line.count("│") > 2]


def test_each_whirl_label_is_printed() -> None:
    """A backward/forward pair (40, 45 Hz), a planar mode (50 Hz) and a torsional one (60 Hz):
    the whirl column reads backward, forward, planar and a dash, the numbers 1 to 4 and the
    rev/min 2400, 2700, 3000, 3600 beside them."""
    zeta = 0.01
    labels = [(40.0, "lateral", "backward"), (45.0, "lateral", "forward"), (50.0, "lateral", "planar")]
    labels.append((60.0, "torsional", "none"))
    rows = [
        {
            "mode": k + 1,
            "frequency_Hz": f,
            "frequency_rpm": 60.0 * f,
            "damping_ratio": zeta,
            "log_decrement": 2.0 * math.pi * zeta / math.sqrt(1.0 - zeta**2),
            "kind": kind,
            "whirl": whirl,
            "component": "shaft",
        }
        for k, (f, kind, whirl) in enumerate(labels)
    ]
    body = _cells(modes_table("modes", rows))
    assert [r[6] for r in body] == ["backward", "forward", "planar", "—"]
    assert [r[0] for r in body] == ["1", "2", "3", "4"]
    assert [r[2] for r in body] == ["2400", "2700", "3000", "3600"]
    assert {r[4] for r in body} == {"0.06283"}  # δ of ζ = 0.01
