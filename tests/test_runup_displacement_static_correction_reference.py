"""A run's physical displacement carries its static correction with a plus sign; its peak's
parabola (mutation hunt h33c).

``TransientResult.displacement(rows)`` is documented as ``Re((Φ_rows Y + r_rows f) e^{iφ})``: the
modal part plus the quasi-static response ``r f`` of the modes left out of the basis (r the
residual flexibility, f = Ω² − iΩ̇). At a constant speed Ω, started in the steady state, the
run's envelope is a fixed point of its equation (the exponential integrator propagates it
exactly, tests/test_runup_lagged_law_static_correction_reference.py), so the signal is the
steady imbalance response of the full model, ``Re(q e^{iΩt})`` with q from the banded
frequency-response solve (:func:`flexshaft.analyses.response.imbalance_response`, another code
path), up to the dynamic part of the modes left out. Those modes (ω ≥ ω₃, the third natural
frequency of the free DOFs, computed here by LAPACK on the dense (K, M)) answer Ω² Q as
r f (1 + O((Ω/ω₃)²)): the bar is 4 (Ω/ω₃)² of the correction's size plus 1e-9 of the signal
(round-off). A correction subtracted instead of added errs by twice its size, which is asserted
to be more than a tenth of the signal.

The rotor: the Jeffcott rotor's tube made heavy (steel density), six elements, the imbalance at
x = 0.25 m off the disk, a two-mode basis; Ω = 40 rad/s, far below its first critical
(≈ 290 rad/s).

:meth:`TransientResult.peak` refines the largest sample by the parabola through it and its two
neighbours: for samples of v(t) = c − a (t − t₀)², a parabola, the refinement is exact, and its
vertex is (c, t₀) (closed form); the speed there is the run's constant Ω.
CPU: one 2-mode run of five output samples, about 0.05 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import jeffcott_text

from flexshaft.analyses.response import imbalance_response
from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

U = 1e-4  # kg m
SPEED = 40.0  # rad/s
X_IMBALANCE = 0.25  # m


def _run():
    text = jeffcott_text(0.0, 0.0, elements=6).replace("density = 0.1", "density = 7800.0")
    model = build_model(loads_design(text))
    dm = model.dofs
    q1 = np.zeros(dm.size, complex)
    node = dm.node_at("shaft", X_IMBALANCE)
    q1[dm.shaft(node, "v")], q1[dm.shaft(node, "w")] = U, -1j * U  # a forward rotating imbalance
    run = transient_response(
        model,
        SpeedProfile.table([0.0, 0.02], [SPEED, SPEED]),
        loads_per_speed_squared=q1,
        basis_size=2,
        rtol=1e-7,
        output_step=0.005,
    )
    return model, q1, node, run


def test_displacement_adds_the_static_correction_of_the_modes_left_out():
    model, q1, node, run = _run()
    dm = model.dofs
    pos = np.full(dm.size, -1)
    pos[dm.free] = np.arange(dm.free.size)
    dofs = np.array([dm.shaft(node, "v"), dm.shaft(node, "w")])
    v, w = run.displacement(pos[dofs])

    q = np.asarray(imbalance_response(model, [SPEED], q1))[dofs, 0]  # (v, w) amplitudes
    reference = np.real(q[:, None] * np.exp(1j * SPEED * run.time)[None, :])
    free = dm.free
    K = (model.K + model.Kp)[free][:, free].toarray()
    M = model.M[free][:, free].toarray()
    w3 = float(np.sqrt(la.eigh(K, M, eigvals_only=True, subset_by_index=(2, 2))[0]))
    assert run.residual is not None
    correction = float(np.abs(run.residual[pos[dofs]]).max()) * SPEED**2
    size = float(np.abs(reference).max())
    assert 2 * correction > 0.1 * size  # the correction matters: a sign slip is far above the bar
    tol = 4 * (SPEED / w3) ** 2 * correction + 1e-9 * size
    assert np.abs(v - reference[0]).max() <= tol
    assert np.abs(w - reference[1]).max() <= tol


def test_peak_is_the_vertex_of_the_parabola_through_the_largest_sample():
    *_, run = _run()
    t = run.time
    assert t.size >= 4
    t0 = t[1] + 0.3 * (t[2] - t[1])  # between the samples, nearer the second
    c, a = 2.5e-3, 7.0
    value, at, speed = run.peak(c - a * (t - t0) ** 2)
    assert value == pytest.approx(c, rel=1e-12)
    assert at == pytest.approx(t0, rel=1e-10)
    assert speed == pytest.approx(SPEED, rel=1e-14)
