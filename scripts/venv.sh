#!/usr/bin/env bash
# The development virtual environment .venv: the package (editable) with the test extras (the
# test, lint and type-check tools) and the explorer's (for its browser tests). Run by
# scripts/test.sh and scripts/lint.sh; a second run only confirms what is installed.
set -euo pipefail
cd "$(dirname "$0")/.."
python3 -m venv .venv
.venv/bin/python -m pip install --quiet --upgrade pip
.venv/bin/python -m pip install --quiet -e ".[test,explore]"
