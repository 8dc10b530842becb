"""The validation cases: published results, where each was read, and what flexshaft computes.

Every case holds the numbers a source published (or, for a closed form, the formula's value
for stated inputs), the place they were read, the design file that reproduces the inputs
(``flexshaft/validation/designs/``, shipped with the package), the quantity flexshaft computes
(:mod:`flexshaft.validation.quantities`) and a relative tolerance justified by the source's
own accuracy: the digits it prints, its measurement scatter, or the theory it differs from.

A value that reached us through another code's test file says so (``via``); nothing here was
computed by flexshaft.
"""

from __future__ import annotations

import math

from flexshaft.validation.case_types import Case, Source
from flexshaft.validation.cases_vm import VM_CASES, VM_SOURCES
from flexshaft.validation.reference import gibert_spinning_beam, rayleigh_cantilever_tip_mass, rotating_damping_onset

__all__ = ["CASES", "GIBERT_ROD", "JEFFCOTT", "SOURCES", "VPCS_CANTILEVER", "Case", "Source", "case_by_id"]


SOURCES: dict[str, Source] = {
    "friswell2010": Source(
        "friswell2010",
        "M. I. Friswell, J. E. T. Penny, S. D. Garvey, A. W. Lees, Dynamics of Rotating Machines, "
        "Cambridge University Press, 2010.",
    ),
    "iso21940": Source(
        "iso21940",
        "ISO 21940-11:2016 (formerly ISO 1940-1), Mechanical vibration, Rotor balancing, Part 11: Procedures "
        "and tolerances for rotors with rigid behaviour: permissible residual unbalance U_per = e_per m with "
        "e_per Ω = G. Worked example: WIDIA tooling catalogue, Technical Information, Balancing, p. K53 "
        '("U per = 9549 x G x M / n").',
    ),
    "gibert": Source(
        "gibert",
        "R.-J. Gibert, Vibrations des structures, closed form of the spinning simply supported "
        "Euler beam, as stated in code_aster Validation Manual V2.02.141, §2.1 'Benchmark solution' "
        "(code_aster documentation, man_v/v2/v2.02.141).",
    ),
    "vpcs": Source(
        "vpcs",
        "Guide VPCS (Validation des progiciels de calcul de structures, SFM/AFNOR), sheet SDLL15/89: Rayleigh "
        "formula of the first frequency of a cantilever with a tip mass, f1 = (1/2π) sqrt(3 E I_z / (L³ (m_c "
        "+ 0.24 M))), as stated in code_aster Validation Manual V2.02.015, §2.1 (uncertainty §2.3).",
    ),
    "schweitzer2009": Source(
        "schweitzer2009",
        "G. Schweitzer, E. H. Maslen (eds.), Magnetic Bearings: Theory, Design, and Application to Rotating "
        "Machinery, Springer, 2009, p. 343: negative stiffness k_s and current gain k_i of a radial bearing in "
        "differential driving mode.",
    ),
    "cengel": Source(
        "cengel",
        "Solutions of a heat-transfer textbook, Chapter 7 'External Forced Convection', Problems 7-53 (a steam "
        "pipe in light wind) and 7-100 (an insulated steam pipe in cross-flow), as reproduced on coursehero.com "
        "(files 6719813 and 6719861, 'Thermodynamics HW Solutions'); the page does not name the book, whose "
        "solution format and air table (Table A-15) are those of Y. A. Çengel's Heat and Mass Transfer.",
    ),
    "bently2002": Source(
        "bently2002",
        "Appendix 6, 'Eigenvalues of the Rotor Model' (pp. 497-498, eqs. A6-1 to A6-8, after Muszynska): the "
        "eigenvalues of M r'' + D r' + (K - j D λ Ω) r = 0, as reproduced on scribd.com (document 755297072). "
        "The page does not name the book; its rotor model and its 'Fluid Circumferential Average Velocity "
        "Ratio' λ are those of D. E. Bently, C. T. Hatch, Fundamentals of Rotating Machinery Diagnostics "
        "(2002).",
    ),
    "calcady": Source(
        "calcady",
        "calcady.com, 'Driveshaft Critical Speed' (trade/automotive/driveshaft-critical-speed), section "
        "'Step-by-Step Example Walkthrough': a 45 in steel driveshaft, 3.5 in OD, 0.083 in wall, E = 30 Mpsi, "
        "0.283 lb/in³, simply supported: 11,390 RPM critical.",
    ),
    **VM_SOURCES,
}

#: Inputs of the closed-form cases, as in their design files (tests/test_validation.py checks both agree).
GIBERT_ROD = {"length": 2.0, "diameter": 0.05, "modulus": 211.0e9, "density": 7810.0, "speed_rpm": 30000.0}
VPCS_CANTILEVER = {
    "length": 1.0,
    "outer_diameter": 0.05,
    "wall_thickness": 0.005,
    "modulus": 210.0e9,
    "density": 7800.0,
    "tip_mass": 10.0,
}

#: The Jeffcott rotor of the internal-damping case (its design file states the same numbers).
JEFFCOTT = {"stiffness": 75398.22368615503, "mass": 10.0, "loss_factor": 0.02, "external_damping": 8.683215054699211}
_JEFFCOTT_OMEGA_N = math.sqrt(JEFFCOTT["stiffness"] / JEFFCOTT["mass"])

_ROSS = "ROSS (petrobras/ross, commit 631a249a), ross/tests/test_examples.py"
_ROSS_BASIS = (
    "the values are printed to 0.01 rad/s (rounding at most 6e-5 of the lowest); ROSS and flexshaft solve "
    "the same discrete model (Timoshenko elements, Cowper coefficient, consistent mass), so only rounding "
    "separates them"
)
_ROSS_KIND = "textbook example, peer-code values"
_ROSS_NOTE = (
    "ROSS's run_modal also returns 650.41 rad/s (ROSS 2.3 on its tests' example-1 rotor with num_modes = 14, "
    "re-run 2026-12-05; the tests' six-value lists stop below it), the same at both speeds and on both bearing "
    "sets, so not a lateral "
    "mode (presumably the torsional mode of ROSS's six-DOF model); flexshaft compares the lateral modes only."
)

CASES: tuple[Case, ...] = (
    Case(
        id="friswell-5.9.1-rest",
        title="Two-disk rotor on isotropic bearings, at rest",
        part="rotor-bearing natural frequencies (Timoshenko shaft, rigid disks, bearings)",
        source="friswell2010",
        where="Example 5.9.1 (p. 206): lateral natural frequencies at 0 rev/min, six Timoshenko elements",
        via=f"as computed by ROSS for the example: {_ROSS}, test_example1_w_equals_0rpm (rotor_example1(6))",
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_1.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 0.0, "count": 3, "stride": 2},
        labels=("pair 1", "pair 2", "pair 3"),
        published=(86.66, 274.31, 716.78),
        unit="rad/s",
        tolerance=1e-4,
        tolerance_basis=_ROSS_BASIS,
        note="At rest each lateral mode is a degenerate pair; one value of each pair is compared. " + _ROSS_NOTE,
    ),
    Case(
        id="friswell-5.9.1-4000",
        title="Two-disk rotor on isotropic bearings, 4000 rev/min",
        part="gyroscopic splitting of the lateral modes (disks and shaft)",
        source="friswell2010",
        where="Example 5.9.1 (p. 206): lateral natural frequencies at 4000 rev/min",
        via=f"as computed by ROSS for the example: {_ROSS}, test_example1_w_equals_4000rpm (rotor_example1(6))",
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_1.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 4000.0, "count": 5},
        labels=("1 backward", "1 forward", "2 backward", "2 forward", "3 backward"),
        published=(85.39, 87.80, 251.78, 294.71, 600.18),
        unit="rad/s",
        tolerance=1e-4,
        tolerance_basis=_ROSS_BASIS,
        note=_ROSS_NOTE,
    ),
    Case(
        id="friswell-5.9.2-rest",
        title="Two-disk rotor on anisotropic bearings, at rest",
        part="rotor-bearing natural frequencies with direction-dependent bearing stiffness",
        source="friswell2010",
        where="Example 5.9.2 (p. 208): bearings of 1 MN/m and 0.8 MN/m, natural frequencies at 0 rev/min",
        via=f"as computed by ROSS for the example: {_ROSS}, test_example3_w_equals_0rpm",
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_2.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 0.0, "count": 5},
        labels=("1 (soft plane)", "1 (stiff plane)", "2 (soft plane)", "2 (stiff plane)", "3 (soft plane)"),
        published=(82.65, 86.66, 254.52, 274.31, 679.49),
        unit="rad/s",
        tolerance=1e-4,
        tolerance_basis=_ROSS_BASIS,
        note=(
            "ROSS's test builds this rotor with 48 elements and accepts 1e-3; its listed values are those of "
            "the six-element model of the book (flexshaft: 679.489 rad/s with 6 elements, 679.297 with 48), "
            "so the design uses six elements. " + _ROSS_NOTE
        ),
    ),
    Case(
        id="friswell-5.9.2-4000",
        title="Two-disk rotor on anisotropic bearings, 4000 rev/min",
        part="gyroscopic splitting with anisotropic bearings (elliptical whirl)",
        source="friswell2010",
        where="Example 5.9.2 (p. 208): natural frequencies at 4000 rev/min",
        via=f"as computed by ROSS for the example: {_ROSS}, test_example3_w_equals_4000rpm",
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_2.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 4000.0, "count": 5},
        labels=("1 backward", "1 forward", "2 backward", "2 forward", "3 backward"),
        published=(82.33, 86.86, 239.64, 287.25, 583.49),
        unit="rad/s",
        tolerance=1e-4,
        tolerance_basis=_ROSS_BASIS,
        note="Six elements, as for the rest case. " + _ROSS_NOTE,
    ),
    Case(
        id="friswell-5.9.5-damped",
        title="Two-disk rotor on damped isotropic bearings, at rest",
        part="damped natural frequencies (bearing dampers in the eigen-solution)",
        source="friswell2010",
        where="Example 5.9.5 (p. 212): bearings of 1 MN/m and 3 kN s/m, eigenvalues at 0 rev/min",
        via=(
            f"as computed by ROSS for the example: {_ROSS}, test_example4_w_equals_0rpm (undamped |s| as wn, "
            "damped Im s as wd, in Hz)"
        ),
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_5.toml",
        quantity="lateral_frequency_pairs",
        arguments={"speed_rpm": 0.0, "count": 3},
        labels=("mode 1 |s|", "mode 1 Im s", "mode 2 |s|", "mode 2 Im s", "mode 3 |s|", "mode 3 Im s"),
        published=(13.91, 13.89, 48.18, 46.54, 137.06, 103.22),
        unit="Hz",
        tolerance=5e-4,
        tolerance_basis=(
            "the values are printed to 0.01 Hz: rounding at most 3.6e-4 of the lowest (13.89 Hz); same discrete "
            "model as ROSS"
        ),
        note=(
            "'undamped' is the modulus |s| of the eigenvalue, 'damped' its imaginary part Im s. The third pair is "
            "heavily damped (ζ = 0.75): the two differ by a third. ROSS's test also lists "
            "the values at 4000 rev/min, accepted at 10 % by that test; they are not used here."
        ),
    ),
    Case(
        id="friswell-5.9.9-rest",
        title="Overhung rotor, at rest",
        part="overhung disk (cantilevered span beyond a bearing)",
        source="friswell2010",
        where="Example 5.9.9 (p. 218): the first six natural frequencies at 0 rev/min",
        via=f"as computed by ROSS for the example: {_ROSS}, test_example2_w_eq_0rpm (rotor_example2(6))",
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_9.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 0.0, "count": 3, "stride": 2},
        labels=("pair 1", "pair 2", "pair 3"),
        published=(90.14, 630.73, 830.43),
        unit="rad/s",
        tolerance=1e-4,
        tolerance_basis=_ROSS_BASIS,
        note="At rest each lateral mode is a degenerate pair; one value of each pair is compared.",
    ),
    Case(
        id="friswell-5.9.9-4000",
        title="Overhung rotor, 4000 rev/min",
        part="gyroscopic stiffening of an overhung disk",
        source="friswell2010",
        where="Example 5.9.9 (p. 218): the first six natural frequencies at 4000 rev/min",
        via=f"as computed by ROSS for the example: {_ROSS}, test_example2_w_eq_4000rpm (rotor_example2(6))",
        reference_kind=_ROSS_KIND,
        design="friswell_5_9_9.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 4000.0, "count": 6},
        labels=("1 backward", "1 forward", "2 backward", "2 forward", "3 backward", "3 forward"),
        published=(76.19, 103.91, 565.99, 634.23, 647.75, 1174.2),
        unit="rad/s",
        tolerance=1e-4,
        tolerance_basis=_ROSS_BASIS + " (1174.2 is printed to 0.1 rad/s: rounding 4e-5)",
    ),
    Case(
        id="friswell-9.7.1-torsion",
        title="Torsional chain of five inertias (free-free)",
        part="torsional modes: disk polar inertia, flexible couplings (torsional stiffness)",
        source="friswell2010",
        where="Example 9.7.1: the torsional natural frequencies of the five-inertia system",
        via=(
            "as reproduced in openTorsion (Aalto-Arotor/openTorsion, commit 51287074), tests/tests.py, "
            "test_friswell_ex971 (values in Hz to 0.01)"
        ),
        reference_kind="textbook example, peer-code values",
        design="friswell_9_7_1.toml",
        quantity="torsional_natural_frequencies",
        arguments={"count": 4},
        labels=("mode 1", "mode 2", "mode 3", "mode 4"),
        published=(81.21, 141.21, 378.95, 536.36),
        unit="Hz",
        tolerance=3e-4,
        tolerance_basis=(
            "values printed to 0.01 Hz (rounding at most 6e-5); flexshaft's links between the inertias are shaft "
            "pieces, not the example's massless rigid links: their compliance and inertia lower the frequencies by "
            "about 1e-4 (see the design file)"
        ),
        note="The rigid-body twist at 0 Hz is left out.",
    ),
    Case(
        id="gibert-spinning-rod",
        title="Spinning simply supported steel rod, 30 000 rev/min",
        part="gyroscopic matrix of the shaft element (distributed polar inertia)",
        source="gibert",
        where="closed form for mode n: ω_b,f = ω_0 (sqrt(λ² + 1) ∓ λ); modes n = 1, 2",
        via="",
        reference_kind="closed form",
        design="gibert_spinning_rod.toml",
        quantity="whirl_frequencies",
        arguments={"speed_rpm": GIBERT_ROD["speed_rpm"], "count": 2},
        labels=("1 backward", "1 forward", "2 backward", "2 forward"),
        published=gibert_spinning_beam(
            length=GIBERT_ROD["length"],
            diameter=GIBERT_ROD["diameter"],
            modulus=GIBERT_ROD["modulus"],
            density=GIBERT_ROD["density"],
            speed=GIBERT_ROD["speed_rpm"] * math.pi / 30.0,
            modes=2,
        ),
        unit="rad/s",
        tolerance=1e-3,
        tolerance_basis=(
            "a different theory: the closed form omits the rotary inertia ρI that flexshaft's Euler-Bernoulli "
            "element keeps, which lowers mode n by (nπr/L)²/2 with r = D/4: 1.9e-4 (n = 1) and 7.7e-4 (n = 2); "
            "discretisation (40 elements) below 1e-6"
        ),
        note="λ = 7.6e-3: the forward and backward whirl of each mode are 1.5 % apart.",
    ),
    Case(
        id="vpcs-sdll15-cantilever",
        title="Cantilevered steel tube with a tip disk",
        part="clamped shaft end, disk mass at a free end",
        source="vpcs",
        where="sheet SDLL15/89, first bending frequency by the Rayleigh formula (quoted in V2.02.015 §2.1)",
        via="",
        reference_kind="closed form",
        design="vpcs_cantilever.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 0.0, "count": 1, "stride": 2},
        labels=("mode 1",),
        published=(rayleigh_cantilever_tip_mass(**VPCS_CANTILEVER),),
        unit="Hz",
        tolerance=1e-2,
        tolerance_basis="the source states the Rayleigh estimate of f1 to ±1 % (V2.02.015 §2.3)",
        note="The tip disk's diametral inertia is zero, as the formula's point mass.",
    ),
    Case(
        id="cengel-7-53-crossflow",
        title="Cylinder in cross-flow of air, Re = 1.632e4 (Churchill-Bernstein)",
        part="tailboom forced convection in the rotor downwash (hover)",
        source="cengel",
        where="Problem 7-53: Re = 1.632 × 10⁴, Pr = 0.7255, Nu = 71.19 by the Churchill-Bernstein correlation",
        via="",
        reference_kind="worked example",
        design=None,
        quantity="cylinder_crossflow_nusselt",
        arguments={"reynolds": 1.632e4, "prandtl": 0.7255, "method": "churchill_bernstein"},
        labels=("Nu_D",),
        published=(71.19,),
        unit="-",
        tolerance=3e-4,
        tolerance_basis=(
            "the solution prints Nu to four figures (71.19: ±7.0e-5) from Re and Pr printed to four figures: "
            "Re ±5 (3.1e-4) moves the correlation's Nu by ±1.75e-4 (d ln Nu/d ln Re = 0.57 there), Pr ±5e-5 by "
            "±2.7e-5; ±2.7e-4 in all"
        ),
        note="Re and Pr are the solution's; flexshaft's air properties are not involved.",
    ),
    Case(
        id="cengel-7-100-crossflow",
        title="Cylinder in cross-flow of air, Re = 3.254e4 (Churchill-Bernstein)",
        part="tailboom forced convection in the rotor downwash (hover)",
        source="cengel",
        where="Problem 7-100: Re = 3.254 × 10⁴, Pr = 0.7336, Nu = 107 by the Churchill-Bernstein correlation",
        via="",
        reference_kind="worked example",
        design=None,
        quantity="cylinder_crossflow_nusselt",
        arguments={"reynolds": 3.254e4, "prandtl": 0.7336, "method": "churchill_bernstein"},
        labels=("Nu_D",),
        published=(107.0,),
        unit="-",
        tolerance=5e-3,
        tolerance_basis="the solution prints Nu to three figures (107: ±0.5, 4.7e-3)",
    ),
    Case(
        id="jeffcott-rotating-damping-onset",
        title="Jeffcott rotor with internal and external viscous damping: whirl onset speed",
        part="whirl stability with internal damping (the thesis's viscous chapter-4 model)",
        source="bently2002",
        where=(
            "eq. A6-7: the growth rate of s1 vanishes at λΩ = sqrt(K/M); with D = c_e + c_i and λ = c_i/(c_e + c_i) "
            "(rotating damping c_i, stationary c_e) that is Ω = ω_n (1 + c_e/c_i)"
        ),
        via="",
        reference_kind="closed form",
        design="jeffcott_internal_damping.toml",
        quantity="whirl_onset_speed",
        arguments={
            "max_speed": 3.0 * _JEFFCOTT_OMEGA_N,
            "n_speeds": 31,
            "n_modes": 2,
            "damping_model": "viscous",
            "reference_frequency": _JEFFCOTT_OMEGA_N,
        },
        labels=("onset speed",),
        published=(
            rotating_damping_onset(
                stiffness=JEFFCOTT["stiffness"],
                mass=JEFFCOTT["mass"],
                external_damping=JEFFCOTT["external_damping"],
                internal_damping=JEFFCOTT["loss_factor"] * JEFFCOTT["stiffness"] / _JEFFCOTT_OMEGA_N,
            ),
        ),
        unit="rad/s",
        tolerance=3e-7,
        tolerance_basis=(
            "the closed form's shaft is massless, the design's has 3.1 mg (density 0.01 kg/m³) under the 10 kg "
            "disk: ω_n and the onset 7.6e-8 lower (half the ratio of Rayleigh's effective shaft mass, 17/35 of it, "
            "to the disk's); the onset is solved to 1e-7 of the speed between the analysed speeds"
        ),
        note=(
            "flexshaft's viscous model takes the shaft's loss factor η as c_i = η k/ω_ref at ω_ref = ω_n "
            "(thesis chapter 4, Zorzi & Nelson's form), which is the rotating viscous damping of the closed form. "
            "With the default hysteretic model this rotor is unstable above ω_n whenever η > 2ζ_e "
            "(docs/model.md): here η = 0.02 > 2ζ_e = 0.01."
        ),
    ),
    Case(
        id="calcady-driveshaft",
        title="Steel driveshaft, simply supported, first critical speed",
        part="isotropic tube, Euler-Bernoulli shaft element, pinned ends",
        source="calcady",
        where="'Step-by-Step Example Walkthrough', step 8: 11,390 RPM",
        via="",
        reference_kind="worked example",
        design="calcady_driveshaft.toml",
        quantity="lateral_natural_frequencies",
        arguments={"speed_rpm": 0.0, "count": 1, "stride": 2},
        labels=("first bending",),
        published=(11390.0,),
        unit="rpm",
        tolerance=6e-3,
        tolerance_basis=(
            "a different theory: the example's formula (30π/L²) sqrt(E I g/w) omits rotary inertia, which lowers "
            "the frequency by (πr/L)²/2 = 3.5e-3 (r² = I/A); its intermediate values are rounded to 4 figures "
            "(I = 1.302 in⁴, w = 0.252 lb/in: 1e-3)"
        ),
        note="flexshaft's value is the natural frequency at rest, as the formula's.",
    ),
    Case(
        id="schweitzer-amb-stiffness",
        title="Radial magnetic bearing: equivalent stiffness of a PD loop at 1 rad/s",
        part="active magnetic bearing: k_s and k_i from the magnet geometry, controller law",
        source="schweitzer2009",
        where="p. 343, k_s and k_i; evaluated for g0 = 1 mm, i0 = 1 A, A = 1e-4 m², N = 200, α = 22.5°, kp = kd = 1",
        via=(
            "as computed by ROSS (petrobras/ross, commit 631a249a), ross/bearing_seal_element.py, "
            "MagneticBearingElement docstring example: kxx[0] = -4639.28... N/m"
        ),
        reference_kind="peer-code value of a book's formula",
        design="ross_magnetic_bearing.toml",
        quantity="actuator_stiffness",
        arguments={"bearing": "amb", "frequency": 1.0},
        labels=("k_s + k_i Re C(i·1 rad/s)",),
        published=(-4639.28,),
        unit="N/m",
        tolerance=2e-6,
        tolerance_basis=(
            "ROSS prints six significant figures (rounding 1e-6); its PID derivative filter (corner 1e4 rad/s) "
            "changes Re C(i) by 1e-4 A/m, 1e-7 of the result"
        ),
        note=(
            "k_s = 4643.9 N/m dominates: the magnet's open-loop negative stiffness against a control "
            "stiffness of only k_i kp = 4.6 N/m."
        ),
    ),
    Case(
        id="iso21940-balance-tolerance",
        title="Permissible residual unbalance of a 2 kg rotor, G 6.3 at 10 000 rev/min",
        part="balance-grade imbalance (Monte-Carlo imbalance, ISO 21940-11)",
        source="iso21940",
        where="WIDIA catalogue p. K53, worked example: M = 2 kg, G 6.3, n = 10 000 RPM, U per = 12 gmm",
        via="",
        reference_kind="worked example",
        design=None,
        quantity="balance_tolerance",
        arguments={"rotor_mass": 2.0, "grade_mm_s": 6.3, "speed_rpm": 10000.0},
        labels=("U_per",),
        published=(12.0,),
        unit="g mm",
        tolerance=5e-2,
        tolerance_basis="the worked example prints two significant figures (12 gmm: ±0.5 gmm, 4.2 %)",
    ),
) + VM_CASES


def case_by_id(case_id: str) -> Case:
    """The case called ``case_id`` (ValueError listing the ids otherwise)."""
    for case in CASES:
        if case.id == case_id:
            return case
    raise ValueError(f"no validation case {case_id!r}; cases: {', '.join(c.id for c in CASES)}")
