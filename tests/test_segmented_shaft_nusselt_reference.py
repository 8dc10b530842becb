"""The Nusselt number a segmented shaft's thermal result reports: the tube covering the most length.

``ShaftThermal.nusselt`` (flexshaft.thermal.analysis) is documented as the rotating-cylinder
correlation "of the diameter covering the most length when a segmented shaft's tubes differ".
A 2 m steel shaft in two segments, 1.5 m of D_o = 50 mm and 0.5 m of D_o = 80 mm (a rigid
coupling between them), spinning at Ω = 300 rad/s in air at 300 K: the reported number is the
correlation's at D = 50 mm. The correlation (Becker's power law Nu = C Re_ω^(2/3) Pr^(1/3),
Re_ω = Ω D²/ν) is evaluated by ``rotating_shaft_convection`` at each diameter; its constant C is
not re-checked here (tests/test_convection_references.py says why), only that the two
diameters' numbers stand in the ratio (80/50)^(4/3) = 1.87 of the power law, so that reporting
the wrong tube cannot pass. Tolerance 1e-12 relative (the same operations).
"""

from __future__ import annotations

from flexshaft.assembly import build_model
from flexshaft.design import design_from_dict
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.options import ThermalOptions
from flexshaft.thermal.shaft import rotating_shaft_convection

OMEGA, T_AIR = 300.0, 300.0


def test_the_reported_nusselt_is_the_longer_tubes():
    rigid = dict.fromkeys(("angular_stiffness", "axial_stiffness", "torsional_stiffness", "lateral_stiffness"), "rigid")
    data = {
        "name": "two tubes",
        "materials": {"steel": {"kind": "isotropic", "E": 200e9, "G": 80e9, "density": 7850.0, "loss_factor": 0.01}},
        "shaft": {
            "x_start": 0.0,
            "x_end": 2.0,
            "outer_diameter": 0.05,
            "wall_thickness": 0.002,
            "material": "steel",
            "fixed_start": ["u", "v", "w", "theta"],
            "fixed_end": ["v", "w"],
            "segments": [
                {"name": "long", "x_start": 0.0, "x_end": 1.5},
                {"name": "short", "x_start": 1.5, "x_end": 2.0, "outer_diameter": 0.08},
            ],
        },
        "couplings": [{"name": "joint", "x": 1.5, **rigid}],
        "bearings": [{"name": "far", "kind": "contact", "x": 2.0, "stiffness": {"u": 0.0}}],
        "operating": {"speed": OMEGA, "power": 1e3},
        "loads": {"eccentricity": 1e-5},
        "mesh": {"shaft_elements": 8},
    }
    model = build_model(design_from_dict(data))
    result = shaft_thermal(model, ThermalOptions(), "thesis", air_temperature=T_AIR)
    narrow, wide = (rotating_shaft_convection(D, OMEGA, T_AIR, "becker")[1].value for D in (0.05, 0.08))
    assert abs(wide / narrow - 1.6 ** (4 / 3)) < 1e-12
    assert abs(result.nusselt.value - narrow) < 1e-12 * narrow
