"""The comparison's mass breakdown and its dataset, on hand-built drivelines and verdicts.

* :func:`driveline_inventory` of a driveline written here: a 12.5 kg tube in three segments
  (two couplings of 0.8 kg and 0 kg), a 1.4 kg hanger, a 2.1 kg damper, two 7.0 kg actuators
  and a gearbox bearing of 9 kg that ends the driveline (not a part; module docstring). By hand:
  total 12.5 + 0.8 + 1.4 + 2.1 + 14.0 = 30.8 kg, 3 + 2 + 1 + 1 + 2 = 9 parts; the massless
  coupling is the only part listed as "mass not given".
* :meth:`Comparison.to_dataset` stores each check's value, limit and margin where their names
  say (a Tsai-Wu factor of 2.5 against 2.0: margin 0.5; a temperature of 350 K against at most
  400 K: margin 50 K).

Fake assessments (plain namespaces holding a :class:`~flexshaft.verdict.result.Verdict`, as in
tests/test_compare_metrics_reference.py); the sums are exact to a few 1e-16 (rel 1e-14).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from flexshaft.comparison import PART_KINDS, Comparison, Inventory, driveline_inventory
from flexshaft.verdict.result import Check, Verdict

pytest.importorskip("xarray")


def _bearing(name, kind, role, mass):
    return SimpleNamespace(name=name, kind=kind, role=role, mass=mass)


@pytest.fixture(scope="module")
def inventory():
    design = SimpleNamespace(
        couplings=[SimpleNamespace(name="c1", mass=0.8), SimpleNamespace(name="c2", mass=0.0)],
        bearings=[
            _bearing("gearbox", "contact", "gearbox", 9.0),
            _bearing("hanger", "contact", "hanger", 1.4),
            _bearing("damper", "contact", "damper", 2.1),
            _bearing("amb_1", "active", "hanger", 7.0),
            _bearing("amb_2", "active", "hanger", 7.0),
        ],
    )
    return driveline_inventory(SimpleNamespace(design=design, shaft_mass=12.5))


def test_the_breakdown_by_kind_and_its_total(inventory):
    assert inventory.mass == {"segments": 12.5, "couplings": 0.8, "hangers": 1.4, "dampers": 2.1, "actuators": 14.0}
    assert inventory.count == {"segments": 3, "couplings": 2, "hangers": 1, "dampers": 1, "actuators": 2}
    assert inventory.total_mass == pytest.approx(30.8, rel=1e-14)
    assert inventory.total_count == 9
    assert inventory.mass_not_given == ("coupling c2",)


def _run(name, checks):
    values = {"v": np.zeros(2), "w": np.zeros(2)}
    return SimpleNamespace(
        verdict=Verdict(tuple(checks)),
        model=SimpleNamespace(
            speed=100.0,
            dofs=SimpleNamespace(values=lambda q, part, field: values[field]),
            design=SimpleNamespace(name=name),
        ),
        resolution=SimpleNamespace(scan_top=2.0),
        static_displacement=np.zeros(2),
    )


def test_the_dataset_keeps_value_limit_and_margin_apart():
    tsai_wu = Check("tsai_wu", "Tsai-Wu", "ratio", "at least", "pass", 2.5, 2.0, 0.5)
    hot = Check("temperature", "temperature", "temperature", "at most", "pass", 350.0, 400.0, 50.0)
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    comparison = Comparison(
        labels=("a", "b"), runs=(_run("A", [tsai_wu, hot]), _run("B", [tsai_wu])), inventories=(inventory, inventory)
    )
    ds = comparison.to_dataset()
    a = ds.sel(design="a")
    assert float(a.check_value.sel(check="tsai_wu")) == 2.5
    assert float(a.check_limit.sel(check="tsai_wu")) == 2.0
    assert float(a.check_margin.sel(check="tsai_wu")) == 0.5
    assert float(a.check_limit.sel(check="temperature")) == 400.0
    assert float(a.check_margin.sel(check="temperature")) == 50.0
    assert np.isnan(float(ds.sel(design="b").check_margin.sel(check="temperature")))  # not listed
