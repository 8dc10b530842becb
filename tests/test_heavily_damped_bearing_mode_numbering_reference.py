"""Which hysteretic modes ``modes()`` lists: a heavily damped bearing mode of lower damped
frequency but larger |s| comes before a lightly damped shaft mode.

Documented rule (docs/model.md, "Modes are numbered by damped frequency Im s ... the n of
lowest Im s among the 2n of lowest |s|"). Rotor: the Jeffcott test tube (tests/rotors.py:
near-massless pinned-pinned steel tube, loss factor η) with a lighter midspan disk (m = 0.5 kg)
on a stiff, heavily damped contact bearing at the disk (stiffness k_b, dashpot c in v and w).
Derived here:

* The antisymmetric shaft pair (A): the disk sits on its node, so neither the disk nor the
  bearing moves in it; every stiffness of that mode is the tube's, with loss η, so its roots are
  s_A = iω₂√(1 + iη) (ζ = sin(½ atan η), |s_A| = ω₂(1 + η²)^¼), ω₂ ≈ (2π/L)²√(EI/ρA) the tube's
  second pinned-pinned frequency.
* The disk pair (B): the tube condenses onto the disk as k_s(1 + iη), k_s = 48EI/L³, so
  m s² + c s + k_b + k_s(1 + iη) = 0 (double: v and w).

k_b puts √((k_b + k_s)/m) at 1.08 ω₂ and c gives ζ_B = 0.45, so |s_B| ≈ 1.08 ω₂ > |s_A| ≈ ω₂
while Im s_B ≈ 1.08·0.893 ω₂ = 0.96 ω₂ < Im s_A ≈ ω₂: by |s| the shaft pair comes first, by
damped frequency the bearing pair does (margins 3-8 %, far above the tube's 0.5 % mesh error of
ω₂). The lowest root is the disk's axial mode (the tube is held axially at x = 0 only, so the
disk rides on its first half, stiffness 2EA/L: √(2EA/(L m)) ≈ 0.027 ω₂, ζ = sin(½ atan η) ≈
η/2, far below both). By |s| the order is that axial root, the A pair, the B pair: the B roots
are the 4th and 5th, inside the rule's pool of the 2n = 6 roots of lowest |s| for n = 3. So the
three modes of lowest damped frequency are the axial mode and the B pair; listing the three of
lowest |s| (the axial mode and the A pair) breaks the rule.

Tolerance: the tube's mass (7.1e-5 kg) is 1.4e-4 of the disk's, which the condensation to k_s
neglects; s_B is asserted to 5e-4 relative (measured 4e-5), while the A pair lies 8 % away.
CPU: one 48-DOF model, a few hundredths of a second.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, E, L, jeffcott_text

from flexshaft.analyses import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, MASS, ZETA_B = 0.02, 0.5, 0.45
EI = E * np.pi * (DO**4 - DI**4) / 64
RHO_A = 0.1 * np.pi * (DO**2 - DI**2) / 4  # the tube's density 0.1 kg/m³ (tests/rotors.py)
W2 = (2 * np.pi / L) ** 2 * np.sqrt(EI / RHO_A)  # second pinned-pinned bending frequency
W_B = 1.08 * W2
K_B = MASS * W_B**2 - K_SHAFT
C_B = 2 * ZETA_B * MASS * W_B


def _model():
    text = jeffcott_text(ETA, C_B)
    text = text.replace(f"mass = {M_DISK}", f"mass = {MASS}")
    text = text.replace("stiffness = {}", f"stiffness = {{ v = {K_B}, w = {K_B} }}")
    assert f"mass = {MASS}" in text and str(K_B) in text
    return build_model(loads_design(text))


def _disk_root() -> complex:
    roots = np.roots([MASS, C_B, K_B + K_SHAFT * (1 + 1j * ETA)])
    return complex(roots[np.argmax(roots.imag)])


def test_the_heavily_damped_bearing_pair_is_listed_before_the_shaft_pair():
    s_b = _disk_root()
    s_a = 1j * W2 * np.sqrt(1 + 1j * ETA)
    assert abs(s_b) > 1.05 * abs(s_a) and s_b.imag < 0.97 * s_a.imag  # the premise, from the closed forms
    m = modes(_model(), 0.0, n_modes=3)
    high = m.eigenvalues[m.eigenvalues.imag > 0.5 * W2]  # the axial mode lies far below
    assert high.size == 2
    np.testing.assert_allclose(high, [s_b, s_b], rtol=5e-4)
    assert m.damping_ratios[m.eigenvalues.imag > 0.5 * W2] == pytest.approx([ZETA_B] * 2, rel=1e-3)
