#!/usr/bin/env bash
# Set up the virtual environment (scripts/venv.sh) and run the whole test suite on two workers.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/venv.sh
# the package's bytecode written once: with PYTHONDONTWRITEBYTECODE set (some CI images and VMs,
# this project's development VM) every Python process the suite starts (xdist workers, the CLI
# end to end, spawned pool workers) would compile flexshaft's sources again (0.15-0.25 s of CPU)
.venv/bin/python -m compileall -q src/flexshaft
# two workers: the suite is mostly single-threaded numerics (about 5.5 CPU-minutes, 3.5 min wall on 2 cores; pytest --cpu-durations=N lists each test).
# PYTHONDONTWRITEBYTECODE is lifted for the run: it also stops pytest from keeping its rewritten
# test modules (tests/__pycache__, git-ignored), so each worker of each run would rewrite the
# asserts of all ~330 test files again (about 5 s of CPU a worker on a 2.6 GHz Xeon, 3 % of a run)
env -u PYTHONDONTWRITEBYTECODE .venv/bin/python -m pytest -n 2 "$@"
