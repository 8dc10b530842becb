"""Reference: the verdict's Campbell task tracks every mode up to a tenth above its ceiling.

The rule (:mod:`flexshaft.verdict.point_tasks`' module docstring and
:func:`~flexshaft.verdict.point_tasks.campbell_mode_count`): the diagram tracks at least
``resolution.campbell_modes`` modes and every undamped mode at rest (of K + K_a, M) below 1.1 ×
the ceiling (the diagram's top speed, ``scan_top`` × Ω_op, times the largest excitation order:
1/rev here, no rotor is given), plus two.

The model: the pinned-pinned steel tube of tests/test_campbell_mode_count_reference.py (D 50 mm,
wall 5 mm, L = 1 m), whose bending frequencies are Rayleigh's beam,

    ω_n² = EI k⁴ / (ρA (1 + k² r²)),  k = nπ/L,  r² = I/A,

each twice (the v and w planes), and Euler-Bernoulli's (r = 0) above them; the 10-element
mesh is within 1e-4 of them on ω₂ (that file). At Ω_op = 2400 rad/s and a two-speed diagram to
1.3 Ω_op the count reaches 1.1 × 3120 = 3432 rad/s: ω₁ ≈ 817 and ω₂ ≈ 3255 rad/s below it (ω₂
above the ceiling itself), ω₃ ≈ 7300 and the torsion 5015 above: 2 × 2 + 2 = 6 modes, not
``campbell_modes`` = 2.

A basis that ends below the ceiling is enlarged: the default basis of 60 modes
(:func:`~flexshaft.analyses.modal.default_basis_size`) of the same tube 2 m long in 20 elements
(120 free DOFs) ends at 74 000 rad/s; with 1.1 × the ceiling placed in the middle of the 7.8 %
gap between its 67th and 68th undamped modes (86 400 and 93 200 rad/s; Ω_op ≈ 62 750 rad/s,
inside the schema's speed limit) the count is 67 + 2 = 69, where a basis left at 60 modes
would count 62. The reference
frequencies come from the dense generalised eigenproblem of the free K and M (scipy's
``eigh``, not the analyses' modal basis), read where no frequency lies within 3.8 % of
the threshold, far beyond their round-off.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import scipy.linalg
from test_campbell_mode_count_reference import TEXT, _bending

from flexshaft.analyses.modal import default_basis_size
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.resolution import REPORT
from flexshaft.verdict.point_tasks import campbell_mode_count, campbell_task


def test_the_campbell_diagram_holds_the_second_bending_pair_above_its_ceiling():
    """The task's diagram tracks 6 modes; at rest two of them are the second bending pair,
    between Rayleigh's ω₂ (less 1e-3: the mesh's 1e-4 and round-off) and Euler-Bernoulli's."""
    resolution = dataclasses.replace(REPORT, campbell_speeds=2, campbell_modes=2)
    model = build_model(loads_design(TEXT))
    camp = campbell_task(model, resolution)
    assert camp.eigenvalues.shape == (2, 6), camp.eigenvalues.shape
    at_rest = np.abs(camp.eigenvalues[0].imag)
    low, high = 0.999 * _bending(2, True), _bending(2, False)
    second = at_rest[(at_rest > low) & (at_rest < high)]
    assert second.size == 2, (at_rest, low, high)
    assert 1.1 * resolution.scan_top * model.speed > high  # ω₂ is inside the 10 % margin


def _long_tube(speed: float | None = None) -> str:
    """The tube 2 m long in 20 elements (bearing stand-in at midspan), at ``speed`` [rad/s]."""
    text = TEXT.replace("shaft_elements = 10", "shaft_elements = 20").replace("x_end = 1.0", "x_end = 2.0")
    text = text.replace("x = 0.5", "x = 1.0")
    return text if speed is None else text.replace(f"speed = {2400.0}", f"speed = {speed}")


def test_a_basis_that_ends_below_the_ceiling_is_enlarged():
    model = build_model(loads_design(_long_tube()))
    free = model.dofs.free
    assert free.size == 120 and not model.actuators  # K_a = 0: no active bearing
    K = model.K.toarray()[np.ix_(free, free)]
    M = model.M.toarray()[np.ix_(free, free)]
    omega = np.sqrt(np.clip(scipy.linalg.eigh(K, M, eigvals_only=True), 0.0, None))
    wanted = math.sqrt(omega[66] * omega[67])  # 1.1 × the ceiling, between the 67th and 68th
    assert omega[67] / omega[66] > 1.07 and omega[59] < 0.9 * omega[66]  # the 60-mode basis ends below
    resolution = dataclasses.replace(REPORT, campbell_speeds=2, campbell_modes=2)
    assert default_basis_size(resolution.campbell_modes) < 67  # fewer basis modes than lie below
    model = build_model(loads_design(_long_tube(wanted / (1.1 * resolution.scan_top))))
    assert abs(1.1 * resolution.scan_top * model.speed / wanted - 1.0) < 1e-12
    assert campbell_mode_count(model, resolution) == 67 + 2
