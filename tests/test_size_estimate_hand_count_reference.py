"""The problem-size estimate's counts on tiny designs, counted by hand (flexshaft.assembly.size).

The estimate refuses or warns before anything is computed, so its counts are the numbers that
decide whether a job runs: a wrong count lets a job hang or refuses a legal one. Here every count
of :func:`~flexshaft.assembly.size.problem_size` is checked against a hand count on the
validation's Jeffcott rotor (``validation/designs/jeffcott_internal_damping.toml``: a 1 m shaft,
8 elements, pinned ends, one bearing and one disk at mid-span), varied one field at a time:

* nodes: the stations 0, 0.5 and 1 m lie on the 8-element grid (h = 0.125 m), so the shaft has
  8 + 1 = 9 nodes; a tailboom of 1 m with 4 elements and stations 0, 0.5, 1 m has 5;
* DOFs: 6 per shaft node (u, v, w, θx, θy, θz: axial, two lateral, twist and two slopes) and 5
  per boom node (the boom has no drive twist), so 6 · 9 = 54 and 6 · 9 + 5 · 5 = 79;
* fixed DOFs: ``fixed_start = [u, v, w, theta]`` (4) and ``fixed_end = [v, w]`` (2), and the
  boom's root clamp (its 5 DOFs): 6 and 11, so 48 and 68 free DOFs;
* controller states: a controller C(s) = N(s)/D(s) of order deg D has deg D states per lateral
  direction (v and w); an amplifier lag adds one order. A remote sensor adds none: the
  first-order model then realises two channels (module docstring of flexshaft.analyses.eigen),
  the magnet's own −k_s at the bearing, static, and the law from the sensing station, with the
  law's states. So D = s² + 3s + 2 gives 2 · 2 = 4 states, with a remote sensor 4 as well, with
  an amplifier 2 · 3 = 6, and a PD law (D = 1) none (the built state matrices are counted in
  tests/test_size_estimate_costs_reference.py);
* the "worst" imbalance placement: the bearings at n distinct stations bound n − 1 bays, and the
  worst case over the signs of the bays' imbalances, the first bay's sign being free (a global
  sign flip gives the same peak), is 2^(bays − 1) load cases; at most MAX_WORST_BAYS = 10 bays
  (512 cases, the documented maximum) are accepted, 11 refused;
* a dense nonsymmetric eigen-solve costs O(n³) (Golub & Van Loan, Matrix Computations, the QR
  algorithm: about 25 n³ flops with the vectors): the cost increments of n → 2n → 4n states are
  in the ratio (64 − 8)/(8 − 1) = 8, whatever the fixed cost and the constant.

Each design is built from a dictionary (no model is assembled): well under 1 s of CPU in all.
"""

from __future__ import annotations

import copy
import math
import tomllib
import warnings

import pytest

from flexshaft.assembly.size import MAX_WORST_BAYS, ProblemSizeWarning, check_problem_size, eigen_seconds, problem_size
from flexshaft.design import DesignError, design_from_dict
from flexshaft.resolution import SCREENING
from flexshaft.validation.runner import design_text

JEFFCOTT = tomllib.loads(design_text("jeffcott_internal_damping.toml"))


def jeffcott(**changes):
    """The Jeffcott rotor's dictionary with top-level tables replaced."""
    data = copy.deepcopy(JEFFCOTT)
    data.update(copy.deepcopy(changes))
    return data


def active(**fields):
    """An active bearing at mid-span with the controller D(s) = s² + 3s + 2 (order 2)."""
    bearing = {
        "name": "amb",
        "kind": "active",
        "x": 0.5,
        "controller": {"numerator": [1.0, 2.0, 1.0], "denominator": [1.0, 3.0, 2.0]},
        "gap": 1e-3,
        "force_capacity": 100.0,
    }
    bearing.update(fields)
    return bearing


def size(data, analysis="model", resolution=SCREENING):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        return problem_size(design_from_dict(data), analysis, resolution)


def test_shaft_nodes_dofs_and_fixed_dofs_of_the_jeffcott_rotor():
    """9 nodes × 6 DOFs = 54, minus the 4 + 2 pinned DOFs: 48 free; one bearing bounds no bay,
    counted as one, with one load case."""
    s = size(JEFFCOTT)
    assert (s.shaft_nodes, s.boom_nodes, s.dofs, s.free_dofs) == (9, 0, 54, 48)
    assert (s.bearings, s.actuators, s.disks, s.controller_states) == (1, 0, 1, 0)
    assert (s.bays, s.load_cases) == (1, 1)


def test_a_tailboom_adds_five_dofs_a_node_and_its_clamped_root():
    """A 1 m boom in 4 elements with the bearing at its 0.5 m station: 5 nodes × 5 DOFs = 25 more
    DOFs (79), of which the root's 5 are clamped (11 fixed, 68 free)."""
    data = jeffcott(
        tailboom={
            "length": 1.0,
            "root_semi_axes": [0.2, 0.15],
            "tip_semi_axes": [0.1, 0.08],
            "wall_thickness": 0.003,
            "material": "steel",
            "shaft_clearance": 0.05,
        },
        mesh={"shaft_elements": 8, "boom_elements": 4},
    )
    data["materials"]["steel"]["density"] = 7800.0
    s = size(data)
    assert (s.shaft_nodes, s.boom_nodes, s.dofs, s.free_dofs) == (9, 5, 79, 68)


@pytest.mark.parametrize(
    "fields, states",
    [
        ({}, 2 * 2),  # order 2, two lateral directions
        ({"sensor_offset": 0.1}, 2 * 2),  # a remote sensor adds none (its magnet's −k_s is static)
        ({"amplifier_bandwidth": 500.0}, 2 * 3),  # the amplifier lag adds one order
        ({"controller": None, "kp": 1.0e5, "kd": 10.0}, 0),  # PD: C(s) = kd s + kp over 1
    ],
    ids=["order 2", "remote sensor", "amplifier", "PD"],
)
def test_controller_states_are_the_order_per_direction(fields, states):
    s = size(jeffcott(bearings=[active(**fields)]))
    assert (s.actuators, s.controller_states) == (1, states)


def bearings_at(stations):
    """The Jeffcott rotor with the "worst" placement and a contact bearing at each station."""
    template = JEFFCOTT["bearings"][0]
    bearings = [dict(template, name=f"b{k}", x=x) for k, x in enumerate(stations)]
    return jeffcott(bearings=bearings, loads={"eccentricity": 1e-5, "imbalance_placement": "worst"})


@pytest.mark.parametrize("count", [3, 4, 6])
def test_the_worst_placement_has_two_to_the_bays_minus_one_cases(count):
    """``count`` bearings at distinct stations (on the element grid): count − 1 bays and
    2^(count − 2) load cases."""
    s = size(bearings_at([0.125 * k for k in range(1, count + 1)]), "assess")
    assert (s.bays, s.load_cases) == (count - 1, 2 ** (count - 2))


def test_ten_bays_are_accepted_eleven_refused():
    """The documented maximum: MAX_WORST_BAYS = 10 bays (11 bearings, 2^9 = 512 load cases) is
    accepted, 11 bays refused naming the placement (the caps on memory and time are lifted so
    that only the bay rule decides)."""
    assert MAX_WORST_BAYS == 10
    unlimited = {"hard_memory": math.inf, "hard_time": math.inf, "soft_memory": math.inf, "soft_time": math.inf}
    ten = design_from_dict(bearings_at([0.1 * k for k in range(11)]))
    assert check_problem_size(ten, "assess", SCREENING, **unlimited).load_cases == 512
    eleven = design_from_dict(bearings_at([k / 11.0 for k in range(12)]))
    with pytest.raises(DesignError, match=r"loads.imbalance_placement"):
        check_problem_size(eleven, "assess", SCREENING, **unlimited)


def test_the_eigen_solve_estimate_is_cubic_in_the_states():
    """(t(4n) − t(2n)) / (t(2n) − t(n)) = (64 − 8)/(8 − 1) = 8 for a cost a + b n³."""
    for n in (50, 200):
        ratio = (eigen_seconds(4 * n) - eigen_seconds(2 * n)) / (eigen_seconds(2 * n) - eigen_seconds(n))
        assert ratio == pytest.approx(8.0, rel=1e-12)
