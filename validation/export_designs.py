"""Write the design files of flexshaft's validation cases to a folder (default: ./designs).

The design files ship inside the package (``flexshaft/validation/designs/``), so that an
installed flexshaft runs ``flexshaft validate`` without this checkout; this script copies them
out to read, edit or run with the other commands, e.g.::

    python validation/export_designs.py /tmp/flexshaft-validation
    flexshaft modes /tmp/flexshaft-validation/friswell_5_9_1.toml --speed-rpm 4000

Each file's header says which published case it reproduces; docs/validation.md lists the cases.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from flexshaft.validation import CASES, design_names, design_text


def export(folder: Path) -> list[Path]:
    """Write every case design file into ``folder`` (created if needed); return the paths."""
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for name in design_names():
        path = folder / name
        path.write_text(design_text(name), encoding="utf-8")
        written.append(path)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "folder", nargs="?", type=Path, default=Path("designs"), help="where to write [default: designs]"
    )
    args = parser.parse_args(argv)
    written = export(args.folder)
    used = {c.design: c.id for c in CASES if c.design}
    for path in written:
        print(f"{path}  ({used.get(path.name, 'no case')})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
