"""An operating point's ply strength follows the shaft lamina's temperature table, not the
``[thermal]`` law; the report's detail labels the critical speeds with its Campbell modes.

References (hand-written docs, quoted verbatim):

* docs/thermal.md, "Lamina properties over temperature": "**Without a table**, the assumed law
  of the `[thermal]` table: E_T and G_LT scale by exp(−(T − T_ref)/θ_E)" and "the table wins
  over the law". The tuned design's lamina ``t700_adiprene`` carries a temperature table
  (tuned.toml), so the law's θ_E (``matrix_modulus_decay``) must not enter anything of its
  ply check: the thermal residual stress integrated over the cool-down from the stress-free
  100 °C to the ambient 25.6 °C is the table's. Changing θ_E from 40 K to 10 K (a generic law
  four times as steep, which would move the residual moduli by factors e^{±74/10}) leaves the
  static and the static + imbalance safety factors unchanged: the computation that reads them
  never reads θ_E, so the comparison is exact (measured difference 0).
* docs/requirements.md, lateral critical speeds, rule 5: "Each peak is labelled with the
  tracked Campbell mode whose 1× critical speed is within 3 %." An envelope point is analysed
  without the report's detail (no Campbell diagram: its criticals carry no mode); the report
  adds the detail to the governing point (:func:`add_report_detail`), whose criticals must then
  carry the label of the Campbell mode within 3 % of each peak. The label names the tracked
  mode (1-based, as the report's tables number modes) and its whirl.

Cost: the tuned design on 18 shaft elements; the smallest grids (strength) and a 12-speed
spin-up with a 9-speed Campbell diagram (labels): measured 0.84-1.08 s CPU each on the loaded
shared machine (review r125; first call 0.92 and 1.08 s, repeated 0.89 and 0.88 s), not well
under 1 s. A coarser mesh (12 shaft and 8 boom elements) was tried and costs the same (1.18 s
against 1.12 s for the labels: the time is the spin-up and Campbell solves, not the mesh), so
the mesh is kept.
"""

from __future__ import annotations

import dataclasses

from conftest import SMALLEST

from flexshaft.design import tuned_design, with_overrides
from flexshaft.verdict.operating_point import add_report_detail, analyse_point

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


def test_a_tabled_laminas_ply_strength_does_not_read_the_thermal_law():
    """θ_E = 40 K and 10 K: the tabled lamina's safety factors are identical (docs/thermal.md)."""
    design = with_overrides(tuned_design(), COARSE)
    assert design.materials[design.shaft.material].temperature_table is not None
    found = []
    for decay in (40.0, 10.0):
        p = analyse_point(with_overrides(design, {"thermal.matrix_modulus_decay": decay}), SMALLEST, detail=False)
        assert p.strength_static is not None and p.strength_total is not None
        found.append((p.strength_static.safety_factor, p.strength_total.safety_factor))
    assert found[0] == found[1]


def test_the_reports_detail_labels_each_critical_with_its_campbell_mode():
    """A point analysed without detail, then given the report's: every peak within 3 % of a 1×
    crossing of the Campbell diagram carries that mode's number and whirl (requirements rule 5)."""
    design = with_overrides(tuned_design(), COARSE)
    resolution = dataclasses.replace(SMALLEST, spinup_speeds=12, campbell_speeds=9)
    p = analyse_point(design, resolution, detail=False)
    assert p.campbell is None
    q = add_report_detail(p)
    assert q.campbell is not None and q.criticals.criticals
    synchronous = [c for c in q.campbell.critical_speeds if c.harmonic == 1.0]
    matched = 0
    for critical in q.criticals.criticals:
        nearest = min(synchronous, key=lambda c: abs(c.speed - critical.speed))
        if abs(nearest.speed - critical.speed) > 0.03 * critical.speed:
            continue
        matched += 1
        mode = critical.location.get("mode", "")
        assert mode.startswith(f"{nearest.mode + 1} "), (critical.speed, mode)
        assert nearest.whirl in mode
    # Every peak must be labelled: measured, all 5 peaks of the scan lie within 1.5 % of a 1×
    # crossing (worst −1.47 %, half the rule's 3 %), so none may drop out of the check.
    assert matched == len(q.criticals.criticals)
