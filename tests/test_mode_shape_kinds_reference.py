"""Reference: the mode-shape figure draws what a torsional or axial mode moves (review, sixteenth
session).

Was: a torsional mode's panel drew its lateral v and w, round-off normalised to ±1, as if it were
a bending shape (the twist not drawn at all). A uniform shaft held in twist and axially at x = 0
and free at x = L has the quarter sines sin(πx/2L) for its first torsional mode (√(G/ρ)/4L) and
its first axial mode (√(E/ρ)/4L): the wave equation φ'' + (ω/c)² φ = 0 with φ(0) = 0 and
φ'(L) = 0 gives φ = sin(πx/2L), ω = πc/(2L), c = √(G/ρ) or √(E/ρ) (derived here). The design:
an aluminium tube, 2 m, Ø100 × 3 mm, on stiff pins (the aft one axially free), 40 elements.
The FE nodal values of a fixed-free bar's first mode with linear elements err by O(h²)
(h = 1/40 of the quarter wave): 2e-3 absolute on the normalised shape.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

TUBE = """
name = "Al tube 2 m on stiff pins"
[materials.al]
kind = "isotropic"
E = 70.0e9
G = 26.923076923e9
density = 2700.0
loss_factor = 0.002
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.1
wall_thickness = 0.003
material = "al"
fixed_start = ["theta"]
fixed_end = []
[[bearings]]
name = "b1"
kind = "contact"
x = 0.0
stiffness = { u = 1.0e12, v = 1.0e12, w = 1.0e12 }
[[bearings]]
name = "b2"
kind = "contact"
x = 2.0
stiffness = { v = 1.0e12, w = 1.0e12 }
[operating]
speed_rpm = 3000.0
power = 100.0e3
[mesh]
shaft_elements = 40
"""


@pytest.fixture(scope="module")
def result():
    model = build_model(loads_design(TUBE))
    return model, modes(model, model.speed, n_modes=8)


@pytest.mark.parametrize(
    ("kind", "label", "frequency"),
    [
        ("torsional", "shaft twist θ (torsion)", np.sqrt(26.923076923e9 / 2700.0) / 8.0),
        ("axial", "shaft axial u", np.sqrt(70.0e9 / 2700.0) / 8.0),
    ],
)
def test_a_torsional_or_axial_panel_draws_its_quarter_sine(result, kind, label, frequency):
    model, found = result
    (k,) = np.flatnonzero(found.kind == kind)
    assert found.frequencies[k] == pytest.approx(frequency, rel=1e-3)  # the mode it is (h² error)
    fig = found.plot_shapes(modes=[k])
    (ax,) = [a for a in fig.axes if a.get_visible()]
    lines = {str(line.get_label()): line for line in ax.get_lines()}
    assert not {"shaft v (vertical)", "shaft w (lateral)"} & set(lines)  # no lateral round-off drawn
    x, y = (np.asarray(v, float) for v in lines[label].get_data())
    assert y == pytest.approx(np.sin(np.pi * x / 4.0), abs=2e-3)
