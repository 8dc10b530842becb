"""The passive every-root check reports its last basis whatever its estimate.

Rule (docs/model.md, "Accuracy of the reduced eigenvalues": when the largest estimate exceeds
the tolerance the basis size doubles, up to a bound, and "the result reports what was
reached"). The code's docstring (code, not a hand-written doc: ``_passive_bases`` in
flexshaft.analyses.root_stability) states it for this check: the bases are tried in order
until one's estimated error of the roots below the spin is within the tolerance; "the last
basis's estimate is reported whatever it is". The last basis is never left at a failing
speed: every speed is solved on it and the check returns.

The natural case needs a model with more free DOFs than 4·max(4n, 60) = 240 (else the last
basis is the whole model, whose estimate is 0), whose four bases up to 276 vectors cost about
1 s; here the list of bases is shortened to one small basis instead, the disk's two undamped
modes with no correction, which is then the last.

Reference (derived here). The Jeffcott-like rotor of tests/rotors.py with a steel tube
(ρ = 7800 kg/m³: 5.5 kg against the 20 kg disk, so the disk's modes alone are a genuinely
truncated basis) at η = 0.02, ζ_e = 0.005 and Ω = 1.5 ω_n: the forward disk root lies below the
spin, its loss circulatory, and η/2 = 0.01 > ζ_e makes it unstable, its growth rate about
(η/2 − ζ_e) ω₁ > 0. On the two-mode basis its estimated error is 1.3e-8 (measured), so a
tolerance of 1e-12 fails it by four orders of magnitude: the check must still return that
basis's roots (the unstable forward root among them) with the estimate it reached, above the
tolerance, and that estimate must be the root's relative distance from the full model's within
a factor 3 (docs/model.md, *The estimate*: estimate/true error 0.98-1.02 measured there; here
1.3e-8 both, ratio 1.0004), the full model's root being the same check on a list holding the
whole model (no reduction, estimate 0). A few hundredths of a second.
"""

from __future__ import annotations

import numpy as np
from rotors import M_DISK, WN, jeffcott_text

from flexshaft.analyses import root_stability as rs
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, C_E = 0.02, 2 * 0.005 * M_DISK * WN
SPEED = 1.5 * WN
TOLERANCE = 1e-12


def steel_rotor():
    text = jeffcott_text(ETA, C_E).replace("density = 0.1", "density = 7800.0")
    return build_model(loads_design(text))


def test_a_last_basis_that_misses_the_tolerance_is_reported_with_its_estimate(monkeypatch):
    model = steel_rotor()
    n_free = int(model.dofs.free.size)

    monkeypatch.setattr(rs, "_passive_bases", lambda *_: [(n_free, 0)])
    full = rs.root_stability(model, [SPEED], tolerance=TOLERANCE)
    assert full.method == "passive" and full.error_estimate == 0.0
    assert len(full.unstable) == 1
    exact = full.unstable[0].root
    assert exact.real > 0 and exact.imag < SPEED

    monkeypatch.setattr(rs, "_passive_bases", lambda *_: [(2, 0)])
    result = rs.root_stability(model, [SPEED], tolerance=TOLERANCE)  # the last basis: returned
    assert result.method == "passive" and result.basis_size == 2 and result.tolerance == TOLERANCE
    assert result.error_estimate is not None and result.error_estimate > 100 * TOLERANCE
    assert len(result.unstable) == 1 and result.onset_speed == SPEED
    root = result.unstable[0].root
    true_error = abs(root - exact) / abs(exact)
    assert true_error > 100 * TOLERANCE
    assert true_error / 3 <= result.error_estimate <= 3 * true_error
    assert np.all(result.roots[0].imag > 0)
