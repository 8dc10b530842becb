"""Self-heating stops, by default, at the first iterate that changes by less than 1 mK.

Documented rule (docs/thermal.md, "Self-heating equilibrium and runaway"): the Picard iteration
response → heat → FD temperature → properties runs "until max |ΔT| < 1 mK". So, without a ``tol``
given, the returned converged iterate T_k and the one before it, T_(k−1), satisfy
max |T_k − T_(k−1)| < 1e-3 K, and the iterate before that did not: max |T_(k−1) − T_(k−2)| ≥ 1e-3 K.

The iterates are read from outside the loop: the iteration is deterministic, so a run stopped
by ``max_iter = j`` (status "not_converged" for j below the converging count) returns exactly
the j-th iterate of the default run, the same operations in the same order.

The case: the baseline design with its imbalance off and its static loads ×100, which warms the
hottest element about 0.2 K above the air (the temperature-dependent moduli then move the
iterates by 0.196 K, 4.5 mK, 0.10 mK, measured). The last change, 1e-4 K, lies a decade below
the 1 mK bound and the one before it, 4.5e-3 K, four times above it, so neither comparison is
near a tie on any BLAS kernel; a 10 mK default would stop one iterate earlier, on the 4.5 mK
change.
"""

from __future__ import annotations

import numpy as np
import pytest

import flexshaft as fs
import flexshaft.thermal.selfheating as selfheating

SCALE = 100.0  # the baseline's static loads x100: a few tenths of a K of self-heating
DOCUMENTED_TOL = 1e-3  # K, docs/thermal.md: "until max |ΔT| < 1 mK"


@pytest.fixture(scope="module")
def model():
    return fs.build_model(fs.baseline_design())


def _iterate(model, j: int) -> np.ndarray:
    """The j-th Picard iterate of the element temperatures (j ≥ 1) [K]."""
    return selfheating.self_heating(
        model, imbalance_scale=0.0, static_scale=SCALE, tol=0.0, max_iter=j
    ).element_temperature


def test_the_default_stops_at_the_first_change_below_one_millikelvin(model):
    result = selfheating.self_heating(model, imbalance_scale=0.0, static_scale=SCALE)
    assert result.status == "converged"
    k = result.iterations
    assert k >= 3  # the case has at least two changes to compare (measured k = 4)
    previous, before = _iterate(model, k - 1), _iterate(model, k - 2)
    assert np.max(np.abs(result.element_temperature - previous)) < DOCUMENTED_TOL
    assert np.max(np.abs(previous - before)) >= DOCUMENTED_TOL
