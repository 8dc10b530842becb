"""A lateral load at ω = 0 on a shaft free to twist: only the loaded blocks are solved.

The Jeffcott rotor of tests/rotors.py with its twist left free at both ends (``fixed_start``
without ``theta``): the whole Z(0, 0) = K is singular (the rigid twist), but no term of K couples
the twist to the lateral DOFs, so a lateral load has a unique lateral response
(docs/model.md's uncoupled blocks; :mod:`flexshaft.analyses.banded` solves the blocks a load
reaches). A static force F at the disk of a pinned-pinned Euler-Bernoulli shaft deflects it by
F L³/(48 E I) = F/k (beam tables, e.g. Roark's simply supported beam with a central load;
derived here by the unit-load method); cubic Hermite elements reproduce the static deflection
under nodal loads exactly. Tolerance 1e-9 relative: K's condition number on the lateral block of
8 elements is below 1e6, so the LU solve is good to ~1e-10.
"""

from __future__ import annotations

import numpy as np
from rotors import K_SHAFT, disk_dofs, jeffcott_text

from flexshaft.analyses import frequency_response
from flexshaft.assembly import build_model
from flexshaft.design import loads_design


def test_a_lateral_static_load_on_a_shaft_free_to_twist_deflects_by_f_over_k():
    text = jeffcott_text(0.0, 0.0)
    held = 'fixed_start = ["u", "v", "w", "theta"]'
    assert held in text
    model = build_model(loads_design(text.replace(held, 'fixed_start = ["u", "v", "w"]')))
    v, w = disk_dofs(model)
    force = 1000.0
    load = np.zeros(model.dofs.size)
    load[v] = force
    q = np.asarray(frequency_response(model, load, 0.0, speed=0.0))
    assert abs(q[v].real / (force / K_SHAFT) - 1) < 1e-9
    assert abs(q[v].imag) < 1e-9 * force / K_SHAFT
    assert abs(q[w]) < 1e-9 * force / K_SHAFT
