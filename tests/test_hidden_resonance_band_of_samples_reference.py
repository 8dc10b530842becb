"""A resonance one to two scan intervals wide, swamped on the samples by a taller neighbour,
is still a critical speed.

Rule (docs/requirements.md, "How flexshaft computes AF", step 2): "Each local maximum of the
orbit envelope (largest over shaft stations and imbalance cases) is a lateral critical speed";
the module docstring of :mod:`flexshaft.analyses.criticals` adds that the critical speeds do not
depend on where the scan's samples fall.

Reference (closed form, derived here as in tests/test_close_resonances_any_sampling_reference.py):
the Jeffcott rotor of tests/rotors.py (disk m = 20 kg at midspan of a near-massless pinned-pinned
tube, k = 48 E I / L³, ω_n = √(k/m)) with a bearing at the disk adding k_v = ((1 + s)² − 1) k in
v only and dashpots c_v = 2 ζ_v √((k + k_v) m), c_w = 2 ζ_w √(k m). The disk does not tilt at
midspan, so v and w are two single-degree-of-freedom systems; under the imbalance force
m e Ω² (cos Ωt, sin Ωt)

    a = m e Ω² / (k + k_v − m Ω² + i c_v Ω),    b = −i m e Ω² / (k − m Ω² + i c_w Ω),

and the orbit's major semi-axis is √((|a|² + |b|² + |a² + b²|)/2). With s = 0.012, ζ_v = 0.001,
ζ_w = 0.006 it has two local maxima near ω_n: the broad w one at 1.00095 ω_n (|Im Ω| ≈ ζ_w ω_n
= 0.006 ω_n, a half-power band 0.012 ω_n wide) on the rising flank of the tall narrow v one at
(1 + s) ω_n. The references are those maxima, bracketed on a fine grid of the formula and located
by a bounded scalar search on the formula itself (no flexshaft code).

The scans (operating speed 1.2 ω_n, top 1.3: to 1.56 ω_n) have 313 and 417 points, intervals of
4.9e-3 and 3.7e-3 ω_n (from 0.02 of the operating speed): the w root's |Im Ω| is 1.2 and 1.6 intervals, inside the
4-interval limit below which a synchronous root is looked for (``_SHOWN_SAMPLES``). On these
samples the w maximum is swamped by the v flank (no sample above both its neighbours there), so
only the seeded root finds it (measured: with the limit at one interval the w maximum is lost at
both scans).

Tolerance: a 20th of the resonance's own half-power bandwidth 2ζω_n, the refinement's stated
resolution (docs/requirements.md step 3: sample intervals at most 1/20 of the bandwidth, the
vertex of a parabola through 1/A²); the tube's mass (3.5e-6 of the disk's) moves the model's
resonance off the closed form's by about 2.6e-4 rad/s, far inside it. Exactly two criticals are
reported between 0.9 and 1.1 ω_n. CPU: one scan of 313-417 banded solves of an 8-element model
and a few refinements, well under a second.
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import WN
from test_close_resonances_any_sampling_reference import _closed_form_maxima, _model

from flexshaft.analyses.criticals import lateral_critical_speeds

SEPARATION, ZETA_V, ZETA_W = 0.012, 0.001, 0.006


@pytest.mark.parametrize("n_points", [313, 417])
def test_swamped_resonance_a_few_intervals_wide_is_a_critical_speed(n_points):
    """Both closed-form maxima are critical speeds, each to a 20th of its own bandwidth."""
    expected = _closed_form_maxima(SEPARATION, ZETA_V, ZETA_W, span=0.05)
    assert expected.size == 2
    model = _model(SEPARATION, ZETA_V, ZETA_W)
    found = sorted(
        c.speed for c in lateral_critical_speeds(model, top=1.3, n_points=n_points) if 0.9 * WN < c.speed < 1.1 * WN
    )
    assert len(found) == 2, np.array(found) / WN
    tolerance = 2 * np.array([ZETA_W, ZETA_V]) * WN / 20
    assert np.all(np.abs(np.array(found) - expected) <= tolerance), (np.array(found) - expected) / tolerance
