"""The passive root check's bases and its reported error, against rules and the full model.

Rotor (tests/rotors.py, derived here): the Jeffcott-like rotor with a steel tube of real
density (ρ = 7800 kg/m³), 12 shaft elements, loss factor η = 0.02 and an external dashpot at
the disk: a passive driveline (no actuator), so :func:`root_stability` takes its passive route.
13 nodes × 6 DOFs less the 4 + 2 fixed ones leave 72 free DOFs.

* Basis schedule (the rule of ``_passive_bases``' docstring): the first basis has
  max(2n, 16) modes, the lowest max(n, 8) enriched with their static corrections (n: the
  modes below the top speed); then *both* doubled while the basis has fewer vectors than free
  DOFs and at most 4·max(4n, 60); then every mode (72, 0) when 72 <= 4·max(4n, 60). At a top
  speed of 0.5 ω_n (ω_n = √(k/m)) no mode lies below it: the fundamental is the disk's
  bending pair, which Dunkerley's lower bound puts at ≥ (1/ω_n² + 1/ω_t²)^(−1/2) = 0.94 ω_n
  (ω_t = (π/L)² √(EI/ρA), the tube's own first bending, 2.7 ω_n), and the torsion
  ((π/2L)√(G/ρ) = 17 ω_n, fixed-free) is higher still. So n = 0 and the schedule is
  (16, 8), (32, 16), (64, 32), (72, 0) (128 > 72 stops the doubling).
* Reported error (RootStability.error_estimate: the largest estimated relative error of the
  roots judged, *at every speed*): on a plain 10-mode first basis (monkeypatched; tolerance
  0.5 so it is kept) the roots below the spin at 1.5 ω_n (the disk's forward whirl) and at
  20 ω_n (with the higher bending modes and the torsion below the spin) are compared with the
  full model's loss-consistent roots (every mode, no reduction: ``consistent_values`` on the
  unreduced basis). The estimate is held within a factor 3 of the true error
  (flexshaft.analyses.eigen_error; tests/test_eigen_accuracy.py); measured here 2.1e-10 at
  1.5 ω_n and 6.7e-6 at 20 ω_n, so the estimate of the two speeds together is within 3× of the
  larger true error, not the smaller one (4 orders of magnitude apart: asserted > 100×).
"""

from __future__ import annotations

import numpy as np
from rotors import DI, DO, WN, E, G, L, jeffcott_text

from flexshaft.analyses import root_stability as rs
from flexshaft.analyses.hysteretic_roots import consistent_values
from flexshaft.analyses.modal import default_basis_size
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

RHO = 7800.0


def steel_rotor():
    text = jeffcott_text(0.02, 1.0, elements=12).replace("density = 0.1", f"density = {RHO}")
    return build_model(loads_design(text))


def test_the_passive_bases_double_both_modes_and_corrections():
    """The docstring schedule at top speed 0.5 ω_n (n = 0, module docstring)."""
    area, inertia = np.pi * (DO**2 - DI**2) / 4, np.pi * (DO**4 - DI**4) / 64
    tube = (np.pi / L) ** 2 * np.sqrt(E * inertia / (RHO * area))
    assert (1 / WN**2 + 1 / tube**2) ** -0.5 > 0.9 * WN
    assert np.pi / (2 * L) * np.sqrt(G / RHO) > 10 * WN
    model = steel_rotor()
    assert model.dofs.free.size == 72
    modes = rs.reduce(model, min(72, default_basis_size(10)))
    assert rs._passive_bases(model, modes, 0.5 * WN) == [(16, 8), (32, 16), (64, 32), (72, 0)]


def _true_error(result, k: int, speed: float, exact: np.ndarray) -> float:
    low = result.roots[k][result.roots[k].imag < speed]
    assert low.size
    return max(float(np.min(np.abs(exact - s)) / abs(s)) for s in low)


def test_the_reported_error_is_the_largest_over_the_speeds(monkeypatch):
    """A plain 10-mode basis: the estimate at 1.5 ω_n and 20 ω_n together is the 20 ω_n one."""
    monkeypatch.setattr(rs, "accurate_basis", lambda n: (10, 0))
    model = steel_rotor()
    full = rs.reduce(model, model.dofs.free.size)
    speeds = np.array([1.5, 20.0]) * WN
    result = rs.root_stability(model, speeds, tolerance=0.5)
    assert result.method == "passive" and result.basis_size < 12
    true = [_true_error(result, k, v, consistent_values(full, v)) for k, v in enumerate(speeds)]
    assert true[1] > 100 * true[0]
    assert true[1] / 3 <= result.error_estimate <= 3 * true[1]
