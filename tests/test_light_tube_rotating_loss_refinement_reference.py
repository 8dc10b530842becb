"""The refinement of hysteretic roots above the spin on their own branch's problem, on a rotor
whose dense eigen-solve is not accurate to Newton's tolerance.

Derived reference. The Jeffcott test rotor (tests/rotors.py: midspan disk m on a pinned-pinned
steel tube of stiffness k = 48EI/L³, loss factor η of the tube) with an anisotropic dashpot at
the disk, c_v in v and c_w = 20 c_v in w. Below the spin's first critical speed (Ω = 0.3-0.7 ω_n)
both disk modes whirl faster than the spin, where the rotating-frame loss has σ = sgn(ω − Ω) =
+1 and weights ``W₊ = (i, i, 0)`` (:mod:`flexshaft.analyses.loss`): the tube's lateral loss is
the complex stiffness iηk on v and on w alike, with no circulatory term, so v and w decouple and
the two roots with Im s > 0 are those of

    m s² + c_v s + k(1 + iη) = 0    and    m s² + c_w s + k(1 + iη) = 0.

The lower branch's problem (σ = −1: ``W₋ = (i, 0, 1)``, the circulatory ηk S coupling v and w
instead of iηk) has a root of the v mode about 2 % away (Re s −2.0 instead of −10.6 rad/s),
also above the spin; it is no eigenvalue there.

Why this rotor: the tube is made nearly massless (density 1e-6 kg/m³, the smallest the design
limits allow; its mass is 3.5e-11 of the disk's), so the basis of every free DOF holds stiff,
light tube modes and the dense solve of the first-order matrix errs by 2e-10 to 1e-8 relative
on the disk's roots (measured, OpenBLAS Prescott and Haswell), above Newton's tolerance of
1e-10: the roots reported are those of the Newton refinement on each root's own branch
(:func:`flexshaft.analyses.hysteretic_roots.damped_modes`). Tolerance 1e-9 relative: Newton's
1e-10 step test and the neglected tube mass (3.5e-11, as the condensation onto the disk is exact
for the tube's stiffness); measured 1e-11. CPU: a 48-DOF model, about 0.1 s for three speeds.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA = 0.05
C_V, C_W = 2 * 0.01 * M_DISK * WN, 2 * 0.2 * M_DISK * WN


@pytest.fixture(scope="module")
def model():
    text = jeffcott_text(ETA, C_V)
    text = text.replace(f"damping = {{ v = {C_V}, w = {C_V} }}", f"damping = {{ v = {C_V}, w = {C_W} }}")
    text = text.replace("density = 0.1", "density = 1e-6")
    assert str(C_W) in text and "density = 1e-6" in text
    return build_model(loads_design(text))


def _upper_root(c: float) -> complex:
    roots = np.roots([M_DISK, c, K_SHAFT * (1 + 1j * ETA)])
    return complex(roots[np.argmax(roots.imag)])


@pytest.mark.parametrize("ratio", [0.3, 0.5, 0.7])
def test_both_disk_modes_above_the_spin_are_the_positive_loss_roots(model, ratio):
    expected = np.sort_complex(np.array([_upper_root(C_V), _upper_root(C_W)]))
    assert np.all(expected.imag > ratio * WN)  # both above the spin: σ = +1
    m = modes(model, ratio * WN, n_modes=2, basis_size=int(model.dofs.free.size))
    np.testing.assert_allclose(np.sort_complex(m.eigenvalues), expected, rtol=1e-9)
