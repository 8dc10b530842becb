"""Two rules of every result (analyses/results.py): ``.plot()`` without a kind draws the first
figure of the result's ``plots``, and a numeric table column with a missing value stays a
numeric column.

References (the module's contract, derived by hand):

* ``ResultMixin.plots`` maps each kind to its drawing method and "the first entry is the
  default" (a stability result's log decrements before its real parts). Checked on a stand-in
  with a stability result's two kinds, whose drawing methods return their own name (no
  matplotlib), ``ax`` and the keyword arguments handed through.
* ``text_table`` right-aligns numbers and left-aligns text; a missing value (None, shown as an
  em dash) belongs to its column's kind. A modes table of two modes whose second damping ratio
  is missing: widths max(len("mode"), 1) = 4 and max(len("ζ [-]"), len("0.0213")) = 6, the
  columns two spaces apart, so the lines are exactly "mode   ζ [-]", "   1  0.0213" and
  "   2       —" (the dash under the last digit, not under the column's first character).
CPU about 1 ms.
"""

from __future__ import annotations

from flexshaft.analyses.results import ResultMixin, text_table


class _TwoFigures(ResultMixin):
    plots = {"log_decrement": "draw_log_decrement", "real_part": "draw_real_part"}

    def draw_log_decrement(self, ax=None, **kwargs):
        return ("log_decrement", ax, kwargs)

    def draw_real_part(self, ax=None, **kwargs):
        return ("real_part", ax, kwargs)


def test_plot_without_a_kind_draws_the_first_figure():
    result = _TwoFigures()
    assert result.plot() == ("log_decrement", None, {})
    assert result.plot(ax="axes", label="this design") == ("log_decrement", "axes", {"label": "this design"})
    assert result.plot("real_part")[0] == "real_part"


def test_a_numeric_column_with_a_missing_value_stays_right_aligned():
    text = text_table(["mode", "ζ [-]"], [[1, 0.0213], [2, None]])
    lines = text.splitlines()
    assert lines[0] == "mode   ζ [-]"
    assert lines[2:] == ["   1  0.0213", "   2       —"]
