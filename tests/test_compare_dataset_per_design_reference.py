"""Each design's numbers stay under its own label and kind in the comparison's metrics and
dataset (:mod:`flexshaft.comparison`).

References, written by hand here:

* part masses: design A's inventory is 10, 2, 3, 4, 5 kg and design B's 20, 1, 6, 7, 8 kg of
  segments, couplings, hangers, dampers and actuators (every kind of a design a different mass,
  so a mislabelled kind cannot match; the ends, not the middle kind, tell a reversed order).
  The dataset's ``part_mass`` of design "a", kind "segments" is
  10 kg, of "a", "actuators" 5 kg; the hand sums of the totals are 10 + 2 + 3 + 4 + 5 = 24 kg
  (A) and 20 + 1 + 6 + 7 + 8 = 42 kg (B), and the ``metric_value`` of ``mass_total`` is 24 kg
  for "a" and 42 kg for "b" (not the other design's).
* tailboom temperatures: the parked skin is hotter than the hovering one. Derived here: both
  solve α G s = ε σ (T⁴ − T_sky⁴) + h (T − T_amb) with the same sun and sky (module docstring of
  :mod:`flexshaft.thermal.tailboom`); at the hover root the parked residual is
  (h_hover − h_parked)(T_hover − T_amb), positive when h_parked < h_hover and T_hover > T_amb
  (both asserted), and h of
  free convection (parked, a few W/m²K) is well below that of the rotor downwash's forced
  convection (hover, tens of W/m²K), so the parked root is the higher one (the thesis's parked
  boom is at 89 °C). On hand values (hover 317 K, parked 362 K) the metric of each condition
  is its own value.

The selections are exact copies of the given numbers (no arithmetic) and the sums are of a
few small integers, exact in binary; equality is then exact. CPU: a few milliseconds and
one tailboom balance.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.comparison import PART_KINDS, Comparison, Inventory, _boom_temperatures
from flexshaft.thermal.options import environment_from
from flexshaft.verdict.result import Check, Verdict

pytest.importorskip("xarray")


def _run(name):
    values = {"v": np.zeros(2), "w": np.zeros(2)}
    check = Check("tsai_wu", "Tsai-Wu", "ratio", "at least", "pass", 2.5, 2.0, 0.5)
    return SimpleNamespace(
        verdict=Verdict((check,)),
        model=SimpleNamespace(
            speed=100.0,
            dofs=SimpleNamespace(values=lambda q, part, field: values[field]),
            design=SimpleNamespace(name=name),
        ),
        resolution=SimpleNamespace(scan_top=2.0),
        static_displacement=np.zeros(2),
    )


def _comparison(boom_temperatures=({}, {})) -> Comparison:
    mass_a = dict(zip(PART_KINDS, (10.0, 2.0, 3.0, 4.0, 5.0), strict=True))
    mass_b = dict(zip(PART_KINDS, (20.0, 1.0, 6.0, 7.0, 8.0), strict=True))
    return Comparison(
        labels=("a", "b"),
        runs=(_run("A"), _run("B")),
        inventories=(Inventory(mass_a, dict.fromkeys(PART_KINDS, 1)), Inventory(mass_b, dict.fromkeys(PART_KINDS, 1))),
        boom_temperatures=boom_temperatures,
    )


def test_the_dataset_part_mass_is_stored_under_its_kind():
    """Each design's hand-given mass of each kind under that kind (module docstring)."""
    ds = _comparison().to_dataset()
    assert float(ds.part_mass.sel(design="a", part_kind="segments")) == 10.0
    assert float(ds.part_mass.sel(design="a", part_kind="couplings")) == 2.0
    assert float(ds.part_mass.sel(design="a", part_kind="actuators")) == 5.0
    assert float(ds.part_mass.sel(design="b", part_kind="segments")) == 20.0
    assert float(ds.part_mass.sel(design="b", part_kind="actuators")) == 8.0


def test_the_dataset_metric_values_belong_to_their_design():
    """The hand sums of each design's masses under that design (module docstring)."""
    ds = _comparison().to_dataset()
    assert float(ds.metric_value.sel(design="a", metric="mass_total")) == 24.0  # 10 + 2 + 3 + 4 + 5
    assert float(ds.metric_value.sel(design="b", metric="mass_total")) == 42.0  # 20 + 1 + 6 + 7 + 8
    assert float(ds.metric_value.sel(design="b", metric="mass_segments")) == 20.0


def test_each_tailboom_condition_reports_its_own_temperature():
    """Hand-given hover and parked temperatures each under its own metric."""
    hand = {"hover": 317.0, "parked": 362.0}
    metrics = {m.key: m for m in _comparison((hand, {})).metrics()}
    assert metrics["boom_temperature_hover"].values == (317.0, None)
    assert metrics["boom_temperature_parked"].values == (362.0, None)


def test_the_parked_tailboom_is_hotter_than_the_hovering_one():
    """The real balance of the baseline's boom (module docstring: free convection parked, forced
    under the downwash in hover); the compared metrics keep that order."""
    design = fs.baseline_design()
    booms = _boom_temperatures(design, SimpleNamespace(thermal=None))
    ambient = environment_from(design.thermal).ambient_temperature
    metrics = {m.key: m for m in _comparison((booms, booms)).metrics()}
    for design in (0, 1):
        hover = metrics["boom_temperature_hover"].values[design]
        parked = metrics["boom_temperature_parked"].values[design]
        assert hover is not None and parked is not None
        assert hover > ambient  # the derivation's premise: the sun heats the hovering boom too
        assert parked > hover
