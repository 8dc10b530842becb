"""The verdict at its boundaries: an onset at standstill, margins of exactly zero, the Kelvin scale.

References, all rules of the hand-written docs/requirements.md or definitions:

* "The checks": every check's margin is value − limit for a minimum and limit − value for a
  maximum, "negative fails": a margin of exactly zero passes, and the smallest margin of the
  instances of a requirement governs;
* "The stability checks": an integrating bearing with a huge integral gain "is unstable at
  rest. The check then fails at the lowest speed with an unstable root"; the whirl-onset limit
  is (1 + ``min_onset_margin``) × the operating speed;
* the table of checks: ``loop_phase_margin`` is the smallest phase margin over each axis's gain
  crossovers against ``min_phase_margin_deg``; ``temperature`` is the maximum shaft temperature,
  the material temperature of a hot-soaked start when it is higher, against
  ``allowable_temperature_c``; ``torsional_separation``'s margin is 0 for a mode inside its
  excitation's band over the speed range;
* the definition of the Celsius scale: a Celsius temperature t is the thermodynamic temperature
  T = t + 273.15 K.

The inputs are hand-built (:class:`~flexshaft.verdict.evidence.Evidence`, and for the
evidence gatherer small ``SimpleNamespace`` stand-ins of a point's analyses with the attributes
it reads): no analysis runs, each test takes milliseconds. The numbers are chosen exact in
binary (625 = 1.25 × 500, a phase margin of 0.0) so that most comparisons are exact; where a
conversion rounds (273.15 and π are not binary fractions) the tolerance is a few ulps.
"""

from __future__ import annotations

import dataclasses
import math
import re
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.design.requirements import Requirements
from flexshaft.units import celsius_to_kelvin
from flexshaft.verdict import gather
from flexshaft.verdict.checks import evaluate, whirl_onset_check
from flexshaft.verdict.evidence import Evidence, LoopEvidence, TorsionalEvidence
from flexshaft.verdict.operating_point import PointAnalyses

# ------------------------------------------------------------------------ an onset at standstill


def test_a_driveline_unstable_at_rest_fails_the_whirl_onset_check():
    """Onset at 0 rad/s (unstable at standstill), analysed to 750 rad/s, Ω_op = 500 rad/s, margin
    0.25: the limit is 1.25 × 500 = 625 rad/s, the value 0, the margin −625 rad/s, a failure
    measured (no lower bound), not "no onset up to 750 rad/s" passing by +125 rad/s."""
    check = whirl_onset_check(0.0, 750.0, 500.0, 0.25, {"mode": "divergence (real root)"})
    assert check.status == "fail"
    assert (check.value, check.limit, check.margin) == (0.0, 625.0, -625.0)
    assert not check.lower_bound
    assert check.location == {"mode": "divergence (real root)"}


def test_the_verdict_of_evidence_with_an_onset_at_rest_fails():
    """The same through :func:`evaluate` of a point's evidence: onset 0 of a stability analysis
    to 750 rad/s, Ω_op 500 rad/s, ``min_onset_margin`` 0.25: whirl_onset fails by 625 rad/s."""
    ev = Evidence(operating_speed=500.0, stability_max_speed=750.0, onset_speed=0.0)
    check = evaluate(ev, Requirements(min_onset_margin=0.25)).check("whirl_onset")
    assert check.status == "fail" and check.margin == -625.0 and not check.lower_bound


# ------------------------------------------------------------------------ a phase margin of zero


def _loop(axis: str, phase_margin: float) -> LoopEvidence:
    return LoopEvidence("amb", axis, 500.0, 2.0, 2 * math.pi * 60.0, 9.0, -6.0, phase_margin, 2 * math.pi * 90.0)


def test_a_loop_with_zero_phase_margin_governs_the_phase_margin_check():
    """Axis y with a phase margin of exactly 0 (its Nyquist curve through −1 at the gain
    crossover), axis z with π/4; ``min_phase_margin_deg`` 30: both are findings, the smaller
    governs: value 0, limit π/6, margin −π/6, a failure (not "no gain crossover")."""
    ev = Evidence(operating_speed=500.0, loops=(_loop("y", 0.0), _loop("z", math.pi / 4)))
    check = evaluate(ev, Requirements(min_phase_margin_deg=30.0)).check("loop_phase_margin")
    assert check.status == "fail" and len(check.findings) == 2
    assert check.value == 0.0
    # radians(30) = π/6 rounds once: a few ulps
    assert check.limit == pytest.approx(math.pi / 6, rel=4e-16)
    assert check.margin == pytest.approx(-math.pi / 6, rel=4e-16)
    assert check.location["actuator"] == "amb (y)"


def test_a_zero_phase_margin_against_a_zero_requirement_passes_at_margin_zero():
    """``min_phase_margin_deg`` 0 and a loop with phase margin exactly 0: margin 0 − 0 = 0,
    which passes ("negative fails"), and it governs over the other axis's π/4."""
    ev = Evidence(operating_speed=500.0, loops=(_loop("y", 0.0), _loop("z", math.pi / 4)))
    check = evaluate(ev, Requirements(min_phase_margin_deg=0.0)).check("loop_phase_margin")
    assert check.status == "pass"
    assert (check.value, check.limit, check.margin) == (0.0, 0.0, 0.0)


# ------------------------------------------------------------------------ the allowable in Kelvin


def _point(allowable_c: float, material_temperature: float) -> NS:
    """A point at 500 rad/s (no speed range) whose every analysis but the thermal one is
    absent or empty: stability and the every-root check find no onset, there are no modes at
    speed and no criticals (no unbalance response), and the spin-up is stubbed empty (no
    speeds), so no spin-up peak is gathered. The shaft's self-heating equilibrium peaks at
    330 K, its material starts at ``material_temperature`` [K] (a hot-soaked start).

    ``model.design`` is None while the point's ``design`` is set (in a real
    :class:`PointAnalyses` the model's design is the design): the only effects are
    ``whirl_scope`` (500 rad/s instead of 1.15 × 500) and ``actuator_limits`` (no actuators),
    which these tests do not read."""
    temperature = NS(temperature=np.array([320.0, 330.0, 325.0]), x=np.array([0.0, 1.0, 2.0]))
    thermal = NS(self_heating=NS(status="converged"), shaft_temperature=temperature, loss_model="rotating")
    no_modes = NS(
        eigenvalues=np.zeros(0, dtype=complex),
        shaft_fractions=np.zeros(0),
        kind=np.zeros(0, dtype=str),
        whirl=(),
        component=(),
        log_decrements=np.zeros(0),
    )
    return NS(
        operating_speed=500.0,
        design=NS(operating=NS(speed_range=None), thermal=NS(allowable_temperature_c=allowable_c)),
        model=NS(actuators=(), speed=500.0, design=None),
        strength_static=None,
        strength_total=None,
        metal_strength=None,
        coupling_misalignment=None,
        buckling=None,
        stability=NS(speeds=np.array([0.0, 750.0]), onset_speed=None),
        modes_at_speed=no_modes,
        roots=NS(onset_speed=None),
        criticals=NS(criticals=None, note="no unbalance response"),
        thermal=thermal,
        conditions=NS(material_temperature=material_temperature, point=NS(material_temperature="given")),
        spinup=NS(speeds=np.zeros(0), shaft_peak=np.zeros(0), up_to=lambda speed: np.flatnonzero(np.zeros(0) <= speed)),
        torsional_separation=None,
        torsional_modes=None,
        bearing_loops=None,
    )


def test_the_allowable_temperature_is_handed_over_in_kelvin():
    """``allowable_temperature_c`` 100 °C is 100 + 273.15 = 373.15 K; the equilibrium peak 330 K
    (the material starts cooler, at 300 K) is 43.15 K below it. 273.15 is no binary fraction:
    the sum rounds once, a few ulps of 373 (an error of 0.15 K, 273 for 273.15, is 4e-4)."""
    point = _point(100.0, 300.0)
    # the stand-in carries only attributes of a real point (operating_speed is its property)
    assert set(vars(point)) - {"operating_speed"} <= {f.name for f in dataclasses.fields(PointAnalyses)}
    ev = gather.gather_evidence(point)
    assert ev.allowable_temperature == pytest.approx(373.15, rel=4e-16)
    assert ev.max_temperature == 330.0
    check = evaluate(ev).check("temperature")
    assert check.status == "pass"
    assert check.margin == pytest.approx(43.15, rel=1e-14)  # 373.15 − 330: cancels 3 of 16 digits


def test_a_hot_soaked_start_exactly_at_the_allowable_passes_with_zero_margin():
    """The material of a hot-soaked start given at 120 °C, the allowable 120 °C: both are the
    same Kelvin temperature (T = t + 273.15 K, the envelope's conversion of a given material
    temperature, flexshaft.thermal.envelope), above the 330 K equilibrium, so the check's value
    is the allowable itself: margin exactly 0, which passes ("negative fails")."""
    point = _point(120.0, celsius_to_kelvin(120.0))
    assert set(vars(point)) - {"operating_speed"} <= {f.name for f in dataclasses.fields(PointAnalyses)}
    ev = gather.gather_evidence(point)
    check = evaluate(ev).check("temperature")
    assert check.value == check.limit and check.margin == 0.0
    assert check.status == "pass"
    assert check.value == pytest.approx(393.15, rel=4e-16)


# ------------------------------------------------------------------------ a torsional mode in its band


def test_a_torsional_mode_inside_its_excitation_band_fails_and_names_the_band_in_hertz():
    """A torsional mode at 9.46 Hz inside the main rotor's 2/rev band 9.15-10.1 Hz over the speed
    range: its margin is 0 (the table of checks: "0 inside"), which fails the default-like
    ``min_torsional_separation`` 0.1 by 0.1 and passes a requirement of 0 at margin 0; the
    detail names the band in Hz (the evidence carries rad/s: 2π rad/s per Hz)."""
    mode = TorsionalEvidence(
        "T1", 2 * math.pi * 9.46, 0.0, "main rotor 2/rev", (2 * math.pi * 9.15, 2 * math.pi * 10.1)
    )
    ev = Evidence(operating_speed=500.0, torsional_modes=(mode,))
    check = evaluate(ev, Requirements(min_torsional_separation=0.1)).check("torsional_separation")
    assert check.status == "fail" and (check.value, check.limit, check.margin) == (0.0, 0.1, -0.1)
    assert check.location["case"] == "main rotor 2/rev"
    # the band's edges in Hz, parsed rather than matched word for word: 2π·9.15/(2π) is 9.15
    # within an ulp; rel=5e-4 admits printing to 4 significant digits (half a unit of the 4th
    # digit is at most 5e-4 relative), while rad/s labelled Hz is off by the factor 2π
    m = re.fullmatch(r"excitation ([\d.]+)-([\d.]+) Hz\b.*", check.location["detail"])
    assert m, check.location["detail"]
    assert float(m[1]) == pytest.approx(9.15, rel=5e-4)
    assert float(m[2]) == pytest.approx(10.1, rel=5e-4)
    at_zero = evaluate(ev, Requirements(min_torsional_separation=0.0)).check("torsional_separation")
    assert at_zero.status == "pass" and at_zero.margin == 0.0
