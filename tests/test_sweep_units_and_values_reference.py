"""What a sweep's results file says about each output and each value swept, against hand laws.

References (worked by hand, not printed by the code):

* a sweep over the special axis ``speed`` Ω = [100, 200] rad/s with two outputs of different
  units, the 1× excitation frequency f = Ω/(2π) in Hz and a stand-in orbit r = Ω · 10⁻⁵ m
  (exact hand laws of the point's own coordinate): each output keeps the unit it was declared
  with (``Output("f1x", "Hz")``, ``Output("orbit", "m")``), as the CF ``units`` attribute, and its
  own values;
* a 1 × 3 grid ``a`` = [1], ``b`` = [10, 20, 30] with f = 100 a + b, run into a folder, then a study
  that differs only in an interior value, ``b`` = [10, 25, 30] (same ends, same count): the
  folder holds another study's points (f = 120 at the middle, where this study's is 125), so
  resuming there must be refused (docs: a folder of another study is never mixed with this one);
* a strength result whose worst point is a quarter turn into the whirl, ``phase_deg`` = 90: the
  file's ``critical_phase_deg`` attribute is 90 (degrees, as its name says; π/2 = 1.5708 in rad).

Tolerances: every value is exact in binary floating point or passes through one division by
2π, compared with rtol 1e-15 (one rounding); labels and units exactly. The file builds no model
(special axes only, the embedded baseline design): well under 1 s of CPU.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.analyses.datasets import strength_dataset
from flexshaft.analyses.shaft_strength import StrengthResult
from flexshaft.sweep import Output, Study, SweepError, Variable, run_sweep

SPEEDS = [100.0, 200.0]  # rad/s


def excitation_and_orbit(point):
    """The 1× excitation frequency of the point's speed (Hz) and a stand-in orbit (m)."""
    omega = point.axes["speed"]
    return {"f1x": omega / (2.0 * math.pi), "orbit": omega * 1e-5}


def hundred_a_plus_b(point):
    return {"f": 100.0 * point.axes["a"] + point.axes["b"]}


def test_each_output_keeps_its_own_unit():
    study = Study(
        "units",
        [Variable("speed", SPEEDS, units="rad/s", long_name="spin speed")],
        [Output("f1x", "Hz", "1x excitation frequency"), Output("orbit", "m", "orbit radius")],
        excitation_and_orbit,
    )
    arrays = run_sweep(study, progress=False, as_arrays=True)
    assert arrays["speed"].attrs["units"] == "rad/s"
    assert arrays["f1x"].attrs["units"] == "Hz"
    assert arrays["orbit"].attrs["units"] == "m"
    np.testing.assert_allclose(arrays["f1x"].values, [100.0 / (2 * math.pi), 200.0 / (2 * math.pi)], rtol=1e-15)
    np.testing.assert_allclose(arrays["orbit"].values, [1e-3, 2e-3], rtol=1e-15)


def _grid(b_values) -> Study:
    return Study("one by three", [Variable("a", [1.0]), Variable("b", b_values)], [Output("f", "1")], hundred_a_plus_b)


def test_folder_of_other_interior_values_is_not_resumed(tmp_path):
    run = tmp_path / "run"
    first = run_sweep(_grid([10.0, 20.0, 30.0]), run, chunk_size=3, progress=False, as_arrays=True)
    np.testing.assert_array_equal(first["f"].values, [[110.0, 120.0, 130.0]])
    # same ends and count, another middle value: the stored 120 is not this study's 125
    with pytest.raises(SweepError, match="different study"):
        run_sweep(_grid([10.0, 25.0, 30.0]), run, chunk_size=3, progress=False)
    fresh = run_sweep(_grid([10.0, 25.0, 30.0]), tmp_path / "fresh", chunk_size=3, progress=False, as_arrays=True)
    np.testing.assert_array_equal(fresh["f"].values, [[110.0, 125.0, 130.0]])


def test_strength_file_gives_the_critical_phase_in_degrees():
    x = np.array([0.0, 0.5, 1.0])  # m
    s = StrengthResult(
        safety_factor=1.5,
        x=0.5,
        element=1,
        ply=0,
        ply_angle_deg=30.0,
        phase_deg=90.0,  # a quarter turn
        bending_sign=1,
        dominant_stress="sigma1",
        stresses=(1e8, 0.0, 0.0),
        x_along=x,
        along_shaft=np.array([2.0, 1.5, 2.0]),
        load_shares={},
    )
    ds = strength_dataset(s)
    assert ds.attrs["critical_phase_deg"] == 90.0
    assert ds.attrs["critical_ply_angle_deg"] == 30.0
