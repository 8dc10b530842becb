"""The verdict's kinking note quotes the Budiansky-Fleck kink-band strength and the misalignment
in the units it prints, against the closed form derived here.

docs/model.md (hand-written): the kink-band strength of a ply elastic-perfectly plastic in
longitudinal shear is sigma_c = G_LT / (1 + phi/gamma_y), gamma_y defaults to S/G_LT, and the
ply check uses min(X_c, sigma_c); ``compressive_strength_note`` is the note when the file's X_c
exceeds that bound. A lamina with G_LT = 100 MPa, S = 20 MPa (gamma_y = 0.2) and phi = 2 deg
(0.034907 rad) gives sigma_c = 100 / (1 + 0.034907/0.2) = 85.14 MPa, well below Rosen's
G_LT = 100 MPa, so the numbers the note prints tell the kink-band value from Rosen's bound and
degrees from radians.
"""

from __future__ import annotations

import math
import re
from types import SimpleNamespace

from flexshaft.strength import compressive_strength, compressive_strength_note


def _number(pattern: str, text: str) -> float:
    match = re.search(pattern, text)
    assert match is not None, f"{pattern!r} not in {text!r}"
    return float(match.group(1))


def test_kink_note_prints_the_kink_band_strength_and_the_misalignment_in_degrees():
    """The note's printed kink-band strength (3 significant digits: within half a unit of the
    last digit, 0.05 MPa, of 85.14 MPa) and misalignment (2 deg, printed '2'), and the ply
    check's X_c (the same 85.1 MPa); Rosen's 100 MPa or 0.0349 (radians) would be far outside."""
    G_LT, S, phi_deg = 100e6, 20e6, 2.0
    lamina = SimpleNamespace(
        X_c=2000e6, G_LT=G_LT, S=S, fibre_misalignment_deg=phi_deg, shear_yield_strain=None, name="soft"
    )
    expected_mpa = G_LT / (1.0 + math.radians(phi_deg) / (S / G_LT)) * 1e-6
    assert abs(expected_mpa - 85.14) < 0.01  # the hand value of the docstring
    note = compressive_strength_note(compressive_strength(lamina), "soft")
    assert note is not None
    assert abs(_number(r"kink-band strength ([0-9.eE+-]+) MPa", note) - expected_mpa) <= 0.05
    assert abs(_number(r"uses ([0-9.eE+-]+) MPa", note) - expected_mpa) <= 0.05
    assert _number(r"misalignment ([0-9.eE+-]+) deg", note) == phi_deg
    assert abs(_number(r"G_LT ([0-9.eE+-]+) MPa", note) - 100.0) <= 0.05
    assert abs(_number(r"gamma_y ([0-9.eE+-]+)", note) - 0.2) <= 5e-4
