"""Analyses: functions that take a model and return plain result objects."""

from flexshaft.analyses.banded import BandedHarmonicSolver, SingularSystemError
from flexshaft.analyses.campbell import Campbell, campbell
from flexshaft.analyses.modal import Modes, modes
from flexshaft.analyses.response import frequency_response, imbalance_response, static_response
from flexshaft.analyses.stability import StabilityResult, stability

__all__ = [
    "Campbell",
    "StabilityResult",
    "campbell",
    "stability",
    "BandedHarmonicSolver",
    "Modes",
    "SingularSystemError",
    "frequency_response",
    "imbalance_response",
    "modes",
    "static_response",
]
