"""The viscous method's default reference frequency: the first mode more than half shaft, not a
lower mode the shaft only shares (mutation hunt h33c).

:func:`flexshaft.analyses.stability.stability` documents ω_ref (the viscous internal-damping
model's one frequency) as "the lowest basis frequency whose mode is more than 50 % shaft (the
first shaft bending mode at rest)". tests/test_jeffcott_modes_closed_form.py checks that a boom
mode with no shaft motion is passed over; here the lower mode carries a quarter of its kinetic
energy in the shaft, so a rule reading any sizeable shaft share would take it.

The driveline: the Jeffcott rotor of tests/rotors.py (20 kg disk at midspan, four elements), free
of the ground laterally and held at both ends by stiff bearings (1e7 N/m) on a short aluminium
tailboom (1.2 m, 20 kg end mass). The reference is computed here, independently of the package's
reduction: LAPACK's dense generalised eigen-solve of (K, M) on the free DOFs, and each mode's
kinetic-energy share φᵀM_shaft φ / φᵀMφ over the shaft's six DOFs per node. The premise: the
first mode (the boom bending with the rotor riding on it, ≈ 173 rad/s) has a shaft share
between 5 % and 50 %, the third (the shaft bending on the flexible boom, ≈ 313 rad/s) more than
half. ω_ref is that third mode's frequency. Tolerance 1e-5 relative: the near-massless tube
(density 0.1, tests/rotors.py) leaves M nearly singular, and the eigenvalues move with the solver:
two LAPACK drivers (eigh with and without vectors) agree to 3e-7 here and the package's
48-vector reduction to 2e-7 (measured); the rule's wrong pick would be 45 % off. About 0.03 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import jeffcott_text

from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

BEARINGS = """[materials.al]
kind = "isotropic"
E = 7e10
G = 2.7e10
density = 2700.0
[tailboom]
length = 1.2
root_semi_axes = [0.1, 0.1]
tip_semi_axes = [0.1, 0.1]
wall_thickness = 0.002
material = "al"
shaft_clearance = 0.05
[tailboom.end_mass]
mass = 20.0
offset = [0.0, 0.0, 0.0]
inertia = [0.0, 0.0, 0.0]
[[bearings]]
name = "front"
kind = "contact"
x = 0.0
stiffness = { v = 1e7, w = 1e7 }
[[bearings]]
name = "rear"
kind = "contact"
x = 1.0
stiffness = { v = 1e7, w = 1e7 }
[[bearings]]"""


def _model():
    text = jeffcott_text(0.01, 0.0, elements=4).replace("damping = { v = 0.0, w = 0.0 }", "")
    text = text.replace('fixed_start = ["u", "v", "w", "theta"]', 'fixed_start = ["u", "theta"]')
    text = text.replace('fixed_end = ["v", "w"]', "fixed_end = []")
    text = text.replace("[[bearings]]", BEARINGS, 1).replace("[mesh]", "[mesh]\nboom_elements = 4")
    return build_model(loads_design(text))


def shaft_shares(model) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The undamped modes of K + K_p (the magnets' static stiffness) on M, dense: their ω²,
    and each mode's share of its kinetic (φᵀMφ) and strain (φᵀKφ, K without the magnets)
    energy held by the shaft's DOFs."""
    dm = model.dofs
    free = dm.free
    K = (model.K + model.Kp)[free][:, free].toarray()
    M = model.M[free][:, free].toarray()
    w2, V = la.eigh(K, M)
    phi = np.zeros((dm.size, V.shape[1]))
    phi[free] = V
    shaft = np.zeros(dm.size, dtype=bool)
    nodes = np.arange(dm.n_shaft_nodes)
    shaft[np.concatenate([dm.shaft(nodes, f) for f in ("u", "v", "w", "theta", "beta", "gamma")])] = True
    Mphi, Kphi = model.M @ phi, model.K @ phi
    kinetic = np.einsum("ij,ij->j", phi[shaft], Mphi[shaft]) / np.einsum("ij,ij->j", phi, Mphi)
    strain = np.einsum("ij,ij->j", phi[shaft], Kphi[shaft]) / np.einsum("ij,ij->j", phi, Kphi)
    return w2, kinetic, strain


def test_reference_frequency_is_the_first_mode_more_than_half_shaft():
    model = _model()
    w2, share, _ = shaft_shares(model)
    assert 0.05 < share[0] < 0.5 and w2[0] > 0  # the premise: a lower mode the shaft shares
    first = int(np.flatnonzero(share > 0.5)[0])
    assert first > 0
    result = stability(model, [0.0, 100.0], n_modes=4, damping_model="viscous")
    assert result.reference_frequency == pytest.approx(np.sqrt(w2[first]), rel=1e-5)
