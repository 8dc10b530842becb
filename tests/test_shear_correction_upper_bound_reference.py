"""The shear correction factor's documented range (0, 1] includes its upper end k = 1.

docs/limits.md: "Also bounded: ... the shear correction (0, 1]" — a closed upper end, so k = 1
(plain first-order shear deformation theory without correction) is a valid design value and
must build a tube, while any k above 1 is refused.

With k = 1 the transverse shear stiffness of first-order shear deformation theory is
A_ij = Σ_k Q_ij,k t_k (derived here as in tests/test_lamina_shear_correction_reference.py: the
transverse shear strains rotate with the ply angle α like a vector, so a ply carries
Q55 = G13 cos²α + G23 sin²α, Q44 = G13 sin²α + G23 cos²α, Q45 = (G13 − G23) cos α sin α). For a
single [0] ply of wall thickness t (cos α = 1, sin α = 0):

    A55 = t G13*,  A44 = t G23*,  A45 = 0,

read as [0, 0] = A55, [1, 1] = A44, [0, 1] = A45: that order is the API contract of
:func:`flexshaft.laminate.transverse_shear_stiffness` (its Returns: "[[A55, A45], [A45, A44]]",
src/flexshaft/laminate.py:331-335), not an assumption of this test.

with the complex moduli of the correspondence principle, G13* = G13 (1 + iη_G) and
G23* = G23 (1 + iη_T) (the loss factors of G_LT and E_T, as
:meth:`flexshaft.laminate.Lamina.from_loss_factors` documents).

Tolerance 1e-12 relative: each entry is one product of decimal inputs times cos² = 1 (a few
roundings, nothing ill-conditioned); A45 = (G13 − G23) cos 0 sin 0 is exactly 0.

Written for the mutation h85b-lamina-shear-correction-one-refused of scripts/mutations.toml.
That mutation is caught by the documented acceptance of k = 1 itself: the refusal raises while
the design (or the Lamina) is built, before any stiffness assertion runs.
"""

from __future__ import annotations

import pytest

# the sibling test's one-ply tube (its constants and design text), with k = 1 for its k = 0.6
from test_lamina_shear_correction_reference import DESIGN as CORRECTED  # noqa: E402
from test_lamina_shear_correction_reference import E_L, E_T, ETA_G, ETA_T, G_13, G_23, G_LT, K_SHEAR, NU_LT, WALL

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.laminate import Lamina, transverse_shear_stiffness

DESIGN = CORRECTED.replace(f"shear_correction = {K_SHEAR}", "shear_correction = 1.0")
assert DESIGN != CORRECTED  # the one line replaced


def test_a_design_with_unit_shear_correction_builds_and_shears_uncorrected():
    laminate = build_model(loads_design(DESIGN)).shaft.laminate
    stiffness = transverse_shear_stiffness(laminate)
    assert stiffness[0, 0] == pytest.approx(WALL * G_13 * (1 + 1j * ETA_G), rel=1e-12)  # A55 = t G13*
    assert stiffness[1, 1] == pytest.approx(WALL * G_23 * (1 + 1j * ETA_T), rel=1e-12)  # A44 = t G23*
    assert stiffness[0, 1] == 0.0  # A45 = (G13 - G23) cos 0 sin 0, exactly zero


def test_the_lamina_accepts_the_closed_upper_end_and_refuses_above_it():
    assert Lamina(E_L, E_T, G_LT, NU_LT, 1500.0, shear_correction=1.0).shear_correction == 1.0
    with pytest.raises(ValueError, match="shear_correction"):
        Lamina(E_L, E_T, G_LT, NU_LT, 1500.0, shear_correction=1.0 + 1e-9)
