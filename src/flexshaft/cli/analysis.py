"""The analysis commands: ``check``, ``baseline``, ``modes``, ``stability``, ``thermal``.

Each prints tables in engineering units (rpm, Hz, °C, mm) with the unit in every header, or
with ``--json`` the same numbers as JSON (SI, unit-suffixed keys). Mode numbers start at 1.
``stability`` and ``thermal`` (seconds with ``--compare-thesis`` or ``--sweeps``) show a
transient progress line on a terminal.
"""

from __future__ import annotations

import sys
from typing import Annotated, Any

import typer

from flexshaft.cli.common import (
    check_finite,
    design_fingerprint,
    fail,
    guarded,
    load_design_argument,
    plain,
    print_json,
    refuse_imbalance_cases,
    refused_by_analyses,
)
from flexshaft.cli.options import (
    Convection,
    DampingModel,
    DesignArgument,
    Embedded,
    JsonOption,
    LossModel,
    NModesOption,
)
from flexshaft.cli.progress import StageProgress

__all__ = ["baseline", "check", "modes", "stability", "thermal"]

#: Lowest ``stability --reference-hz`` [Hz]: the viscous model's damping η K/ω_ref grows as
#: 1/ω_ref, and far below any natural frequency it overflows the eigen-solution (1e-200 Hz ended
#: in an internal error); 1e-3 Hz runs on the embedded designs.
LOWEST_REFERENCE_HZ = 1e-3

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).


@guarded
def baseline(
    name: Annotated[
        Embedded,
        typer.Option(
            "--name",
            case_sensitive=False,
            help="Embedded design: baseline (thesis Table 3.1: K_p 1e7 N/m, K_d 0), tuned (the tuned final "
            "design, every command's default) or current (today's segmented aluminium driveline).",
        ),
    ] = Embedded.baseline,
    as_json: JsonOption = False,
) -> None:
    """Print an embedded design file (start your own from a copy); with --json, its values as
    the schema holds them."""
    from flexshaft.design import embedded_design, embedded_text

    if as_json:
        print_json(embedded_design(name.value).model_dump(mode="json"))
        return
    sys.stdout.write(embedded_text(name.value))


@guarded
def check(design: DesignArgument = None, as_json: JsonOption = False) -> None:
    """Validate a design file and print a one-line summary (with --json: every problem found)."""
    import warnings

    from flexshaft.assembly.size import ProblemSizeWarning, check_problem_size
    from flexshaft.design import DesignError

    try:
        loaded = load_design_argument(design)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", ProblemSizeWarning)
            check_problem_size(loaded.design, "run", source=loaded.source)  # refuses what a run would refuse
        refused_by_analyses(loaded)  # and what the analyses refuse: a design `check` calls ok runs
    except DesignError as exc:
        if as_json:
            print_json(
                {
                    "ok": False,
                    "source": exc.source,
                    "problems": [{"path": p.path, "message": p.message} for p in exc.problems],
                }
            )
        raise
    notes = [str(w.message) for w in caught if issubclass(w.category, ProblemSizeWarning)]
    if as_json:
        print_json(
            {
                "ok": True,
                "design": loaded.design.name,
                "source": loaded.source,
                "design_fingerprint": design_fingerprint(loaded.design),
                "warnings": notes,
            }
        )
        return
    from flexshaft.cli.tables import design_source

    typer.echo(f"ok: {plain(loaded.design.name)} ({plain(design_source(design))})")
    for note in notes:
        typer.echo(f"warning: {plain(note)}", err=True)


@guarded
def modes(
    design: DesignArgument = None,
    speed_rpm: Annotated[
        float | None,
        typer.Option(
            "--speed-rpm", help="Spin speed [rpm]; default: the design's operating speed.", show_default=False
        ),
    ] = None,
    n_modes: NModesOption = 10,
    as_json: JsonOption = False,
) -> None:
    """Damped natural frequencies, damping, whirl direction and component of the lowest modes
    (numbered from 1)."""
    from flexshaft.design.schema import MAX_SPEED_RPM

    check_finite("--speed-rpm", speed_rpm, 0.0, MAX_SPEED_RPM, unit="rpm")
    loaded = load_design_argument(design)
    from flexshaft.cli.bounds import check_modes

    check_modes(loaded.design, n_modes)  # refused with the numbers before computing
    from flexshaft.analyses.summary import modes_at
    from flexshaft.assembly import build_model
    from flexshaft.units import rad_s_to_rpm, rpm_to_rad_s

    model = build_model(loaded.design)
    speed = model.speed if speed_rpm is None else rpm_to_rad_s(speed_rpm)
    rows = modes_at(model, speed, n_modes)
    if as_json:
        print_json(
            {"design": loaded.design.name, "speed_rpm": rad_s_to_rpm(speed), "mode_numbering": "from 1", "modes": rows}
        )
        return
    from flexshaft.cli.tables import design_heading, design_source, modes_table, print_line, sig, stdout_console

    console = stdout_console()
    print_line(console, design_heading(loaded.design.name, design_source(design)), style="bold")
    console.print(modes_table(f"modes at {sig(rad_s_to_rpm(speed))} rpm", rows))


@guarded
def stability(
    design: DesignArgument = None,
    max_rpm: Annotated[
        float | None,
        typer.Option(
            "--max-rpm", help="Highest speed analysed [rpm]; default: 1.5 × the operating speed.", show_default=False
        ),
    ] = None,
    n_speeds: Annotated[
        int,
        typer.Option(
            "--n-speeds",
            min=2,
            max=2000,
            help="Number of speeds (× --n-modes: refused with the numbers when estimated above 10 min).",
        ),
    ] = 61,
    n_modes: Annotated[
        int, typer.Option("--n-modes", min=1, max=100, help="Number of tracked modes (see --n-speeds).")
    ] = 10,
    damping_model: Annotated[
        DampingModel,
        typer.Option(
            "--damping-model",
            case_sensitive=False,
            help="hysteretic: the composite's loss factor, each mode at its own frequency; viscous: thesis "
            "chapter 4, one reference frequency.",
        ),
    ] = DampingModel.hysteretic,
    reference_hz: Annotated[
        float | None,
        typer.Option(
            "--reference-hz",
            help="Reference frequency ω_ref of the viscous model [Hz]; default: the first shaft mode.",
            show_default=False,
        ),
    ] = None,
    compare_thesis: Annotated[
        bool, typer.Option("--compare-thesis", help="Also the thesis's aluminium, (45/-45)s and (45/-45/0/0)s shafts.")
    ] = False,
    as_json: JsonOption = False,
) -> None:
    """Whirl stability with internal damping: onset speed of instability and the unstable mode,
    against the design's required onset margin."""
    import numpy as np

    from flexshaft.design.schema import MAX_SPEED_RPM

    check_finite("--max-rpm", max_rpm, maximum=MAX_SPEED_RPM, positive=True, unit="rpm")
    check_finite("--reference-hz", reference_hz, positive=True)
    if reference_hz is not None and reference_hz < LOWEST_REFERENCE_HZ:
        fail(
            f"--reference-hz: at least {LOWEST_REFERENCE_HZ:g} Hz: the viscous model's damping η K/ω_ref grows as "
            f"1/ω_ref and overflows the eigen-solution far below any natural frequency (got {reference_hz:g})"
        )
    loaded = load_design_argument(design)
    from flexshaft.cli.bounds import check_stability

    check_stability(loaded.design, n_speeds, n_modes, 4 if compare_thesis else 1)  # before computing
    from flexshaft.analyses.stability import stability as stability_analysis
    from flexshaft.assembly import build_model
    from flexshaft.design import DesignError
    from flexshaft.resolution import REPORT
    from flexshaft.units import hz_to_rpm, rad_s_to_rpm, rpm_to_rad_s
    from flexshaft.verdict.checks import whirl_onset_check

    d = loaded.design
    model = build_model(d)
    top = rpm_to_rad_s(max_rpm) if max_rpm else max(model.speed, 1.0) * REPORT.whirl_top
    speeds = np.linspace(0.0, top, n_speeds)
    # [Hz] -> [rad/s] through the rpm of the same rotation frequency
    reference = None if reference_hz is None else rpm_to_rad_s(hz_to_rpm(reference_hz))
    designs = {"design": d}
    if compare_thesis:
        from flexshaft.thesis.whirl import thesis_shaft_designs

        try:
            designs.update(thesis_shaft_designs(d))
        except DesignError as exc:
            fail(f"--compare-thesis needs an isotropic material 'al6061_t6' and a lamina shaft:\n{exc}")
    margin = d.requirements.min_onset_margin
    shafts: dict[str, dict[str, Any]] = {}  # the JSON record of each shaft
    with StageProgress(transient=True) as progress:
        results = {}
        for label, dd in designs.items():
            progress.step(f"whirl stability: {label}")
            results[label] = stability_analysis(
                model if label == "design" else build_model(dd), speeds, n_modes, damping_model.value, reference
            )
    for label, result in results.items():
        onset_check = whirl_onset_check(result.onset_speed, float(speeds[-1]), model.speed, margin)
        shafts[label] = {
            "onset_speed_rpm": None if result.onset_speed is None else rad_s_to_rpm(result.onset_speed),
            "unstable_mode_whirl": result.onset_whirl,
            "min_damping_ratio": float(result.stability_margin.min()),
            "onset_check": onset_check.status,
        }
    operating_rpm = rad_s_to_rpm(model.speed)
    out = {
        "design": d.name,
        "damping_model": damping_model.value,
        "analysed_to_rpm": rad_s_to_rpm(top),
        "operating_speed_rpm": operating_rpm,
        "min_onset_margin": margin,
        "required_onset_rpm": (1 + margin) * operating_rpm,
        "shafts": shafts,
    }
    if as_json:
        print_json(out)
        return
    from flexshaft.cli.tables import design_heading, design_source, print_line, sig, stdout_console, table

    console = stdout_console()
    print_line(console, design_heading(d.name, design_source(design)), style="bold")
    print_line(
        console,
        f"operating speed {sig(operating_rpm)} rpm; required: no whirl onset below "
        f"{sig(out['required_onset_rpm'])} rpm ({sig(margin * 100, 3)} % margin, [requirements] "
        f"min_onset_margin); {damping_model.value} internal damping, analysed to "
        f"{sig(out['analysed_to_rpm'])} rpm",
    )
    rows = []
    for label, r in shafts.items():
        onset = r["onset_speed_rpm"]
        ratio = onset / operating_rpm if onset is not None and operating_rpm > 0 else None
        rows.append(
            [
                label,
                onset if onset is not None else f"stable to {sig(out['analysed_to_rpm'])}",
                ratio,
                r["unstable_mode_whirl"] or "—",
                r["min_damping_ratio"],
                r["onset_check"].upper(),
            ]
        )
    console.print(
        table(
            "whirl onset",
            ["shaft", "onset [rpm]", "onset / operating", "unstable whirl", "min damping ratio ζ", "check"],
            rows,
            numeric={1, 2, 4},
        )
    )


@guarded
def thermal(
    design: DesignArgument = None,
    loss_model: Annotated[
        LossModel | None,
        typer.Option(
            "--loss-model",
            case_sensitive=False,
            help="Shaft heat model; default: the design's analysis.internal_damping.",
            show_default=False,
        ),
    ] = None,
    convection: Annotated[
        Convection | None,
        typer.Option(
            "--convection",
            case_sensitive=False,
            help="Rotating-shaft convection correlation; default: the design's.",
            show_default=False,
        ),
    ] = None,
    self_heat: Annotated[
        bool, typer.Option("--self-heating", help="Iterate temperature-dependent matrix properties to equilibrium.")
    ] = False,
    sweeps: Annotated[
        bool,
        typer.Option("--sweeps", help="Peak rise against wall thickness and convection (thesis figures 3.18, 3.19)."),
    ] = False,
    as_json: JsonOption = False,
) -> None:
    """Tailboom skin temperatures (hover, parked), shaft temperature rise and self-heating margin."""
    loaded = load_design_argument(design)
    refuse_imbalance_cases(loaded.design, loaded.source)  # the shaft's heat needs the imbalance response
    from flexshaft.assembly import build_model
    from flexshaft.thermal.study import thermal_summary

    d = loaded.design
    with StageProgress(transient=True) as progress:
        progress.step(
            "tailboom and shaft temperatures" + (", self-heating" if self_heat else "") + (", sweeps" if sweeps else "")
        )
        out = thermal_summary(
            d,
            build_model(d),
            loss_model=None if loss_model is None else loss_model.value,
            convection=None if convection is None else convection.value,
            self_heat=self_heat,
            sweeps=sweeps,
        )
    if as_json:
        print_json(out)
        return
    from flexshaft.cli.tables import design_heading, design_source

    _print_thermal(design_heading(d.name, design_source(design)), out)


def _print_thermal(heading: str, out: dict) -> None:
    from flexshaft.cli.tables import print_line, sig, stdout_console, table

    console = stdout_console()
    print_line(console, heading, style="bold")
    if "tailboom_c" in out:
        flags = out.get("tailboom_flags", {})
        console.print(
            table(
                "tailboom skin temperature",
                ["condition", "temperature [°C]", "note"],
                [[k, v, flags.get(k, "")] for k, v in out["tailboom_c"].items()],
                numeric={1},
            )
        )
    rows = []
    for key, s in out.items():
        if key.startswith("shaft_") and key.endswith("_loss_model"):
            model = key[len("shaft_") : -len("_loss_model")]
            rows.append(
                [
                    model + (" (used)" if model == out["loss_model"] else ""),
                    s["air_c"],
                    s["h_W_m2K"],
                    s["heat_vibration_W"],
                    s["heat_static_W"],
                    s["peak_rise_K"],
                    s["peak_x_m"],
                ]
            )
    console.print(
        table(
            "shaft at the operating speed",
            [
                "loss model",
                "air [°C]",
                "h [W/(m² K)]",
                "vibration heat [W]",
                "static heat [W]",
                "peak rise [K]",
                "peak at x [m]",
            ],
            rows,
        )
    )
    source = {
        "self_heating": "self-heating equilibrium",
        "reference_properties": "reference-temperature properties",
    }.get(out["max_shaft_temperature_source"], out["max_shaft_temperature_source"])
    print_line(
        console,
        f"max shaft temperature {sig(out['max_shaft_temperature_c'])} °C ({source}); allowable "
        f"{sig(out['allowable_temperature_c'])} °C; margin {sig(out['temperature_margin_K'])} K",
    )
    if "self_heating" in out:
        sh = out["self_heating"]
        print_line(
            console, f"self-heating: {sh['status']} after {sh['iterations']} iterations, margin {sig(sh['margin_K'])} K"
        )
    for key, title in (
        ("peak_rise_K_by_wall", "peak shaft temperature rise by wall thickness"),
        ("peak_rise_K_by_convection", "peak shaft temperature rise by convection coefficient"),
    ):
        if key in out:
            console.print(table(title, ["case", "peak rise [K]"], [[k, v] for k, v in out[key].items()], numeric={1}))
