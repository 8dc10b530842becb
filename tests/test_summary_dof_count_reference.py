"""The model summary's DOF counts (``results.json``'s ``summary``) against a hand count from the
numbering documented in docs/model.md ("Coordinates and DOFs"):

    [ shaft node 0: u v w θ β γ | shaft node 1 | ... | boom node 0: v w θ β γ | ... | extra ]

so a shaft node carries 6 DOFs and a boom node 5; "Constrained DOFs are listed in
``model.dofs.fixed``; analyses work on ``model.dofs.free``", and "The boom root is clamped; the
shaft ends are constrained in the DOFs listed in ``shaft.fixed_start`` / ``shaft.fixed_end``".

The model (derived here): the tests' Jeffcott rotor with 2 shaft elements (the disk and the
damper sit at the midspan node: 3 shaft nodes) on a 2-element tail boom (3 boom nodes), no tail
rotor (no extra DOF). Total 6·3 + 5·3 = 33; constrained: ``fixed_start`` (u, v, w, θ) 4 +
``fixed_end`` (v, w) 2 + the clamped boom root's 5 = 11; free 33 − 11 = 22. The counts are
integers: exact equality.

That ``dofs`` means all the DOFs, the constrained ones included, is inferred here from the key
beside it: the summary also reports ``free_dofs``, which would be redundant if ``dofs`` counted
only the free ones (no document states it).
"""

from __future__ import annotations

from rotors import jeffcott_text
from test_summary_reference import BOOM

from flexshaft.analyses.summary import model_summary
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

SHAFT_NODES, BOOM_NODES = 3, 3
SHAFT_NODE_DOFS, BOOM_NODE_DOFS = 6, 5
FIXED = 4 + 2 + 5


def test_dof_counts_are_the_documented_numbering():
    """dofs = 6 per shaft node + 5 per boom node = 33, every DOF and not only the free ones;
    free_dofs = 33 − 11 constrained = 22 (docstring of the module)."""
    text = jeffcott_text(0.01, 0.0, elements=2).replace("shaft_elements = 2", "shaft_elements = 2\nboom_elements = 2")
    s = model_summary(build_model(loads_design(text + BOOM)))
    total = SHAFT_NODE_DOFS * SHAFT_NODES + BOOM_NODE_DOFS * BOOM_NODES
    assert (s["shaft_nodes"], s["boom_nodes"]) == (SHAFT_NODES, BOOM_NODES)
    assert s["dofs"] == total == 33
    assert s["free_dofs"] == total - FIXED == 22
