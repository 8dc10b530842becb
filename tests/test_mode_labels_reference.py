"""Mode labels by definition: a rigid axial shaft motion, a boom-only motion, an orthotropic pair (hunt h39a).

References (the labels' definitions, :mod:`flexshaft.analyses.classify`, and a closed form).

1. Kinetic-energy shares. A shape that moves only the shaft's axial DOFs u (every shaft node
   the same u: a rigid axial translation) puts all its kinetic energy φᴴMφ in the axial group:
   the shaft elements' axial mass couples u to u only, so the share is 1 to round-off and the
   mode is ``axial`` (share > 1/2), whirl ``none``, component ``shaft``. A shape that moves only
   the boom's DOFs has a boom share of 1: component ``boom``, kind ``lateral`` (neither the
   shaft's twist nor its axial motion carries more than half the energy). Tolerance 1e-12 on
   the shares (a sum of a few positive terms over itself).

2. An orthotropic support splits the planes. The Jeffcott rotor of tests/rotors.py with a
   contact bearing at the disk of stiffness k_b in v and k_b (1 + ε) in w, ε = 2e-4, k_b = k:
   the planes decouple, ω_v² = (k + k_b)/m and ω_w² = (k + k_b(1 + ε))/m (the tube's mass,
   3.5e-6 of the disk's, moves them by ~1e-6: tolerance 1e-5). The two modes are 5e-5 apart, far
   from degenerate (the labels combine only eigenvalues within 1e-8 of each other into circular
   forward/backward whirls): each is a planar orbit, v alone or w alone, whirl ratio
   r = −2 Im(v̄ w)/(|v|² + |w|²) = 0 and label ``planar``. On isotropic supports (ε = 0) the same
   pair is degenerate and resolved into a forward and a backward circular whirl.
CPU: a 56-DOF coarse tuned model and two 4-element Jeffcott modal solves, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK

from flexshaft.analyses.classify import label_modes
from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides

EPS = 2e-4


@pytest.fixture(scope="module")
def coarse():
    return build_model(with_overrides(tuned_design(), {"mesh.shaft_elements": 2, "mesh.boom_elements": 2}))


def test_a_rigid_axial_shaft_motion_is_axial_and_a_boom_motion_is_the_boom(coarse):
    dm = coarse.dofs
    shapes = np.zeros((dm.size, 2))
    shapes[dm.shaft(np.arange(dm.n_shaft_nodes), "u"), 0] = 1.0
    shapes[dm.boom_dofs, 1] = 1.0
    labels = label_modes(coarse, shapes)
    assert labels.shares.shaft_axial == pytest.approx([1.0, 0.0], abs=1e-12)
    assert labels.shares.boom == pytest.approx([0.0, 1.0], abs=1e-12)
    assert list(labels.kind) == ["axial", "lateral"]
    assert list(labels.whirl) == ["none", "planar"]
    assert list(labels.component) == ["shaft", "boom"]


@pytest.mark.parametrize("eps", [0.0, EPS])
def test_an_orthotropic_pair_is_planar_and_an_isotropic_one_circular(eps):
    bearing = f'kind = "contact"\nstiffness = {{ v = {K_SHAFT}, w = {K_SHAFT * (1 + eps)} }}'
    result = modes(model_with(bearing), 0.0, n_modes=2)
    expected = np.sqrt(np.array([2.0, 2.0 + eps]) * K_SHAFT / M_DISK) / (2 * np.pi)
    assert result.frequencies[:2] == pytest.approx(expected, rel=1e-5)
    if eps:
        assert list(result.whirl[:2]) == ["planar", "planar"]
    else:
        assert sorted(result.whirl[:2]) == ["backward", "forward"]
