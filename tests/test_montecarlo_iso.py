"""Monte-Carlo imbalance by ISO 21940-11 (issue 25, point 5): the samples' rotor is the run's.

ISO 21940-11:2016 §5.3 grades the whole balanced rotor: e_per = G/Ω_max, U_per = e_per m, m the
rotating mass (tubes, disks, coupling hubs: :mod:`flexshaft.assembly.balance`). The Monte-Carlo
draws one eccentricity e_b per bay and weighs it with the bay's own rotating mass m_b
(:func:`~flexshaft.assembly.balance.bay_rotating_masses`, Σ m_b = m), with the run's eccentricity
function. The references are hand computations from the design files: the segmented ``current``
driveline (6061-T6 tube D_o 0.1016 m, wall 1.651e-3 m, 8.05 m, 2700 kg/m³; four 1.0 kg coupling
hubs at 0.79, 2.21, 5.21, 6.63 m; bearing stations 0.74, 2.16, 3.71, 5.16, 6.58, 8.05 m), and the
moments of the draws (independent uniform phases, e = e_per √u for the "disk" distribution).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses import imbalance_response
from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.assembly.balance import design_eccentricity, permissible_eccentricity
from flexshaft.assembly.loads import imbalance_loads, per_bay_imbalance_loads
from flexshaft.design import embedded_design, loads_design, tuned_design, with_overrides
from flexshaft.montecarlo import (
    EccentricityDistribution,
    bay_unbalances,
    draw_imbalance,
    run_montecarlo,
    runup_montecarlo,
    unit_responses,
)
from flexshaft.montecarlo.samples import combine

# the `current` driveline by hand (its design file)
RHO, DO, T, LENGTH = 2700.0, 0.1016, 1.651e-3, 8.05
PER_METRE = RHO * math.pi / 4 * (DO**2 - (DO - 2 * T) ** 2)  # 1.39971 kg/m
BAY_LENGTHS = np.array([2.16, 1.55, 1.45, 1.42, 1.47])  # the overhang 0-0.74 m with the first bay
BAY_HUBS = np.array([1.0, 1.0, 0.0, 1.0, 1.0])  # hubs at 0.79, 2.21 | -, 5.21, 6.63
BAY_MASSES = PER_METRE * BAY_LENGTHS + BAY_HUBS
ROTOR_MASS = PER_METRE * LENGTH + 4 * 1.0  # 15.268 kg


@pytest.fixture(scope="module")
def current():
    model = build_model(embedded_design("current"))
    return model, unit_responses(model, [model.speed], "mid_bay", refine=False)


def test_the_samples_weigh_each_bay_with_its_rotating_mass(current):
    """m_b = tube between the bay's edges + its hubs: 4.023, 3.170, 2.030, 2.988, 3.058 kg,
    summing to the rotor's 15.268 kg (11.268 kg of tubes; the tube share alone was 26 % low)."""
    model, units = current
    assert ROTOR_MASS == pytest.approx(15.268, abs=1e-3)
    np.testing.assert_allclose(units.bay_mass, BAY_MASSES, rtol=1e-12)
    assert units.bay_mass.sum() == pytest.approx(ROTOR_MASS, rel=1e-12)
    assert units.bay_mass.sum() / model.shaft_mass == pytest.approx(ROTOR_MASS / (PER_METRE * LENGTH), rel=1e-12)


def test_unbalance_of_the_samples_against_the_whole_rotors(current):
    """G 6.3 at the operating speed: e_per = 6.3e-3/502.65 = 12.53 µm, U_per = e_per m =
    1.914e-4 kg m (191 g mm) for 15.268 kg.

    * ``fixed`` at e_per: every sample's bay unbalances add up in magnitude to U_per exactly,
      and in phase (angles 0) to the same resultant;
    * ``disk`` of radius e_per (e = e_per √u, E e² = e_per²/2) with independent uniform angles:
      E Σ_b |U_b|² = E |Σ_b U_b|² = (e_per²/2) Σ m_b² = (U_per²/2) Σ m_b²/m² (the cross terms
      vanish); 4000 samples, within 5 standard errors of the sample means.
    """
    model, units = current
    e_per = permissible_eccentricity(6.3, model.speed)
    assert e_per == pytest.approx(6.3e-3 / (4800 * math.pi / 30), rel=1e-12)
    u_per = e_per * ROTOR_MASS
    assert u_per == pytest.approx(1.914e-4, rel=1e-3)
    fixed = draw_imbalance(
        range(200), units.n_bays, EccentricityDistribution.from_grade(6.3, model.speed, "fixed"), "mid_bay", 4
    )
    U = bay_unbalances(units.bay_mass, fixed)
    np.testing.assert_allclose(np.abs(U).sum(axis=1), u_per, rtol=1e-12)
    fixed.angle[:] = 0.0
    np.testing.assert_allclose(np.abs(bay_unbalances(units.bay_mass, fixed).sum(axis=1)), u_per, rtol=1e-12)

    disk = draw_imbalance(
        range(4000), units.n_bays, EccentricityDistribution.from_grade(6.3, model.speed), "mid_bay", 5
    )
    U = bay_unbalances(units.bay_mass, disk)
    expected = e_per**2 / 2 * np.sum(BAY_MASSES**2)
    for square in (np.sum(np.abs(U) ** 2, axis=1), np.abs(U.sum(axis=1)) ** 2):
        error = square.std() / math.sqrt(square.size)
        assert square.mean() == pytest.approx(expected, abs=5 * error)


def test_the_weights_of_a_sample_carry_its_bay_unbalances(current):
    """The station weights of a sample (cubic Lagrange basis, which sums to 1) add up to each
    bay's U_b e^{iψ_b}: what the unit responses are multiplied by is the bay's unbalance."""
    model, units = current
    draws = draw_imbalance(range(50), units.n_bays, EccentricityDistribution("disk", 2e-5), "mid_bay", 6)
    _, weights = combine(units, draws)
    per_bay = weights.reshape(50, units.n_bays, 4).sum(axis=2)
    np.testing.assert_allclose(per_bay, bay_unbalances(units.bay_mass, draws), rtol=1e-12)


def _mid_bay_sample_response(model, units, e):
    """Operating-speed response of the sample with every bay at eccentricity e, angle 0, mid-bay."""
    draws = draw_imbalance([0], units.n_bays, EccentricityDistribution("fixed", e), "mid_bay", 0)
    draws.angle[:] = 0.0
    idx, weights = combine(units, draws)
    return units.operating[:, idx[0]] @ weights[0]


def test_a_sample_at_e_per_in_every_bay_is_the_runs_imbalance():
    """The tuned driveline with its actuators moved to 8.05/3 and 2·8.05/3 m: its three bays
    (the 0-0.79 m overhang with the first) carry equal rotating masses, so the sample with every
    bay at the design's e_c, in phase and at mid-bay, is the run's imbalance load exactly (the
    run shares e_c m equally among the bays): the responses at the operating speed agree to
    1e-9 of the largest (unit responses and the direct solve factor the same matrix)."""
    design = with_overrides(tuned_design(), {"bearings[1].x": LENGTH / 3, "bearings[2].x": 2 * LENGTH / 3})
    model = build_model(design)
    units = unit_responses(model, [model.speed], "mid_bay", refine=False)
    np.testing.assert_allclose(units.bay_mass, np.full(3, units.bay_mass.mean()), rtol=1e-12)
    e = design_eccentricity(design)
    sample = _mid_bay_sample_response(model, units, e)
    run = imbalance_response(model, [model.speed], imbalance_loads(model, "mid_bay"))[:, 0, 0]
    assert np.abs(sample - run).max() <= 1e-9 * np.abs(run).max()


def test_with_unequal_bays_the_sample_and_the_run_carry_the_same_total_unbalance(current):
    """``current``: the sample with every bay at e_c, in phase, carries e_c m_b at each mid-bay,
    the run e_c m/5 (the thesis's equal share); both add up to e_c m = e_c · 15.268 kg (by hand),
    the total rotating force per Ω² (the consistent nodal loads of a point force sum to it)."""
    model, units = current
    e = design_eccentricity(model.design)
    nodes = np.arange(model.dofs.n_shaft_nodes)
    sample = per_bay_imbalance_loads(model, e * units.bay_mass)
    run = imbalance_loads(model, "mid_bay")[:, 0]
    for Q in (sample, run):
        assert complex(Q[model.dofs.shaft(nodes, "v")].sum()) == pytest.approx(e * ROTOR_MASS, rel=1e-12)


def test_the_runup_weighs_each_bay_with_its_rotating_mass():
    """A two-bay steel tube with a 2 kg disk in its first bay: m_1 = ρ A L/2 + 2 kg, m_2 = ρ A L/2.
    The run-up samples equal a direct transient with U_b = e_b m_b (by hand) to 1e-4 (different
    integration steps at rtol 1e-7, complex64 envelopes). The run-up takes 0.5 s (1100 rad/s²,
    CPU budget, issue 23): the weighting holds for any speed profile, and each transient costs
    in proportion to its duration."""
    text = _two_bay_with_disk()
    model = build_model(loads_design(text))
    tube = 7850.0 * math.pi / 4 * (0.05**2 - 0.04**2) * 1.0  # kg per bay (1 m)
    masses = np.array([tube + 2.0, tube])
    profile = SpeedProfile.constant_acceleration(50.0, 600.0, 1100.0)
    samples = runup_montecarlo(
        model, profile, 2, seed=9, distribution=EccentricityDistribution("disk", 2e-5), rtol=1e-7, output_step=1e-3
    )
    for k in range(2):
        U = samples.draws.eccentricity[k] * masses
        run = transient_response(
            model,
            profile,
            loads_per_speed_squared=per_bay_imbalance_loads(model, U, samples.draws.angle[k]),
            rtol=1e-7,
            output_step=1e-3,
        )
        assert samples.shaft_peak[k] == pytest.approx(run.shaft_peak.max(), rel=1e-4)


def test_a_balance_grade_draws_at_the_runs_eccentricity():
    """``run_montecarlo(grade_mm_s=G)`` scales the draws by e_per at the highest operating speed,
    the eccentricity the run takes from ``[loads] balance_grade = G`` (speed range 0.9-1.1 of
    6000 rpm: 6.3e-3 / (1.1 · 628.32) = 9.115 µm)."""
    text = _two_bay_with_disk().replace("speed_rpm = 6000.0", "speed_rpm = 6000.0\nspeed_range = [0.9, 1.1]")
    design = loads_design(text)
    result = run_montecarlo(design, 2, grade_mm_s=6.3, n_speeds=5, strength=False, progress=False)
    graded = with_overrides(design, {"loads.eccentricity": 0.0, "loads.balance_grade": 6.3})
    assert result.dataset.attrs["eccentricity_scale_m"] == pytest.approx(design_eccentricity(graded), rel=1e-12)
    assert design_eccentricity(graded) == pytest.approx(6.3e-3 / (1.1 * 6000 * math.pi / 30), rel=1e-12)


def _two_bay_with_disk() -> str:
    """A 2 m steel tube (D_o 50 mm, wall 5 mm) on contact bearings at both ends and an active
    bearing at mid-span, with a 2 kg disk at 0.5 m."""
    return """
name = "two-bay rotor with a disk"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7850.0
loss_factor = 0.002
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.05
wall_thickness = 0.005
material = "steel"
fixed_start = ["u", "theta"]
[[disks]]
name = "disk"
x = 0.5
mass = 2.0
[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = { v = 5e7, w = 5e7 }
[[bearings]]
name = "amb"
kind = "active"
x = 1.0
kp = 2e6
kd = 200.0
[[bearings]]
name = "right"
kind = "contact"
x = 2.0
stiffness = { v = 5e7, w = 5e7 }
[operating]
speed_rpm = 6000.0
power = 0.0
[loads]
eccentricity = 10e-6
[mesh]
shaft_elements = 10
"""
