"""Figures from plain arrays: the plotting layer every result's ``.plot()`` hands off to.

Each function takes numpy arrays in engineering units (rpm, Hz, °C; lengths in metres, drawn in
mm) and an optional ``ax`` (draw into these axes, else a new figure), draws with matplotlib
(imported only when a figure is drawn, so ``import flexshaft`` stays light) and returns the
figure. Nothing here knows about models or analyses; the result objects
(:class:`flexshaft.analyses.Campbell`, ...) convert their SI data and call in.

Modules: :mod:`~flexshaft.plot.campbell` (Campbell diagram), :mod:`~flexshaft.plot.shapes`
(mode shapes, static deflection), :mod:`~flexshaft.plot.response` (Bode, orbits),
:mod:`~flexshaft.plot.driveline` (responses over speed, safety factor, actuators, load shares;
re-exports the common ones), :mod:`~flexshaft.plot.stability` (log decrement and Re(s) against
speed, onset maps), :mod:`~flexshaft.plot.studies` (thesis chapter-3 studies),
:mod:`~flexshaft.plot.thermal`, :mod:`~flexshaft.plot.verdict` (requirement margins),
:mod:`~flexshaft.plot.output` (saving, batch rendering in worker processes) and
:mod:`~flexshaft.plot.style` / :mod:`~flexshaft.plot.labels` (shared helpers).
"""
