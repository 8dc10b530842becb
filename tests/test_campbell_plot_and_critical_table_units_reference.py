"""The Campbell figure's and the critical-speed table's units, against the damped Jeffcott rotor
without internal loss (tests/rotors.py; closed form derived here).

The rotor: a 20 kg disk (no rotary inertia, hence no gyroscopic coupling) at the middle of a
near-massless pinned-pinned tube (k = 48EI/L³) with an external dashpot c_e at the disk and no
material loss (η = 0). In the complex coordinate r = v + i w of the disk a whirl r = e^{st}
obeys m s² + c_e s + k = 0 at every spin: both whirls have the damped frequency
ω_d = ω_n √(1 − ζ²), ζ = c_e/(2√(km)) = 0.1, independent of the speed, so the two tracked
curves are flat and each crosses the 1× line ω = Ω at Ω = ω_d, i.e. at
N = ω_d · 60/(2π) rpm and f = ω_d/(2π) Hz (linear interpolation of a straight g = ω_d − Ω is
exact).

* ``Campbell.plot_campbell`` draws "in rpm and Hz" (its docstring): with ``damping=False`` each
  mode is one line, at the abscissae Ω · 60/(2π) (1e-12: an affine map of the inputs) and the
  ordinate ω_d/(2π) (1e-4: the tube's mass, 3.5e-6 of the disk's, and the modal basis leave
  about 1e-6 on these roots; tests/test_campbell_jeffcott_reference.py asserts the same rotor at
  1e-4); the critical-speed marker sits at (N, N/60) on the 1× line.
* ``max_critical_rpm`` marks "the critical speeds (up to ``max_critical_rpm``)", a limit in
  rpm: half the critical speed in rpm hides the marker (N/2 rpm is still 4.8 times the
  critical speed's value in rad/s, so a limit compared in rad/s would keep it); 1.5 N shows it.
* ``CriticalSpeeds.labelled(campbell)`` labels the unbalance-response peaks by the documented
  rule of docs/requirements.md ("How flexshaft computes AF", step 5): "Each peak is labelled
  with the tracked Campbell mode whose 1× critical speed is within 3 %". A peak 1 % above ω_d
  takes the mode number (from 1) and whirl of one of the two crossings there; one 10 % above
  ω_d takes none. The peaks of that rule are those steps 2–4 resolve and give an AF; an
  undamped critical (no AF method) is not one and takes none either (this restriction rests
  only on label_critical_speeds's docstring, "the resolved peaks", not on a hand-written doc).
* ``CriticalSpeeds.to_dataframe`` gives each critical's "speed [rpm] and [rad/s]": 100π rad/s
  is 3000 rpm exactly (1 rev = 2π rad, 1 min = 60 s; 1e-12).

Five speeds, two modes: about 0.1 s of CPU besides matplotlib's import.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from rotors import M_DISK, WN, jeffcott

from flexshaft.analyses.campbell import campbell
from flexshaft.analyses.criticals import CriticalSpeeds, LateralCritical

ZETA = 0.1
C_E = 2 * ZETA * M_DISK * WN
WD = WN * np.sqrt(1 - ZETA**2)
SPEEDS = WN * np.array([0.0, 0.4, 0.8, 1.2, 1.6])
RPM = 60.0 / (2.0 * np.pi)


@pytest.fixture(scope="module")
def diagram():
    return campbell(jeffcott(0.0, C_E), SPEEDS, n_modes=2)


def test_the_crossings_are_at_the_damped_frequency(diagram):
    assert [c.speed for c in diagram.critical_speeds] == pytest.approx([WD, WD], rel=1e-4)


def test_campbell_figure_is_drawn_in_rpm_and_hz(diagram):
    import matplotlib.pyplot as plt

    fig = diagram.plot_campbell(damping=False)
    try:
        ax = fig.axes[0]
        curves = [  # the mode curves: flat at ω_d/2π (the marker, on them, is not a curve)
            line
            for line in ax.get_lines()
            if line.get_label() != "critical speed"
            and np.allclose(np.asarray(line.get_ydata(), float), WD / (2 * np.pi), 1e-3)
        ]
        assert len(curves) >= 2  # the two whirls (a run of one whirl label each at least)
        for line in curves:  # each run of a whirl label: consecutive samples, in rpm
            x = np.asarray(line.get_xdata(), float)
            first = int(np.argmin(np.abs(SPEEDS * RPM - x[0])))
            assert x == pytest.approx(SPEEDS[first : first + x.size] * RPM, rel=1e-12, abs=1e-9)
            assert np.asarray(line.get_ydata(), float) == pytest.approx(np.full(x.size, WD / (2 * np.pi)), rel=1e-4)
        assert max(np.max(line.get_xdata()) for line in curves) == pytest.approx(SPEEDS[-1] * RPM, rel=1e-12)
        (marker,) = [line for line in ax.get_lines() if line.get_label() == "critical speed"]
        assert np.asarray(marker.get_xdata(), float) == pytest.approx([WD * RPM] * 2, rel=1e-4)
        assert np.asarray(marker.get_ydata(), float) == pytest.approx([WD / (2 * np.pi)] * 2, rel=1e-4)
    finally:
        plt.close(fig)


def _markers(diagram, limit_rpm: float) -> list:
    import matplotlib.pyplot as plt

    fig = diagram.plot_campbell(damping=False, max_critical_rpm=limit_rpm)
    try:
        return [line for line in fig.axes[0].get_lines() if line.get_label() == "critical speed"]
    finally:
        plt.close(fig)


def test_critical_marks_stop_at_a_limit_in_rpm(diagram):
    assert _markers(diagram, 0.5 * WD * RPM) == []
    assert len(_markers(diagram, 1.5 * WD * RPM)) == 1


def test_critical_speed_table_gives_rpm_and_rad_s():
    found = CriticalSpeeds((LateralCritical(100.0 * np.pi, 12.0, {"station": 0.5}),), 400.0)
    table = found.to_dataframe()
    assert table["speed_rpm"].to_numpy() == pytest.approx([3000.0], rel=1e-12)
    assert table["speed_rad_s"].to_numpy() == pytest.approx([100.0 * np.pi], rel=1e-12)


def test_critical_speeds_are_labelled_by_the_campbell_crossing_within_three_percent(diagram):
    near = LateralCritical(1.01 * WD, 8.0, {"station": 0.5, "af_method": "half-power"})
    far = LateralCritical(1.10 * WD, 8.0, {"station": 0.5, "af_method": "half-power"})
    undamped = LateralCritical(0.99 * WD, float("inf"), {"station": 0.5})
    found = CriticalSpeeds((undamped, near, far), 2.0 * WN).labelled(diagram)
    crossings = {f"{c.mode + 1} ({c.whirl})" for c in diagram.critical_speeds}
    assert found.criticals is not None
    assert found.criticals[1].location.get("mode") in crossings
    assert found.criticals[1].speed == near.speed
    assert found.criticals[2].location.get("mode", "") == ""
    assert found.criticals[0].location.get("mode", "") == ""
