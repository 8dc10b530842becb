"""Vectorized scatter of stacked local matrices into one sparse global matrix."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

__all__ = ["scatter", "scatter_blocks", "restrict"]


def scatter(blocks, dofs, size: int) -> sp.csr_matrix:
    """Sum local matrices into a global CSR matrix in one COO pass.

    Parameters
    ----------
    blocks : ndarray
        Local matrices, (n, d, d).
    dofs : ndarray of int
        Their global DOFs, (n, d).
    size : int
        Global size.
    """
    blocks = np.asarray(blocks)
    dofs = np.asarray(dofs)
    if blocks.size == 0:
        return sp.csr_matrix((size, size), dtype=blocks.dtype if blocks.dtype != object else float)
    rows = np.broadcast_to(dofs[:, :, None], blocks.shape).ravel()
    cols = np.broadcast_to(dofs[:, None, :], blocks.shape).ravel()
    return sp.coo_matrix((blocks.ravel(), (rows, cols)), shape=(size, size)).tocsr()


def scatter_blocks(parts, size: int) -> sp.csr_matrix:
    """:func:`scatter` of several ``(blocks, dofs)`` pairs of any block sizes in one COO pass."""
    rows, cols, data = [], [], []
    for blocks, dofs in parts:
        blocks, dofs = np.asarray(blocks), np.asarray(dofs)
        if blocks.size == 0:
            continue
        rows.append(np.broadcast_to(dofs[:, :, None], blocks.shape).ravel())
        cols.append(np.broadcast_to(dofs[:, None, :], blocks.shape).ravel())
        data.append(blocks.ravel())
    if not data:
        return sp.csr_matrix((size, size))
    return sp.coo_matrix(
        (np.concatenate(data), (np.concatenate(rows), np.concatenate(cols))), shape=(size, size)
    ).tocsr()


def restrict(matrix, free: np.ndarray):
    """Sub-matrix on the free DOFs (rows and columns)."""
    return matrix[free][:, free]
