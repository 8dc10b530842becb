"""Each loop refined with its own bearing's feedback law: two different laws against the
hand-written plant of a rigid rotor (issue 30).

The loops' refinements evaluate L(iω) = G P_c/(1 − G P_c) of one loop at a time with that
loop's law G. tests/test_loop_robustness.py checks the model's loop against the rigid rotor's
plant with both bearings on one PID law, where taking the other bearing's law changes nothing;
here bearing 2 runs a stiffer, more damped law (k_p 2.5e4 A/m, k_d 16 A s/m against 1.5e4 and
10), so each bearing's margins differ, and each is checked against its own closed form.

Derived (one plane, at rest, the rotor rigid: b_j = (1, x_j) about its centre, x = ∓0.4 m): loop
j's plant with the other bearing i closed is P_j = b_jᵀ Z_j⁻¹ b_j with
Z_j = diag(m s², I_t s²) − k_s b_j b_jᵀ + (G_i − k_s) b_i b_iᵀ, and L_j = G_j P_j,
G(s) = k_i (k_p + k_I/s + k_d s/(1 + s/ω_d))/(1 + s/ω_a). The FE rotor is 1e4 times stiffer
than steel: as in tests/test_loop_robustness.py the margins agree to 1e-4 (its rigid-body
roots differ from the closed form by ~1e-6, amplified near the lightly damped peaks).

CPU: the model and its loops on the default 200-point grid, about 0.2 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_loop_robustness import HALF_SPAN, I_T, KI, KS, M_ROTOR, PID, rotor_text

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.loop_margins import loop_margins
from flexshaft.assembly import build_model
from flexshaft.design import loads_design, with_overrides

SECOND_LAW = {"kp": 2.5e4, "kd": 16.0}
#: b_j of each bearing on the rigid rotor, (1, x_j) about its centre
LEVER = {"amb_1": np.array([1.0, -HALF_SPAN]), "amb_2": np.array([1.0, HALF_SPAN])}


def law(s, kp: float, kd: float, k_integral: float = PID["integral_gain"]):
    """G(s) of the docstring with PID's filter and amplifier, at gains (k_p, k_d, k_I)."""
    wd, wa = 2 * np.pi * PID["derivative_cutoff"], 2 * np.pi * PID["amplifier_bandwidth"]
    return KI * (kp + k_integral / s + kd * s / (1 + s / wd)) / (1 + s / wa)


def rigid_loop(laws: dict, own: str, other: str):
    """L_j(iω) of bearing ``own``'s loop with ``other`` closed on the rigid rotor (docstring);
    ``laws`` maps each bearing to the gains of :func:`law`."""

    def loop(w):
        out = []
        for s in 1j * np.asarray(w, dtype=float):
            Z = np.diag([M_ROTOR * s * s, I_T * s * s]) - KS * np.outer(LEVER[own], LEVER[own])
            Z += (law(s, *laws[other]) - KS) * np.outer(LEVER[other], LEVER[other])
            out.append(law(s, *laws[own]) * (LEVER[own] @ np.linalg.solve(Z, LEVER[own])))
        return np.array(out)

    return loop


def test_each_loop_is_refined_with_its_own_bearings_law():
    design = loads_design(rotor_text(2.1e15, PID))
    model = build_model(with_overrides(design, {f"bearings[1].{k}": v for k, v in SECOND_LAW.items()}))
    loops = bearing_loops(model, frequency_range=(0.5, 2000.0))
    assert [(lp.actuator, lp.axis) for lp in loops] == [("amb_1", "v"), ("amb_1", "w"), ("amb_2", "v"), ("amb_2", "w")]
    laws = {"amb_1": (PID["kp"], PID["kd"]), "amb_2": (SECOND_LAW["kp"], SECOND_LAW["kd"])}
    references = {
        own: loop_margins(rigid_loop(laws, own, other), 2 * np.pi * loops[0].frequencies)
        for own, other in (("amb_1", "amb_2"), ("amb_2", "amb_1"))
    }
    one, two = references["amb_1"], references["amb_2"]
    assert abs(one.phase_margin_deg / two.phase_margin_deg - 1) > 0.01  # the two laws' loops differ
    for lp in loops:
        m, r = lp.margins, references[lp.actuator]
        assert m.peak_sensitivity == pytest.approx(r.peak_sensitivity, rel=1e-4)
        assert m.phase_margin_deg == pytest.approx(r.phase_margin_deg, rel=1e-4)
        assert m.gain_margin_upper_db == pytest.approx(r.gain_margin_upper_db, rel=1e-4)
        assert m.gain_margin_lower_db == pytest.approx(r.gain_margin_lower_db, rel=1e-4)
