"""A given tail-rotor aerodynamic damping, including zero, replaces the default 2P/Ω².

docs/model.md (the tail rotor): the rotor adds "aerodynamic damping ``c_r = (dQ/dΩ)/n²`` to
ground (default ``2P/Ω²``...)": the default applies only when the key is omitted. A given
dQ/dΩ is reflected through the gearbox by 1/n² (φ_shaft = n φ_rotor, the dissipated power
c_tr Ω_tr² = c_r Ω² kept), so dQ/dΩ = 0 (a rotor whose torque does not change with speed, e.g.
a test rig's pure inertia) gives c_r = 0 exactly, whatever P and Ω; the default 2P/Ω² is
derived in tests/test_tail_rotor_damping_reference.py. The values are single divisions of
exact inputs: 1e-14 relative (a few ulps), and exact 0 for the zero case.
"""

from __future__ import annotations

import pytest

from flexshaft.design.drivetrain import TailRotor

POWER, SPEED = 100.0e3, 314.0  # W, rad/s: 2P/Ω² = 2.03 N m s/rad, far from 0


def _rotor(**extra) -> TailRotor:
    return TailRotor(blades=4, polar_inertia=12.0, gearbox_ratio=3.4, **extra)


def test_zero_aerodynamic_damping_is_no_damping_not_the_default():
    assert 2 * POWER / SPEED**2 > 1.0  # the default would be clearly non-zero here
    assert _rotor(aerodynamic_damping=0.0).reflected_damping(POWER, SPEED) == 0.0


def test_given_aerodynamic_damping_is_reflected_by_one_over_n_squared():
    c_tr, n = 50.0, 3.4
    assert _rotor(aerodynamic_damping=c_tr).reflected_damping(POWER, SPEED) == pytest.approx(c_tr / n**2, rel=1e-14)


def test_omitted_aerodynamic_damping_is_the_default():
    assert _rotor().reflected_damping(POWER, SPEED) == pytest.approx(2 * POWER / SPEED**2, rel=1e-14)
