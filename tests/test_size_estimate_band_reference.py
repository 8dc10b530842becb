"""The problem-size estimate's half-bandwidth and spin-up memory against the model they stand for
(flexshaft.assembly.size).

* **Half-bandwidth.** The estimate takes the banded harmonic solver's half-bandwidth k as 24
  with a tailboom and 12 without (docs: module docstring). What the solver really meets is
  measured here on the built model: the union pattern of K, M, G and C on the free DOFs,
  ordered as the solver orders it (:func:`flexshaft.analyses.banded.band_ordering`, along the
  driveline or reverse Cuthill-McKee), and its half-bandwidth max |pos(i) − pos(j)| over the
  pattern's entries computed here. By
  hand: without a boom the lateral DOFs (v, w, β, γ) of one node couple to the next node's
  only (the axial and twist DOFs form blocks of their own, ordered apart), so 2 · 4 − 1 = 7;
  with a boom a station holds up to 11 DOFs (a shaft node's 6, a boom node's 5) and an element
  or a bearing reaches the next station's, so at most 2 · 11 − 1 = 21, and more than the
  boom-less 7 (17 measured on the boomed test rotor). An estimate is
  useful when it neither undercounts the band (k ≥ measured) nor doubles it (k ≤ 2 measured).
  The memory is also bounded absolutely (below: LAPACK's band storage); otherwise ratios, so
  the constant factors of the estimate do not enter:
  - banded memory 16 F (3k + 1) bytes a band array (the estimate counts two): per free DOF, the boomed design over the
    boom-less one is (3 k_b + 1)/(3 k_s + 1), within a factor 2 of the measured widths' ratio;
  - banded LU time ∝ F k² (band Gaussian elimination costs about 2 n p q flops for bandwidths
    p, q: Golub & Van Loan, Matrix Computations, §4.3): the increment of
    :func:`~flexshaft.assembly.size.harmonic_seconds` per DOF with a boom over the one without is
    (k_b/k_s)², within a factor 4 of the measured widths' squared ratio.
* **Spin-up responses' memory** is 16 bytes (complex) per DOF, load case and speed: the
  "worst" placement over two bays (2^(2−1) = 2 load cases) holds twice the memory of the
  one-case "mid_bay" placement, everything else equal.

Cheap: two 8-element models and three estimates (no analysis run), about 0.2 s.

Written for the mutations h35c-size-harmonic-half-band-swapped,
h35c-size-problem-half-band-swapped and h35c-size-spinup-memory-one-case of
scripts/mutations.toml.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from flexshaft.analyses.banded import band_ordering
from flexshaft.assembly import build_model
from flexshaft.assembly.size import ProblemSizeWarning, harmonic_seconds, problem_size
from flexshaft.design import loads_design
from flexshaft.resolution import SCREENING

HEAD = """
name = "shaft on a tapered boom"
[materials.steel]
kind = "isotropic"
E = 210e9
G = 80e9
density = 7800.0
[materials.al]
kind = "isotropic"
E = 70e9
G = 26e9
density = 2700.0
[shaft]
x_start = 0.0
x_end = 2.0
outer_diameter = 0.08
wall_thickness = 0.003
material = "steel"
fixed_start = ["u", "theta"]
"""
BOOM = """
[tailboom]
length = 2.0
root_semi_axes = [0.25, 0.18]
tip_semi_axes = [0.12, 0.09]
wall_thickness = 0.002
material = "al"
shaft_clearance = 0.05
"""
TAIL = """
[[bearings]]
name = "hanger"
kind = "contact"
x = 0.7
stiffness = { v = 1e7, w = 2e7 }
[[bearings]]
name = "mount"
kind = "contact"
x = 1.55
stiffness = { v = 1e7, w = 1e7 }
[operating]
speed_rpm = 3000.0
power = 0.0
[mesh]
shaft_elements = 5
boom_elements = 3
"""
THIRD = """
[[bearings]]
name = "front"
kind = "contact"
x = 0.2
stiffness = { v = 1e7, w = 1e7 }
"""


def _measured_half_band(design) -> int:
    model = build_model(design)
    free = model.dofs.free
    pattern = (abs(model.K) + abs(model.M) + abs(model.G) + abs(model.C))[free][:, free].tocsr()
    order = band_ordering(pattern, model.dofs.stations[free])
    position = np.empty(order.size, dtype=int)
    position[order] = np.arange(order.size)  # row i sits at position[i] in the solver's ordering
    entries = pattern.tocoo()
    return int(np.abs(position[entries.row] - position[entries.col]).max())


def _size(design, analysis="assess"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        return problem_size(design, analysis, SCREENING)


@pytest.fixture(scope="module")
def designs():
    return loads_design(HEAD + TAIL), loads_design(HEAD + BOOM + TAIL)


@pytest.fixture(scope="module")
def measured(designs):
    return tuple(_measured_half_band(d) for d in designs)


def test_the_measured_bands_are_the_hand_counts(measured):
    assert measured[0] == 7
    assert 7 < measured[1] <= 21


def test_the_banded_memory_per_dof_follows_the_measured_band(designs, measured):
    shaft, boomed = (_size(d) for d in designs)
    per_dof = [s.memory["banded harmonic solver"] / s.free_dofs for s in (shaft, boomed)]
    ratio = per_dof[1] / per_dof[0]  # (3 k_b + 1) / (3 k_s + 1)
    k_s, k_b = measured
    true = (3 * k_b + 1) / (3 * k_s + 1)
    assert true / 2 <= ratio <= 2 * true


def test_the_banded_memory_holds_one_lapack_band_of_the_measured_width(designs, measured):
    """Absolute, not a ratio (a review: scaling both estimated widths alike passed the ratio):
    LAPACK's zgbsv stores a band of kl = ku = k in LDAB = 2 kl + ku + 1 = 3k + 1 rows of N complex
    numbers, 16 bytes each (LAPACK Users' Guide, "Band storage"). The solver holds at least that
    for the measured k, and an estimate that neither undercounts nor doubles the band holds at
    most two such arrays (the band and its factor) of twice the measured width."""
    for design, k in zip(designs, measured):
        size = _size(design)
        band = 16.0 * size.free_dofs
        assert band * (3 * k + 1) <= size.memory["banded harmonic solver"] <= 2 * band * (3 * 2 * k + 1)


def test_the_banded_solve_time_grows_with_the_square_of_the_measured_band(measured):
    n = 10_000
    with_boom = harmonic_seconds(2 * n, True) - harmonic_seconds(n, True)
    without = harmonic_seconds(2 * n, False) - harmonic_seconds(n, False)
    k_s, k_b = measured
    true = (k_b / k_s) ** 2
    assert true / 4 <= with_boom / without <= 4 * true


def test_the_spinup_memory_holds_every_load_case():
    one = _size(loads_design(HEAD + BOOM + TAIL + THIRD + '[loads]\nimbalance_placement = "mid_bay"\n'))
    worst = _size(loads_design(HEAD + BOOM + TAIL + THIRD + '[loads]\nimbalance_placement = "worst"\n'))
    assert (one.load_cases, worst.load_cases) == (1, 2)
    assert worst.memory["spin-up responses"] == pytest.approx(2 * one.memory["spin-up responses"], rel=1e-12)
