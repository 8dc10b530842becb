"""A magnet's coil turns at the floor of their range: above 0, and the gains grow as N².

docs/limits.md, section 1 (hand-written): "| `Current`, `CoilTurns`, `PoleArea` | magnet geometry
| above 0, up to 10 kA, 1e5 turns, 10 m² |". A magnet of zero turns has no ampere-turns: for the
differential pair (F = μ₀N²A cos α/4 [(i₀ + i)²/(g₀ − x)² − (i₀ − i)²/(g₀ + x)²], linearised)
its gains k_i = μ₀N²A cos α i₀/g₀² and k_s = k_i i₀/g₀ are both 0, a bearing that cannot pull.
The schema refuses it at ``coil_turns`` with a DesignError naming the field; were the schema to
let it pass, the model build would fail later with a bare ValueError from elements/magnetic.py.

The smallest whole coils are built with those closed forms (derived here from the force law
above, α = 22.5° the default pole angle): A = 1e-2 m², i₀ = 1 A, g₀ = 1 mm give for N = 1
k_i = 4π·1e-7 · 1e-2 · cos 22.5° / 1e-6 = 1.161e-2 N/A and k_s = 11.61 N/m, and N = 2 gives four
times both. The model's actuator carries them (on the Jeffcott rotor of tests/rotors.py with
the bearing at its disk). Tolerance rtol 1e-12: a few products of doubles; μ₀ is the same
4π·1e-7 in the code and here (it differs from CODATA 2018 by 5.5e-10, irrelevant to a
comparison of the same constant). CPU: two 4-element models, milliseconds.
"""

from __future__ import annotations

import math

import pytest
from rotors import jeffcott_text

from flexshaft.assembly import build_model
from flexshaft.design import DesignError, loads_design

MU_0 = 4.0e-7 * math.pi
AREA, BIAS, GAP = 1e-2, 1.0, 1e-3


def design_text(turns: float) -> str:
    text = jeffcott_text(0.0, 0.0, elements=4)
    head, tail = text.split("[[bearings]]")
    tail = tail[tail.index("[[disks]]") :]
    bearing = "\n".join(
        [
            'kind = "active"',
            "kp = 5000.0",
            "kd = 2.0",
            f"coil_turns = {turns!r}",
            f"pole_area = {AREA!r}",
            f"bias_current = {BIAS!r}",
            f"air_gap = {GAP!r}",
        ]
    )
    return f'{head}[[bearings]]\nname = "b"\nx = 0.5\n{bearing}\n{tail}'


def test_a_magnet_of_zero_turns_is_refused_at_its_coil_turns():
    with pytest.raises(DesignError, match=r"bearings\[0\]\.coil_turns: must be > 0"):
        loads_design(design_text(0.0))


@pytest.mark.parametrize("turns", [1.0, 2.0])
def test_the_smallest_coils_give_gains_growing_as_turns_squared(turns):
    model = build_model(loads_design(design_text(turns)))
    (actuator,) = model.actuators
    k_i = MU_0 * turns**2 * AREA * math.cos(math.radians(22.5)) * BIAS / GAP**2
    assert actuator.current_gain == pytest.approx(k_i, rel=1e-12)
    assert actuator.negative_stiffness == pytest.approx(k_i * BIAS / GAP, rel=1e-12)
