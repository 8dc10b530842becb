"""A root is seeded only where the projected orbit has a maximum of its own (hunt h45a).

:func:`flexshaft.analyses.criticals._hidden_resonances` samples the projected orbit at
Re Ω_k + |Im Ω_k| (−2 … 2, an eighth apart) and seeds the root only when some interior sample
is above both its neighbours (a taller neighbour may set the window's edge; "no maximum of its
own there" otherwise): a root the imbalance does not excite shows only the flank of a
neighbour's resonance.

Reference (closed form): the damped Jeffcott rotor of tests/test_hidden_seed_half_width_reference.py
(ζ = 0.002, dashpot at the disk, forward imbalance). Its projected problem is the
single-degree-of-freedom k − mΩ² + icΩ, whose orbit |q| = u Ω² / |k − mΩ² + icΩ| rises
monotonically up to its peak Ω_p = ω_n/√(1 − 2ζ²) and falls beyond (its derivative's sign is
that of Ω_p − Ω). A root placed (by substituting the root finder) 3 half-widths ζω_n below the
resonance samples Ω ∈ ω_n + ζω_n (−5 … −1), all below Ω_p: the samples rise monotonically to the
grid's right end, no interior maximum of its own, not seeded; the mirror root 3 half-widths above
falls monotonically from the left end, not seeded either. The true root (the control) is seeded.
The samples differ by ≥ 2 % between neighbours (|q| ∝ 1/|Ω − Ω̃| near resonance), so the
comparisons are far from round-off. CPU: a few 3-column projections, milliseconds.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_hidden_seed_half_width_reference import CENTRE, HALF_WIDTH, setting

import flexshaft.analyses.criticals as criticals

__all__ = ["setting"]  # the Jeffcott rotor, its loads, speeds and peak basis of the half-width file


@pytest.mark.parametrize("offset", [-3.0, 3.0])
def test_a_root_on_the_flank_of_another_resonance_is_not_seeded(setting, monkeypatch, offset):
    model, loads, speeds, span = setting
    root = np.array([CENTRE + offset * HALF_WIDTH + 1j * HALF_WIDTH])
    monkeypatch.setattr(criticals, "synchronous_roots", lambda *args: root)
    assert criticals._hidden_resonances(model, loads, speeds, None, [], span) == []


def test_the_resonance_itself_is_seeded(setting, monkeypatch):
    model, loads, speeds, span = setting
    root = np.array([CENTRE + 1j * HALF_WIDTH])
    monkeypatch.setattr(criticals, "synchronous_roots", lambda *args: root)
    (seed,) = criticals._hidden_resonances(model, loads, speeds, None, [], span)
    assert seed.speed == pytest.approx(CENTRE, rel=1e-5)
