"""Assembly layer: global DOF numbering, sparse scatter, and the model built from a design."""

from flexshaft.assembly.dofs import BOOM_FIELDS, SHAFT_FIELDS, DofMap
from flexshaft.assembly.model import Actuator, BearingLink, Controller, Model, ShaftProperties

__all__ = ["BOOM_FIELDS", "SHAFT_FIELDS", "Actuator", "BearingLink", "Controller", "DofMap", "Model", "ShaftProperties", "build_model"]


def build_model(design) -> Model:
    """Assemble the global model of a validated design (see :mod:`flexshaft.assembly.build`)."""
    from flexshaft.assembly.build import build_model as _build

    return _build(design)
