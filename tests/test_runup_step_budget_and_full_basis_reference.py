"""The run-up's step-count refusal by the rigid disk's gyroscopic ratio, and the full modal
basis as a valid request, by hand.

* **Step budget.** The envelope integrator treats the gyroscopic drift (Ω − Ω_ref) G̃ between
  two refreshes of the eigenbasis explicitly; the basis is refreshed when Ω has moved by 2 % of
  its largest value (docs/transient.md), so the drift rate is 0.02 Ω_max ‖G̃‖₂ and a step must
  keep h × rate below the scheme's stability bound c. Derived here: with a zero linear part
  ETDRK4 is RK4, whose stability function R(z) = 1 + z + z²/2 + z³/6 + z⁴/24 gives, on the
  imaginary axis z = iy, |R|² = 1 − y⁶/72 + y⁸/576 ≤ 1 exactly for y ≤ 2√2 = 2.83; the code
  uses c = 2.8 (a source comment of ``flexshaft.analyses.envelope``, not docs/*.md: the bound
  rounded down). A run of duration D then needs D × 0.02 Ω_max ‖G̃‖₂ / c steps, and docs/limits.md
  says the run-up refuses, before integrating, one that needs more than MAX_STEPS = 100,000.
  Derived here: on the Jeffcott rotor of tests/rotors.py (pinned-pinned near-massless tube,
  midspan disk with diametral I_d and polar I_p inertias), the disk's tilt pair has modal
  coordinates mass-normalised by I_d (θ² I_d = 1) and gyroscopic coupling I_p θ², so
  ‖G̃‖₂ = I_p/I_d; the translation modes carry no tilt at the midspan disk and the tube's own
  inertia is 3.5e-6 of the disk's. With the flat disk's I_p = 2 I_d, Ω_max = 1000 rad/s:
  D = 2450 s needs 2450 × 0.02 × 1000 × 2 / c ≈ 35,000 steps, below the limit for any
  c > 0.98 (accepted; the integrator, a stub here, is reached), D = 2e4 s needs 2.83e5 to 2.86e5
  for c between 2.8 and 2√2 (refused; the message's three digits must lie in that range, each
  end widened by the 2e-3 of its rounding).
* **Full basis.** docs/limits.md: the run-up refuses "a ``basis_size`` above the model's free
  DOFs", so a basis of every free DOF (the unreduced model) is accepted, and one more is
  refused. With every mode kept, the constant-speed response held from its steady state is the
  undamped Jeffcott rotor's, derived here: m r̈ + k r = U Ω² e^{iΩt} gives the whirl radius
  |r| = (U/m) Ω² / (ω² − Ω²), at Ω = ω/2: (U/m)/3. The tube's mass, (17/35) × 3.55e-6 =
  1.7e-6 of the disk's as Rayleigh's effective mass, enters r = UΩ²/(k − m(1 + ε)Ω²) as
  ε Ω²/(ω² − Ω²) = ε/3 = 5.7e-7, which is what is measured; 2e-5 allowed (35 times that).

Written for the mutations h67c-runup-step-budget-times-stable-step and
h67c-transient-full-basis-refused of scripts/mutations.toml.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from jeffcott_bearing import U, imbalance_vector
from rotors import M_DISK, WN, L, jeffcott_text

import flexshaft.analyses.transient as transient_module
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.analyses.speed_profile import SpeedProfile
from flexshaft.analyses.transient import run_up, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

MAX_STEPS = 100_000  # docs/limits.md
I_D = 0.05  # kg m², the flat disk's diametral inertia; I_p = 2 I_d
TOP = 1000.0  # rad/s


class _Reached(Exception):
    """The integration was reached: the run passed every refusal before it."""


def _flat_disk_rotor():
    text = jeffcott_text(0.0, 200.0, elements=4).replace(
        "mass = 20.0", f"mass = 20.0\ndiametral_inertia = {I_D}\npolar_inertia = {2 * I_D}"
    )
    return build_model(loads_design(text))


def _steps(duration: float) -> float:
    return duration * 0.02 * TOP * 2.0 / 2.8


def test_a_run_within_the_step_budget_is_integrated(monkeypatch):
    def _integrator(*args, **kwargs):
        raise _Reached

    monkeypatch.setattr(transient_module, "integrate_envelope", _integrator)
    duration = 2450.0
    assert _steps(duration) == pytest.approx(35_000.0, rel=1e-12)
    assert _steps(duration) < MAX_STEPS
    with pytest.raises(_Reached):
        run_up(_flat_disk_rotor(), duration, stop=TOP, basis_size=6, output_step=1.0e3)


def test_a_run_over_the_step_budget_is_refused_with_its_step_count(monkeypatch):
    def _integrator(*args, **kwargs):
        raise AssertionError("the run was integrated instead of refused")

    monkeypatch.setattr(transient_module, "integrate_envelope", _integrator)
    duration = 2.0e4
    with pytest.raises(RefusedInputError, match="integration steps") as refusal:
        run_up(_flat_disk_rotor(), duration, stop=TOP, basis_size=6, output_step=5.0e3)
    quoted = float(re.search(r"about ([0-9.e+]+) integration steps", str(refusal.value)).group(1))
    rate_steps = duration * 0.02 * TOP * 2.0  # steps × c
    assert rate_steps / (2.0 * np.sqrt(2.0)) * (1 - 2e-3) <= quoted <= rate_steps / 2.8 * (1 + 2e-3)


def test_a_basis_of_every_free_dof_is_accepted_and_one_more_refused():
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=4)))
    n_free = model.dofs.free.size
    speed = 0.5 * WN
    profile = SpeedProfile.table([0.0, 0.05], [speed, speed])
    loads = imbalance_vector(model)
    run = transient_response(model, profile, loads_per_speed_squared=loads, basis_size=n_free, output_step=0.01)
    assert run.basis_size == n_free
    node = model.dofs.node_at("shaft", L / 2)
    expected = (U / M_DISK) * speed**2 / (WN**2 - speed**2)
    assert np.max(np.abs(run.shaft_orbit[node] / expected - 1)) <= 2e-5
    with pytest.raises(RefusedInputError, match="basis_size must be at most"):
        transient_response(model, profile, loads_per_speed_squared=loads, basis_size=n_free + 1, output_step=0.01)
