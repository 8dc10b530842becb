"""What every result object shares: ``.plot()``, ``.to_dataset()``, ``.save()``, and the
tables a notebook shows.

A result (modes, Campbell diagram, stability, response, strength, thermal, spin-up map,
verdict) keeps its data in SI units. ``.to_dataset()`` gives an :class:`xarray.Dataset` with
CF-style attributes (``units``, ``long_name``; coded labels as integers with ``flag_values``
and ``flag_meanings``; a ``Conventions`` attribute), ``.save(path)`` writes it to netCDF
(netCDF3 through scipy unless netCDF4 is installed; ``.nc`` is added to a path without a
suffix), and ``.plot(ax=None, **kw)`` converts the data to engineering units and hands them to a
figure function of :mod:`flexshaft.plot` (imported only then), returning the matplotlib figure.
xarray and matplotlib are imported lazily.

In a notebook a result shows a compact table (``_repr_html_``, built by :func:`html_table`);
``print()`` of the modes prints the same table as text (:func:`text_table`); results whose
natural form is a table have ``.to_dataframe()`` (:func:`dataframe`: pandas, imported then; it
comes with xarray).
"""

from __future__ import annotations

import html
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from flexshaft import __version__
from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.netcdf import write_netcdf

__all__ = [
    "CONVENTIONS",
    "ResultMixin",
    "StationWarning",
    "cell_text",
    "coded",
    "dataframe",
    "html_table",
    "netcdf_path",
    "new_arrays",
    "new_dataset",
    "text_table",
]

#: The ``Conventions`` attribute of every dataset the package writes.
CONVENTIONS = "CF-1.10"


def coded(labels, meanings: Sequence[str], long_name: str) -> tuple[np.ndarray, dict]:
    """Integer codes of string ``labels`` with CF ``flag_values``/``flag_meanings`` attributes.

    Unknown labels raise ``ValueError``; meanings must not contain spaces (CF).
    """
    labels = np.asarray(labels, dtype=str)
    lookup = {m: k for k, m in enumerate(meanings)}
    unknown = sorted(set(np.unique(labels)) - set(lookup))
    if unknown:
        raise ValueError(f"labels {unknown} are not among {list(meanings)}")
    codes = np.vectorize(lookup.__getitem__, otypes=[np.int8])(labels) if labels.size else labels.astype(np.int8)
    attrs = {
        "long_name": long_name,
        "flag_values": np.arange(len(meanings), dtype=np.int8),
        "flag_meanings": " ".join(meanings),
    }
    return codes, attrs


def new_arrays(variables: dict, coords: dict, title: str, **attrs: Any) -> LabelledArrays:
    """The plain-array content of :func:`new_dataset` (no xarray import): study results travel
    between processes as these (:mod:`flexshaft.analyses.labelled`)."""
    return LabelledArrays(
        variables, coords, {"Conventions": CONVENTIONS, "title": title, "source": f"flexshaft {__version__}", **attrs}
    )


def new_dataset(variables: dict, coords: dict, title: str, **attrs: Any):
    """An :class:`xarray.Dataset` with the package's global attributes."""
    return new_arrays(variables, coords, title, **attrs).to_dataset()


class StationWarning(UserWarning):
    """A station asked for is not a node: the result is shown at the nearest node."""


def cell_text(value: Any, digits: int = 4) -> str:
    """A table cell: a float with ``digits`` significant figures (``g`` format), an integer
    (Python or NumPy) whole (12345 stays "12345"), a boolean as ``true``/``false``, None as an
    em dash, anything else as text."""
    if value is None:
        return "—"
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value)).lower()
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        return f"{float(value):.{digits}g}"
    return str(value)


def text_table(headers: Sequence[str], rows: Sequence[Sequence[Any]], title: str = "", caption: str = "") -> str:
    """A plain-text table: numbers right-aligned, text left-aligned, one line per row."""
    cells = [[cell_text(v) for v in row] for row in rows]
    numeric = [
        all(isinstance(row[i], (int, float, np.integer, np.floating)) or row[i] is None for row in rows) and bool(rows)
        for i in range(len(headers))
    ]
    widths = [max([len(h), *(len(r[i]) for r in cells)]) for i, h in enumerate(headers)]

    def line(values) -> str:
        return "  ".join(v.rjust(w) if num else v.ljust(w) for v, w, num in zip(values, widths, numeric)).rstrip()

    out = ([title] if title else []) + [line(headers), line(["-" * w for w in widths])]
    out += [line(r) for r in cells]
    return "\n".join(out + ([caption] if caption else []))


def html_table(
    headers: Sequence[str],
    rows: Sequence[Sequence[Any]],
    *,
    title: str = "",
    caption: str = "",
    row_styles: Sequence[Mapping[int, str]] | None = None,
) -> str:
    """An HTML table (every cell escaped; numbers right-aligned through :func:`cell_text`), with
    an optional bold title above and a caption below. ``row_styles[k]`` maps a column of row k
    to a CSS style (e.g. the colour of a verdict's status)."""
    esc = html.escape
    head = "".join(f"<th>{esc(str(h))}</th>" for h in headers)
    body = []
    for k, row in enumerate(rows):
        styles = row_styles[k] if row_styles is not None else {}
        tds = []
        for i, value in enumerate(row):
            align = "right" if isinstance(value, (int, float, np.integer, np.floating)) else "left"
            style = f"text-align:{align};" + styles.get(i, "")
            tds.append(f'<td style="{esc(style)}">{esc(cell_text(value))}</td>')
        body.append("<tr>" + "".join(tds) + "</tr>")
    top = f"<p><b>{esc(title)}</b></p>" if title else ""
    bottom = f'<p style="font-size:smaller">{esc(caption)}</p>' if caption else ""
    return f"{top}<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>{bottom}"


def dataframe(columns: Mapping[str, Sequence[Any]], index: str | None = None):
    """A :class:`pandas.DataFrame` of ``columns`` (indexed by the column ``index`` if given)."""
    import pandas as pd  # heavy (about 0.5 s to import): only a table asked for needs it; xarray brings it

    frame = pd.DataFrame(dict(columns))
    return frame.set_index(index) if index is not None else frame


def netcdf_path(path: str | Path) -> Path:
    """``path`` with ``.nc`` added when it has no suffix (``"campbell"`` → ``campbell.nc``)."""
    path = Path(path)
    return path if path.suffix else path.with_name(path.name + ".nc")


class ResultMixin:
    """``.plot()`` through :mod:`flexshaft.plot`, ``.save()`` through ``.to_dataset()``."""

    #: ``kind -> name of the method that draws it``; the first entry is the default.
    plots: dict[str, str] = {}

    def to_dataset(self):  # pragma: no cover - every result defines it
        raise NotImplementedError

    def save(self, path: str | Path) -> Path:
        """Write :meth:`to_dataset` to a netCDF file at ``path``, with ``.nc`` added when the
        path has no suffix (``save("campbell")`` writes ``campbell.nc``); returns the path
        written."""

        path = netcdf_path(path)
        write_netcdf(self.to_dataset(), path)
        return path

    def plot(self, kind: str | None = None, ax=None, **kwargs):
        """Draw the result (``kind`` selects the figure when it has several); returns the figure.

        ``ax`` draws into an existing matplotlib axes (its figure is returned); keyword
        arguments go to the plotting function of :mod:`flexshaft.plot`.
        """
        if not self.plots:
            raise TypeError(f"{type(self).__name__} has no plot")
        kind = kind or next(iter(self.plots))
        if kind not in self.plots:
            raise ValueError(f"kind must be one of {sorted(self.plots)} (got {kind!r})")
        return getattr(self, self.plots[kind])(ax=ax, **kwargs)
