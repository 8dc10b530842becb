"""The proportional gain of a transfer-function controller (the s⁰ coefficient of its Laurent
series about s = 0) and its relative degree (flexshaft.assembly.controller), against closed
forms derived here, and the modal-basis stiffness of a bearing built from such a law.

Derived reference.

* A law with integral action ``C(s) = (n2 s² + n1 s + n0) / (s (d1 s + d0))``: with
  1/(d0 + d1 s) = (1/d0)(1 − (d1/d0) s + O(s²)),
  C(s) = n0/(d0 s) + (n1/d0 − n0 d1/d0²) + O(s), so its proportional gain (the constant term)
  is ``k0 = n1/d0 − n0 d1/d0²``. The denominator's constant d0 is deliberately not 1.
* A finite-gain law ``(a s + b)/(c s + d)`` has the proportional gain C(0) = b/d.
* A bearing with current gain k_i and magnet stiffness k_s carries ``k_i C(s) − k_s``
  (docs/magnetic-bearings.md); the constant term of its Laurent series is k_i k0 − k_s, which
  ``Model.Kp`` puts on the magnet's lateral DOFs when positive.
* The relative degree is deg(denominator) − deg(numerator): a proportional law behind two
  first-order lags, kp/((1 + s/ω1)(1 + s/ω2)), has relative degree 2 (strictly proper, always
  allowed); a PD law kp + kd s has −1 (the one improper degree allowed); a lag has 1.

Tolerances: the gains are a handful of floating-point operations on the given coefficients
(root finding cancels nothing: the laws share no root), so 1e-12 relative. CPU: one 4-element
build, ms.
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.assembly.controller import Controller
from flexshaft.design import loads_design

N2, N1, N0 = 3.0, 8.0e6, 4.0e8  # numerator, highest power first
D1, D0 = 2.0e-3, 5.0  # denominator (D1 s + D0) s
KI, KS = 2.0, 1.0e5  # [N/A], [N/m]


def _magnet_model(law: str, extra: str = ""):
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    magnet = f'[[bearings]]\nname = "m"\nx = 0.25\nkind = "active"\n{law}\n{extra}'
    return build_model(loads_design(head + magnet + tail))


def test_the_proportional_gain_of_an_integrating_law_is_its_laurent_constant_term():
    law = Controller((N2, N1, N0), (D1, D0, 0.0))
    expected = N1 / D0 - N0 * D1 / D0**2  # 1.568e6 N/m
    assert law.integrates
    assert abs(law.proportional_gain - expected) <= 1e-12 * abs(expected)


def test_the_proportional_gain_of_a_finite_law_is_its_static_gain():
    law = Controller((7.0, 6.0e5), (2.0e-3, 4.0))
    assert abs(law.proportional_gain - 6.0e5 / 4.0) <= 1e-12 * 6.0e5 / 4.0


def test_the_basis_stiffness_of_a_bearing_is_ki_times_the_laurent_constant_minus_ks():
    model = _magnet_model(
        f"controller = {{ numerator = [{N2}, {N1}, {N0}], denominator = [{D1}, {D0}, 0.0] }}", f"ki = {KI}\nks = {KS}\n"
    )
    dm = model.dofs
    node = int(np.flatnonzero(np.isclose(dm.shaft_x, 0.25))[0])
    expected = KI * (N1 / D0 - N0 * D1 / D0**2) - KS  # 3.036e6 N/m
    Kp = model.Kp.toarray()
    for f in ("v", "w"):
        i = dm.shaft(node, f)
        assert abs(Kp[i, i] - expected) <= 1e-12 * expected


def test_relative_degree_is_denominator_degree_minus_numerator_degree():
    w1, w2, kp = 300.0, 2.0e3, 1.0e6
    two_lags = Controller((kp,), (1.0 / (w1 * w2), 1.0 / w1 + 1.0 / w2, 1.0))
    assert two_lags.relative_degree == 2
    assert Controller.pd(kp, 50.0).relative_degree == -1
    assert Controller.lag(w1).relative_degree == 1


def test_a_strictly_proper_law_of_relative_degree_two_builds_as_its_transfer_function():
    """A design's law kp/((1 + s/ω1)(1 + s/ω2)) is accepted and evaluated as written."""
    w1, w2, kp = 300.0, 2.0e3, 1.0e6
    model = _magnet_model(
        f"controller = {{ numerator = [{kp}], denominator = [{1.0 / (w1 * w2)!r}, {1.0 / w1 + 1.0 / w2!r}, 1.0] }}"
    )
    s = 40.0 + 900.0j
    expected = kp / ((1.0 + s / w1) * (1.0 + s / w2))
    got = complex(model.actuators[0].law(s))
    assert abs(got - expected) <= 1e-12 * abs(expected)
