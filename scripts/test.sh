#!/usr/bin/env bash
# Set up a virtual environment with the test extras (and the explorer's, for its browser tests)
# and run the whole test suite on two workers.
set -euo pipefail
cd "$(dirname "$0")/.."
python3 -m venv .venv
.venv/bin/python -m pip install --quiet --upgrade pip
.venv/bin/python -m pip install --quiet -e ".[test,explore]"
# two workers: the suite is mostly single-threaded numerics (about 2.5 CPU-minutes; pytest --cpu-durations=N lists each test)
.venv/bin/python -m pytest -n 2 "$@"
