"""The design explorer in the browser (``flexshaft explore``, the extra ``flexshaft[explore]``).

* :mod:`~flexshaft.explore.controls`: the design variables of the page, bounds from the schema;
* :mod:`~flexshaft.explore.compute`: one update (the screening assessment as JSON) and a sweep point;
* :mod:`~flexshaft.explore.export`: the edited design as a design file, and its run command;
* :mod:`~flexshaft.explore.pareto`: the optimizer's Pareto front of a run folder;
* :mod:`~flexshaft.explore.fullrun`: a full-resolution run through ``flexshaft run``'s pipeline;
* :mod:`~flexshaft.explore.workers`: the worker processes and the pages' sessions;
* :mod:`~flexshaft.explore.server`: the web application (Starlette) and its JSON API;
* :mod:`~flexshaft.explore.launch`: the local server (uvicorn) on a free port.

Nothing is imported here: ``import flexshaft`` and the CLI never load the web stack
(docs/explorer.md).
"""
