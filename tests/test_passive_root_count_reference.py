"""The passive every-root check without the loss-free solve (flexshaft.analyses.root_stability).

A passive driveline's check solves its roots on the loss's two branches; the loss-free state
matrix was solved as well, for its real roots only (a divergence, which the energy argument
rules out when the basis stiffness is positive semi-definite), and is no longer solved then.

References, on the Jeffcott-like rotor of tests/rotors.py (η = 0.02, ζ_e = 0.005, the rotating
loss; derived in tests/test_damping.py):

* The count. Every modal coordinate of this lightly damped model contributes one oscillatory root
  with Im s > 0 to the loss-consistent set R(Ω) (each mode's root lies on its own side of the
  spin, none near it: checked), so the roots examined at each speed are the basis size, with no
  real root to add (derived: a real root needs an overdamped mode, ζ >= 1; the model's largest
  damping is the disk's ζ_e = 0.005 and the loss's η/2).
* The guard. A basis mode given a negative stiffness −a² (a = ω_n/2; the disk's mode in one
  plane: no design input yields one, the test sets it) makes the loss-free closed loop diverge:
  its real root solves ``s² + (c_e/m) s − a² = 0`` (the disk mode's modal damping c_e/m; the
  near-massless tube, 7e-6 of the disk mass, leaves about 1e-8: 1e-6 asserted), which the check
  must still find, the loss-free solve being kept for a stiffness that is not semi-definite.

Small model (8 elements), a few tenths of a second.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from rotors import M_DISK, WN, jeffcott

from flexshaft.analyses import root_stability as rs
from flexshaft.analyses.root_stability import root_stability

ETA, C_E = 0.02, 2 * 0.005 * M_DISK * WN


def test_a_passive_check_examines_one_root_per_mode():
    speeds = [0.0, 0.6 * WN, 1.6 * WN]
    result = root_stability(jeffcott(ETA, C_E), speeds)
    assert result.method == "passive"
    for speed, roots, count in zip(speeds, result.roots, result.n_roots):
        if speed:
            assert np.min(np.abs(roots.imag - speed)) > 0.01 * speed  # no mode near the spin
        assert np.all(roots.imag > 0)
        assert count == roots.size == result.basis_size
    assert all(r.kind == "oscillatory" for r in result.unstable)


def test_a_passive_check_with_a_negative_stiffness_still_finds_the_divergence(monkeypatch):
    a = 0.5 * WN
    lateral_basis = rs._lateral_basis

    def softened(model, red):
        red = lateral_basis(model, red)
        w2 = red.w2.copy()
        w2[int(np.argmin(np.abs(w2 - WN**2)))] = -(a**2)  # the disk's mode in one plane
        return dataclasses.replace(red, w2=w2)

    monkeypatch.setattr(rs, "_lateral_basis", softened)
    result = root_stability(jeffcott(ETA, C_E), [0.6 * WN])
    assert result.method == "passive"
    divergent = [r for r in result.unstable if r.kind == "divergence"]
    c = C_E / M_DISK
    assert len(divergent) == 1
    assert divergent[0].root == pytest.approx((-c + np.sqrt(c * c + 4 * a * a)) / 2, rel=1e-6)
