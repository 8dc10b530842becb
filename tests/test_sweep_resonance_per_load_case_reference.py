"""The spin-up sweep's resonance check takes the worst load case: a critical excited by one
case only is still solved in full, against closed forms.

:func:`~flexshaft.analyses.sweep_projection.imbalance_sweep` solves in full every speed (among
the local maxima of the response and their neighbours) where its reduced model's
``κ_ω = ω ‖Z⁻¹ (∂Z/∂ω) q‖ / ‖q‖`` exceeds ``0.1 / RESONANCE_TOLERANCE`` (1e4), "largest over the
load cases" (its ``sensitivity`` docstring): a near-undamped resonance is then reported and
resolved by the full solver, whichever case excites it.

Reference (closed form, derived here). The Jeffcott rotor of tests/rotors.py with a spring k_s
in w only at the disk and a dashpot c in both planes decouples into two single-DOF planes (the
tube's mass is 3.5e-6 of the disk's and the disk has no inertia about its axes: no gyroscopic
coupling). Two load cases: a unit force per Ω² in v only (case 1) and in w only (case 2). Case j
moves only plane j, ``q_j = Ω²/(k_j − mΩ² + icΩ)`` with k_v = k, k_w = k + k_s, so each case's
own measure is that of one plane (tests/test_resonance_sensitivity_reference.py):

    κ_j(Ω) = Ω |−2mΩ + ic| / |k_j − mΩ² + icΩ|,   ≈ 1/ζ_j at Ω = ω_j = √(k_j/m).

At ω_v the v case gives κ = 1/ζ_v = 3.3e4 (above 1e4) and the w case only 4.5 (the w plane is
far from its critical there: 2k/k_s = 2/0.44 = 4.55); at ω_w the other way round (4.0e4
against 6.5 for the v case: 2(k + k_s)/k_s = 6.55). So each resonant speed must be solved in
full although one of the two cases hardly responds there; a measure taken from the quieter case
(or a mean) would leave ω_v to the reduced model. ω_v is not one of the 13 initial snapshots
(ω_w is; the snapshot rule of src/flexshaft/analyses/sweep_projection.py, step 1 of its module
docstring and the first full solve of ``_greedy``, near line 382: 13 speeds evenly spread over
the scan's indices, the ends included), and the scan is accepted without a greedy round (the
planes' shapes do not change with speed beyond the tube's 3.5e-6 mass ratio, tolerance 1e-6),
so only the κ_ω rule can put ω_v among the full solves. The closed-form κ values are a margin
of 3 above the threshold and three decades of the threshold below in the quiet case, so the
tube's 3.5e-6 cannot move either across it.

What is asserted of the κ_ω rule is the documented flag :attr:`SweepResult.full
<flexshaft.analyses.sweep_projection.SweepResult>` ("The speeds solved in full") at both
criticals, and only that: the snapshots span both plane shapes, so a sweep that leaves ω_v to
the reduced model gives the same values (measured: within 7e-10 of the dense solve either
way), and at ζ = 3e-5 neither sweep raises a ResonanceWarning.

The values are checked too, against a dense LAPACK solve of the full
``(K − Ω²M + iΩ(ΩG + C)) q = Ω² Q₁`` (at these resonances the tube's mass, amplified by 1/ζ, moves
the closed form itself by ~3e-2), within the requested tolerance 1e-6 of each case's peak (the
:func:`~flexshaft.analyses.sweep_projection.imbalance_sweep` docstring: "Largest estimated
error of the checked outputs, relative to each one's peak over the scan"; measured 3.5e-10 and
6.8e-10, the reduced model on a basis spanning both planes being exact up to round-off).
CPU: ~10 ms for the sweep, ~50 ms for the dense check.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as la
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott_text

from flexshaft.analyses.banded import RESONANCE_TOLERANCE
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import loads_design

ZETA_V = 3e-5  # damping ratio of the v plane; the w plane's is ζ_v √(k/(k + k_s))


def test_a_critical_excited_by_one_load_case_only_is_solved_in_full():
    c = 2 * ZETA_V * np.sqrt(K_SHAFT * M_DISK)
    k_s = 0.44 * K_SHAFT
    text = jeffcott_text(0.0, c).replace("stiffness = {}", f"stiffness = {{ w = {k_s} }}")
    model = build_model(loads_design(text))
    v, w = disk_dofs(model)
    Q = np.zeros((model.dofs.size, 2), complex)
    Q[v, 0], Q[w, 1] = 1.0, 1.0  # case 1 loads plane v only, case 2 plane w only
    stiffness = (K_SHAFT, K_SHAFT + k_s)
    criticals = [np.sqrt(k / M_DISK) for k in stiffness]
    speeds = np.sort(np.concatenate([np.linspace(0.6, 1.5, 120) * WN, criticals]))
    at = [int(np.argmin(np.abs(speeds - x))) for x in criticals]
    kappa = np.array(
        [
            speeds * np.abs(-2 * M_DISK * speeds + 1j * c) / np.abs(k - M_DISK * speeds**2 + 1j * c * speeds)
            for k in stiffness
        ]
    )  # (case, speed): each case's own closed-form measure
    threshold = 0.1 / RESONANCE_TOLERANCE
    # the premise: at each critical one case is resonant, the other far below the threshold
    assert kappa[0, at[0]] > 3 * threshold and kappa[1, at[0]] < 1e-3 * threshold
    assert kappa[1, at[1]] > 3 * threshold and kappa[0, at[1]] < 1e-3 * threshold

    sweep = imbalance_sweep(model, speeds, Q, tolerance=1e-6)

    # the sweep's initial snapshots: src/flexshaft/analyses/sweep_projection.py, _greedy's first
    # solve_full (near line 382), _INITIAL_SNAPSHOTS = 13 indices evenly spread, ends included
    initial = np.unique(np.linspace(0, speeds.size - 1, 13).round().astype(int))
    assert at[0] not in initial  # only the κ_ω rule can solve ω_v in full
    assert sweep.rounds == 0 and sweep.basis_size > 0
    assert sweep.full[at].all()  # the catch of the κ_ω rule: the values agree either way

    free = model.dofs.free
    M, K, G, C = (restrict(A.tocsr(), free).toarray() for A in (model.M, model.K, model.G, model.C))
    q = np.asarray(sweep.response)[free]
    for case in range(2):
        direct = np.column_stack(
            [la.solve(K - s * s * M + 1j * s * (s * G + C), s * s * Q[free, case]) for s in speeds]
        )
        assert np.abs(q[:, case, :] - direct).max() <= 1e-6 * np.abs(direct).max()  # the tolerance asked for
