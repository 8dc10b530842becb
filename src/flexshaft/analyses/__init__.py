"""Analyses: functions that take a model and return plain result objects."""

from flexshaft.analyses.modal import Modes, modes
from flexshaft.analyses.response import SingularSystemError, dynamic_stiffness, frequency_response

__all__ = ["Modes", "SingularSystemError", "dynamic_stiffness", "frequency_response", "modes"]
