"""Bearing loops on their default grid, shared by tests/test_loop_projection.py and
tests/test_loop_robustness.py (computed once per process: CPU budget, issue 23).

The tuned driveline with real magnets (PID, amplifier and derivative-filter lags, the sensor
4 cm beside each magnet) is the poor-loop case of both files. ``bearing_loops`` given no poles
computes ``closed_loop_poles`` at the operating speed; :func:`case` computes them once per model
and :func:`default_loops` passes them, which is what the default does.
"""

from __future__ import annotations

import functools
from collections.abc import Callable

from flexshaft.analyses.bearing_loops import bearing_loops
from flexshaft.analyses.root_stability import closed_loop_poles
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides

#: The magnets' keys (both active bearings): PID with integral action, amplifier and
#: derivative-filter lags, non-collocated sensor.
PID = {"ks": 8.47e5, "ki": 177.0, "kp": 7610.0, "kd": 3.16, "integral_gain": 4.8e4, "derivative_cutoff": 500.0}
PID.update(amplifier_bandwidth=1000.0, sensor_offset=0.04)


def magnetic_tuned_design():
    """The tuned design with the real magnets of :data:`PID` on both active bearings."""
    return with_overrides(tuned_design(), {f"bearings[{i}].{k}": v for i in (1, 2) for k, v in PID.items()})


@functools.cache
def magnetic_tuned_model():
    """``build_model(magnetic_tuned_design())``, built once (the tests do not modify it)."""
    return build_model(magnetic_tuned_design())


@functools.cache
def case(make: Callable):
    """``make()`` and its default grid's poles (``closed_loop_poles`` at the operating speed)."""
    model = make()
    return model, closed_loop_poles(model, model.speed)


def loops(make: Callable, **options):
    """``bearing_loops(make(), **options)`` on the default grid (the poles computed once); not
    cached: the module's settings may be patched."""
    model, poles = case(make)
    return bearing_loops(model, poles=poles, **options)


@functools.cache
def default_loops(make: Callable, projected: bool = True):
    """:func:`loops` with the module's own settings, computed once: only for tests that patch
    nothing before reading it."""
    return loops(make, projected=projected)
