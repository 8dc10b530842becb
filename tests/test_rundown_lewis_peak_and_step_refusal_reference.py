"""A run-down through the critical speed by Lewis's asymptote, and the rigid-body rule of the
step-count refusal, by hand.

* **Run-down through the critical.** The undamped Jeffcott rotor of tests/rotors.py (a 20 kg disk
  on a near-massless pinned-pinned tube, ω = √(k/m), k = 48EI/L³) with an imbalance U at the
  disk runs down at constant deceleration α from 1.3 ω to rest. In complex coordinates
  m r̈ + k r = UΩ² e^{iφ}; near the critical, r = A e^{iωt} with A slow gives
  2iωm Ȧ ≈ UΩ² e^{i(φ − ωt)}, and φ − ωt = const − α s²/2 (s the time after Ω = ω). The
  deceleration's Fresnel integral is the complex conjugate of the acceleration's, so |A| is
  Lewis's (1932) run-up result, derived here for the mirror case: largest |A|/e = ½√(π/λ) F*,
  F* = max|C(u) + ½ + i(S(u) + ½)| = 1.65556 (λ = α/ω², e = U/m), reached at s = u*√(π/α), i.e.
  at Ω = ω(1 − u*√(πλ)) (below ω, where the run-up's is above). After the passage, the free
  whirl left (|A(∞)| = √2/F* of the peak) plus the forced orbit below 0.9 ω (at most
  0.81/0.19 e) stays at least 5 % below the peak (bound 5.4 %, measured 6.5 %), so the peak is
  the run's largest envelope. The neglected terms are O(√λ) (tests/test_transient.py measures
  1.6 % at λ = 1e-3 for the run-up; measured here 1.6 % and 3e-6 in speed): 2.5 % and 2e-4 ω.
  Integrated at the default rtol = 1e-5 over 71 steps: at most 7e-4 of the peak.
  The default output step is 8 samples per period of the fastest envelope content, whose
  angular frequency is the run's largest speed Ω_max (docstring of ``output_step``:
  π/(4 Ω_max)); for a run-down that is its first speed, not its last.
* **The culprit of a refused run.** A run that would need more than MAX_STEPS integration steps
  is refused before integrating; the message blames a disk only when its polar inertia exceeds
  twice its diametral one, which no rigid body has (with x the axis, 2 I_d − I_p = 2∫x² dm ≥ 0,
  zero for a flat disk; the docstring of ``_gyroscopic_culprit``). A thick disk
  with I_p = 1.6 I_d is physical and is not blamed; nor is the flat disk's limit I_p = 2 I_d
  exactly (0.1/0.05 kg m², a quotient of exactly 2.0 in binary: the rule is strict); one with
  I_p = 3 I_d is. All three runs are refused (about 2.3e5, 2.9e5 and 4.3e5 steps for a 2e4-s run
  to 1000 rad/s, more than 1e5), so the integration is never reached (replaced here by a stub
  that fails the test if it is).

Written for the mutations h54b-runup-top-speed-is-final-speed and h54b-runup-culprit-ratio-one
of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector
from rotors import M_DISK, WN, jeffcott_text
from scipy.optimize import minimize_scalar
from scipy.special import fresnel

import flexshaft.analyses.transient as transient_module
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.analyses.transient import run_up
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def test_a_run_down_through_the_critical_reaches_lewis_peak():
    result = minimize_scalar(lambda u: -np.hypot(*(np.array(fresnel(u))[::-1] + 0.5)), bracket=(1.1, 1.2, 1.3))
    u_star, f_star = result.x, -result.fun
    assert f_star == pytest.approx(1.65556, abs=1e-5)
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=4)))
    lam = 1e-3
    alpha = lam * WN**2
    start = 1.3 * WN
    run = run_up(
        model, start / alpha, start=start, stop=0.0, loads_per_speed_squared=imbalance_vector(model), basis_size=2
    )
    value, _, speed = run.peak()
    asymptote = 0.5 * np.sqrt(np.pi / lam) * f_star * (U / M_DISK)
    assert value == pytest.approx(asymptote, rel=2.5e-2)
    assert speed / WN == pytest.approx(1 - u_star * np.sqrt(np.pi * lam), abs=2e-4)
    assert np.diff(run.time).max() <= np.pi / (4 * start) * (1 + 1e-12)


@pytest.mark.parametrize("ratio, blamed", [(1.6, False), (2.0, False), (3.0, True)])
def test_only_an_impossible_disk_is_blamed_for_a_refused_run(monkeypatch, ratio, blamed):
    def _integrator(*args, **kwargs):
        raise AssertionError("the run was integrated instead of refused")

    monkeypatch.setattr(transient_module, "integrate_envelope", _integrator)
    diametral = 0.05
    text = jeffcott_text(0.0, 200.0, elements=4).replace(
        "mass = 20.0", f"mass = 20.0\ndiametral_inertia = {diametral}\npolar_inertia = {ratio * diametral}"
    )
    model = build_model(loads_design(text))
    with pytest.raises(RefusedInputError, match="integration steps") as refusal:
        run_up(model, 2.0e4, stop=1000.0, basis_size=6, output_step=5.0e3)
    assert ("disks[0].polar_inertia" in str(refusal.value)) is blamed
