"""Assembly layer: global DOF numbering, sparse scatter, and the model built from a design.

Submodules load on first use, so that :mod:`flexshaft.assembly.size` (the problem-size
estimate a ``flexshaft check`` may call) does not import scipy.
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = [
    "BOOM_FIELDS",
    "SHAFT_FIELDS",
    "Actuator",
    "BearingLink",
    "Controller",
    "DofMap",
    "Model",
    "ShaftProperties",
    "build_model",
]

_LAZY = {
    "BOOM_FIELDS": "flexshaft.assembly.dofs",
    "SHAFT_FIELDS": "flexshaft.assembly.dofs",
    "DofMap": "flexshaft.assembly.dofs",
    "Actuator": "flexshaft.assembly.model",
    "BearingLink": "flexshaft.assembly.model",
    "Controller": "flexshaft.assembly.model",
    "Model": "flexshaft.assembly.model",
    "ShaftProperties": "flexshaft.assembly.model",
}


def build_model(design) -> Any:
    """Assemble the global model of a validated design (see :mod:`flexshaft.assembly.build`)."""
    # here, not above: the build loads scipy, and `import flexshaft.assembly` stays light
    from flexshaft.assembly.build import build_model as build

    return build(design)


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
