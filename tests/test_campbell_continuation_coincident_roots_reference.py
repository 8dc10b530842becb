"""A continuation step that lands two modes on one eigenvalue is refused (hunt h45a).

:func:`flexshaft.analyses.campbell.track_modes` documents that a continuation step is accepted
when every mode converged, kept its shape (MAC ≥ 0.9) "and no two modes landed on the same
eigenvalue"; otherwise the speed's eigenvalues are solved and matched afresh. Reference
(definition): two tracked curves are two modes, and one root (non-degenerate) is one mode.

The root finder is substituted (the step's logic is what is checked): it returns the previous
shapes unchanged (MAC = 1 each, converged) with the eigenvalues 100i and 100i (1 + 1e-9) rad/s,
1e-9 apart relative: the step is refused (None). The control: eigenvalues 100i and 200i rad/s
are accepted as they are. Exact comparisons. CPU: microseconds.
"""

from __future__ import annotations

import importlib

import numpy as np

campbell = importlib.import_module("flexshaft.analyses.campbell")  # the package exports a function of that name


def _step(monkeypatch, roots):
    shapes = np.eye(3, 2, dtype=complex)
    monkeypatch.setattr(campbell, "mode_roots", lambda red, speed, s, Y: (roots, shapes, np.ones(2, bool)))
    speeds = np.array([0.0, 10.0])
    eig = np.array([[100j, 200j], [0.0, 0.0]])
    return campbell._continue(None, speeds, eig, [shapes, shapes], 1, 2)


def test_two_modes_on_one_root_are_refused(monkeypatch):
    assert _step(monkeypatch, np.array([100j, 100j * (1 + 1e-9)])) is None


def test_two_distinct_roots_are_accepted(monkeypatch):
    s, Y = _step(monkeypatch, np.array([100j, 200j]))
    assert np.array_equal(s, [100j, 200j]) and np.array_equal(Y, np.eye(3, 2))
