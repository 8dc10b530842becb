"""The requirements verdict and the one recipe that produces it.

* :mod:`~flexshaft.verdict.assess`: ``assess(design, resolution) -> Assessment``;
* :mod:`~flexshaft.verdict.operating_point`: every analysis at one operating point;
* :mod:`~flexshaft.verdict.gather`: the evidence each requirement needs, read from them;
* :mod:`~flexshaft.verdict.evidence`: the evidence's types;
* :mod:`~flexshaft.verdict.checks`: the requirements, one check each, in one table;
* :mod:`~flexshaft.verdict.result`: ``Check``, ``Finding`` and ``Verdict``.
"""
