"""Two refusals of flexshaft.assembly.checks: a model whose matrices overflowed, and a
controller whose static stiffness is hugely negative.

Derived reference.

* ``check_finite_model`` refuses "a model with a non-finite matrix entry". Under IEEE 754 an
  overflow (E I / h³ or ρ A beyond 1.8e308) gives ±inf, not NaN, so an assembled matrix with a
  single +inf or −inf entry is non-finite and must be refused, like one with NaN; the same
  model with finite entries passes.
* docs/limits.md: "Its static gain k_i C(0) counts as a support stiffness in the check above"
  (a support stiffer than 1e8 times one shaft element's E I/h³ is refused). Why the limit
  exists (same section): a diagonal entry k_el + k rounds with an error of about ε|k|, so the
  lowest eigenvalues lose digits in proportion to |k| / k_el, whatever the sign of k. A law
  whose static gain is −1e20 N/m (C(s) = (s − 1e20)/(1e-3 s + 1), here 4e13 times E I/h³ of
  the 4-element tube) is therefore as ill-conditioned as +1e20 N/m and is refused; a modest
  negative static gain (−1e5 N/m, 0.04 E I/h³) is not.

CPU: a few 4-element builds, milliseconds each.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from rotors import jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.assembly.checks import check_finite_model
from flexshaft.design import DesignError, loads_design


def _magnet_text(law: str) -> str:
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    return head + f'[[bearings]]\nname = "m"\nx = 0.25\nkind = "active"\n{law}\n' + tail


@pytest.mark.parametrize("matrix", ["K", "M", "G"])
@pytest.mark.parametrize("value", [np.inf, -np.inf, np.nan])
def test_a_model_with_an_overflowed_entry_is_refused(matrix, value):
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=4)))
    check_finite_model(model)  # the finite model passes
    bad = getattr(model, matrix).copy()
    assert bad.nnz
    bad.data[0] = value
    with pytest.raises(DesignError, match="non-finite"):
        check_finite_model(dataclasses.replace(model, **{matrix: bad}))


@pytest.mark.parametrize("static", [1.0e20, -1.0e20])
def test_a_static_gain_far_beyond_the_element_stiffness_is_refused_whatever_its_sign(static):
    law = f"controller = {{ numerator = [1.0, {static!r}], denominator = [1.0e-3, 1.0] }}"
    with pytest.raises(DesignError, match=r"bearings\[0\]\.controller"):
        build_model(loads_design(_magnet_text(law)))


def test_a_modest_negative_static_gain_is_not_refused():
    law = "controller = { numerator = [1.0, -1.0e5], denominator = [1.0e-3, 1.0] }"
    model = build_model(loads_design(_magnet_text(law)))
    assert abs(complex(model.actuators[0].law(0.0)) + 1.0e5) <= 1e-9 * 1.0e5
