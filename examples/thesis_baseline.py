"""The thesis baseline: every analysis at the operating point, the verdict and a Campbell diagram.

Physics. The driveline of Ocalan (2002), thesis Table 3.1: a one-piece (55/−55/0/0)s
carbon/polyurethane flexible-matrix-composite shaft, 8.05 m long, spinning supercritically at
4800 rev/min on a tapered elliptical aluminium tailboom, held by two contact hanger bearings (at
0.79 m and at its aft end) and two active magnetic bearings with the study gains K_p = 1e7 N/m,
K_d = 0. The run
computes the natural frequencies at rest and at speed, the Campbell diagram (damped
eigenvalues over speed, forward and backward whirl), the spin-up imbalance response from the
shaft's mass eccentricity, the static manoeuvre and torque loads, the ply Tsai-Wu safety
factor, torsional buckling, the shaft temperature and the whirl-stability onset of the
rotating-frame internal damping, and checks them against the design's ``[requirements]``.

This is the configuration the thesis's design studies start from, not a finished design: it
fails its requirements (whirl onset below the operating speed, spin-up orbit far above the
limit). ``custom_fmc_design.py`` starts from the tuned design, which passes.

Run: ``python examples/thesis_baseline.py [--quick] [--out DIR]``; writes ``campbell.png``.
``--quick`` uses 60 spin-up speeds and 12 Campbell speeds instead of 651 and 60.
"""

from __future__ import annotations

import argparse
import dataclasses
from pathlib import Path

import flexshaft as fs
from flexshaft.units import rad_s_to_rpm


def campbell_figure(campbell, operating_rpm: float):
    """The Campbell diagram as a matplotlib figure: ``campbell.plot()`` where the result offers
    it, else the plotting function it hands off to."""
    if "campbell" in getattr(campbell, "plots", {}):
        return campbell.plot(operating_rpm=operating_rpm)
    from flexshaft.plot.driveline import campbell_figure as figure

    critical = [c.speed_rpm for c in campbell.critical_speeds]
    return figure(rad_s_to_rpm(campbell.speeds), campbell.frequencies, campbell.whirl, critical, operating_rpm)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer speeds (for the test suite)")
    parser.add_argument("--out", type=Path, default=Path("example-output/thesis_baseline"), help="output folder")
    args = parser.parse_args(argv)

    design = fs.baseline_design()
    # what `flexshaft run` computes (fs.REPORT), with fewer speeds for the test suite
    resolution = dataclasses.replace(fs.REPORT, spinup_speeds=60, campbell_speeds=12) if args.quick else fs.REPORT
    results = fs.assess(design, resolution)
    operating_rpm = design.operating.speed_rpm

    print(design.name)
    print(f"shaft mass {results.model.shaft_mass:.2f} kg, operating speed {operating_rpm:.0f} rpm")
    print("natural frequencies at rest [Hz]:", ", ".join(f"{f:.2f}" for f in results.modes_at_rest.frequencies[:6]))
    print(
        "critical speeds [rpm]:", ", ".join(f"{c.speed_rpm:.0f} ({c.whirl})" for c in results.campbell.critical_speeds)
    )
    print()
    print(results.verdict.summary)
    for check in results.verdict.checks:
        print(f"  {check.status:>13}  {check.title}")

    args.out.mkdir(parents=True, exist_ok=True)
    figure = campbell_figure(results.campbell, operating_rpm)
    figure.savefig(args.out / "campbell.png", dpi=120)
    print(f"\nCampbell diagram: {args.out / 'campbell.png'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
