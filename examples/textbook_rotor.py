"""Textbook rotor: Friswell et al., Example 5.9.1, against its published natural frequencies.

Physics. A uniform solid steel shaft, 1.5 m long and 50 mm in diameter (E = 211 GPa, G = 81.2
GPa, ρ = 7810 kg/m³), carries two rigid steel disks 70 mm thick at 0.5 m (diameter 280 mm)
and 1.0 m (350 mm) and rests at both ends on isotropic bearings of 1 MN/m, with no damping
and no rotational bearing stiffness. The disks' mass and inertias follow from their geometry
(bore 50 mm): m = ρ π (D² − d²) w / 4, I_p = m (D² + d²) / 8, I_d = I_p / 2 + m w² / 12. The
shaft is modelled with six Timoshenko elements (``shear_deformation = true``), the model of the
book and of ROSS, so the finite-element natural frequencies can be compared digit for digit.
At rest the lateral modes come in equal pairs; at 4000 rev/min the gyroscopic moments of the
disks split each pair into a backward and a forward whirl mode.

Source. M. I. Friswell, J. E. T. Penny, S. D. Garvey and A. W. Lees, *Dynamics of Rotating
Machines*, Cambridge University Press, 2010, Example 5.9.1 (p. 206). The reference values are
those published for this example by ROSS, the open-source rotordynamics package
(petrobras/ross, ``docs/examples/example_05_09_01.rst``, six elements, the values also checked
in its ``ross/tests/test_examples.py``).

The schema refuses a zero bore (``wall_thickness < outer_diameter / 2``), so the solid shaft is
given a 0.2 µm bore; its effect on the section properties is below 1e-10.

Run: ``python examples/textbook_rotor.py`` (``--quick`` changes nothing here: it is fast).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

from flexshaft.analyses import modes
from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.units import rpm_to_rad_s

STEEL_DENSITY = 7810.0  # kg/m^3
DISK_WIDTH, DISK_BORE = 0.07, 0.05  # m

#: Lateral natural frequencies [rad/s] published for the example (ROSS documentation).
PUBLISHED = {
    0.0: [86.65811435, 86.65811435, 274.31285391, 274.31285391, 716.78631221, 716.78631221],
    4000.0: [85.389467, 87.7958637, 251.78460413, 294.71333087, 600.17936195, 827.07536193],
}
#: Largest relative difference accepted. The published values carry 8 to 10 significant figures
#: and both codes solve the same discrete model (six Timoshenko elements with Cowper's shear
#: coefficient, consistent mass, the same disks): measured 5e-11. 1e-6 is far above round-off and
#: far below any change of model (48 elements instead of 6 move the third pair by 3e-4).
TOLERANCE = 1e-6


def disk_properties(outer_diameter: float) -> tuple[float, float, float]:
    """Mass [kg], diametral and polar inertia [kg m²] of a steel disk on the shaft."""
    mass = STEEL_DENSITY * math.pi * (outer_diameter**2 - DISK_BORE**2) * DISK_WIDTH / 4.0
    polar = mass * (outer_diameter**2 + DISK_BORE**2) / 8.0
    return mass, polar / 2.0 + mass * DISK_WIDTH**2 / 12.0, polar


def design_text(elements: int = 6) -> str:
    """The example as a flexshaft design file (no tailboom: the bearings hold the shaft to ground)."""
    disks = ""
    for name, x, diameter in (("left", 0.5, 0.28), ("right", 1.0, 0.35)):
        mass, diametral, polar = disk_properties(diameter)
        disks += (
            f'[[disks]]\nname = "{name}"\nx = {x}\nmass = {mass!r}\n'
            f"diametral_inertia = {diametral!r}\npolar_inertia = {polar!r}\n"
        )
    return f"""
name = "Friswell et al. (2010), Example 5.9.1"

[materials.steel]
kind = "isotropic"
E = 211.0e9
G = 81.2e9
density = {STEEL_DENSITY}

[shaft]
x_start = 0.0
x_end = 1.5
outer_diameter = 0.05
wall_thickness = 0.0249999      # solid shaft: a 0.2 um bore (the schema asks for a tube)
material = "steel"
fixed_start = ["u", "theta"]    # no rigid-body axial and twist motion
shear_deformation = true        # Timoshenko elements, as in the book

[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = {{ v = 1.0e6, w = 1.0e6 }}

[[bearings]]
name = "right"
kind = "contact"
x = 1.5
stiffness = {{ v = 1.0e6, w = 1.0e6 }}

{disks}
[operating]
speed_rpm = 4000.0
power = 0.0

[mesh]
shaft_elements = {elements}
"""


def lateral_frequencies(model, speed_rpm: float, count: int = 6) -> np.ndarray:
    """The lowest ``count`` lateral natural frequencies [rad/s] at ``speed_rpm`` (exact eigen-solution)."""
    result = modes(model, rpm_to_rad_s(speed_rpm), n_modes=2 * count + 4, basis_size=model.dofs.free.size)
    lateral = result.kind == "lateral"
    return np.abs(result.eigenvalues[lateral])[:count]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="reduced size (no effect: the example is small)")
    parser.add_argument("--out", type=Path, default=None, help="unused: the example writes no file")
    parser.parse_args(argv)

    model = build_model(loads_design(design_text()))
    worst = 0.0
    print("Friswell et al. (2010) Example 5.9.1: lateral natural frequencies [rad/s]")
    print(f"{'speed [rpm]':>11} {'mode':>4} {'flexshaft':>10} {'published':>10} {'difference':>10}")
    for speed_rpm, published in PUBLISHED.items():
        computed = lateral_frequencies(model, speed_rpm, len(published))
        for mode, (ours, theirs) in enumerate(zip(computed, published), start=1):
            difference = ours / theirs - 1.0
            worst = max(worst, abs(difference))
            print(f"{speed_rpm:11.0f} {mode:4d} {ours:10.2f} {theirs:10.2f} {difference:+10.1e}")
    print(f"largest relative difference {worst:.1e} (accepted: {TOLERANCE:.0e})")
    if worst > TOLERANCE:
        print("FAILED: flexshaft disagrees with the published frequencies", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
