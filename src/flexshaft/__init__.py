"""flexshaft: design and analysis of high-flexibility rotorcraft tail-rotor drivelines.

A flexible-matrix-composite drive shaft on a flexible tailboom, held by hanger bearings and
actively controlled magnetic bearings (Ocalan 2002). Typical use:

>>> import flexshaft as fs
>>> design = fs.baseline_design()            # or fs.load_design("my.toml")
>>> model = fs.build_model(design)
>>> m = fs.modes(model, speed=design.operating.speed_rad_s)
>>> m                                        # m.frequencies [Hz], m.whirl, m.shapes, ...
Modes(10 modes at 4800 rpm: [...] Hz, internal damping 'rotating', eigenvalues within ... of the full model (estimated))
>>> print(m)                                 # doctest: +SKIP
>>> a = fs.assess(design, fs.SCREENING)      # doctest: +SKIP
>>> a                                        # doctest: +SKIP
>>> a.verdict.headline, a.to_dataframe()     # doctest: +SKIP

``assess(design, resolution)`` is the one recipe that judges a design (what ``flexshaft run``
computes at :data:`REPORT`); its :class:`Assessment` holds every analysis and the verdict. In
a notebook it shows the verdict table; ``print(m)`` prints the modes' table; the tutorial is
docs/tutorial.ipynb.

The top level stays light: submodules load on first use.
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

_LAZY = {
    "Design": "flexshaft.design",
    "DesignError": "flexshaft.design",
    "load_design": "flexshaft.design",
    "loads_design": "flexshaft.design",
    "baseline_design": "flexshaft.design",
    "baseline_text": "flexshaft.design",
    "tuned_design": "flexshaft.design",
    "embedded_design": "flexshaft.design",
    "embedded_text": "flexshaft.design",
    "with_overrides": "flexshaft.design",
    "build_model": "flexshaft.assembly",
    "Model": "flexshaft.assembly",
    "modes": "flexshaft.analyses",
    "Modes": "flexshaft.analyses",
    "frequency_response": "flexshaft.analyses",
    "SingularSystemError": "flexshaft.analyses",
    "assess": "flexshaft.verdict.assess",
    "Assessment": "flexshaft.verdict.assess",
    "Resolution": "flexshaft.resolution",
    "SCREENING": "flexshaft.resolution",
    "VERDICT": "flexshaft.resolution",
    "REPORT": "flexshaft.resolution",
    "FINE": "flexshaft.resolution",
}

__all__ = ["__version__", *_LAZY]


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'flexshaft' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
