"""The comparison's requirement units follow each check's physical kind, and both designs are
assessed on the grids the comparison asks for (:mod:`flexshaft.comparison`).

References, written by hand here:

* units: a check's ``kind`` is its physical quantity (:class:`flexshaft.verdict.result.Check`:
  "Physical kind of value, limit and margin"). The SI unit of a speed is the radian per
  second, of a length the metre, of a temperature the kelvin, and a ratio of two like
  quantities (a safety factor) is dimensionless, written "1" as in every other unit
  attribute of the dataset (``part_count``'s "1"). So the dataset's ``check_units`` of a whirl
  onset (kind speed) is "rad/s", of a spin-up peak orbit (kind length) "m", of a shaft
  temperature (kind temperature) "K" and of a Tsai-Wu safety factor (kind ratio) "1". (The
  temperature check's key, "temperature", is also a kind's name, so that row cannot tell a
  unit looked up by key from one looked up by kind; the speed and length rows can.) Strings:
  exact equality.
* grids: :func:`flexshaft.comparison.compare` documents ``resolution`` as the "Grids of each
  assessment", and docs/architecture.md:63-69 defines a ``Resolution`` as the holder of
  "every grid size and range of the recipe". A comparison asked for at SCREENING must
  therefore hand SCREENING, not the default REPORT, to the assessment of each of its two
  designs: two different columns of one table judged on the coarse grids asked for. The
  assessment itself is replaced by a recorder returning a hand-made run (the grids it would
  use are :mod:`flexshaft.resolution`'s, checked in tests/test_resolution_density_reference.py),
  so no analysis runs.

CPU: milliseconds (two embedded designs read, no analysis).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

import flexshaft.comparison as comparison_module
from flexshaft.comparison import PART_KINDS, Comparison, Inventory, compare
from flexshaft.design import embedded_design
from flexshaft.resolution import REPORT, SCREENING
from flexshaft.verdict.result import Check, Verdict

pytest.importorskip("xarray")

CHECKS = (
    Check("tsai_wu", "Tsai-Wu", "ratio", "at least", "pass", 2.5, 2.0, 0.5),
    Check("whirl_onset", "whirl onset", "speed", "at least", "pass", 600.0, 500.0, 100.0),
    Check("spinup_deflection", "spin-up orbit", "length", "at most", "pass", 1e-4, 5e-4, 4e-4),
    Check("temperature", "shaft temperature", "temperature", "at most", "pass", 330.0, 350.0, 20.0),
)
EXPECTED_UNITS = {"tsai_wu": "1", "whirl_onset": "rad/s", "spinup_deflection": "m", "temperature": "K"}


def _run(name, checks=CHECKS, design=None, resolution=None):
    values = {"v": np.zeros(2), "w": np.zeros(2)}
    return SimpleNamespace(
        verdict=Verdict(checks),
        model=SimpleNamespace(
            speed=100.0,
            shaft_mass=1.0,
            dofs=SimpleNamespace(values=lambda q, part, field: values[field]),
            design=design if design is not None else SimpleNamespace(name=name),
        ),
        resolution=resolution if resolution is not None else SimpleNamespace(scan_top=2.0),
        static_displacement=np.zeros(2),
        thermal=SimpleNamespace(tailboom={"hover": SimpleNamespace(temperature=300.0)}),
    )


def test_each_requirement_carries_the_si_unit_of_its_physical_kind():
    """check_units: rad/s for the onset speed, m for the orbit, K, and 1 for a safety factor."""
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    result = Comparison(labels=("a", "b"), runs=(_run("A"), _run("B")), inventories=(inventory, inventory))
    ds = result.to_dataset()
    units = dict(zip((str(k) for k in ds["check"].values), (str(u) for u in ds["check_units"].values), strict=True))
    assert units == EXPECTED_UNITS


def test_both_designs_are_assessed_at_the_resolution_the_comparison_asks_for(monkeypatch):
    """compare(resolution=SCREENING) assesses each design at SCREENING, not at REPORT."""
    asked = []

    def recorder(design, resolution=REPORT, *, executor=None, progress=None):
        asked.append((design.name, resolution))
        return _run(design.name, design=design, resolution=resolution)

    monkeypatch.setattr(comparison_module, "assess", recorder)
    designs = (embedded_design("tuned"), embedded_design("current"))
    compare(designs[0], designs[1], resolution=SCREENING)
    assert [name for name, _ in asked] == [d.name for d in designs]
    assert all(resolution is SCREENING for _, resolution in asked)
