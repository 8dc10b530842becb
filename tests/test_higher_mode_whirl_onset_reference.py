r"""A higher mode that goes unstable first: the assessment's whirl stability tracks it.

A uniform pinned-pinned steel tube with rotating (hysteretic) internal loss η and one dashpot
c_e at midspan. In complex coordinates r = v + i w a mode of frequency ω_n and external damping
ratio ζ_e obeys, at a root s = iω of its modal equation m s² + c s + k + i η k sign(ω − Ω) = 0,
ω = ω_n and c ω_n = −η k sign(ω_n − Ω): a root crosses the axis only at Ω > ω_n, and only
when ζ_e = c/(2 m ω_n) ≤ η/2 (derived here; the hysteretic loss is bounded, not growing with
the spin).

* Mode 1 (sin πx/L, antinode at midspan) gets ζ_e = 5 η/2 from the dashpot: it is stable at
  every speed.
* Mode 2 (sin 2πx/L) has its node at midspan: the dashpot does not damp it (ζ_e = 0), and its
  forward whirl goes unstable as soon as the spin passes its forward whirl frequency, at the
  second forward critical speed.

For a Rayleigh beam (rotary inertia ρI, gyroscopic ρJ = 2ρI per length) in forward synchronous
whirl, r = R sin(kx) e^{iΩt} with k = 2π/L gives E I k⁴ − ρA Ω² − ρI k² Ω² + 2 ρI k² Ω² = 0, so

.. math:: Ω_c = ω_{EB} / \sqrt{1 - r_g^2 k^2},\qquad ω_{EB} = k^2\sqrt{EI/ρA},\quad
          r_g^2 = I/A = (D_o^2 + D_i^2)/16

(derived here: the gyroscopic couple of forward synchronous whirl outweighs the rotary inertia,
and the critical rises). The operating speed is set at Ω_c/1.3, so the screening's whirl
speeds (rest to 1.5 Ω_op) reach 1.15 Ω_c. Tracking only the first whirl pair would find no onset
at all there.
"""

from __future__ import annotations

import numpy as np

import flexshaft as fs

E, G, RHO, ETA = 210e9, 80e9, 7850.0, 0.02
L, DO, WALL = 2.0, 0.05, 0.005
DI = DO - 2 * WALL
I_AREA = np.pi * (DO**4 - DI**4) / 64
AREA = np.pi * (DO**2 - DI**2) / 4
K2 = 2 * np.pi / L
OMEGA_EB = K2**2 * np.sqrt(E * I_AREA / (RHO * AREA))
OMEGA_C = OMEGA_EB / np.sqrt(1 - (DO**2 + DI**2) / 16 * K2**2)
#: Mode 1's modal mass ρ A L / 2 and frequency (k = π/L): its ζ_e = 5 η / 2 from the dashpot
#: (unit mode shape at midspan).
OMEGA_1 = (np.pi / L) ** 2 * np.sqrt(E * I_AREA / (RHO * AREA))
C_E = 2 * (RHO * AREA * L / 2) * OMEGA_1 * 2.5 * ETA


def _design(N: int = 8) -> fs.Design:
    return fs.loads_design(
        f"""
name = "tube with a dashpot on its second mode's node"
[materials.steel]
kind = "isotropic"
E = {E}
G = {G}
density = {RHO}
loss_factor = {ETA}
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {DO}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "v", "w", "theta"]
fixed_end = ["v", "w"]
[[bearings]]
name = "damper"
kind = "contact"
x = {L / 2}
stiffness = {{}}
damping = {{ v = {C_E}, w = {C_E} }}
[operating]
speed_rpm = {OMEGA_C / 1.3 * 30 / np.pi}
power = 0.0
[analysis]
internal_damping = "rotating"
[mesh]
shaft_elements = {N}
"""
    )


def test_second_mode_onset_is_its_forward_critical_speed():
    """The onset is mode 2's forward critical Ω_c (module docstring) and its root's frequency is
    Ω_c too. Tolerance 2e-3: the cubic elements' frequency error falls as h⁴ (measured: the
    onset 4.0e-3 above Ω_c with 4 elements, 3.1e-4 with these 8, 6.6e-5 with 16), and the onset
    is refined between the 21 screening speeds; an onset of mode 1 (none below 1.15 Ω_c) or a
    missed mode 2 is off by more than 15 %."""
    a = fs.assess(_design(), fs.SCREENING)
    st = a.stability
    assert st.onset_speed is not None, "mode 2's forward whirl must go unstable below 1.15 Ω_c"
    assert st.onset_kind == "oscillatory"
    assert abs(st.onset_speed / OMEGA_C - 1) < 2e-3
    k = min(st.at_speed(st.onset_speed), st.speeds.size - 1)
    assert abs(abs(st.eigenvalues[k, st.unstable_mode].imag) / OMEGA_C - 1) < 2e-3
    assert st.whirl[k, st.unstable_mode] == "forward"
