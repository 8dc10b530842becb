"""The shear-deformable tube's search solves the first n past the one that ended its global branch.

References: docs/model.md ("Governing mode", the hand-written paragraph after the shear
theory): the global helical mode is the first local minimum of T(n) counting from n = 2, a
shorter-wave mode or the crimping limit governs otherwise, and infinite-tube solutions screen the
short-wave n and replace the Ritz series where the tube holds more than about 100 axial
half-waves. API contract (docstring of flexshaft.buckling.shear, "Search and governing mode"):
the critical torque of each sense is the lowest of the shear-crimping limit, the first local
minimum over n (the global helical branch) and every shorter-wave n above it up to n_max. The
global branch learns of its minimum at n_g only when it has solved n_g + 1 and seen the torque
rise; the next n, n_g + 2, is the first short-wave candidate the branch has not solved, and it
belongs to the search as much as any larger n.

What is checked, and against what: the torques 20.08, 20.57 and 18.43 N m below are the
product's own endless-tube curve (shear_helix_curve), not an independent reference; the test
checks only the selection rule applied to that curve (n = 4 chosen, not the first minimum
n = 2) and the crimping limit against its closed form 2 pi R^2 k t sqrt(G_13 G_23).

The wall: hoop plies (90 deg) of a soft-matrix lamina (G_13 = 5 MPa, G_23 = 20 MPa), 0.5 mm
thick, on a 60 m span, so that every n takes the endless-tube value (more than ~100 axial
half-waves: the documented rule; the endless-tube solution is checked, for an isotropic tube
only, against the Mindlin-modified Donnell dispersion relation in tests/test_buckling.py, not
for this orthotropic wall). Its curve first falls to n = 2 (20.08 N m), rises at n = 3
(20.57 N m) and falls again at n = 4 (18.43 N m), far below the crimping limit
2 pi R^2 k t sqrt(G_13 G_23) = 63.6 N m (k = 5/6). With n_max = 4 the lowest value of the rule
is n = 4's; a search that starts its short-wave branch one n too late stops at the first
minimum, 9 % higher. Hoop plies are mirror-symmetric, so both senses are equal.

Tolerance 1e-9 relative: the search and the reference evaluate the same endless-tube minimum
over k, both refined by golden section to about 1e-9 at a smooth minimum; a lost n costs 9 %.
CPU: three endless-tube curves of three n, about 0.03 s.
"""

from __future__ import annotations

import numpy as np
import pytest

from flexshaft.buckling import torsional_buckling_torque
from flexshaft.buckling.shear import shear_helix_curve
from flexshaft.laminate import Lamina, Laminate

RADIUS = (0.1016 - 3e-3) / 2  # [m], mid-surface radius of a 101.6 mm tube with 3 mm wall
THICKNESS = 0.5e-3  # [m]
G_13, G_23, KAPPA = 5e6, 0.02e9, 5.0 / 6.0
LAMINA = Lamina(115e9, 0.1e9, 0.035e9, 0.3, 1600.0, G_13=G_13, G_23=G_23)


def test_the_n_after_the_global_branchs_last_is_a_short_wave_candidate():
    wall = Laminate.from_layup("(90)s", THICKNESS, LAMINA)
    curve, _ = shear_helix_curve(wall, RADIUS, np.arange(2, 5))
    # the shape this checks: minimum at n = 2 seen at n = 3, lower again at n = 4 (both senses)
    assert np.all(curve[1] > curve[0]) and np.all(curve[2] < 0.95 * curve[0])
    crimping = 2 * np.pi * RADIUS**2 * KAPPA * THICKNESS * np.sqrt(G_13 * G_23)
    assert np.all(curve < 0.5 * crimping)
    result = torsional_buckling_torque(wall, RADIUS, 60.0, n_max=4)
    assert result.n_terms == 0  # every n on the endless-tube path
    assert result.crimping_torque_positive == pytest.approx(crimping, rel=1e-12)
    assert result.global_n_positive == 2 and result.global_n_negative == 2
    assert result.global_torque_positive == pytest.approx(curve[0, 0], rel=1e-9)
    assert result.torque_positive == pytest.approx(curve[2, 0], rel=1e-9)
    assert result.torque_negative == pytest.approx(curve[2, 1], rel=1e-9)
    assert (result.n_positive, result.n_negative) == (4, 4)
    assert result.governing_positive == "shear crimping"  # a shorter wave below the first minimum
