"""The ``flexshaft compare`` report puts each design's compared quantities, notes and spin-up
curve under its own label (report/compare.py), beside tests/test_compare_report_sides_reference.py:
the metric values, lower-bound flags and notes of ``results.json``, the notes columns of the
key-numbers table, and the spin-up overlay's speed axis.

References (derived, by hand): a stand-in comparison whose designs A and B have distinct inputs
(so a value taken from the other design is seen); ``results.json`` is SI (the module docstring:
"``results.json`` (SI)"), so a metric's values go out as given; rpm = 60·Ω/(2π), so
Ω = 2π·N/60 rad/s is drawn at N rpm (the spin-up figure's ``speeds_rpm``). Figures are replaced
by stubs that draw nothing. CPU about 0.01 s.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace as NS

import numpy as np
import pytest

from flexshaft.comparison import PART_KINDS, Metric
from flexshaft.report import compare


def _inventory(total):
    mass = dict.fromkeys(PART_KINDS, 0.0)
    return NS(mass=mass, count=dict.fromkeys(PART_KINDS, 0), total_mass=total, total_count=0, mass_not_given=[])


def _comparison(metrics, runs=None):
    if runs is None:
        runs = tuple(
            NS(model=NS(design=NS(name=name)), verdict=NS(summary="PASS", to_dict=dict), notes=[])
            for name in ("alpha", "beta")
        )
    return NS(
        labels=("A", "B"),
        runs=runs,
        inventories=(_inventory(12.0), _inventory(30.0)),
        critical_speeds=lambda d: [],
        metrics=lambda: list(metrics),
    )


#: Whirl onset: A stable to the top of its scan (a lower bound, 6000 rpm), B's onset at 5400 rpm.
_ONSET = Metric(
    "whirl_onset",
    "whirl onset",
    "rad/s",
    (2.0 * math.pi * 6000.0 / 60.0, 2.0 * math.pi * 5400.0 / 60.0),
    ("none up to 1.5 × Ω_op", "forward whirl, mode 2"),
    (True, False),
)


def test_results_json_metric_values_notes_and_bounds_per_design():
    """results.json carries each design's own SI value of a compared quantity (no conversion):
    A 200π rad/s (a lower bound, with its note), B 180π rad/s (found, with its own note)."""
    (metric,) = compare.comparison_json(_comparison([_ONSET]))["metrics"]
    assert (metric["key"], metric["unit"]) == ("whirl_onset", "rad/s")
    # values passed through as stored: exact, no arithmetic on them
    assert metric["values"] == {"A": 200.0 * math.pi, "B": 180.0 * math.pi}
    assert metric["lower_bounds"] == {"A": True, "B": False}
    assert metric["notes"] == {"A": "none up to 1.5 × Ω_op", "B": "forward whirl, mode 2"}


def test_key_numbers_table_notes_under_their_own_design():
    """Columns "note (A)", "note (B)" hold A's note and B's note: the caveat "none up to
    1.5 × Ω_op" (why A's value is a lower bound) belongs beside "> 6000 rpm", not beside B."""
    table = compare._metrics_table(_comparison([_ONSET]))
    assert list(table.columns) == ["quantity", "A", "B", "note (A)", "note (B)"]
    # the values' display ("> " before a lower bound) is format_metric's docstring (code); the
    # reference here is each note in its own design's column
    assert table.rows == [["whirl onset", "> 6000 rpm", "5400 rpm", "none up to 1.5 × Ω_op", "forward whirl, mode 2"]]


def test_spinup_overlay_speeds_in_rpm_each_design_its_own(monkeypatch, tmp_path):
    """A's spin-up samples at Ω = 2π·1000/60 and 2π·5000/60 rad/s go to the overlay at 1000 and
    5000 rpm with A's peaks (0.2 mm, 0.4 mm); B's at 2π·2000/60 and 2π·6000/60 rad/s at 2000 and
    6000 rpm with B's (0.3 mm, 0.1 mm). The operating speeds (5000, 6000 rpm) are on the same axis."""
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    monkeypatch.setattr(compare, "campbell_overlay_figure", lambda *args: None)
    calls: dict = {}
    monkeypatch.setattr(
        compare, "spinup_overlay_figure", lambda responses, op, limit: calls.update(responses=responses, op=op)
    )

    def run(rpm, peaks):
        speeds = np.array(rpm) * 2.0 * math.pi / 60.0
        return NS(
            model=NS(speed=speeds[-1], design=NS(requirements=NS(max_spinup_deflection=1e-3))),
            campbell=NS(speeds=speeds, frequencies=np.zeros((2, 1)), whirl=[["forward"]] * 2),
            spinup=NS(speeds=speeds, shaft_peak=np.array(peaks)),
        )

    cases = (("A", [1000.0, 5000.0], [2e-4, 4e-4]), ("B", [2000.0, 6000.0], [3e-4, 1e-4]))
    compare._dynamics_section(_comparison([], runs=tuple(run(r, p) for _, r, p in cases)), tmp_path)
    for label, rpm, peaks in cases:
        speeds, peak = calls["responses"][label]
        # rpm back from rad/s: one multiplication and one division each way, 1e-12 relative
        assert np.asarray(speeds) == pytest.approx(rpm, rel=1e-12)
        assert np.asarray(peak).tolist() == peaks  # the orbit goes in metres, as given
    assert calls["op"] == pytest.approx({"A": 5000.0, "B": 6000.0}, rel=1e-12)
