"""The a-posteriori eigenvalue error estimate holds a bounded number of dense matrices.

:func:`flexshaft.analyses.eigen_error.eigenvalue_corrections` solves one left vector per mode
from that mode's matrix T_k (nb x nb, complex). It held all of them at once: m·nb²·16 bytes,
646 MB for ``flexshaft modes --n-modes 500`` (343 modes of a 343-vector basis), where
docs/limits.md promised about 110 MB (peak RSS 774 MB measured with ``/usr/bin/time -v``; 177 MB
now). It now holds at most ``_CHUNK_BYTES`` of them at a time. Each mode's solve is its own
LAPACK call whatever the chunk, so the numbers are the same to the bit.
"""

from __future__ import annotations

import tracemalloc

import numpy as np

import flexshaft.analyses.eigen_error as eigen_error
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.hysteretic_roots import damped_modes
from flexshaft.assembly import build_model
from flexshaft.design import tuned_design, with_overrides


def _corrections_and_peak(red, s, Y) -> tuple[np.ndarray, int]:
    tracemalloc.start()
    try:
        delta = eigen_error.eigenvalue_corrections(red, 0.0, s, Y)
        return delta, tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_the_modes_matrices_are_held_a_chunk_at_a_time(monkeypatch):
    """60 modes of the tuned design on a coarse mesh (a 100-vector basis: 60 x 100² x 16 B =
    9.6 MB all at once) with chunks of 512 kB (3 modes): the same corrections, bit for bit, and
    a peak of traced memory (numpy reports its arrays to tracemalloc) lower by at least 90 % of
    what the chunks leave out. Both runs allocate everything else alike."""
    model = build_model(with_overrides(tuned_design(), {"mesh.shaft_elements": 12, "mesh.boom_elements": 6}))
    red = reduce(model, 100)
    s, Y = damped_modes(red, 0.0, 60)
    s, Y = s[s.imag > 0], Y[:, s.imag > 0]
    m, nb = s.size, red.size
    all_at_once = m * nb * nb * 16
    monkeypatch.setattr(eigen_error, "_CHUNK_BYTES", 2**62)
    whole, peak_whole = _corrections_and_peak(red, s, Y)
    chunk = 2**19
    monkeypatch.setattr(eigen_error, "_CHUNK_BYTES", chunk)
    chunked, peak_chunked = _corrections_and_peak(red, s, Y)
    assert m >= 50 and nb == 100
    np.testing.assert_array_equal(chunked, whole)
    assert np.all(np.isfinite(whole))
    assert peak_whole >= all_at_once  # the measurement sees the matrices
    assert peak_whole - peak_chunked >= 0.9 * (all_at_once - chunk)
