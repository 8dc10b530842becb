"""The notebook table of the critical speeds (``CriticalSpeeds._repr_html_``) in the units its
header states, against a unit conversion derived here.

The table's header names the speed column "speed [rpm]" and its title gives the search's top
"up to ... rpm"; the criticals and the search top are held in rad/s. With 1 rev = 2π rad and
1 min = 60 s, N [rpm] = Ω [rad/s] · 60/(2π): a critical at Ω = 100π rad/s is 3000 rpm and a
top at 200π rad/s is 6000 rpm (a table in rad/s would read 314.2 and 628.3). The AF and the
station pass through unchanged (7.5 and 0.25 m).

The cells print 4 significant digits (``html_table``), so the parsed values are compared with
rel 1e-3: far tighter than the factor 60/(2π) ≈ 9.55 a unit slip makes. No solve: a
hand-built ``CriticalSpeeds``; well under 0.1 s.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from flexshaft.analyses.criticals import CriticalSpeeds, LateralCritical


def _cells(html: str) -> list[list[str]]:
    body = html.split("<tbody>", 1)[1]
    return [re.findall(r"<td[^>]*>(.*?)</td>", row) for row in re.findall(r"<tr>(.*?)</tr>", body)]


def test_the_table_gives_each_critical_speed_in_rpm():
    criticals = (
        LateralCritical(100.0 * np.pi, 7.5, {"station": 0.25, "mode": "1 (forward)"}),
        LateralCritical(150.0 * np.pi, 3.0, {"station": 0.5}),
    )
    html = CriticalSpeeds(criticals, 200.0 * np.pi)._repr_html_()
    rows = _cells(html)
    assert [float(r[0]) for r in rows] == pytest.approx([3000.0, 4500.0], rel=1e-3)
    assert [float(r[1]) for r in rows] == pytest.approx([7.5, 3.0], rel=1e-3)
    assert [float(r[2]) for r in rows] == pytest.approx([0.25, 0.5], rel=1e-3)
    title = re.search(r"up to ([0-9.]+) rpm", html)
    assert title is not None and float(title.group(1)) == pytest.approx(6000.0, rel=1e-3)
