"""The thesis-shaft comparison (:func:`flexshaft.thesis.whirl.compare_shafts`, figures 4.2-4.4)
hands the reference frequency it is given to each shaft, checked on its aluminium shaft against
the Jeffcott rotor's closed form.

flexshaft's viscous internal-damping model turns the shaft's loss factor η into the rotating
viscous damping c_i = η k / ω_ref. For a Jeffcott rotor (disk m on a massless shaft of stiffness
k, stationary damping c_e at the disk), m r'' + (c_e + c_i) r' + (k − i c_i Ω) r = 0 has the root
s = i ω_n exactly when c_i Ω = (c_e + c_i) ω_n, so the whirl onset is

    Ω_onset = ω_n (1 + c_e ω_ref / (η k))

(derived in tests/test_shaft_stability_reference_frequency_reference.py). The rotor is the
validation case ``jeffcott-rotating-damping-onset``'s (k = 75 398 N/m, m = 10 kg, c_e = 2 ζ_e m ω_n,
ζ_e = 0.005, η = 0.02): with ω_ref = 2 ω_n, c_e ω_ref/(η k) = 4 ζ_e/η = 1 and Ω_onset = 2 ω_n,
where the default ω_ref (the first shaft mode, ω_n) would give 1.5 ω_n. The comparison's
aluminium shaft takes the material ``al6061_t6``: here the case's own steel under that name, so
the closed form holds; its FMC shafts need a lamina shaft material (a generic carbon/epoxy,
not asserted). Tolerance 1e-6 as in that file: the 3.1 mg shaft under the 10 kg disk lowers ω_n
by 7.6e-8 and the onset is solved to 1e-7 of the speed.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from flexshaft.design.io import design_from_dict
from flexshaft.thesis.whirl import compare_shafts
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import case_design

K, M, C_E, ETA = 75398.22368615503, 10.0, 8.683215054699211, 0.02

LAMINA = {
    "kind": "lamina",
    "density": 0.01,
    "E_L": 130e9,
    "E_T": 9e9,
    "G_LT": 5e9,
    "nu_LT": 0.3,
    "X_t": 1.5e9,
    "X_c": 1.2e9,
    "Y_t": 50e6,
    "Y_c": 200e6,
    "S": 70e6,
}


def test_the_aluminium_shaft_uses_the_reference_frequency_it_is_given():
    data = case_design(case_by_id("jeffcott-rotating-damping-onset")).model_dump()
    data["materials"]["al6061_t6"] = dict(data["materials"]["steel"])
    data["materials"]["fmc"] = LAMINA
    data["shaft"]["material"], data["shaft"]["layup"] = "fmc", "(45/-45)s"
    design = design_from_dict(data)
    omega_n = math.sqrt(K / M)
    omega_ref = 2.0 * omega_n
    expected = omega_n * (1.0 + C_E * omega_ref / (ETA * K))
    assert expected == pytest.approx(2.0 * omega_n, rel=1e-6)  # 4 ζ_e / η = 1
    speeds = np.linspace(0.0, 3.0 * omega_n, 32)  # 2 ω_n mid-way between two samples, no near-tie
    res = compare_shafts(design, speeds, "viscous", n_modes=2, reference_frequency=omega_ref)
    assert res["aluminium 6061-T6"].onset_speed == pytest.approx(expected, rel=1e-6)
