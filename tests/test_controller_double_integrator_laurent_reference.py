"""The proportional gain (s⁰ coefficient of the Laurent series about s = 0) of a controller law
with a DOUBLE pole at the origin (flexshaft.assembly.controller), against closed forms derived
here, and the modal-basis stiffness of a magnetic bearing built from such a law.

Derived reference.

* A "PII" law ``C(s) = kp + ki/s + kii/s² = (kp s² + ki s + kii)/s²`` has the Laurent series
  kii s⁻² + ki s⁻¹ + kp: its constant term is ``kp``, whatever ki and kii.
* A general law ``C(s) = P(s) / (s² Q(s))`` with ``P = n3 s³ + n2 s² + n1 s + n0`` and
  ``Q = d1 s + d0``: write P/Q = c0 + c1 s + c2 s² + …; matching powers in P = Q Σ c_k s^k gives
  c0 = n0/d0, c1 = (n1 − d1 c0)/d0, c2 = (n2 − d1 c1)/d0, so
  ``c2 = n2/d0 − n1 d1/d0² + n0 d1²/d0³``, and the s⁰ coefficient of C = s⁻² P/Q is c2.
  d0 is deliberately not 1, and n0 ≠ 0 with P(−d0/d1) ≠ 0, so no root cancels.
* A bearing with current gain k_i and magnet stiffness k_s carries ``k_i C(s) − k_s``
  (docs/magnetic-bearings.md: ``G(s) − k_s`` with ``G = k_i A(s) C(s)``; no amplifier lag
  here). The constant term of its Laurent series, k_i c2 − k_s, is the bearing's proportional
  stiffness, and docs/magnetic-bearings.md ("Modal basis with negative stiffness", lines
  109-111) puts its positive part k_a in the modal basis ("`k_a` the positive part of each
  bearing's proportional stiffness (`k_i K_p − k_s` of a PD or PID law ...), never negative"):
  ``Model.Kp`` holds that k_a on the magnet's lateral DOFs.

Tolerances: the gains are a handful of floating-point operations on the given coefficients; the
three terms of c2 (1.6e6, −3.2e4, 3.2e2) do not cancel, so relative rounding stays within a few
ulps: 1e-12 relative. CPU: one 4-element build, milliseconds.
"""

from __future__ import annotations

import numpy as np
from test_controller_laurent_gain_and_relative_degree_reference import (
    _magnet_model,  # the same magnet on the same rotor
)

from flexshaft.assembly.controller import Controller

N3, N2, N1, N0 = 3.0, 8.0e6, 4.0e8, 1.0e10  # numerator, highest power first
D1, D0 = 2.0e-3, 5.0  # denominator s² (D1 s + D0)
C2 = N2 / D0 - N1 * D1 / D0**2 + N0 * D1**2 / D0**3  # 1.56832e6 N/m
KI, KS = 2.0, 1.0e5  # [N/A], [N/m]


def test_the_proportional_gain_of_a_pii_law_is_kp():
    """PII law kp + ki/s + kii/s²: the Laurent constant term and the basis stiffness are kp."""
    kp, ki, kii = 1.2e6, 3.0e7, 4.0e9
    law = Controller((kp, ki, kii), (1.0, 0.0, 0.0))
    assert law.integrates
    assert abs(law.proportional_gain - kp) <= 1e-12 * kp
    assert abs(law.basis_stiffness - kp) <= 1e-12 * kp


def test_the_proportional_gain_of_a_double_integrator_is_the_laurent_constant_term():
    """P(s)/(s² Q(s)): the s⁰ coefficient is c2 = n2/d0 − n1 d1/d0² + n0 d1²/d0³."""
    law = Controller((N3, N2, N1, N0), (D1, D0, 0.0, 0.0))
    assert abs(law.proportional_gain - C2) <= 1e-12 * C2


def test_the_basis_stiffness_of_a_double_integrating_bearing_is_ki_c2_minus_ks():
    """Model.Kp on the magnet's v and w DOFs is k_a = k_i c2 − k_s (positive here)."""
    model = _magnet_model(
        f"controller = {{ numerator = [{N3}, {N2}, {N1}, {N0}], denominator = [{D1}, {D0}, 0.0, 0.0] }}",
        f"ki = {KI}\nks = {KS}\n",
    )
    dm = model.dofs
    node = int(np.flatnonzero(np.isclose(dm.shaft_x, 0.25))[0])
    expected = KI * C2 - KS  # 3.03664e6 N/m
    Kp = model.Kp.toarray()
    for f in ("v", "w"):
        i = dm.shaft(node, f)
        assert abs(Kp[i, i] - expected) <= 1e-12 * expected
