"""Element layer: pure functions returning local matrices. Nothing global lives here."""

from flexshaft.elements.bearing import attachment_transform, relative_rows, spring_matrix
from flexshaft.elements.boom import EllipseSection, boom_element_matrices, ellipse_section
from flexshaft.elements.inertia import disk_matrices, end_mass_kinematics, end_mass_matrix
from flexshaft.elements.shaft import TubeSection, cowper_shear_coefficient, shaft_element_matrices
from flexshaft.elements.shape import FIELDS, beam_shape

__all__ = [
    "FIELDS",
    "EllipseSection",
    "TubeSection",
    "attachment_transform",
    "beam_shape",
    "boom_element_matrices",
    "cowper_shear_coefficient",
    "disk_matrices",
    "ellipse_section",
    "end_mass_kinematics",
    "end_mass_matrix",
    "relative_rows",
    "shaft_element_matrices",
    "spring_matrix",
]
