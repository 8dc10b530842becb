"""The rules that say which point, which check and which temperature reach the verdict of an
envelope (flexshaft.verdict.envelope, flexshaft.design.envelope, flexshaft.verdict.gather,
flexshaft.verdict.evidence, flexshaft.design.segments), each against the rule's documented
statement (no number the code produced):

* envelope_verdict keeps a check listed at a later point only (module docstring of
  flexshaft.verdict.envelope: "a check listed at some point only follows them"): a requirement a
  point cannot list must not vanish from the envelope's verdict;
* governing_point names the first point when no check was evaluated anywhere (its docstring);
* an Evidence without a spin-up (a point at rest: gather gives no spinup_peak) leaves the
  spin-up deflection check "not evaluated", never a pass on a zero orbit;
* the whirl-damping check's scope ends at the highest lateral whirl mode computed, whatever its
  shaft share (gather._whirl_modes_top's docstring): a boom-dominated mode above the shaft's
  lengthens it;
* a point that names no material temperature puts the shaft at the ambient (the "ambient" source,
  design.envelope's docstring: "a cold-soaked start"): T_m = T_amb + 273.15 K exactly, not the
  boom's hover air, on a design with a tailboom, whose hover air is warmer than the ambient;
* envelope_point finds a design's own point before the default of that name;
* a coupling without ``allowable_angle_deg`` is not checked (Coupling's docstring: "omitted: not
  checked"): through the model, its misalignment, gather and evaluate, the coupling_angle check
  is "not evaluated" and names the coupling, and judged once an allowable angle is given.

All cheap: synthetic evidence, verdicts and modes, one design dump, the boom's closed-form
temperatures and two 20-element hinged tubes (well under 0.5 s together).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.analyses.misalignment import coupling_misalignment
from flexshaft.assembly import build_model
from flexshaft.design import baseline_design, design_from_dict, with_overrides
from flexshaft.design.envelope import EnvelopePoint, envelope_point
from flexshaft.design.requirements import Requirements
from flexshaft.thermal.envelope import point_conditions
from flexshaft.verdict.checks import evaluate
from flexshaft.verdict.envelope import PointAssessment, envelope_verdict, governing_point
from flexshaft.verdict.evidence import Evidence, ModeDamping
from flexshaft.verdict.gather import _couplings, _whirl_modes_top
from flexshaft.verdict.result import Verdict

OP = 500.0  # rad/s


def _point(name: str, keep=lambda c: True, **values) -> PointAssessment:
    ev = Evidence(
        operating_speed=OP, stability_max_speed=1.5 * OP, modes_at_operating=(ModeDamping("1", 300.0, 0.2),), **values
    )
    verdict = evaluate(ev)
    return PointAssessment(
        name=name, analyses=None, evidence=ev, verdict=Verdict(tuple(c for c in verdict.checks if keep(c)))
    )


def test_a_check_listed_at_a_later_point_only_stays_in_the_envelope_verdict():
    """Tsai-Wu is not listed at "cold" and is 1.2 (< 1.5: fails) at "hot": the envelope fails it
    at "hot"."""
    cold = _point("cold", keep=lambda c: c.key != "tsai_wu", safety_factor=3.0, safety_factor_location={})
    hot = _point("hot", safety_factor=1.2, safety_factor_location={"station": 2.0})
    assert "tsai_wu" not in [c.key for c in cold.verdict.checks]
    check = envelope_verdict([cold, hot]).check("tsai_wu")
    assert check.status == "fail" and check.value == 1.2 and check.location["point"] == "hot"


def test_the_first_point_governs_when_no_check_was_evaluated():
    points = [_point(n, keep=lambda c: c.status == "not evaluated") for n in ("a", "b", "c")]
    assert all(c.status == "not evaluated" for p in points for c in p.verdict.checks)
    assert governing_point(points) == "a"


def test_no_spinup_response_leaves_the_spinup_check_not_evaluated():
    """A limit of 1 mm is given; the evidence has no spin-up peak (a point at rest)."""
    check = evaluate(Evidence(operating_speed=0.0), Requirements(max_spinup_deflection=1e-3)).check("spinup_deflection")
    assert check.status == "not evaluated" and check.value is None


def test_the_whirl_scope_ends_at_the_highest_whirl_mode_whatever_its_shaft_share():
    """Two lateral whirl modes (ζ = 0.005): 100 rad/s with 90 % of its energy in the shaft, 200
    rad/s with 2 % (a boom mode): the scope's top is 200 rad/s; the overdamped root (ζ = 1) and a
    torsional mode at 300 rad/s are no whirl modes."""
    s = np.array([-0.5 + 100j, -1.0 + 200j, -400.0 + 0j, -0.5 + 300j])
    modes = SimpleNamespace(
        eigenvalues=s, kind=np.array(["lateral", "lateral", "lateral", "torsional"]), shaft_fractions=[0.9, 0.02, 1, 1]
    )
    assert _whirl_modes_top(SimpleNamespace(modes_at_speed=modes)) == 200.0


def test_a_point_without_a_material_temperature_puts_the_shaft_at_the_ambient():
    """The baseline has a tailboom, whose hover air lies above the ambient (asserted below):
    the ambient source must give T_amb exactly (-20 °C = 253.15 K)."""
    design = baseline_design()
    assert design.tailboom is not None
    ambient = point_conditions(design, EnvelopePoint(name="p", ambient_temperature_c=-20.0))
    hover = point_conditions(
        design, EnvelopePoint(name="q", ambient_temperature_c=-20.0, material_temperature="shaft_air")
    )
    assert ambient.material_temperature == pytest.approx(253.15, abs=1e-9)
    assert hover.material_temperature > ambient.material_temperature + 1.0  # the sources differ here


def test_a_designs_own_point_comes_before_the_default_of_its_name():
    design = with_overrides(baseline_design(), {"envelope.points[0].ambient_temperature_c": -55.0})
    assert design.envelope.points[0].name == "cold_day"
    assert envelope_point(design, "cold_day").ambient_temperature_c == -55.0


def _coupling_angle_check(**coupling):
    """The coupling_angle check of a 20-element tube on pinned ends with a hinge ``c`` at 0.5 m
    (the hinged tubes of tests/test_misalignment_total_angle_reference.py), from the design's
    coupling through the model, its misalignment (at rest: zero angles), gather and evaluate."""
    length = 1.2
    data = {
        "name": "hinged tube",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": length,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": length, "stiffness": {"u": 0.0}}],
        "couplings": [
            {"name": "c", "x": 0.5, "angular_stiffness": 1e4, "axial_stiffness": "rigid", "torsional_stiffness": 1e5}
            | coupling
        ],
        "operating": {"speed_rpm": 3000.0, "power": 0.0},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 20},
    }
    model = build_model(design_from_dict(data))
    angles = coupling_misalignment(model, np.zeros(model.dofs.size))
    evidence = Evidence(operating_speed=OP, **_couplings(SimpleNamespace(coupling_misalignment=angles)))
    return evaluate(evidence).check("coupling_angle")


def test_a_coupling_without_an_allowable_angle_is_not_checked():
    """Coupling's docstring: ``allowable_angle_deg`` "omitted: not checked". Omitted, the check is
    not evaluated and its note names the coupling; given (1°), the same coupling's zero angle is
    judged (a pass with the limit in radians): the omission is what leaves it unjudged."""
    omitted = _coupling_angle_check()
    assert omitted.status == "not evaluated" and omitted.value is None
    assert "allowable_angle_deg" in omitted.note and "(c)" in omitted.note
    given = _coupling_angle_check(allowable_angle_deg=1.0)
    assert given.status == "pass" and given.limit == pytest.approx(np.radians(1.0), rel=1e-12)
