"""The problem-size estimate's memory and cost terms on the Jeffcott rotor, against counts of the
model they stand for (flexshaft.assembly.size).

The estimate gates every run (refused above the hard caps, warned above the soft ones), so a
term counted wrong refuses a legal job or lets a hopeless one start. On the validation's Jeffcott
rotor (``validation/designs/jeffcott_internal_damping.toml``: 8 elements, 9 shaft nodes, 54 DOFs,
fixed_start 4 + fixed_end 2: 48 free, no tailboom, no tail rotor; see
tests/test_size_estimate_hand_count_reference.py for those counts):

* the banded harmonic solver: LAPACK's banded LU (zgbtrf: its band array needs
  LDAB >= 2 KL + KU + 1 rows) of n complex entries (16 bytes, complex128) per row. The estimate
  assumes a half-bandwidth of 12 without a tailboom (its bound, not a count: one node's 6 DOFs
  and the next's) and holds two arrays (the matrix and its factor) of 3 × 12 + 1 rows:
  16 × 48 × 37 × 2 = 56 832 bytes. Against the solver the built model really gets
  (:class:`~flexshaft.analyses.banded.BandedHarmonicSolver`'s kl, ku and n: kl = ku = 7,
  measured), the estimate's band covers the real one (12 ≥ kl, ku) and each of its two arrays
  is at least the real LU buffer, 16 n (2 kl + ku + 1) bytes;
* the every-root check of a design with controller states is a dense eigen-solution of the
  whole first-order model: displacement and velocity of each free DOF (2 × 48) plus the law's
  states on each lateral direction (the order-2 law C(s) = (s² + 5s + 1)/(s² + 3s + 2), no
  pole-zero cancellation, so 2 × 2), 100 states, and three 100 × 100 arrays (one per speed:
  rest, operating, onset) of 16 bytes an entry (complex128, as the eigenvectors are):
  3 × 16 × 100² = 480 000 bytes. The 100 is cross-checked on the built model: the state matrix
  of its reduction on every free DOF (:func:`flexshaft.analyses.eigen.reduce`) is 100 × 100.
  A remote sensor adds no state (the magnet's own −k_s is static: the module docstring of
  flexshaft.analyses.eigen), so the count and the built matrix stay 100; an amplifier lag adds
  one order (6 states, 102). A collocated bearing whose controller has states is *not*
  passive: the exact check's matrices are counted;
* the torsional modes are a dense complex eigen-solution of 2 × twist DOFs, costed a + b (2 t)³
  for t twist DOFs. The estimate counts one twist per shaft node plus the tail rotor's own DOF
  when its drive is elastic (held twists included: an upper bound); with the shaft's twist left
  free at the start the built torsional system has exactly 9 (8 elements), 10 (8 elements and an
  elastic tail rotor) and 17 (16 elements) DOFs, checked. Whatever a and b, the increments then
  stand in the ratio (t(8 el + rotor) − t(8 el)) / (t(16 el) − t(8 el)) = (20³ − 18³)/(34³ − 18³)
  = (10³ − 9³)/(17³ − 9³) = 271/4184 (six DOFs a node would give 8911/903744, 0.0099);
* the hard caps are 2 GiB and 4 hours (docs/limits.md: "check_problem_size refuses a design
  above 2 GiB or 4 hours").

Five tiny models are built (8 and 16 elements, a few ms each); about 0.1 s in all.
"""

from __future__ import annotations

import copy
import tomllib
import warnings

import pytest

from flexshaft.analyses.banded import BandedHarmonicSolver
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.torsional import torsional_system
from flexshaft.assembly import build_model
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
        "controller": {"numerator": [1.0, 5.0, 1.0], "denominator": [1.0, 3.0, 2.0]},
        "gap": 1e-3,
        "force_capacity": 100.0,
    }
    bearing.update(fields)
    data["bearings"] = [bearing]
    return data


def test_the_banded_harmonic_solver_covers_the_real_band_buffer():
    """The estimate: 16 bytes × 48 free DOFs × (3 × 12 + 1) band rows × 2 arrays, exactly
    (integers in floats); each of its arrays holds at least the built solver's LU buffer."""
    s = _size(JEFFCOTT)
    assert s.free_dofs == 48
    assert s.memory["banded harmonic solver"] == 16 * 48 * (3 * 12 + 1) * 2
    solver = BandedHarmonicSolver(build_model(design_from_dict(JEFFCOTT)))
    assert solver.n == 48 and max(solver.kl, solver.ku) <= 12
    assert s.memory["banded harmonic solver"] / 2 >= 16 * solver.n * (2 * solver.kl + solver.ku + 1)


@pytest.mark.parametrize(
    "fields, states",
    [({}, 4), ({"sensor_offset": 0.125}, 4), ({"amplifier_bandwidth": 500.0}, 6)],
    ids=["collocated", "remote sensor", "amplifier"],
)
def test_the_exact_every_root_check_counts_the_built_state_matrix(fields, states):
    """An order-2 law: 4 controller states (6 with an amplifier lag, order 3), 2 × 48 + 4 = 100
    first-order states (102), three arrays of 16 bytes an entry (3 × 16 × 100² bytes); the built
    model's state matrix is 100 × 100 (102 × 102), collocated or not; the check is not the
    passive one."""
    data = _with_active(**fields)
    s = _size(data)
    assert (s.free_dofs, s.controller_states) == (48, states)
    n = 2 * 48 + states
    assert s.memory["every-root state matrix"] == 3 * 16 * n**2
    model = build_model(design_from_dict(data))
    assert reduce(model, model.dofs.free.size).state_matrix(0.0).shape == (n, n)


def test_a_passive_design_has_no_exact_every_root_matrix():
    """A PD law (no controller states) at a collocated sensor is passive: no dense whole-model
    eigen-solution is costed."""
    s = _size(_with_active(controller=None, kp=1.0e5, kd=10.0))
    assert s.controller_states == 0
    assert "every-root state matrix" not in s.memory


def _twist_free(elements, rotor=False):
    data = copy.deepcopy(JEFFCOTT)
    data["shaft"]["fixed_start"] = ["u", "v", "w"]  # the twist left free: every node's twist counts
    data["mesh"]["shaft_elements"] = elements
    if rotor:  # an elastic drive: the rotor's own twist DOF
        data["tail_rotor"] = {"blades": 4, "polar_inertia": 12.0, "gearbox_ratio": 3.4, "input_stiffness": 1.0e5}
    return data


def test_the_torsional_cost_grows_with_the_cube_of_the_twist_dofs():
    """(10³ − 9³)/(17³ − 9³) = 271/4184: the increments of a + b (2t)³ cancel a and b, and their
    difference is a few 1e-5 s beside a of 0.02 s: rel 1e-9 leaves room for that cancellation
    (measured 1e-13)."""
    cases = {"8": _twist_free(8), "8+rotor": _twist_free(8, rotor=True), "16": _twist_free(16)}
    twists = {k: torsional_system(build_model(design_from_dict(d))).dofs.size for k, d in cases.items()}
    assert twists == {"8": 9, "8+rotor": 10, "16": 17}
    t = {k: _size(d).time["torsional modes"] for k, d in cases.items()}
    ratio = (t["8+rotor"] - t["8"]) / (t["16"] - t["8"])
    assert ratio == pytest.approx(271 / 4184, rel=1e-9)  # 10³ − 9³ = 271, 17³ − 9³ = 4184


def test_the_hard_caps_are_the_documented_ones():
    """docs/limits.md: 2 GiB and 4 hours."""
    assert HARD_MEMORY_BYTES == 2 * 1024**3
    assert HARD_TIME_SECONDS == 4 * 3600.0
