r"""A shallow dip of a resonance circle on a sloping real background, which the search of
``dip_crossovers`` (flexshaft.analyses.loop_dips) reaches only after its refitted circle has
predicted it across the axis, against the crossings of Im L = 0 in closed form.

The loop, built by formula (derived here), with u = (ω − ω_r)/(ζ ω_r), ω_r = 2π·100 rad/s,
ζ = 0.01:

    L(ω) = P + i h − i ρ (1 + i u)/(1 − i u) + β (ω − ω_r)/ω_r,

P = −0.8, h = 0.95, ρ = 1, β = 15 (real). Since (1 + i u)/(1 − i u) = (1 − u² + 2iu)/(1 + u²),
the mode term runs over the circle of centre P + i h and radius ρ, its lowest point P + i(h − ρ)
at u = 0, and the background β(ω − ω_r)/ω_r is real: it moves Re L only (by 0.15 per half
width ζω_r, 15 % of the radius), so the circle is not the image of ln ω under one Möbius map
any more while

    Im L = h − ρ (1 − u²)/(1 + u²)

is exact. Im L = 0 where u² = (ρ − h)/(ρ + h) = 0.05/1.95: u = ∓0.160128, ω = ω_r(1 + ζu) =
627.31242 and 629.32465 rad/s; there Re L = P + 2ρu/(1 + u²) + βζu = −1.13627 and −0.46373,
a pair of phase crossovers (the second an upper gain margin of 20 lg(1/0.46373) = 6.675 dB).
The dip reaches 0.05 below the axis over a third of a half width.

The part searched is [ω_r(1 − 1.5ζ), ω_r(1 + 3ζ)] with the third point at ω_r(1 − 3ζ), and its
mirror image in u ([−3ζ, 1.5ζ], third at +3ζ): Im L = 1.335 and 1.750 at the ends, above the
axis. Traced by hand (scalar complex arithmetic, no LAPACK/BLAS): the map through the three
points puts its extreme at Im 0.134 (above the axis), the first point evaluated has Im L =
0.749; the refit puts the extreme at Im 0.0214, the second point (626.947 rad/s in the first
case) has Im L = 0.0409, 0.0195 off that map; the refit through it and its neighbours now puts
the extreme at Im −0.0478, across the axis. Its signed clearance −0.0478 is below the map's
error 0.0195, so the search goes on, and its third point (Im L = −0.0495) is across: split and
refined. Weighing the refit's distance from the axis (0.0478 > 0.0195, 2.5 times) instead
of its signed clearance would stop the search there with no crossing and lose the pair.

Tolerance: the search refines each crossing by regula falsi to a bracket of 1e-8 ω holding the
point returned; the closed-form roots are exact to round-off: 2e-8 relative. Im L at the points
returned: |d Im L/dω| = 4ρu/((1 + u²)² ζω_r) ≤ 1.3/(ζω_r) = 0.21 s/rad (largest at u = 1/√3),
and 1e-8 ω = 6.3e-6 rad/s moves Im L by at most 1.3e-6, hence 2e-6. Re L at the points
returned: Re L = P + 2ρu/(1 + u²) + β(ω − ω_r)/ω_r, d/du [2u/(1 + u²)] = 2(1 − u²)/(1 + u²)² ≤ 2,
so |d Re L/dω| ≤ (2ρ/ζ + β)/ω_r = 215/628.3 = 0.34 s/rad and 6.3e-6 rad/s moves Re L by at
most 2.2e-6, hence 1e-5 (a factor 4.6 above; a lost crossing moves it by 0.1 or more). The value
returned with each point is the loop evaluated there: the same formula at the same ω, equal to
round-off of numbers of order 1, checked to 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.local_projection import lockstep
from flexshaft.analyses.loop_dips import dip_crossovers

WR, ZETA = 2 * np.pi * 100.0, 0.01
P, H, RHO, BETA = -0.8, 0.95, 1.0, 15.0


def _loop(w):
    w = np.asarray(w, dtype=float)
    u = (w - WR) / (ZETA * WR)
    return P + 1j * H - 1j * RHO * (1 + 1j * u) / (1 - 1j * u) + BETA * (w - WR) / WR


U = np.sqrt((RHO - H) / (RHO + H))  # Im L = 0 at u = ±U (module docstring)
CROSSINGS = WR * (1 + ZETA * np.array([-U, U]))
RE_AT_CROSSINGS = P + 2 * RHO * np.array([-U, U]) / (1 + U**2) + BETA * ZETA * np.array([-U, U])


@pytest.mark.parametrize("ends, third", [((-1.5, 3.0), -3.0), ((-3.0, 1.5), 3.0)], ids=["below", "above"])
def test_a_dip_the_refit_predicts_across_the_axis_is_searched_to_its_pair(ends, third):
    a, b = WR * (1 + ZETA * np.array(ends))
    c = WR * (1 + ZETA * third)
    la, lb, lc = complex(_loop(a)), complex(_loop(b)), complex(_loop(c))
    assert la.imag > 1.3 and lb.imag > 1.3  # the grid sees no crossing in the part
    assert CROSSINGS == pytest.approx([627.31242, 629.32465], abs=1e-5)
    assert RE_AT_CROSSINGS == pytest.approx([-1.13627, -0.46373], abs=1e-5)
    # the closed form is the loop's: Im L vanishes there
    assert np.all(np.abs(_loop(CROSSINGS).imag) < 1e-12)
    found = lockstep([dip_crossovers(a, b, la, lb, c, lc)], lambda x, _: _loop(x))[0]
    assert len(found) == 2
    assert [x for x, _ in found] == pytest.approx(CROSSINGS, rel=2e-8)
    for (x, value), re in zip(found, RE_AT_CROSSINGS):
        assert value == pytest.approx(complex(_loop(x)), abs=1e-12)  # the loop's value at the point
        assert abs(value.imag) < 2e-6
        assert value.real == pytest.approx(re, abs=1e-5)
    # the upper gain margin the pair sets
    assert 20 * np.log10(1 / abs(found[1][1])) == pytest.approx(6.675, abs=1e-3)
