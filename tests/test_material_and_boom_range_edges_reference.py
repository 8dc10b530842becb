"""Edges of the documented ranges of a ply and of the boom's wall rule.

References (hand-written docs and closed forms derived here):

* docs/limits.md, "[materials.<name>] (kink band): initial fibre misalignment 0 to 10°": φ = 0
  is allowed. The kink-band strength of :class:`flexshaft.design.materials.Lamina`'s docstring
  and docs/model.md, σ_c = G_LT/(1 + φ/γ_y) (Budiansky & Fleck 1993), at φ = 0 is Rosen's
  σ_c = G_LT exactly (the formula has no rounding at φ = 0: 1 + 0/γ_y = 1).
* docs/limits.md: "thermal expansion ±1e-3 1/K, temperatures (−273.15, 400] °C": both ends of
  the expansion range and 400 °C itself (a stress-free temperature of a high-temperature cure,
  e.g. 350 °C) are accepted; just beyond is refused. T [K] = T [°C] + 273.15.
* docs/limits.md, section 2: "the wall thinner than the radius (smallest semi-axis)": the
  smallest of all four semi-axes, root and tip. A boom whose root lateral semi-axis (0.03 m) is
  below every tip semi-axis (an unusual flare, still a valid input) refuses a wall of 0.035 m.

The edges are exact decimal inputs compared with ``<=``/``<`` in the validators, so there is no
tolerance to choose except 1e-12 relative for the sums in floating point (ulp ~ 1e-16).
"""

from __future__ import annotations

import pydantic
import pytest

from flexshaft.design.components import Tailboom
from flexshaft.design.materials import Lamina
from flexshaft.strength import compressive_strength

G_LT = 4.0e9
PLY = {
    "kind": "lamina",
    "density": 1600.0,
    "E_L": 120.0e9,
    "E_T": 8.0e9,
    "G_LT": G_LT,
    "nu_LT": 0.3,
    "X_t": 2.0e9,
    "X_c": 5.0e9,  # above G_LT so that the kink band governs
    "Y_t": 40.0e6,
    "Y_c": 140.0e6,
    "S": 60.0e6,
}


def test_a_perfectly_aligned_ply_kinks_at_rosens_strength():
    """φ = 0 is inside the documented 0-10° range; σ_c = G_LT/(1 + 0) = G_LT (Rosen)."""
    strength = compressive_strength(Lamina(**PLY, fibre_misalignment_deg=0.0))
    assert strength.misalignment == 0.0
    assert strength.kink_band == pytest.approx(G_LT, rel=1e-12)
    assert strength.effective == pytest.approx(G_LT, rel=1e-12)  # below X_c = 5 GPa
    with pytest.raises(pydantic.ValidationError, match="fibre_misalignment_deg"):
        Lamina(**PLY, fibre_misalignment_deg=-0.1)


@pytest.mark.parametrize("name", ["alpha_L", "alpha_T"])
def test_the_expansion_range_is_closed_at_plus_minus_1e_3(name):
    """±1e-3 1/K accepted (a closed range), 1.001e-3 refused naming the key."""
    for value in (1e-3, -1e-3):
        assert getattr(Lamina(**PLY, **{name: value}), name) == value
    with pytest.raises(pydantic.ValidationError, match=name):
        Lamina(**PLY, **{name: 1.001e-3})


def test_a_stress_free_temperature_up_to_400_c_is_accepted():
    """350 °C and 400 °C accepted (623.15 K, 673.15 K); 400.1 °C refused."""
    for celsius in (350.0, 400.0):
        ply = Lamina(**PLY, stress_free_temperature_c=celsius)
        assert ply.stress_free_temperature == pytest.approx(celsius + 273.15, rel=1e-12)
    with pytest.raises(pydantic.ValidationError, match="stress_free_temperature_c"):
        Lamina(**PLY, stress_free_temperature_c=400.1)


def _flared_boom(wall: float) -> Tailboom:
    return Tailboom(
        length=2.0,
        root_semi_axes=(0.1, 0.03),
        tip_semi_axes=(0.06, 0.05),
        wall_thickness=wall,
        material="al",
        shaft_clearance=0.08,
    )


def test_the_boom_wall_is_checked_against_the_root_semi_axes_too():
    """Smallest semi-axis min(0.1, 0.03, 0.06, 0.05) = 0.03 m, at the root: 0.035 m refused."""
    assert _flared_boom(0.029).wall_thickness == 0.029
    with pytest.raises(pydantic.ValidationError, match="smallest semi-axis"):
        _flared_boom(0.035)
