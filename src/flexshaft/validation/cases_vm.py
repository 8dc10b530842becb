"""Validation cases from primary rotordynamics sources whose inputs and published values reach us
through the input files of the ANSYS Mechanical APDL Verification Manual.

Each ANSYS verification test (VM) restates a published problem (its ``/COM, REF`` line names the
paper or book), gives every input of the model, and holds the reference values in its result
table (``*VFILL,VALUE(i,1),DATA,...``: the "TARGET" column). The input files are read from
PyMAPDL's copy (``ansys/pymapdl``, ``src/ansys/mapdl/core/examples/verif/``, commit
5e5a4759). The target values are those the VM attributes to the publication; ANSYS's own
results are not used.
"""

from __future__ import annotations

from flexshaft.validation.case_types import Case, Source

__all__ = ["VM_CASES", "VM_SOURCES", "ZORZI_REFERENCE_FREQUENCY"]

_VM = (
    "as restated in the ANSYS Verification Manual input file {vm} (ansys/pymapdl, "
    "src/ansys/mapdl/core/examples/verif/{file}, commit 5e5a4759)"
)

VM_SOURCES: dict[str, Source] = {
    "nelson1976": Source(
        "nelson1976",
        "H. D. Nelson, J. M. McVaugh, The dynamics of rotor-bearing systems using finite elements, "
        "J. Engineering for Industry 98(2):593-600, 1976: the critical (whirl) speeds of its rotor, as "
        "restated with the rotor's inputs by ANSYS Verification Manual tests VM247 and VM263.",
    ),
    "zorzi1976": Source(
        "zorzi1976",
        "E. S. Zorzi, H. D. Nelson, Finite element simulation of rotor-bearing systems with internal "
        "damping, J. Engineering for Power 99:71-76 (the year as VM261 gives it, 1976): the critical speeds "
        "of a uniform shaft with internal viscous damping, as restated with the rotor's inputs by ANSYS "
        "Verification Manual test VM261.",
    ),
    "thomson": Source(
        "thomson",
        "W. T. Thomson, Vibration Theory and Applications, 2nd printing, p. 272, Example 8.4-5: the "
        "torsional frequencies of a drill pipe carrying the bit, as restated with the inputs by ANSYS "
        "Verification Manual test VM57.",
    ),
}

#: ω_ref [rad/s] at which the Zorzi-Nelson design's loss factor η gives the viscous c_i = β k (β = η/ω_ref).
ZORZI_REFERENCE_FREQUENCY = 500.0

_NM_KIND = "published finite-element results"
_NM_BASIS = (
    "the published values are the paper's finite-element solution of the same Rayleigh-beam model, "
    "printed to five figures; the VM's metric inputs carry three significant figures (a diameter of "
    "1.02 cm is known to ±0.5 %, and the whirl speeds of a beam scale with its diameter), which bounds "
    "the agreement at a few tenths of a per cent. flexshaft's values are converged (18 and 144 elements "
    "agree to 1e-5)"
)
_NM_LABELS = ("1 backward", "1 forward", "2 backward", "2 forward", "3 backward", "3 forward")
_NM_NOTE = (
    "The pencil K x = ω² (M − i G/h) x gives the critical speeds exactly, without a speed grid; the "
    "labels follow the whirl of each solution's orbit. The rotor is Nelson and McVaugh's: a stepped "
    "shaft with tubular steps, one disk, two isotropic undamped bearings."
)

_ZN_BASIS = (
    "the published 4950 rev/min differs by 1.0 % from an exact solution of the VM's own inputs (an "
    "Euler-Bernoulli beam of 20 elements on its bearings: 4998.6 and 10501 rev/min, "
    "tests/test_validation_source_budgets_reference.py), the paper's model and not its inputs; the "
    "published speeds carry three figures (10500: ±0.48 %). The inputs are rounded: E = 2.1e11 Pa two "
    "significant figures (±2.4 %), which moves the speeds by ±0.46 % and ±0.09 % only (the bearings, "
    "1.75e7 N/m, are about as stiff as the shaft: d ln f/d ln E = 0.195 and 0.039, not ½), ρ = 7800 "
    "kg/m³ three (±0.03 % in a speed). Five elements as the VM; 80 elements change the two speeds by "
    "5e-5 and 2e-4"
)

VM_CASES: tuple[Case, ...] = (
    Case(
        id="nelson-mcvaugh-1976-critical",
        title="Nelson-McVaugh rotor: critical speeds (ω = Ω)",
        part="stepped shaft with tubular steps, disk gyroscopics, isotropic bearings: synchronous critical speeds",
        source="nelson1976",
        where="the rotor's critical speeds for whirl ratio 1, as the VM's result table lists them (CRIC1-CRIC6)",
        via=_VM.format(vm="VM247", file="vm247.dat")
        + ", VALUE(1..6,1) ('critical speed value obtained from reference')",
        reference_kind=_NM_KIND,
        design="nelson_mcvaugh_1976.toml",
        quantity="synchronous_critical_speeds",
        arguments={"harmonic": 1.0, "count": 6},
        labels=_NM_LABELS,
        published=(15470.0, 17159.0, 46612.0, 49983.0, 64752.0, 96457.0),
        unit="rpm",
        tolerance=1e-2,
        tolerance_basis=_NM_BASIS,
        note=_NM_NOTE,
    ),
    Case(
        id="nelson-mcvaugh-1976-half",
        title="Nelson-McVaugh rotor: spin speeds where a whirl frequency is 2Ω",
        part="gyroscopic coupling away from synchronism (whirl ratio 1/2)",
        source="nelson1976",
        where="whirl speeds for whirl ratio 1/2, divided by 2 by the VM to the spin speed (its 'slope 2')",
        via=_VM.format(vm="VM263", file="vm263.dat")
        + ", VALUE(1..6,1) ('critical speed value obtained from reference/2')",
        reference_kind=_NM_KIND,
        design="nelson_mcvaugh_1976.toml",
        quantity="synchronous_critical_speeds",
        arguments={"harmonic": 2.0, "count": 6},
        labels=_NM_LABELS,
        published=(7929.0, 8350.0, 23760.0, 24602.0, 34820.0, 42776.0),
        unit="rpm",
        tolerance=1e-2,
        tolerance_basis=_NM_BASIS,
        note=(
            "VM263 models the same rotor with axisymmetric solid elements; its inputs (bearings of 4.378e7 "
            "N/m, E, ρ) are VM247's, whose beam model is the design here. " + _NM_NOTE
        ),
    ),
    Case(
        id="nelson-mcvaugh-1976-quarter",
        title="Nelson-McVaugh rotor: spin speeds where a whirl frequency is 4Ω",
        part="gyroscopic coupling away from synchronism (whirl ratio 1/4)",
        source="nelson1976",
        where="whirl speeds for whirl ratio 1/4, divided by 4 by the VM to the spin speed (its 'slope 4')",
        via=_VM.format(vm="VM247", file="vm247.dat")
        + ", VALUE(7..12,1) ('critical speed value obtained from reference/4')",
        reference_kind=_NM_KIND,
        design="nelson_mcvaugh_1976.toml",
        quantity="synchronous_critical_speeds",
        arguments={"harmonic": 4.0, "count": 6},
        labels=_NM_LABELS,
        published=(4015.0, 4120.25, 11989.25, 12200.0, 18184.25, 20162.25),
        unit="rpm",
        tolerance=1e-2,
        tolerance_basis=_NM_BASIS,
        note=_NM_NOTE,
    ),
    Case(
        id="zorzi-nelson-1976-critical",
        title="Uniform shaft on flexible bearings: forward critical speeds",
        part="uniform steel shaft on undamped bearings: forward synchronous critical speeds",
        source="zorzi1976",
        where="first and second forward critical speeds, 4950 and 10 500 rev/min, as the VM's result table lists them",
        via=_VM.format(vm="VM261", file="vm261.dat") + ", VALUE(1,1) and VALUE(2,1)",
        reference_kind="published finite-element results",
        design="zorzi_nelson_1976.toml",
        quantity="synchronous_critical_speeds",
        arguments={"harmonic": 1.0, "count": 2, "whirl": "forward"},
        labels=("1 forward", "2 forward"),
        published=(4950.0, 10500.0),
        unit="rpm",
        tolerance=1.5e-2,
        tolerance_basis=_ZN_BASIS,
        note="The internal damping does not enter the undamped critical speeds.",
    ),
    Case(
        id="zorzi-nelson-1976-onset",
        title="Uniform shaft with internal viscous damping on undamped bearings: whirl onset speed",
        part="whirl instability from rotating (internal) viscous damping, multi-mode rotor (the viscous model)",
        source="zorzi1976",
        where=(
            "the first forward critical speed, 4950 rev/min: with no damping in the fixed frame the viscous "
            "internal-damping threshold Ω = ω (1 + c_e/c_i) is the forward critical speed itself, and the VM "
            "lists the first forward mode as unstable just above it ('unstable frequency near 5000 rpm')"
        ),
        via=_VM.format(vm="VM261", file="vm261.dat") + ", VALUE(1,1) and VALUE(3,1)",
        reference_kind="published finite-element results",
        design="zorzi_nelson_1976.toml",
        quantity="whirl_onset_speed",
        arguments={
            "max_speed": 700.0,
            "n_speeds": 15,
            "n_modes": 4,
            "damping_model": "viscous",
            "reference_frequency": ZORZI_REFERENCE_FREQUENCY,
        },
        labels=("onset speed",),
        published=(4950.0,),
        unit="rpm",
        tolerance=1.5e-2,
        tolerance_basis=_ZN_BASIS + "; the onset is solved to 1e-9 between the analysed speeds",
        note=(
            "Internal damping β = 2e-4 s proportional to the shaft's stiffness (VM261's MP,BETD), entered as "
            "the loss factor η = β ω_ref at ω_ref = 500 rad/s of flexshaft's viscous model (c_i = η k/ω_ref "
            "= β k). The published logarithmic decrements of the unstable modes (the VM's VALUE(3..4,1), read "
            "from the paper's Fig. 3) are not compared: see docs/validation.md."
        ),
    ),
    Case(
        id="thomson-drill-pipe-torsion",
        title="Drill pipe 5000 ft long with the bit's inertia: torsional frequencies",
        part="torsion of a long tube with an end inertia (continuous shaft, disk polar inertia)",
        source="thomson",
        where="Example 8.4-5 (p. 272): f1 = 0.3833 Hz, f2 = 1.260 Hz",
        via=_VM.format(vm="VM57", file="vm57.dat") + ", VALUE(1..2,1)",
        reference_kind="textbook example",
        design="thomson_drill_pipe.toml",
        quantity="torsional_block_frequencies",
        arguments={"count": 2},
        labels=("f1", "f2"),
        published=(0.3833, 1.260),
        unit="Hz",
        tolerance=5e-4,
        tolerance_basis=(
            "the example prints four significant figures (0.3833: ±1.3e-4; 1.260: ±4e-4); its frequency "
            "equation β tan β = J_pipe/J_bit gives 0.383323 and 1.259942 Hz for these inputs, and 96 "
            "elements reproduce them to 5e-5"
        ),
        note="Clamped in twist at the top, free at the bit. The inputs are converted from ft, slug and lbf.",
    ),
)
