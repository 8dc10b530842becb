"""Arguments, options and choices shared by the commands (typer ``Annotated`` style).

Choices are enums, so their values appear in ``--help`` and are matched case-insensitively;
their values are the ``Literal`` aliases of the layers below (a test checks they agree).
Units are written in brackets in every help text (the apps set ``rich_markup_mode=None``,
so ``[rpm]`` is printed, not taken for markup).
"""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated

import typer

from flexshaft.parallel import MAX_JOBS

__all__ = [
    "Convection",
    "DampingModel",
    "DaskOption",
    "DesignArgument",
    "ForceOption",
    "JOBS_HELP",
    "JobsOption",
    "MAX_JOBS",
    "JsonOption",
    "LossModel",
    "NModesOption",
    "Resolution",
    "Studies",
]


class DampingModel(str, Enum):
    """Internal-damping method of the stability analysis (``flexshaft.analyses.stability.DampingModel``)."""

    hysteretic = "hysteretic"
    viscous = "viscous"


class LossModel(str, Enum):
    """Hysteretic heat model of the shaft (``flexshaft.design.schema.InternalDamping``)."""

    thesis = "thesis"
    rotating = "rotating"


class Convection(str, Enum):
    """Convection correlation of the rotating shaft (``flexshaft.design.thermal_schema.ShaftConvection``)."""

    becker = "becker"
    kendoush = "kendoush"


class Studies(str, Enum):
    """Design studies in the ``run`` report."""

    report = "report"
    full = "full"
    none = "none"


class Embedded(str, Enum):
    """The embedded designs (``flexshaft.design.EMBEDDED_DESIGNS``)."""

    baseline = "baseline"
    tuned = "tuned"
    current = "current"


class Resolution(str, Enum):
    """Grid resolution of the chapter-3 design studies (``flexshaft.thesis.design_studies.STUDY_GRIDS``)."""

    report = "report"
    full = "full"


DesignArgument = Annotated[
    Path | None,
    typer.Argument(
        help="Design file (TOML). Default: the embedded tuned design (`flexshaft baseline --name tuned`), as "
        "for every command.",
        show_default=False,
        metavar="DESIGN",
    ),
]
JsonOption = Annotated[
    bool,
    typer.Option(
        "--json",
        help="Print machine-readable JSON on stdout: SI values, each unit in its key "
        "(e.g. frequency_Hz, wall_thickness_m; speeds _rpm, temperatures _c [°C]).",
    ),
]
ForceOption = Annotated[
    bool,
    typer.Option(
        "--force", help="Write into a non-empty --out folder that flexshaft did not write, or wrote for another design."
    ),
]
JOBS_HELP = (
    f"Local worker processes (one BLAS thread each), at most {MAX_JOBS}; the work bound counts at "
    "most this machine's CPUs."
)
JobsOption = Annotated[int, typer.Option("--jobs", "-j", min=1, max=MAX_JOBS, help=JOBS_HELP)]
DaskOption = Annotated[
    str | None, typer.Option("--dask", help="Dask scheduler address, e.g. tcp://host:8786 (needs flexshaft[dask]).")
]
NModesOption = Annotated[
    int,
    typer.Option(
        "--n-modes",
        min=1,
        max=500,
        help="Number of modes (numbered from 1 in the output; the Python API counts from 0).",
    ),
]
