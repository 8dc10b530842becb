"""Parallel work: the process pools (:mod:`~flexshaft.parallel.pool`), BLAS thread control
(:mod:`~flexshaft.parallel.threads`) and independent tasks on a pool or in this process
(:mod:`~flexshaft.parallel.tasks`).

``flexshaft run`` starts one pool of forked workers (:func:`~flexshaft.parallel.pool.worker_pool`)
for its analyses, the thesis studies and the report's figures; the sweep engine builds its
workers with the same :func:`~flexshaft.parallel.pool.new_pool`.
"""
