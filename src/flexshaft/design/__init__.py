"""Design files: the validated input schema of flexshaft and the packaged designs (thesis baseline, tuned).

>>> from flexshaft.design import baseline_design, with_overrides
>>> design = with_overrides(baseline_design(), {"shaft.wall_thickness": 0.002})
>>> design.shaft.ply_angles_deg
(55.0, -55.0, 0.0, 0.0, 0.0, 0.0, -55.0, 55.0)

Only pydantic and the standard library are imported here: the design package is a data leaf
(:mod:`flexshaft.design.layup` holds the one layup parser).
"""

from flexshaft.design.io import (
    DEFAULT_DESIGN,
    EMBEDDED_DESIGNS,
    DesignError,
    Problem,
    baseline_design,
    baseline_text,
    design_from_dict,
    embedded_design,
    embedded_text,
    load_design,
    loads_design,
    tuned_design,
    with_overrides,
)
from flexshaft.design.schema import Design

__all__ = [
    "DEFAULT_DESIGN",
    "EMBEDDED_DESIGNS",
    "Design",
    "DesignError",
    "Problem",
    "baseline_design",
    "baseline_text",
    "design_from_dict",
    "embedded_design",
    "embedded_text",
    "load_design",
    "loads_design",
    "tuned_design",
    "with_overrides",
]
