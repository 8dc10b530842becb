"""An output that cannot apply to the design is said to be so, never a bare NaN.

Was: ``flexshaft montecarlo`` on the embedded current driveline (no active bearing, aluminium
tubes) wrote samples.nc with ``actuator_*_max`` and ``safety_factor`` NaN in every sample and
nothing saying why. Reference: the documented rule that no output file holds a silent NaN
(README, the analyses' results "checked finite"; CF conventions' ``comment`` attribute for the
explanation): every column is either finite in every sample or carries a ``comment`` naming
why it is not applicable. The design is the Jeffcott rotor of tests/rotors.py (a steel tube on
one contact damper: no active bearing, not laminated) spun at 3000 rpm, 10 samples at 2
speeds (the smallest run the command allows).
"""

from __future__ import annotations

import numpy as np
from rotors import jeffcott_text

from flexshaft.design import loads_design
from flexshaft.montecarlo.steady import run_montecarlo
from flexshaft.sweep import Study, Variable, run_sweep


def test_outputs_that_cannot_apply_carry_their_reason_and_the_rest_are_finite() -> None:
    design = loads_design(jeffcott_text(0.01, 50.0).replace("speed_rpm = 0.0", "speed_rpm = 3000.0"))
    ds = run_montecarlo(design, 10, grade_mm_s=6.3, n_speeds=2).dataset
    for name, variable in ds.data_vars.items():
        values = np.asarray(variable.values, dtype=float)
        if str(name).startswith("actuator_"):
            assert np.isnan(values).all() and "no active bearing" in variable.attrs["comment"], name
        elif name == "safety_factor":
            assert np.isnan(values).all() and "not laminated" in variable.attrs["comment"]
        else:
            assert np.isfinite(values).all() and "comment" not in variable.attrs, name
    assert np.all(ds["shaft_peak"].values > 0)


def _half_defined(point) -> dict:
    """``x`` where a > 2 (the closed form: NaN at a = 1 and 2), ``y`` everywhere."""
    a = point.axes["a"]
    return {"x": a if a > 2 else float("nan"), "y": 2.0 * a}


def test_a_sweep_output_with_nan_points_counts_them_in_its_comment(tmp_path) -> None:
    """Was: `flexshaft study wall` on the current (aluminium) driveline wrote results.nc with
    its three Tsai-Wu factors and the spin-up peak NaN at every wall and nothing saying why.
    Every sweep output with NaN points now says how many and what they stand for."""
    import xarray as xr

    study = Study("half", [Variable("a", [1.0, 2.0, 3.0, 4.0])], ["x", "y"], _half_defined)
    ds = run_sweep(study, tmp_path / "run", progress=False)
    on_disk = xr.load_dataset(tmp_path / "run" / "results.nc")
    for result in (ds, on_disk):
        assert result["x"].attrs["comment"].startswith("NaN at 2 of 4 points: the output does not apply")
        assert "comment" not in result["y"].attrs
        np.testing.assert_array_equal(result["y"].values, [2.0, 4.0, 6.0, 8.0])
