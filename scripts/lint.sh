#!/usr/bin/env bash
# Lint, formatting and type checks with the versions pinned in the test extra (configuration in
# pyproject.toml: [tool.ruff], [tool.mypy]). Fix what they report; an ignore says why.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/venv.sh
.venv/bin/ruff check .
.venv/bin/ruff format --check .
.venv/bin/mypy  # the package, src/flexshaft ([tool.mypy] files)
