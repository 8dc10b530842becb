"""The logarithmic decrement in every code path against its definition and its closed form.

Reference problem: the Jeffcott-like rotor of tests/rotors.py with an external dashpot c_e at
the disk and no material loss. Its disk obeys m r̈ + c_e ṙ + k r = 0 (k = 48 E I / L³), so each
lateral mode has ζ = c_e / (2√(k m)) and, by definition of the logarithmic decrement
(ratio of successive peaks of a free decay),

    δ = ln(x_i / x_{i+1}) = ζ ω_n T_d = 2πζ / √(1 − ζ²).

The free decay is integrated here with scipy's DOP853 (independent of the package), and the
peak ratio is compared with the closed form; then every path that reports a log decrement is
compared with the closed form: :func:`flexshaft.modes` (``Modes.log_decrements``), the Campbell
diagram and the whirl stability (``EigenvalueCurves.log_decrements``, both methods), and
:func:`flexshaft.design.requirements.log_decrement_from_damping_ratio` (a damping-ratio
requirement). ζ = 0.3 makes the √(1 − ζ²) factor a 4.8 % effect and the ζ of a mutated
definition (−Re s/Im s, say) differ by 5 %, far above the tolerance.

Tolerance: the tube's mass (7e-6 of the disk's; rotors.py) shifts ω_n and ζ by a few 1e-6
relative; 1e-4 is asserted. The speed does not change the answer: the disk has no polar
inertia and the tube's is 1e-6 of the disk's diametral scale, and with no material loss there
is no circulatory term.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott
from scipy.integrate import solve_ivp

import flexshaft as fs
from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.stability import stability
from flexshaft.design.requirements import Requirements, log_decrement_from_damping_ratio

ZETA = 0.3
C_E = 2 * ZETA * math.sqrt(K_SHAFT * M_DISK)  # N s/m
DELTA = 2 * math.pi * ZETA / math.sqrt(1 - ZETA**2)
REL = 1e-4
SPEEDS = [0.0, 0.3 * WN, 0.8 * WN]


@pytest.fixture(scope="module")
def model():
    return jeffcott(0.0, C_E)


def free_decay_log_decrement(zeta: float, omega_n: float = WN, n_peaks: int = 4) -> np.ndarray:
    """ln of the ratio of successive peaks of x'' + 2ζω_n x' + ω_n² x = 0, x(0) = 1, x'(0) = 0,
    integrated with DOP853 at rtol 1e-12; peaks located where x' changes sign from + to −, by
    the dense output and a bracketing root solve."""
    from scipy.optimize import brentq

    def f(_t, y):
        return [y[1], -2 * zeta * omega_n * y[1] - omega_n**2 * y[0]]

    period = 2 * math.pi / (omega_n * math.sqrt(1 - zeta**2))
    sol = solve_ivp(
        f, (0.0, (n_peaks + 1.5) * period), [1.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-30, dense_output=True
    )
    t = np.linspace(0.0, sol.t[-1], 20001)
    v = sol.sol(t)[1]
    peaks = []
    for k in np.flatnonzero((v[:-1] > 0) & (v[1:] <= 0)):
        tp = brentq(lambda s: sol.sol(s)[1], t[k], t[k + 1], xtol=1e-15)
        peaks.append(sol.sol(tp)[0])
    peaks = np.array(peaks)
    assert peaks.size >= n_peaks, peaks
    return np.log(peaks[:-1] / peaks[1:])


def test_free_decay_integration_gives_the_closed_form_log_decrement():
    # The peak ratio of an independent time integration is the definition of δ; the closed
    # form 2πζ/√(1 − ζ²) must reproduce it (integration at rtol 1e-12: 1e-8 asserted).
    for zeta in (0.02, ZETA, 0.6):
        measured = free_decay_log_decrement(zeta)
        assert measured == pytest.approx(2 * math.pi * zeta / math.sqrt(1 - zeta**2), rel=1e-8)
    assert free_decay_log_decrement(ZETA) == pytest.approx(DELTA, rel=1e-8)


def test_damping_ratio_requirement_converts_to_the_free_decay_log_decrement():
    # min_damping_ratio is checked as a log decrement: the conversion must be the free decay's.
    for zeta in (0.0, 0.05, ZETA, 0.6):
        expected = free_decay_log_decrement(zeta)[0] if zeta else 0.0
        assert log_decrement_from_damping_ratio(zeta) == pytest.approx(expected, rel=1e-8, abs=1e-15)
    assert Requirements(min_damping_ratio=ZETA).required_log_decrement == pytest.approx(DELTA, rel=1e-12)


def test_modes_report_the_dashpot_log_decrement(model):
    m = fs.modes(model, n_modes=2)
    assert set(m.kind) == {"lateral"}
    assert m.damping_ratios == pytest.approx([ZETA, ZETA], rel=REL)
    assert m.log_decrements == pytest.approx([DELTA, DELTA], rel=REL)
    # the damped frequency is ω_n √(1 − ζ²): the eigenvalue, not only its ratio, is right
    assert np.abs(m.eigenvalues.imag) == pytest.approx([WN * math.sqrt(1 - ZETA**2)] * 2, rel=REL)


def test_campbell_reports_the_dashpot_log_decrement_at_every_speed(model):
    c = campbell(model, SPEEDS, n_modes=2)
    assert c.damping_ratios == pytest.approx(np.full((3, 2), ZETA), rel=REL)
    assert c.log_decrements == pytest.approx(np.full((3, 2), DELTA), rel=REL)


@pytest.mark.parametrize("method", ["hysteretic", "viscous"])
def test_stability_reports_the_dashpot_log_decrement_at_every_speed(model, method):
    s = stability(model, SPEEDS, n_modes=2, damping_model=method)
    assert s.log_decrements == pytest.approx(np.full((3, 2), DELTA), rel=REL)
    assert s.onset_speed is None
    # the stability margin is the smallest damping ratio over the modes at each speed
    assert s.stability_margin == pytest.approx(np.full(3, ZETA), rel=REL)


def test_log_decrement_grows_without_bound_as_the_damping_ratio_nears_one(model):
    # δ = 2πζ/√(1 − ζ²): at ζ = 0.99 the free decay loses a factor e^44 per period, and the
    # path through the modes must agree with the definition there too (the √ term is 7x).
    zeta = 0.99
    m = fs.modes(jeffcott(0.0, 2 * zeta * math.sqrt(K_SHAFT * M_DISK)), n_modes=2)
    expected = 2 * math.pi * zeta / math.sqrt(1 - zeta**2)
    # ζ near 1 amplifies the relative error of ζ by 1/(1 − ζ²) ≈ 50: 50 × 1e-4 asserted
    assert m.log_decrements == pytest.approx([expected, expected], rel=5e-3)


def test_the_stability_margin_is_the_least_damped_mode():
    # A dashpot of different strength in the two planes: the v- and w-plane disk modes have
    # ζ_v = 0.3 and ζ_w = 0.1 (each plane is its own single-DOF oscillator); the margin at every
    # speed is the smaller one, and each mode's log decrement is its own plane's.
    from rotors import jeffcott_text

    from flexshaft.assembly import build_model
    from flexshaft.design import loads_design

    c_w = 2 * 0.1 * math.sqrt(K_SHAFT * M_DISK)
    text = jeffcott_text(0.0, C_E).replace(f"w = {C_E}", f"w = {c_w}")
    assert f"w = {c_w}" in text
    s = stability(build_model(loads_design(text)), SPEEDS, n_modes=2)
    assert s.stability_margin == pytest.approx(np.full(3, 0.1), rel=REL)
    expected = sorted(2 * math.pi * z / math.sqrt(1 - z**2) for z in (0.1, ZETA))
    assert np.sort(s.log_decrements, axis=1) == pytest.approx(np.tile(expected, (3, 1)), rel=REL)
