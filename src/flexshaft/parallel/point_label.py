"""Which point of a sweep the work in progress belongs to, for the warnings raised deep inside
its analyses.

In a sweep of hundreds of designs (an optimizer's generation, ``flexshaft study``) a warning
such as "the response at ω = 139.871 rad/s lies within 6e-06 of an undamped resonance" cannot
be acted on unless it says which design raised it. The sweep engine sets the point's label
around each evaluation (:func:`at_point`, :func:`flexshaft.sweep.study.evaluate_chunk`), and
flexshaft's own warning sites (a resonance, a problem size) prefix their text with it
(:func:`labelled`). A context variable, so that points evaluated at once in threads (a Dask
worker's) each see their own; warning filters, categories and the once-per-location registries
are left as they are.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from contextvars import ContextVar

__all__ = ["at_point", "labelled"]

_LABEL: ContextVar[str] = ContextVar("flexshaft_point_label", default="")


@contextlib.contextmanager
def at_point(label: str) -> Iterator[None]:
    """Messages made by :func:`labelled` within this block name the point ``label``."""
    token = _LABEL.set(label)
    try:
        yield
    finally:
        _LABEL.reset(token)


def labelled(message: str) -> str:
    """``message`` prefixed with ``at <label>: `` inside :func:`at_point`, else unchanged."""
    label = _LABEL.get()
    return f"at {label}: {message}" if label else message
