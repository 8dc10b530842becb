"""The dense modal basis is refused when its memory, in bytes, exceeds the cap (mutation hunt 101c).

Rule (docs/limits.md, section on the size estimates): "modal basis: dense up to 900 free DOFs
(about 5 × 8 n² bytes), else sparse", and "`check_problem_size` refuses a design above
**2 GiB**". :func:`~flexshaft.analyses.reduced_basis.modal_basis` applies the same cap itself
to a dense basis asked for explicitly (``method="dense"``): five dense n × n float64 matrices,
8 bytes an entry, against ``HARD_MEMORY_BYTES``.

A real 2 GiB case needs n ≈ 7,300 free DOFs (a dense eigen-solve of minutes), so the cap is
lowered here on the module (``monkeypatch``) for a small model: tests/test_eigen_accuracy.py's
steel tube with 8 elements, n = 52 free DOFs, 5 × 8 n² = 108,160 bytes. With the cap at half
that (54,080 bytes; above 5 n² = 13,520, the count without the 8 bytes an entry) the basis is
refused with its message; with the cap just above 40 n² it is computed. The numbers are exact
integers: no tolerance.

CPU: one 52-DOF model and one dense 4-mode basis: about 0.05 s.
"""

from __future__ import annotations

import pytest
from test_eigen_accuracy import SHAFT

import flexshaft
import flexshaft.analyses.reduced_basis as reduced_basis
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.design import loads_design


def test_a_dense_basis_over_the_byte_cap_is_refused(monkeypatch):
    model = flexshaft.build_model(loads_design(SHAFT.replace("shaft_elements = 30", "shaft_elements = 8")))
    n = model.dofs.free.size
    assert n == 52  # 9 nodes × 6 DOFs, u and θ fixed at the start
    need = 5 * 8 * n * n  # bytes: docs/limits.md's 5 × 8 n²
    monkeypatch.setattr(reduced_basis, "HARD_MEMORY_BYTES", need // 2)
    with pytest.raises(RefusedInputError, match="dense modal basis of 4 modes on 52 free DOFs"):
        reduced_basis.modal_basis(model, 4, method="dense")
    monkeypatch.setattr(reduced_basis, "HARD_MEMORY_BYTES", need + 1)
    w2, Phi = reduced_basis.modal_basis(model, 4, method="dense")
    assert Phi.shape == (n, 4)
