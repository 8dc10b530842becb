"""``model_guards`` reports a refused modal basis once, first, and not again as the modes' fault.

The analyses' preflight (flexshaft.analyses.preflight) builds the modal basis first; when it is
refused, the modes at the operating speed, which start from that basis (the code's comment: "the
modes need the basis"), are not tried, so ``flexshaft check`` does not name the cause a second
time under ``design``. (Going on would also add the static and imbalance solves' own refusals,
``bearings`` and ``operating.speed_rpm``, which do not use the basis; this test asserts only what
the basis rule states.)
Reference design: the Jeffcott rotor of tests/rotors.py with a nearly massless tube (density
1e-6 kg/m³) and its supports removed, a free member with almost no mass, whose basis the
eigen-solver refuses (tests/test_api_guards.py shows the first problem; here, the whole list).
"""

from __future__ import annotations

from test_api_guards import free_massless_jeffcott_text

from flexshaft.analyses.preflight import model_guards
from flexshaft.design import loads_design


def test_a_refused_basis_is_the_only_problem() -> None:
    problems = model_guards(loads_design(free_massless_jeffcott_text()))
    paths = [problem.path for problem in problems]
    assert paths[0] == "shaft.material" and paths.count("shaft.material") == 1
    assert "design" not in paths  # the modes' refusal of the same basis is not reported
    assert "almost no mass" in problems[0].message
