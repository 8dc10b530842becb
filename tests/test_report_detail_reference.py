"""What only the report shows, added to a point analysed without it, against the documented rule
and closed forms (derived here).

Documented rule: docs/optimizer.md, "`flexshaft run` computes everything its report shows
(Campbell diagram, thermal design sweeps, modes at rest, leave-one-out load shares, the classical
buckling comparison ...)", an assessment at a ``Resolution`` with ``report_detail=False`` leaves
that out; docs/architecture.md, "What only the report shows is computed once, at the governing
point (the point of the tightest check): `add_report_detail`". So a point of the tuned design
analysed without the detail and given it by ``add_report_detail`` carries the modes at rest, the
classical buckling comparison and the thermal sweeps; the same point without it carries none of
them; and a point analysed at a resolution asking for the detail (no ``detail`` argument) carries
the modes at rest, checked on the Jeffcott rotor of tests/rotors.py. Each is checked against
physics:

* **Modes at rest.** At Ω = 0 the gyroscopic and circulatory terms vanish; the lightly damped
  roots s of (M s² + C s + K + K_p) q = 0 (the tuned design's PD loops: their proportional
  stiffness K_p) have |s| = ω_n (1 + O(ζ²)), ω_n² the eigenvalues of the undamped pencil
  (K + K_p, M) on the free DOFs, solved here with scipy's dense ``eigh`` (not the product's modal
  solver). K_p is only the positive part of the loops' k_p − k_s, so K + K_p is the full static
  stiffness only for pure PD loops without magnet stiffness: the test asserts that premise.
  Second order in the damping: measured 1.28e-3 (4th mode, ζ = 0.012, about 9 ζ²: the damping
  C + K_d is not proportional, so the modes couple through it; the shaft's loss factor
  η ≈ 7e-4 adds (1 + η²)^{1/4} − 1 ≈ 1e-7); 5e-3 ≈ 4× that. The lowest lateral modes and the
  torsional mode at rest, 31.06, 37.96 and 49.98 rad/s, are 22 % and 32 % apart, so no mode can
  be taken for its neighbour within 5e-3. (Numbers with ``mesh.shaft_elements = 6``, used
  here; 1.23e-3 and 31.03 rad/s with 12.)
* **Modes at rest by the resolution (Jeffcott rotor).** A heavy midspan disk m on a pinned-pinned
  steel tube: the Euler-Bernoulli midspan stiffness k = 48 E I / L³, so the two whirls at rest
  have ω_n = √(48 E I / (L³ m)) (``rotors.WN``; undamped here, s = ±i ω_n). The Hermite cubics of
  the shaft elements hold the point-load deflection exactly; the tube's own mass, 3.5e-6 of the
  disk's, moves ω_n by Rayleigh's −(17/70)(3.5e-6) = −8.5e-7 (effective mass 17/35 of the tube's
  with the static deflection shape); measured −8.6e-7. 1e-5 holds that with ten times room and
  is far below any mode that is not the disk's (the next, axial, is 12.8 ω_n).
* **Classical buckling.** The classical (Kirchhoff-Love) shell is the shear-deformable one with
  the transverse shear strains held at zero: as continua, its critical torque is the minimum of
  the same Rayleigh quotient over a smaller set of shapes, so it is at least the shear theory's
  global torque, and it has no shear-crimping mode (a transverse-shear mode): its crimping torque
  is infinite. The two solvers are not nested Ritz spaces, though: the classical one takes one
  number of axial terms M from its helix wavenumber, the shear-deformable one takes M per
  circumferential wave number n and may use the infinite-tube value at an n, and the two define
  their global minimum differently. So the inequality of the discretised torques holds here
  because the factors, 2.3× and 2.7× (15117 against 6485 N m positive, 17939 against 6757 N m
  negative), dwarf any truncation error. The verdict's buckling factor does not change with the
  report's detail (``add_report_detail``: "the verdict's numbers do not change"); same
  computation, 1e-12.
* **Thermal sweeps.** docs/thermal.md: generated heat = convected + end flows, and "the
  convection sweep tends to the local balance θ = q/(hPℓ)": with convection carrying the heat,
  the peak rise falls as 1/h. The neglected conduction G(2θ_i − θ_{i−1} − θ_{i+1}), G = k A/ℓ_e,
  moves the peak from the local balance by at most b(h) = max 2 (G_l + G_r)/C_i of itself,
  C_i = h P ℓ_i (tests/test_thermal_studies.py, where that bound is the tolerance). The local
  balance's h·θ is the same for every h (the heat sources do not depend on h), so each h·θ_max
  lies within b(h) of one common value; b is computed here from the sweep's own stations and
  the shaft's conductivity: 0.90 % at h = 5, 0.23 % at 20, 0.03 % at the correlation's
  143.8 W/(m² K) with ``mesh.shaft_elements = 6`` used here (about 1.1 % for the worst pair;
  measured spread of h·θ_max 0.07 %; b grows with finer elements, G ∝ 1/ℓ_e and C_i ∝ ℓ_i:
  2.2 %, 0.54 %, 0.08 % with 12). The h of each profile is read from
  structured data, not from its label (whole W/(m² K)): the sweep's coefficients
  (``temperature_profiles``' default, 5, 20 and the correlation) and the correlation's value from
  the shaft result under the same options and loss model.
"""

from __future__ import annotations

import dataclasses
import inspect

import numpy as np
import pytest
import scipy.linalg
from conftest import SMALLEST
from rotors import WN, jeffcott_text

from flexshaft.design import loads_design, tuned_design, with_overrides
from flexshaft.thermal.study import temperature_profiles
from flexshaft.verdict.operating_point import add_report_detail, analyse_point

COARSE = {"mesh.shaft_elements": 6, "mesh.boom_elements": 4}


@pytest.fixture(scope="module")
def bare():
    return analyse_point(with_overrides(tuned_design(), COARSE), SMALLEST, detail=False)


@pytest.fixture(scope="module")
def shown(bare):
    return add_report_detail(bare)


def test_a_point_without_detail_has_none_of_the_reports_extras(bare):
    assert bare.modes_at_rest is None
    assert bare.buckling is not None and bare.buckling.classical is None
    assert bare.thermal is not None and bare.thermal.profiles is None


def test_the_report_detail_adds_the_modes_at_rest_of_the_undamped_pencil(shown):
    found = shown.modes_at_rest
    assert found is not None
    s = np.asarray(found.eigenvalues)
    zeta = -s.real / np.abs(s)
    assert np.all(zeta < 0.02)  # lightly damped: the second-order shift is small
    model = shown.model
    # K + K_p is the full static stiffness: pure PD loops, no magnet (negative) stiffness
    assert model.all_pd and all(a.negative_stiffness == 0 for a in model.actuators)
    free = model.dofs.free
    K = (model.K + model.Kp).toarray()[np.ix_(free, free)]
    M = model.M.toarray()[np.ix_(free, free)]
    omega = np.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True, subset_by_index=[0, s.size - 1]))
    assert np.abs(s) == pytest.approx(omega, rel=5e-3)


def test_the_report_detail_adds_the_classical_buckling_and_keeps_the_verdicts_factor(bare, shown):
    b = shown.buckling
    assert b is not None and b.classical is not None
    assert b.classical.theory == "classical" and b.result.theory != "classical"
    for sense in ("positive", "negative"):
        assert getattr(b.classical, f"crimping_torque_{sense}") == np.inf
        assert getattr(b.classical, f"global_torque_{sense}") >= getattr(b.result, f"global_torque_{sense}")
    assert b.safety_factor == pytest.approx(bare.buckling.safety_factor, rel=1e-12)


def test_the_report_detail_adds_the_convection_sweep_falling_as_one_over_h(shown):
    thermal = shown.thermal
    assert thermal is not None and thermal.profiles is not None
    correlation = thermal.shaft[thermal.loss_model]
    swept = inspect.signature(temperature_profiles).parameters["coefficients"].default
    h = np.array([correlation.temperature.heat_transfer_coefficient if c is None else c for c in swept])
    by_h = thermal.profiles.by_h
    assert list(by_h) == [f"h = {v:.0f} W/m²K" + (" (correlation)" if c is None else "") for v, c in zip(h, swept)]
    peaks = np.array([rise.max() for rise in by_h.values()])
    # the conduction bound b(h) of each h (tests/test_thermal_studies.py)
    x = thermal.profiles.x
    ell_e = np.diff(x)
    ell = np.zeros(x.size)
    ell[:-1] += ell_e / 2
    ell[1:] += ell_e / 2
    Do, Di = shown.model.shaft.outer_diameter, shown.model.shaft.inner_diameter
    G = correlation.conductivity * np.pi * (Do**2 - Di**2) / 4 / ell_e
    b = np.array([np.max(2 * (G[:-1] + G[1:]) / (v * np.pi * Do * ell[1:-1])) for v in h])
    assert h[-1] > 100.0 and b.max() < 0.05  # the local balance applies (b: 0.90 %, 0.23 %, 0.03 %)
    assert np.all(np.diff(peaks) < 0)
    q = h * peaks  # each within b of the local balance's common h θ: the intervals overlap
    assert np.max(q / (1 + b)) <= np.min(q / (1 - b))


def test_a_resolution_asking_for_the_detail_gives_it_without_the_argument():
    p = analyse_point(loads_design(jeffcott_text(0.0, 0.0)), dataclasses.replace(SMALLEST, report_detail=True))
    found = p.modes_at_rest
    assert found is not None
    s = np.asarray(found.eigenvalues)[np.asarray(found.kind) == "lateral"][:2]
    assert s.size == 2
    assert np.abs(s) == pytest.approx(np.full(2, WN), rel=1e-5)
