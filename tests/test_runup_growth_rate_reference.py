"""A stable run reports its slowest decay rate as its largest growth rate (mutation hunt h95c).

Reference, derived here (tests/test_overhung_disk_whirl.py's overhung rotor): a rigid disk
(m, I_d, I_p) at the tip of a massless cantilever of tip stiffness EI/L³ [[12, −6L], [−6L, 4L²]]
on (deflection, slope), a dashpot c at the disk in both lateral directions; the tip's axial and
torsional freedoms are held (`fixed_end = ["u", "theta"]`), so the four lowest modes are the
disk's lateral ones, damped by the dashpot. The tube's own modes (its mass 1e-6 of the disk's) lie
far above them and are nearly undamped (their decay rates -1e-5 1/s and less; with the default
basis the run's largest growth rate is their round-off, ~1e-9 1/s): `basis_size=4` keeps them out.
In the complex coordinates r = v ± i w (ψ the matching slope) the free motion e^{λt}
at speed Ω solves

    (m λ² + c λ + k11)(I_d λ² ∓ i I_p Ω λ + k22) − k12² = 0,

two quartics whose eight roots are the eigenvalues of the real four-DOF rotor; the run's complex
envelopes (the response times e^{−iΩt}) shift only their imaginary parts. A run held at
Ω = 100 rad/s never refreshes its eigenbasis, so its largest growth rate is the largest real
part of these roots (−3.096 1/s): negative, a stable run, not 0.

Tolerance 1e-4 relative: the tube's mass (1e-6 of the disk's, frequencies to a few 1e-6 in
tests/test_overhung_disk_whirl.py) and the four-mode basis (measured 2.7e-6). About 0.05 s.
"""

from __future__ import annotations

import numpy as np
from test_overhung_disk_whirl import EI, I_D, I_P, MASS, L, design_text

from flexshaft.analyses.transient import SpeedProfile, transient_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

C = 1000.0  # N s/m, the dashpot at the disk
K11, K12, K22 = 12 * EI / L**3, -6 * EI / L**2, 4 * EI / L


def slowest_decay(speed: float) -> float:
    """Largest real part of the roots of both quartics above [1/s]."""
    roots = []
    for sense in (+1, -1):
        a = np.polynomial.Polynomial([K11, C, MASS])
        b = np.polynomial.Polynomial([K22, -sense * 1j * I_P * speed, I_D])
        roots += list((a * b - K12**2).roots())
    return max(float(r.real) for r in roots)


def test_a_stable_run_reports_its_slowest_decay_rate():
    speed = 100.0
    expected = slowest_decay(speed)
    assert expected < -1.0  # the premise: every mode decays
    damper = (
        f'[[bearings]]\nname = "damper"\nkind = "contact"\nx = {L}\n'
        f"stiffness = {{}}\ndamping = {{ v = {C}, w = {C} }}\n"
    )
    text = design_text(speed * 60 / (2 * np.pi)).replace("[[disks]]", damper + "[[disks]]")
    text = text.replace("fixed_start = [", 'fixed_end = ["u", "theta"]\nfixed_start = [')
    model = build_model(loads_design(text))
    dm = model.dofs
    tip = dm.node_at("shaft", L)
    q1 = np.zeros(dm.size, complex)
    q1[dm.shaft(tip, "v")], q1[dm.shaft(tip, "w")] = 1e-4, -1e-4j
    run = transient_response(
        model, SpeedProfile.table([0.0, 0.2], [speed, speed]), loads_per_speed_squared=q1, basis_size=4
    )
    assert run.refreshes == 1
    assert abs(run.max_growth_rate - expected) <= 1e-4 * abs(expected)
