"""``model_guards`` reports a refused modal basis once, and nothing that depends on it.

The analyses' preflight (flexshaft.analyses.preflight) builds the modal basis first and stops
there when it is refused: every later check (the modes at the operating speed) starts from that
basis (its docstring: "the modes need the basis"), so ``flexshaft check`` names the cause once.
Reference design: the Jeffcott rotor of tests/rotors.py with a nearly massless tube (density
1e-6 kg/m³) and its supports removed, a free member with almost no mass, whose basis the
eigen-solver refuses (tests/test_api_guards.py shows the first problem; here, the whole list).
"""

from __future__ import annotations

from rotors import jeffcott_text

from flexshaft.analyses.preflight import model_guards
from flexshaft.design import loads_design


def test_a_refused_basis_is_the_only_problem() -> None:
    text = (
        jeffcott_text(0.0, 0.0)
        .replace("density = 0.1", "density = 1e-6")
        .replace('fixed_start = ["u", "v", "w", "theta"]', "")
        .replace('fixed_end = ["v", "w"]', "")
    )
    problems = model_guards(loads_design(text))
    assert [problem.path for problem in problems] == ["shaft.material"]
    assert "almost no mass" in problems[0].message
