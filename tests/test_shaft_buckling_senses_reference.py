"""The laminated shaft's buckling numbers in each sense of the torque, by mirror symmetry.

An unbalanced laminate buckles at different torques in the two senses (the fibres of a [+45]
ply are stretched by one sense and compressed by the other; the laminated shell of
:mod:`flexshaft.buckling`). Reflecting the tube in a plane through its axis maps the ply angle
θ to −θ and the torque T to −T, and leaves a simply supported tube, its radius and length
unchanged: the [−45] tube's positive-sense numbers (critical, global and crimping torques, wave
number) are the [+45] tube's negative-sense numbers and the other way round. So each sense of
the [+45] tube is checked against the other tube's opposite sense, for the shear-deformable
shell and for the classical one, whose critical torque in the weaker sense is
min(T₊, T₋) = min(T₊[+45], T₊[−45]). The tube (0.2 m long, 101.6 mm, 3 mm of a carbon/epoxy
ply) is short enough that the two senses differ by a factor 2 and buckle in different wave
numbers (4 and 2). Tolerance 1e-9: the mirror image is the same Ritz problem with its coupling
terms' signs reversed, solved to round-off.

The mirror cannot tell which sense is which (a convention flipped in both tubes passes it), so
the senses are anchored independently by the crimping closed form of
tests/test_buckling_weaker_sense_reference.py: for plies at +45°, T₊ = 2πR² k t G₂₃ and
T₋ = 2πR² k t G₁₃, R = (D − t)/2 = 49.3 mm the mid-surface radius, k = 5/6 the lamina's default
shear correction, and the ply's defaults in :mod:`flexshaft.design.materials` G₁₃ = G_LT = 4 GPa,
G₂₃ = E_T/(2(1 + ν₂₃)) = E_T/3 = 2.667 GPa (ν₂₃ = 0.5): T₊ = 101 808.127 N m,
T₋ = 152 712.191 N m. The package evaluates the same closed form of A (A44 = A55 =
k t (G₁₃ + G₂₃)/2, A45 = k t (G₁₃ − G₂₃)/2, T = 2πR²(√(A44 A55) ∓ A45)); the difference loses
about G₁₃/G₂₃ = 1.5 ulp, so 1e-12 relative. Each sense's critical torque is the lowest of its
global helix, its crimping limit and any shorter wave below both (:mod:`flexshaft.buckling.shear`);
this tube has none, so it is min(global, crimping): the global helix, 9.2 and 19.4 kN m, far
below crimping. The positive sense is the weaker: a positive torque (vector
along +x on the end x = L, the convention of :mod:`flexshaft.buckling`) stretches the +45°
fibres and compresses the −45° diagonal, across the fibres, where only the matrix carries
(E_T = 8 GPa against E_L = 120 GPa), so the compressed diagonal buckles sooner; for crimping
the positive sense takes the smaller transverse shear modulus, G₂₃ < G₁₃.
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from flexshaft.analyses.shaft_buckling import shaft_buckling
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

L, D, WALL = 0.2, 0.1016, 0.003

TUBE = f"""
name = "one-ply tube"
[materials.ply]
kind = "lamina"
density = 1600.0
E_L = 120.0e9
E_T = 8.0e9
G_LT = 4.0e9
nu_LT = 0.3
X_t = 2000.0e6
X_c = 1000.0e6
Y_t = 40.0e6
Y_c = 140.0e6
S = 60.0e6
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D}
wall_thickness = {WALL}
material = "ply"
layup = "ANGLE"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "stop"
kind = "contact"
x = {L}
stiffness = {{}}
[operating]
speed_rpm = 4000.0
power = 150e3
[mesh]
shaft_elements = 4
"""


def _model(angle: str):
    return build_model(loads_design(TUBE.replace("ANGLE", angle)))


@pytest.fixture(scope="module")
def pair():
    plus, minus = _model("45"), _model("-45")
    return plus, minus, shaft_buckling(plus).to_dict(), shaft_buckling(minus).to_dict()


def test_each_sense_is_the_mirror_tubes_other_sense(pair):
    _, _, plus, minus = pair
    for key in ("critical_torque", "global_torque", "crimping_torque"):
        assert plus[f"{key}_negative_Nm"] == pytest.approx(minus[f"{key}_positive_Nm"], rel=1e-9)
        assert plus[f"{key}_positive_Nm"] == pytest.approx(minus[f"{key}_negative_Nm"], rel=1e-9)
    assert plus["wave_number_negative"] == minus["wave_number_positive"]
    assert plus["wave_number_positive"] == minus["wave_number_negative"]
    # the senses differ, so a sense read for the other cannot pass the above
    assert plus["critical_torque_negative_Nm"] > 1.5 * plus["critical_torque_positive_Nm"]
    assert plus["wave_number_positive"] != plus["wave_number_negative"]
    assert plus["global_torque_positive_Nm"] < 0.5 * plus["crimping_torque_positive_Nm"]


def test_the_classical_comparison_is_the_weaker_sense(pair):
    plus_model, minus_model, plus, _ = pair
    senses = [
        shaft_buckling(m, theory="classical").result.torque_positive for m in (plus_model, minus_model)
    ]  # T₊ of [+45] and T₊ of [−45] = T₋ of [+45]
    assert max(senses) > 1.5 * min(senses)
    assert plus["classical_critical_torque_Nm"] == pytest.approx(min(senses), rel=1e-9)


def test_the_senses_crimping_limits_and_critical_torques_by_closed_form(pair):
    _, _, plus, _ = pair
    crimping = 2 * math.pi * ((D - WALL) / 2) ** 2 * (5 / 6) * WALL  # 2πR² k t, per pascal of G
    g13, g23 = 4.0e9, 8.0e9 / 3  # G_LT and E_T/3, the lamina's defaults
    assert plus["crimping_torque_positive_Nm"] == pytest.approx(crimping * g23, rel=1e-12)  # 101 808.127
    assert plus["crimping_torque_negative_Nm"] == pytest.approx(crimping * g13, rel=1e-12)  # 152 712.191
    for sense in ("positive", "negative"):
        lower = min(plus[f"global_torque_{sense}_Nm"], plus[f"crimping_torque_{sense}_Nm"])
        assert plus[f"critical_torque_{sense}_Nm"] == pytest.approx(lower, rel=1e-12)
    assert plus["critical_torque_positive_Nm"] < plus["critical_torque_negative_Nm"]  # the weaker sense


def test_the_safety_factor_takes_the_weaker_sense_whichever_way_the_plies_lean(pair):
    """The drive's handedness is not known to the check, so its safety factor is the weaker
    sense's T_cr over T = P/Ω (:mod:`flexshaft.analyses.shaft_buckling`): the same for the
    [+45] tube, whose positive sense is the weaker, and its mirror image [−45], whose negative
    sense is. T = 150 kW/(4000 rpm · 2π/60) = 358.098622 N m by hand. Tolerance 1e-12: one
    division of the numbers checked by the mirror above."""
    _, _, plus, minus = pair
    torque = 150e3 / (4000.0 * 2.0 * math.pi / 60.0)
    assert minus["torque_Nm"] == pytest.approx(torque, rel=1e-12)
    assert minus["critical_torque_negative_Nm"] < minus["critical_torque_positive_Nm"]  # the mirror's weaker sense
    for tube in (plus, minus):
        weaker = min(tube["critical_torque_positive_Nm"], tube["critical_torque_negative_Nm"])
        assert tube["safety_factor"] == pytest.approx(weaker / torque, rel=1e-12)
    assert minus["safety_factor"] == pytest.approx(plus["safety_factor"], rel=1e-9)


def test_the_printed_summary_names_the_weaker_senses_mode(pair):
    """The summary prints T_cr = min(T₊, T₋) and the mode that governs it, the weaker sense's.
    The [−45] tube's weaker sense is the negative one (the mirror of [+45]); its modes are
    relabelled by hand, the positive sense "global helical" and the negative "shear crimping",
    so the summary must name shear crimping at the negative sense's torque."""
    _, minus_model, _, minus = pair
    found = shaft_buckling(minus_model)
    relabelled = replace(
        found, result=replace(found.result, governing_positive="global helical", governing_negative="shear crimping")
    )
    weaker = minus["critical_torque_negative_Nm"]
    assert weaker < minus["critical_torque_positive_Nm"]
    assert f"T_cr {weaker:.4g} N m (shear crimping)" in repr(relabelled)
