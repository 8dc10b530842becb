"""Figures from plain arrays: the plotting layer every result's ``.plot()`` hands off to.

Each function takes numpy arrays in engineering units (rpm, Hz, mm, °C) and an optional
``ax``, draws with matplotlib (imported only when a figure is drawn, so ``import flexshaft``
stays light) and returns the figure. Nothing here knows about models or analyses; the result
objects (:class:`flexshaft.analyses.Campbell`, ...) convert their SI data and call in.
"""
