"""ResonanceWarning near an undamped gyroscopic (backward-whirl) resonance, from a closed form.

Model (derived here): a rigid disk of diametral inertia I_d and polar inertia I_p = 2 I_d at the
midspan of a pinned-pinned Euler-Bernoulli tube of length L, nearly massless (density 1e-6
kg/m³: its mass, 7e-10 kg, and rotary inertia move the disk's frequencies by about 1e-11
relative). By symmetry the disk's tilt decouples from its translation; a moment M at the
midspan of a simply supported beam turns the section there by θ = M L / (12 E I), so the tilt
stiffness is k_θ = 12 E I / L (the cubic Hermite elements are exact for nodal loads, the
midspan being a node). In complex tilt coordinates the disk spinning at Ω obeys

    Z_b(ω) = k_θ − I_d ω² − I_p Ω ω      (backward whirl)

whose root at Ω = ω is ω_b = √(k_θ / (3 I_d)) for I_p = 2 I_d. There

    ∂Z_b/∂ω = −2 I_d ω − I_p Ω = −4 I_d ω_b,

and at ω = ω_b (1 + δ), Z_b ≈ ∂Z_b/∂ω · δ ω_b, so the sensitivity the solver documents
(banded module docstring), κ_ω = ω ‖Z⁻¹ (∂Z/∂ω) q‖ / ‖q‖ with ∂Z/∂ω = −2ωM + i(ΩG + C), is
1/δ to first order (the non-resonant forward-whirl and translation parts add O(1)). The rule
quoted from that docstring: κ_ω is computed only when the factor's pivots are screened (their
smallest/largest ratio below PIVOT_SCREEN = 1e-8; measured 2.5e-10 here for the factorised lateral
block, 40× below), and above 1/RESONANCE_TOLERANCE = 1e5 a ResonanceWarning is given, its message
stating 1/κ_ω, "within about ... (relative) of an undamped resonance".

A real unit moment on one tilt DOF splits equally into forward and backward whirl, so the
resonant part of that tilt is 1/(2 |Z_b|) = 1/(2 · 4 I_d ω_b² δ): a check that ω_b is the
model's resonance (to about 1e-11, 1 % of δ = 1e-9).
"""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

from flexshaft.analyses.banded import RESONANCE_TOLERANCE, BandedHarmonicSolver, ResonanceWarning
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

E, G = 210e9, 80e9
DO, DI, L = 0.05, 0.04, 1.0
I_D, I_P = 0.1, 0.2
I_AREA = np.pi * (DO**4 - DI**4) / 64
K_TILT = 12 * E * I_AREA / L
W_B = np.sqrt(K_TILT / (3 * I_D))  # the backward-whirl resonance at Ω = ω (I_p = 2 I_d)
# κ_ω = 1e9: far above 1e5; the pivot spread of the factorised lateral block (rows 0-32) is
# 2.5e-10 (2.5e-9 at δ = 1e-8), screened (below 1e-8). With the torsion column of the second
# test the loaded span also holds the axial block, and the spread is 4.1e-12.
DELTA = 1e-9

TEXT = f"""
name = "midspan disk with gyroscopic tilt"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = 1e-6
loss_factor = 0.0
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {(DO - DI) / 2}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "no_damper"
kind = "contact"
x = {L / 2}
stiffness = {{}}
damping = {{}}
[[disks]]
name = "disk"
x = {L / 2}
mass = 20.0
diametral_inertia = {I_D}
polar_inertia = {I_P}
[operating]
speed_rpm = 0.0
power = 0.0
[mesh]
shaft_elements = 8
"""


@pytest.fixture(scope="module")
def rotor():
    model = build_model(loads_design(TEXT))
    free = list(model.dofs.free)
    node = model.dofs.node_at("shaft", L / 2)
    return (
        BandedHarmonicSolver(model),
        free.index(model.dofs.shaft(node, "beta")),
        free.index(model.dofs.shaft(node, "theta")),
    )


def _solve_recording(solver, rhs):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        x = solver.solve(W_B * (1 + DELTA), rhs, speed=W_B)
    return x, [w for w in caught if issubclass(w.category, ResonanceWarning)]


def _quoted_distance(warning) -> float:
    """1/κ_ω as the message states it ("within about 1.0e-09 (relative)")."""
    return float(re.search(r"within about ([0-9.e+-]+) \(relative\)", str(warning.message)).group(1))


def test_backward_whirl_resonance_warns_with_its_closed_form_distance(rotor):
    """κ_ω = 1/δ = 1e9 at ω = ω_b (1 + 1e-9), Ω = ω_b (module docstring): a ResonanceWarning
    that quotes 1/κ_ω = δ. Tolerance 10 %: the quoted value has two significant digits, the
    resonance lies within 1e-11 of ω_b (1 % of δ) and the O(1) non-resonant parts of κ_ω are
    1e-9 of it. The tilt amplitude 1/(2 · 4 I_d ω_b² δ) within 5 % (same 1 % offset) checks
    that ω_b is the model's resonance. ∂Z/∂ω with the gyroscopic term of the opposite sign
    (−2 I_d ω + I_p Ω, zero here) makes κ_ω of order one and loses the warning."""
    solver, beta, _ = rotor
    rhs = np.zeros(solver.n)
    rhs[beta] = 1.0
    x, caught = _solve_recording(solver, rhs)
    amplitude = 1.0 / (2 * 4 * I_D * W_B**2 * DELTA)
    assert abs(x[beta]) == pytest.approx(amplitude, rel=0.05)
    assert 1 / DELTA > 1 / RESONANCE_TOLERANCE
    assert len(caught) == 1
    assert _quoted_distance(caught[0]) == pytest.approx(DELTA, rel=0.1)


def test_two_load_columns_warn_when_one_of_them_is_resonant(rotor):
    """Two load columns solved at once: the tilt moment of the previous test (κ_ω = 1/δ =
    1e9) and a torsional moment at the disk, whose block is uncoupled from the lateral one:
    its response is the torsion mode's, κ_ω = 2 ω² / |ω_t² − ω²| ≈ 2.5 with ω_t =
    √(G J/(L/2) / I_p) = 538 rad/s. The response is within 1e-9 of a resonance whichever
    column shows it, so the warning is given and quotes the resonant column's 1/κ_ω = δ (10 %,
    as above); the least sensitive column's κ_ω would hide it."""
    solver, beta, theta = rotor
    rhs = np.zeros((solver.n, 2))
    rhs[beta, 0] = 1.0
    rhs[theta, 1] = 1.0
    x, caught = _solve_recording(solver, rhs)
    assert np.all(np.abs(x[[beta, theta], [0, 1]]) > 0)
    assert len(caught) == 1
    assert _quoted_distance(caught[0]) == pytest.approx(DELTA, rel=0.1)
