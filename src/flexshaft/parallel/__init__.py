"""Parallel work: the process pools (:mod:`~flexshaft.parallel.pool`), BLAS thread control
(:mod:`~flexshaft.parallel.threads`) and independent tasks on a pool or in this process
(:mod:`~flexshaft.parallel.tasks`).

``flexshaft run`` starts one pool of forked workers (:func:`~flexshaft.parallel.pool.worker_pool`)
for its analyses, the thesis studies and the report's figures; the sweep engine builds its
workers with the same :func:`~flexshaft.parallel.pool.new_pool`.
"""

__all__ = ["MAX_JOBS"]

#: Most local worker processes a command starts (``--jobs``), and the least the Python API's
#: sweeps allow (:func:`flexshaft.parallel.pool.max_jobs`): each is a forked process, all started
#: at once (``--jobs 100000`` forked 4,400 processes before it was stopped). Here, without
#: imports, so that the CLI's options read it at start-up for nothing.
MAX_JOBS = 64
