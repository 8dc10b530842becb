"""The problem-size estimate's memory and cost terms on the Jeffcott rotor, counted by hand
(flexshaft.assembly.size).

The estimate gates every run (refused above the hard caps, warned above the soft ones), so a
term counted wrong refuses a legal job or lets a hopeless one start. On the validation's Jeffcott
rotor (``validation/designs/jeffcott_internal_damping.toml``: 8 elements, 9 shaft nodes, 54 DOFs,
fixed_start 4 + fixed_end 2: 48 free, no tailboom, no tail rotor; see
tests/test_size_estimate_hand_count_reference.py for those counts):

* the banded harmonic solver: LAPACK's banded LU (zgbtrf: its band array needs
  LDAB >= 2*KL+KU+1 rows) of a matrix with kl = ku sub- and super-diagonals keeps 2 kl + ku + 1 = 3 kl + 1 rows
  of n complex entries (16 bytes, complex128); the estimate holds two such arrays (the matrix and
  its factor). Without a tailboom the half-bandwidth is 12 (one node's 6 DOFs and the next's): so
  16 × 48 × 37 × 2 = 56 832 bytes, with nothing measured;
* the every-root check of a design with controller states is a dense eigen-solution of the
  whole first-order model: 2 states per free DOF plus the controllers' states of both lateral
  directions (2 × 2 for the order-2 law D(s) = s² + 3s + 2), so 2 × 48 + 2 × 4 = 104 states, and
  three complex 104 × 104 matrices (one per speed: rest, operating, onset) of 16 bytes:
  3 × 16 × 104² = 519 168 bytes. A collocated bearing whose controller has states is *not*
  passive: the exact check's matrices are counted;
* the torsional modes: one twist DOF per shaft node (9; the Jeffcott rotor has no tail rotor, so
  no drive-train DOF), a dense complex eigen-solution of 2 × 9 states, costed
  _TORSION_FIXED + _TORSION_CUBIC × 18³ (the module's calibrated constants: the count 18 is the
  hand-counted part);
* the hard caps are 2 GiB and 4 hours (docs/limits.md: "check_problem_size refuses a design
  above 2 GiB or 4 hours").

Each design is built from a dictionary (no model is assembled): a few ms.
"""

from __future__ import annotations

import copy
import tomllib
import warnings

import pytest

from flexshaft.assembly import size as size_module
from flexshaft.assembly.size import HARD_MEMORY_BYTES, HARD_TIME_SECONDS, ProblemSizeWarning, problem_size
from flexshaft.design import design_from_dict
from flexshaft.resolution import SCREENING
from flexshaft.validation.runner import design_text

JEFFCOTT = tomllib.loads(design_text("jeffcott_internal_damping.toml"))


def _size(data, analysis="assess"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        return problem_size(design_from_dict(data), analysis, SCREENING)


def _with_active(**fields):
    data = copy.deepcopy(JEFFCOTT)
    bearing = {
        "name": "amb",
        "kind": "active",
        "x": 0.5,
        "controller": {"numerator": [1.0, 2.0, 1.0], "denominator": [1.0, 3.0, 2.0]},
        "gap": 1e-3,
        "force_capacity": 100.0,
    }
    bearing.update(fields)
    data["bearings"] = [bearing]
    return data


def test_the_banded_harmonic_solver_holds_two_complex_band_arrays():
    """16 bytes × 48 free DOFs × (3 × 12 + 1) band rows × 2 arrays, exactly (integers in floats)."""
    s = _size(JEFFCOTT)
    assert s.free_dofs == 48
    assert s.memory["banded harmonic solver"] == 16 * 48 * (3 * 12 + 1) * 2


def test_the_exact_every_root_check_counts_both_directions_controller_states():
    """A collocated bearing with an order-2 controller: 4 controller states, 104 first-order
    states, three complex 104² matrices (3 × 16 × 104² bytes); the check is not the passive one."""
    s = _size(_with_active())
    assert (s.free_dofs, s.controller_states) == (48, 4)
    assert s.memory["every-root state matrix"] == 3 * 16 * (2 * 48 + 2 * 4) ** 2


def test_a_passive_design_has_no_exact_every_root_matrix():
    """A PD law (no controller states) at a collocated sensor is passive: no dense whole-model
    eigen-solution is costed."""
    s = _size(_with_active(controller=None, kp=1.0e5, kd=10.0))
    assert s.controller_states == 0
    assert "every-root state matrix" not in s.memory


def test_the_torsional_modes_are_costed_on_one_twist_per_node():
    """9 twist DOFs, 18 first-order states, one operating point (no [envelope])."""
    s = _size(JEFFCOTT)
    expected = size_module._TORSION_FIXED + size_module._TORSION_CUBIC * (2.0 * 9) ** 3
    assert s.time["torsional modes"] == pytest.approx(expected, rel=1e-12)


def test_the_hard_caps_are_the_documented_ones():
    """docs/limits.md: 2 GiB and 4 hours."""
    assert HARD_MEMORY_BYTES == 2 * 1024**3
    assert HARD_TIME_SECONDS == 4 * 3600.0
