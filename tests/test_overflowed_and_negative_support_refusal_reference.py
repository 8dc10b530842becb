"""Two refusals of flexshaft.assembly.checks: a model whose matrices overflowed, and a
controller whose static stiffness is hugely negative.

Derived reference.

* ``check_finite_model`` refuses "a model with a non-finite matrix entry". Under IEEE 754 an
  overflow gives ±inf, not NaN, so an assembled matrix with a single +inf or −inf entry is
  non-finite and must be refused, like one with NaN; the same model with finite entries passes.
  (Public API only: the design bounds keep E I/h³ and ρA finite, docs/limits.md §1, so
  build_model cannot produce ±inf; the test hands the check a model with an entry replaced.)
* docs/limits.md §2: a lateral support stiffer than 1e8 times one shaft element's E I/h³ (h =
  shaft length / ``mesh.shaft_elements``) is refused, and "Its static gain k_i C(0) counts as a
  support stiffness in the check above". For the 4-element Jeffcott tube (E = 210 GPa, D_o =
  50 mm, D_i = 40 mm, h = 0.25 m) E I/h³ = 2.434e6 N/m, so the threshold is 2.434e14 N/m:
  C(s) = (s + k)/(1e-3 s + 1) on a bearing without ki (k_i = 1, so k_i C(0) = k) with
  k = ±3e14 (1.23 times the threshold) is refused by ``check_bearing_stiffness`` and k = ±2e14
  (0.82 times) passes it, on both signs.
* Why the sign does not matter (derived here, not in docs/limits.md, which measured positive
  stiffnesses only): a support k adds k to a diagonal entry of size k_el, which rounds with an
  error of about ε|k|, so the lowest eigenvalues lose digits in proportion to |k| / k_el
  whatever the sign of k. With a negative static gain the modal-basis stiffness Kp is clipped
  to 0 (``Controller.basis_stiffness``), so the ill-conditioning shows in K + G(s) and in the
  controller states of the eigen-analysis rather than in the basis. A modest negative static
  gain (−1e5 N/m, 0.04 E I/h³) builds.

CPU: a few 4-element builds, milliseconds each.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from rotors import DI, DO, E, L, jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.assembly.build import shaft_properties
from flexshaft.assembly.checks import check_bearing_stiffness, check_finite_model
from flexshaft.design import DesignError, loads_design

ELEMENTS = 4
K_ELEMENT = E * np.pi * (DO**4 - DI**4) / 64 / (L / ELEMENTS) ** 3  # E I/h³ = 2.434e6 N/m
THRESHOLD = 1.0e8 * K_ELEMENT  # docs/limits.md §2: 2.434e14 N/m


def _magnet_text(law: str) -> str:
    text = jeffcott_text(0.0, 0.0, elements=ELEMENTS)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    return head + f'[[bearings]]\nname = "m"\nx = 0.25\nkind = "active"\n{law}\n' + tail


@pytest.mark.parametrize("matrix", ["K", "M", "G"])
@pytest.mark.parametrize("value", [np.inf, -np.inf, np.nan])
def test_a_model_with_an_overflowed_entry_is_refused(matrix, value):
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=ELEMENTS)))
    check_finite_model(model)  # the finite model passes
    bad = getattr(model, matrix).copy()
    assert bad.nnz
    bad.data[0] = value
    with pytest.raises(DesignError, match="non-finite"):
        check_finite_model(dataclasses.replace(model, **{matrix: bad}))


@pytest.mark.parametrize("sign", [1.0, -1.0])
@pytest.mark.parametrize("magnitude", [3.0e14, 2.0e14])
def test_a_static_gain_beyond_1e8_element_stiffnesses_is_refused_whatever_its_sign(sign, magnitude):
    """k = ±3e14 N/m (above 1e8 E I/h³ = 2.434e14 N/m) is refused by the support check,
    ±2e14 N/m is not; both are 18 % or more away from the threshold, far beyond rounding."""
    assert 2.43e14 < THRESHOLD < 2.44e14  # the closed form above
    refused = magnitude > THRESHOLD
    law = f"controller = {{ numerator = [1.0, {sign * magnitude!r}], denominator = [1.0e-3, 1.0] }}"
    design = loads_design(_magnet_text(law))
    if refused:
        with pytest.raises(DesignError, match=r"bearings\[0\]\.controller"):
            check_bearing_stiffness(design, shaft_properties(design))
    else:
        check_bearing_stiffness(design, shaft_properties(design))


def test_a_modest_negative_static_gain_is_not_refused():
    law = "controller = { numerator = [1.0, -1.0e5], denominator = [1.0e-3, 1.0] }"
    model = build_model(loads_design(_magnet_text(law)))
    # C(0) = −1e5/1 is exact (polyval at 0, a division by 1); 1e-9 only allows for an
    # evaluation through the realization D − C A⁻¹ B, a handful of roundings.
    assert abs(complex(model.actuators[0].law(0.0)) + 1.0e5) <= 1e-9 * 1.0e5
