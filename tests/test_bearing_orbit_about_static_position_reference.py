"""A bearing's orbit drawn where the shaft sits: about its static position in the clearance.

The actuator-excursion check judges static offset + orbit against the auxiliary-bearing gap
(docs/requirements.md); the report's orbit figure and bearing table must show the same two
parts. References (derived here):

* the Jeffcott rotor of tests/jeffcott_bearing.py (a 20 kg disk on a near-massless tube of
  stiffness k at the disk, ONE bearing at the disk, each plane on its own): a static load P
  deflects the disk, and with it the bearing's relative displacement, by P / (k + Z_b(0)),
  Z_b(0) = k_b for a contact bearing, k_i K_p − k_s for a PD magnetic bearing; a bearing with
  integral action holds it at 0 (statics). Tolerance 1e-9: one static solve of a
  well-conditioned 4-element model (condition of the stiffness ~1e4, round-off 1e-12);
* the figure's drawn data in its own units: an orbit of radius a about a centre (c_v, c_w) is
  the circle whose points average to the centre and lie at distance a from it; the note reads
  |c| + a as a share of the gap (the check's sum; a 3-4-5 offset of 0.5 mm and a 0.1 mm orbit
  against a 0.75 mm gap: 80 %). Drawn coordinates carry only float round-off: 1e-9.
"""

from __future__ import annotations

import numpy as np
import pytest
from jeffcott_bearing import ACTIVE, CONTACT, KB, KI, KP, KS, PID, disk, model_with
from rotors import K_SHAFT

from flexshaft.analyses.reactions import bearing_reactions
from flexshaft.analyses.response import static_response
from flexshaft.plot.response import orbit_figure


def _reaction(bearing: str, pv: float, pw: float):
    model = model_with(bearing)
    v, w = disk(model)
    load = np.zeros(model.dofs.size)
    load[v], load[w] = pv, pw
    q_static = static_response(model, load, speed=0.0)
    return bearing_reactions(model, q_static, np.zeros(model.dofs.size, complex), speed=0.0, loads=load)["b"]


def _static_position(bearing: str, pv: float, pw: float):
    return _reaction(bearing, pv, pw).static_position


@pytest.mark.parametrize(("bearing", "stiffness"), [(CONTACT, KB), (ACTIVE, KI * KP - KS)], ids=["contact", "pd"])
def test_static_position_is_the_load_over_the_parallel_stiffness(bearing, stiffness):
    r = _reaction(bearing, -300.0, 400.0)
    k = K_SHAFT + stiffness
    assert r.static_position == pytest.approx((-300.0 / k, 400.0 / k), rel=1e-9)
    assert r.static_offset == pytest.approx(500.0 / k, rel=1e-9)  # |(−300, 400)| = 500 N (3-4-5)


def test_an_integrating_bearing_holds_the_shaft_at_its_centre():
    assert np.abs(_static_position(PID, -300.0, 400.0)).max() < 1e-12


def _drawn(centres, gap=7.5e-4):
    """The orbit panel of a 0.1 mm forward circle about ``centres`` (v, w) [m]."""
    import matplotlib.pyplot as plt

    fig = orbit_figure({"amb": (1.0e-4, -1.0e-4j)}, {"amb": gap}, centres=centres)
    (ax,) = [a for a in fig.axes if a.get_visible()]
    orbit = ax.lines[0]
    note = [t.get_text() for t in ax.texts if "gap" in t.get_text()]
    lines = [(np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)) for line in ax.lines]
    limits = ax.get_xlim(), ax.get_ylim()
    plt.close(fig)
    return np.asarray(orbit.get_xdata(), float), np.asarray(orbit.get_ydata(), float), note, lines, limits


def test_orbit_is_drawn_about_the_static_position_and_its_note_adds_both():
    cv, cw = -3.0e-4, 4.0e-4  # |c| = 0.5 mm
    w, v, note, lines, (xlim, ylim) = _drawn({"amb": (cv, cw)})
    # in mm (the extent, 0.75 mm gap, is above 0.1 mm); the closed curve's first point repeats
    assert np.mean(w[:-1]) == pytest.approx(cw * 1e3, abs=1e-9)
    assert np.mean(v[:-1]) == pytest.approx(cv * 1e3, abs=1e-9)
    assert np.hypot(w - cw * 1e3, v - cv * 1e3) == pytest.approx(0.1, abs=1e-9)
    assert note == ["static 0.5 mm + orbit 0.1 mm\n80 % of gap 0.75 mm"]
    # the gap circle about the bearing's centre (0, 0), inside the axes
    radii = [np.hypot(x, y) for x, y in lines if x.size > 2]
    assert any(np.allclose(r, 0.75, atol=1e-9) for r in radii)
    assert xlim[1] >= 0.75 and ylim[0] <= -0.75


def test_without_a_static_offset_the_note_is_the_orbit_alone():
    w, v, note, _, _ = _drawn(None)
    assert np.mean(w[:-1]) == pytest.approx(0.0, abs=1e-9) and np.mean(v[:-1]) == pytest.approx(0.0, abs=1e-9)
    assert note == ["max 0.1 mm\n13.3 % of gap 0.75 mm"]


def test_an_offset_a_millionth_of_the_orbit_is_round_off():
    """An integrating bearing holds the shaft at its centre: its computed static offset is
    round-off (6e-13 μm beside a 50 μm orbit on the tuned design with integral action, audit
    a2). Below 1e-6 of the orbit (or gap) the panel states the orbit alone."""
    _, _, note, _, _ = _drawn({"amb": (1.0e-16, 0.0)})
    assert note == ["max 0.1 mm\n13.3 % of gap 0.75 mm"]
