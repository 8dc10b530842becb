"""Every result object exports a CF-style xarray Dataset that survives a netCDF round trip.

The reference is the result itself: after ``to_dataset()`` → netCDF (netCDF4 when installed, else scipy.s netCDF3,
the install without netCDF4) → ``open_dataset``, the stored numbers equal the result's own
arrays, every data variable has a ``long_name``, coded labels decode through
``flag_values``/``flag_meanings``, and the global ``Conventions`` attribute is set.
"""

import dataclasses

import numpy as np
import pytest
import xarray as xr
from conftest import SMALLEST

from flexshaft.analyses import campbell, imbalance_response, modes, stability
from flexshaft.analyses.shaft_strength import shaft_safety_factor, static_load_parts
from flexshaft.analyses.spinup import spinup_map
from flexshaft.assembly import build_model
from flexshaft.assembly.loads import imbalance_loads
from flexshaft.design import baseline_design, with_overrides


@pytest.fixture(scope="module")
def model():
    return build_model(with_overrides(baseline_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 8}))


def round_trip(result, tmp_path):
    path = result.save(tmp_path / f"{type(result).__name__}.nc")
    with xr.open_dataset(path, mask_and_scale=False) as ds:
        ds = ds.load()
    assert ds.attrs["Conventions"].startswith("CF-")
    for name, var in ds.data_vars.items():
        assert "long_name" in var.attrs, name
    return ds


def decode(var):
    meanings = var.attrs["flag_meanings"].split()
    lookup = dict(zip(np.asarray(var.attrs["flag_values"]).tolist(), meanings))
    return np.vectorize(lookup.__getitem__)(var.values)


def test_modes(model, tmp_path):
    m = modes(model, model.speed, n_modes=8)
    ds = round_trip(m, tmp_path)
    np.testing.assert_array_equal(ds.frequency.values, m.frequencies)
    np.testing.assert_array_equal(ds.log_decrement.values, m.log_decrements)
    # and what they mean, from the definitions: s = −σ + iω_d, f = ω_d/2π [Hz]; the log decrement
    # ln(x(t)/x(t + T_d)) = σ T_d = 2π σ/ω_d (equal to 2πζ/√(1 − ζ²), ζ = σ/|s|); a few ulps
    s = m.eigenvalues
    np.testing.assert_allclose(ds.frequency.values, s.imag / (2 * np.pi), rtol=1e-14)
    np.testing.assert_allclose(ds.log_decrement.values, -2 * np.pi * s.real / s.imag, rtol=1e-12)
    assert list(decode(ds.kind)) == list(m.kind) and list(decode(ds.whirl)) == list(m.whirl)
    v = m.shapes[model.dofs.shaft(np.arange(model.dofs.n_shaft_nodes), "v")]  # (nodes, modes)
    np.testing.assert_array_equal(ds.shaft_v_real.values, v.real.T)
    assert ds.frequency.attrs["units"] == "Hz" and ds.attrs["internal_damping"] == "rotating"


def test_campbell_and_stability(model, tmp_path):
    speeds = np.linspace(0.0, model.speed, 9)
    c = campbell(model, speeds, n_modes=6)
    ds = round_trip(c, tmp_path)
    np.testing.assert_array_equal(ds.frequency.values, c.frequencies)
    assert list(decode(ds.whirl).ravel()) == list(c.whirl.ravel())
    np.testing.assert_array_equal(ds.critical_speed.values, [k.speed for k in c.critical_speeds])
    s = stability(model, speeds, n_modes=6)
    ds = round_trip(s, tmp_path)
    np.testing.assert_array_equal(ds.growth_rate.values, s.real_parts)
    assert ds.speed.attrs["units"] == "rad/s"


def test_response_strength_spinup_and_verdict(model, tmp_path):
    q = imbalance_response(model, [100.0, 300.0], imbalance_loads(model))
    ds = round_trip(q, tmp_path)
    nodes = np.arange(model.dofs.n_shaft_nodes)
    np.testing.assert_array_equal(ds.shaft_w_imag.values[0], np.asarray(q)[model.dofs.shaft(nodes, "w"), 0].imag.T)
    strength = shaft_safety_factor(model, static_load_parts(model), q[:, 0, -1])
    ds = round_trip(strength, tmp_path)
    assert ds.attrs["safety_factor"] == strength.safety_factor
    np.testing.assert_array_equal(ds.safety_factor_along.values, strength.along_shaft)
    smap = spinup_map(model, [1e6, 1e7], [0.0, 500.0], speeds=np.linspace(50.0, model.speed, 20))
    ds = round_trip(smap, tmp_path)
    np.testing.assert_array_equal(ds.shaft_peak.values, smap.shaft_peak)
    from flexshaft.design import design_from_dict
    from flexshaft.verdict.assess import assess

    # one envelope point on the smallest grids a resolution accepts (CPU budget, issue 23): the
    # verdict's dataset is one row per check, the same checks whatever the points and grids; the
    # last check is stored as not evaluated (as it is when its evidence is missing: a shaft
    # that is not laminated has no ply strength), so that all three statuses are stored
    data = model.design.model_dump()
    data["envelope"]["points"] = data["envelope"]["points"][:1]
    verdict = assess(design_from_dict(data), SMALLEST).verdict
    last = verdict.checks[-1]
    missing = dataclasses.replace(last, status="not evaluated", value=None, margin=None, location={}, findings=())
    verdict = dataclasses.replace(verdict, checks=(*verdict.checks[:-1], missing))
    ds = round_trip(verdict, tmp_path)
    assert list(ds.check.values) == [c.key for c in verdict.checks]
    assert list(decode(ds.status)) == [c.status.replace(" ", "_") for c in verdict.checks]
    assert {"pass", "fail", "not_evaluated"} <= set(decode(ds.status))
