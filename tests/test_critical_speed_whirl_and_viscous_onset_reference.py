"""The Verification-Manual rotor cases compute the whirl and the damping model their sources state.

References (read for this test, or derived here):

* ANSYS VM261 (ansys/pymapdl, ``src/ansys/mapdl/core/examples/verif/vm261.dat``, read at commit
  1c24d5ca): ``*VFILL,VALUE(1,1),DATA,4950 ! 1ST FORWARD CRITICAL SPEED - REFERENCE`` and
  ``VALUE(2,1),DATA,10500 ! 2ND FORWARD CRITICAL SPEED``; the internal damping is ``MP,BETD``
  (β = 2e-4 s, damping β K proportional to the stiffness, acting in the rotating frame) and
  ``CORIOLIS,ON,,,ON,ON`` (gyroscopic and rotating damping): a viscous internal damping.
* Gyroscopic splitting, derived here: a thin slice of a spinning shaft has a polar inertia twice
  its diametral one (I_p = 2 I_d). In synchronous forward whirl (ω = Ω) its gyroscopic moment
  Ω I_p ω acts against the rotary inertia I_d ω², the net moment being −(I_p − I_d) ω² = −I_d ω²
  of the wrong sign for inertia, so the slope stiffens: the forward critical speed lies ABOVE
  the natural frequency at rest. In backward whirl the two add (I_d + I_p), so the backward
  critical speed lies BELOW it. The same holds for any whirl ratio 1/h > 0 (the gyroscopic
  moment keeps the sign of the whirl direction), so a backward whirl speed is below the forward
  one of the same mode (Nelson & McVaugh's pairs, labelled "k backward", "k forward").
* Viscous internal-damping threshold, derived here: with the rotating damping C_i = β K_s
  (shaft elements only; MP,BETD on material 1, the beams' material, the bearings being
  material 2) and no damping in the fixed frame, the fixed-frame equations in complex
  coordinates read M q'' + Ω G q' + β K_s (q' − iΩ q) + K q = 0 (K = K_s + the bearings').
  A root on the imaginary axis, q = x e^{iωt}, needs the damping term iβ(ω − Ω) K_s x to vanish
  (it is the only non-Hermitian part; x^H K_s x > 0, the shaft bends in these modes), so
  ω = Ω and K x = Ω² (M − iG) x: the onset of instability is exactly the first forward
  synchronous critical speed (docs/validation.md, "Where flexshaft's models differ from the
  sources' theories": "Jeffcott rotor, Ω = ω_n (1 + c_e/c_i)", here with c_e = 0). A
  hysteretic model has no such exact threshold (docs/validation.md, "The hysteretic whirl onset
  depends on the speed grid").

Each test computes a 5-element (VM261) or an 18-element (VM247) beam model: well under 1 s.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from flexshaft.assembly import build_model
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.quantities import synchronous_critical_speeds
from flexshaft.validation.runner import UNITS, case_design, run_case


def _rest_lateral_rpm(case_id: str, pairs: int) -> np.ndarray:
    """Undamped natural frequencies at rest [rpm] of the first ``pairs`` degenerate lateral pairs
    of the case's design: K x = ω² M x on the free DOFs, one value of each pair (the pair's two
    eigenvalues are equal, so which one is taken does not matter)."""
    model = build_model(case_design(case_by_id(case_id)))
    free = np.asarray(model.dofs.free)
    stiffness = model.K[np.ix_(free, free)].toarray()
    mass = model.M[np.ix_(free, free)].toarray()
    squared = scipy.linalg.eigh(stiffness, mass, eigvals_only=True, subset_by_index=[0, 2 * pairs - 1])
    return np.sqrt(squared[::2]) * UNITS["rpm"]


def test_the_zorzi_nelson_critical_speeds_are_forward_whirl():
    """VM261 lists FORWARD critical speeds, so the case's values must lie above the rest
    frequencies (gyroscopic stiffening, docstring). The splitting is 0.065 % and 0.42 % here; the
    margin asked, 1e-4, is 10⁸ times the eigen-solvers' round-off (1e-12 on 20 DOFs)."""
    case = case_by_id("zorzi-nelson-1976-critical")
    assert case.labels == ("1 forward", "2 forward")
    computed = np.asarray(run_case(case).computed)
    rest = _rest_lateral_rpm(case.id, 2)
    # the second "pair" at rest must not be the first one again (a degenerate pair split by round-off)
    assert rest[1] > 1.5 * rest[0]
    assert np.all(computed / rest - 1.0 > 1e-4), (computed, rest)


def test_the_critical_speed_pencil_splits_each_rest_pair():
    """Gyroscopic splitting (derived in the module docstring; docs/examples.md says the same of
    Friswell's rotor: "the gyroscopic moments of the disks split each pair into a backward and a
    forward whirl mode"): in synchronous whirl the gyroscopic moment raises the forward and
    lowers the backward frequency, so with ``whirl="both"`` (no whirl filter) the first two
    critical speeds of the VM261 rotor bracket its first natural frequency at rest, the backward
    one below and the forward one above. Measured: 4993.903 and 5000.403 rpm about 4997.157 rpm,
    ∓6.5e-4 relative; the margin asked, 1e-4 on each side, is 10⁸ times the eigen-solvers'
    round-off (1e-12 on 20 DOFs) and a sixth of the split. The first pair is the lowest two
    speeds: the second pair lies near 10,480 rpm, twice as high."""
    case = case_by_id("zorzi-nelson-1976-critical")
    speeds = synchronous_critical_speeds(case_design(case), harmonic=1.0, count=2, whirl="both") * UNITS["rpm"]
    rest = _rest_lateral_rpm(case.id, 1)[0]
    assert speeds[0] < rest * (1.0 - 1e-4) and speeds[1] > rest * (1.0 + 1e-4), (speeds, rest)


def test_the_zorzi_nelson_viscous_onset_is_the_forward_critical_speed():
    """Viscous internal damping without fixed-frame damping: the onset is the first forward
    synchronous critical speed exactly (docstring). The pencil gives that speed to round-off and
    the stability analysis refines its onset to 1e-9 between its speeds, so 1e-7 is a safe
    bound; a hysteretic model of the same loss factor puts it 1.4e-3 away (grid-dependent)."""
    onset = run_case(case_by_id("zorzi-nelson-1976-onset")).computed[0]
    critical = run_case(case_by_id("zorzi-nelson-1976-critical")).computed[0]
    assert onset == pytest.approx(critical, rel=1e-7)


@pytest.mark.parametrize(
    "case_id", ["nelson-mcvaugh-1976-critical", "nelson-mcvaugh-1976-half", "nelson-mcvaugh-1976-quarter"]
)
def test_the_nelson_mcvaugh_labels_name_the_whirl_of_each_speed(case_id):
    """Each label "k backward"/"k forward" must name the whirl of its speed: the published
    backward speed of mode k is below the forward one (gyroscopic splitting, docstring; 1.8 to
    49 % apart in VM247/VM263), and it agrees, within the case's own tolerance, with the k-th
    speed flexshaft finds among the solutions whose orbits whirl in that direction."""
    case = case_by_id(case_id)
    design = case_design(case)
    harmonic = case.arguments["harmonic"]
    by_whirl = {
        whirl: synchronous_critical_speeds(design, harmonic=harmonic, count=3, whirl=whirl) * UNITS["rpm"]
        for whirl in ("backward", "forward")
    }
    published = dict(zip(case.labels, case.published))
    for mode in (1, 2, 3):
        assert published[f"{mode} backward"] < published[f"{mode} forward"]
        for whirl in ("backward", "forward"):
            value = published[f"{mode} {whirl}"]
            assert abs(by_whirl[whirl][mode - 1] / value - 1.0) <= case.tolerance, (mode, whirl, value)
