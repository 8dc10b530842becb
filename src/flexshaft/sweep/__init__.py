"""Sweeps: design variables × outputs, run locally or on Dask, resumable, saved as netCDF.

>>> from flexshaft.sweep import Output, Study, Variable, run_sweep
>>> study = Study(
...     name="wall thickness",
...     variables=[Variable(path="shaft.wall_thickness", name="wall", values=[0.002, 0.003], units="m")],
...     outputs=[Output("shaft_mass", "kg")],
...     evaluate=shaft_mass_of,                     # a module-level function of a Point
... )
>>> ds = run_sweep(study, "runs/wall", jobs=2)     # doctest: +SKIP

The thesis studies of DESIGN.md §3 are in :mod:`flexshaft.studies.sweeps`. xarray is imported
when results are assembled; Dask only when a Dask client or address is given.
"""

from flexshaft.sweep.run import chunk_bounds, finished_chunks, run_sweep, to_dataset
from flexshaft.sweep.study import Output, Point, Study, SweepError, SweepWarning, Variable, evaluate_chunk

__all__ = [
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
