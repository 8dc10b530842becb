"""The problem-size estimate's DOF count with an elastic tail-rotor drive, and which cap refuses
and which warns, against the numbering and the rule of the hand-written docs.

* **DOFs.** docs/model.md ("Global numbering"): six DOFs per shaft node, five per boom node,
  then the *extra* DOFs, "the tail rotor's twist behind an elastic drive". A 2 m tube meshed in
  4 elements with its only bearing at the aft end has the 5 stations 0, 0.5, ..., 2 m
  (tests/test_assembly_load_resultants_reference.py asserts this mesh), no boom and one
  extra DOF with a ``[tail_rotor]`` of finite input stiffness: 6 · 5 + 1 = 31 DOFs, of which
  fixed_start (4) and fixed_end (2) are held: 25 free.
* **Caps.** docs/limits.md (section 5): ``check_problem_size`` "refuses a design above 2 GiB
  or 4 hours (estimated) ... and warns (``ProblemSizeWarning``) above 512 MiB, 10 minutes" —
  the hard cap refuses, the soft cap only warns. With the time caps given explicitly
  (soft 1e-9 s, hard 1e9 s) any estimate lies between them: a warning and the size, no error;
  a refusal (DesignError) is failed explicitly, which is what catches a time held to the soft
  cap.

Counts are integers (exact); no floating-point tolerance.

Written for the mutations h54c-size-drive-dofs-dropped and h54c-size-time-cap-soft of
scripts/mutations.toml.
"""

from __future__ import annotations

import pytest

from flexshaft.assembly.size import ProblemSizeWarning, check_problem_size, problem_size
from flexshaft.design import DesignError, design_from_dict


def _design(**extra):
    data = {
        "name": "tube with an elastic tail-rotor drive",
        "materials": {"al": {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0, "loss_factor": 0.0}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "al",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
        },
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed_rpm": 3000.0, "power": 50.0e3},
        "loads": {"eccentricity": 0.0},
        "mesh": {"shaft_elements": 4},
    }
    data.update(extra)
    return design_from_dict(data)


ROTOR = {"blades": 4, "polar_inertia": 1.0, "gearbox_ratio": 2.0, "input_stiffness": 2.0e3}


def test_the_estimate_counts_the_tail_rotor_twist():
    size = problem_size(_design(tail_rotor=ROTOR), "model")
    assert (size.shaft_nodes, size.boom_nodes) == (5, 0)
    assert size.dofs == 6 * 5 + 1
    assert size.free_dofs == 6 * 5 + 1 - 6
    plain = problem_size(_design(), "model")
    assert plain.dofs == 6 * 5


def test_an_estimate_between_the_time_caps_warns_and_is_not_refused():
    design = _design()
    with pytest.warns(ProblemSizeWarning):
        try:
            size = check_problem_size(design, "model", soft_time=1e-9, hard_time=1e9)
        except DesignError as e:
            pytest.fail(f"an estimate below the hard time cap was refused: {e}")
    assert 1e-9 < size.time_seconds < 1e9
