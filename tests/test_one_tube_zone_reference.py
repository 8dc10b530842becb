"""The one zone of an unsegmented shaft spans the shaft, [x_start, x_end], even when the shaft
starts aft of the boom root (design/components.py ``Shaft.tubes``).

Reference (docs/segmented-driveline.md: "An existing design file is one tube"; the metal
buckling of each isotropic segment is taken "between its ends (simply supported ...)"): a steel
tube from x = 0.5 m to x = 1.5 m is one zone 1.0 m long, not 1.5 m (the station of its aft end);
its mass is ρ π (D_o² − D_i²)/4 · L = 7800 · π (0.05² − 0.04²)/4 · 1.0 = 5.5135 kg (hand sum),
and the torsional-buckling check of the metal shaft uses the shell length L = 1.0 m. The
geometry is exact in binary up to one rounding of x_end − x_start: rel 1e-12 leaves room for
that and the products of the mass formula. CPU about 0.1 s (an 8-element tube).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.metal_strength import metal_strength
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from tests.rotors import jeffcott_text

X_START, X_END, DENSITY = 0.5, 1.5, 7800.0


def _aft_shifted_steel_tube():
    text = (
        jeffcott_text(0.0, 0.0)
        .replace("x_start = 0.0", f"x_start = {X_START}")
        .replace("x_end = 1.0", f"x_end = {X_END}")
        .replace("x = 0.5", f"x = {(X_START + X_END) / 2}")
        .replace("density = 0.1", f"density = {DENSITY}")
    )
    design = loads_design(text)
    assert design.shaft.x_start == X_START and design.shaft.x_end == X_END
    return build_model(design)


def test_one_tube_zone_spans_the_shaft_not_the_boom_root():
    model = _aft_shifted_steel_tube()
    (zone,) = model.segments
    assert zone.x_start == pytest.approx(X_START, rel=1e-12)
    assert zone.x_end == pytest.approx(X_END, rel=1e-12)
    assert zone.length == pytest.approx(1.0, rel=1e-12)
    hand_mass = DENSITY * math.pi * (0.05**2 - 0.04**2) / 4.0 * 1.0
    assert hand_mass == pytest.approx(5.5135, rel=1e-4)
    assert zone.mass == pytest.approx(hand_mass, rel=1e-12)


def test_metal_buckling_length_is_the_tube_between_its_ends():
    model = _aft_shifted_steel_tube()
    result = metal_strength(model, np.zeros(model.dofs.size))
    (buckling,) = result.buckling
    assert buckling.length == pytest.approx(X_END - X_START, rel=1e-12)
