#!/usr/bin/env bash
# Set up the virtual environment (scripts/venv.sh) and run the whole test suite on two workers.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/venv.sh
# two workers: the suite is mostly single-threaded numerics (about 7.5 CPU-minutes; pytest --cpu-durations=N lists each test)
.venv/bin/python -m pytest -n 2 "$@"
