r"""A Campbell sweep's speed list, its reported accuracy, and its text and notebook tables, on the
Jeffcott rotor of tests/rotors.py (a disk at midspan of a uniform tube on rigid supports, no
damping: the disk does not tilt in the first mode, so both whirls stay at ω_n = √(k/m) at
every speed and cross the 1× line ω = Ω at Ω = ω_n).

* **Speeds strictly increasing** (API contract: :func:`flexshaft.analyses.campbell.campbell`
  docstring, ``speeds``: "Ω [rad/s], increasing"). The tracking numbers the modes at the first
  speed and continues each curve from the earlier speeds
  (:func:`~flexshaft.analyses.continuation.predicted_start` extrapolates over the speed
  steps): a decreasing list would number the modes at its highest speed, and a repeated speed
  is a step of zero width (the extrapolation divides by it). Both are refused as input
  (:class:`~flexshaft.analyses.guards.RefusedInputError`) before any solve; the increasing
  list of the same speeds is accepted.
* **The reported tolerance** (API contract: ``Campbell.tolerance`` docstring,
  :class:`~flexshaft.analyses.campbell.Campbell`: "The accuracy the basis was chosen for
  (None: a basis size given by the caller)"; docs/model.md: "A ``basis_size`` given by the
  caller is used as it is"): an explicit ``basis_size`` reports no tolerance, neither on the
  result nor as the dataset's ``eigenvalue_tolerance`` attribute; the default basis reports
  the tolerance asked for.
* **The repr's top speed in rpm**: the sweep to 1.5 ω_n rad/s ends at 1.5 ω_n · 60/2π rpm
  (4328 rpm for ω_n = 302.14 rad/s), printed to the rpm ("to {top:.0f} rpm").
* **The notebook's critical-speed table numbers modes as the mode table above it** (API
  contract: ``Campbell.to_dataframe`` docstring, the critical speeds' "tracked mode (numbered
  from 1)", and ``Campbell.mode_summary`` docstring, "numbered from 1 as the modes at the
  first speed"; README.md, Output, as supporting text: "Modes are numbered from 1 (the Python
  API counts from 0)"): each crossing at Ω = ω_n (2885 rpm, closed form above) names a mode
  number of the summary table whose whirl is the crossing's. Which of the degenerate pair is
  numbered 1 is not asserted (the eigen-solver's order of a degenerate pair), only that the
  two tables agree.

Tolerances: the crossing speed to ±1 rpm, 3.5e-4 relative at 2885 rpm (the table prints whole
rpm). The closed form neglects the tube's own mass (tests/rotors.py: density 0.1 kg/m³, the
tube 3.5e-6 of the disk mass), which lowers ω_n by about ½ · (17/35) · 3.5e-6 ≈ 9e-7 relative
(Rayleigh: 17/35 of a pinned-pinned beam's mass moves with its midspan), far inside ±1 rpm;
the rest are exact (a refusal, None, an integer printed by the repr).

Written for the mutations h88a-campbell-speeds-order-unchecked,
h88a-campbell-tolerance-with-explicit-basis, h88a-campbell-repr-top-speed-rad-s and
h88a-campbell-html-critical-mode-zero-based of scripts/mutations.toml. CPU: 3 tests (4
cases), 3- and 4-speed sweeps of a 2-mode Jeffcott rotor, about 0.1 s, plus the xarray import
of the first ``to_dataset`` call (about 0.4 s of CPU, once per session).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from rotors import WN, jeffcott

from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.guards import RefusedInputError

RPM = 60.0 / (2.0 * np.pi)


@pytest.fixture(scope="module")
def model():
    return jeffcott(0.0, 0.0)


@pytest.mark.parametrize(
    "speeds",
    [
        [1.5 * WN, 0.5 * WN, 0.0],  # decreasing: modes numbered at the top speed
        [0.0, 0.5 * WN, 0.5 * WN, 1.5 * WN],  # a repeated speed: a step of zero width
    ],
)
def test_a_sweep_not_strictly_increasing_is_refused(model, speeds):
    """Decreasing or repeated speeds are refused; the increasing list of the same speeds is not."""
    with pytest.raises(RefusedInputError, match="strictly increasing"):
        campbell(model, speeds, 2, basis_size=12)
    result = campbell(model, sorted(set(speeds)), 2, basis_size=12)
    assert result.speeds[0] == 0.0 and np.all(np.diff(result.speeds) > 0)


def test_an_explicit_basis_reports_no_tolerance(model):
    """basis_size given: tolerance None (no eigenvalue_tolerance attribute); default: the one asked."""
    speeds = [0.0, 0.5 * WN, 1.5 * WN]
    given = campbell(model, speeds, 2, basis_size=12)
    assert given.tolerance is None
    assert given.basis_size == 12
    assert "eigenvalue_tolerance" not in given.to_dataset().attrs
    chosen = campbell(model, speeds, 2, tolerance=1e-5)
    assert chosen.tolerance == 1e-5
    assert chosen.to_dataset().attrs["eigenvalue_tolerance"] == 1e-5


def _rows(html: str) -> list[list[str]]:
    return [re.findall(r"<td[^>]*>([^<]*)</td>", row) for row in re.findall(r"<tr>(.*?)</tr>", html)]


def test_repr_and_notebook_tables_in_rpm_and_numbered_from_one(model):
    """Top speed 1.5 ω_n in rpm; each critical speed's mode number is the summary row of its whirl."""
    result = campbell(model, [0.0, 0.5 * WN, 1.5 * WN], 2, basis_size=12)
    assert f"to {1.5 * WN * RPM:.0f} rpm" in repr(result)
    assert f"{1.5 * WN * RPM:.0f}" == "4328"  # the value quoted in the docstring

    html = result._repr_html_()
    summary_html, critical_html = html.split("<b>critical speeds</b>", 1)
    summary = {row[0]: row[4] for row in _rows(summary_html) if row}
    assert sorted(summary) == ["1", "2"]
    critical = [row for row in _rows(critical_html) if row]
    assert len(critical) == 2  # both whirls cross 1× at ω_n
    for speed_rpm, mode, harmonic, whirl in critical:
        assert float(speed_rpm) == pytest.approx(WN * RPM, abs=1.0)
        assert float(harmonic) == 1.0
        assert mode in summary, f"critical speed names mode {mode}, not in the summary {sorted(summary)}"
        assert summary[mode] == whirl
    assert sorted(row[1] for row in critical) == ["1", "2"]
