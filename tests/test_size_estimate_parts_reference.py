"""The problem-size estimate's parts against what they stand for (flexshaft.assembly.size):
the controller's order read from its denominator, and the banded solve's cost in the
half-bandwidth.

* **A law with an integrator.** A controller C(s) = N(s)/D(s) has deg D states per lateral
  direction, a pole at s = 0 included: D(s) = s² + 3s = s (s + 3) (an integrator and a lag;
  denominator [1, 3, 0], highest power first) is of order 2, so one such active bearing adds
  2 · 2 = 4 states, and the Jeffcott rotor's first-order model on its 48 free DOFs has
  2 · 48 + 4 = 100 states. The 100 is checked on the built model's state matrix
  (:func:`flexshaft.analyses.eigen.reduce` on every free DOF), independently of the estimate.
* **The banded solve's cost.** Gaussian elimination of a band matrix with bandwidths p = q = k
  costs about 2 n k² flops (Golub & Van Loan, Matrix Computations, §4.3), so one harmonic
  solve costs a + b n k². The estimate takes k = 24 with a tailboom and 12 without (module
  docstring of flexshaft.assembly.size, and tests/test_size_estimate_band_reference.py for
  the bands measured on built models): whatever a and b, the cost's increment per added free
  DOF with a boom over the one without is (24/12)² = 4, exactly (differences of floats of
  1e-3 to 1e-2 s: rel 1e-9).
* **The dense modal basis's cost.** Below the sparse limit the modal basis is a dense
  generalised symmetric eigen-solve, O(n³) (Golub & Van Loan, §8.3: tridiagonal reduction,
  4n³/3 flops, and the vectors): its time a + b n³. The Jeffcott rotor at 8, 16 and 32 elements
  has 6 (e + 1) − 6 = 48, 96 and 192 free DOFs (hand count: 6 DOFs a node, 6 held), so the
  increments of the ``"model"`` estimate's basis time stand in the ratio
  (192³ − 96³)/(96³ − 48³) = 8 (4 for a quadratic cost), whatever a and b.

* **The sparse modal basis's memory.** Above 900 free DOFs (with the basis of 60 modes below
  half of them) the basis is a shift-invert Lanczos solve, ``scipy.sparse.linalg.eigsh(K,
  k=nb, M=M, sigma=...)`` (flexshaft.analyses.reduced_basis): scipy's docstring gives its
  default number of Lanczos vectors, ``ncv = min(n, max(2*k + 1, 20))``, each of n doubles
  (the shift's sparse LU factor comes on top; it is not bounded here). At 160 elements
  (6 · 161 − 6 = 960 free DOFs) the estimate must hold at least 8 · 960 · (2 · 60 + 1) bytes.

* **The documented parts** (docs/limits.md, section 5, quoted): "`model` is the assembly
  (0.03 s + 2e-5 s × DOFs), one modal basis and two eigen-solutions"; "the projected spin-up
  scan 1e-6 s × n_s F + 1.2e-7 s × F²" for the one load case of a ``"mid_bay"`` placement (the
  other load cases of ``"worst"`` are extra); "the whirl stability 0.04 s + 7e-5 s × F + n_w ×
  (1e-2 s + 1.5e-6 s × F)" for a design without controller states (n_w = 21 whirl speeds at
  SCREENING, whose Campbell grid is empty). With controller states, each whirl speed's reduced
  eigen-solution grows from 2 nb to 2 nb + s states, so its extra time is
  eigen_seconds(2 nb + s) − eigen_seconds(2 nb): 96 → 100 on the Jeffcott rotor with an order-2
  law (nb = 48 modes: all its free DOFs), both sizes read from the built model's reduced state
  matrices. The times are sums of a few floats: rel 1e-12.

* **The exact every-root check** of a design with controller states or a remote sensor is "a
  dense eigen-solution of the whole model at three speeds" (docs/limits.md): each speed costs
  at least one first-order eigen-solution of 2 F + s states (``eigen_seconds``: one speed's
  solve with its tracking), here 2 · 48 = 96 for a PD law at a remote sensor, on top of the
  loops' 1.2e-3 s × F + 3.5e-7 s × F².
* **The torsional modes**: "0.02 s + 3.5e-9 s × (2 × twist DOFs)³" (docs/limits.md), the
  Jeffcott rotor's 9 shaft nodes each with a twist (no tail rotor: no drive-train DOF).
* **Every envelope point**: the time of an assessment "is the sum of its parts at each point of
  the design's `[envelope]`" (docs/limits.md): each per-point part of the tuned design (4
  points) is 4 times that of its operating point alone.

* **The thesis studies of ``flexshaft run``**: "6 s (imports, figures, files) and 9e-3 s +
  1.6e-5 s × F for each whirl speed of its thesis studies (6 eigen-solutions per whirl speed,
  18 with PD actuators)" (docs/limits.md): 18 for a PD law, 6 for an order-2 law (its gain map
  is not run: it varies K_p and K_d), each solve then larger by the controller's states as above.

No analysis is run; one 8-element model is built (a few ms): about 0.05 s in all.

Written for the mutations h50b-size-trim-trailing-zeros, h50b-size-harmonic-band-linear,
h50b-size-dense-basis-time-square, h50b-size-sparse-basis-no-lanczos-vectors,
h50b-size-model-one-eigen-solution, h50b-size-with-states-basis-not-doubled,
h50b-size-other-cases-all-cases, h50b-size-whirl-stability-campbell-grid,
h50b-size-roots-one-speed, h50b-size-torsion-not-doubled, h50b-size-point-parts-once and
h50b-size-gain-map-any-active of
scripts/mutations.toml.
"""

from __future__ import annotations

import copy
import tomllib
import warnings

import pytest

from flexshaft.analyses.eigen import reduce
from flexshaft.assembly import build_model
from flexshaft.assembly.size import ProblemSizeWarning, eigen_seconds, harmonic_seconds, problem_size
from flexshaft.design import design_from_dict
from flexshaft.resolution import SCREENING
from flexshaft.validation.runner import design_text

JEFFCOTT = tomllib.loads(design_text("jeffcott_internal_damping.toml"))


def _size(data, analysis="assess"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        return problem_size(design_from_dict(data), analysis, SCREENING)


def _with_law(numerator, denominator):
    data = copy.deepcopy(JEFFCOTT)
    data["bearings"] = [
        {
            "name": "amb",
            "kind": "active",
            "x": 0.5,
            "controller": {"numerator": numerator, "denominator": denominator},
            "gap": 1e-3,
            "force_capacity": 100.0,
        }
    ]
    return data


def test_an_integrator_pole_is_a_controller_state():
    """D(s) = s (s + 3): order 2, 4 states on the two lateral directions, 100 first-order
    states in all, as the built model's state matrix has."""
    data = _with_law([1.0, 5.0, 1.0], [1.0, 3.0, 0.0])
    s = _size(data)
    assert (s.free_dofs, s.controller_states) == (48, 4)
    model = build_model(design_from_dict(data))
    assert reduce(model, model.dofs.free.size).state_matrix(0.0).shape == (2 * 48 + 4,) * 2


def test_the_harmonic_solve_costs_the_square_of_the_half_bandwidth():
    """(h(2n, boom) − h(n, boom)) / (h(2n, no boom) − h(n, no boom)) = (24/12)² = 4."""
    n = 1000
    boom = harmonic_seconds(2 * n, True) - harmonic_seconds(n, True)
    bare = harmonic_seconds(2 * n, False) - harmonic_seconds(n, False)
    assert boom / bare == pytest.approx((24 / 12) ** 2, rel=1e-9)


def test_the_dense_modal_basis_costs_the_cube_of_the_free_dofs():
    """Increments of a + b n³ at n = 48, 96, 192: ratio 8 (differences of a few 1e-4 s beside
    a = 0.01 s: rel 1e-9)."""
    t = {}
    for elements in (8, 16, 32):
        data = copy.deepcopy(JEFFCOTT)
        data["mesh"]["shaft_elements"] = elements
        s = _size(data, "model")
        assert s.dense_basis and s.free_dofs == 6 * (elements + 1) - 6
        t[s.free_dofs] = s.time["modal basis"]
    assert (t[192] - t[96]) / (t[96] - t[48]) == pytest.approx(8.0, rel=1e-9)


def test_the_sparse_modal_basis_holds_its_lanczos_vectors():
    """960 free DOFs, nb = 60 modes: at least ncv = 121 Lanczos vectors, in doubles."""
    data = copy.deepcopy(JEFFCOTT)
    data["mesh"]["shaft_elements"] = 160
    s = _size(data, "model")
    n, nb = 960, 60
    assert s.free_dofs == n and not s.dense_basis
    assert s.memory["modal basis (sparse)"] >= 8 * n * max(2 * nb + 1, 20)


def test_the_model_estimate_is_one_basis_and_two_eigen_solutions():
    """48 free DOFs, a basis of 48 modes: two solves of 2 · 48 states."""
    s = _size(JEFFCOTT, "model")
    assert s.time["eigen-solutions"] == pytest.approx(2 * eigen_seconds(2 * 48), rel=1e-12)
    assert s.time["assembly"] == pytest.approx(0.03 + 2e-5 * 54, rel=1e-12)


def test_one_load_case_costs_the_documented_spin_up_scan():
    s = _size(JEFFCOTT)
    n_s, f = SCREENING.spinup_speeds, 48
    assert s.load_cases == 1 and s.n_speeds == n_s
    assert s.time["spin-up scan"] == pytest.approx(1e-6 * n_s * f + 1.2e-7 * f**2, rel=1e-12)


def test_the_whirl_stability_runs_over_the_whirl_speeds():
    s = _size(JEFFCOTT)
    n_w, f = SCREENING.whirl_speeds, 48
    assert (s.whirl_speeds, s.campbell_speeds) == (21, 0)
    expected = 0.04 + 7e-5 * f + n_w * (1e-2 + 1.5e-6 * f)
    assert s.time["whirl stability"] == pytest.approx(expected, rel=1e-12)


def test_controller_states_add_the_larger_solve_at_each_whirl_speed():
    pd = _with_law([1.0], [1.0])
    del pd["bearings"][0]["controller"]
    pd["bearings"][0].update(kp=1.0e5, kd=10.0)  # a PD law: no state
    law = _with_law([1.0, 5.0, 1.0], [1.0, 3.0, 2.0])  # order 2: 4 states
    sizes = []
    for data in (pd, law):
        model = build_model(design_from_dict(data))
        sizes.append(reduce(model, 48).state_matrix(0.0).shape[0])
    assert sizes == [96, 100]
    extra = _size(law).time["whirl stability"] - _size(pd).time["whirl stability"]
    # (a difference: h50b-size-with-states-basis-not-doubled, which changes what is subtracted
    # from the larger solve, cancels in it; the whirl-stability and gain-map parts' own tests
    # in this file catch that one)
    assert extra == pytest.approx(SCREENING.whirl_speeds * (eigen_seconds(100) - eigen_seconds(96)), rel=1e-9)


def test_the_exact_every_root_check_solves_at_three_speeds():
    data = _with_law([1.0], [1.0])
    del data["bearings"][0]["controller"]
    data["bearings"][0].update(kp=1.0e5, kd=10.0, sensor_offset=0.125)  # PD, remote sensor
    s = _size(data)
    f = 48
    assert s.controller_states == 0 and "every-root state matrix" in s.memory
    loops = 1.2e-3 * f + 3.5e-7 * f**2
    assert s.time["every-root check and loops"] - loops >= 3 * eigen_seconds(2 * f) * (1 - 1e-12)


def test_the_torsional_modes_cost_the_documented_complex_solve():
    s = _size(JEFFCOTT)
    assert s.shaft_nodes == 9
    assert s.time["torsional modes"] == pytest.approx(0.02 + 3.5e-9 * (2 * 9) ** 3, rel=1e-12)


def test_every_per_point_part_is_counted_at_each_envelope_point():
    from flexshaft.design import tuned_design

    design = tuned_design()
    points = len(design.envelope.points)
    assert points == 4
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        one = problem_size(design.model_copy(update={"envelope": None}), "assess", SCREENING)
        every = problem_size(design, "assess", SCREENING)
    parts = (
        "spin-up scan",
        "whirl stability",
        "every-root check and loops",
        "torsional modes",
        "modes, strength, buckling, thermal",
    )
    for part in parts:
        assert every.time[part] == pytest.approx(points * one.time[part], rel=1e-12), part


def test_the_thesis_gain_map_is_counted_for_pd_laws_only():
    pd = _with_law([1.0], [1.0])
    del pd["bearings"][0]["controller"]
    pd["bearings"][0].update(kp=1.0e5, kd=10.0)
    law = _with_law([1.0, 5.0, 1.0], [1.0, 3.0, 2.0])
    n_w, f = SCREENING.whirl_speeds, 48
    per_solve = 9e-3 + 1.6e-5 * f
    with_states = eigen_seconds(100) - eigen_seconds(96)
    assert _size(pd, "run").time["thesis studies and report"] == pytest.approx(6.0 + 18 * n_w * per_solve, rel=1e-9)
    expected = 6.0 + 6 * n_w * (per_solve + with_states)
    assert _size(law, "run").time["thesis studies and report"] == pytest.approx(expected, rel=1e-9)
