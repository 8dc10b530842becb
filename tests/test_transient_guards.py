"""The run-up, Monte-Carlo and sweep entry points refuse what they cannot compute (issue 27,
"silently wrong through the API" and "API hangs"): each was a hang or an absurd number.

* ``run_up(model, 1.0, max_step=0.0)`` and ``basis_size=10**6`` never returned;
* ``run_up`` / ``transient_response`` with a zero imbalance load never returned: the step
  control divided by an error of exactly 0 (as 1e-300) and shrank the step to nothing;
* a short run-up of an unstable design returned 4e97 m;
* ``run_montecarlo(design, 2.5, ...)`` ran 2 samples, ``n_speeds=1`` was accepted;
* ``run_sweep(..., client="garbage")`` failed inside distributed; ``jobs=2.5`` ran 2 workers.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

from flexshaft.analyses.envelope import MAX_GROWTH
from flexshaft.analyses.guards import RefusedInputError, UnstableResponseError
from flexshaft.analyses.transient import SpeedProfile, run_up, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import baseline_design, with_overrides
from flexshaft.sweep import Output, Study, SweepError, Variable, run_sweep
from flexshaft.sweep.dask import check_scheduler_address

BASELINE = baseline_design()


@pytest.fixture(scope="module")
def model():
    return build_model(with_overrides(BASELINE, {"mesh.shaft_elements": 12, "mesh.boom_elements": 6}))


def returns_within(call, seconds: float = 20.0):
    start = time.process_time()
    value = call()
    assert time.process_time() - start < seconds
    return value


@pytest.mark.parametrize(
    "options, words",
    [
        ({"max_step": 0.0}, "max_step"),
        ({"max_step": float("nan")}, "max_step"),
        ({"output_step": -1.0}, "output_step"),
        ({"basis_size": 10**6}, "basis_size must be at most"),
        ({"basis_size": 2.5}, "basis_size"),
        ({"rtol": 0.5}, "rtol"),
    ],
)
def test_run_up_options_are_refused_before_integrating(model, options, words):
    with pytest.raises(RefusedInputError, match=words):
        returns_within(lambda: run_up(model, 1.0, **options), 1.0)


@pytest.mark.parametrize(
    "args, words",
    [
        ({"duration": 0.0}, "duration"),
        ({"duration": 1.0, "stop": float("inf")}, "stop"),
        ({"duration": 1.0, "start": -1.0}, "start"),
        ({"duration": 1.0, "dwell": -1.0}, "dwell"),
        ({"duration": 1.0, "start": 100.0, "stop": 100.0}, "two different speeds"),
    ],
)
def test_run_up_speeds_and_times_are_refused(model, args, words):
    with pytest.raises(RefusedInputError, match=words):
        run_up(model, **args)


def test_a_zero_load_gives_a_zero_response(model):
    """A linear system at rest with no forcing stays at rest: every envelope exactly 0 (was a
    run that never ended)."""
    zero = np.zeros(model.dofs.size)
    result = returns_within(lambda: run_up(model, 1.0, loads_per_speed_squared=zero))
    assert result.steps < 200
    assert np.all(result.shaft_orbit == 0.0) and np.all(result.actuator_force == 0.0)
    profile = SpeedProfile.table([0.0, 0.5, 1.0], [0.0, 200.0, 200.0])
    held = returns_within(lambda: transient_response(model, profile, loads_per_speed_squared=zero))
    assert np.all(held.shaft_orbit == 0.0)


def test_a_short_run_up_of_an_unstable_design_is_refused():
    """Was: run_up(model, 0.05, start=0, stop=20) with K_i = 1e15 on amb_1 returned 4e97 m. The
    loop is unstable at rest (growth rate 2e4 1/s): a free whirl grows e^7 = MAX_GROWTH-fold in
    0.35 ms, so the run is refused within milliseconds of simulated time."""
    unstable = build_model(with_overrides(BASELINE, {"bearings[1].integral_gain": 1e15, "mesh.shaft_elements": 12}))
    with pytest.raises(UnstableResponseError, match="unstable") as info:
        returns_within(lambda: run_up(unstable, 0.05, start=0.0, stop=20.0), 5.0)
    assert f"more than {MAX_GROWTH:g}" in str(info.value)
    assert issubclass(UnstableResponseError, RefusedInputError)  # a user error at the CLI


def test_a_long_dwell_at_an_unstable_speed_is_refused_before_integrating(model):
    """The baseline is slightly unstable at its operating speed (the causal rotating loss:
    growth rate ~0.01 1/s): a 2 s run-up is computed (e^0.02; a 10 s one, e^0.1, takes the same
    path at twice the CPU, both far below MAX_GROWTH = e^7), a 900 s dwell (e^9) is refused up
    front instead of after 30 s of integration."""
    result = run_up(model, 2.0)
    assert 0 < result.max_growth_rate < 0.05 and np.isfinite(result.peak()[0])
    with pytest.raises(UnstableResponseError, match="held there"):
        returns_within(lambda: run_up(model, 10.0, dwell=900.0, output_step=0.05), 2.0)


def test_a_gyroscopic_coupling_beyond_a_rigid_body_is_refused_up_front():
    """Was: `current` with couplings[1].polar_inertia = 1e7 (diametral 1.3e-3) ran for more than
    240 s: I_p/I_d = 7.7e9 > 2 (no rigid body: I_p ≤ I_1 + I_2 = 2 I_d) makes a forward whirl at
    ~1e10 rad/s whose change with the speed needs ~1e8 steps."""
    from flexshaft.design import embedded_design

    heavy = build_model(with_overrides(embedded_design("current"), {"couplings[1].polar_inertia": 1.0e7}))
    with pytest.raises(RefusedInputError, match=r"couplings\[1\]\.polar_inertia") as info:
        returns_within(lambda: run_up(heavy, 0.5), 2.0)
    assert "I_p ≤ 2 I_d" in str(info.value)


# ------------------------------------------------------------------------------------------------
# Monte-Carlo and sweeps


@pytest.mark.parametrize(
    "args, words",
    [
        ({"n_samples": 2.5}, "n_samples"),
        ({"n_samples": 0}, "n_samples"),
        ({"n_samples": 10, "n_speeds": 1}, "n_speeds"),
        ({"n_samples": 10, "seed": -1}, "seed"),
        ({"n_samples": 10, "seed": 2**63}, "seed"),
        ({"n_samples": 10, "seed": 1.5}, "seed"),
    ],
)
def test_run_montecarlo_counts_are_whole_numbers(args, words):
    from flexshaft.montecarlo import run_montecarlo

    with pytest.raises(RefusedInputError, match=words):
        run_montecarlo(BASELINE, grade_mm_s=6.3, **args)


def test_a_balance_grade_of_a_design_at_rest_is_refused():
    from flexshaft.montecarlo import run_montecarlo

    at_rest = with_overrides(BASELINE, {"operating.speed_rpm": 0.0, "operating.power": 0.0})
    with pytest.raises(RefusedInputError, match="operating speed"):
        run_montecarlo(at_rest, 10, grade_mm_s=6.3)


@pytest.mark.parametrize(
    "address",
    ["tcp://127.0.0.1:8786", "tls://scheduler.example.org:8786", "127.0.0.1:8786", "tcp://[::1]:8786", "inproc://x/1"],
)
def test_scheduler_addresses_of_dask_are_accepted(address):
    assert check_scheduler_address(address) == address


@pytest.mark.parametrize(
    "address", ["garbage", "tcp://host", "tcp://host:0", "tcp://host:99999", "http://host:8786", "", 8786, "tcp://:1"]
)
def test_other_addresses_are_refused_naming_the_form(address):
    with pytest.raises(SweepError, match="PROTOCOL://HOST:PORT"):
        check_scheduler_address(address, "client")


def _mass(point):
    return {"mass": point.model.shaft_mass}


STUDY = Study(
    name="wall",
    variables=[Variable(path="shaft.wall_thickness", name="wall", values=[0.002, 0.003])],
    outputs=[Output("mass", "kg")],
    evaluate=_mass,
    base=with_overrides(BASELINE, {"mesh.shaft_elements": 6, "mesh.boom_elements": 4}),
)


@pytest.mark.parametrize(
    "options, words",
    [({"jobs": 2.5}, "jobs"), ({"jobs": True}, "jobs"), ({"chunk_size": 0}, "chunk_size"), ({"client": "x"}, "x")],
)
def test_run_sweep_refuses_its_options_before_computing(options, words):
    with pytest.raises(SweepError, match=words):
        run_sweep(STUDY, progress=False, **options)


def test_run_sweep_refuses_more_workers_than_the_cpus_or_64(monkeypatch):
    """Was: ``run_sweep(jobs=100000)`` started that many processes (the CLI's ``--jobs`` stops at
    64). The API allows the machine's CPUs, at least 64: here a 2-CPU machine, so 64 and not 65."""
    import flexshaft.sweep.run as sweep_run

    monkeypatch.setattr(sweep_run.os, "cpu_count", lambda: 2)
    with pytest.raises(SweepError, match=r"jobs must be a whole number from 1 to 64 .*got 65"):
        run_sweep(STUDY, progress=False, jobs=65)
    monkeypatch.setattr(sweep_run.os, "cpu_count", lambda: 96)
    with pytest.raises(SweepError, match=r"from 1 to 96 .*got 97"):
        run_sweep(STUDY, progress=False, jobs=97)
