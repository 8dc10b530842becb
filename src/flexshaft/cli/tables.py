"""Terminal tables: engineering units in the headers, significant figures in the cells.

Every cell goes through :func:`cell` (numbers with :func:`sig`, text through
:func:`flexshaft.cli.common.plain`) and reaches rich as a :class:`rich.text.Text`, so markup in
a design or component name is never interpreted. Headers carry their unit, ``frequency [Hz]``;
lengths are shown in mm, stresses in MPa and speeds in rpm, as in the HTML report.
"""

from __future__ import annotations

import errno
import functools
import math
import os
import sys
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import Any

from flexshaft.cli.common import plain
from flexshaft.units import m_to_mm, rad_s_to_rpm

__all__ = [
    "DISPLAY_UNITS",
    "cell",
    "dataset_json",
    "dataset_table",
    "design_heading",
    "design_source",
    "display_unit",
    "matrix_table",
    "modes_table",
    "print_line",
    "sig",
    "stderr_console",
    "stdout_console",
    "table",
    "unit_key",
    "verdict_line",
    "verdict_table",
]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Pascals per megapascal.
PA_PER_MPA = 1.0e6

#: SI unit (a Dataset's ``units`` attribute) -> (display unit, conversion from SI).
DISPLAY_UNITS: dict[str, tuple[str, Callable[[Any], Any]]] = {
    "m": ("mm", m_to_mm),
    "Pa": ("MPa", lambda value: value / PA_PER_MPA),
    "rad/s": ("rpm", rad_s_to_rpm),
}


def sig(value: Any, digits: int = 4) -> str:
    """A number with ``digits`` significant figures, for people.

    Integers of up to six digits are never rounded away (``4800``, ``123457``); magnitudes
    from 1e-3 to 1e6 are fixed-point (``55.32``, ``0.01235``), others in exponent form with
    trailing zeros dropped (``3.1e-06``, ``1.2e+07``). None prints as an em dash.
    """
    if value is None:
        return "—"
    if isinstance(value, bool):
        return str(value).lower()
    value = float(value)
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    if value == 0.0:
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    if -3 <= exponent < 6:
        if exponent >= digits - 1:
            return f"{value:.0f}"
        return f"{value:.{digits - 1 - exponent}f}".rstrip("0").rstrip(".")
    mantissa, _, power = f"{value:.{digits - 1}e}".partition("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return f"{mantissa}e{power}"


def cell(value: Any, digits: int = 4) -> str:
    """A table cell: numbers with :func:`sig`, None as an em dash, the rest as plain text."""
    if value is None or (isinstance(value, (int, float)) and not isinstance(value, bool)):
        return sig(value, digits)
    if hasattr(value, "dtype") and getattr(value, "shape", None) == ():  # numpy scalar
        return sig(float(value), digits)
    return plain(value)


def stdout_console():
    """A rich console on stdout: no markup or highlighting of its own; 200 columns when
    stdout is not a terminal, so that piped tables are never squeezed. A reader that goes
    away (``flexshaft run | head``) raises ``BrokenPipeError`` (:func:`_quiet_on_broken_pipe`)."""
    from rich.console import Console

    console = Console(highlight=False, width=None if sys.stdout.isatty() else 200)
    console.on_broken_pipe = functools.partial(_quiet_on_broken_pipe, console)  # type: ignore[method-assign]
    return console


def _quiet_on_broken_pipe(console) -> None:
    """rich's ``Console.on_broken_pipe`` for the CLI: silence the console and raise
    ``BrokenPipeError``, which the commands' error boundary (:func:`flexshaft.cli.common.guarded`)
    handles as it does a write of ``typer.echo`` to a closed stdout: a reader that went away,
    exit 0, the output folder's marker written as after a finished command (``run`` writes its
    folder before it prints its tables). rich's own hook raises ``SystemExit(1)``, which passed by
    the boundary: the folder of a finished ``flexshaft run | head`` stayed marked incomplete, and
    the command exited 1 without a word."""
    console.quiet = True
    raise BrokenPipeError(errno.EPIPE, os.strerror(errno.EPIPE))


def stderr_console():
    """A rich console on stderr (progress displays)."""
    from rich.console import Console

    return Console(stderr=True, highlight=False)


def design_source(path: Path | None, embedded: str | None = None) -> str:
    """Where a command's design came from: the file, or ``embedded NAME design`` without one
    (``embedded``, default :data:`flexshaft.design.DEFAULT_DESIGN`)."""
    if path is not None:
        return os.fsdecode(path)
    from flexshaft.design import DEFAULT_DESIGN  # loaded already: the command read its design

    return f"embedded {embedded or DEFAULT_DESIGN} design"


def design_heading(name: str, source: str) -> str:
    """The first line of every command: ``design: NAME (SOURCE)``, the design it analyses and
    where it came from (:func:`design_source`)."""
    return f"design: {name} ({source})"


def print_line(console, text: str, style: str | None = None) -> None:
    """Print one line of plain text (no markup interpretation, control characters escaped)."""
    from rich.text import Text

    console.print(Text(plain(text), style=style or ""), soft_wrap=True)


def table(
    title: str | None,
    headers: Sequence[str],
    rows: Iterable[Sequence[Any]],
    *,
    numeric: Iterable[int] | None = None,
    caption: str | None = None,
    digits: int = 4,
):
    """A rich table of plain-text cells; ``numeric`` column indices are right-aligned
    (default: the columns whose first cell is a number)."""
    from rich.table import Table
    from rich.text import Text

    rows = [list(r) for r in rows]
    if numeric is None:
        numeric = (
            {i for i, v in enumerate(rows[0]) if isinstance(v, (int, float)) and not isinstance(v, bool)}
            if rows
            else set()
        )
    numeric = set(numeric)
    out = Table(
        title=Text(plain(title)) if title else None,
        caption=Text(plain(caption)) if caption else None,
        min_width=max(len(title or ""), len(caption or "")) + 4,
    )  # no wrapped title or caption
    cells = [[c if isinstance(c, Text) else Text(cell(c, digits)) for c in row] for row in rows]
    for i, header in enumerate(headers):  # on a narrow terminal headers and text wrap, numbers never do
        word = max((len(w) for w in str(header).split()), default=0)
        widest = max([word, *(r[i].cell_len for r in cells if i < len(r))]) if i in numeric else None
        out.add_column(
            Text(plain(header)), justify="right" if i in numeric else "left", min_width=widest, overflow="fold"
        )
    for row in cells:
        out.add_row(*row)
    return out


def modes_table(title: str, rows: Sequence[dict]):
    """Modes (rows of :func:`flexshaft.analyses.summary.modes_table`): mode numbers from 1."""
    return table(
        title,
        ["mode", "f [Hz]", "f [rpm]", "ζ [-]", "δ [-]", "kind", "whirl", "component"],
        [
            [
                r["mode"],
                r["frequency_Hz"],
                r["frequency_rpm"],
                r["damping_ratio"],
                r["log_decrement"],
                r["kind"],
                "—" if r["whirl"] == "none" else r["whirl"],
                r["component"],
            ]
            for r in rows
        ],
        numeric=range(5),
        caption="f damped frequency, ζ damping ratio, δ log decrement; mode numbers start at 1",
    )


_STATUS_STYLE = {"PASS": "green", "FAIL": "bold red", "not evaluated": "yellow"}


def verdict_table(verdict):
    """The requirements verdict (:class:`flexshaft.verdict.result.Verdict`), worst case of each."""
    from rich.text import Text

    from flexshaft.report.verdict import VERDICT_COLUMNS, verdict_rows

    rows = []
    for check, row in zip(verdict.checks, verdict_rows(verdict, compact=True)):
        status = row[4]
        where = row[5] if status != "not evaluated" and row[5] else row[6]  # a check with no location: its note
        count = f" {check.n_failed}/{len(check.findings)}" if check.n_failed and len(check.findings) > 1 else ""
        rows.append([*row[:4], Text(plain(status + count), style=_STATUS_STYLE[status]), where])
    return table("requirements verdict (worst case of each)", VERDICT_COLUMNS[:-1], rows, numeric={1, 2, 3})


def verdict_line(verdict) -> str:
    """The verdict in one line, first of a run's output after the design's:
    ``verdict: FAIL — 2 of 9 checks fail: whirl onset speed (3125 rpm; required ≥ 5520 rpm), …``
    (:func:`flexshaft.verdict.text.verdict_headline`)."""
    from flexshaft.verdict.text import verdict_headline

    return f"verdict: {verdict_headline(verdict)}"


# ------------------------------------------------------------------------------------------------
# xarray Datasets of the studies (units in attributes)


def display_unit(units: str | None) -> tuple[str, Callable[[Any], Any]]:
    """The display unit of an SI unit string and the conversion to it ("" if dimensionless)."""
    units = (units or "").strip()
    if units in DISPLAY_UNITS:
        return DISPLAY_UNITS[units]
    return ("" if units in ("", "1") else units), (lambda value: value)


def unit_key(name: str, units: str | None) -> str:
    """A JSON key with its SI unit as suffix: ``wall_thickness_m``, ``kp_N_per_m``."""
    units = (units or "").strip()
    if units in ("", "1"):
        return name
    suffix = {"N m": "Nm"}.get(units, units.replace("/", "_per_").replace(" ", "_"))
    return f"{name}_{suffix}"


def _header(da) -> str:
    unit, _ = display_unit(da.attrs.get("units"))
    label = str(da.name)
    return f"{label} [{unit}]" if unit else label


def _values(da):
    _, convert = display_unit(da.attrs.get("units"))
    return convert(da.values)


def dataset_table(ds, variables: Sequence[str], title: str):
    """A table of a one-dimensional study Dataset: its coordinate and ``variables``, in
    display units with the unit in each header."""
    (dim,) = ds[variables[0]].dims
    columns = [ds[dim], *(ds[v] for v in variables)]
    values = [_values(c) for c in columns]
    rows = [[float(v[i]) for v in values] for i in range(ds.sizes[dim])]
    return table(title, [_header(c) for c in columns], rows, numeric=range(len(columns)))


def matrix_table(da, title: str):
    """A two-dimensional DataArray as a table: first dimension down, second across."""
    rows_dim, cols_dim = da.dims
    row_values, col_values = _values(da[rows_dim]), _values(da[cols_dim])
    unit, _ = display_unit(da[cols_dim].attrs.get("units"))
    corner = f"{rows_dim} \\ {cols_dim}" + (f" [{unit}]" if unit else "")
    values = _values(da)
    rows = [[float(r), *(float(v) for v in values[i])] for i, r in enumerate(row_values)]
    return table(
        f"{title}: {_header(da)}", [corner, *(sig(c) for c in col_values)], rows, numeric=range(len(col_values) + 1)
    )


def dataset_json(ds, variables: Sequence[str] | None = None) -> dict:
    """A study Dataset as JSON-ready data: coordinates and variables under unit-suffixed keys
    (SI values, from the ``units`` attributes), with each variable's dimensions."""
    names = list(variables) if variables is not None else list(ds.data_vars)
    return {
        "coords": {unit_key(str(c), ds[c].attrs.get("units")): ds[c].values.tolist() for c in ds.coords},
        "variables": {unit_key(v, ds[v].attrs.get("units")): ds[v].values.tolist() for v in names},
        "dims": {
            unit_key(v, ds[v].attrs.get("units")): [unit_key(str(d), ds[d].attrs.get("units")) for d in ds[v].dims]
            for v in names
        },
    }
