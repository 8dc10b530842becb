"""Thermal-design sweeps of a design (thesis figures 3.18, 3.19) in flexshaft.thermal.study."""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.thermal.analysis import shaft_air_temperature, shaft_thermal
from flexshaft.thermal.heat import heat_sources
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.study import convection_sweep, temperature_profiles, wall_thickness_sweep


@pytest.fixture(scope="module")
def baseline():
    design = fs.baseline_design()
    return design, fs.build_model(design)


def test_convection_sweep_tends_to_the_local_balance(baseline):
    # Reference: with conduction along the wall weak against convection, each interior node's
    # control volume convects what it generates, θ_i = s_i / (h P ℓ_i) (s_i: half of each
    # adjacent element's heat). The neglected conduction term is G(2θ_i − θ_{i−1} − θ_{i+1}) with
    # G = k A / L_e, so the peak differs from the local balance by at most 2 (G_l + G_r)/C_i of
    # itself, C_i = h P ℓ_i: that bound is the tolerance.
    design, model = baseline
    options = thermal_options(design.thermal)
    coefficients = (20.0, 144.0)
    sweep = convection_sweep(model, coefficients, options=options)
    src = heat_sources(model)
    x = src.x
    L = np.diff(x)
    ell = np.zeros(x.size)
    ell[:-1] += L / 2
    ell[1:] += L / 2
    s = np.zeros(x.size)
    s[:-1] += src.total / 2
    s[1:] += src.total / 2
    Do, Di = model.shaft.outer_diameter, model.shaft.inner_diameter
    k = shaft_thermal(model, options).conductivity
    G = k * np.pi * (Do**2 - Di**2) / 4 / L
    for h, peak, rise in zip(coefficients, sweep["peak_rise"], sweep["rise"]):
        C = h * np.pi * Do * ell
        local = s[1:-1] / C[1:-1]
        bound = np.max(2 * (G[:-1] + G[1:]) / C[1:-1])
        assert bound < 0.1  # the limit applies on the baseline mesh (5 % at h = 20, 0.7 % at 144)
        assert peak == pytest.approx(local.max(), rel=bound)
        assert rise.shape == x.shape
    assert sweep["peak_rise"][0] > sweep["peak_rise"][1]


def test_wall_thickness_sweep_rebuilds_each_design_at_the_boom_air(baseline):
    design, model = baseline
    options = thermal_options(design.thermal)
    sweep = wall_thickness_sweep(design, [0.002, design.shaft.wall_thickness])
    assert sweep["rise"].shape == (2, model.dofs.shaft_x.size)
    # at the design's own wall the sweep is the design's shaft temperature (same air, options,
    # loss model): plumbing check
    own = shaft_thermal(model, options)
    assert sweep["peak_rise"][1] == pytest.approx(own.peak_rise, rel=1e-12)
    assert own.temperature.air_temperature == pytest.approx(shaft_air_temperature(design.tailboom, options))
    # a thinner wall at fixed D_o bends more under the same loads but has less lossy material:
    # both heat values are positive and differ
    assert np.all(sweep["heat"] > 0) and sweep["heat"][0] != sweep["heat"][1]


def test_temperature_profiles_are_labelled_by_wall_and_by_h(baseline):
    design, model = baseline
    prof = temperature_profiles(design, model, walls=(0.003,), coefficients=(5.0, None))
    assert list(prof.by_wall) == ["wall 3.0 mm"]
    labels = list(prof.by_h)
    assert labels[0] == "h = 5 W/m²K" and labels[1].endswith("(correlation)")
