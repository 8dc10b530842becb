"""The soft/stiff-plane labels of Friswell's anisotropic-bearing case name the plane each mode moves in.

Reference (derived here): Example 5.9.2 of Friswell et al. (2010) is the two-disk rotor of
5.9.1 on bearings of 1 MN/m in v and 0.8 MN/m in w (the case's design file). At rest (no
gyroscopic coupling) an axisymmetric shaft with disks bends in two independent planes, each
plane's modes only feeling that plane's bearing stiffness, so every mode moves in one plane;
the "soft plane" is the plane of the smaller bearing stiffness (w here, read from the design's
bearings), and by the Rayleigh quotient a softer support lowers that plane's frequencies, so the
lowest mode is a soft-plane mode. The case labels its five values "1 (soft plane)",
"1 (stiff plane)", ...: the test solves K x = ω² M x on the free lateral DOFs (v, w, β, γ: 28,
dense; the torsional and axial DOFs, whose lowest mode at 235 rad/s lies among these, are left
out), checks that the frequencies are the published ones (ROSS's, to 1e-3) and then, mode by
mode in ascending order, that the translations of the mode lie in the plane the label names.
The planes decouple exactly, so the other plane's share is round-off (below 1e-20 of the
squared amplitude); the test asks below 1e-6, far from both round-off and a mixed mode (a share
of order 1). The six lowest lateral frequencies are 4.8 % or more apart, so no near-degenerate
pair mixes the planes and the ordering does not depend on round-off.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg

from flexshaft.assembly import build_model
from flexshaft.validation.cases import case_by_id
from flexshaft.validation.runner import case_design


def test_each_label_names_the_plane_of_its_mode():
    case = case_by_id("friswell-5.9.2-rest")
    design = case_design(case)
    assert design is not None
    stiffness = {plane: {b.stiffness[plane] for b in design.bearings} for plane in ("v", "w")}
    assert stiffness == {"v": {1.0e6}, "w": {0.8e6}}  # Example 5.9.2: the same two values at both bearings
    soft, stiff = "w", "v"

    model = build_model(design)
    nodes = np.arange(model.dofs.n_shaft_nodes)
    lateral = np.concatenate([np.atleast_1d(model.dofs.shaft(nodes, f)) for f in ("v", "w", "beta", "gamma")])
    own = np.intersect1d(np.asarray(model.dofs.free), lateral)
    K = model.K[np.ix_(own, own)].toarray()
    M = model.M[np.ix_(own, own)].toarray()
    count = len(case.labels)
    squared, vectors = scipy.linalg.eigh(K, M, subset_by_index=[0, count - 1])
    # the same modes as the published ones (ROSS's values to 0.01 rad/s; 1e-3 is loose on purpose:
    # this test is about the planes, the case itself checks the values at 1e-4)
    np.testing.assert_allclose(np.sqrt(squared), case.published, rtol=1e-3)
    position = {dof: i for i, dof in enumerate(own)}
    for label, x in zip(case.labels, vectors.T, strict=True):
        energy = {}
        for plane in ("v", "w"):
            rows = [position[d] for d in np.atleast_1d(model.dofs.shaft(nodes, plane)) if d in position]
            energy[plane] = float(np.sum(x[rows] ** 2))
        moving = max(energy, key=energy.__getitem__)
        other = "v" if moving == "w" else "w"
        assert energy[other] < 1e-6 * energy[moving], (label, energy)
        named = soft if "(soft plane)" in label else stiff if "(stiff plane)" in label else None
        assert named == moving, f"{label!r}: the mode moves in {moving}, the soft plane is {soft}"
