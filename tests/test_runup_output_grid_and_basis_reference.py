"""The run-up's output instants, its default basis and its refusal of long unstable dwells, by hand.

* **Output instants.** :func:`transient_response` reports at evenly spaced instants from t = 0 to
  the end of the profile t = T (its docstring: ``output_step`` is their spacing), so the last
  output is the end of the run, Ω(T) the top speed, and no spacing exceeds the step asked for.
  A constant-acceleration ramp from Ω₀ to Ω₁ in T has φ(T) = (Ω₀ + Ω₁) T / 2 (the integral of a
  linear speed).
* **Default output step** (:func:`default_output_step`): 8 samples per period of the fastest
  envelope content, whose angular frequency is Ω_max, i.e. 2π/(8 Ω_max) = π/(4 Ω_max) (the
  docstring of ``output_step``).
* **Default basis** (:func:`default_basis_size`): every undamped mode below 4 × the largest
  speed. Counted here by a dense generalized eigenproblem (scipy.linalg.eigh of the free K, M),
  an independent solver, on a 20-element Jeffcott tube with 120 free DOFs and a cut-off that
  takes more than the search's first 60 trial modes.
* **Accumulated growth.** A run is refused when ∫ max(0, largest Re λ) dt over its dwells
  exceeds ln MAX_GROWTH (the docstring of ``_refuse_growth_at_constant_speed``: the growth of
  a free whirl held there). Two dwells of 5 s at the Jeffcott rotor's unstable Ω = 2ω_n
  (growth rate ≈ 1.0 1/s: ηω_n/6 from the run-up's causal loss model, whose reference
  frequency is ω_n + Ω, tests/test_runup_unstable_dwell_reference.py; the hysteretic
  eigen-analysis's branch gives ηω_n/2) grow e^5 each,
  below MAX_GROWTH = 1e3 = e^6.9 alone, e^10 together: refused.

* **Every free DOF.** A shaft whose first free DOF (index 0 of the free set) is its start node's
  v, held there by a 5e6 N/m spring in v only, under a disk imbalance at constant Ω = 0.7 ω_n,
  started from its steady state: the run's shaft envelope at every node, the start node's
  included, is the steady orbit of the direct frequency-domain solve
  (:func:`steady_state_envelope`, banded LU of the full model; the rotor's only loss is a
  viscous dashpot, the same in both). Four basis modes and no static correction: 1e-6 relative
  (measured: they agree to 1e-8: the disk is the only mass, so the static shape under a disk
  load lies in the span of the first v and w modes and the tube's modes, left out with no
  static correction, take almost none of the load; with the first free DOF's row dropped the
  start node would read 0).

Tolerances: the instants are float64 arithmetic (1e-12); the eigenvalue count is exact (the
cut-off is chosen at the middle of the gap between two modes, far from either, 5 %).

Written for the mutations h51d-transient-end-time-missing, h51d-transient-output-count-floor,
h51d-transient-output-step-per-radian-as-period, h51d-transient-basis-stops-at-full-guess and
h51d-transient-growth-per-dwell, h51d-transient-rows-first-free-dof-dropped of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla
from rotors import WN, jeffcott, jeffcott_text

import flexshaft.analyses.transient as transient_module
from flexshaft.analyses.guards import UnstableResponseError
from flexshaft.analyses.transient import (
    SpeedProfile,
    default_basis_size,
    default_output_step,
    run_up,
    steady_state_envelope,
    transient_response,
)
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design


def test_the_outputs_run_from_t0_to_the_end_of_the_ramp():
    model = jeffcott(0.0, 200.0)  # ζ ≈ 0.016 external damping, stable at every speed
    start, stop, duration, step = 0.2 * WN, 0.5 * WN, 0.05, 0.0031  # T/step = 16.1: not a whole number
    run = run_up(model, duration, start=start, stop=stop, basis_size=2, output_step=step)
    assert run.time[0] == 0.0
    assert run.time[-1] == pytest.approx(duration, rel=1e-12)
    assert run.speed[-1] == pytest.approx(stop, rel=1e-12)
    assert np.diff(run.time).max() <= step * (1 + 1e-12)
    assert run.phase[-1] == pytest.approx(0.5 * (start + stop) * duration, rel=1e-12)


def test_the_default_output_step_is_eight_samples_per_period():
    for omega in (50.0, 314.0, 2000.0):
        assert default_output_step(omega) == pytest.approx(np.pi / (4 * omega), rel=1e-12)


def test_the_default_basis_holds_every_mode_below_four_times_the_speed():
    model = build_model(loads_design(jeffcott_text(0.0, 0.0, elements=20)))
    free = model.dofs.free
    assert free.size > 60
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    M = restrict(model.M.tocsr(), free).toarray()
    w2 = sla.eigh(K, M, eigvals_only=True)
    k = 80  # the cut-off between modes 80 and 81 (more than the first 60 trial modes)
    assert w2[k - 1] < 0.95 * w2[k]  # a clear gap
    cut = np.sqrt(np.sqrt(w2[k - 1] * w2[k]))  # ω at the geometric middle of the gap
    assert default_basis_size(model, cut / 4.0) == k


def test_the_growth_of_two_unstable_dwells_adds_up(monkeypatch):
    class _Reached(Exception):
        pass

    def _integrator(*args, **kwargs):
        raise _Reached

    monkeypatch.setattr(transient_module, "integrate_envelope", _integrator)
    model = jeffcott(0.02, 0.0, "rotating")
    s = 2.0 * WN

    def run(second_dwell):
        times = [0.0, 5.0, 5.2, 5.4, 5.4 + second_dwell]
        speeds = [s, s, 1.05 * s, s, s]
        return transient_response(
            model, SpeedProfile.table(times, speeds), basis_size=2, initial="rest", output_step=0.5
        )

    with pytest.raises(_Reached):  # one dwell of 5 s (e^5) and a short one (e^0.5): integrated
        run(0.5)
    with pytest.raises(UnstableResponseError):  # e^5 twice: refused
        run(5.0)


def test_the_first_free_dof_is_reported():
    text = jeffcott_text(0.0, 200.0, elements=4).replace(
        'fixed_start = ["u", "v", "w", "theta"]', 'fixed_start = ["u", "w", "theta"]'
    )
    text = text.replace(
        "[[disks]]", '[[bearings]]\nname = "end"\nkind = "contact"\nx = 0.0\nstiffness = { v = 5e6 }\n[[disks]]'
    )
    model = build_model(loads_design(text))
    assert model.dofs.free[0] == model.dofs.shaft(0, "v")
    node = model.dofs.node_at("shaft", 0.5)
    q1 = np.zeros(model.dofs.size, complex)
    q1[model.dofs.shaft(node, "v")], q1[model.dofs.shaft(node, "w")] = 1e-4, -1e-4j
    s = 0.7 * WN
    run = transient_response(
        model,
        SpeedProfile.table([0.0, 0.01], [s, s]),
        basis_size=4,
        output_step=0.005,
        loads_per_speed_squared=q1,
        static_correction=False,
    )
    steady = steady_state_envelope(model, [s], q1).shaft_orbit[:, 0]
    assert steady[0] > 0.1 * steady.max()  # the start node moves
    assert run.shaft_orbit[:, -1] == pytest.approx(steady, rel=1e-6)
