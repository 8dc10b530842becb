"""Whirl labels of the Campbell diagram and of ``modes`` against the overhung rotor's closed form.

Reference: the overhung disk of tests/test_overhung_disk_whirl.py (a rigid disk m, I_d, I_p at the
tip of a massless clamped cantilever). Its whirl frequencies are the positive roots of

    (k11 − m ω²)(k22 − I_d ω² ± I_p Ω ω) − k12² = 0      (+ forward, − backward)

(Genta, *Dynamics of Rotating Systems*, ch. 4): with spin about +x, the forward whirl frequencies
rise with Ω and the backward ones fall. So at Ω = 1000 rad/s (a 30 % gyroscopic split) every
lateral mode whose frequency is a root of the "+" equation must be labelled ``"forward"`` and
every root of the "−" equation ``"backward"``, in the Campbell diagram's labels (projected mode
shapes, :class:`~flexshaft.analyses.classify.ModalLabeler`) and in ``modes``'s (expanded mode
shapes). Frequencies to 5e-5 as in that test (the tube's mass is 1e-6 of the disk's).

Kind: a tail rotor behind an elastic drive (its own twist DOF, :mod:`flexshaft.assembly.drive`) on
a held, nearly massless shaft is one torsional oscillator, ω² = k_eff n²/J_tr with
1/k_eff = 1/k_shaft + 1/k_input + n²/k_hub (tests/test_torsional.py): the Campbell mode at that
frequency carries its kinetic energy in the drive train's twist and is ``"torsional"``, with no
whirl and no critical speed (in the Campbell diagram and in ``modes``).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_overhung_disk_whirl import closed_form, design_text
from test_torsional import K_SHAFT, shaft_text

import flexshaft as fs
from flexshaft.analyses.campbell import campbell
from flexshaft.design import loads_design

SPEED = 1000.0  # rad/s


def _assert_whirl_matches_closed_form(frequencies: np.ndarray, whirl: np.ndarray) -> None:
    """Each closed-form root (two forward, two backward) is a computed mode with its whirl."""
    for sense, label in ((+1, "forward"), (-1, "backward")):
        for root in closed_form(SPEED, sense):
            k = int(np.argmin(np.abs(frequencies - root)))
            assert frequencies[k] == pytest.approx(root, rel=5e-5)
            assert whirl[k] == label, (root, frequencies, whirl)


def test_campbell_whirl_labels_follow_the_gyroscopic_closed_form():
    model = fs.build_model(loads_design(design_text(SPEED * 60 / (2 * np.pi))))
    diagram = campbell(model, np.array([0.0, 0.5 * SPEED, SPEED]), n_modes=6, damped=False)
    _assert_whirl_matches_closed_form(diagram.eigenvalues[-1].imag, diagram.whirl[-1])


def test_modes_whirl_labels_follow_the_gyroscopic_closed_form():
    model = fs.build_model(loads_design(design_text(SPEED * 60 / (2 * np.pi))))
    m = fs.modes(model, speed=SPEED, n_modes=6, damped=False)
    _assert_whirl_matches_closed_form(m.eigenvalues.imag, m.whirl)


def test_campbell_labels_the_tail_rotor_behind_its_drive_spring_torsional():
    """Frequency to 3e-7 as in tests/test_torsional.py (the shaft's twist inertia is 1e-7 of the
    rotor's)."""
    J_tr, n, k_in, k_hub = 12.0, 3.4, 4.0e4, 2.5e5
    text = shaft_text(
        f"[tail_rotor]\nblades = 4\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n"
        f"input_stiffness = {k_in}\nhub_stiffness = {k_hub}\naerodynamic_damping = 0.0\n"
    )
    model = fs.build_model(loads_design(text))
    assert model.dofs.extra == ("tail_rotor",)
    k_eff = 1.0 / (1.0 / K_SHAFT + 1.0 / k_in + n**2 / k_hub)
    expected = np.sqrt(k_eff * n**2 / J_tr)
    diagram = campbell(model, np.array([0.0, 100.0]), n_modes=2, damped=False)
    k = int(np.argmin(np.abs(diagram.eigenvalues[-1].imag - expected)))
    assert diagram.eigenvalues[-1, k].imag == pytest.approx(expected, rel=3e-7)
    assert diagram.kind is not None
    assert list(diagram.kind[:, k]) == ["torsional", "torsional"]
    assert list(diagram.whirl[:, k]) == ["none", "none"]
    assert all(c.mode != k for c in diagram.critical_speeds)
    m = fs.modes(model, speed=100.0, n_modes=2, damped=False)  # the expanded shapes' labels
    k = int(np.argmin(np.abs(m.eigenvalues.imag - expected)))
    assert m.kind[k] == "torsional" and m.whirl[k] == "none"
