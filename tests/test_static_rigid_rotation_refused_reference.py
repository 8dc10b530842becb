"""A static load on a shaft free to turn about a single pin is refused, not answered with a
round-off deflection; pinned at both ends it is the beam formula.

Reference (statics). The tube of tests/rotors.py pinned at its start only (v, w held there, the
tilts free) has a rigid rotation about the pin that no stiffness resists: a transverse load P at
the middle has a moment P L/2 about the pin that nothing balances, so no static equilibrium
exists. The assembled K is singular in exact arithmetic; in floating point the LU leaves a pivot
of round-off size (not an exact zero: measured, the solve then returned ~1e10 m for 100 N, a round-off result),
which :func:`~flexshaft.analyses.response.static_response` must screen and report as
:class:`~flexshaft.analyses.banded.SingularSystemError`. The same tube pinned at both ends
deflects at the middle by the simply supported beam's ``P L³/(48 EI)`` (Hermite cubic elements
are exact at a node under a point load; the light tube's weight is not loaded here), to 1e-9
relative (the solve's round-off, κ(K) ε ≈ 1e-10).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, disk_dofs, jeffcott_text

from flexshaft.analyses.banded import SingularSystemError
from flexshaft.analyses.response import static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _model(fixed_end: str):
    text = jeffcott_text(0.0, 0.0, elements=7).replace('fixed_end = ["v", "w"]', f"fixed_end = {fixed_end}")
    model = build_model(loads_design(text))
    v, w = disk_dofs(model)
    Q = np.zeros(model.dofs.size)
    Q[v], Q[w] = 100.0, 37.0
    return model, Q, v, w


def test_a_shaft_pinned_at_one_end_has_no_static_equilibrium():
    model, Q, _, _ = _model("[]")
    with pytest.raises(SingularSystemError):
        static_response(model, Q, 0.0)


def test_pinned_at_both_ends_it_deflects_as_the_simply_supported_beam():
    model, Q, v, w = _model('["v", "w"]')
    q = static_response(model, Q, 0.0)
    assert q[v] == pytest.approx(100.0 / K_SHAFT, rel=1e-9)
    assert q[w] == pytest.approx(37.0 / K_SHAFT, rel=1e-9)
