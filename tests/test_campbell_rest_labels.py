"""Whirl labels of the Campbell diagram at rest: a degenerate pair takes its continuation's
label, a mode alone at its frequency keeps its own (planar).

Reference (derived here) on the overhung disk of tests/test_overhung_disk_whirl.py: a massless
cantilever with a rigid disk (m, I_d, I_p) at its tip, tip stiffness EI/L³ [[12, −6L], [−6L, 4L²]]
on (deflection, slope) in each plane. At rest there is no gyroscopic moment, the only coupling
of the two bending planes, so each plane vibrates alone at the roots ω of

    (k11 + k_s − m ω²)(k22 − I_d ω²) − k12² = 0,

k_s the plane's extra tip spring. Anisotropic rotor: a tip spring k_s = 0.3 k11 in v only. The
v plane's roots then differ from the w plane's (k_s = 0) by several per cent: every lateral mode
at rest is alone at its frequency and lies in one plane (V ≡ 0 or W ≡ 0), so its whirl ratio
−2 Σ Im(V̄W)/Σ(|V|²+|W|²) is exactly 0: planar, as ``modes(speed=0)`` labels it. Axisymmetric
rotor (no spring): each root is a double one (the two planes alike) that may whirl either way;
spinning, the gyroscopic moment splits it into the forward root of (k11 − mω²)(k22 − I_dω² +
I_pΩω) − k12² = 0 and the backward one of the same with −I_pΩω (test_overhung_disk_whirl.py):
the mode at rest is labelled by the curve it continues into.

A critical speed between rest and the first spinning sample is at a spin: it takes the whirl
of the spinning mode (the modal analysis at the critical speed itself is the reference), not
the planar label at rest.

Tolerances: the tube's mass is 1e-6 of the disk's (the frequencies agree with the massless
closed form to a few 1e-6, 5e-5 asserted as in test_overhung_disk_whirl.py); a rest ratio is 0
up to round-off, far below the planar threshold 0.1 asserted. Four shaft elements (the closed
form holds at any mesh: the shaft's elements are exact for a massless beam), four modes.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_overhung_disk_whirl import EI, I_D, MASS, L, closed_form, design_text

import flexshaft as fs
from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.classify import WHIRL_THRESHOLD
from flexshaft.design import loads_design

K11, K12, K22 = 12 * EI / L**3, -6 * EI / L**2, 4 * EI / L
K_SPRING = 0.3 * K11
SPEEDS = [0.0, 500.0, 1000.0]


def planar_roots(k_s: float) -> np.ndarray:
    """Positive roots ω of (k11 + k_s − m ω²)(k22 − I_d ω²) − k12² = 0 (one plane at rest)."""
    a = np.polynomial.Polynomial([K11 + k_s, 0.0, -MASS])
    b = np.polynomial.Polynomial([K22, 0.0, -I_D])
    roots = (a * b - K12**2).roots()
    roots = roots[np.abs(roots.imag) < 1e-9 * np.abs(roots)].real
    return np.sort(roots[roots > 0])


def _model(k_s: float):
    text = design_text(0.0)
    if k_s:
        text += f'\n[[bearings]]\nname = "tip spring"\nkind = "contact"\nx = {L}\nstiffness = {{v = {k_s}}}\n'
    return fs.build_model(loads_design(text))


def test_anisotropic_rotor_is_planar_at_rest_and_whirls_when_spinning():
    model = _model(K_SPRING)
    diagram = campbell(model, SPEEDS, n_modes=4)
    lateral = diagram.kind[0] == "lateral"
    # the modes at rest are the two planes' own roots: the lowest of each plane and the w plane's second
    expected = np.sort(np.concatenate([planar_roots(0.0), planar_roots(K_SPRING)[:1]]))
    assert np.sort(diagram.eigenvalues[0, lateral].imag) == pytest.approx(expected, rel=5e-5)
    assert np.all(np.abs(diagram.whirl_ratios[0, lateral]) < WHIRL_THRESHOLD)
    assert np.all(diagram.whirl[0, lateral] == "planar")
    at_rest = fs.modes(model, speed=0.0, n_modes=4)
    assert list(diagram.whirl[0]) == list(at_rest.whirl)
    for k, speed in enumerate(SPEEDS[1:], start=1):  # spinning: the labels of the modes at that speed
        spinning = fs.modes(model, speed=speed, n_modes=8)
        for m in range(diagram.eigenvalues.shape[1]):  # the same root in both analyses, the same label
            same = np.argmin(np.abs(spinning.eigenvalues - diagram.eigenvalues[k, m]))
            assert spinning.eigenvalues[same] == pytest.approx(diagram.eigenvalues[k, m], rel=1e-6)
            assert diagram.whirl[k, m] == spinning.whirl[same]
        assert set(diagram.whirl[k, lateral]) == {"forward", "backward"}


@pytest.mark.parametrize("n_modes", [4, 3])
def test_axisymmetric_rotor_is_labelled_by_its_continuation_at_rest(n_modes):
    """Four modes: the disk's first pair, the torsion and the second pair's lower member, whose
    partner is cut (then degenerate with an untracked root); three: the first pair, the torsion."""
    diagram = campbell(_model(0.0), SPEEDS, n_modes=n_modes)
    lateral = diagram.kind[0] == "lateral"
    assert np.sort(diagram.eigenvalues[0, lateral].imag) == pytest.approx(
        np.repeat(closed_form(0.0, +1), 2)[: lateral.sum()], rel=5e-5
    )
    fwd, bwd = closed_form(SPEEDS[1], +1), closed_form(SPEEDS[1], -1)
    for m in np.flatnonzero(lateral):
        w1 = diagram.eigenvalues[1, m].imag
        sense = "forward" if np.min(np.abs(fwd - w1)) < np.min(np.abs(bwd - w1)) else "backward"
        assert min(np.min(np.abs(fwd - w1) / w1), np.min(np.abs(bwd - w1) / w1)) < 5e-5
        assert diagram.whirl[0, m] == sense  # the curve's label at rest is its continuation's
        assert diagram.whirl_ratios[0, m] == diagram.whirl_ratios[1, m]
    assert sorted(diagram.whirl[0, lateral][:2]) == ["backward", "forward"]


def test_critical_speed_above_rest_takes_the_whirl_of_the_spinning_mode():
    """The anisotropic rotor's lowest curve falls from 196 rad/s at rest below the 1× line
    before 500 rad/s: its critical speed lies between rest and the first spinning sample. There
    the rotor spins and the mode whirls (the gyroscopic moment couples the planes): its label is
    that of the same root in ``modes`` at the critical speed itself, not the planar one at rest."""
    model = _model(K_SPRING)
    diagram = campbell(model, SPEEDS, n_modes=4)
    (crossing,) = [c for c in diagram.critical_speeds if c.mode == 0]
    assert 0.0 < crossing.speed < SPEEDS[1]
    there = fs.modes(model, speed=crossing.speed, n_modes=4)
    root = np.argmin(np.abs(there.eigenvalues.imag - crossing.speed))  # the mode on the 1× line
    assert crossing.whirl == there.whirl[root] != "planar"
