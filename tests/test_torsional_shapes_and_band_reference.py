r"""Torsional mode shapes of two inertias on a light shaft, and whether a mode lies inside its
nearest excitation's band.

Mode shapes (closed form, derived here). A disk J₁ at the forward end and a rigidly driven tail
rotor J₂ = J_tr/n² at the aft twist, on a shaft of stiffness k = G J_p/L and negligible
inertia, free in twist: the rigid-body twist θ₁ = θ₂ and the flexible mode θ₁/θ₂ = −J₂/J₁
(zero angular momentum). Mass-normalised (φᵀMφ = 1, stated in the :class:`TorsionalModes`
docstring only, not in docs/*.md):

.. math:: θ_{rigid} = 1/\sqrt{J_1 + J_2},\qquad θ_2^2 = J_1/(J_2 (J_1 + J_2)),\quad θ_1 = -θ_2 J_2/J_1 .

The shaft's inertia ρ J_p L (density 1e-2 kg/m³: 6.8e-8 kg m²) is 7e-8 of J₁ + J₂ but 2.3e-7
of the lighter end's J₁ (and the hub disk's 1 kg adds nothing in twist): it moves these
values by up to a few 1e-7 (measured 9e-8, 1.5e-7, 2.5e-7); 1e-6 relative is asserted (the
eigen-solver's round-off on this 9-DOF problem is of order 1e-13).

Band (docs/model.md, torsional separation: the margin is "`1 − f_n/f_lo` below it, `f_n/f_hi −
1` above, 0 inside"; docs/requirements.md's `torsional_separation` row the same; the
:class:`TorsionalSeparation` docstring: ``within_range`` is "True when the natural frequency lies
inside the excitation's band"). The one-mode shaft of
tests/test_torsional.py's series test (held forward twist, drive spring k_in, rotor J_tr/n²:
f₁ = √(k_eff n²/J_tr)/2π, 1/k_eff = 1/k + 1/k_in; the model's f₁ differs from it by 5.7e-10
(measured: the nearly massless shaft), 3e-7 asserted) run with the tail rotor's 1/rev at
0.95 f₁, 1.00 f₁ and 1.05 f₁ over a ±2 % speed range: the band [0.98, 1.02] × f_e lies below
f₁, holds it, and lies above it. Its nearest excitation is that 1/rev (the shaft's 1/rev is
n = 3.4 times higher, the blade passage 5 times).

Written for the mutations h58e-torsion-shapes-unit-peak and h58e-torsion-within-range-open-above
of scripts/mutations.toml. CPU: three 8-element models, about 0.1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_torsional import K_SHAFT, shaft_text

from flexshaft.analyses.torsional import torsional_modes, torsional_separation
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def _text(tables: str, fixed_start: str, rpm: float = 3000.0, speed_range: str = "") -> str:
    """A steel tube on two stiff contact bearings, 8 elements, nearly massless."""
    return shaft_text(tables, fixed_start, rpm=rpm, operating=speed_range)


def test_two_inertia_mode_shapes_are_mass_normalised():
    """Rigid twist 1/√(J₁ + J₂) at both ends; flexible θ₂² = J₁/(J₂(J₁ + J₂)), θ₁ = −θ₂ J₂/J₁."""
    J1, J_tr, n = 0.3, 4.0, 2.5
    J2 = J_tr / n**2
    text = _text(
        f'[[disks]]\nname = "hub"\nx = 0.0\nmass = 1.0\npolar_inertia = {J1}\n'
        f"[tail_rotor]\nblades = 3\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\n",
        fixed_start='["u", "v", "w"]',
    )
    model = build_model(loads_design(text))
    tm = torsional_modes(model, 2)
    fore, aft = model.dofs.shaft(0, "theta"), model.dofs.shaft(model.dofs.n_shaft_nodes - 1, "theta")
    rigid, flexible = tm.shapes[:, 0], tm.shapes[:, 1]
    assert abs(rigid[fore]) == pytest.approx(1.0 / np.sqrt(J1 + J2), rel=1e-6)
    assert abs(rigid[aft]) == pytest.approx(1.0 / np.sqrt(J1 + J2), rel=1e-6)
    theta2 = np.sqrt(J1 / (J2 * (J1 + J2)))
    assert abs(flexible[aft]) == pytest.approx(theta2, rel=1e-6)
    assert flexible[fore] / flexible[aft] == pytest.approx(-J2 / J1, rel=1e-6)


@pytest.mark.parametrize(("ratio", "inside"), [(0.95, False), (1.00, True), (1.05, False)])
def test_within_range_holds_only_a_mode_inside_the_band(ratio, inside):
    """Tail-rotor 1/rev at ``ratio`` × f₁, band ±2 %: f₁ above it, inside it, below it."""
    J_tr, n, k_in = 12.0, 3.4, 4.0e4
    k_eff = 1.0 / (1.0 / K_SHAFT + 1.0 / k_in)
    f1 = np.sqrt(k_eff * n**2 / J_tr) / (2 * np.pi)
    text = _text(
        f"[tail_rotor]\nblades = 5\npolar_inertia = {J_tr}\ngearbox_ratio = {n}\ninput_stiffness = {k_in}\n",
        fixed_start='["u", "v", "w", "theta"]',
        rpm=ratio * f1 * n * 60.0,
        speed_range="speed_range = [0.98, 1.02]",
    )
    (first, *_) = torsional_separation(build_model(loads_design(text)))
    assert first.excitation == "tail rotor 1/rev"
    assert first.natural_frequency == pytest.approx(f1, rel=3e-7)
    low, high = first.band
    assert low == pytest.approx(0.98 * ratio * f1, rel=1e-9) and high == pytest.approx(1.02 * ratio * f1, rel=1e-9)
    assert first.within_range is inside
    assert (first.margin == 0.0) is inside
