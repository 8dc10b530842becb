"""Campbell diagram at the limits of a request: as many tracked modes as the basis has, and a
crossing between rest and the first spinning sample of a curve that stops being lateral.

Mode count (reference derived here, on the overhung disk of tests/test_overhung_disk_whirl.py):
a plain modal basis of ``n`` undamped modes at rest spans exactly those modes, so the reduced
problem has exactly ``n`` oscillatory roots at rest (no rigid-body mode: the shaft is clamped),
and they are the basis modes' own frequencies. For ``n = 3`` these are the disk's first bending
pair (the two planes alike at rest) and the first torsion mode. The pair's frequency is the
lower positive root ω of the massless-cantilever closed form (k11 − m ω²)(k22 − I_d ω²) − k12² = 0
(``closed_form(0, +1)[0]`` of that file, 195.887 rad/s). Tracking all three is a valid request
(the guard refuses only *fewer* modes than asked for); four of a three-mode basis are refused.
Tolerance 5e-5 relative: the tube's mass is 1e-6 of the disk's, so the FE frequency agrees
with the massless closed form to a few 1e-6 (the same bound as test_overhung_disk_whirl.py).

Rest crossing (reference: docs/model.md, "only lateral modes make 1× critical speeds" and the
whirl is "none" only for the other kinds, so a critical speed of a lateral curve never carries
"none"; derived here for the sample data): a critical speed is the crossing of a lateral curve
with ω = kΩ, linearly interpolated, g(Ω) = Im s(Ω) − kΩ, t = g₀/(g₀ − g₁). On a curve lateral at
rest and torsional at the first spinning sample (a kind change) the only lateral sample of the
interval is rest, labelled "planar": the crossing keeps that whirl. (The critical_speeds
docstring says a crossing below the first spinning sample takes that sample's whirl, with no
condition on its kind; the code steps up only to a lateral sample, which is what the rule
above needs.) Data:
Im s = 50, 60 rad/s at Ω = 0, 100 rad/s, k = 1: g = 50, −40, t = 5/9, Ω_c = 500/9 rad/s; the
interpolation is exact up to one rounding of a few operations (1e-12 relative asserted).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_campbell_rest_labels import _model
from test_overhung_disk_whirl import closed_form

from flexshaft.analyses.campbell import campbell, critical_speeds
from flexshaft.analyses.guards import RefusedInputError


def test_as_many_tracked_modes_as_the_basis_has_is_a_valid_request():
    model = _model(0.0)
    diagram = campbell(model, [0.0, 500.0], n_modes=3, basis_size=3, damped=False)
    lateral = diagram.kind[0] == "lateral"
    assert lateral.sum() == 2
    first = closed_form(0.0, +1)[0]
    assert diagram.eigenvalues[0, lateral].imag == pytest.approx([first, first], rel=5e-5)
    with pytest.raises(RefusedInputError):  # more than the three the basis has
        campbell(model, [0.0, 500.0], n_modes=4, basis_size=3, damped=False)


def test_rest_crossing_of_a_curve_leaving_the_lateral_kind_keeps_its_lateral_whirl():
    speeds = np.array([0.0, 100.0])
    eigenvalues = np.array([[50.0j], [60.0j]])
    kind = np.array([["lateral"], ["torsional"]])
    whirl = np.array([["planar"], ["none"]])
    (crossing,) = critical_speeds(speeds, eigenvalues, whirl, kind)
    assert crossing.speed == pytest.approx(500.0 / 9.0, rel=1e-12)
    assert crossing.mode == 0
    assert crossing.whirl != "none"
    assert crossing.whirl == "planar"
