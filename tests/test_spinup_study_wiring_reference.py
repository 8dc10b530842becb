"""The spin-up study's definitions worked by hand on stand-ins (thesis study 6,
:mod:`flexshaft.thesis.spinup_maps`): no receptance is solved (milliseconds).

References:

* the tuned gains obey the thesis's criterion (§3.3, quoted by
  tests/test_spinup_tuning_selection.py): the quietest pair "staying in the limits of allowable
  shaft displacement at the actuator location". The gap is the largest allowed orbit
  (``actuator_gap`` in :func:`~flexshaft.thesis.design_studies.design_studies`), an "at most"
  limit as every limit of the verdict (tests/test_verdict_boundary.py): a pair whose orbit
  equals the gap (2⁻¹² m, binary exact) is allowed;
* the frequency-response surfaces (thesis figures 3.13, 3.14) are the curves of the gain pairs
  their coordinates name: :func:`~flexshaft.analyses.spinup.spinup_curves` takes a law as a
  ``(kp, kd)`` pair (its docstring), so the pair handed to it is the case's (K_p, K_d);
* the default (K_p, K_d) map spans K_p from 1e5 to 1e8 N/m in 30 gains, and K_d = 0 then 29
  from 10 to 10^4.5 N s/m (the docstring); the map is drawn on logarithmic axes with cells
  centred on the grid values in log10 (:mod:`flexshaft.plot.gain_maps`), so the grid is even in
  log10: K_p,i = 10^(5 + 3i/29), a constant ratio 10^(3/29) between neighbours.

Tolerances: exact values, or 1e-12 relative for the powers of ten.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from flexshaft.assembly.model import Controller
from flexshaft.thesis import spinup_maps

KP = np.array([1e5, 1e6, 1e7])  # [N/m]
KD = np.array([0.0, 100.0, 1000.0])  # [N s/m]
# spin-up shaft peak [m], (n_kp, n_kd), asymmetric: a law built from the other axis's indices
# (K_p,j, K_d,i) would read the transposed entry
PEAK = np.array([[3.0, 1.0, 5.0], [9.0, 4.0, 6.0], [7.0, 8.0, 2.0]]) * 1e-3
GAP = 2.0**-12  # [m]
# each actuator's peak orbit [m] (n_kp, n_kd, 2): the quietest allowed pair (1e5, 100), off the
# diagonal, reaches the gap exactly at its second actuator; (1e5, 1000) and (1e6, 1000) are
# below the gap; the rest (the quieter diagonal (1e7, 1000) included) far beyond it
ORBIT = np.full((3, 3, 2), 1.0)
ORBIT[0, 1] = (GAP / 2, GAP)
ORBIT[0, 2] = (GAP / 4, GAP / 4)
ORBIT[1, 2] = (GAP / 8, GAP / 8)


def _study(monkeypatch, gap):
    seen = []

    def curves(rec, law):
        if isinstance(law, tuple):  # a surface's (kp, kd) pair
            seen.append(law)
            peak = 0.0
        else:
            kp, kd = law[0].kp, law[0].kd
            peak = float(PEAK[np.flatnonzero(KP == kp)[0], np.flatnonzero(KD == kd)[0]])
        return SimpleNamespace(
            shaft_peak=np.array([peak]),
            shaft_orbit=np.array([[peak]]),
            actuator_displacement=np.zeros((2, 1)),
            actuator_force=np.zeros((2, 1)),
        )

    rec = SimpleNamespace(
        n_actuators=2, speeds=np.array([100.0]), shaft_x=np.array([0.0]), actuator_names=("amb_1", "amb_2")
    )
    smap = SimpleNamespace(
        kp=KP, kd=KD, shaft_peak=PEAK, actuator_displacement_peak=ORBIT, to_arrays=lambda: SimpleNamespace(attrs={})
    )
    monkeypatch.setattr(spinup_maps, "spinup_speeds", lambda model, n: None)
    monkeypatch.setattr(spinup_maps, "clustered_receptance", lambda model, laws, speeds: rec)
    monkeypatch.setattr(spinup_maps, "spinup_map", lambda model, kp, kd, receptance: smap)
    monkeypatch.setattr(spinup_maps, "spinup_curves", curves)
    monkeypatch.setattr(spinup_maps, "_refined_peak", lambda model, law, speeds, curve: (float(curve.max()), 100.0))
    model = SimpleNamespace(actuators=[SimpleNamespace(controller=Controller.pd(1e6, 1000.0))] * 2)
    grid = {"map_speeds": 10, "map_kp": KP, "map_kd": KD}
    return spinup_maps.spinup_studies(model, grid, gap), seen


def test_a_pair_whose_orbit_equals_the_gap_is_allowed(monkeypatch):
    out, _ = _study(monkeypatch, GAP)
    assert out["gains_after"] == (1e5, 100.0) and out["peak_after"] == 1e-3
    # just below the gap that pair is out: the next quietest within it, (1e5, 1000), 5 mm
    out, _ = _study(monkeypatch, np.nextafter(GAP, 0.0))
    assert out["gains_after"] == (1e5, 1000.0) and out["peak_after"] == 5e-3


def test_surfaces_are_the_curves_of_the_gain_pairs_they_name(monkeypatch):
    out, seen = _study(monkeypatch, None)
    assert seen == list(spinup_maps.SURFACE_GAINS)
    surfaces = out["surfaces"]
    kp, kd = surfaces.coords["kp"].values, surfaces.coords["kd"].values
    assert list(zip(kp.tolist(), kd.tolist())) == [tuple(map(float, p)) for p in seen]


def test_default_gain_grid_is_even_in_log10(monkeypatch):
    got = {}

    def fake_map(model, kp, kd, speeds):
        got["kp"], got["kd"] = np.asarray(kp), np.asarray(kd)
        return SimpleNamespace(to_dataset=lambda: None)

    monkeypatch.setattr(spinup_maps, "build_model", lambda design: None)
    monkeypatch.setattr(spinup_maps, "spinup_speeds", lambda model, n: None)
    monkeypatch.setattr(spinup_maps, "spinup_map", fake_map)
    spinup_maps.spinup_gain_map(design=object())
    kp, kd = got["kp"], got["kd"]
    assert kp.size == 30 and kd.size == 30
    np.testing.assert_allclose(kp, [10.0 ** (5 + 3 * i / 29) for i in range(30)], rtol=1e-12)
    assert kd[0] == 0.0
    np.testing.assert_allclose(kd[1:], [10.0 ** (1 + 3.5 * i / 28) for i in range(29)], rtol=1e-12)
