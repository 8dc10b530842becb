"""A sharp resonance between the scan's samples is found, whatever the scan's spacing.

Reference (closed form): the Jeffcott rotor of tests/rotors.py (a 20 kg midspan disk on a
near-massless pinned-pinned tube of stiffness k = 48 E I / L³) with a bearing at the disk that
adds stiffness k_v = (1.01² − 1) k in v only (the v resonance 1 % above the w one), a light
dashpot in v (ζ_v = 1e-4) and a heavier one in w (ζ_w = 0.002). The disk has no tilt at
midspan, so v and w decouple into two single-degree-of-freedom systems; under the imbalance
force m e Ω² (cos Ωt, sin Ωt) their complex amplitudes are

    a = m e Ω² / (k + k_v − m Ω² + i c_v Ω),    b = −i m e Ω² / (k − m Ω² + i c_w Ω),

and the orbit's major semi-axis is √((|a|² + |b|² + |a² + b²|)/2) (the largest of
|Re(a e^{iθ})|² + |Re(b e^{iθ})|² over θ). The v resonance is 2e-4 ω_n wide: every scan spacing
used here (9e-3 to 7e-2 ω_n) steps over it, and the w resonance's bump, 1 % below, hides it; the
w peak's own refinement (± its 4e-3 ω_n bandwidth) does not reach it. Before the synchronous
roots seeded the refinement (:mod:`flexshaft.analyses.synchronous_roots`), the scans of 31, 61
and 101 speeds reported the w peak alone. The reference peak is the maximum of that closed
form, found by a bounded scalar search on the formula itself (no flexshaft code).
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.optimize
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.banded import solver_for
from flexshaft.analyses.criticals import lateral_critical_speeds, scan_critical_speeds
from flexshaft.analyses.spinup_response import spinup_response
from flexshaft.analyses.synchronous_roots import synchronous_roots
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm

ECCENTRICITY = 1e-5
K_V = (1.01**2 - 1) * K_SHAFT
ZETA_V, ZETA_W = 1e-4, 0.002
C_V = 2 * ZETA_V * np.sqrt((K_SHAFT + K_V) * M_DISK)
C_W = 2 * ZETA_W * np.sqrt(K_SHAFT * M_DISK)


def _rotor():
    text = jeffcott_text(0.0, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * WN)}")
    text = text.replace("stiffness = {}", f"stiffness = {{ v = {K_V} }}")
    text = text.replace("damping = { v = 0.0, w = 0.0 }", f"damping = {{ v = {C_V}, w = {C_W} }}")
    return build_model(loads_design(text + f"\n[loads]\neccentricity = {ECCENTRICITY}\n"))


def _orbit(speed):
    """The closed-form orbit (module docstring) [m]."""
    force = M_DISK * ECCENTRICITY * speed**2
    a = force / (K_SHAFT + K_V - M_DISK * speed**2 + 1j * C_V * speed)
    b = -1j * force / (K_SHAFT - M_DISK * speed**2 + 1j * C_W * speed)
    return np.sqrt((abs(a) ** 2 + abs(b) ** 2 + abs(a * a + b * b)) / 2)


def _sharp_peak():
    """The closed form's largest orbit and its speed, near the v resonance."""
    wv = np.sqrt((K_SHAFT + K_V) / M_DISK)
    found = scipy.optimize.minimize_scalar(
        lambda s: -_orbit(s),
        bounds=(wv * (1 - 5 * ZETA_V), wv * (1 + 5 * ZETA_V)),
        method="bounded",
        options={"xatol": 1e-9 * wv},
    )
    return float(found.x), float(_orbit(found.x))


@pytest.fixture(scope="module")
def rotor():
    return _rotor()


def test_the_rotors_eccentricity_is_the_disks():
    """The closed form's imbalance m e Ω² is the model's: the orbit far below both resonances
    (Ω = 0.3 ω_n, where it is quasi-static) agrees with it to the tube's mass share (7e-6) and
    the damping's O(ζ²) effect."""
    # guards the reference below: a model whose imbalance differed would fail here, not there
    from flexshaft.analyses.criticals import _shaft_orbits
    from flexshaft.analyses.response import imbalance_response
    from flexshaft.assembly.loads import imbalance_loads

    model = _rotor()
    speed = 0.3 * WN
    node = model.dofs.node_at("shaft", 0.5)
    orbit = _shaft_orbits(model, imbalance_response(model, [speed], imbalance_loads(model)))[node].max()
    assert orbit == pytest.approx(_orbit(speed), rel=1e-4)


@pytest.mark.parametrize("n_points", [21, 31, 41, 61, 101, 161])
def test_the_sharp_peak_is_found_whatever_the_scan(rotor, n_points):
    """At every scan size the critical speeds hold the sharp v resonance with the closed form's
    peak orbit (to 1e-4: the refinement's vertex parabola through 1/A² at a 20th of the
    bandwidth, exact for one mode, the broad w resonance's share varying across the band by
    less than that) at its speed (to a 20th of its 2e-4 ω_n bandwidth), and the broad w one."""
    speed, peak = _sharp_peak()
    criticals = lateral_critical_speeds(rotor, top=1.3, n_points=n_points)
    sharp = min(criticals, key=lambda c: abs(c.speed - speed))
    assert abs(sharp.speed - speed) <= 2 * ZETA_V * speed / 20
    assert sharp.location["peak_orbit"] == pytest.approx(peak, rel=1e-4)
    assert any(abs(c.speed - WN) <= 0.01 * WN for c in criticals)  # the broad w resonance


def test_synchronous_roots_of_the_full_model_are_the_closed_forms(rotor):
    """On the whole free space (V = I) the roots with real part near ω_n are the two
    single-degree-of-freedom roots Ω = (i c ± √(4 m k' − c²))/(2m) of k' − mΩ² + i c Ω = 0
    (k' = k + k_v for v, k for w), to the tube's mass share (7e-6 of the disk's: its modal mass
    shifts the frequency by less than 1e-5 relative)."""
    solver = solver_for(rotor)
    V = np.eye(solver.n, dtype=complex)
    roots = synchronous_roots(solver, solver.project(V[None])[0], 0.9 * WN, 1.1 * WN)
    expected = [
        (1j * c + np.sqrt(4 * M_DISK * k - c * c)) / (2 * M_DISK) for k, c in ((K_SHAFT, C_W), (K_SHAFT + K_V, C_V))
    ]
    assert roots.size == 2
    for root, want in zip(roots, expected):
        assert root.real == pytest.approx(want.real, rel=1e-5)
        assert root.imag == pytest.approx(want.imag, rel=1e-3)


@pytest.mark.parametrize("n_points", [101, 161])
def test_an_assessments_scan_finds_it_from_its_reduced_basis(rotor, n_points):
    """As an assessment runs it: the spin-up scan from its greedy reduced basis, the critical
    speeds seeded from that basis's synchronous roots; the same closed-form peak and speed as
    above (same tolerances)."""
    speed, peak = _sharp_peak()
    scan = spinup_response(rotor, np.linspace(0.1, 1.3, n_points) * rotor.speed)
    assert scan.basis is not None  # the projected path, not the all-full fallback
    found = scan_critical_speeds(rotor, scan.speeds, scan.orbits, 1.3, responses=scan.response, basis=scan.basis)
    sharp = min(found.criticals, key=lambda c: abs(c.speed - speed))
    assert abs(sharp.speed - speed) <= 2 * ZETA_V * speed / 20
    assert sharp.location["peak_orbit"] == pytest.approx(peak, rel=1e-4)


def test_all_full_refinement_finds_it_too(rotor):
    """``projected=False`` (full solves at every refinement speed, the tests' reference path):
    the same peak, seeded from the scan's responses."""
    speed, peak = _sharp_peak()
    criticals = lateral_critical_speeds(rotor, top=1.3, n_points=61, projected=False)
    sharp = min(criticals, key=lambda c: abs(c.speed - speed))
    assert abs(sharp.speed - speed) <= 2 * ZETA_V * speed / 20
    assert sharp.location["peak_orbit"] == pytest.approx(peak, rel=1e-4)


class _RationalWeights:
    """A stand-in solver of one degree of freedom: Z(Ω) = k − m Ω² + C(iΩ), the law
    C(s) = kd s/(1 + s/ω_f) a filtered derivative (rational: the windows must be halved)."""

    k, m, kd, wf = 4.0e4, 1.0, 2.0, 300.0

    def term_weights(self, omegas, speeds):
        s = 1j * np.asarray(omegas, dtype=float)
        return np.column_stack([np.ones_like(s), s * s, self.kd * s / (1 + s / self.wf)])


def test_roots_of_a_rational_law_are_the_polynomials():
    """k − mΩ² + kd iΩ/(1 + iΩ/ω_f) = 0 times (1 + iΩ/ω_f) is the cubic
    (k − mΩ²)(1 + iΩ/ω_f) + i kd Ω = 0 (its roots by numpy.roots, a companion matrix of its
    coefficients): the roots in range agree to 1e-7 relative (the windows' fit holds the
    weights to 1e-8 of their size; the root moves by about that over the weights' cancellation
    at resonance, k/(mΩ²) = 1)."""
    z = _RationalWeights()
    cubic = np.polymul([-z.m, 0.0, z.k], [1j / z.wf, 1.0]) + np.array([0.0, 0.0, 1j * z.kd, 0.0])
    expected = [r for r in np.roots(cubic) if 100.0 <= r.real <= 400.0]
    terms = np.array([z.k, z.m, 1.0], dtype=complex).reshape(3, 1, 1)  # k·1 + m·s² + 1·C(s)
    roots = synchronous_roots(z, terms, 100.0, 400.0)
    assert len(expected) == 1 and roots.size == 1
    assert abs(roots[0] - expected[0]) <= 1e-7 * abs(expected[0])


def test_a_peak_whose_refinement_stalls_is_replaced_by_the_seeded_one():
    """One resonance, isotropic damping ζ = 1e-5 (the tests/rotors.py rotor with a dashpot
    c = 2ζ√(km) at the disk), 21 scan speeds (spacing 360 bandwidths): the scan's own bump is
    refined from a bandwidth estimate far too small, each window inside the peak's flank, and
    stops unresolved with a lower-bound AF (1.2e5 at 302.139 rad/s, orbit 0.27 m, before the
    seeds). The seeded refinement replaces it with the closed form's peak: for m r̈ + c ṙ + k r =
    m e Ω² e^{iΩt} the orbit e Ω²/√((ω² − Ω²)² + (2ζωΩ)²) peaks at e/(2ζ√(1 − ζ²)) (to 1e-4 as
    above), with AF = 1/(2ζ) to the 2e-3 of the half-power interpolation
    (tests/test_separation.py), and one critical speed is reported."""
    zeta = 1e-5
    c = 2 * zeta * np.sqrt(K_SHAFT * M_DISK)
    text = jeffcott_text(0.0, c).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * WN)}")
    model = build_model(loads_design(text + f"\n[loads]\neccentricity = {ECCENTRICITY}\n"))
    (critical,) = lateral_critical_speeds(model, top=1.3, n_points=21)
    assert "detail" not in critical.location  # resolved
    assert critical.location["peak_orbit"] == pytest.approx(ECCENTRICITY / (2 * zeta * np.sqrt(1 - zeta**2)), rel=1e-4)
    assert critical.amplification_factor == pytest.approx(1 / (2 * zeta), rel=2e-3)
    assert critical.speed == pytest.approx(WN / np.sqrt(1 - 2 * zeta**2), abs=2 * zeta * WN / 20)


def test_the_actuator_is_judged_at_a_peak_between_the_samples():
    """The assessment's actuator excursion and force (its spin-up scan, 261 speeds, spacing
    1.8 rad/s) at a resonance 0.0065 rad/s wide between two samples. Closed form: a magnetic
    bearing at the disk with the law ki (kp + i kd Ω) − ks (tests/jeffcott_bearing.py's gains, kd
    for ζ = 1e-5) adds k_a = ki kp − ks and c_a = ki kd; the disk's orbit under its imbalance
    peaks at e/(2ζ√(1 − ζ²)) at Ω_p = ω_n/√(1 − 2ζ²) (ω_n² = (k + k_a)/m), the actuator's
    excursion is that orbit (it sits at the disk, no static load) and its force
    |ki (kp + i kd Ω_p) − ks| times it. Tolerance 1e-5: the tube's mass (7e-6 of the disk's) and
    its share of the imbalance. Before the critical speeds' peaks were added to the scan
    (flexshaft.analyses.spinup_response.with_speeds), the actuator was judged at the samples:
    the excursion read there was below 1 % of the peak."""
    from jeffcott_bearing import KI, KP, KS

    import flexshaft as fs

    zeta = 1e-5
    k = K_SHAFT + KI * KP - KS
    kd = 2 * zeta * np.sqrt(k * M_DISK) / KI
    wn = np.sqrt(k / M_DISK)
    head, tail = jeffcott_text(0.0, 0.0, elements=4).split("[[bearings]]")
    bearing = f'name = "amb"\nx = 0.5\nkind = "active"\nkp = {KP}\nkd = {kd}\nks = {KS}\nki = {KI}\ngap = 0.1\n'
    text = f"{head}[[bearings]]\n{bearing}force_capacity = 1e6\n{tail[tail.index('[[disks]]') :]}"
    text = text.replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * wn)}")
    verdict = fs.assess(loads_design(text + f"\n[loads]\neccentricity = {ECCENTRICITY}\n"), fs.SCREENING).verdict
    peak, speed = ECCENTRICITY / (2 * zeta * np.sqrt(1 - zeta**2)), wn / np.sqrt(1 - 2 * zeta**2)
    excursion, force = verdict.check("actuator_orbit"), verdict.check("actuator_force")
    assert excursion.value == pytest.approx(peak, rel=1e-5)
    assert force.value == pytest.approx(abs(KI * (KP + 1j * speed * kd) - KS) * peak, rel=1e-5)
    assert excursion.location["speed"] == pytest.approx(speed, rel=1e-5)


def _two_resonances(separation: float, zeta: float):
    """The rotor of this file with its v resonance ``separation`` above the w one and both
    dashpots at ``zeta``; and the closed form's local maxima of the orbit (a grid of 2e5 speeds
    over 0.9-1.1 ω_n: 3e-4 rad/s apart)."""
    kv = ((1 + separation) ** 2 - 1) * K_SHAFT
    cv, cw = 2 * zeta * np.sqrt((K_SHAFT + kv) * M_DISK), 2 * zeta * np.sqrt(K_SHAFT * M_DISK)
    text = jeffcott_text(0.0, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * WN)}")
    text = text.replace("stiffness = {}", f"stiffness = {{ v = {kv} }}")
    text = text.replace("damping = { v = 0.0, w = 0.0 }", f"damping = {{ v = {cv}, w = {cw} }}")
    model = build_model(loads_design(text + f"\n[loads]\neccentricity = {ECCENTRICITY}\n"))
    s = np.linspace(0.9 * WN, 1.1 * WN, 200001)
    force = M_DISK * ECCENTRICITY * s**2
    a = force / (K_SHAFT + kv - M_DISK * s**2 + 1j * cv * s)
    b = -1j * force / (K_SHAFT - M_DISK * s**2 + 1j * cw * s)
    orbit = np.sqrt((abs(a) ** 2 + abs(b) ** 2 + abs(a * a + b * b)) / 2)
    maxima = np.flatnonzero((orbit[1:-1] > orbit[:-2]) & (orbit[1:-1] >= orbit[2:])) + 1
    return model, s[maxima]


@pytest.mark.parametrize("n_points", [21, 31, 61])
def test_two_resonances_sampled_as_one_bump_are_both_found(n_points):
    """Two resonances 3 % apart, ζ = 0.005 each (bands of 3 rad/s, 9 rad/s apart), scanned at
    14-36 rad/s: the samples show one bump. Both local maxima of the closed-form orbit are
    critical speeds, at its speeds to a 20th of the bandwidth (the refinement's resolution);
    before the synchronous roots seeded the search, each of these scans found one of them."""
    zeta = 0.005
    model, expected = _two_resonances(0.03, zeta)
    assert expected.size == 2
    found = [
        c.speed for c in lateral_critical_speeds(model, top=1.3, n_points=n_points) if 0.9 * WN < c.speed < 1.1 * WN
    ]
    assert np.allclose(found, expected, rtol=0, atol=2 * zeta * WN / 20)
