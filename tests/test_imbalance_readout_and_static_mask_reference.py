"""The imbalance response's read-out axes and the static solve's inputs (analyses/response.py)
on tests/rotors.py's Jeffcott-like rotor (20 kg disk at midspan of a near-massless
pinned-pinned tube, k = 48 EI/L³, no damping), against closed forms.

1. Synchronous response to ``Ω² Q₁ e^{iΩt}`` with Q₁ = (v: 1, w: −i) N s² at the disk (a
   forward rotating unit of m e): the disk's complex coordinate r = v + i w obeys
   (k − m Ω²) r = 2 Ω² below and above the critical, so v = Ω²/(k − m Ω²) (the Jeffcott
   rotor, derived here: the forward load is the circular v = F, w = −iF, each plane
   k v − m Ω² v = Ω²). The response's ``spin_speeds`` and ``frequencies`` are the speeds asked
   (the excitation is synchronous: ω = Ω). Tolerance 1e-4 relative: the tube (7.07e-5 kg,
   3.5e-6 of the disk) adds about 17/35 of its mass at the disk, a mass error δm that moves v
   by (δm/m) r²/|1 − r²| (r = Ω/ω_n), at most 1.8 at the speeds used: ≤ 4e-6 (measured
   5.7e-7 and −3.1e-6), 25× inside the tolerance.
2. ``static_response(within=mask)`` on the lateral DOFs (the axial and torsional blocks of
   this rotor are uncoupled from them) gives the full solve's deflection F/k at the disk; a
   complex static load is refused (``static_response`` takes constant loads [N, N m], and a
   constant load has no phase; the refusal's message: "static loads must be real").
   Tolerance 1e-10: the Euler-Bernoulli element is exact for point loads, round-off only.

CPU: one 8-element model, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.response import imbalance_response, static_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

F = 100.0  # N


@pytest.fixture(scope="module")
def model():
    return build_model(loads_design(jeffcott_text(0.0, 0.0)))


def _disk(model):
    node = model.dofs.node_at("shaft", 0.5)
    return model.dofs.shaft(node, "v"), model.dofs.shaft(node, "w")


def test_the_imbalance_response_is_read_against_the_speeds_asked(model):
    v, w = _disk(model)
    Q1 = np.zeros(model.dofs.size, dtype=complex)
    Q1[v], Q1[w] = 1.0, -1j
    speeds = np.array([0.5, 1.5]) * WN
    q = imbalance_response(model, speeds, Q1)
    np.testing.assert_array_equal(q.spin_speeds, speeds)
    np.testing.assert_array_equal(q.frequencies, speeds)
    expected = speeds**2 / (K_SHAFT - M_DISK * speeds**2)
    np.testing.assert_allclose(np.asarray(q)[v], expected, rtol=1e-4)
    np.testing.assert_allclose(np.asarray(q)[w], -1j * expected, rtol=1e-4)


def test_a_static_solve_on_the_lateral_blocks_is_the_full_one(model):
    v, _ = _disk(model)
    Q = np.zeros(model.dofs.size)
    Q[v] = F
    n = np.arange(model.dofs.n_shaft_nodes)
    lateral = np.concatenate([model.dofs.shaft(n, f) for f in ("v", "w", "beta", "gamma")])
    mask = np.isin(model.dofs.free, lateral)
    assert 0 < mask.sum() < mask.size
    q = static_response(model, Q, 0.0, within=mask)
    assert q[v] == pytest.approx(F / K_SHAFT, rel=1e-10)
    np.testing.assert_allclose(q, static_response(model, Q, 0.0), rtol=0, atol=1e-10 * F / K_SHAFT)


def test_complex_static_loads_are_refused(model):
    v, w = _disk(model)
    Q = np.zeros(model.dofs.size, dtype=complex)
    Q[v], Q[w] = F, -1j * F
    with pytest.raises(ValueError, match="must be real"):
        static_response(model, Q, 0.0)
