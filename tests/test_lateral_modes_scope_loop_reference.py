"""lateral_modes solves more modes until one lies at or above the scope's end, when no cheap count
of the modes below it exists (flexshaft.verdict.operating_point).

Above WHOLE_DENSE_BASIS_UP_TO free DOFs the count of the modes below the onset requirement's
speed is not known before the solve (``_modes_below`` returns 0): the first solve holds the
asked lateral count plus one, and the loop must grow it until the last mode solved reaches
``up_to`` (its docstring: "until a mode at or above ``up_to`` is solved"). The model here is
made that large for real: the tube in 90 elements, 91 nodes × 6 − 6 held = 540 free DOFs (the
precondition is asserted), built and solved in a few hundredths of a second.

Reference (closed form, as in tests/test_whirl_damping_frequency_scope_reference.py): the
pinned-pinned steel tube of tests/rotors.py without its disk, bending modes
ω_k = (kπ/L)² √(EI/ρA) (ω₁ = 817 rad/s, ω₂ = 4 ω₁), each a pair of whirls. Asked for 2 lateral
modes with the scope ending at 1.15 Ω for Ω = ω₂/1.1 (so 1.045 ω₂): both whirls of the second
pair (within 2 % of ω₂: rotary inertia about 1 % and the gyroscopic split, measured 1.4 %) must
be held. Non-vacuity: a first solve of 3 modes, as the loop starts, holds only one of them (the
loop is what brings in the other). Tolerances as in that file.
"""

from __future__ import annotations

import re

import numpy as np
from rotors import DI, DO, E, L, jeffcott_text

from flexshaft.analyses.dense_spectrum import WHOLE_DENSE_BASIS_UP_TO
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.units import rad_s_to_rpm
from flexshaft.verdict import operating_point

RHO = 7850.0
AREA, INERTIA = np.pi * (DO**2 - DI**2) / 4, np.pi * (DO**4 - DI**4) / 64
OMEGA_2 = 4 * (np.pi / L) ** 2 * np.sqrt(E * INERTIA / (RHO * AREA))
SPEED = OMEGA_2 / 1.1

TEXT = re.sub(
    r"\[\[disks\]\]\n(?:[^\[\n][^\n]*\n)*",
    "",
    jeffcott_text(0.0, 250.0, elements=90)
    .replace("density = 0.1", f"density = {RHO}")
    .replace("speed_rpm = 0.0", f"speed_rpm = {rad_s_to_rpm(SPEED)}"),
)


def _second_pair_whirls(found) -> int:
    whirl = operating_point.whirl_modes(found)
    f = np.abs(found.eigenvalues.imag)
    return int(np.sum(whirl & (np.abs(f / OMEGA_2 - 1.0) < 0.02)))


def test_the_modes_solved_reach_the_scope_without_a_count_below_it():
    model = build_model(loads_design(TEXT))
    assert model.dofs.free.size > WHOLE_DENSE_BASIS_UP_TO  # no count below the scope: the loop decides
    up_to = 1.15 * SPEED
    assert OMEGA_2 < up_to
    assert _second_pair_whirls(operating_point.modes(model, SPEED, 3)) == 1  # the first solve stops inside
    assert _second_pair_whirls(operating_point.lateral_modes(model, SPEED, 2, up_to=up_to)) == 2
