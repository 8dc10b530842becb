"""The problem-size estimate's modal basis and first-order state matrices, from its docstring's
rules and hand counts (mutation hunt h37c).

:mod:`flexshaft.assembly.size` documents: the modal basis is a dense generalised eigen-solve
(``8 n²`` bytes per matrix, about five such arrays) up to ``SPARSE_BASIS_ABOVE`` = 900 free DOFs;
the first-order eigen-problems have ``2 nb + s`` states (``nb`` modal coordinates, ``s``
controller states: displacement and velocity of each mode), four arrays of ``16 (2 nb + s)²``
bytes. ``nb`` is the run's basis, ``RUN_BASIS`` = 60 coordinates, or every free DOF when fewer.

On tests/test_size_estimate_hand_count_reference.py's Jeffcott rotor (1 m, 8 elements, 48 free
DOFs, counted there): nb = 48, 96 states; with its order-2 active bearing (4 states) 100. With
40 elements (h = 0.025 m, stations 0, 0.5, 1 m on the grid): 41 nodes × 6 − 6 = 240 free DOFs,
still dense (240 ≤ 900) although the 60-coordinate basis is below half of them: 5 · 8 · 240²
bytes; nb = 60, 120 states. Exact integer arithmetic in floats: compared exactly.
"""

from __future__ import annotations

from test_size_estimate_hand_count_reference import JEFFCOTT, active, jeffcott, size


def test_state_matrices_count_two_states_per_mode_plus_the_controllers():
    plain = size(JEFFCOTT)
    assert plain.free_dofs == 48
    assert plain.memory["state matrices"] == 4 * 16.0 * (2 * 48) ** 2
    with_law = size(jeffcott(bearings=[active()]))
    assert with_law.controller_states == 4
    assert with_law.memory["state matrices"] == 4 * 16.0 * (2 * 48 + 4) ** 2
    # independent of the bytes per entry: four states more than 96 scale it by 100²/96²
    # (each side one rounding of the same ratio: equal)
    assert with_law.memory["state matrices"] / plain.memory["state matrices"] == 100**2 / 96**2


def test_a_model_below_the_sparse_limit_takes_the_dense_basis():
    fine = size(jeffcott(mesh={"shaft_elements": 40}))
    assert fine.free_dofs == 240
    assert fine.dense_basis
    assert fine.memory["modal basis (dense)"] == 5 * 8.0 * 240**2
    assert fine.memory["state matrices"] == 4 * 16.0 * (2 * 60) ** 2
