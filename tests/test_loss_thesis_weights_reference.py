"""The thesis's fixed-frame loss has no side of the synchronous line.

The thesis (eqs. 2.39-2.40) writes the members' loss as a complex stiffness in the fixed frame,
L(ω) = i sgn(ω) (F + K_lat): the shaft's lateral loss weighs like the boom's, whatever the
whirl's side of the spin, and nothing is circulatory. So for ``internal_damping = "thesis"`` a
mode's weights are (fixed, lateral, circulatory) = (i, i, 0) at every ω > 0, also when a side
σ = sgn(ω − Ω) is named (the rotating-frame model's σ has no meaning there). Exact numbers:
compared with ==.
"""

from __future__ import annotations

import pytest

from flexshaft.analyses.loss import eigen_coefficients


@pytest.mark.parametrize("sigma", [-1.0, 0.0, 1.0, None])
@pytest.mark.parametrize("omega", [100.0, 300.0, 900.0])
def test_the_thesis_weights_ignore_the_side_of_the_synchronous_line(omega, sigma):
    w = eigen_coefficients("thesis", omega, 300.0, sigma)
    assert (w.fixed, w.lateral, w.circulatory) == (1j, 1j, 0.0)
