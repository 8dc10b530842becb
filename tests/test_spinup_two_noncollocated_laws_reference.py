"""Spin-up curves of two different non-collocated bearings on one disk, by hand.

The Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk at midspan of a near-massless
pinned-pinned tube of length L = 1 m, k = 48EI/L³ = 1.826e6 N/m) carries two ideal PD magnetic
bearings at the disk (k_i = 1, k_s = 0, no lag) with different laws: "a" with
G_a = 1e5 + iΩ 50 whose sensor reads the shaft 0.25 m aft of the disk, "b" with
G_b = 4e5 + iΩ 200 whose sensor reads it 0.1 m forward. Every force acts at midspan and the tube
is massless, so the tube takes the static shape of a midspan-loaded simply supported beam,
y(x)/y(L/2) = φ(x) = (x/L)(3 − 4(x/L)²) for x ≤ L/2 (symmetric about midspan): the sensors read
φ_a = φ(0.25) = 0.6875 and φ_b = φ(0.4) = 0.944 of the disk's deflection r. In complex
coordinates (each law the same on v and w) the disk's forward circle and the carried forces are

    r = UΩ²/|k − mΩ² + φ_a G_a + φ_b G_b|,     F_a = |G_a| φ_a r,   F_b = |G_b| φ_b r,

and the relative orbit at both magnets (at the disk, the ground fixed) is r. The speeds 100, 300
and 500 rad/s straddle the undamped resonance √((k + φ_a 1e5 + φ_b 4e5)/m) = 337 rad/s.

Tolerance 1e-4 relative: the tube's mass (3.5e-6 of the disk's) shifts the resonance by ~1e-6
relative, which the 11 % distance of 300 rad/s from it amplifies a few-fold (measured 6.4e-6 on
every output, OpenBLAS Prescott and Haswell alike); 1e-4 is 15× that. The laws differ 4×, so a law
put on the other bearing's axis moves the outputs by 30 % or more (measured): the catch is
unaffected by the tighter bound.

Written for the mutation h54b-spinup-noncollocated-gain-order of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector
from rotors import K_SHAFT, M_DISK, jeffcott_text

from flexshaft.analyses.spinup import actuator_receptance, spinup_curves
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

LAWS = {"a": (1.0e5, 50.0, 0.25), "b": (4.0e5, 200.0, -0.1)}  # kp [N/m], kd [N s/m], sensor offset [m]
SPEEDS = np.array([100.0, 300.0, 500.0])  # rad/s


def _shape(x: float) -> float:
    """Deflection at x over the midspan's of a simply supported unit beam under a midspan load."""
    x = min(x, 1.0 - x)
    return x * (3.0 - 4.0 * x * x)


def _model():
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    bearings = "".join(
        f'[[bearings]]\nname = "{name}"\nx = 0.5\nkind = "active"\nkp = {kp}\nkd = {kd}\nsensor_offset = {offset}\n'
        for name, (kp, kd, offset) in LAWS.items()
    )
    return build_model(loads_design(head + bearings + tail))


def test_two_different_noncollocated_laws_on_one_disk():
    model = _model()
    assert [a.collocated for a in model.actuators] == [False, False]
    rec = actuator_receptance(model, SPEEDS, imbalance_vector(model)[:, None])
    curves = spinup_curves(rec, [(kp, kd) for kp, kd, _ in LAWS.values()])
    laws = {name: kp + 1j * SPEEDS * kd for name, (kp, kd, _) in LAWS.items()}
    seen = {name: _shape(0.5 + offset) for name, (_, _, offset) in LAWS.items()}
    assert seen["a"] == pytest.approx(0.6875, rel=1e-12) and seen["b"] == pytest.approx(0.944, rel=1e-12)
    r = U * SPEEDS**2 / np.abs(K_SHAFT - M_DISK * SPEEDS**2 + sum(seen[n] * laws[n] for n in LAWS))
    node = model.dofs.node_at("shaft", 0.5)
    assert curves.shaft_orbit[node] == pytest.approx(r, rel=1e-4)
    for k, name in enumerate(LAWS):
        assert curves.actuator_displacement[k] == pytest.approx(r, rel=1e-4)
        assert curves.actuator_force[k] == pytest.approx(np.abs(laws[name]) * seen[name] * r, rel=1e-4)
