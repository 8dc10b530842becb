"""The refinement of hysteretic roots above the spin on their own branch's problem: through
``modes()`` on a rotor whose dense eigen-solve is not accurate to Newton's tolerance, and directly.

Derived reference. The Jeffcott test rotor (tests/rotors.py: midspan disk m on a pinned-pinned
steel tube of stiffness k = 48EI/L³, loss factor η of the tube) with an anisotropic dashpot at
the disk, c_v in v and c_w = 20 c_v in w. Below the spin's first critical speed (Ω = 0.3-0.7 ω_n)
both disk modes whirl faster than the spin, where the rotating-frame loss has σ = sgn(ω − Ω) =
+1 and weights ``W₊ = (i, i, 0)`` (:mod:`flexshaft.analyses.loss`): the tube's lateral loss is
the complex stiffness iηk on v and on w alike, with no circulatory term, so v and w decouple and
the two roots with Im s > 0 are those of

    m s² + c_v s + k(1 + iη) = 0    and    m s² + c_w s + k(1 + iη) = 0.

The lower branch's problem (σ = −1: ``W₋ = (i, 0, 1)``, the circulatory ηk S coupling v and w
instead of iηk) has a root of each mode near it: 2.8 % away for v (Re s −2.0 instead of −10.6
rad/s) and 2.2 % for w (−61.4 instead of −68.1 rad/s), also above the spin; they are no
eigenvalues there.

Why this rotor: the tube is made nearly massless (density 1e-6 kg/m³, the smallest the design
limits allow; its mass is 3.5e-11 of the disk's), so the basis of every free DOF holds stiff,
light tube modes and the dense solve of the first-order matrix errs by 8.5e-11 to 7.3e-9
relative on the disk's roots (measured over 7 OpenBLAS kernels × numpy 2.4 and 1.26; at every
speed one of the two roots errs by more than 1e-9), above Newton's tolerance of 1e-10: the roots
reported are those of the Newton refinement on each root's own branch
(:func:`flexshaft.analyses.hysteretic_roots.damped_modes`). Tolerance 1e-9 relative: Newton's
1e-10 step test and the neglected tube mass (3.5e-11, as the condensation onto the disk is exact
for the tube's stiffness); measured 1e-11. CPU: a 48-DOF model, about 0.1 s for three speeds.

That first test catches a refinement on the wrong branch's problem only through that rounding
error: damped_modes' first Newton step of a root above the spin whose vector it deferred solves
with the upper branch's LU factors of that vector's inverse iteration, so a dense root within
Newton's 1e-10 stops there, and only a larger error takes a second step, on the wrong problem.
The dense error itself is not asserted (it depends on the BLAS kernel). The second test does
not rest on it: it calls the refinement (:func:`~flexshaft.analyses.hysteretic_roots._polish`)
on the usual tube (density 0.1 kg/m³) with no shared factors, so every Newton step, the first
included, is on the problem of the branch chosen, and a wrong branch's full step moves the root
the 2.2-2.8 % to its T₋ root. Its tolerance is 1e-5 relative, set by the tube mass
m_t = 3.5e-6 m that the condensation neglects: moving with the disk, an effective mass m_e ≤ m_t
shifts each root by about ½ m_e/m ≤ 1.8e-6 (measured 8.8e-7, close to Rayleigh's m_e = 17/35 m_t
for the static deflection shape; the same with all 48 modes, so the 8-mode basis adds nothing
measurable); 1e-5 leaves a factor 5 for the dashpots' share of the roots' sensitivity to the
mass, and is 2800 times below a refinement on T₋ (measured 2.8e-2). CPU: an 8-mode basis, a few
hundredths of a second a speed.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses import modes
from flexshaft.analyses.eigen import lowest_modes, reduce
from flexshaft.analyses.hysteretic_roots import _polish, consistent_roots
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA = 0.05
C_V, C_W = 2 * 0.01 * M_DISK * WN, 2 * 0.2 * M_DISK * WN


def _text() -> str:
    text = jeffcott_text(ETA, C_V)
    text = text.replace(f"damping = {{ v = {C_V}, w = {C_V} }}", f"damping = {{ v = {C_V}, w = {C_W} }}")
    assert str(C_W) in text
    return text


@pytest.fixture(scope="module")
def model():
    text = _text().replace("density = 0.1", "density = 1e-6")
    assert "density = 1e-6" in text
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


@pytest.mark.parametrize("ratio", [0.3, 0.5, 0.7])
def test_each_root_above_the_spin_is_refined_on_the_positive_loss_problem(ratio):
    red = reduce(build_model(loads_design(_text())), 8)  # the usual tube, 3.5e-6 of the disk's mass
    expected = np.sort_complex(np.array([_upper_root(C_V), _upper_root(C_W)]))
    assert np.all(expected.imag > ratio * WN)  # both above the spin: σ = +1
    s, Y = consistent_roots(red, ratio * WN)
    wanted = lowest_modes(s, 2)
    polished = _polish(red, ratio * WN, s[wanted], Y[:, wanted])  # no deferred roots: no shared factors
    assert polished is not None
    np.testing.assert_allclose(np.sort_complex(polished[0]), expected, rtol=1e-5)
