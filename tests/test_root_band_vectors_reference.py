"""The every-root check of a passive driveline with a root just above the spin (root_stability).

The check judges the roots below the spin and those in a 1 % band above it (a root the basis
error could move across the spin) and estimates their error against the full model from their
vectors (flexshaft.analyses.eigen_error). Was: the roots of the band lie on the upper branch's
own side, and ``consistent_values_below`` gave them zero columns (it solved vectors below the
spin only); their estimate came out NaN, counted as an infinite error, so the check doubled its
basis up to the largest: the whole model where it is small enough (the coarse driveline below:
145 vectors instead of 50, 0.28 s instead of 0.013 s), else the largest basis with an estimate
of ``inf`` reported ("within inf"; the current driveline's own mesh: 221 vectors, 0.4 s) for
roots that were right to 1e-14.

Reference: the full (unreduced) model, every mode in the basis, solved densely with every
vector (``consistent_roots``): its roots and vectors are those of the discretised problem, with
no basis error. The case: the current aluminium driveline on a coarse mesh (16 shaft and 6 boom
elements, 170 free DOFs; a coarse mesh changes the frequencies, not what is checked), spun at
ω₁/1.003 and ω₁/1.008, ω₁ its first natural frequency (31.0 rad/s, 6 rad/s from the next one),
so that the first mode's root lies in the band Ω < Im s < 1.01 Ω, and at ω₁/1.05, where it lies
above the band: the band must cost the check no larger basis. Tolerances: the estimate must
be finite and within the check's 1e-6 (EIGENVALUE_TOLERANCE); the band's roots within 1e-6 of
the full model's (what that accuracy promises; measured 3e-14); each band root's vector a unit
vector of MAC at least 1 − 1e-6 with the full model's (an isolated root: its vector is
determined to about the root's error over its 6 rad/s gap, far below that).
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.eigen_error import EIGENVALUE_TOLERANCE
from flexshaft.analyses.hysteretic_roots import consistent_roots, consistent_values_below
from flexshaft.analyses.modal import modes
from flexshaft.analyses.root_stability import root_stability
from flexshaft.assembly import build_model
from flexshaft.design import embedded_design, with_overrides

BAND = 1.01


@pytest.fixture(scope="module")
def driveline():
    design = with_overrides(
        embedded_design("current"), {"mesh.shaft_elements": 16, "mesh.boom_elements": 6, "envelope": None}
    )
    model = build_model(design)
    first = 2 * np.pi * float(modes(model, 0.0, 2).frequencies[0])
    return model, first, reduce(model, int(model.dofs.free.size))


@pytest.mark.parametrize("factor", [1.003, 1.008])
def test_a_root_just_above_the_spin_is_judged_with_its_vector(driveline, factor):
    model, first, whole = driveline
    speed = first / factor
    s_full, Y_full = consistent_roots(whole, speed)
    band = np.flatnonzero((s_full.imag >= speed) & (s_full.imag < BAND * speed))
    assert band.size >= 1  # the case: the first mode's root in the band above the spin

    result = root_stability(model, [speed])
    assert result.method == "passive"
    assert result.basis_size == root_stability(model, [first / 1.05]).basis_size < model.dofs.free.size
    assert result.error_estimate is not None and np.isfinite(result.error_estimate)
    assert result.error_estimate <= EIGENVALUE_TOLERANCE
    roots = np.asarray(result.roots[0])
    for k in band:
        assert np.min(np.abs(roots - s_full[k])) <= EIGENVALUE_TOLERANCE * abs(s_full[k])

    # the vectors the check's estimate reads, on a reduced basis of its kind (the whole model's
    # first 50 modes): every root below 1.01 Ω has a unit vector, the band's the full model's
    red = reduce(model, 50)
    s, Y = consistent_values_below(red, speed, BAND)
    judged = np.flatnonzero(s.imag < BAND * speed)
    assert judged.size >= band.size
    assert np.allclose(np.linalg.norm(Y[:, judged], axis=0), 1.0, rtol=1e-12)
    for k in band:
        i = int(np.argmin(np.abs(s - s_full[k])))
        assert s[i].imag >= speed  # the band root, not a neighbour
        x = red.shapes(Y[:, [i]])[:, 0]
        x_full = whole.shapes(Y_full[:, [k]])[:, 0]
        mac = abs(np.vdot(x_full, x)) ** 2 / (np.vdot(x, x).real * np.vdot(x_full, x_full).real)
        assert mac >= 1 - 1e-6
