"""The viscous method's default reference frequency on a rotor bouncing on soft magnetic
bearings: the first mode whose kinetic energy is mostly the shaft's, not its strain energy
(mutation hunt h43b).

:func:`flexshaft.analyses.stability.stability` documents ω_ref as "the lowest basis frequency
whose mode is more than 50 % shaft (the first shaft bending mode at rest)";
tests/test_viscous_reference_shaft_majority_reference.py measures the share as the kinetic
energy φᵀM_shaft φ / φᵀMφ. There the bearings are contact springs in K, and for an eigenvector of
(K, M) the shaft rows of Kφ = ω²Mφ make a stiffness share equal to the kinetic one. Here the
same boomed Jeffcott rotor (tests/rotors.py: 20 kg disk at midspan of a near-massless tube,
k = 48EI/L³) is held by two PD magnets of K_p = 1e5 N/m (no K_d) on a thin-walled boom (0.5 mm
wall, 2 kg end mass): its lowest pair, the rotor bouncing on the magnets at about 88 rad/s,
carries 99 % of its kinetic energy in the shaft (the disk) but only about a third of the strain
energy of K (the rest is the boom's, the magnets' being outside K): a share read from the
stiffness would pass it over for the tube's own mode near 3850 rad/s.

The reference is computed here, independently of the package's reduction: LAPACK's dense
generalised eigen-solve of (K + K_a, M) on the free DOFs, K_a = K_p B_aᵀB_a the magnets' basis
stiffness (the model's Kp), and each mode's kinetic-energy share over the shaft's six DOFs per
node. Tolerance 1e-5 relative, as the contact-bearing test on this rotor (the near-singular M of
the near-massless tube; measured 3.3e-6 against the package's 48-vector reduction).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text
from test_viscous_reference_shaft_majority_reference import BEARINGS, shaft_shares

from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

MAGNET = 'kind = "active"\nkp = 1e5\nkd = 0.0'


def _model():
    bearings = BEARINGS.replace("wall_thickness = 0.002", "wall_thickness = 0.0005")
    bearings = bearings.replace("mass = 20.0", "mass = 2.0")
    for x in ("0.0", "1.0"):
        contact = f'kind = "contact"\nx = {x}\nstiffness = {{ v = 1e7, w = 1e7 }}'
        assert contact in bearings
        bearings = bearings.replace(contact, f"{MAGNET}\nx = {x}")
    text = jeffcott_text(0.01, 0.0, elements=4).replace("damping = { v = 0.0, w = 0.0 }", "")
    text = text.replace('fixed_start = ["u", "v", "w", "theta"]', 'fixed_start = ["u", "theta"]')
    text = text.replace('fixed_end = ["v", "w"]', "fixed_end = []")
    text = text.replace("[[bearings]]", bearings, 1).replace("[mesh]", "[mesh]\nboom_elements = 4")
    return build_model(loads_design(text))


def test_reference_frequency_of_a_rotor_on_soft_magnets_is_its_bounce():
    model = _model()
    assert len(model.actuators) == 2
    w2, kinetic, strain = shaft_shares(model)
    # the premise: the lowest mode is the shaft's by kinetic energy, not by K's strain energy
    assert kinetic[0] > 0.9 and strain[0] < 0.5 and w2[0] > 0
    result = stability(model, [0.0, 100.0], n_modes=4, damping_model="viscous")
    assert result.reference_frequency == pytest.approx(np.sqrt(w2[0]), rel=1e-5)
