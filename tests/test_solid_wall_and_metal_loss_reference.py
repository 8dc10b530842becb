"""A shaft wall at half its diameter, and a metal whose loss factor is omitted.

References, independent of flexshaft's code:

* a tube of outer diameter D_o and wall t has the inner diameter D_i = D_o − 2t (geometry); the
  design file's contract (``Shaft`` and docs/design-reference.md: ``wall_thickness`` "less than
  D_o/2 (a tube of inner diameter D_o − 2t)") is strict, because at t = D_o/2 the bore closes
  (D_i = 0: a solid bar, not a tube). The edge is checked in exact binary numbers: D_o = 2⁻⁴ m,
  t = 2⁻⁵ m is the closed bore, and t = 2⁻⁵ − 2⁻²⁰ m leaves D_i = 2⁻¹⁹ m exactly (every
  number a dyadic fraction, no rounding), in the design and in the tube the model is built of.
* a metal given without loss data has no internal damping (the neutral idealisation: no
  damping is assumed that the file does not give; a loss factor η makes both moduli complex,
  E(1 + iη)). A metal written without a loss factor is elastic: the built tube's
  moduli are E(1 + i·0) and G(1 + i·0), exactly the real numbers of the file (70 GPa and
  26 GPa for aluminium), and a loss factor written in the file gives E·η as the loss modulus
  (η = 0.004: 0.28 GPa), to the last bit of one product (rel 1e-15).

Cheap: a schema check and one tube's moduli (no mesh, no solve).
Written for the mutations h51c-comp-solid-shaft-accepted and
h51c-materials-isotropic-loss-default of scripts/mutations.toml.
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from flexshaft.assembly.build import shaft_properties
from flexshaft.design import design_from_dict
from flexshaft.design.components import Shaft

D_O = 2.0**-4  # 62.5 mm


def _shaft(wall: float) -> Shaft:
    return Shaft(x_start=0.0, x_end=1.0, outer_diameter=D_O, wall_thickness=wall, material="al")


def test_a_wall_of_half_the_diameter_closes_the_bore_and_is_refused():
    with pytest.raises(ValidationError, match="wall_thickness"):
        _shaft(D_O / 2.0)  # D_i = D_o - 2t = 0: a solid bar
    thinner = _shaft(2.0**-5 - 2.0**-20)
    assert thinner.inner_diameter == 2.0**-19  # D_o - 2t, exact in binary
    # the bore of the tube the model is built of (assembly.build), not only the design's property
    material = {"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0}
    assert _metal_tube(material, outer=D_O, wall=2.0**-5 - 2.0**-20).inner_diameter == 2.0**-19


def _metal_tube(material: dict, outer: float = 0.05, wall: float = 0.002):
    design = design_from_dict(
        {
            "name": "metal loss default",
            "materials": {"al": material},
            "shaft": {
                "x_start": 0.0,
                "x_end": 1.0,
                "outer_diameter": outer,
                "wall_thickness": wall,
                "material": "al",
                "fixed_start": ["u", "v", "w", "theta"],
                "fixed_end": ["v", "w"],
            },
            "bearings": [{"name": "far", "kind": "contact", "x": 1.0, "stiffness": {"u": 0.0}}],
            "operating": {"speed_rpm": 3000.0, "power": 0.0},
            "loads": {"eccentricity": 0.0},
        }
    )
    return shaft_properties(design)


def test_a_metal_without_a_loss_factor_is_elastic():
    tube = _metal_tube({"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0})
    assert tube.youngs_modulus == complex(70.0e9, 0.0)
    assert tube.shear_modulus == complex(26.0e9, 0.0)


def test_a_written_metal_loss_factor_gives_the_loss_modulus():
    tube = _metal_tube({"kind": "isotropic", "E": 70.0e9, "G": 26.0e9, "density": 2700.0, "loss_factor": 0.004})
    assert tube.youngs_modulus.real == 70.0e9 and tube.shear_modulus.real == 26.0e9
    assert tube.youngs_modulus.imag == pytest.approx(0.28e9, rel=1e-15)  # E η
    assert tube.shear_modulus.imag == pytest.approx(0.104e9, rel=1e-15)  # G η
