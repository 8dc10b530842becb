"""What the every-root check reports at a speed, and the order of R(Ω), against closed forms.

Reference (derived). The Jeffcott rotor of tests/rotors.py (20 kg midspan disk on a near-massless
pinned-pinned tube, k = 48EI/L³, loss factor η, external damper c_e at the disk). Each plane is
one mass: above the spin the rotating-frame loss is i η k, below it (forward whirl, ω < Ω) it
is −i η k, so the forward root solves

    m s² + c_e s + k (1 ± iη) = 0     (+ above the spin, − below it),

(tests/test_root_stability.py). With η = 0.3 and ζ_e = 0.005 the forward root at 1.6 ω_n lies
below the spin and is unstable, ζ = −Re s/|s| ≈ −0.14; read as −Re s/Im s it would be 1 % more
negative (1/√(1 − ζ²) − 1). At 0.6 ω_n every root is above the spin: the forward root is the
"+" one, stable, and the least damped roots are the tube's modes (exactly so the
antisymmetric ones, whose node at midspan the disk's damper cannot reach; the symmetric ones,
the disk nearly still, agree): the loss alone, s² = −ω²(1 + iη),
ζ = −Re s/|s| = sin(atan(η)/2) = 0.1452 (the backward root, above the spin at both speeds, is
the "+" one at both). :meth:`RootStability.roots_at` returns the roots of the speed analysed nearest
to the one asked.

The order of R(Ω) (:func:`~flexshaft.analyses.hysteretic_roots.consistent_roots`: sorted by
|s|). A bearing at the disk adds 3k and a heavy damper c_v (ζ_v = 0.9) in v, a light one in w:
at rest the v root of m s² + c_v s + k(1 + iη) + 3k = 0 has |s| ≈ 2.2 ω_n but Im s ≈ 0.89 ω_n,
the w root of m s² + c_w s + k(1 + iη) = 0 has |s| ≈ Im s ≈ ω_n: by |s| the w root comes first,
by frequency the v root would.

Tolerances: the tube's mass (3.5e-6 of the disk's) and the truncation leave ~1e-5 on the disk
roots (tests/test_root_stability.py asserts 1e-4): 1e-4 on roots, 5e-4 relative on ζ (the
root's error over |s|, times a few), ten times below the 1 % the wrong ratio would make.
Written for the h46b-root-* and h46b-hyst-* mutations of scripts/mutations.toml; about 0.2 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import K_SHAFT, M_DISK, WN, jeffcott, jeffcott_text

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import consistent_roots
from flexshaft.analyses.root_stability import root_stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, ZETA_E = 0.3, 0.005
C_E = 2 * ZETA_E * M_DISK * WN


def forward(sign: float) -> complex:
    """The forward root (Im s > 0) of m s² + c_e s + k(1 + sign iη) = 0."""
    roots = np.roots([M_DISK, C_E, K_SHAFT * (1 + sign * 1j * ETA)])
    return complex(roots[np.argmax(roots.imag)])


@pytest.fixture(scope="module")
def result():
    return root_stability(jeffcott(ETA, C_E), [0.6 * WN, 1.6 * WN])


def test_the_least_damped_root_and_its_damping_ratio_minus_re_s_over_modulus(result):
    below = forward(-1.0)
    assert below.real > 0 and below.imag < 1.6 * WN
    zeta = -below.real / abs(below)
    assert zeta == pytest.approx(-0.14, abs=0.01)
    assert abs(-below.real / below.imag - zeta) > 0.005 * abs(zeta)  # the two ratios told apart
    assert result.least_damped[1] == pytest.approx(below, rel=1e-4)
    assert result.least_damping_ratio[1] == pytest.approx(zeta, rel=5e-4)
    assert result.worst_at(1.6 * WN).damping_ratio == pytest.approx(zeta, rel=5e-4)
    # at 0.6 ω_n the least damped are the tube's antisymmetric modes (a node at the damper):
    # s = iω √(1 + iη), ζ = sin(atan(η)/2) (−Re s/Im s = tan(atan(η)/2), 1.1 % more)
    assert result.least_damping_ratio[0] == pytest.approx(np.sin(np.arctan(ETA) / 2), rel=5e-4)


def test_roots_at_reads_the_nearest_speed_analysed(result):
    below = forward(-1.0)  # the unstable forward root, there above the spin only
    for get in (result.roots_at, result.resolved_roots_at):
        assert np.min(np.abs(get(1.5 * WN) - below)) <= 1e-4 * abs(below)  # 1.6 ω_n's roots
        assert np.min(np.abs(get(0.7 * WN) - below)) > 1e-2 * abs(below)  # 0.6 ω_n's


def test_consistent_roots_are_sorted_by_modulus_not_frequency():
    c_v, c_w, k_v = 2 * 0.9 * np.sqrt(4 * K_SHAFT * M_DISK), 2 * 0.01 * M_DISK * WN, 3 * K_SHAFT
    text = jeffcott_text(ETA, 0.0, elements=4).replace("stiffness = {}", f"stiffness = {{ v = {k_v} }}")
    text = text.replace("damping = { v = 0.0, w = 0.0 }", f"damping = {{ v = {c_v}, w = {c_w} }}")
    assert f"v = {c_v}" in text
    red = reduce(build_model(loads_design(text)), 12)
    v = np.roots([M_DISK, c_v, K_SHAFT * (1 + 1j * ETA) + k_v])
    w = np.roots([M_DISK, c_w, K_SHAFT * (1 + 1j * ETA)])
    v, w = complex(v[np.argmax(v.imag)]), complex(w[np.argmax(w.imag)])
    assert abs(w) < abs(v) and v.imag < w.imag  # the two orders differ
    s, _ = consistent_roots(red, 0.0)
    assert s[:2] == pytest.approx([w, v], rel=1e-4)
    assert np.all(np.diff(np.abs(s)) >= 0)
