"""A comparison of two designs that run at different speeds, on hand-built verdicts, and the
tailboom temperatures it reports (:mod:`flexshaft.comparison`).

Each design's critical speeds are placed against *its own* operating speed. Design A runs at
Ω_A = 500 rad/s, design B at Ω_B = 300 rad/s, and both have criticals at 200 and 400 rad/s. By
hand: A's nearest critical below is 400 and it has none above; B's nearest below is 200 and
its nearest above is 400. The separation margin of a critical (API 684, the fraction of the
operating speed) is |ω_c − Ω|/Ω: B's 400 rad/s critical is |400 − 300|/300 = 1/3 from its
operating speed, whatever the required margin (0.15 here) it is compared with.

The tailboom's skin temperature in the comparison is in kelvin. Reference, derived: the skin's
steady balance (absorbed sun = net radiation to the sky + convection to the air) has the residual
f(T) = α G s − ε σ (T⁴ − T_sky⁴) − h (T − T_amb), falling with T, with G = S_c f cos θ_s (thesis
eq. 2.58) and s the sunlit share of the skin. At T = T_amb it is positive on the default
environment (written out below: about 900 W/m² absorbed against about 80 W/m² radiated to a
285 K sky), so the skin is warmer than the ambient air, T > T_amb ≈ 299 K, and less than 150 K
warmer (the thesis's parked boom is at 89 °C). A value in °C (tens of degrees) cannot pass.

Exact selections and one division (rel 1e-15). CPU: a few milliseconds for the verdicts and
one tailboom balance.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.comparison import PART_KINDS, Comparison, Inventory, _boom_temperatures
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperatures
from flexshaft.verdict.result import Check, Finding, Verdict

REQUIRED = 0.15


def _run(speed: float):
    criticals = []
    for critical in (200.0, 400.0):
        sm = abs(critical - speed) / speed
        criticals.append(Finding(sm, REQUIRED, sm - REQUIRED, {"speed": critical, "amplification_factor": 3.0}))
    worst = min(criticals, key=lambda f: f.margin)
    check = Check(
        "separation", "separation", "fraction", "at least", "pass", worst.value, REQUIRED, worst.margin,
        findings=tuple(criticals),
    )  # fmt: skip
    return SimpleNamespace(
        verdict=Verdict((check,)),
        model=SimpleNamespace(speed=speed, dofs=SimpleNamespace(values=lambda q, part, field: np.zeros(3))),
        resolution=SimpleNamespace(scan_top=2.0),
        static_displacement=np.zeros(3),  # the static deflection metric reads it (not compared here)
    )


@pytest.fixture(scope="module")
def comparison():
    inventory = Inventory(dict.fromkeys(PART_KINDS, 1.0), dict.fromkeys(PART_KINDS, 1))
    return Comparison(labels=("a", "b"), runs=(_run(500.0), _run(300.0)), inventories=(inventory, inventory))


def test_each_designs_criticals_are_placed_against_its_own_operating_speed(comparison):
    metrics = {m.key: m for m in comparison.metrics()}
    assert metrics["critical_below"].values == (400.0, 200.0)
    assert metrics["critical_above"].values == (None, 400.0)


def test_a_criticals_margin_is_its_separation_from_the_operating_speed(comparison):
    found = {c["speed"]: c for c in comparison.critical_speeds(1)}
    assert found[400.0]["margin"] == pytest.approx(1.0 / 3.0, rel=1e-15)
    assert found[200.0]["margin"] == pytest.approx(1.0 / 3.0, rel=1e-15)
    assert found[400.0]["required"] == REQUIRED
    found = {c["speed"]: c for c in comparison.critical_speeds(0)}
    assert found[200.0]["margin"] == pytest.approx(0.6, rel=1e-15)  # |200 − 500| / 500


def test_the_tailboom_temperatures_are_kelvin_above_the_ambient_air():
    design = fs.baseline_design()
    options = thermal_options(design.thermal)
    env = options.environment
    # the balance's residual at the ambient temperature is positive (module docstring)
    sigma = 5.670374419e-8
    alpha = env.emissivity if env.solar_absorptivity is None else env.solar_absorptivity
    irradiation = env.solar_constant * env.solar_fraction * math.cos(env.solar_zenith)  # thesis eq. 2.58
    absorbed = alpha * irradiation * env.solar_area_fraction
    radiated = env.emissivity * sigma * (env.ambient_temperature**4 - env.sky_temperature**4)
    assert absorbed > 5 * radiated > 0.0
    booms = tailboom_temperatures(boom_equivalent_diameter(design.tailboom), env, options.boom_convection)
    run = SimpleNamespace(thermal=SimpleNamespace(tailboom=booms))
    found = _boom_temperatures(design, run)
    assert set(found) == {"hover", "parked"}
    for value in found.values():
        assert env.ambient_temperature < value < env.ambient_temperature + 150.0


def test_a_tailboom_temperature_computed_for_the_comparison_is_kelvin_too():
    """A run without a thermal result: the comparison computes the boom's balance itself (the
    same kelvin band as above, from the same residual)."""
    design = fs.baseline_design()
    ambient = thermal_options(design.thermal).environment.ambient_temperature
    found = _boom_temperatures(design, SimpleNamespace(thermal=None))
    assert set(found) == {"hover", "parked"}
    for value in found.values():
        assert ambient < value < ambient + 150.0
