"""Of two divergent roots, the divergence onset's shape is the faster root's (mutation hunt h53c).

Reference (derived here), the rotor of tests/test_stability_fastest_divergence_reference.py:
the Jeffcott rotor of tests/rotors.py (a 20 kg disk on a near-massless pinned-pinned tube,
k = 48EI/L³) with, at the disk, an open-loop magnet (K_p = 0, negative stiffness k_s = 3k in
both planes, no controller states) and a contact bearing of stiffness k_c = k in w only. No
damping, no loss, no polar inertia, so the planes do not couple and each is one mass:

* v: m s² + (k − k_s) = 0, s = √(2k/m): the faster divergence, its shape pure v;
* w: m s² + (k − k_s + k_c) = 0, s = √(k/m): the slower one, its shape pure w.

The stability analysis reports the divergence that decides (the largest real root, e^{st}
grows fastest; docs/magnetic-bearings.md, *Divergence*) and, as the onset's shape, that root's
shape (the rule that docs page states, derived here: the fastest-growing motion is the one
seen first): at the disk all v, no w. The tube's mass (3.5e-6 of the disk's, tests/rotors.py)
and the round-off of the real eigenvectors leave the w
share of the v-plane shape far below 1e-6 (the two planes' equations are exactly decoupled
in the assembled matrices, so the w part is round-off only); the bound 1e-6 on |w|/|v| is
both far above that and far below the 1 the other root's shape would show (|v|/|w| → ∞).
"""

from __future__ import annotations

import numpy as np
from jeffcott_bearing import disk, model_with
from rotors import K_SHAFT

from flexshaft.analyses.stability import stability


def test_the_divergence_onset_shape_is_the_faster_roots_plane():
    magnet = f'kind = "active"\nkp = 0.0\nks = {3 * K_SHAFT}\nki = 100.0'
    w_only = f'\n[[bearings]]\nname = "c"\nx = 0.5\nkind = "contact"\nstiffness = {{ w = {K_SHAFT} }}'
    model = model_with(magnet + w_only + "\ndamping = {}")
    result = stability(model, [0.0, 100.0], n_modes=2)
    assert result.onset_kind == "divergence"
    v, w = disk(model)
    shape = np.asarray(result.onset_shape)
    assert abs(shape[v]) > 0.0
    assert abs(shape[w]) <= 1e-6 * abs(shape[v])
