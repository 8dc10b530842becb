"""The layup notation's explicit signs: '+θ' is +θ, and every spelling of the pair ± is +θ/−θ.

Reference: the stacking notation of docs/design-reference.md (``[shaft] layup``, ``±45``) and
of :func:`flexshaft.design.layup.parse_layup`'s docstring and error text: ``"(±45)s"``,
``"+-45"`` and ``"+/-45"`` all expand the pair to 45/−45 (``"∓45"`` to −45/45), and a signed
angle is that angle. Angles are compared exactly (each is a float read from the text, times ±1).
"""

from __future__ import annotations

import pytest

from flexshaft.design.layup import parse_layup


def test_an_explicit_plus_sign_keeps_the_angle():
    assert parse_layup("+45/-45") == (45.0, -45.0)
    assert parse_layup("(+30/-30)s") == (30.0, -30.0, -30.0, 30.0)


@pytest.mark.parametrize("text", ["±55", "+-55", "+/-55"])
def test_every_spelling_of_the_plus_minus_pair_is_plus_then_minus(text):
    assert parse_layup(text) == (55.0, -55.0)
    assert parse_layup(f"[{text}/0]s") == (55.0, -55.0, 0.0, 0.0, -55.0, 55.0)
