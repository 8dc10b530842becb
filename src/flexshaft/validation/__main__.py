"""``python -m flexshaft.validation [PAGE]``: print the generated validation table, or with
PAGE (docs/validation.md) rewrite the page's generated block in place; exit 3 when a case
leaves its tolerance."""

from __future__ import annotations

import argparse
from pathlib import Path

from flexshaft.validation.runner import markdown, run_validation, update_document


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m flexshaft.validation", description=__doc__.splitlines()[0])
    parser.add_argument("page", nargs="?", type=Path, help="Markdown page whose generated block to rewrite")
    args = parser.parse_args(argv)
    report = run_validation()
    if args.page is None:
        print(markdown(report), end="")
    else:
        args.page.write_text(update_document(args.page.read_text(encoding="utf-8"), report), encoding="utf-8")
    return 0 if report.passed else 3


if __name__ == "__main__":
    raise SystemExit(main())
