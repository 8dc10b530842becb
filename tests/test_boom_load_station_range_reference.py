"""A boom load's station is checked against the tailboom [0, length], not the shaft's range.

Reference: the documented rule of docs/limits.md section 2 (checks of several numbers), "every
bearing, disk, sensor and load on its member": a ``[[loads.point]]`` with ``on = "boom"``
acts at boom station ``x``, which must lie on the tailboom [0, length]; where the shaft
[x_start, x_end] is shorter or longer than the boom, the shaft's range says nothing about it.

* **A boom longer than the shaft** (2.5 m against the shaft's [0, 2] m): a boom point load at
  x = 2.3 m is on its member and the design loads. Its physics is then checked too: the
  design's static load (``external_static_load``, the point loads with no load factor) carries
  the force on the boom's DOFs with resultant F and first moment F x about x = 0
  (Σ x_i Q_v,i + Σ Q_γ,i, derived here from the Hermite shape functions, which reproduce a
  rigid translation and rotation exactly), and nothing on the shaft.
* **A boom shorter than the shaft** (1.5 m against [0, 2] m): a boom point load at x = 1.8 m
  lies beyond the boom's tip, though inside the shaft's range; it is refused at
  ``loads.point[0].x``, and x = 1.4 m on the same design loads.

Tolerances: the resultants are sums of a few nodal values of order 1e2-1e3 N, exact up to
rounding: 1e-12 relative.

Written for the mutation h64f-schema-boom-load-checked-on-shaft of scripts/mutations.toml.
"""

from __future__ import annotations

import numpy as np
import pytest
from boomed_rotor import shaft_and_boom

from flexshaft.assembly import build_model
from flexshaft.assembly.loads import external_static_load
from flexshaft.design import DesignError, loads_design

F_Y = -400.0  # N along y


def _design(boom_length: float, load_x: float) -> str:
    """Shaft [0, 2] m on two hangers whose boom stations lie on a boom of ``boom_length``."""
    return f"""
name = "a boom point load"
{shaft_and_boom(boom_length)}[[bearings]]
name = "fore"
kind = "contact"
x = 0.6
x_boom = 0.5
stiffness = {{ v = 1e7, w = 1e7 }}
[[bearings]]
name = "aft"
kind = "contact"
x = 1.9
x_boom = 1.2
stiffness = {{ v = 1e7, w = 1e7 }}
[operating]
speed_rpm = 3000.0
power = 0.0
[loads]
eccentricity = 0.0
[[loads.point]]
name = "boom load"
on = "boom"
x = {load_x}
force = [0.0, {F_Y}, 0.0]
[mesh]
shaft_elements = 4
boom_elements = 3
"""


def test_boom_load_beyond_the_shaft_but_on_the_boom_is_accepted_and_loads_the_boom() -> None:
    x = 2.3  # beyond the shaft's x_end = 2.0, on the 2.5 m boom
    model = build_model(loads_design(_design(2.5, x)))
    dm = model.dofs
    Q = external_static_load(model)
    boom = np.arange(dm.n_boom_nodes)
    qv, qg = Q[dm.boom(boom, "v")], Q[dm.boom(boom, "gamma")]
    assert qv.sum() == pytest.approx(F_Y, rel=1e-12)
    assert (dm.boom_x * qv).sum() + qg.sum() == pytest.approx(F_Y * x, rel=1e-12)
    assert np.abs(Q[dm.shaft(np.arange(dm.n_shaft_nodes), "v")]).max() == 0.0


def test_boom_load_beyond_the_boom_tip_is_refused_though_on_the_shaft() -> None:
    with pytest.raises(DesignError) as caught:
        loads_design(_design(1.5, 1.8))  # the shaft reaches 2.0 m, the boom only 1.5 m
    assert any(line.startswith("loads.point[0].x:") for line in str(caught.value).splitlines()), str(caught.value)
    loads_design(_design(1.5, 1.4))  # on the boom: loads
