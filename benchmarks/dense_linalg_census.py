"""Dense linear algebra of one screening point (issue 30): each call site's calls and CPU.

Wraps the dense solvers of ``scipy.linalg`` and ``numpy.linalg`` (eig, eigvals, eigh, solve,
lu_factor, qr, svd, ...; the batched Newton steps' ``numpy.linalg.solve``), the band solver
``lapack.zgbsv`` and its ``zgbtrs`` of :mod:`flexshaft.analyses.banded`, the LU of the scalar
Newton steps (``eigen._gesv``), the inverse iterations' ``lapack.zgetrf``/``zgetrs``
(:mod:`flexshaft.analyses.hysteretic_roots`) and the shaft's thermal ``solve_banded`` (bound at
import in :mod:`flexshaft.thermal.shaft`, wrapped there), runs one warm
``flexshaft.assess(tuned design without its envelope, SCREENING)`` and prints, by call site
(the flexshaft line that called), the calls, their CPU, and the shapes and dtypes met. The
wrappers see the module attributes at call time, so a solver bound at import elsewhere (``from
scipy.linalg import eig``) is missed. One BLAS thread.

    PYTHONPATH=src .venv/bin/python benchmarks/dense_linalg_census.py
"""

from __future__ import annotations

import collections
import sys
import time
import traceback
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

SCIPY = ("eig", "eigvals", "eigh", "eigvalsh", "solve", "lu_factor", "lu_solve", "schur", "qr", "svd", "cho_factor")
NUMPY = ("eig", "eigvals", "eigh", "solve", "inv", "svd", "qr", "lstsq", "cholesky")


def main() -> None:
    bu.reexec_with_threads(1, __file__)
    import numpy as np
    import scipy.linalg as la

    import flexshaft as fs
    import flexshaft.analyses.banded as banded
    import flexshaft.analyses.eigen as eigen
    import flexshaft.thermal.shaft as thermal_shaft
    from flexshaft.design.io import tuned_design

    one = tuned_design().model_copy(update={"envelope": None})
    fs.assess(one, fs.SCREENING)  # warm: imports, caches of the process
    table: dict = collections.defaultdict(lambda: [0, 0.0, set()])

    def wrap(owner, name: str, label: str) -> None:
        f = getattr(owner, name)

        def counted(*args, **kwargs):
            t = time.process_time()
            out = f(*args, **kwargs)
            cpu = time.process_time() - t
            site = next((s for s in reversed(traceback.extract_stack()[:-1]) if "flexshaft" in s.filename), None)
            where = "?" if site is None else f"{site.filename.split('flexshaft/')[-1]}:{site.lineno}"
            first = next((a for a in args if hasattr(a, "shape")), None)
            row = table[(label, where)]
            row[0] += 1
            row[1] += cpu
            if first is not None:
                row[2].add(f"{first.shape} {first.dtype}")
            return out

        setattr(owner, name, counted)

    for name in SCIPY:
        wrap(la, name, f"scipy.linalg.{name}")
    for name in NUMPY:
        wrap(np.linalg, name, f"numpy.linalg.{name}")
    wrap(banded.lapack, "zgbsv", "lapack.zgbsv")
    wrap(banded.lapack, "zgbtrs", "lapack.zgbtrs")
    wrap(la.lapack, "zgetrf", "lapack.zgetrf")
    wrap(la.lapack, "zgetrs", "lapack.zgetrs")
    wrap(eigen, "_gesv", "lapack.zgesv (Newton)")
    wrap(thermal_shaft, "solve_banded", "scipy.linalg.solve_banded (bound at import)")
    t = time.process_time()
    fs.assess(one, fs.SCREENING)
    total = time.process_time() - t
    print(f"one screening point of the tuned design: CPU {total:.3f} s (wrappers included)")
    print(f"  {'CPU ms':>7s} {'calls':>5s}  solver / call site / shapes")
    summed = 0.0
    for (label, where), (calls, cpu, shapes) in sorted(table.items(), key=lambda kv: -kv[1][1]):
        summed += cpu
        print(f"  {cpu * 1e3:7.1f} {calls:5d}  {label}  {where}  {', '.join(sorted(shapes)[:3])}")
    print(f"  {summed * 1e3:7.1f}        in all")


if __name__ == "__main__":
    main()
