"""``compare`` refuses two equal column labels before analysing anything.

:func:`~flexshaft.comparison.compare`'s ``labels`` are the column headings of the two designs
and the ``design`` coordinate of :meth:`~flexshaft.comparison.Comparison.to_dataset`; two equal
labels would give two columns with the same heading and a coordinate whose two entries cannot
be told apart (the rule reasoned here; its error text is "labels: expected two different names").
The refusal comes before either design is assessed, so the test costs milliseconds (the
message is the user-facing rule and the only observable of a refusal).
"""

from __future__ import annotations

import pytest

from flexshaft.comparison import compare


def test_two_equal_labels_are_refused():
    with pytest.raises(ValueError, match="two different names"):
        compare("tuned", "current", labels=("x", "x"))
