"""More validation cases held to their sources' text and to budgets derived by hand
(flexshaft.validation.cases, cases_vm, runner; mutation hunt h41b).

``tests/test_validation.py`` compares docs/validation.md with the table the cases produce, which
only says the page is current, not that a number was typed right. These tests read the sources:

* openTorsion (Aalto-Arotor/openTorsion, ``tests/tests.py``, ``test_friswell_ex971``, read at
  commit 51287074, the commit the case cites): ``correct = [0, 81.21, 141.21, 378.95, 536.36]``
  for ``Ip1to3 = 3.5e-3``, ``Ip4 = 0.15``, ``Ip5 = 0.05``, ``k1 = k2 = 12e3``, ``k3 = 14e3``,
  ``k4 = 10e3``. Independently, the free-free chain K θ = ω² J θ of those five inertias and four
  springs, solved here with a dense symmetric eigen-solver, gives 81.2076, 141.2141, 378.9530
  and 536.3633 Hz, which round to the printed values.
  Tolerance budget: the printing, half of 0.01 Hz over 81.21 Hz = 6.2e-5, plus what the design
  file's links (shaft pieces standing for massless rigid links) take: each 1 m piece of
  D = 0.05 m (bore 2e-7 m: J = π D⁴/32 = 6.136e-7 m⁴), G = 4e14 Pa, ρ = 1 kg/m³ has a twist
  stiffness G J/L = 2.45e8 N m/rad, 14e3/2.45e8 = 5.7e-5 of the stiffest spring's compliance,
  and a polar inertia ρ J L = 6.1e-7 kg m², 1.75e-4 of the smallest disk's; a frequency
  ω ∝ sqrt(k/J) moves by at most half their sum, 1.16e-4. Budget 1.78e-4; the case's
  tolerance must lie in [budget, 2 budget], as in test_validation_published_values_reference.
* ANSYS VM263 (ansys/pymapdl, ``src/ansys/mapdl/core/examples/verif/vm263.dat``, read at commit
  29270f14): ``*VFILL,VALUE(1..6,1),DATA,7929 / 8350 / 23760 / 24602 / 34820 / 42776 !
  CRITICAL SPEED VALUE OBTAINED FROM REFERENCE/2``.
* ANSYS VM261 (same folder, ``vm261.dat``, read at commit 1c24d5ca): ``E = 2.1E+11``,
  ``DENS = 7800``, ``VALUE(1,1) 4950`` and ``VALUE(2,1) 10500`` rev/min, for a uniform shaft
  L = 1.27 m, D = 0.1016 m on two bearings of 1.75e7 N/m (the case's design file restates them).
  Those bearings are about as stiff as the shaft, so a frequency does not scale as sqrt(E/ρ).
  An independent solution of the stated inputs, a 20-element Euler-Bernoulli beam (cubic
  Hermite elements, consistent mass, no rotary inertia or gyroscopics) written here, gives
  4998.55 and 10501.04 rev/min (40 elements change them by 2e-7; flexshaft's own 5-element
  model gives 5000.4 for the first, 0.04 % away), d ln f/d ln E = 0.195 and 0.039, and
  d ln f/d ln ρ = −0.5. Budget, as the project's rule takes the worst of the case's values:
  (a) the printing, three figures, max(5/4950, 50/10500) = 0.48 %; (c) the reference's model
  differs from an exact solution of its own inputs by 0.98 % (4950 against 4998.55; 0.01 % for
  10500): 1.46 % in all, and the tolerance lies in [budget, 2 budget]. (b) The rounding of the
  stated inputs, E to two figures (±2.38 %, ×0.195 = ±0.46 %) and ρ to three (±0.064 %, ×0.5 =
  ±0.032 %), is computed and not added: flexshaft and the beam take the same stated inputs, so
  that rounding cannot move a correct flexshaft away from the beam; it can only explain part of
  (c). Added, the budget would be 1.95 %, above the tolerance of 1.5 %, which rests on (a) + (c).
* Çengel's Problem 7-53 (the case quotes Re = 1.632 × 10⁴, Pr = 0.7255, Nu = 71.19, Churchill-
  Bernstein). The correlation, typed from Churchill & Bernstein (1977) as Incropera's eq. 7.54
  gives it, Nu = 0.3 + 0.62 Re^½ Pr^⅓ [1 + (0.4/Pr)^⅔]^−¼ [1 + (Re/282 000)^⅝]^⅘, gives 71.186
  there (rounds to 71.19). Budget from the printed figures, as the case's basis states it:
  Nu ±0.005/71.19 = 7.0e-5, plus Re ±5 and Pr ±5e-5 through the correlation's slopes
  d ln Nu/d ln Re and d ln Nu/d ln Pr (central differences here): 2.7e-4; tolerance in
  [budget, 2 budget].
* ``runner.significant``: n significant figures are the n digits from the first non-zero one
  (716.789 → 716.79 at five; 11338.4 → 11338; 0.0123456 → 0.012346), as its docstring shows;
  above five digits the rest are zeros (123456.7 → 123460, not the six-figure 123457), and a
  rounding that carries into a new leading digit keeps five (9.99997 → 10.000, not 10.0000;
  99999.7 → 100000, i.e. 1.0000e5, the only plain-notation form);
  ``runner.percent``: "a relative difference in percent to 0.001 %": 2e-5 is +0.002 %, −1.2e-4
  −0.012 %, and only what rounds to 0.000 % (below 5e-6) is shown as "< 0.001 %".

No flexshaft model is computed (a 5 × 5 and a 42 × 42 eigen-solve): milliseconds of CPU.
"""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest
import scipy.linalg

from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import design_text, percent, significant

OPENTORSION_EX971 = (0.0, 81.21, 141.21, 378.95, 536.36)
CHAIN_INERTIAS = (3.5e-3, 3.5e-3, 3.5e-3, 0.15, 0.05)  # [kg m²]
CHAIN_SPRINGS = (12e3, 12e3, 14e3, 10e3)  # [N m/rad]
VM263_SLOPE_2 = (7929.0, 8350.0, 23760.0, 24602.0, 34820.0, 42776.0)
VM261_CRITICAL = (4950.0, 10500.0)


def _chain_frequencies_hz() -> np.ndarray:
    stiffness = np.zeros((5, 5))
    for i, k in enumerate(CHAIN_SPRINGS):
        stiffness[i : i + 2, i : i + 2] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
    squared = scipy.linalg.eigh(stiffness, np.diag(CHAIN_INERTIAS), eigvals_only=True)
    return np.sqrt(np.clip(squared, 0.0, None)) / (2.0 * math.pi)


def test_the_torsion_chain_values_are_opentorsions_and_the_chains():
    case = case_by_id("friswell-9.7.1-torsion")
    assert case.published == OPENTORSION_EX971[1:]
    # the chain itself, solved here: each printed value is its frequency rounded to 0.01 Hz
    np.testing.assert_allclose(_chain_frequencies_hz()[1:], OPENTORSION_EX971[1:], rtol=0, atol=0.005)


def test_the_torsion_chain_tolerance_is_its_printing_and_links():
    printing = 0.005 / 81.21
    polar = math.pi * 0.05**4 / 32.0  # [m^4], the bore of 2e-7 m is negligible
    compliance_ratio = max(CHAIN_SPRINGS) / (4e14 * polar / 1.0)
    inertia_ratio = 1.0 * polar * 1.0 / min(CHAIN_INERTIAS)
    links = (compliance_ratio + inertia_ratio) / 2.0
    assert links == pytest.approx(1.16e-4, rel=0.01)
    budget = printing + links
    tolerance = case_by_id("friswell-9.7.1-torsion").tolerance
    assert budget <= tolerance <= 2.0 * budget, (budget, tolerance)


def test_the_half_harmonic_values_are_vm263s():
    assert case_by_id("nelson-mcvaugh-1976-half").published == VM263_SLOPE_2


def _vm261_beam_rpm(modulus: float = 2.1e11, density: float = 7800.0, elements: int = 20) -> np.ndarray:
    """VM261's shaft (L = 1.27 m, D = 0.1016 m, bearings 1.75e7 N/m at both ends) as
    Euler-Bernoulli cubic elements with consistent mass: its first two frequencies [rev/min]."""
    length, diameter, bearing = 1.27, 0.1016, 1.75e7
    inertia, area, h = math.pi * diameter**4 / 64.0, math.pi * diameter**2 / 4.0, length / elements
    k_e = modulus * inertia / h**3 * np.array(
        [[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
         [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]]
    )  # fmt: skip
    m_e = density * area * h / 420.0 * np.array(
        [[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
         [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]]
    )  # fmt: skip
    n = 2 * (elements + 1)
    stiffness, mass = np.zeros((n, n)), np.zeros((n, n))
    for e in range(elements):
        stiffness[2 * e : 2 * e + 4, 2 * e : 2 * e + 4] += k_e
        mass[2 * e : 2 * e + 4, 2 * e : 2 * e + 4] += m_e
    stiffness[0, 0] += bearing
    stiffness[-2, -2] += bearing
    squared = scipy.linalg.eigh(stiffness, mass, eigvals_only=True, subset_by_index=[0, 1])
    return np.sqrt(squared) * 60.0 / (2.0 * math.pi)


@pytest.mark.parametrize("case_id", ["zorzi-nelson-1976-critical", "zorzi-nelson-1976-onset"])
def test_the_zorzi_nelson_tolerance_is_its_printing_and_model_difference(case_id):
    case = case_by_id(case_id)
    assert case.published == VM261_CRITICAL[: len(case.published)]
    exact = _vm261_beam_rpm()
    assert exact == pytest.approx((4998.55, 10501.04), abs=0.01)
    # (b) the inputs' rounding through the beam's sensitivities: computed, not added (docstring)
    step = 1e-3
    d_e = np.log(_vm261_beam_rpm(modulus=2.1e11 * (1 + step)) / exact) / np.log(1 + step)
    d_rho = np.log(_vm261_beam_rpm(density=7800.0 * (1 + step)) / exact) / np.log(1 + step)
    assert d_e == pytest.approx((0.195, 0.039), abs=1e-3)
    assert d_rho == pytest.approx((-0.5, -0.5), abs=1e-4)
    rounding = max(d_e) * 0.05e11 / 2.1e11 + 0.5 * 5.0 / 7800.0
    assert rounding == pytest.approx(4.97e-3, rel=0.01)
    # (a) printing, worst of ALL the case's values; (c) the reference against the exact solution
    printing = max(0.5 * 10.0 ** (math.floor(math.log10(v)) - 2) / v for v in VM261_CRITICAL)
    assert printing == pytest.approx(50.0 / 10500.0)
    model = max(abs(v - x) / v for v, x in zip(VM261_CRITICAL, exact))
    assert model == pytest.approx(9.81e-3, rel=0.01)
    budget = printing + model
    assert budget <= case.tolerance <= 2.0 * budget, (budget, case.tolerance)
    assert printing + model + rounding == pytest.approx(1.95e-2, rel=0.01)  # not added: see the docstring


def _churchill_bernstein(reynolds: float, prandtl: float) -> float:
    return 0.3 + (
        0.62
        * reynolds**0.5
        * prandtl ** (1.0 / 3.0)
        / (1.0 + (0.4 / prandtl) ** (2.0 / 3.0)) ** 0.25
        * (1.0 + (reynolds / 282000.0) ** (5.0 / 8.0)) ** 0.8
    )


def test_the_cengel_7_53_tolerance_is_its_printed_figures():
    case = case_by_id("cengel-7-53-crossflow")
    re_, pr = case.arguments["reynolds"], case.arguments["prandtl"]
    assert (re_, pr, case.published) == (1.632e4, 0.7255, (71.19,))
    assert round(_churchill_bernstein(re_, pr), 2) == 71.19

    def slope(f, x, h=1e-4):  # d ln Nu / d ln x, central difference
        return (math.log(f(x * (1 + h))) - math.log(f(x * (1 - h)))) / (2 * h)

    d_re = slope(lambda r: _churchill_bernstein(r, pr), re_)
    d_pr = slope(lambda p: _churchill_bernstein(re_, p), pr)
    assert d_re == pytest.approx(0.57, abs=0.01)
    budget = 0.005 / 71.19 + d_re * 5.0 / re_ + d_pr * 5e-5 / pr
    assert budget == pytest.approx(2.7e-4, rel=0.03)
    assert budget <= case.tolerance <= 2.0 * budget, (budget, case.tolerance)


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (716.789, "716.79"),
        (11338.4, "11338"),
        (0.0123456, "0.012346"),
        (86.6612, "86.661"),
        (123456.7, "123460"),
        (99999.7, "100000"),
        (9.99997, "10.000"),
    ],
)
def test_five_significant_figures(value, text):
    assert significant(value, 5) == text


@pytest.mark.parametrize(
    ("difference", "text"), [(2e-5, "+0.002 %"), (-1.2e-4, "-0.012 %"), (6e-6, "+0.001 %"), (4e-6, "< 0.001 %")]
)
def test_differences_in_percent_to_a_thousandth(difference, text):
    assert percent(difference) == text


def _smallest_diameter_m(design_name: str) -> float:
    """The smallest outer diameter in a packaged design file, read with the standard library."""
    shaft = tomllib.loads(design_text(design_name))["shaft"]
    return min([shaft["outer_diameter"], *(segment["outer_diameter"] for segment in shaft.get("segments", ()))])


@pytest.mark.parametrize(
    "case_id", ["nelson-mcvaugh-1976-critical", "nelson-mcvaugh-1976-half", "nelson-mcvaugh-1976-quarter"]
)
def test_the_nelson_mcvaugh_tolerance_is_its_input_rounding(case_id):
    """The three Nelson-McVaugh cases (VM247 and VM263, one rotor, one design file) hold their
    whirl speeds to a tolerance that the rounding of their inputs must justify. The budget is
    derived here from the design file, not from the case's own words: its smallest diameter
    (element 1 of VM247, ``outer_diameter = 0.0102`` m in validation/designs/
    nelson_mcvaugh_1976.toml) is written to three significant figures, so it is known to half a
    unit of the third, 0.5e-4 m, i.e. 0.5e-4/0.0102 = 4.90e-3 (0.49 %); the whirl speeds of a solid
    beam scale with its diameter (ω ∝ √(EI/ρA)/L² ∝ D); the worst diameter's 0.49 % is taken for
    every step (the larger diameters' roundings are smaller, e.g. 2.04 cm ±0.25 %). The printed speeds add at most half
    a unit of the smallest one, 0.5/4015 = 1.2e-4 (an upper bound: the others are larger).
    Budget 5.03e-3. This diameter-only budget is assumed, and it is a lower bound: the lengths
    are three-figure numbers too (1.27 cm to ±0.4 %) and enter as ω ∝ 1/L², twice as strongly;
    they are not counted. flexshaft's worst differences (docs/validation.md's table) are 0.61 %,
    0.30 % and 0.30 %: the 0.61 % exceeds the diameter-only budget, which the uncounted lengths
    must account for. The project's rule (budget <= tolerance <= 2 budget,
    tests/test_validation_published_values_reference.py) on the derived budget gives
    [0.503 %, 1.006 %]; the assertion checks each case's tolerance against that interval (the
    stated 1 % lies in it; a tolerance of 3 % does not)."""
    case = case_by_id(case_id)
    diameter = _smallest_diameter_m(case.design)
    assert diameter == 0.0102  # the design file's element 1, as VM247 gives it
    half_unit = 0.5 * 10.0 ** (math.floor(math.log10(diameter)) - 2)  # three significant figures
    assert half_unit == pytest.approx(0.5e-4, rel=1e-12)
    budget = half_unit / diameter + 0.5 / 4015.0
    assert budget <= case.tolerance <= 2.0 * budget, (case_id, case.tolerance, budget)
