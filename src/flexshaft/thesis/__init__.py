"""The thesis's studies (Ocalan 2002), each module named by what it computes.

Chapter 3, on the sweep engine: :mod:`~flexshaft.thesis.ply_angle` (study 1),
:mod:`~flexshaft.thesis.two_angles` (2), :mod:`~flexshaft.thesis.wall` (3, and the forced
response of a few walls), :mod:`~flexshaft.thesis.gain` (4), :mod:`~flexshaft.thesis.buckling_sweep`
(5), :mod:`~flexshaft.thesis.spinup_maps` (6: the spin-up over the actuator gains), with the
strength output they share in :mod:`~flexshaft.thesis.strength` (the six study functions are
importable from this package); all of them in one call: :mod:`~flexshaft.thesis.design_studies`.
Chapter 4: :mod:`~flexshaft.thesis.whirl` (the three shafts and the whirl onset over the gains).
:mod:`~flexshaft.thesis.report_studies` starts the studies ``flexshaft run`` reports beside a
design's assessment.
"""

from flexshaft.thesis.buckling_sweep import buckling_study
from flexshaft.thesis.gain import proportional_gain_study
from flexshaft.thesis.ply_angle import ply_angle_study
from flexshaft.thesis.spinup_maps import spinup_gain_map
from flexshaft.thesis.two_angles import two_angle_study
from flexshaft.thesis.wall import wall_thickness_study

__all__ = [
    "buckling_study",
    "ply_angle_study",
    "proportional_gain_study",
    "spinup_gain_map",
    "two_angle_study",
    "wall_thickness_study",
]
