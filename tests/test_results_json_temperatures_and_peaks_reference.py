"""``results.json``'s tailboom temperatures, the shaft's dissipated heat and the actuators' spin-up
peaks, against the documented key rules and the assessment's SI results.

References: README ("Interfaces", ``--json``): absolute temperatures in °C under ``_c`` keys, so a
boom skin temperature T [K] appears as T − 273.15 (the Celsius scale's definition); a ``_W`` key
is a power, and the shaft's heat is the power dissipated over the whole shaft: docs/thermal.md,
"Shaft heat generation", P = (ω/2) Re(Xᴴ K'' X) per element, summed over the elements;
``actuator_max_*`` are the
largest values over the spin-up scan (the key's name: the maximum, not the value at the
operating speed). The design is the tests' small run design (conftest.RUN_DESIGN: the Table 3.1
baseline on 4 shaft and 2 boom elements, two magnetic bearings) judged at its own operating
point on tiny grids with the report's detail (three spin-up speeds besides the operating one, a
four-speed Campbell diagram, the thermal results): about 0.3 s of CPU. Each key is one copy,
sum or unit shift of analysis numbers of order 1-1e4, so the tolerance is round-off: rel 1e-12
(a sum of a few positive terms loses no more than a few ulps).
"""

from __future__ import annotations

import numpy as np
import pytest

# the run design on tiny grids with the report's detail, assessed once per module, and its
# results.json (the thermal study and its tailboom temperatures included)
from test_results_json_reference import run  # noqa: F401 (pytest fixture)


def test_tailboom_temperatures_in_celsius(run):  # noqa: F811
    """``thermal.tailboom_c``: each condition's boom skin temperature T [K] as T − 273.15 °C; the
    hover and parked skins are above 0 °C on the design's hot day, so kelvin would read 273 too
    high."""
    a, data = run
    boom = a.thermal.tailboom
    assert set(boom) == {"hover", "parked"}
    written = data["thermal"]["tailboom_c"]
    assert set(written) == set(boom)
    for condition, result in boom.items():
        assert written[condition] == pytest.approx(result.temperature - 273.15, rel=1e-12)
        assert 0.0 < written[condition] < 150.0  # a skin temperature in °C, not kelvin


def test_shaft_heat_is_the_power_over_the_whole_shaft(run):  # noqa: F811
    """``thermal.shaft_<model>.heat_W``: the dissipated power of the whole shaft, the sum of the
    elements' powers P = (ω/2) Re(Xᴴ K'' X); several elements carry heat, so one element's heat
    (the largest) is less than the total."""
    a, data = run
    assert a.thermal.shaft
    for model, s in a.thermal.shaft.items():
        heats = np.asarray(s.sources.total, dtype=float)
        total = float(np.sum(heats))
        assert data["thermal"][f"shaft_{model}"]["heat_W"] == pytest.approx(total, rel=1e-12)
        assert np.count_nonzero(heats > 0.0) >= 2
        assert float(np.max(heats)) < total * (1.0 - 1e-6)


def test_actuator_peaks_are_the_largest_over_the_scan(run):  # noqa: F811
    """``imbalance.actuator_max_force_N`` / ``actuator_max_displacement_m``: each magnetic
    bearing's largest force [N] and displacement [m] over the spin-up scan's speeds. On this
    design the force is not largest at the operating speed (a critical below the operating speed), so the
    force at the operating sample would read short."""
    a, data = run
    sp, imb = a.spinup, data["imbalance"]
    assert len(sp.actuator_force) == 2
    (at,) = np.flatnonzero(sp.speeds == a.model.speed)  # the operating speed is a sample
    for name, force in sp.actuator_force.items():
        assert imb["actuator_max_force_N"][name] == pytest.approx(max(float(f) for f in force), rel=1e-12)
        assert float(np.max(force)) > float(force[at]) * (1.0 + 1e-6)
    for name, displacement in sp.actuator_displacement.items():
        assert imb["actuator_max_displacement_m"][name] == pytest.approx(max(float(d) for d in displacement), rel=1e-12)
