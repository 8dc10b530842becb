"""The margins figure writes a lower-bound margin as such ("≥").

A hand-built margin that is only a lower bound (the verdict could only bound it) must not read
as exact: its text starts with "≥ ", then the margin/limit in percent (0.25 → "+25%"), derived
from the value given. Agg, no file.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

from flexshaft.plot.verdict import margins_figure  # noqa: E402


def test_lower_bound_margin_is_written_with_at_least():
    fig = margins_figure(["onset", "orbit"], [0.25, 0.5], ["pass", "pass"], ["+1200 rpm", "+0.1 mm"], [True, False])
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert "≥ +25%  (+1200 rpm)" in texts and "+50%  (+0.1 mm)" in texts
