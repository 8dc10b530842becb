"""Hysteretic roots: an eigenvector's phase is arbitrary, and the fixed-frame loss's roots below the spin (hunt h39a).

References.

1. Phase. An eigenvector is defined up to a complex factor: ``line_root`` (the on-line eigenvalue
   of a mode whose two branch roots straddle the synchronous line the wrong way) must give the
   same root whatever phase the dense solve handed the upper branch's vector. The case is the
   circular whirl in a gap of tests/test_hysteretic_gap_pairing_reference.py (a Jeffcott rotor,
   steel tube, η = 0.05, disk of polar inertia 0.2 kg m² off-centre), whose on-line root is
   computed there independently: QZ on the blended pencil (1 − μ) T₋ + μ T₊ tracked in μ, with
   brentq on Im s(μ) = Ω. The vector of the upper root is given aligned with the lower's and
   turned by e^{iφ}, φ = 0, π/2, π; each must land on that root within the tolerance derived
   there (1e-7 |s| + 40 · 1e-9 Ω), Im s = Ω to the band 1e-9.

2. The fixed-frame (thesis) loss at speed: one branch, weights (i, i, 0) on (F, K_lat, K_lat S)
   at every frequency (flexshaft.analyses.loss). Its roots below the spin are what the passive
   every-root check judges and estimates the error of, so ``consistent_values_below`` must give
   their unit modal coordinates: each a null vector of T(s) = s² I + s (ΩG + C) + Λ + i (F + K_lat),
   assembled here from the reduced model's matrices, ‖T(s) y‖ <= 1e-12 ‖T(s)‖₂ (the dense solve's
   backward error, 2e-17 measured), and the roots those of QZ on another linearisation
   (tests/test_stability.py :func:`pencil_roots`), to 1e-8 relative (1e-10 measured).
   The rotor: the same Jeffcott rotor, thesis loss, disk at midspan, at Ω = 1000 rad/s, above its
   first pair (284 rad/s), below the next (3256 rad/s).
CPU: a few dozen 16 x 16 QZ solves and two 8-mode reductions, about 0.15 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text
from scipy.optimize import brentq
from test_hysteretic_gap_pairing_reference import _reduced
from test_stability import ABOVE, BELOW, pencil_roots

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import branch_roots, branches, consistent_values_below, line_root
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


@pytest.fixture(scope="module")
def gap():
    red = _reduced()
    speed = 2479.0
    above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
    p = above[np.argmin(np.abs(above - 1j * speed))]
    q = below[np.argmin(np.abs(below - p))]
    for _ in range(6):  # the speed between the two branch frequencies (the gap test's fixed point)
        speed = 0.5 * (p.imag + q.imag)
        above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
        p, q = above[np.argmin(np.abs(above - p))], below[np.argmin(np.abs(below - q))]
    assert p.imag < speed < q.imag

    def blended(mu):
        roots = pencil_roots(red, speed, tuple((1 - mu) * b + mu * a for a, b in zip(ABOVE, BELOW)))
        return roots[np.argmin(np.abs(roots - (q + mu * (p - q))))]

    mu = brentq(lambda m: blended(m).imag - speed, 0.0, 1.0, xtol=1e-15, rtol=1e-15)
    return red, speed, p, q, blended(mu)


@pytest.mark.parametrize("phi", [0.0, np.pi / 2, np.pi])
def test_the_on_line_root_does_not_depend_on_the_vectors_phase(gap, phi):
    red, speed, p, q, reference = gap
    lower, upper = branches(red, speed)
    s_lo, Y_lo = branch_roots(red, speed, lower.weights)
    s_hi, Y_hi = branch_roots(red, speed, upper.weights)
    i, j = np.argmin(np.abs(s_lo - q)), np.argmin(np.abs(s_hi - p))
    y_lo, y_hi = Y_lo[:, i], Y_hi[:, j]
    overlap = np.vdot(y_lo, y_hi)
    assert abs(overlap) ** 2 > 0.9  # the same mode on both branches
    y_hi = y_hi * np.conj(overlap) / abs(overlap) * np.exp(1j * phi)
    found = line_root(red, speed, lower.weights, upper.weights, (s_lo[i], y_lo), (s_hi[j], y_hi))
    assert found is not None
    assert found[0].imag == pytest.approx(speed, rel=1e-9)
    assert abs(found[0] - reference) <= 1e-7 * abs(reference) + 40 * 1e-9 * speed


def test_the_on_line_root_from_a_vector_a_quarter_turn_out_at_the_midpoint(gap):
    """The worst start: the upper root's vector is the lower's own turned by a quarter turn
    (y₊ = i y₋, the same mode, phase π/2) and the two roots straddle the line by exactly
    ±1 rad/s, so regula falsi's first trial is μ = ½ exactly (1 / (1 − (−1)); speed ± 1 and
    back are exact in binary: 1 is a multiple of the speed's ulp). Aligned to the lower's
    phase, y₊ is y₋ and the blended start (1 − μ) y₋ + μ y₊ is y₋; turned the other way it
    would be ½ y₋ − ½ y₋ = 0 exactly, from which no Newton solve starts. The root must be the
    QZ on-line root of :func:`gap`, to the same tolerance as above."""
    red, speed, p, q, reference = gap
    lower, upper = branches(red, speed)
    s_lo, Y_lo = branch_roots(red, speed, lower.weights)
    s_hi, _ = branch_roots(red, speed, upper.weights)
    i, j = np.argmin(np.abs(s_lo - q)), np.argmin(np.abs(s_hi - p))
    y_lo = Y_lo[:, i]
    low = (complex(s_lo[i].real, speed + 1.0), y_lo)
    high = (complex(s_hi[j].real, speed - 1.0), 1j * y_lo)
    assert (low[0].imag - speed) / ((low[0].imag - speed) - (high[0].imag - speed)) == 0.5
    found = line_root(red, speed, lower.weights, upper.weights, low, high)
    assert found is not None
    assert found[0].imag == pytest.approx(speed, rel=1e-9)
    assert abs(found[0] - reference) <= 1e-7 * abs(reference) + 40 * 1e-9 * speed


def test_the_thesis_losss_roots_below_the_spin_have_their_null_vectors():
    text = jeffcott_text(0.05, 50.0, "thesis", elements=6).replace("density = 0.1", "density = 7800.0")
    red = reduce(build_model(loads_design(text)), 8)
    speed = 1000.0
    s, Y = consistent_values_below(red, speed)
    reference = pencil_roots(red, speed, ABOVE)
    assert s.size == reference.size
    for root in s:
        assert np.min(np.abs(reference - root)) <= 1e-8 * abs(root)
    K = np.diag(red.w2) + 1j * red.F + 1j * red.L
    D = speed * red.G + red.C
    below = np.flatnonzero(s.imag < speed)
    assert below.size == 2  # the first forward and backward whirl
    for k in below:
        T = s[k] ** 2 * np.eye(red.size) + s[k] * D + K
        assert np.linalg.norm(Y[:, k]) == pytest.approx(1.0, abs=1e-12)
        assert np.linalg.norm(T @ Y[:, k]) <= 1e-12 * np.linalg.norm(T, 2)
