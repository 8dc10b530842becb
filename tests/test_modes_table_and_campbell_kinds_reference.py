"""The modes' table (damping, decrement, the shaft's energy share), a degenerate pair at rest,
and which Campbell curves give critical speeds (hunt h41a).

References, derived here:

* **Damping columns.** The Jeffcott rotor of tests/rotors.py with a dashpot c = 2ζ√(km) at the
  disk (ζ = 0.2; tests/jeffcott_bearing.py): s = −ζω_n ± iω_n√(1 − ζ²), so the table's damping
  ratio is ζ = 0.2 and its log decrement δ = 2πζ/√(1 − ζ²) = 1.2825 (the small-damping rule
  δ/2π ≈ ζ is 2 % off at ζ = 0.2); the tube's distributed mass moves ζ by ~1e-5: 1e-4 asserted.
* **The shaft's energy share.** A driveline without a tailboom has all its kinetic energy in the
  shaft's DOFs (a disk sits on a shaft node), whatever the mode's kind: the share is 1 for the
  axial mode of the tube on a soft axial spring (tests/test_axial_mode_normalisation_reference.py,
  ω² = k_u/m), as for a lateral one. 1e-12 (round-off of an energy ratio).
* **A degenerate pair at rest, most forward first.** The undamped isotropic Jeffcott rotor at
  rest has one double root ±iω_n; :func:`~flexshaft.analyses.classify.circular_pairs` resolves
  it into the two circular orbits, "most forward first". A forward orbit turns with the spin
  (about +x, from y to z): v = cos ωt, w = sin ωt, i.e. the phasors W = −iV; backward W = +iV.
  So mode 1's disk motion has W/V = −i and mode 2's +i (an exact double root: 1e-8).
* **Critical speeds are lateral crossings** (:mod:`flexshaft.analyses.campbell`'s docstring: a
  torsional or axial curve meeting ω = kΩ is no whirl resonance). The tube on the soft axial
  spring (k_u = 1e4 N/m) has its axial mode at ω_a = √(k_u/m) = 24.98 rad/s, m = 16.03 kg (the
  tube, 7800 · π(0.05² − 0.04²)/4 · 2 = 11.03 kg, and the 5 kg disk), for every speed (no
  gyroscopic coupling of u); scanned from 0 to 40 rad/s its curve crosses ω = Ω while the
  lateral modes (a pinned 2 m tube with a 5 kg disk) stay above twice the top speed, well
  clear of the line ω = Ω: no critical speed. An excitation order must be > 0 (ω = 0·Ω excites nothing): refused.

CPU: three modes solves of 2-3 modes and one undamped Campbell diagram of 5 speeds, ~0.3 s.
Written for h41a-modal-table-damping-from-decrement, h41a-modal-shaft-fraction-lateral-only,
h41a-modal-pair-planes-swapped, h41a-campbell-criticals-every-kind and
h41a-campbell-zero-harmonic-accepted of scripts/mutations.toml.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from jeffcott_bearing import model_with
from rotors import K_SHAFT, M_DISK, disk_dofs, jeffcott
from test_axial_mode_normalisation_reference import DISK, K_U, TUBE

from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ZETA = 0.2


def test_the_tables_damping_ratio_and_log_decrement_of_a_damped_jeffcott_rotor():
    c = ZETA * 2 * np.sqrt(K_SHAFT * M_DISK)
    model = model_with(f'kind = "contact"\nstiffness = {{}}\ndamping = {{ v = {c}, w = {c} }}')
    rows = modes(model, 0.0, n_modes=2).table()
    delta = 2 * math.pi * ZETA / math.sqrt(1 - ZETA**2)
    assert [r["damping_ratio"] for r in rows] == pytest.approx([ZETA] * 2, rel=1e-4)
    assert [r["log_decrement"] for r in rows] == pytest.approx([delta] * 2, rel=1e-4)
    assert [r["shaft_energy_fraction"] for r in rows] == pytest.approx([1.0] * 2, rel=1e-12)


def test_an_axial_mode_of_a_driveline_without_boom_is_all_shaft():
    m = modes(build_model(loads_design(TUBE)), 0.0, n_modes=3, damped=False)
    assert m.kind[0] == "axial"
    assert m.table()[0]["shaft_energy_fraction"] == pytest.approx(1.0, rel=1e-12)
    assert m.shaft_fractions == pytest.approx(np.ones(3), rel=1e-12)


def test_a_degenerate_pair_at_rest_is_resolved_forward_first():
    model = jeffcott(0.0, 0.0)
    m = modes(model, 0.0, n_modes=2, damped=False)
    v, w = disk_dofs(model)
    assert m.shapes[w, 0] / m.shapes[v, 0] == pytest.approx(-1j, abs=1e-8)
    assert m.shapes[w, 1] / m.shapes[v, 1] == pytest.approx(1j, abs=1e-8)
    assert list(m.whirl) == ["forward", "backward"]


def test_an_axial_curve_crossing_the_spin_line_is_no_critical_speed():
    model = build_model(loads_design(TUBE))
    omega_axial = math.sqrt(K_U / (7800 * math.pi * (0.05**2 - 0.04**2) / 4 * 2.0 + DISK))
    speeds = np.linspace(0.0, 40.0, 5)
    result = campbell(model, speeds, n_modes=3, damped=False)
    axial = [m for m in range(3) if result.kind[0, m] == "axial"]
    assert len(axial) == 1
    curve = result.eigenvalues[:, axial[0]].imag
    assert curve == pytest.approx(np.full(5, omega_axial), rel=1e-3)
    assert curve[0] > speeds[0] and curve[-1] < speeds[-1]  # it does cross ω = Ω
    # the lateral curves never meet ω = Ω in the scan: above the top speed, with a factor 2 of room
    assert result.eigenvalues[:, [m for m in range(3) if m != axial[0]]].imag.min() > 2.0 * speeds[-1]
    assert result.critical_speeds == ()


def test_an_excitation_order_of_zero_is_refused():
    with pytest.raises(ValueError, match="harmonics must be excitation orders > 0"):
        campbell(build_model(loads_design(TUBE)), [0.0, 10.0], n_modes=1, harmonics=(1.0, 0.0))
