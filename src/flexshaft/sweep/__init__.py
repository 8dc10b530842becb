"""Sweeps: design variables × outputs, run locally or on Dask, resumable, saved as netCDF.

>>> from flexshaft.sweep import Output, Study, Variable, run_sweep
>>> def shaft_mass_of(point):                   # in a module, so that workers can import it
...     return {"shaft_mass": point.model.shaft_mass}
>>> study = Study(
...     name="wall thickness",
...     variables=[Variable(path="shaft.wall_thickness", name="wall", values=[0.002, 0.003], units="m")],
...     outputs=[Output("shaft_mass", "kg")],
...     evaluate=shaft_mass_of,
... )
>>> ds = run_sweep(study, progress=False)        # in this process; "runs/wall", jobs=2 to store and share
>>> ds["shaft_mass"].round(2).values.tolist()     # ρ π (D − t) t L of the 8.05 m baseline shaft [kg]
[8.31, 12.34]

The thesis's chapter-3 studies are in :mod:`flexshaft.thesis` (docs/studies.md).
xarray is imported when results are assembled; Dask only when a Dask client or address is
given.
"""

from flexshaft.sweep.run import chunk_bounds, finished_chunks, run_sweep, to_dataset
from flexshaft.sweep.study import (
    DifferentStudyError,
    Output,
    Point,
    Study,
    SweepError,
    SweepWarning,
    Variable,
    evaluate_chunk,
)

__all__ = [
    "DifferentStudyError",
    "Output",
    "Point",
    "Study",
    "SweepError",
    "SweepWarning",
    "Variable",
    "chunk_bounds",
    "evaluate_chunk",
    "finished_chunks",
    "run_sweep",
    "to_dataset",
]
