"""A disk given only its mass is a point mass: it adds m to the three translations of its node
and nothing to its rotations or to the gyroscopic matrix (design/components.py ``Disk``).

Reference (derived here; docs/model.md: a disk is a "lumped mass, diametral and polar inertia,
gyroscopic G[β, γ] = +I_p"): a disk whose design gives no diametral or polar inertia has
I_d = I_p = 0, so the difference between the assembled model with the disk and the same model
without it is diag(m, m, m, 0, 0, 0) on the disk node's (u, v, w, θ, β, γ) and zero elsewhere,
and the gyroscopic matrices are equal. Tolerance: the disk node's entries are sums of the tube's
entries and m, so their difference carries one rounding of m: atol 1e-12 m. CPU about 0.1 s.
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from tests.rotors import M_DISK, L, jeffcott_text

DISK_BLOCK = f'[[disks]]\nname = "disk"\nx = {L / 2}\nmass = {M_DISK}\n'


def test_a_disk_without_inertias_is_a_point_mass():
    text = jeffcott_text(0.0, 0.0)
    assert DISK_BLOCK in text  # the disk gives its mass alone
    with_disk = build_model(loads_design(text))
    without = build_model(loads_design(text.replace(DISK_BLOCK, "")))
    assert with_disk.dofs.size == without.dofs.size  # the damper keeps a node at L/2 either way

    node = with_disk.dofs.node_at("shaft", L / 2)
    dofs = [with_disk.dofs.shaft(node, f) for f in ("u", "v", "w", "theta", "beta", "gamma")]
    expected = np.zeros((with_disk.dofs.size, with_disk.dofs.size))
    expected[dofs, dofs] = [M_DISK, M_DISK, M_DISK, 0.0, 0.0, 0.0]

    added = (with_disk.M - without.M).toarray()
    np.testing.assert_allclose(added, expected, rtol=0, atol=1e-12 * M_DISK)
    gyroscopic = (with_disk.G - without.G).toarray()
    np.testing.assert_allclose(gyroscopic, 0.0, rtol=0, atol=1e-12 * M_DISK)
