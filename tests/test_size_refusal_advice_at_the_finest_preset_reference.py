"""What a problem-size refusal tells a user of the finest resolution preset (flexshaft.assembly.size).

Reference (API contract: the code's own rule). ``_finer_than_fine``'s docstring
(src/flexshaft/assembly/size.py, near line 399): "(``"resolution"``, advice) when a grid of
``resolution`` is finer than :data:`FINE`'s: a refusal then names the resolution", and the
advice it gives (near line 407): "use coarser grids (the presets fs.SCREENING to fs.FINE)". So a
design assessed at ``FINE`` itself uses a preset of that range and no grid finer than
``FINE``'s: its refusal must name what else to change (on a small design without imbalance
cases or controller states, the mesh ``mesh.shaft_elements``), not ``resolution``; telling it
to coarsen its grids *to* that range would contradict the advice's own words. One spin-up speed
more than ``FINE``'s (1,302 instead of 1,301) is finer than ``FINE`` and must be named
``resolution``. Context only: docs/architecture.md lists the resolution presets up to ``FINE``
("twice the report's density, to check convergence"), and docs/limits.md, section 5, says that
``check_problem_size`` refuses a design above its caps "with the numbers and what to change".

The design is the validation's Jeffcott rotor (``validation/designs/jeffcott_internal_damping.toml``,
8 shaft elements, 54 DOFs); ``hard_time`` is lowered to 1 ms so that any estimate (seconds)
is over it. No model is built; each check takes milliseconds.
"""

from __future__ import annotations

import dataclasses
import tomllib

import pytest

from flexshaft.assembly.size import check_problem_size
from flexshaft.design import DesignError, baseline_design, design_from_dict
from flexshaft.resolution import FINE, SCREENING
from flexshaft.validation.runner import design_text

JEFFCOTT = design_from_dict(tomllib.loads(design_text("jeffcott_internal_damping.toml")))


def refused_paths(resolution) -> set[str]:
    """Field paths of the refusal of the Jeffcott assessment at ``resolution`` over a 1 ms time cap."""
    with pytest.raises(DesignError) as refusal:
        check_problem_size(JEFFCOTT, "assess", resolution, hard_time=1e-3)
    return {problem.path for problem in refusal.value.problems}


def test_a_refusal_at_the_fine_preset_names_the_mesh_not_the_resolution():
    """At exactly FINE's grids the refusal names the mesh and not the resolution."""
    paths = refused_paths(FINE)
    assert "mesh.shaft_elements" in paths
    assert "resolution" not in paths


def test_a_refusal_finer_than_fine_names_the_resolution():
    """One spin-up speed more than FINE's is a custom, finer grid: the refusal names ``resolution``."""
    finer = dataclasses.replace(FINE, name="finer", spinup_speeds=FINE.spinup_speeds + 1)
    assert "resolution" in refused_paths(finer)


def mesh_advice(design) -> str:
    """The refusal's advice at ``mesh.shaft_elements`` for ``design`` assessed at SCREENING over a 1 ms cap."""
    with pytest.raises(DesignError) as refusal:
        check_problem_size(design, "assess", SCREENING, hard_time=1e-3)
    (message,) = [p.message for p in refusal.value.problems if p.path == "mesh.shaft_elements"]
    return message


def test_the_mesh_advice_counts_boom_elements_only_with_a_tailboom():
    """``mesh.boom_elements`` is the "Approximate number of tailboom elements" (the ``Mesh``
    docstring, src/flexshaft/design/schema.py): a design without a ``[tailboom]`` has none, and
    the advice for the Jeffcott rotor (no tailboom, 8 shaft elements, default boom_elements 24)
    must not tell its user that 24 boom elements make its DOFs. The baseline, with its
    tailboom, is told both counts (36 and 24)."""
    assert JEFFCOTT.tailboom is None and JEFFCOTT.mesh.boom_elements == 24
    jeffcott = mesh_advice(JEFFCOTT)
    assert jeffcott.startswith("8 shaft elements (no tailboom) give ")
    assert "boom elements" not in jeffcott
    assert mesh_advice(baseline_design()).startswith("36 shaft and 24 boom elements give ")


def test_the_size_summary_counts_boom_nodes_only_with_a_tailboom():
    """The size summary (what a size warning prints) of the Jeffcott rotor: 8 shaft elements,
    9 nodes, no tailboom, says so instead of counting "0 boom nodes"; the baseline (tailboom)
    gives both counts."""
    from flexshaft.assembly.size import problem_size

    assert "(9 shaft nodes, no tailboom)" in problem_size(JEFFCOTT, "assess", SCREENING).summary()
    baseline = problem_size(baseline_design(), "assess", SCREENING)
    assert f"shaft and {baseline.boom_nodes:,} boom nodes)" in baseline.summary() and baseline.boom_nodes > 0
