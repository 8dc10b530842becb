"""Two resonances closer than one half-power band of each are both critical speeds, at any scan.

Rule (docs/requirements.md, "How flexshaft computes AF", step 2): "Each local maximum of the
orbit envelope (largest over shaft stations and imbalance cases) is a lateral critical speed";
the module docstring of :mod:`flexshaft.analyses.criticals` adds that the critical speeds do not
depend on where the scan's samples fall.

Reference (closed form, derived here as in tests/test_hidden_resonances.py): the Jeffcott rotor
of tests/rotors.py (a disk of mass m = 20 kg at midspan of a near-massless pinned-pinned tube of
stiffness k = 48 E I / L³, ω_n = √(k/m)) with a bearing at the disk adding k_v = ((1 + s)² − 1) k
in v only, so that the v resonance √((k + k_v)/m) = (1 + s) ω_n lies a fraction s above the w one,
and dashpots c_v = 2 ζ_v √((k + k_v) m), c_w = 2 ζ_w √(k m). The disk does not tilt at midspan,
so v and w are two single-degree-of-freedom systems; under the imbalance force
m e Ω² (cos Ωt, sin Ωt) their complex amplitudes are

    a = m e Ω² / (k + k_v − m Ω² + i c_v Ω),    b = −i m e Ω² / (k − m Ω² + i c_w Ω),

and the orbit's major semi-axis is √((|a|² + |b|² + |a² + b²|)/2) (the largest over θ of
|Re(a e^{iθ})|² + |Re(b e^{iθ})|²). With s = 0.004, ζ_v = ζ_w = 0.002 the half-power bands
(2ζ ω_n = 0.004 ω_n wide) touch: the orbit has two local maxima, 1.000281 and 1.003725 ω_n,
the upper 0.08 % taller, with a dip of 8 % between them. The references are those maxima,
bracketed on a grid of the formula and located by a bounded scalar search on the formula
itself (no flexshaft code).

Before the fix (hunt f58), the 21-point scan (spacing 0.077 ω_n) found only the upper maximum:
the w root's window Re Ω + |Im Ω| (0, ±0.5, ±1, ±2) reaches the v peak at its +2 edge, whose
orbit is the window's largest, and the seed was dropped as having "no maximum of its own"
although the window's samples rise to a maximum at Re Ω and fall after it. Likewise s = 0.002
with ζ = 0.001 (21 and 41 points), and ζ_v = 1e-4, ζ_w = 2e-3 with s = 0.004 (21 and 41 points).

Tolerance: a 20th of the resonance's own half-power bandwidth 2ζω_n, the refinement's stated
resolution (docs/requirements.md step 3: sample intervals at most 1/20 of the bandwidth, the
vertex of a parabola through 1/A²). Measured: at most 0.017 of it for the equal dampings and
0.09 for the sharp v peak at ζ_v = 1e-4 (tolerance 3e-3 rad/s; the tube's mass, 3.5e-6 of the
disk's, moves the model's resonance off the closed form's by about 2.6e-4 rad/s), the same at
every scan size, so the margin does not rest on round-off. Exactly two criticals are reported in the
band (no duplicate of a peak found by both the scan and a seed). CPU: one scan of 21-61 banded
solves of an 8-element model and a few refinements, about 0.1-0.3 s per case.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.optimize
from rotors import K_SHAFT, M_DISK, WN, jeffcott_text

from flexshaft.analyses.criticals import lateral_critical_speeds
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm

ECCENTRICITY = 1e-5
#: (separation s, ζ_v, ζ_w): the hunter's three cases
CASES = [(0.004, 0.002, 0.002), (0.002, 0.001, 0.001), (0.004, 1e-4, 2e-3)]


def _damping(separation: float, zeta_v: float, zeta_w: float) -> tuple[float, float, float]:
    k_v = ((1 + separation) ** 2 - 1) * K_SHAFT
    return k_v, 2 * zeta_v * np.sqrt((K_SHAFT + k_v) * M_DISK), 2 * zeta_w * np.sqrt(K_SHAFT * M_DISK)


def _model(separation: float, zeta_v: float, zeta_w: float):
    k_v, c_v, c_w = _damping(separation, zeta_v, zeta_w)
    text = jeffcott_text(0.0, 0.0).replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(1.2 * WN)}")
    text = text.replace("stiffness = {}", f"stiffness = {{ v = {k_v} }}")
    text = text.replace("damping = { v = 0.0, w = 0.0 }", f"damping = {{ v = {c_v}, w = {c_w} }}")
    return build_model(loads_design(text + f"\n[loads]\neccentricity = {ECCENTRICITY}\n"))


def _closed_form_maxima(separation: float, zeta_v: float, zeta_w: float, span: float = 0.01) -> np.ndarray:
    """The local maxima [rad/s] of the closed-form orbit (module docstring) within ±``span`` of
    ω_n, bracketed on a grid 1e-6 ω_n apart (1/200 of the v band at ζ_v = 1e-4, 1/1000 at
    5e-4) and located by a bounded search on the formula."""
    k_v, c_v, c_w = _damping(separation, zeta_v, zeta_w)

    def orbit(speed):
        force = M_DISK * ECCENTRICITY * speed**2
        a = force / (K_SHAFT + k_v - M_DISK * speed**2 + 1j * c_v * speed)
        b = -1j * force / (K_SHAFT - M_DISK * speed**2 + 1j * c_w * speed)
        return np.sqrt((abs(a) ** 2 + abs(b) ** 2 + abs(a * a + b * b)) / 2)

    grid = np.linspace((1 - span) * WN, (1 + span) * WN, round(2 * span / 1e-6) + 1)
    level = orbit(grid)
    bracketed = np.flatnonzero((level[1:-1] > level[:-2]) & (level[1:-1] > level[2:])) + 1
    maxima = [
        scipy.optimize.minimize_scalar(
            lambda s: -orbit(s), bounds=(grid[i - 1], grid[i + 1]), method="bounded", options={"xatol": 1e-9 * WN}
        ).x
        for i in bracketed
    ]
    return np.array(maxima)


@pytest.mark.parametrize("n_points", [21, 31, 41, 61])
@pytest.mark.parametrize(("separation", "zeta_v", "zeta_w"), CASES)
def test_both_close_maxima_are_critical_speeds_at_any_scan(separation, zeta_v, zeta_w, n_points):
    """Both closed-form maxima (the lower the w resonance's, the upper the v one's) are critical
    speeds, each to a 20th of its own resonance's bandwidth, and no other critical is reported
    between 0.9 and 1.1 ω_n."""
    expected = _closed_form_maxima(separation, zeta_v, zeta_w)
    assert expected.size == 2
    model = _model(separation, zeta_v, zeta_w)
    found = sorted(
        c.speed for c in lateral_critical_speeds(model, top=1.3, n_points=n_points) if 0.9 * WN < c.speed < 1.1 * WN
    )
    assert len(found) == 2, np.array(found) / WN
    tolerance = 2 * np.array([zeta_w, zeta_v]) * WN / 20
    assert np.all(np.abs(np.array(found) - expected) <= tolerance), (np.array(found) - expected) / tolerance
