"""The spin-up response's one-line summary, and an added speed at an undamped resonance.

Summary (hand-typed arrays, references derived here): a scan of 100, 150 and 200 rad/s whose
shaft envelope (two nodes) peaks at the middle speed, 0.12 mm, and an active bearing ``b``
whose relative orbit peaks at 4e-5 m and force at 50 N. The summary reports the largest shaft
orbit and the speed where it occurs, and the actuators' largest orbit and force:
Ω [rpm] = Ω [rad/s] · 60/(2π), so 100, 150, 200 rad/s are 954.9, 1432.4, 1909.9 rpm (shown
whole: "955", "1432", "1910"), and 1 m = 1000 mm (0.12 mm, 0.04 mm at 3 significant figures).
Exact strings: the numbers are formatted, not computed.

Singular speed (closed form, the undamped rigid rotor of
tests/test_critical_search_load_cases_reference.py without its dashpots): the in-phase
imbalance case drives the pure translation M ẍ + 3k x = e M Ω² (no rotation, so no gyroscopic
coupling), x = e M Ω²/(3k − M Ω²), singular at ω_t = √(3k/M). The model's own singular speed
(its near-rigid tube's flexibility moves it by ~1e-6 relative) is found by Brent's method
(``brentq``) on the reciprocal of the disk's response, which changes sign through the
resonance, and is confirmed singular (:class:`~flexshaft.analyses.banded.SingularSystemError`).
This rests on no exact float: the near-rigid tube (E = 2.1e15 Pa) makes the dynamic stiffness
so ill-conditioned that SingularSystemError is raised throughout about ±1.5e-7 relative of
the root (regular at ±2e-7 and beyond; measured with OpenBLAS Prescott and Haswell), and
Brent's method stops at the first singular speed it meets, where ``reciprocal`` returns 0
(its fourth evaluation, after one at 1.5e-6 from the root), so xtol and rtol play no role.
``with_speeds`` documents that such a speed is skipped, and the other added speeds kept:
0.9 ω_t below it and 1.1 ω_t above, where every node moves by |x| (the anti-phase case's
rocking, e M/(4I) · 0.5 m ≈ 2e-7 m, is about 200 times smaller, so the in-phase case is the
worst). Tolerance 1e-4 relative on |x|: the model's translation frequency differs from ω_t by
~1e-6 relative, which moves x by ~1e-6 · 2/|1 − (Ω/ω_t)²| ≈ 1e-5 at 0.9 and 1.1 ω_t
(measured 1.2e-5 and 1.6e-5, the tube's flexibility included). CPU about 0.1 s.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq
from test_critical_search_load_cases_reference import KB, M_TOTAL, TEXT, C

from flexshaft.analyses.banded import SingularSystemError
from flexshaft.analyses.response import imbalance_response
from flexshaft.analyses.spinup_response import SpinupResponse, spinup_response, with_speeds
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import loads_design

ECCENTRICITY = 1e-5  # m, the design text's
W_T = math.sqrt(3 * KB / M_TOTAL)  # rad/s, the undamped translation


def _summary_of_a_hand_scan() -> SpinupResponse:
    speeds = np.array([100.0, 150.0, 200.0])
    envelope = np.array([[0.02e-3, 0.12e-3, 0.05e-3], [0.01e-3, 0.07e-3, 0.09e-3]])  # m
    orbits = envelope[:, None, :]
    return SpinupResponse(
        speeds=speeds,
        response=np.zeros((4, 1, 3), complex),
        orbits=orbits,
        worst_case=np.zeros(3, dtype=int),
        envelope=envelope,
        actuator_displacement={"b": np.array([1e-5, 4e-5, 2e-5])},
        actuator_force={"b": np.array([10.0, 50.0, 20.0])},
    )


def test_the_summary_names_the_peak_orbit_its_speed_and_the_actuators_in_mm():
    """The shaft's peak is 0.12 mm at 150 rad/s = 1432 rpm (not the 0.09 mm = max(0.05, 0.09) mm
    reached at the top speed, nor the smallest); the bearing's peak orbit 4e-5 m = 0.04 mm, its
    force 50 N."""
    text = repr(_summary_of_a_hand_scan())
    assert text == (
        "SpinupResponse(3 speeds 955 to 1910 rpm, peak shaft orbit 0.12 mm at 1432 rpm; actuators b 0.04 mm, 50 N)"
    )


def _undamped_model():
    text = TEXT.replace(f"damping = {{ v = {C}, w = {C} }}\n", "")
    assert "damping" not in text
    return build_model(loads_design(text))


def _singular_speed(model) -> float:
    """The model's undamped translation speed: the root of 1/Re(v) at the disk, in phase."""
    loads = imbalance_loads(model)[:, :1]
    v = model.dofs.shaft(model.dofs.node_at("shaft", 0.5), "v")

    def reciprocal(speed: float) -> float:
        try:
            q = np.asarray(imbalance_response(model, [speed], loads))
        except SingularSystemError:
            return 0.0
        return 1.0 / q[v, 0, 0].real

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the resonance warnings of the speeds near the root
        # Brent's method: it ends at the first singular speed it meets (reciprocal = 0 there)
        return brentq(reciprocal, W_T * (1 - 1e-3), W_T * (1 + 1e-3), xtol=1e-14, rtol=4 * np.finfo(float).eps)


def test_a_singular_added_speed_is_skipped_and_the_speeds_above_it_kept():
    model = _undamped_model()
    singular = _singular_speed(model)
    assert singular == pytest.approx(W_T, rel=1e-5)
    with pytest.raises(SingularSystemError), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        imbalance_response(model, [singular], imbalance_loads(model))
    scan = spinup_response(model, np.array([0.5, 0.7]) * W_T, projected=False)
    below, above = 0.9 * W_T, 1.1 * W_T
    added = with_speeds(model, scan, [below, singular, above])
    assert added.speeds == pytest.approx(np.array([0.5, 0.7, 0.9, 1.1]) * W_T, rel=1e-15)
    for speed in (below, above):
        k = int(np.argmin(np.abs(added.speeds - speed)))
        x = ECCENTRICITY * M_TOTAL * speed**2 / abs(3 * KB - M_TOTAL * speed**2)
        assert added.worst_case[k] == 0  # the in-phase case
        assert added.envelope[:, k] == pytest.approx(np.full(added.envelope.shape[0], x), rel=1e-4)
