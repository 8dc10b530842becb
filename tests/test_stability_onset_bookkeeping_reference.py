"""The whirl-stability result's onset, divergence flag, description and viscous reference frequency
against closed forms and the definitions they state.

* Viscous internal damping (the thesis's chapter-4 model, flexshaft.analyses.stability) on the Jeffcott
  rotor of tests/rotors.py: the forward root of m s² + (c_e + c_i) s + k − iΩ c_i = 0 is on the
  imaginary axis, s = iω, when −mω² + k = 0 and (c_e + c_i) ω = Ω c_i, i.e. at
  Ω = ω_n (1 + c_e/c_i) (derived; tests/test_stability.py checks it on a fine grid). Here on a
  grid of two speeds, 0.5 and 2 ω_n: the onset is solved between them, not interpolated
  (a linear interpolation of ζ across that bracket misses it by percents). Tolerance 1e-5: the
  tube's mass share (7e-6 of the disk's) moves ω_n by less (measured 9e-7).
* The viscous method's default reference frequency is the first mode that is mostly shaft: on
  a rotor whose whole mass is the shaft's and a disk on it, the disk's first bending mode. With
  the disk at a = 0.875 L of a pinned-pinned tube (the node at 7/8 of an 8-element mesh) its
  stiffness is k = 3 E I L/(a² b²), b = L − a (derived: the deflection under a point load P at
  a of a simply supported beam is P a² b²/(3 E I L), by the unit-load method), so
  ω_ref = √(k/m). Tolerance 1e-5, as above
  (measured 3.5e-6).
* :func:`~flexshaft.analyses.stability.onset_speed`, :attr:`StabilityResult.divergent` and
  :meth:`StabilityResult.onset_description` on hand-made eigenvalues: the definitions their
  docstrings state (ζ = −Re s/|s| below −tolerance is unstable; a divergence at any speed
  counts; the whirl of the unstable mode at the first unstable speed).
"""

from __future__ import annotations

import numpy as np
import pytest
from rotors import DI, DO, K_SHAFT, M_DISK, WN, E, L, jeffcott, jeffcott_text

from flexshaft.analyses.stability import StabilityResult, onset_speed, stability
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

ETA, ZETA_E = 0.02, 0.005
C_E = 2 * ZETA_E * M_DISK * WN


def test_an_onset_between_the_first_two_speeds_is_solved_not_interpolated():
    c_i = ETA * K_SHAFT / WN  # ω_ref = ω_n
    result = stability(
        jeffcott(ETA, C_E), np.array([0.5, 2.0]) * WN, n_modes=2, damping_model="viscous", reference_frequency=WN
    )
    assert result.onset_speed == pytest.approx(WN * (1 + C_E / c_i), rel=1e-5)


def test_the_default_viscous_reference_is_the_first_bending_mode_of_the_shaft():
    a = 0.875 * L
    b = L - a
    stiffness = 3 * E * (np.pi * (DO**4 - DI**4) / 64) * L / (a * a * b * b)
    model = build_model(loads_design(jeffcott_text(ETA, C_E).replace(f"x = {L / 2}", f"x = {a}")))
    result = stability(model, np.array([0.0, 0.5]) * WN, n_modes=2, damping_model="viscous")
    assert result.reference_frequency == pytest.approx(np.sqrt(stiffness / M_DISK), rel=1e-5)


def _zeta_root(zeta: float, omega: float = 100.0) -> complex:
    """The root of damping ratio ζ and modulus ω: s = ω(−ζ + i√(1 − ζ²))."""
    return complex(omega * -zeta, omega * np.sqrt(1 - zeta * zeta))


def test_a_mode_unstable_from_the_first_speed_has_its_onset_there():
    speeds = np.array([10.0, 20.0, 30.0])
    eig = np.array(
        [
            [_zeta_root(0.01), _zeta_root(-0.02)],
            [_zeta_root(0.01), _zeta_root(-0.03)],
            [_zeta_root(0.01), _zeta_root(-0.04)],
        ]
    )
    assert onset_speed(speeds, eig) == (10.0, 1, 0)
    # and a crossing inside: ζ from 0.02 to −0.02 between 20 and 30 is zero at 25 (linear in ζ)
    eig[:, 1] = [_zeta_root(0.04), _zeta_root(0.02), _zeta_root(-0.02)]
    crossing, mode, index = onset_speed(speeds, eig)
    assert (mode, index) == (1, 2)
    assert crossing == pytest.approx(25.0, rel=1e-12)


def _result(**changes) -> StabilityResult:
    speeds = np.array([10.0, 20.0, 30.0])
    eig = np.array([[_zeta_root(0.02)], [_zeta_root(0.01)], [_zeta_root(-0.01)]])
    fields = {
        "speeds": speeds,
        "eigenvalues": eig,
        "whirl": np.array([["backward"], ["backward"], ["forward"]]),
        "damping_model": "hysteretic",
        "onset_speed": 25.0,
        "unstable_mode": 0,
        "onset_shape": None,
        "divergence": np.zeros(3),
    }
    fields.update(changes)
    return StabilityResult(**fields)


def test_a_divergence_at_one_speed_makes_the_result_divergent():
    result = _result(divergence=np.array([0.0, 0.0, 3.0]))
    assert result.divergent
    assert list(result.stability_margin) == pytest.approx([0.02, 0.01, -1.0])
    assert not _result().divergent


def test_the_onset_is_described_by_the_whirl_at_the_first_unstable_speed():
    """Onset at 25 between the samples 20 (stable, labelled backward) and 30 (unstable,
    forward): the mode that turns unstable whirls as at 30. An onset on a sample, 30, reads it."""
    assert _result().onset_description() == "mode 1, forward whirl"
    assert _result(onset_speed=30.0).onset_description() == "mode 1, forward whirl"


def test_the_onset_whirl_is_the_label_where_the_mode_is_first_unstable():
    """Whirl labels that differ at rest, below the onset, where the mode is first unstable and at
    the top speed (backward, backward, forward, backward at 10, 20, 30, 40): with the onset at 23,
    nearer the stable sample 20, the label is the one at 30, the first speed at or above the onset
    (the speed of ``onset_shape``), not the nearest sample's, the first's or the last's. This one
    label is what the report, the verdict's location and results.json give (the property's
    docstring). Stable, or at a divergence (no tracked mode), there is none."""
    speeds = np.array([10.0, 20.0, 30.0, 40.0])
    eig = np.array([[_zeta_root(z)] for z in (0.02, 0.01, -0.01, -0.02)])
    whirl = np.array([["backward"], ["backward"], ["forward"], ["backward"]])
    fields = {"speeds": speeds, "eigenvalues": eig, "whirl": whirl, "onset_speed": 23.0}
    result = _result(**fields)
    assert result.onset_whirl == "forward"
    assert result.onset_description() == "mode 1, forward whirl"
    assert _result(**{**fields, "onset_speed": 30.0}).onset_whirl == "forward"  # on a sample: that one
    assert _result(**{**fields, "onset_speed": None, "unstable_mode": None}).onset_whirl is None
    diverging = _result(**{**fields, "unstable_mode": None, "onset_kind": "divergence"})
    assert diverging.onset_whirl is None
