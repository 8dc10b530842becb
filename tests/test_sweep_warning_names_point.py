"""A warning raised while a sweep evaluates a point names that point.

In a sweep of hundreds of designs (an optimizer's generation, ``flexshaft study``), a warning
such as "the response at ω = 139.871 rad/s lies within 6e-06 of an undamped resonance" cannot be
acted on unless it says which design raised it. :func:`flexshaft.sweep.study.evaluate_chunk`
sets the point's label (:mod:`flexshaft.parallel.point_label`) and flexshaft's warning sites
prefix their text with it; the category, the filters and the once-per-location registries are
left alone, and points evaluated at once in threads (a Dask worker's) each name their own.

The resonance is real: the undamped Jeffcott rotor of tests/test_api_guards.py (k = 48 E I / L³,
the effective mass of tests/test_massless_members.py) driven at ω = ω_n (1 − 1e-7), within the
banded solver's RESONANCE_TOLERANCE (1e-5) of its natural frequency, and at ω_n (1 − 1e-3),
outside it (no warning), as that file checks against the closed form.
"""

from __future__ import annotations

import threading
import warnings

import numpy as np
import pytest
from rotors import disk_dofs
from test_api_guards import OMEGA_N, jeffcott

from flexshaft.analyses.banded import ResonanceWarning
from flexshaft.analyses.response import frequency_response
from flexshaft.parallel.point_label import at_point, labelled
from flexshaft.sweep import Output, Study, Variable, evaluate_chunk

MODEL = jeffcott()
V, _ = disk_dofs(MODEL)
LOAD = np.zeros(MODEL.dofs.size)
LOAD[V] = 100.0


def _response_near_resonance(point):
    """The disk's response at ω_n (1 − detuning): only the 1e-7 detuning warns."""
    omega = OMEGA_N * (1 - point.axes["detuning"])
    return {"x": abs(frequency_response(MODEL, LOAD, omega, 0.0)[V])}


def _study(variables):
    return Study(name="near", variables=variables, outputs=[Output("x", "m")], evaluate=_response_near_resonance)


def _resonance_messages(study, start, stop, action="always"):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter(action)
        evaluate_chunk(study, start, stop)
    return [str(w.message) for w in caught if issubclass(w.category, ResonanceWarning)]


def test_the_resonance_warning_names_its_point_and_keeps_its_category():
    study = _study([Variable("detuning", [1e-3, 1e-7]), Variable("fidelity", ["screening"])])
    messages = _resonance_messages(study, 0, 2)
    assert len(messages) == 1  # the 1e-7 point only, once
    # the single-valued fidelity axis says nothing about which point it was: left out
    assert messages[0].startswith("at detuning = 1e-07: the response at ω = ")
    assert "within about 1.0e-07 (relative) of an undamped resonance" in messages[0]
    assert labelled("text") == "text"  # the label ends with its point


def test_every_variable_is_named_when_none_varies():
    study = _study([Variable("detuning", [1e-7]), Variable("case", ["a"])])
    messages = _resonance_messages(study, 0, 1)
    assert len(messages) == 1 and messages[0].startswith("at detuning = 1e-07, case = a: the response")


def test_outside_a_sweep_the_message_is_unchanged_and_filters_still_apply():
    with pytest.warns(ResonanceWarning, match=r"^the response at ω = "):
        frequency_response(MODEL, LOAD, OMEGA_N * (1 - 1e-7), 0.0)
    # an "error" filter still turns the warning into an exception at its own site, in a sweep too
    study = _study([Variable("detuning", [1e-7])])
    with warnings.catch_warnings():
        warnings.simplefilter("error", ResonanceWarning)
        with pytest.raises(ResonanceWarning, match=r"^at detuning = 1e-07: the response"):
            evaluate_chunk(study, 0, 1)
    # "once": one line for the same text from the same place, as before the label existed
    repeated = _study([Variable("detuning", [1e-7]), Variable("repeat", [1, 2, 3])])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("once")
        evaluate_chunk(repeated, 0, 3)
    assert len(caught) == 3  # three points, three texts (each names its own repeat)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("once")
        for _ in range(3):
            frequency_response(MODEL, LOAD, OMEGA_N * (1 - 1e-7), 0.0)
    assert len(caught) == 1


def test_points_evaluated_at_once_in_threads_name_their_own():
    """Two threads inside two points at the same time (as a Dask worker's threads run two chunks):
    each message names the point of the thread that raised it."""
    inside = threading.Barrier(2)
    messages: dict[str, str] = {}

    def work(label):
        with at_point(label):
            inside.wait(timeout=10)  # both labels set before either message is made
            messages[label] = labelled("text")
            inside.wait(timeout=10)

    threads = [threading.Thread(target=work, args=(label,)) for label in ("a = 1", "a = 2")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert messages == {"a = 1": "at a = 1: text", "a = 2": "at a = 2: text"}
    assert labelled("text") == "text"  # and nothing is left set in this thread
