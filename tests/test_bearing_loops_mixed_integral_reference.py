"""The loops of two magnetic bearings of which only one integrates: bearing 1 runs the PID law of
tests/test_loop_robustness.py, bearing 2 a filtered PD law without integral action (k_p 2.5e4
A/m, k_d 16 A s/m). The loop analysis must still run and give each loop's margins.

Derived as in tests/test_bearing_loops_two_laws_reference.py (one plane, at rest, the rotor
rigid: b_j = (1, x_j) about its centre, x = ∓0.4 m): loop j's plant with the other bearing i
closed is P_j = b_jᵀ Z_j⁻¹ b_j with Z_j = diag(m s², I_t s²) − k_s b_j b_jᵀ + (G_i − k_s) b_i b_iᵀ
and L_j = G_j P_j, G(s) = k_i (k_p + k_I/s + k_d s/(1 + s/ω_d))/(1 + s/ω_a), k_I = 0 for
bearing 2. The FE rotor is 1e4 times stiffer than steel: the margins agree to 1e-4 as there.

The static loop gain L(0): bearing 1's is infinite (C(0) = ∞: no crossover at ω = 0), and at
ω = 0 its integrator holds its sensed displacement at zero, so the rotor pivots about bearing 1
and bearing 2's plant is P₂(0) = −1/k_s (its magnet's negative stiffness alone):
L₂(0) = −k_i k_p₂/k_s = −100 × 2.5e4/5e5 = −5, a phase crossover at ω = 0 with the lower gain
margin −20 log10 5 = −13.98 dB (the PD bearing's gain may fall by that before the magnet pulls
the rotor over). It used to be dropped (no static crossover of any loop when any bearing
integrates: the lower margin read −inf, a gain-margin check blind to it). The references
below give bearing 1's loop no static crossover (``static_gain=None``) and bearing 2's this
L₂(0).

Written for the mutations h37a-loop-static-gain-any-integrator (the static gain solved on the
loops' banded solver unless every bearing integrates: singular at ω = 0) and
h37a-loop-static-dropped-beside-integrator (the old gap) of scripts/mutations.toml. The same L₂(0)
holds for the rotor free to twist: its torsion is a block of its own that no loop touches, and
the static problem is solved on the loops' blocks (mutation lead18-loop-static-whole-model: the
whole model's static problem, singular there, and the margin lost again). CPU: each model and
its loops on the default grid, about 0.3 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_bearing_loops_two_laws_reference import rigid_loop
from test_loop_robustness import KI, KS, PID, rotor_text

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.loop_margins import loop_margins
from flexshaft.assembly import build_model
from flexshaft.design import loads_design, with_overrides

PD_LAW = {"kp": 2.5e4, "kd": 16.0, "integral_gain": 0.0}


def _loops(text: str):
    model = build_model(with_overrides(loads_design(text), {f"bearings[1].{k}": v for k, v in PD_LAW.items()}))
    assert [a.integrates for a in model.actuators] == [True, False]
    return bearing_loops(model, frequency_range=(0.5, 2000.0))


@pytest.fixture(scope="module")
def loops():
    return _loops(rotor_text(2.1e15, PID))


@pytest.fixture(scope="module")
def free_twist_loops():
    """The same rotor free to twist (no fixed θ): its whole static problem is singular (the
    torsional rigid-body motion), its lateral one, where the loops are, is not."""
    text = rotor_text(2.1e15, PID)
    assert 'fixed_start = ["u", "theta"]' in text
    return _loops(text.replace('fixed_start = ["u", "theta"]', 'fixed_start = ["u"]'))


def test_a_pd_bearing_beside_an_integrating_one_has_its_own_margins(loops):
    laws = {
        "amb_1": (PID["kp"], PID["kd"], PID["integral_gain"]),
        "amb_2": (PD_LAW["kp"], PD_LAW["kd"], PD_LAW["integral_gain"]),
    }
    grid = 2 * np.pi * loops[0].frequencies
    static = {"amb_1": None, "amb_2": -KI * PD_LAW["kp"] / KS}  # L(0): pivoting about bearing 1
    references = {
        own: loop_margins(rigid_loop(laws, own, other), grid, static[own])
        for own, other in (("amb_1", "amb_2"), ("amb_2", "amb_1"))
    }
    for lp in loops:
        m, r = lp.margins, references[lp.actuator]
        assert m.peak_sensitivity == pytest.approx(r.peak_sensitivity, rel=1e-4)
        assert m.phase_margin_deg == pytest.approx(r.phase_margin_deg, rel=1e-4)
        assert m.gain_margin_upper_db == pytest.approx(r.gain_margin_upper_db, rel=1e-4)
        assert np.isfinite(m.gain_margin_lower_db)  # bearing 1's at a finite ω, bearing 2's at 0
        assert m.gain_margin_lower_db == pytest.approx(r.gain_margin_lower_db, rel=1e-4)


@pytest.mark.parametrize("which", ["twist held", "free to twist"])
def test_the_pd_loops_lower_gain_margin_at_zero_frequency(which, request):
    loops = request.getfixturevalue("loops" if which == "twist held" else "free_twist_loops")
    expected = -20.0 * np.log10(KI * PD_LAW["kp"] / KS)  # L(0) = −k_i k_p/k_s, pivoting about bearing 1
    two = [lp.margins for lp in loops if lp.actuator == "amb_2"]
    assert len(two) == 2 and expected == pytest.approx(-13.979400, abs=1e-6)
    for m in two:
        assert m.gain_margin_lower_db == pytest.approx(expected, rel=1e-4)
        assert m.phase_crossovers[0] == 0.0


def test_a_restricted_static_solve_refuses_a_mask_that_drops_a_load():
    """``static_response(within=)`` solves on a subset of the free DOFs and is exact only when the
    loads are zero outside it: a mask of the wrong length, or one that leaves out a loaded DOF,
    is refused by name rather than solved wrong."""
    from flexshaft.analyses.response import static_response

    model = build_model(loads_design(rotor_text(2.1e15, PID)))
    free = model.dofs.free
    loads = np.zeros(model.dofs.size)
    loads[free[0]] = 1.0
    keep = np.ones(free.size, dtype=bool)
    with pytest.raises(ValueError, match="mask of the"):
        static_response(model, loads, 0.0, within=keep[:-1])
    keep[0] = False
    with pytest.raises(ValueError, match="every loaded DOF"):
        static_response(model, loads, 0.0, within=keep)
