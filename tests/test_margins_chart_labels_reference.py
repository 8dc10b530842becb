"""Each bar of the verdict's margins chart carries its own check's numbers: the normalised
margin in percent and the margin in the check's unit (:meth:`Verdict.plot_margins`,
:func:`flexshaft.plot.verdict.margins_figure`).

References:

* docs/requirements.md, "The checks": "a **margin** in the value's unit (value − limit for a
  minimum, limit − value for a maximum: negative fails)" and the check's ``normalised_margin``
  is "the margins figure's number".
* The ``plot_margins`` docstring: "its margin divided by its limit ... with the margin in
  engineering units beside each bar"; the ``margins_figure`` docstring: texts are "The margin
  in engineering units, written beside each bar (e.g. "+0.18 mm")" and ``limits`` is the
  "axis range [-]; longer bars are cut with an arrow and their value written" (the value, not
  "∞", which is for "+inf when it passed with nothing to measure").

Four hand-built checks, by hand (top to bottom):

* ``orbit`` "at most": value 0.07 mm, limit 0.25 mm, margin 0.18 mm → +72 %, "+0.18 mm";
* ``safety`` "at least": value 2.5, limit 2.0, margin 0.5 → +25 %, "+0.5";
* ``force`` "at most": value 1030 N, limit 1000 N, margin −30 N → −3 % (fails), "-30 N";
* ``buckling`` "at least": value 9.0, limit 1.5, margin 7.5 → +500 %, beyond the default
  +300 % axis limit: cut, written "+500%", "+7.5".

Each label is found by its anchor's height, the height of its bar's centre. Matplotlib Agg,
labels compared as strings (the percentages are whole numbers of percent from one division,
far from a rounding edge: 0.72, 0.25, −0.03, 5.0). CPU about 0.3 s.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

from flexshaft.verdict.result import Check, Verdict  # noqa: E402

# title, expected percentage, expected engineering-unit margin
EXPECTED = [
    ("orbit", "+72%", "+0.18 mm"),
    ("safety", "+25%", "+0.5"),
    ("force", "-3%", "-30 N"),
    ("buckling", "+500%", "+7.5"),
]


def _verdict() -> Verdict:
    return Verdict(
        (
            Check("orbit", "orbit", "length", "at most", "pass", 0.07e-3, 0.25e-3, 0.18e-3),
            Check("safety", "safety", "ratio", "at least", "pass", 2.5, 2.0, 0.5),
            Check("force", "force", "force", "at most", "fail", 1030.0, 1000.0, -30.0),
            Check("buckling", "buckling", "ratio", "at least", "pass", 9.0, 1.5, 7.5),
        )
    )


def _labels_by_bar(ax) -> list[str]:
    """The label anchored at each bar's height, bars top to bottom."""
    bars = sorted(ax.patches, key=lambda p: -p.get_y())
    out = []
    for bar in bars:
        yc = bar.get_y() + bar.get_height() / 2
        texts = [t.get_text() for t in ax.texts if hasattr(t, "xy") and abs(t.xy[1] - yc) < 1e-9]
        assert len(texts) == 1, texts
        out.append(texts[0])
    return out


def test_each_bar_is_labelled_with_its_own_checks_margins() -> None:
    fig = _verdict().plot_margins()
    try:
        labels = _labels_by_bar(fig.axes[0])
        assert len(labels) == len(EXPECTED)
        for label, (title, percent, text) in zip(labels, EXPECTED):
            assert label.startswith(percent), (title, label)
            assert f"({text})" in label, (title, label)
            assert "∞" not in label and "fails" not in label, (title, label)
    finally:
        plt.close(fig)


def test_a_small_failing_margin_keeps_its_number() -> None:
    """A check failing by 3 % of its limit is a finite, non-zero margin: the figure writes it
    (only a failure with nothing to show, a margin within half a percent of zero, reads "fails")."""
    fig = Verdict((Check("force", "force", "force", "at most", "fail", 1030.0, 1000.0, -30.0),)).plot_margins()
    try:
        (label,) = _labels_by_bar(fig.axes[0])
        assert label.startswith("-3%") and "(-30 N)" in label, label
    finally:
        plt.close(fig)
