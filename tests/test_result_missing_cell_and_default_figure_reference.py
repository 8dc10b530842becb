"""A printed table's column of numbers with a missing value, and the figure ``.plot()`` draws
without ``kind`` (analyses/results.py: ``text_table``, ``ResultMixin.plot``).

References (the module's documented contract, expected strings written out by hand):

* ``text_table``: "numbers right-aligned, text left-aligned"; ``cell_text`` shows None as an
  em dash. A missing value in a column of numbers (a damping ratio not computed, a margin not
  applicable) is still a column of numbers: its cells end in one column (the per-column reading
  of the rule, derived here: the rule does not say where the dash goes). Rows (1, 55.3219),
  (2, None), (3, 120.5) under "mode" and "f [Hz]": widths max(4, 1) = 4 and max(6, 5, 1, 5) = 6,
  two spaces between columns, every cell right-justified, so
  ``"   1   55.32"``, ``"   2       —"``, ``"   3   120.5"``.
* ``ResultMixin.plots`` (its ``#:`` comment, results.py): "kind -> name of the method that
  draws it; the first entry is the default": a result listing ("bode", "orbit") draws the
  Bode plot when no kind is given, and an unknown kind is refused naming the kinds.

Exact strings (no arithmetic beyond 4-significant-figure formatting); CPU about 1 ms.
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.results import ResultMixin, text_table


def test_missing_value_keeps_a_column_of_numbers_right_aligned():
    text = text_table(["mode", "f [Hz]"], [[1, 55.3219], [2, None], [3, 120.5]])
    assert text.splitlines() == ["mode  f [Hz]", "----  ------", "   1   55.32", "   2       —", "   3   120.5"]


def test_text_column_stays_left_aligned():
    """A column of words is left-aligned: "FAIL" padded on the right to the width of "status"."""
    text = text_table(["check", "status"], [["onset", "FAIL"], ["strength", "PASS"]])
    assert text.splitlines()[2:] == ["onset     FAIL", "strength  PASS"]


class _TwoFigures(ResultMixin):
    """A result with two figures, the Bode plot listed first (as HarmonicResponse lists them)."""

    plots = {"bode": "plot_bode", "orbit": "plot_orbit"}

    def plot_bode(self, ax=None, **kwargs):
        return ("bode", ax, kwargs)

    def plot_orbit(self, ax=None, **kwargs):
        return ("orbit", ax, kwargs)


def test_plot_without_kind_draws_the_first_listed_figure():
    result = _TwoFigures()
    assert result.plot() == ("bode", None, {})
    assert result.plot("orbit", ax="axes", station=4.31) == ("orbit", "axes", {"station": 4.31})
    with pytest.raises(ValueError, match=r"\['bode', 'orbit'\]"):
        result.plot("campbell")
