"""A run-up settles on the steady gyroscopic imbalance response of its final speed, through its
drift term (mutation hunt h33c).

The run-up's integrator (:mod:`flexshaft.analyses.envelope`) keeps one eigenbasis of the system
at a reference speed Ω_ref and carries the change of the gyroscopic (and rotating-loss) terms
since Ω_ref, ``(Ω − Ω_ref) G``, as an explicit drift; the basis is refreshed only when Ω has moved
by more than 2 % of the top speed. A ramp from Ω_a = 0.985 Ω_b to Ω_b followed by a long dwell at
Ω_b never refreshes it (asserted: one basis), so the state it settles on at Ω_b is reached only
through the drift, with Ω − Ω_ref = 0.015 Ω_b.

Reference, derived here (tests/test_overhung_disk_whirl.py's overhung rotor): a rigid disk
(m, I_d, I_p) at the tip of a massless cantilever of tip stiffness EI/L³ [[12, −6L], [−6L, 4L²]]
on (deflection, slope), a dashpot c at the disk, a forward imbalance U at the disk. In complex
coordinates r = v + i w, ψ the matching slope, the steady synchronous response at Ω (the
gyroscopic moment of a forward whirl at ω = Ω is the tilt stiffness +I_p Ω²) solves

    [k11 − mΩ² + icΩ,  k12               ] [r]   [U Ω²]
    [k12,              k22 − I_d Ω² + I_p Ω²] [ψ] = [0   ],

and the run's complex envelopes are (v, w) = (r, −i r). Ω_b = 0.95 × the forward synchronous
critical (≈ 238 rad/s, the peak of |r(Ω)|, found here on a grid). Had the drift the wrong sign,
the run would settle on the gyroscopic term at 2Ω_ref − Ω_b = 0.97 Ω_b: |r| 4 % off (the same
formula). Tolerance 1e-4 relative: the tube's mass (1e-6 of the disk's: frequencies to a few
1e-6, tests/test_overhung_disk_whirl.py), the free motion's decay over the 1 s dwell
(e^{−(c/2m) t} = e^{−25}), the 6-mode basis with its static correction and the integrator's
rtol 1e-8 (measured 2.3e-6 in all). About 0.2 s.
"""

from __future__ import annotations

import numpy as np
from test_overhung_disk_whirl import EI, I_D, I_P, MASS, L, design_text

from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

C = 1000.0  # N s/m, the dashpot at the disk
U = 1e-4  # kg m
K11, K12, K22 = 12 * EI / L**3, -6 * EI / L**2, 4 * EI / L


def steady_r(speed: float, gyroscopic_speed: float) -> complex:
    """r of the 2×2 system above; the gyroscopic tilt stiffness at ``gyroscopic_speed``."""
    A = np.array(
        [[K11 - MASS * speed**2 + 1j * C * speed, K12], [K12, K22 - I_D * speed**2 + I_P * gyroscopic_speed * speed]]
    )
    return complex(np.linalg.solve(A, [U * speed**2, 0.0])[0])


def test_the_run_settles_on_the_steady_gyroscopic_response_through_the_drift():
    grid = np.linspace(50.0, 1500.0, 2901)
    critical = grid[int(np.argmax([abs(steady_r(w, w)) for w in grid]))]
    top = 0.95 * critical
    start = 0.985 * top
    exact = steady_r(top, top)
    wrong = steady_r(top, 2 * start - top)
    assert abs(wrong - exact) > 0.02 * abs(exact)  # the premise: a wrong-signed drift is seen

    damper = (
        f'[[bearings]]\nname = "damper"\nkind = "contact"\nx = {L}\n'
        f"stiffness = {{}}\ndamping = {{ v = {C}, w = {C} }}\n"
    )
    text = design_text(top * 60 / (2 * np.pi)).replace("[[disks]]", damper + "[[disks]]")
    model = build_model(loads_design(text))
    dm = model.dofs
    tip = dm.node_at("shaft", L)
    q1 = np.zeros(dm.size, complex)
    q1[dm.shaft(tip, "v")], q1[dm.shaft(tip, "w")] = U, -1j * U
    run = transient_response(
        model,
        SpeedProfile.constant_acceleration(start, top, (top - start) / 0.05, dwell=1.0),
        loads_per_speed_squared=q1,
        basis_size=6,
        rtol=1e-8,
    )
    assert run.refreshes == 1  # one basis, at the start speed: the end is reached by the drift
    v, w = run.shaft_envelope[:, tip, -1]
    assert abs(v - exact) <= 1e-4 * abs(exact)
    assert abs(w + 1j * exact) <= 1e-4 * abs(exact)
