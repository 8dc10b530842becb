"""The layup notation's explicit signs: '+θ' is +θ, and every spelling of the pair ± is +θ/−θ.

Reference: the laminate orientation code as published, not the parser's own text.
US Army TM 1-1500-204-23-11 (its laminate orientation code; read at
aviationmaintenance.tpub.com/TM-1-1500-204-23-11/TM-1-1500-204-23-1100115.html): adjacent plies of
equal angle and opposite sign are condensed to ± or ∓ "with the sign that is on top representing
the first ply in the layup order", so ±θ is +θ then −θ; the CADEC user manual §6.9 "Laminate
notation" (help.cadec-online.com/UserManualEN/sect0016.html): "[45/−45] or [±45]". The first ply
of the layup string is the inner ply (docs/design-reference.md, ``[shaft] layup``: "inner ply
first"; ``±45`` listed among the notation). ``+-`` and ``+/-`` are ASCII spellings of ± that no published
code defines: the project's convention (flexshaft.design.layup) is to read them as ±. A signed
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
