"""The projected sweep solves in full a nearly undamped resonance beside the response's peak.

:mod:`flexshaft.analyses.sweep_projection` (docstring): a speed where the reduced model's
``κ_ω = ω ‖Zr⁻¹ (∂Zr/∂ω) y‖/‖y‖`` exceeds a tenth of 1/RESONANCE_TOLERANCE (1e4) is solved in
full; κ_ω "is evaluated at the local maxima of ‖y‖ and their neighbours". κ_ω measures the
nearest resonance's sharpness whatever the amplitude, so a weakly excited, nearly undamped mode
can set it one sample beside a stronger, better damped peak that holds the maximum of ‖y‖.

Rotor (closed form): the Jeffcott rotor of tests/rotors.py, its disk m = 20 kg on k = 48 E I/L³
with a support adding Δk = k (1.01² − 1) in w only, so the planes are two decoupled
single-degree-of-freedom systems, ω_v = ω_n and ω_w = 1.01 ω_n, with dashpots giving
ζ_v = 1e-3 and ζ_w = 1e-5. The forces U Ω² in v and 0.006 U Ω² in w give, in each plane,
x_p = F_p Ω²/(k_p − mΩ² + i c_p Ω) and ``Z⁻¹ ∂Z/∂ω x_p = x_p (−2mΩ + i c_p)/(k_p − mΩ² + i c_pΩ)``,
so κ_ω = Ω √Σ|x_p a_p|² / √Σ|x_p|² with a_p that ratio. Speeds (0.55 + 0.01 j) ω_n, j = 0..100:
at j = 45 (Ω = ω_v) |v| = U/(2ζ_v m) = 500 U/m dominates, κ_ω ≈ 2mΩ/c_v = 1/ζ_v = 1000; at
j = 46 (Ω = ω_w) |v| ≈ 50 U/m but |w| = 0.006 U/(2ζ_w m) = 300 U/m: ‖y‖ is smaller than at
j = 45 (no local maximum) but κ_ω ≈ 9.86e4 > 1e4 (both computed below from these formulas).
So j = 46 must be solved in full. The tube's density is cut to 1e-6 kg/m³ (its mass 7e-11 of
the disk's): the response then lies in the two planes' static shapes at every speed, the scan's
two ends span it to round-off and the scan is accepted without a greedy round (which would
otherwise pick j = 46 for its residual), so only the resonance check can send j = 46 to a full
solve. There |w| is checked against 0.006 U/(2ζ_w m) with rtol 1e-8: the tube's mass moves it
by about its share (measured 7e-11), the full solve's round-off κ_ω ε by about 1e-11. The
closed-form κ is a guide for the setup, checked against its threshold by a factor 4. CPU: about 50 ms.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, M_DISK, WN, disk_dofs, jeffcott_text

from flexshaft.analyses.banded import RESONANCE_TOLERANCE
from flexshaft.analyses.sweep_projection import imbalance_sweep
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

U, SHARE = 1e-4, 6e-3
DK = K_SHAFT * (1.01**2 - 1)
CV = 2 * 1e-3 * np.sqrt(K_SHAFT * M_DISK)
CW = 2 * 1e-5 * np.sqrt((K_SHAFT + DK) * M_DISK)


def _kappa(speed: float) -> float:
    x, a = [], []
    for force, k, c in ((U, K_SHAFT, CV), (SHARE * U, K_SHAFT + DK, CW)):
        d = k - M_DISK * speed**2 + 1j * c * speed
        x.append(force * speed**2 / d)
        a.append((-2 * M_DISK * speed + 1j * c) / d)
    x, a = np.array(x), np.array(a)
    return float(speed * np.linalg.norm(x * a) / np.linalg.norm(x))


def test_a_sharp_resonance_beside_the_peak_is_solved_in_full():
    speeds = WN * (0.55 + 0.01 * np.arange(101))
    threshold = 0.1 / RESONANCE_TOLERANCE
    assert _kappa(speeds[46]) > 4 * threshold and _kappa(speeds[45]) < threshold / 4
    text = jeffcott_text(0.0, 0.0).replace("density = 0.1", "density = 1e-6")
    text = text.replace("stiffness = {}", f"stiffness = {{ w = {DK} }}")
    text = text.replace("damping = { v = 0.0, w = 0.0 }", f"damping = {{ v = {CV}, w = {CW} }}")
    model = build_model(loads_design(text))
    v, w = disk_dofs(model)
    loads = np.zeros((model.dofs.size, 1))
    loads[v, 0], loads[w, 0] = U, SHARE * U
    sweep = imbalance_sweep(model, speeds, loads)
    q = np.abs(np.asarray(sweep.response)[[v, w], 0])
    assert q[0, 45] > np.hypot(*q[:, 46]) > 4 * q[0, 46]  # the peak of ‖y‖ at 45; w dominates at 46
    assert sweep.rounds == 0 and sweep.basis_size > 0 and sweep.full[46]
    np.testing.assert_allclose(q[1, 46], SHARE * U / (2 * 1e-5 * M_DISK), rtol=1e-8)  # resonant |w|
