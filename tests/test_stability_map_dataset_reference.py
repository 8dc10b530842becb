"""The whirl-stability map's labelled arrays and the stacking of maps, against hand-built maps.

References (documented rules, no number of flexshaft):

* :func:`~flexshaft.thesis.whirl.stability_dataset` labels the map's onset speed [rad/s] as
  ``onset_speed`` and its smallest damping ratio at the operating speed [1] as
  ``damping_ratio`` (the dataset's own units: rad/s and 1), on the map's K_p and K_d;
* :func:`~flexshaft.thesis.whirl.stack_maps` stacks maps "over the same K_d values and speeds":
  rows over other K_d values of the same count cannot share one K_d axis and are refused.

Exact comparisons: the values are copied, never computed.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.thesis.whirl import StabilityMap, stability_dataset, stack_maps


def _map(kd=(0.0, 1e3)) -> StabilityMap:
    onset = np.array([[350.0, np.nan], [420.0, 610.0]])
    ratio = np.array([[0.012, 0.034], [-0.002, 0.051]])
    return StabilityMap(np.array([3e5, 2e6]), np.array(kd), onset, ratio, 900.0)


def test_dataset_keeps_onset_and_damping_ratio_apart():
    smap = _map()
    ds = stability_dataset(smap)
    np.testing.assert_array_equal(ds["damping_ratio"].values, smap.margin_at_operating)
    np.testing.assert_array_equal(ds["onset_speed"].values, smap.onset_speed)
    np.testing.assert_array_equal(ds["kp"].values, smap.kp)
    np.testing.assert_array_equal(ds["kd"].values, smap.kd)


def test_stacking_refuses_maps_over_other_kd_values():
    with pytest.raises(ValueError, match="K_d"):
        stack_maps([_map((0.0, 1e3)), _map((0.0, 2e3))])
