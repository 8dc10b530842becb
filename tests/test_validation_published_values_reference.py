"""The validation cases' published values and tolerances against the text of their sources.

``flexshaft validate`` can only be as right as the numbers typed into its case table
(flexshaft.validation.cases, cases_vm). A published value mistyped within its tolerance, or a
tolerance wider than the source's printed digits justify, lets a wrong flexshaft pass. These
tests hold the table to the sources' own text, read for this test:

* ROSS (petrobras/ross, ``ross/tests/test_examples.py``, read in the stored copy at commit
  188ac4fd; the cases cite 631a249a, whose values the cases state are the same), Friswell et
  al.'s Examples 5.9.1, 5.9.2, 5.9.5 and 5.9.9 as ROSS computes them::

      test_example1_w_equals_0rpm     [86.66, 86.66, 274.31, 274.31, 716.78, 716.78]
      test_example1_w_equals_4000rpm  [85.39, 87.80, 251.78, 294.71, 600.18, 827.08]
      test_example2_w_eq_0rpm         [90.14, 90.14, 630.73, 630.73, 830.43, 830.43]
      test_example2_w_eq_4000rpm      [76.19, 103.91, 565.99, 634.23, 647.75, 1174.2]
      test_example3_w_equals_0rpm     [82.65, 86.66, 254.52, 274.31, 679.49, 716.79]
      test_example3_w_equals_4000rpm  [82.33, 86.86, 239.64, 287.25, 583.49, 806.89]
      test_example4_w_equals_0rpm     wn_hertz [13.91, 13.91, 48.18, 48.18, 137.06, 137.06]
                                      wd_hertz [13.89, 13.89, 46.54, 46.54, 103.22, 103.22]

* ANSYS VM247 (ansys/pymapdl, ``src/ansys/mapdl/core/examples/verif/vm247.dat``, read at commit
  29270f14): ``*VFILL,VALUE(1..6,1),DATA,15470 / 17159 / 46612 / 49983 / 64752 / 96457 ! CRITICAL
  SPEED VALUE OBTAINED FROM REFERENCE`` and ``VALUE(7..12,1),DATA,4015 / 4120.25 / 11989.25 /
  12200 / 18184.25 / 20162.25 ! ... FROM REFERENCE/4``;
* ANSYS VM57 (same folder, ``vm57.dat``, commit 1c24d5ca): ``*VFILL,VALUE(1,1),DATA,.3833,1.260``
  (Thomson, Ex. 8.4-5, "PAGE 272");
* the ISO 21940-11 worked example as the case quotes its source (WIDIA catalogue p. K53):
  "M = 2 kg, G 6.3, n = 10 000 RPM, U per = 12 gmm", with its formula "U per = 9549 x G x M / n";
* Çengel's Problem 7-100 as the case quotes it: "Nu = 107".

Tolerance budget. Where a case's only stated error is the rounding of the printed values (ROSS's
and the textbook examples' digits), that rounding, half a unit of the last printed digit over
the value, maximised over the case's values, is the least tolerance that lets a correct flexshaft
pass; a tolerance more than twice it would accept an error the printed digits resolve. So
budget <= tolerance <= 2 budget. (The cases whose basis adds a modelling difference, e.g. the
rotary inertia a closed form omits, are not held to this rule here.)

No model is computed: the case table only (milliseconds of CPU).
"""

from __future__ import annotations

import math

import pytest

from flexshaft.validation.cases import case_by_id

ROSS_EX1_0 = (86.66, 86.66, 274.31, 274.31, 716.78, 716.78)
ROSS_EX1_4000 = (85.39, 87.80, 251.78, 294.71, 600.18, 827.08)
ROSS_EX2_0 = (90.14, 90.14, 630.73, 630.73, 830.43, 830.43)
ROSS_EX2_4000 = (76.19, 103.91, 565.99, 634.23, 647.75, 1174.2)
ROSS_EX3_0 = (82.65, 86.66, 254.52, 274.31, 679.49, 716.79)
ROSS_EX3_4000 = (82.33, 86.86, 239.64, 287.25, 583.49, 806.89)
ROSS_EX4_WN = (13.91, 13.91, 48.18, 48.18, 137.06, 137.06)
ROSS_EX4_WD = (13.89, 13.89, 46.54, 46.54, 103.22, 103.22)
VM247_SLOPE_1 = (15470, 17159, 46612, 49983, 64752, 96457)
VM247_SLOPE_4 = (4015, 4120.25, 11989.25, 12200, 18184.25, 20162.25)
VM57 = (0.3833, 1.260)

#: case id -> the values it compares, as the source prints them (the degenerate pairs at rest
#: once each, the 5.9.5 pairs as |s|, Im s per mode), and the last printed digit of each
SOURCE_VALUES = {
    "friswell-5.9.1-rest": (ROSS_EX1_0[::2], 0.01),
    "friswell-5.9.1-4000": (ROSS_EX1_4000[:5], 0.01),
    "friswell-5.9.2-rest": (ROSS_EX3_0[:5], 0.01),
    "friswell-5.9.2-4000": (ROSS_EX3_4000[:5], 0.01),
    "friswell-5.9.5-damped": (tuple(v for pair in zip(ROSS_EX4_WN[::2], ROSS_EX4_WD[::2]) for v in pair), 0.01),
    "friswell-5.9.9-rest": (ROSS_EX2_0[::2], 0.01),
    "friswell-5.9.9-4000": (ROSS_EX2_4000, (0.01,) * 5 + (0.1,)),
    "nelson-mcvaugh-1976-critical": (VM247_SLOPE_1, None),
    "nelson-mcvaugh-1976-quarter": (VM247_SLOPE_4, None),
    "thomson-drill-pipe-torsion": (VM57, (1e-4, 1e-3)),
    "iso21940-balance-tolerance": ((12.0,), 1.0),
    "cengel-7-100-crossflow": ((107.0,), 1.0),
}


@pytest.mark.parametrize("case_id", sorted(SOURCE_VALUES))
def test_the_published_values_are_the_sources(case_id):
    values, _ = SOURCE_VALUES[case_id]
    assert case_by_id(case_id).published == tuple(float(v) for v in values)


@pytest.mark.parametrize("case_id", sorted(k for k, (_, step) in SOURCE_VALUES.items() if step is not None))
def test_a_rounding_tolerance_is_the_printed_digits(case_id):
    """budget = max_i (step_i / 2) / |value_i| <= tolerance <= 2 budget."""
    values, step = SOURCE_VALUES[case_id]
    steps = step if isinstance(step, tuple) else (step,) * len(values)
    budget = max(s / 2.0 / abs(v) for v, s in zip(values, steps))
    tolerance = case_by_id(case_id).tolerance
    assert budget <= tolerance <= 2.0 * budget, (case_id, budget, tolerance)


def test_the_balance_example_follows_its_formula():
    """U_per = e_per M with e_per Ω = G: U [g mm] = 1000 × M [kg] × G [mm/s] / (2π n/60 [rad/s])
    = (60000/2π) G M / n = 9549.3 G M / n, the catalogue's "9549 x G x M / n". For M = 2 kg,
    G 6.3, n = 10 000 rev/min: 12.03 g mm, which the example prints to two figures as 12."""
    case = case_by_id("iso21940-balance-tolerance")
    assert case.arguments == {"rotor_mass": 2.0, "grade_mm_s": 6.3, "speed_rpm": 10000.0}
    assert 60000.0 / (2.0 * math.pi) == pytest.approx(9549.0, abs=0.5)
    u_per = 60000.0 / (2.0 * math.pi) * 6.3 * 2.0 / 10000.0
    assert u_per == pytest.approx(12.03, abs=0.005)
    assert case.published == (float(round(u_per)),)
    assert case.unit == "g mm"
