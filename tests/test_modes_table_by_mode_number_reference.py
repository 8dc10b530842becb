"""The modes' table for pandas is indexed by the mode number, from 1, in increasing frequency.

References:

* API contract (docstring of :meth:`~flexshaft.analyses.modal.Modes.to_dataframe`):
  ":meth:`table` as a :class:`pandas.DataFrame` indexed by the mode number (from 1)". README.md
  documents the same in its Python example (the comment on ``m.to_dataframe()``: "the same
  rows, modes numbered from 1 by damped frequency") and for the command line's tables (Output:
  "Modes are numbered from 1 (the Python API counts from 0) in increasing damped frequency").
* Closed form: a simply supported uniform Euler–Bernoulli beam has the bending frequencies
  ω_n = (nπ/L)² √(EI/(ρA)) (derived here: w = sin(nπx/L) satisfies w = w'' = 0 at both ends
  and EI w'''' = ρA ω² w for that ω); at rest each is a degenerate pair of the two lateral
  planes, so modes 2n − 1 and 2n both have f_n. The pinned tube of
  tests/test_montecarlo_unbalance_on_a_pinned_tube_reference.py (steel, D = 50 mm, wall 5 mm,
  L = 2 m, bearings of 1e11 N/m): f₁, f₂, f₃ = 32.51, 130.05, 292.62 Hz. Tolerance 1 %: the
  elements are Euler–Bernoulli (docs/model.md: Timoshenko shear "reduces exactly to
  Euler-Bernoulli when off, the thesis default"), but with rotary inertia ρI, which lowers f_n
  by about (nπ r_g/L)²/2 = 3.16e-4, 1.26e-3, 2.85e-3 for n = 1, 2, 3 with r_g = 16 mm (measured
  0.03, 0.13, 0.28 %); 20 elements are converged far below that. A table not indexed by the
  mode number reads mode 2 (32.5 Hz) as the row of mode 3 (130 Hz).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_montecarlo_unbalance_on_a_pinned_tube_reference import D_OUT, PINNED_TUBE, RHO, WALL, E, L

from flexshaft.analyses.modal import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design

pytest.importorskip("pandas")


def test_modes_table_rows_are_found_by_their_mode_number():
    table = modes(build_model(loads_design(PINNED_TUBE)), n_modes=6, damped=False).to_dataframe()
    assert table.index.name == "mode"
    assert list(table.index) == [1, 2, 3, 4, 5, 6]
    d_in = D_OUT - 2 * WALL
    ei = E * np.pi / 64 * (D_OUT**4 - d_in**4)
    rho_a = RHO * np.pi / 4 * (D_OUT**2 - d_in**2)
    for n in (1, 2, 3):
        f_n = (n * np.pi / L) ** 2 * np.sqrt(ei / rho_a) / (2 * np.pi)
        for mode in (2 * n - 1, 2 * n):
            assert table.loc[mode, "frequency_Hz"] == pytest.approx(f_n, rel=1e-2)
