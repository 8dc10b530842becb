"""A labelled plain array selected twice, a selection method other than nearest, and a
selection by a coordinate that is not a dimension.

References: xarray itself, which the module stands for (flexshaft/analyses/labelled.py:
``LabelledArray.sel`` gives "The values at the coordinate values nearest those given, the
selected dimensions dropped (xarray's ``sel(..., method="nearest")``; no other method)").

* An array selected on one dimension keeps the coordinates of the dimensions it still has, as
  xarray's DataArray does: a second nearest-point selection on one of them picks the same value
  as xarray's (``ds["amplitude"].sel(speed=x).sel(station=y)``, one axis at a time).
* "no other method": ``method=None`` (xarray's exact match, which raises KeyError for a value
  that is not on the axis) must be refused, not treated as nearest.
* A coordinate that is not a dimension (``kp`` over the ``case`` dimension): xarray selects the
  one case at that kp; the plain arrays may refuse it ("no dimension ... among ...",
  flexshaft/analyses/labelled.py), a loud refusal rather than every case returned unselected.

The values compared are picked from the same random array by both libraries: exact equality.
"""

from __future__ import annotations

import pytest
import xarray as xr
from test_labelled import _spec

from flexshaft.analyses.labelled import LabelledArrays


@pytest.mark.parametrize("alpha, beta", [(54.0, 1.0), (20.0, 44.0), (-10.0, 100.0)])
def test_a_selected_array_selects_again_on_its_remaining_axis_as_xarray(alpha, beta):
    data, coords, attrs = _spec()
    arrays, ds = LabelledArrays(data, coords, attrs), xr.Dataset(data, coords=coords, attrs=attrs)
    row = arrays["safety_factor"].sel(alpha=alpha)
    want_row = ds["safety_factor"].sel(alpha=alpha, method="nearest")
    assert row.dims == want_row.dims == ("beta",)
    got = row.sel(beta=beta)
    want = want_row.sel(beta=beta, method="nearest")
    assert got.dims == () and float(got) == float(want)


def test_method_none_is_refused_not_nearest():
    """xarray's method=None is an exact match (KeyError off the axis); the plain arrays support
    only nearest ("no other method") and say so instead of answering another point."""
    data, coords, attrs = _spec()
    arrays, ds = LabelledArrays(data, coords, attrs), xr.Dataset(data, coords=coords, attrs=attrs)
    with pytest.raises(KeyError):
        ds["peak"].sel(alpha=54.0, method=None)
    with pytest.raises(ValueError, match="only 'nearest'"):
        arrays["peak"].sel(alpha=54.0, method=None)
    with pytest.raises(ValueError, match="only 'nearest'"):
        arrays.sel(alpha=54.0, method=None)


def test_a_non_dimension_coordinate_is_selected_as_xarray_or_refused():
    """xarray 2026.9 selects the one case at kp=2e6 (kp a coordinate over the case dimension).
    The plain arrays select on dimensions only and refuse other indexers with KeyError "no
    dimension ... among ..." (flexshaft/analyses/labelled.py, ``LabelledArrays.sel``). That is
    acceptable: a loud refusal, not a wrong answer. What is not: answering with anything but
    xarray's single case (e.g. every case, unselected)."""
    data, coords, attrs = _spec()
    arrays, ds = LabelledArrays(data, coords, attrs), xr.Dataset(data, coords=coords, attrs=attrs)
    want = ds.sel(kp=2e6, method="nearest")
    assert want.sizes.get("case", 1) == 1  # xarray's reference: one case, not both
    try:
        got = arrays.sel(kp=2e6)
    except KeyError:
        return  # refused: the plain arrays select on dimensions only
    assert got.to_dataset().identical(want)
