"""The numbers and labels of the data files (xarray datasets, netCDF) against hand derivations.

The datasets are built from hand-made results whose every value is known in closed form (no
model is assembled: the dataset functions only read the attributes named here), then written to
netCDF and read back; each stored value is checked WITH its unit attribute and its coordinates.

Derived (single-DOF oscillator, m x'' + c x' + k x = 0, ζ = c/(2√(km)), ω_n = √(k/m)):

* eigenvalue s = −ζω_n + iω_d, ω_d = ω_n√(1 − ζ²) [rad/s]; damped frequency f = ω_d/2π [Hz];
  growth rate Re s = −ζω_n [1/s]; damping ratio ζ = −Re s/|s|;
* log decrement δ = ln(x(t)/x(t + T_d)) = ζω_n T_d = 2πζ/√(1 − ζ²) [-] (not ζ);
* a speed Ω [rad/s] is 60Ω/2π rpm; a harmonic excitation at ω [rad/s] is ω/2π Hz.

The DOF layout is hand-made too: shaft node j holds (u, v, w) at DOFs 3j, 3j + 1, 3j + 2; boom
node j holds (v, w) after the shaft's. A forward circular whirl orbit at shaft node j has
v = a_j e^{iφ}, w = −i v (w lags v by 90°), so Re w = a_j sin φ and Im w = −a_j cos φ.

Tolerances: the values pass through numpy and a float64 netCDF file unchanged, so stored numbers
equal the hand values to round-off of the few operations the test itself does (rtol 1e-14);
integers, labels and unit strings are compared exactly.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

import flexshaft.netcdf as nc
from flexshaft.analyses.campbell import CriticalSpeed, EigenvalueCurves
from flexshaft.analyses.datasets import curves_dataset, modes_dataset, response_dataset, strength_dataset
from flexshaft.analyses.response import HarmonicResponse
from flexshaft.analyses.results import new_arrays
from flexshaft.analyses.shaft_strength import StrengthResult
from flexshaft.netcdf import write_labelled_netcdf, write_netcdf

K, M = 4.0e6, 10.0  # N/m, kg
WN = math.sqrt(K / M)  # 632.455... rad/s
ZETA = 0.05
WD = WN * math.sqrt(1 - ZETA**2)
DELTA = 2 * math.pi * ZETA / math.sqrt(1 - ZETA**2)  # 0.3146..., six times ζ
SHAFT_X = np.array([0.0, 0.5, 1.0])  # m
BOOM_X = np.array([0.2, 1.2])  # m
PHI = 0.3  # rad, phase of the orbits
A = np.array([1.0, 2.0, 4.0]) * 1e-3  # m, orbit radius at each shaft node
B_V, B_W = np.array([0.1, 0.3]) * 1e-3, np.array([0.5, 0.7]) * 1e-3  # m, boom amplitudes (real)


class Dofs:
    """Hand-made DOF layout (see the module docstring)."""

    shaft_x, boom_x, n_shaft_nodes, n_boom_nodes, ndof = SHAFT_X, BOOM_X, 3, 2, 13

    @staticmethod
    def shaft(index, field):
        return 3 * np.asarray(index) + "uvw".index(field)

    @staticmethod
    def boom(index, field):
        return 9 + 2 * np.asarray(index) + "vw".index(field)


def whirl_vector(scale: float = 1.0) -> np.ndarray:
    """Forward circular whirl of the shaft (v = a e^{iφ}, w = −i v), the boom in phase."""
    q = np.zeros(Dofs.ndof, complex)
    nodes = np.arange(3)
    q[Dofs.shaft(nodes, "v")] = scale * A * np.exp(1j * PHI)
    q[Dofs.shaft(nodes, "w")] = -1j * scale * A * np.exp(1j * PHI)
    q[Dofs.boom(np.arange(2), "v")] = scale * B_V
    q[Dofs.boom(np.arange(2), "w")] = scale * B_W
    return q


def decode(var) -> list[str]:
    lookup = dict(zip(np.asarray(var.attrs["flag_values"]).tolist(), var.attrs["flag_meanings"].split()))
    return [lookup[int(c)] for c in np.ravel(var.values)]


def read_back(ds, tmp_path, name):
    path = write_netcdf(ds, tmp_path / f"{name}.nc")
    with xr.open_dataset(path) as back:
        return back.load()


def test_modes_file_of_a_damped_oscillator(tmp_path):
    speed = 500.0  # rad/s
    s = np.array([-ZETA * WN + 1j * WD, 1j * 2 * WN])  # mode 2: undamped, twice ω_n
    shapes = np.stack([whirl_vector(1.0), whirl_vector(2.0)], axis=1)  # (ndof, 2)
    m = SimpleNamespace(
        eigenvalues=s,
        frequencies=s.imag / (2 * np.pi),
        damping_ratios=np.array([ZETA, 0.0]),
        log_decrements=np.array([DELTA, 0.0]),
        shaft_fractions=np.array([1.0, 0.5]),  # a shaft mode; a coupled mode with half its energy in the boom
        kind=np.array(["lateral", "torsional"]),
        whirl=np.array(["backward", "none"]),
        component=np.array(["shaft", "coupled"]),
        dofs=Dofs(),
        shapes=shapes,
        speed=speed,
        internal_damping="rotating",
    )
    ds = read_back(modes_dataset(m), tmp_path, "modes")
    assert list(ds.mode.values) == [1, 2]  # 1 = lowest
    assert ds.frequency.attrs["units"] == "Hz"
    np.testing.assert_allclose(ds.frequency.values, [WD / (2 * np.pi), WN / np.pi], rtol=1e-14)
    assert ds.growth_rate.attrs["units"] == "s-1"
    np.testing.assert_allclose(ds.growth_rate.values, [-ZETA * WN, 0.0], rtol=1e-14, atol=0)
    np.testing.assert_allclose(ds.damping_ratio.values, [ZETA, 0.0], rtol=1e-14)
    np.testing.assert_allclose(ds.log_decrement.values, [DELTA, 0.0], rtol=1e-14)
    np.testing.assert_array_equal(ds.shaft_energy_share.values, [1.0, 0.5])
    assert ds.log_decrement.values[0] == pytest.approx(0.31455, rel=1e-4)  # 2π·0.05/√0.9975
    assert ds.attrs["speed"] == speed and ds.attrs["speed_units"] == "rad/s"
    assert ds.attrs["speed_rpm"] == pytest.approx(speed * 60 / (2 * np.pi), rel=1e-14)  # 4774.6 rpm
    assert decode(ds.kind) == ["lateral", "torsional"]
    assert decode(ds.whirl) == ["backward", "none"]
    assert decode(ds.component) == ["shaft", "coupled"]
    # stations in metres, in node order
    assert ds.x_shaft.attrs["units"] == "m" and ds.x_boom.attrs["units"] == "m"
    np.testing.assert_array_equal(ds.x_shaft.values, SHAFT_X)
    np.testing.assert_array_equal(ds.x_boom.values, BOOM_X)
    # the forward orbit: Re v = a cos φ, Im v = a sin φ, Re w = a sin φ, Im w = −a cos φ; mode 2 twice
    assert ds.shaft_w_imag.dims == ("mode", "x_shaft") and ds.shaft_w_real.attrs["units"] == "m"
    for k, scale in ((0, 1.0), (1, 2.0)):
        a = scale * A
        np.testing.assert_allclose(ds.shaft_v_real.values[k], a * np.cos(PHI), rtol=1e-14)
        np.testing.assert_allclose(ds.shaft_v_imag.values[k], a * np.sin(PHI), rtol=1e-14)
        np.testing.assert_allclose(ds.shaft_w_real.values[k], a * np.sin(PHI), rtol=1e-14)
        np.testing.assert_allclose(ds.shaft_w_imag.values[k], -a * np.cos(PHI), rtol=1e-14)
        np.testing.assert_array_equal(ds.shaft_u_real.values[k], 0.0)
        np.testing.assert_allclose(ds.boom_v_real.values[k], scale * B_V, rtol=1e-14)
        np.testing.assert_allclose(ds.boom_w_real.values[k], scale * B_W, rtol=1e-14)
        np.testing.assert_array_equal(ds.boom_w_imag.values[k], 0.0)


class Curves(EigenvalueCurves):
    """Eigenvalue curves made by hand: mode 1 the damped oscillator at every speed, mode 2
    undamped at 2ω_n."""

    speeds = np.array([0.0, 100.0, 300.0])  # rad/s
    eigenvalues = np.tile([-ZETA * WN + 1j * WD, 2j * WN], (3, 1))
    whirl = np.array([["forward", "backward"]] * 3)
    internal_damping = "rotating"
    # a mode at ω crosses the line ω = hΩ at Ω = ω/h: mode 1 at ω_d/2 (2×) and ω_d (1×), mode 2 at 2ω_n (1×)
    critical_speeds = (
        CriticalSpeed(WD / 2, 0, 2.0, "forward"),
        CriticalSpeed(WD, 0, 1.0, "forward"),
        CriticalSpeed(2 * WN, 1, 1.0, "backward"),
    )


def test_campbell_file_of_a_damped_oscillator(tmp_path):
    ds = read_back(curves_dataset(Curves(), "Campbell diagram"), tmp_path, "campbell")
    assert ds.speed.attrs["units"] == "rad/s" and ds.speed_rpm.attrs["units"] == "rpm"
    np.testing.assert_array_equal(ds.speed.values, [0.0, 100.0, 300.0])
    np.testing.assert_allclose(ds.speed_rpm.values, np.array([0.0, 100.0, 300.0]) * 60 / (2 * np.pi), rtol=1e-14)
    assert list(ds.mode.values) == [1, 2]
    assert ds.frequency.dims == ("speed", "mode") and ds.frequency.attrs["units"] == "Hz"
    np.testing.assert_allclose(ds.frequency.values, [[WD / (2 * np.pi), WN / np.pi]] * 3, rtol=1e-14)
    np.testing.assert_allclose(ds.damping_ratio.values, [[ZETA, 0.0]] * 3, rtol=1e-13, atol=1e-16)
    np.testing.assert_allclose(ds.log_decrement.values, [[DELTA, 0.0]] * 3, rtol=1e-13, atol=1e-16)
    assert decode(ds.whirl) == ["forward", "backward"] * 3
    # the crossings in rad/s, their tracked mode (1-based) and excitation order
    assert ds.critical_speed.attrs["units"] == "rad/s"
    np.testing.assert_allclose(ds.critical_speed.values, [WD / 2, WD, 2 * WN], rtol=1e-14)
    assert list(ds.critical_mode.values) == [1, 1, 2]
    assert list(ds.critical_harmonic.values) == [2.0, 1.0, 1.0]
    assert decode(ds.critical_whirl) == ["forward", "forward", "backward"]
    # the frequency at 110 rad/s is the row of the nearest speed, 100 rad/s
    assert float(ds.frequency.sel(speed=110.0, mode=2, method="nearest")) == pytest.approx(WN / np.pi, rel=1e-14)


def test_response_file_of_a_whirl_orbit(tmp_path):
    omegas, spins = np.array([100.0, 250.0]), np.array([100.0, 125.0])  # rad/s (2× excitation at 250)
    values = np.stack([whirl_vector(1.0), whirl_vector(3.0)], axis=1)[:, None, :]  # (ndof, case, frequency)
    r = HarmonicResponse(values, omegas, spins, Dofs(), "imbalance", "rotating")
    ds = read_back(response_dataset(r), tmp_path, "response")
    assert ds.frequency.attrs["units"] == "rad/s" and ds.spin_speed.attrs["units"] == "rad/s"
    np.testing.assert_array_equal(ds.frequency.values, omegas)
    np.testing.assert_array_equal(ds.spin_speed.values, spins)
    assert ds.spin_speed.dims == ("frequency",)
    assert list(ds.case.values) == [1]
    assert ds.shaft_w_imag.dims == ("case", "frequency", "x_shaft")
    np.testing.assert_allclose(ds.shaft_w_imag.values[0, 1], -3 * A * np.cos(PHI), rtol=1e-14)
    np.testing.assert_allclose(ds.shaft_v_imag.values[0, 0], A * np.sin(PHI), rtol=1e-14)
    np.testing.assert_allclose(ds.boom_v_real.values[0, 1], 3 * B_V, rtol=1e-14)


def test_strength_file_names_the_worst_station_and_ply(tmp_path):
    along = np.array([2.5, 1.75, 3.0])  # the minimum 1.75 at the middle station, 0.5 m
    s = StrengthResult(
        safety_factor=1.75,
        x=0.5,
        element=1,
        ply=2,  # the third ply from the inside: ply 3 of a 1-based table
        ply_angle_deg=45.0,
        phase_deg=90.0,
        bending_sign=1,
        dominant_stress="sigma1",
        stresses=(1e8, 0.0, 0.0),
        x_along=SHAFT_X,
        along_shaft=along,
        load_shares={"torque": 0.75, "bending": 0.25},
    )
    ds = read_back(strength_dataset(s), tmp_path, "strength")
    assert ds.station.attrs["units"] == "m"
    np.testing.assert_array_equal(ds.station.values, SHAFT_X)
    np.testing.assert_array_equal(ds.safety_factor_along.values, along)
    assert ds.attrs["safety_factor"] == 1.75 and ds.attrs["critical_station_m"] == 0.5
    # the attribute's station is the one where the stored curve is smallest
    assert float(ds.station[int(np.argmin(ds.safety_factor_along.values))]) == ds.attrs["critical_station_m"]
    assert ds.attrs["critical_ply"] == 3 and ds.attrs["critical_ply_angle_deg"] == 45.0
    assert ds.attrs["failure_index_share_torque"] == 0.75


def test_plain_arrays_written_and_selected_as_labelled(tmp_path, monkeypatch):
    """The study-result path: plain labelled arrays selected by nearest speed and written by
    scipy's netCDF3 writer, read back by xarray with its default decoding."""
    speeds = np.array([0.0, 100.0, 300.0])  # rad/s
    freq = np.array([[WD, 2 * WN]] * 3) / (2 * np.pi)  # Hz; an exact zero lies in the speeds
    orbit = np.array([0.0, 1e-3, 2e-3])  # m: zero at rest
    arrays = new_arrays(
        {
            "frequency": (("speed", "mode"), freq, {"units": "Hz", "long_name": "damped natural frequency"}),
            "orbit": ("speed", orbit, {"units": "m", "long_name": "orbit radius"}),
        },
        {
            "speed": ("speed", speeds, {"units": "rad/s"}),
            "speed_rpm": ("speed", speeds * 60 / (2 * np.pi), {"units": "rpm"}),
            "mode": ("mode", np.array([1, 2]), {"long_name": "mode number"}),
        },
        "hand-made curves",
        operating_speed=WN,  # rad/s, not representable in float32
    )
    picked = arrays.sel(speed=110.0, mode=2)  # nearest: 100 rad/s, mode 2
    assert float(picked["frequency"]) == pytest.approx(WN / np.pi, rel=1e-14)
    assert float(picked["orbit"]) == 1e-3
    assert picked["frequency"].attrs["units"] == "Hz" and picked["orbit"].attrs["units"] == "m"
    assert float(arrays["orbit"].sel(speed=160.0)) == 1e-3  # 160 is nearer 100 than 300
    assert float(arrays["orbit"].sel(speed=210.0)) == 2e-3

    monkeypatch.setattr(nc, "_netcdf4_available", lambda: False)  # the scipy netCDF3 path
    path = write_labelled_netcdf(arrays, tmp_path / "curves.nc")
    with xr.open_dataset(path) as back:
        back = back.load()
    np.testing.assert_array_equal(back.orbit.values, orbit)  # the zero at rest is a value, not missing
    np.testing.assert_array_equal(back.speed.values, speeds)
    assert set(back.coords) == {"speed", "speed_rpm", "mode"} and back.speed_rpm.dims == ("speed",)
    np.testing.assert_allclose(back.speed_rpm.values, speeds * 60 / (2 * np.pi), rtol=1e-14)
    assert back.frequency.attrs["units"] == "Hz" and back.speed.attrs["units"] == "rad/s"
    assert back.attrs["operating_speed"] == WN  # float64, exactly
