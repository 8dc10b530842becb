"""Reference: a results file names each location's unit (review, sixteenth session).

Was: results.json and ``--json`` wrote a finding's ``"speed": 628.9`` (rad/s) with no unit in
its key, where the CLI promises "each unit in its key". Exact: keys and the same floats.
"""

from __future__ import annotations

import numpy as np

from flexshaft.analyses.criticals import LateralCritical
from flexshaft.design.requirements import Requirements
from flexshaft.verdict import checks
from flexshaft.verdict.evidence import Evidence

RPM = 2.0 * np.pi / 60.0
OMEGA = 4800.0 * RPM
RANGE = (0.95 * OMEGA, 1.05 * OMEGA)


def test_a_results_file_names_each_locations_unit():
    """The location keeps its Python keys; its dictionary for a file carries the SI unit:
    speed_rad_s, reference_speed_rad_s, station_m (a key without a unit unchanged)."""
    critical = (LateralCritical(6000.0 * RPM, 5.19, {"station": 0.0, "mode": "3"}),)
    ranged = checks.separation(Evidence(OMEGA, RANGE, critical_speeds=critical), Requirements())
    assert "speed" in ranged.location and "station" in ranged.location
    for location in (ranged.to_dict()["location"], ranged.to_dict()["findings"][0]["location"]):
        assert location["speed_rad_s"] == 6000.0 * RPM
        assert location["reference_speed_rad_s"] == RANGE[1]
        assert location["station_m"] == 0.0 and location["mode"] == "3"
        assert not {"speed", "station", "reference_speed"} & set(location)
