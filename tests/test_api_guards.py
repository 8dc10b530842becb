"""Refusals of the lower layers (issue 27): each reproducer gets a correct result or a clear error.

* speeds above a design's limit (10^6 rev/min) through the API: ``modes(model, 1e30)`` gave
  frequencies 0 and −0 Hz;
* a statically singular driveline (an unsupported rigid-body motion): ``static_response``
  returned up to 7e11 m instead of raising ``SingularSystemError``; a regular but soft one must
  still be solved;
* an undamped resonance: a harmonic response within the accuracy of the natural frequencies
  warns (``ResonanceWarning``), one singular to working precision raises;
* derived numbers the analyses cannot evaluate: a controller pole at 1e30 rad/s, a static gain
  of 1e37 N/m, an ambient of 400 °C, a sky at 400 °C, a matrix law that stiffens the ply
  beyond validity; a design at rest for the spin-up grid; an unstable loop in the run-up;
* ``model_guards`` and ``thermal_guards`` report every one of them for ``flexshaft check``.

References are closed forms (a Jeffcott rotor, tests/rotors.py, with a nearly massless tube:
k = 48 E I / L³ and the effective mass of tests/test_massless_members.py) or the physics the
refusal states.
"""

from __future__ import annotations

import copy
import re
import warnings

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, L, disk_dofs, jeffcott_text
from test_massless_members import effective_mass

from flexshaft.analyses.banded import ResonanceWarning, SingularSystemError
from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.guards import MAX_SPEED, RefusedInputError, UnstableResponseError
from flexshaft.analyses.modal import modes
from flexshaft.analyses.preflight import model_guards
from flexshaft.analyses.response import frequency_response, imbalance_response, static_response
from flexshaft.analyses.spinup import spinup_speeds
from flexshaft.analyses.stability import stability
from flexshaft.assembly import build_model
from flexshaft.assembly.checks import MAX_CONTROLLER_POLE
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import DesignError, design_from_dict, embedded_design, loads_design
from flexshaft.design.schema import MAX_SPEED_RPM
from flexshaft.thermal.preflight import thermal_guards
from flexshaft.units import rpm_to_rad_s
from flexshaft.verdict.assess import envelope_problems

DENSITY = 1e-6  # the massless-tube idealisation: the tube is 3.5e-11 of the disk's mass
M_E = effective_mass(DENSITY)
OMEGA_N = np.sqrt(K_SHAFT / M_E)
BASELINE = embedded_design("baseline")


def jeffcott(c_e: float = 0.0, text_changes: dict | None = None):
    text = jeffcott_text(0.0, c_e).replace("density = 0.1", f"density = {DENSITY!r}")
    for old, new in (text_changes or {}).items():
        assert old in text
        text = text.replace(old, new)
    return build_model(loads_design(text))


def variant(name: str, change) -> object:
    data = copy.deepcopy(embedded_design(name).model_dump())
    change(data)
    return design_from_dict(data)


def without_tables(data: dict) -> dict:
    """The design data with no lamina temperature table: the assumed matrix law
    (``[thermal] matrix_*``) then sets the lamina at a temperature (a table replaces the law)."""
    for material in data["materials"].values():
        material.pop("temperature_table", None)
    return data


# ---------------------------------------------------------------------------------------------
# Speeds


def test_the_speed_limit_is_the_designs():
    assert MAX_SPEED == pytest.approx(rpm_to_rad_s(MAX_SPEED_RPM), rel=1e-15)


@pytest.mark.parametrize("speed", [MAX_SPEED * (1 + 1e-12), 1e6, 1e30])
def test_every_eigen_and_harmonic_analysis_refuses_speeds_above_the_limit(speed):
    """Was: modes(model, 1e30) returned 0 and −0 Hz (campbell, stability, imbalance_response
    likewise); the CLI refused, the API did not."""
    model = build_model(BASELINE)
    message = re.escape(f"at most {MAX_SPEED:,.0f} rad/s (10^6 rev/min")
    loads = imbalance_loads(model)
    calls = [
        lambda: modes(model, speed, 4),
        lambda: campbell(model, [0.0, speed], 2),
        lambda: stability(model, [0.0, speed], 2),
        lambda: imbalance_response(model, [10.0, speed], loads),
        lambda: frequency_response(model, loads[:, 0], 10.0, speed=speed),
        lambda: static_response(model, np.real(loads[:, 0]), speed=speed),
    ]
    for call in calls:
        with pytest.raises(RefusedInputError, match=message):
            call()


def test_at_the_limit_the_jeffcott_whirls_stay_at_the_natural_frequency():
    """At Ω = MAX_SPEED the midspan disk (no inertia of its own) has no gyroscopic coupling: both
    whirls at ω_n with ζ = c/(2√(k m_e)). The tube's polar inertia ρJL (3.6e-13 kg m²) splits
    them by about Ω ρJ (4.8/L)/(2 m_e ω_n) = 1.5e-11. Newton's refinement stops at a step of
    1e-10 |s| (flexshaft.analyses.eigen.newton), which bounds the error by 9 steps when its last
    steps contract by r ≤ 0.9 (r/(1 − r)): 1e-9 of |s|, and 1e-9/ζ = 5e-8 of ζ = −Re s/|s|."""
    c = 2 * 0.02 * np.sqrt(K_SHAFT * M_E)
    result = modes(jeffcott(c), MAX_SPEED, 2)
    assert np.abs(result.eigenvalues) / OMEGA_N == pytest.approx([1.0, 1.0], abs=1e-9)
    assert result.damping_ratios == pytest.approx([0.02, 0.02], rel=5e-8)


def test_a_spin_up_to_a_design_at_rest_is_refused():
    """Was: a design with speed_rpm = 0 got a spin-up grid up to 1 rad/s."""
    at_rest = variant("baseline", lambda d: d["operating"].update(speed_rpm=0.0, power=0.0))
    model = build_model(at_rest)
    with pytest.raises(RefusedInputError, match=r"operating speed is 0 \(operating.speed_rpm = 0\)"):
        spinup_speeds(model, 10)
    # the analyses at the operating speed itself run: modes at rest, static deflection
    assert np.all(np.isfinite(modes(model, model.speed, 4).eigenvalues))


# ---------------------------------------------------------------------------------------------
# Statically singular systems


def single_support(stiffness: dict, fixed: list, elements: int):
    """The current driveline on one contact bearing (no fixed DOFs but ``fixed``)."""

    def change(data):
        first = data["bearings"][0]
        data["bearings"] = [{"name": "only", "kind": "contact", "x": first["x"], "stiffness": stiffness}]
        data["shaft"]["fixed_start"], data["shaft"]["fixed_end"] = fixed, []
        data["mesh"]["shaft_elements"] = elements

    return variant("current", change)


@pytest.mark.parametrize(
    "stiffness, fixed, elements",
    [({"u": 1e8, "v": 1e8}, ["theta"], 7), ({"v": 1e-3, "w": 1e-3}, ["u", "theta"], 13), ({}, [], 48)],
)
def test_a_static_rigid_body_motion_raises_singular_system_error(stiffness, fixed, elements):
    """One support point leaves the shaft free to pivot (and free in w, or everywhere): the
    static stiffness is singular. Was: 8e7 to 2e12 m for a 100 N load (a round-off pivot
    instead of 0). Detected by iterative refinement on the equilibrated matrix, on the loads
    and on a random probe: a singular matrix's corrections do not contract."""
    model = build_model(single_support(stiffness, fixed, elements))
    load = np.zeros(model.dofs.size)
    load[model.dofs.shaft(5, "v")] = 100.0
    with pytest.raises(SingularSystemError, match="unconstrained rigid-body motion"):
        static_response(model, load)


def test_a_soft_but_regular_support_is_still_solved():
    """Ill-conditioned but regular: the Jeffcott tube on two 1 N/m springs (κ ≈ 1e12) under a
    midspan load P deflects P/(2 k_s) + P L³/(48 E I) at the disk. The springs' share is known
    to ε κ ≈ 1e-4 at worst: tolerance 1e-4 (measured 1e-10)."""
    soft = 1.0
    changes = {
        'fixed_start = ["u", "v", "w", "theta"]': 'fixed_start = ["u", "theta"]',
        'fixed_end = ["v", "w"]': "fixed_end = []",
        "[[bearings]]": (
            f'[[bearings]]\nname = "a"\nkind = "contact"\nx = 0.0\nstiffness = {{ v = {soft}, w = {soft} }}\n'
            f'[[bearings]]\nname = "b"\nkind = "contact"\nx = {L}\nstiffness = {{ v = {soft}, w = {soft} }}\n'
            "[[bearings]]"
        ),
    }
    model = jeffcott(0.0, changes)
    v, _ = disk_dofs(model)
    load = np.zeros(model.dofs.size)
    load[v] = 100.0
    q = static_response(model, load)
    assert q[v] == pytest.approx(100.0 / (2 * soft) + 100.0 / K_SHAFT, rel=1e-4)


# ---------------------------------------------------------------------------------------------
# Undamped resonance


def test_a_harmonic_response_at_an_undamped_resonance_warns_and_is_still_the_closed_form():
    """Undamped Jeffcott rotor at ω = ω_n (1 − δ): X = F/(k − m_e ω²), sensitivity to ω
    2 m_e ω²/|k − m_e ω²| ≈ 1/δ. Within RESONANCE_TOLERANCE (1e-5) of the resonance the response
    warns, quoting δ; the value stays the closed form to the round-off of k and m_e (about 1e-13
    relative: assembly of 8 elements, measured 2.4e-14) amplified by 1/(2δ): tolerance 1e-12/δ.
    At the resonance to working precision: SingularSystemError (README: "reports the
    singularity instead of printing inf"). Was: 3.6e3 m for 100 N at an undamped gyroscopic
    frequency of the baseline, without a word."""
    model = jeffcott()
    v, _ = disk_dofs(model)
    load = np.zeros(model.dofs.size)
    load[v] = 100.0
    for delta, warns in ((1e-3, False), (1e-7, True)):
        omega = OMEGA_N * (1 - delta)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            q = frequency_response(model, load, omega, 0.0)
        raised = [w for w in caught if issubclass(w.category, ResonanceWarning)]
        assert bool(raised) == warns
        if warns:
            assert f"within about {delta:.1e} (relative) of an undamped resonance" in str(raised[0].message)
        assert q[v].real == pytest.approx(100.0 / (K_SHAFT - M_E * omega**2), rel=1e-12 / delta)
    with pytest.raises(SingularSystemError, match="singular at ω"):
        frequency_response(model, load, OMEGA_N, 0.0)


def test_a_damped_resonance_does_not_warn():
    """ζ = 0.02 bounds the sensitivity by 1/(2ζ) = 25: no warning at ω_n."""
    model = jeffcott(2 * 0.02 * np.sqrt(K_SHAFT * M_E))
    v, _ = disk_dofs(model)
    load = np.zeros(model.dofs.size)
    load[v] = 100.0
    with warnings.catch_warnings():
        warnings.simplefilter("error", ResonanceWarning)
        q = frequency_response(model, load, OMEGA_N, 0.0)
    assert abs(q[v]) == pytest.approx(100.0 / (2 * 0.02 * K_SHAFT), rel=1e-9)


# ---------------------------------------------------------------------------------------------
# Controller laws


def controller(num, den):
    def change(data):
        for index in (1, 2):
            bearing = data["bearings"][index]
            bearing.update(kp=None, kd=None, controller={"numerator": num, "denominator": den})

    return variant("baseline", change)


def test_a_controller_pole_beyond_the_limit_is_refused_naming_the_controller():
    """denominator = [1e-30, 1] is a pole at −1e30 rad/s: was a spurious divergent root at rest
    (modes' first frequency 0 Hz) and exit 4 in run."""
    with pytest.raises(DesignError, match=r"bearings\[1\].controller: .*pole at s = -1e\+30 rad/s"):
        build_model(controller([1e7], [1e-30, 1.0]))


def test_a_fast_but_allowed_pole_is_the_constant_gain_to_its_physical_phase_lag():
    """C(s) = 1e7/(s/p + 1) with p = MAX_CONTROLLER_POLE against C = 1e7: the lag changes each
    eigenvalue by about |s|/p (≤ 1e-9 for the modes below 1e3 rad/s here), and the eigen-solve
    keeps that: tolerance 1e-8 relative."""
    lagged = modes(build_model(controller([1e7], [1.0 / MAX_CONTROLLER_POLE, 1.0])), 502.0, 6).eigenvalues
    constant = modes(build_model(controller([1e7], [1.0])), 502.0, 6).eigenvalues
    np.testing.assert_allclose(lagged, constant, rtol=1e-8)


def test_a_static_gain_beyond_a_rigid_support_is_refused():
    """denominator = [1, 1e-30]: a near-integrator whose static gain C(0) = 1e37 N/m is a
    support stiffer than the rigid limit (was: the modal basis failed)."""
    with pytest.raises(DesignError, match=r"bearings\[1\].controller: 1e\+37 N/m .*static gain of C\(s\)"):
        build_model(controller([1e7], [1.0, 1e-30]))


def test_an_integral_gain_that_destabilises_the_loop_is_reported_unstable_in_the_run_up():
    """integral_gain = 1e15 with kp = 1e7: the integral corner is 1e8 rad/s and the loop is
    unstable (a root at Re s = +4.7e4 1/s near 8.2e4 rad/s at every speed; a balanced realisation
    gives the same roots to 1e-11): the run-up overflows and says so with a ValueError
    (was FloatingPointError, exit 4)."""
    from flexshaft.analyses.transient import run_up

    design = variant("baseline", lambda d: d["bearings"][1].update(integral_gain=1e15))
    with pytest.raises(UnstableResponseError, match="the system is unstable there"):
        run_up(build_model(design), 0.5)  # the reproducer: `flexshaft runup --duration 0.5`
    assert issubclass(UnstableResponseError, RefusedInputError)


# ---------------------------------------------------------------------------------------------
# [thermal] bounds


def test_an_ambient_beyond_the_air_properties_is_refused_by_the_schema():
    """Was: ambient_temperature_c = 400 (the schema's maximum) failed in the thermal analysis
    with "air temperature must be within 200-600 K"."""
    for value in (400.0, 177.0, -74.0):
        with pytest.raises(DesignError, match=r"thermal.ambient_temperature_c: .*allowed: \[-73, 176\] degC"):
            variant("baseline", lambda d, v=value: d["thermal"].update(ambient_temperature_c=v))

    def law(data: dict, value: float) -> None:  # the assumed law: no table to cover the air
        for material in data["materials"].values():
            material.pop("temperature_table", None)
        data["envelope"] = None
        data["thermal"].update(ambient_temperature_c=value)

    for value in (176.0, -73.0):  # the limits themselves are evaluated
        assert thermal_guards(variant("baseline", lambda d, v=value: law(d, v))) == []
    # at 176 °C the sunlit hover air (156.6 °C) lies beyond the lamina's table (-60 to 120 °C),
    # where the self-heating starts and refuses the ply (the table is not extrapolated): the
    # preflight says so, naming the table; the envelope's hot-soak point parks the shaft at
    # 130 °C, beyond it too: `run` refuses it there, and so does `check` (the envelope's problems)
    hot = variant("baseline", lambda d: d["thermal"].update(ambient_temperature_c=176.0))
    assert [p.path for p in thermal_guards(hot)] == ["materials.t700_adiprene.temperature_table.temperature_c"]
    assert thermal_guards(variant("baseline", lambda d: d["thermal"].update(ambient_temperature_c=-73.0))) == []
    assert [p.path for p in envelope_problems(hot)] == ["envelope.points[2]"]
    assert "'hot_soak_start'" in envelope_problems(hot)[0].message


def test_check_refuses_what_an_envelope_point_refuses_in_one_line():
    """Was: a matrix law with T_ref = 0 °C and θ_E = 5 K passed ``check``, then ``run`` refused the
    design at its hot-soak point in a pydantic message of several lines with a web link. At the
    point's material temperature T_m the law gives E_T = G_LT = 0.1 GPa · exp(−T_m/5 K) (the
    baseline lamina's 0.1 GPa at 0 °C), 1.9 Pa at the parked shaft's 88.8 °C: below the schema's
    1 kPa. ``check`` now reports each envelope point the verdict would refuse, naming the point,
    the fields, the values they would take and the keys that set them, on one line."""
    import math

    from flexshaft.thermal.envelope import point_conditions

    design = variant(
        "baseline",
        lambda d: without_tables(d)["thermal"].update(matrix_reference_temperature_c=0.0, matrix_modulus_decay=5.0),
    )
    assert thermal_guards(design) == []  # valid from the shaft's air to the allowable 100 °C
    problems = envelope_problems(design)
    assert [p.path for p in problems] == ["envelope.points[2]"]
    message = problems[0].message
    assert "'hot_soak_start'" in message and "'t700_adiprene'" in message
    assert "\n" not in message and "pydantic" not in message
    # T_m: the parked tailboom's skin, from the thermal model (at the design's own law, valid)
    no_envelope = variant("baseline", lambda d: d.update(envelope=None))
    parked = point_conditions(no_envelope, design.envelope.points[2]).material_temperature_c
    assert 80.0 < parked < 100.0
    e_t = 0.1e9 * math.exp(-parked / 5.0)
    assert f"E_T would be {e_t:.6g}" in message and f"G_LT would be {e_t:.6g}" in message
    assert "greater than or equal to 1000" in message and "matrix_modulus_decay" in message


@pytest.mark.parametrize(
    "change, field",
    [
        ({"sky_temperature_c": 400.0}, "sky_temperature_c"),
        ({"solar_constant": 1e4, "solar_area_fraction": 1.0}, "solar_constant"),
        ({"matrix_reference_temperature_c": 400.0, "matrix_modulus_decay": 5.0}, "matrix_modulus_decay"),
    ],
)
def test_thermal_combinations_the_correlations_cannot_evaluate_are_reported(change, field):
    """A sky at 400 °C or 1e4 W/m² of sun heat the parked skin beyond the air properties' 600 K
    film temperature; a reference temperature of 400 °C with θ_E = 5 K stiffens E_T by 8e30 at
    the shaft's air, beyond a valid ply. Each is a problem naming the fields (was a ValueError
    from inside the analysis)."""
    design = variant("baseline", lambda d: without_tables(d)["thermal"].update(change))
    problems = thermal_guards(design)
    assert len(problems) == 1 and field in problems[0].message


# ---------------------------------------------------------------------------------------------
# model_guards + thermal_guards: what check reports


def design_guards(design):
    """What ``flexshaft check`` is to report (the CLI joins the two lists)."""
    return model_guards(design) + thermal_guards(design)


@pytest.mark.parametrize("name", ["baseline", "tuned", "current"])
def test_the_embedded_designs_have_no_problems(name):
    assert design_guards(embedded_design(name)) == []


GEOMETRY = {"air_gap": 5e-4, "bias_current": 5.0, "pole_area": 5e-4}


@pytest.mark.parametrize(
    "change, path",
    [
        (lambda d: d["bearings"][1].update(GEOMETRY, coil_turns=1e5), "bearings[1].coil_turns"),
        (lambda d: d["bearings"][1].update(GEOMETRY, coil_turns=100.0, air_gap=1e-6), "bearings[1].coil_turns"),
        (lambda d: d["bearings"][1].update(GEOMETRY, coil_turns=100.0, pole_area=10.0), "bearings[1].coil_turns"),
        (
            lambda d: d["bearings"][1].update(
                kp=None, kd=None, controller={"numerator": [1e7], "denominator": [1e-30, 1.0]}
            ),
            "bearings[1].controller",
        ),
        (
            lambda d: d["bearings"][1].update(
                kp=None, kd=None, controller={"numerator": [1e100], "denominator": [1.0]}
            ),
            "bearings[1].controller",
        ),
        (lambda d: d["thermal"].update(sky_temperature_c=400.0), "thermal"),
        (
            lambda d: without_tables(d)["thermal"].update(
                matrix_reference_temperature_c=400.0, matrix_modulus_decay=5.0
            ),
            "thermal.matrix_reference_temperature_c",
        ),
    ],
)
def test_design_guards_report_what_the_analyses_refuse_after_the_schema(change, path):
    """Schema-valid designs that every analysis then refused while `check` printed ok (issue 27:
    coil_turns = 1e5 and 26 more): the guards name the field."""
    design = variant("baseline", change)
    problems = design_guards(design)
    assert problems and problems[0].path == path


def test_model_guards_report_a_statically_singular_driveline():
    design = single_support({"u": 1e8, "v": 1e8}, ["theta"], 7)
    problems = model_guards(design)
    assert [p.path for p in problems] == ["bearings"]
    assert "static deflection" in problems[0].message and "rigid-body motion" in problems[0].message


def free_massless_jeffcott_text() -> str:
    """The Jeffcott rotor of tests/rotors.py with a nearly massless tube (1e-6 kg/m³) and no
    supports: a free member with almost no mass, whose modal basis the preflight refuses."""
    return (
        jeffcott_text(0.0, 0.0)
        .replace("density = 0.1", "density = 1e-6")
        .replace('fixed_start = ["u", "v", "w", "theta"]', "")
        .replace('fixed_end = ["v", "w"]', "")
    )


def test_model_guards_report_a_free_massless_member():
    problems = model_guards(loads_design(free_massless_jeffcott_text()))
    assert problems[0].path == "shaft.material" and "almost no mass" in problems[0].message


def test_the_tube_constants_are_the_reference_rotors():
    """The closed forms above use the tests/rotors.py tube (guards against a silent change)."""
    assert (DO, DI, L, M_DISK) == (0.05, 0.04, 1.0, 20.0)


def test_every_refusal_of_the_lower_layers_is_a_refused_input_error():
    """A command reports RefusedInputError as a user error (exit 2) and any other exception as a
    fault of flexshaft (exit 4): the refusals above all derive from it (and from ValueError, as
    before), while a bug's ValueError does not (the thermal broadcast error of issue 27 was one)."""
    from flexshaft.analyses.guards import NonFiniteResultError

    for kind in (SingularSystemError, NonFiniteResultError, UnstableResponseError):
        assert issubclass(kind, RefusedInputError) and issubclass(kind, ValueError)
    from flexshaft.thermal.tailboom import tailboom_temperatures

    hot_sky = variant("baseline", lambda d: d["thermal"].update(sky_temperature_c=400.0))
    from flexshaft.thermal.options import thermal_options

    with pytest.raises(RefusedInputError, match="no skin temperature"):
        tailboom_temperatures(1.0, thermal_options(hot_sky.thermal).environment)
