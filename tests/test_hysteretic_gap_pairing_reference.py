"""A circular whirl in a gap of the hysteretic problem: its one eigenvalue sits on the line.

Reference (the hysteretic problem's definition, :mod:`flexshaft.analyses.hysteretic_roots`, whose
branch weights tests/test_damping.py derives): above the spin the loss weights are W₊ = (i, i, 0),
below it W₋ = (i, 0, 1). A mode whose upper-branch root s₊ lies below the spin and whose
lower-branch root s₋ lies above it (ω₊ < Ω < ω₋, a *gap*) has neither as an eigenvalue; its one
eigenvalue lies on the line, Im s = Ω with the sign set-valued, a root of (1 − μ) T₋ + μ T₊.
s₊ and s₋ are computed here by QZ on another linearisation (tests/test_stability.py
:func:`pencil_roots`), the gap speed by the fixed point Ω = (ω₊ + ω₋)/2 of that test, and the
on-line root independently of the code's regula falsi and Newton polish: QZ of the blended pencil
(weights (1 − μ) W₋ + μ W₊) tracked in μ from s₋, with SciPy's brentq on μ ↦ Im s(μ) − Ω
(μ = 1.2e-4, s = 56.5489284 + 2478.8306233i rad/s here).

The rotor: an axisymmetric one (tests/rotors.py's Jeffcott rotor with a steel tube, η = 0.05,
a 20 kg disk of polar inertia 0.2 kg m² and its dashpot at x = 0.3 m): on isotropic supports
every whirl is circular, so a mode's unit modal vector y satisfies yᵀy ≈ 0 (the v and w parts
a quarter turn apart) while yᴴy = 1. The pairing of a mode's two branch roots must read the MAC
|y₋ᴴ y₊|² (1 here); without the conjugate it reads |y₋ᵀ y₊|² ≈ 0, pairs nothing, and the mode
loses its eigenvalue. The disk's gyroscopic moment splits the branch roots of the mode crossing
the spin near 2479 rad/s by 3.15e-7 Ω (ω₊ < ω₋: a gap), 300 times the synchronous band
(1e-9 Ω) within which an on-line root is accepted.

Asserted, for :func:`consistent_roots` and :func:`damped_modes` (whose Newton polish must not
carry the on-line root off the line onto s₋, the wrong side): exactly one eigenvalue of the mode
(within |s₊ − s₋| of their midpoint; the next eigenvalue is 371 rad/s away), with Im s = Ω to
the band (1e-9) and s equal to the QZ on-line root within 1e-7 |s| + 40 · 1e-9 Ω. The first term
is the QZ-against-QR tolerance of tests/test_hysteretic_gap_continuation_reference.py; the second
is the code's freedom to stop anywhere in the band |Im s − Ω| ≤ 1e-9 Ω: along the μ path the root
moves |dRe s/dIm s| = 34.8 in real part per unit of imaginary part at the root (the QZ root
differenced in μ), so a stop at the band's edge moves Re s by up to 35 · 1e-9 Ω; 40 covers it.
The code agrees to 4.7e-7 rad/s (tolerance 3.5e-4 rad/s), while an unpolished interpolation
between s₋ and s₊ (Re s ≈ 0, the midpoint, which also lies between Re s₊ and Re s₋) errs by
57 rad/s.
CPU: one 8-mode reduction and a few dozen 16 × 16 QZ solves, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import jeffcott_text
from scipy.optimize import brentq
from test_stability import ABOVE, BELOW, pencil_roots

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import consistent_roots, damped_modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, C_E, X_DISK, POLAR = 0.05, 50.0, 0.3, 0.2


def _reduced():
    text = jeffcott_text(ETA, C_E, elements=6).replace("density = 0.1", "density = 7800.0")
    disk = f"x = {X_DISK}\nmass = 20.0\npolar_inertia = {POLAR}\ndiametral_inertia = {POLAR / 2}"
    damper = f"x = {X_DISK}\nstiffness = {{}}"
    text = text.replace("x = 0.5\nmass = 20.0", disk).replace("x = 0.5\nstiffness = {}", damper)
    assert disk in text and damper in text
    return reduce(build_model(loads_design(text)), 8)


def gap(red) -> tuple[float, complex, complex]:
    """The speed between the branch roots p (of T₊, below the spin) and q (of T₋, above it) of
    the whirl near 2479 rad/s, and those roots, found by bisecting on their frequencies."""
    speed = 2479.0
    above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
    p = above[np.argmin(np.abs(above - 1j * speed))]
    q = below[np.argmin(np.abs(below - p))]
    for _ in range(6):  # the speed between the two branch frequencies, which move with it
        speed = 0.5 * (p.imag + q.imag)
        above, below = pencil_roots(red, speed, ABOVE), pencil_roots(red, speed, BELOW)
        p, q = above[np.argmin(np.abs(above - p))], below[np.argmin(np.abs(below - q))]
    assert p.imag < speed < q.imag and q.imag - p.imag > 1e-7 * speed  # a gap, far wider than the band
    return speed, p, q


def on_line_root(red, speed: float, p: complex, q: complex) -> complex:
    """The root on the spin line: that of (1 − μ) T₋ + μ T₊ whose Im s = Ω, followed from q
    (μ = 0) towards p (μ = 1), μ by brentq."""

    def blended(mu):
        roots = pencil_roots(red, speed, tuple((1 - mu) * b + mu * a for a, b in zip(ABOVE, BELOW)))
        return roots[np.argmin(np.abs(roots - (q + mu * (p - q))))]

    return blended(brentq(lambda m: blended(m).imag - speed, 0.0, 1.0, xtol=1e-15, rtol=1e-15))


def test_a_circular_whirl_in_a_gap_has_its_one_eigenvalue_on_the_line():
    red = _reduced()
    speed, p, q = gap(red)
    reference = on_line_root(red, speed, p, q)
    tol = 1e-7 * abs(reference) + 40 * 1e-9 * speed
    for name, s in (
        ("consistent_roots", consistent_roots(red, speed)[0]),
        ("damped_modes", damped_modes(red, speed, 6)[0]),
    ):
        mode = s[np.abs(s - 0.5 * (p + q)) <= abs(p - q)]  # a disc holding both branch roots, and no other
        assert mode.size == 1, (name, mode)
        assert mode[0].imag == pytest.approx(speed, rel=1e-9), name
        assert abs(mode[0] - reference) <= tol, (name, mode[0], reference)
