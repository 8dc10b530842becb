"""What the operating point's strength checks make of the imbalance response
(:func:`flexshaft.verdict.operating_point.analyse_point`), against a closed form and a
superposition identity.

* **The metal check carries the imbalance whirl as a mean bending stress.** The Jeffcott-like
  rotor of tests/rotors.py (a 20 kg disk at midspan of a near-massless pinned-pinned steel tube,
  no damping) given steel strengths, spinning at Ω = ω_n/2 with an eccentricity e. The
  imbalance force F = e m Ω² (m the rotating mass: disk plus tube) acts at midspan (the mid-bay
  of the one bay); with the disk's inertia force m_d Ω² |r| (below the critical, in phase with
  F; |r| the disk's orbit radius) the tube carries P = F + m_d Ω² |r| at midspan. The orbit is
  the Jeffcott closed form (derived here): the undamped disk m_d r̈ + k r = F e^{iΩt} whirls at
  |r| = F/(k − m_d Ω²), so P = F (1 + m_d Ω²/(k − m_d Ω²)) = F/(1 − Ω²/ω_n²), with
  ω_n² = k/m_d = 48 E I/(L³ m_d); at Ω = ω_n/2, P = 4F/3. A synchronous forward whirl, so every
  section bends by the moment
  M(x) = P min(x, L − x)/2 (statics of the pinned-pinned beam) in a plane that turns with the
  shaft: a bending stress frozen in the material, the mean σ_m = M r_o / I at the outer fibre
  (Shigley's mean stress; the metal-strength module's rule "a mean stress E r |a_f| on the worst
  fibre"). No axial load and no torque: nothing else is mean. Dropping the imbalance leaves no
  mean stress at all. Tolerance 2e-5: the tube's distributed inertia, 3.5e-6 of the disk's, is
  the only term left out, in the orbit and in the bending alike (measured: P 1.4e-7 from
  4F/3, the stresses within 7e-7).
* **Removing the imbalance from static + imbalance leaves the static check.** With the report's
  detail the point's static + imbalance ply check also gives its leave-one-out safety factors
  (:func:`~flexshaft.analyses.shaft_strength.shaft_safety_factor`, "the minimum safety factor
  with one load removed"); without the imbalance the loads are exactly the static check's
  (same torque factor, temperature, residual stress and kinking), so that factor equals the
  point's static safety factor (1e-12 relative: the same sums over the same ply stresses; the
  phases of the removed imbalance only repeat the static grid).
* **The imbalance check does not depend on the time origin of the whirl.** The response at
  speed is a complex amplitude q: the shaft's displacement is Re(q e^{iΩt}), and the ply check
  sweeps the whole turn (72 phases φ_k = 2πk/72). Shifting the time origin by a quarter turn
  turns q into i q and maps the phase grid onto itself (18 steps), so the point's static +
  imbalance safety factor must equal the same check of i q (1e-12 relative: the two evaluate
  e^{iφ} at different arguments, ~1e-16 apart, through a well-conditioned Tsai-Wu root). Only
  the real part Re(q) would be a different, planar loading (measured 2.40 against 2.06). The
  tuned design with a poorly balanced shaft (e = 0.91 mm, 50 × its own), where the imbalance
  lowers the static safety factor (2.82) by more than a quarter.

CPU: the Jeffcott point 0.06 s, the tuned design's coarse points 0.35 s and 0.4 s.
"""

from __future__ import annotations

import numpy as np
from conftest import SMALLEST
from rotors import DI, DO, M_DISK, WN, L, jeffcott_text

from flexshaft.analyses.shaft_strength import shaft_safety_factor
from flexshaft.design import loads_design, tuned_design, with_overrides
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict import operating_point

OMEGA, ECCENTRICITY = 0.5 * WN, 1e-4
TUBE_DENSITY = 0.1  # tests/rotors.py's near-massless tube


def _jeffcott_with_strengths():
    text = jeffcott_text(0.0, 0.0).replace(
        "loss_factor = 0.0",
        "loss_factor = 0.0\nyield_strength = 250e6\nultimate_strength = 400e6\nfatigue_strength = 150e6",
    )
    text = text.replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(OMEGA)}")
    return loads_design(text + f"[loads]\neccentricity = {ECCENTRICITY}\n")


def test_the_metal_mean_stress_is_the_imbalance_whirls_bending():
    p = operating_point.analyse_point(_jeffcott_with_strengths(), SMALLEST, detail=False)
    metal = p.metal_strength
    area, inertia = np.pi * (DO**2 - DI**2) / 4, np.pi * (DO**4 - DI**4) / 64
    force = ECCENTRICITY * (M_DISK + TUBE_DENSITY * area * L) * OMEGA**2
    load = force / (1.0 - (OMEGA / WN) ** 2)  # the Jeffcott closed form: 4F/3 at Ω = ω_n/2
    x = np.asarray(metal.x)
    expected = load * np.minimum(x, L - x) / 2 * (DO / 2) / inertia
    peak = load * L / 4 * (DO / 2) / inertia
    assert peak > 1e6  # a stress far above round-off: 2.1 MPa
    np.testing.assert_allclose(metal.sigma_mean, expected, rtol=2e-5, atol=2e-5 * peak)


def test_the_static_plus_imbalance_check_without_the_imbalance_is_the_static_check():
    coarse = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}
    p = operating_point.analyse_point(with_overrides(tuned_design(), coarse), SMALLEST, detail=True)
    without = p.strength_total.safety_factor_without
    assert "imbalance" in without
    np.testing.assert_allclose(without["imbalance"], p.strength_static.safety_factor, rtol=1e-12)


def test_the_imbalance_check_is_the_same_a_quarter_turn_later(monkeypatch):
    calls = []

    def recorded(model, parts, dynamic=None, **options):
        result = shaft_safety_factor(model, parts, dynamic, **options)
        calls.append((parts, dynamic, options))
        return result

    monkeypatch.setattr(operating_point, "shaft_safety_factor", recorded)
    unbalanced = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12, "loads.eccentricity": 9.1e-4}
    p = operating_point.analyse_point(with_overrides(tuned_design(), unbalanced), SMALLEST, detail=False)
    (parts, dynamic, options) = calls[-1]
    assert dynamic is not None and p.imbalance_at_speed.shape[1] == 1
    assert p.strength_total.safety_factor < 0.75 * p.strength_static.safety_factor  # the imbalance matters
    later = shaft_safety_factor(p.model, parts, 1j * p.imbalance_at_speed[:, 0], **options)
    np.testing.assert_allclose(p.strength_total.safety_factor, later.safety_factor, rtol=1e-12)
