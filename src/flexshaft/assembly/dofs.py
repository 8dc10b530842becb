"""The one global DOF numbering of the package.

Global vector layout::

    [ shaft node 0: u v w θ β γ | shaft node 1: ... | ... | boom node 0: v w θ β γ | ... | extra ]

Shaft nodes come first, 6 DOFs each in :data:`SHAFT_FIELDS` order; boom nodes follow, 5 DOFs
each in :data:`BOOM_FIELDS` order; the *extra* DOFs close the vector: lumped scalar DOFs that
belong to no node, named in :attr:`DofMap.extra` (``"tail_rotor"``: the reflected twist of the
tail rotor behind its drive's spring, :mod:`flexshaft.assembly.drive`). Every caller asks
:class:`DofMap` for an index by ``(component, node, field)`` (or an extra DOF by its name); no
index is hard-coded anywhere else.

Shaft nodes are in order of station. Consecutive nodes form a shaft element, except at a
coupling joint (:attr:`DofMap.shaft_joints`): there two nodes share the station, one on each
side of the coupling, and no shaft element joins them (the coupling element does). Ask for the
elements with :meth:`DofMap.element_dofs`, :attr:`DofMap.shaft_element_nodes` and
:attr:`DofMap.shaft_element_x`, never by pairing consecutive nodes.

A rigid direction of a coupling is an exact constraint: the aft node's DOF is *tied* to the
forward node's (:attr:`DofMap.tied`). :meth:`DofMap.index` (and so every lookup by node and
field, and :meth:`DofMap.element_dofs`) returns the forward node's index for a tied DOF, so the
aft side's elements assemble onto it and reading the aft node gives its value; the tied DOF's
own slot stays empty and is not free. Sum a quantity over nodes with :meth:`DofMap.unique`
so that a tied DOF counts once.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Literal

import numpy as np

__all__ = ["SHAFT_FIELDS", "BOOM_FIELDS", "Component", "DofMap"]

SHAFT_FIELDS: tuple[str, ...] = ("u", "v", "w", "theta", "beta", "gamma")
BOOM_FIELDS: tuple[str, ...] = ("v", "w", "theta", "beta", "gamma")
Component = Literal["shaft", "boom"]


@dataclass(frozen=True)
class DofMap:
    """Node stations, the DOF numbering and the constrained DOFs.

    Parameters
    ----------
    shaft_x : ndarray
        Shaft node stations [m], increasing.
    boom_x : ndarray
        Tailboom node stations [m], increasing; empty without a tailboom.
    fixed : ndarray of int
        Global indices of constrained (zero) DOFs.
    shaft_joints : ndarray of int
        Shaft node indices j whose pair (j, j + 1) is a coupling joint (same station, no
        shaft element between them); empty for a one-piece shaft.
    tied : ndarray of int, shape (n, 2)
        Pairs (tied DOF, DOF it equals) of raw global indices: the rigid directions of the
        couplings (the aft node's DOF equals the forward node's).
    extra : tuple of str
        Names of the extra DOFs after the boom's, in order (:meth:`extra_dof`); they are twist
        DOFs of the drive train and sit at the shaft's aft station in :attr:`stations`.
    """

    shaft_x: np.ndarray
    boom_x: np.ndarray
    fixed: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    shaft_joints: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    tied: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=int))
    extra: tuple[str, ...] = ()

    def __repr__(self) -> str:
        """One line: nodes, stations and DOF counts (the arrays are in the attributes)."""
        span = f", x = {self.shaft_x[0]:g} to {self.shaft_x[-1]:g} m" if self.n_shaft_nodes else ""
        return (
            f"DofMap({self.n_shaft_nodes} shaft nodes{span}, {self.n_boom_nodes} boom nodes, "
            f"{len(self.extra)} extra, {self.size} DOFs ({self.free.size} free))"
        )

    @cached_property
    def _alias(self) -> np.ndarray | None:
        if not len(self.tied):
            return None
        alias = np.arange(self.size)
        alias[np.asarray(self.tied)[:, 0]] = np.asarray(self.tied)[:, 1]
        return alias

    def unique(self, index) -> np.ndarray:
        """The distinct global indices of ``index`` (a tied DOF appears once), sorted."""
        return np.unique(np.asarray(index, dtype=int))

    @property
    def shaft_element_nodes(self) -> np.ndarray:
        """(n_elements, 2) node indices of every shaft element (coupling joints excluded)."""
        start = np.setdiff1d(np.arange(max(self.n_shaft_nodes - 1, 0)), np.asarray(self.shaft_joints, dtype=int))
        return np.stack([start, start + 1], axis=1)

    @property
    def shaft_element_x(self) -> np.ndarray:
        """(n_elements, 2) stations [m] of both ends of every shaft element."""
        return np.asarray(self.shaft_x, dtype=float)[self.shaft_element_nodes]

    @property
    def n_shaft_nodes(self) -> int:
        return len(self.shaft_x)

    @property
    def n_boom_nodes(self) -> int:
        return len(self.boom_x)

    @property
    def size(self) -> int:
        """Number of global DOFs, fixed ones included."""
        return 6 * self.n_shaft_nodes + 5 * self.n_boom_nodes + len(self.extra)

    @property
    def boom_dofs(self) -> np.ndarray:
        """Global indices of every boom DOF (fixed ones included), increasing."""
        start = 6 * self.n_shaft_nodes
        return np.arange(start, start + 5 * self.n_boom_nodes)

    @property
    def extra_dofs(self) -> np.ndarray:
        """Global indices of the extra DOFs, in the order of :attr:`extra`."""
        start = 6 * self.n_shaft_nodes + 5 * self.n_boom_nodes
        return np.arange(start, start + len(self.extra))

    def extra_dof(self, name: str) -> int:
        """Global index of the extra DOF called ``name``."""
        if name not in self.extra:
            raise ValueError(f"the model has no extra DOF {name!r} (it has {list(self.extra)})")
        return 6 * self.n_shaft_nodes + 5 * self.n_boom_nodes + self.extra.index(name)

    @property
    def stations(self) -> np.ndarray:
        """(size, 3) of every global DOF: its node's station [m], component (0 shaft, 1 boom,
        2 extra) and field index (in :data:`SHAFT_FIELDS` or :data:`BOOM_FIELDS` order, the
        position in :attr:`extra`): the key of a DOF ordering along the driveline
        (:mod:`flexshaft.analyses.banded`). An extra DOF sits at the shaft's aft station."""
        ns, nb, ne = self.n_shaft_nodes, self.n_boom_nodes, len(self.extra)
        aft = float(self.shaft_x[-1]) if ns else 0.0
        return np.column_stack(
            [
                np.concatenate(
                    [
                        np.repeat(np.asarray(self.shaft_x, dtype=float), 6),
                        np.repeat(np.asarray(self.boom_x, dtype=float), 5),
                        np.full(ne, aft),
                    ]
                ),
                np.concatenate([np.zeros(6 * ns), np.ones(5 * nb), np.full(ne, 2.0)]),
                np.concatenate([np.tile(np.arange(6.0), ns), np.tile(np.arange(5.0), nb), np.arange(float(ne))]),
            ]
        )

    @property
    def free(self) -> np.ndarray:
        """Global indices of the unconstrained DOFs, increasing."""
        mask = np.ones(self.size, dtype=bool)
        mask[self.fixed] = False
        if len(self.tied):
            mask[np.asarray(self.tied)[:, 0]] = False  # a tied DOF's own slot is empty
        return np.flatnonzero(mask)

    def index(self, component: Component, node, field: str):
        """Global index of ``field`` at ``node`` (int or int array) of ``component``."""
        node = np.asarray(node)
        if component == "shaft":
            n, fields, base, per = self.n_shaft_nodes, SHAFT_FIELDS, 0, 6
        elif component == "boom":
            n, fields, base, per = self.n_boom_nodes, BOOM_FIELDS, 6 * self.n_shaft_nodes, 5
        else:
            raise ValueError(f"component must be 'shaft' or 'boom', got {component!r}")
        if field not in fields:
            raise ValueError(f"{component} nodes have fields {fields}, got {field!r}")
        if np.any((node < -n) | (node >= n)):
            raise IndexError(f"{component} node {node} out of range 0..{n - 1}")
        idx = base + per * np.mod(node, n) + fields.index(field)
        if self._alias is not None:
            idx = self._alias[idx]
        return int(idx) if idx.ndim == 0 else idx

    def shaft(self, node, field: str):
        """Global index of a shaft DOF."""
        return self.index("shaft", node, field)

    def boom(self, node, field: str):
        """Global index of a tailboom DOF."""
        return self.index("boom", node, field)

    def element_dofs(self, component: Component) -> np.ndarray:
        """Global DOFs of every element of a component: (nel, 12) shaft or (nel, 10) boom."""
        if component == "shaft":
            per_node = 6 * np.arange(self.n_shaft_nodes)[:, None] + np.arange(len(SHAFT_FIELDS))
            if self._alias is not None:
                per_node = self._alias[per_node]
            if len(self.shaft_joints):
                ends = self.shaft_element_nodes
                return np.hstack([per_node[ends[:, 0]], per_node[ends[:, 1]]])
        elif component == "boom":
            per_node = 6 * self.n_shaft_nodes + 5 * np.arange(self.n_boom_nodes)[:, None] + np.arange(len(BOOM_FIELDS))
        else:
            raise ValueError(f"component must be 'shaft' or 'boom', got {component!r}")
        return np.hstack([per_node[:-1], per_node[1:]])

    def locate(self, component: Component, x: float) -> tuple[int, float, float]:
        """Element holding station ``x`` [m]: ``(element, xi, element length)``.

        At a coupling joint the station belongs to the element after it (aft of the coupling).
        """
        xs = self._stations(component)
        if len(xs) < 2:
            raise ValueError(f"no {component} elements")
        self._check_station(component, xs, x)
        if component == "shaft" and len(self.shaft_joints):
            ends = self.shaft_element_x
            e = int(np.clip(np.searchsorted(ends[:, 0], x, side="right") - 1, 0, len(ends) - 1))
            start, length = ends[e, 0], ends[e, 1] - ends[e, 0]
            return e, float(np.clip((x - start) / length, 0.0, 1.0)), float(length)
        e = int(np.clip(np.searchsorted(xs, x, side="right") - 1, 0, len(xs) - 2))
        length = xs[e + 1] - xs[e]
        return e, float(np.clip((x - xs[e]) / length, 0.0, 1.0)), float(length)

    def node_at(self, component: Component, x: float) -> int:
        """Index of the node nearest to station ``x`` [m]; at a coupling (two nodes at one
        station) the forward flange's node for x at or before the station, the aft one after it.

        Raises
        ------
        ValueError
            When ``x`` is not finite or lies outside the member (beyond a tolerance of 1e-9 of
            its length), or the member has no nodes.
        """
        xs = self._stations(component)
        if len(xs) == 0:
            raise ValueError(f"the model has no {component} nodes")
        self._check_station(component, xs, x)
        j = int(np.argmin(np.abs(xs - x)))
        if j + 1 < len(xs) and xs[j + 1] == xs[j] and x > xs[j]:
            return j + 1  # a coupling's two nodes share the station: aft of it is the aft flange's node
        return j

    @staticmethod
    def _check_station(component: Component, xs: np.ndarray, x: float) -> None:
        """``x`` must be finite and on the member (within 1e-9 of its length)."""
        if not np.isfinite(x):
            raise ValueError(f"x must be a finite station [m] (got {x!r})")
        tol = 1e-9 * max(1.0, abs(xs[-1] - xs[0]))
        if x < xs[0] - tol or x > xs[-1] + tol:
            raise ValueError(f"x = {x} m is outside the {component} [{xs[0]}, {xs[-1]}] m")

    def _stations(self, component: Component) -> np.ndarray:
        if component not in ("shaft", "boom"):
            raise ValueError(f"component must be 'shaft' or 'boom', got {component!r}")
        return self.shaft_x if component == "shaft" else self.boom_x

    def values(self, q: np.ndarray, component: Component, field: str) -> np.ndarray:
        """``field`` at every node of ``component`` from a global vector (leading axis = DOF)."""
        n = self.n_shaft_nodes if component == "shaft" else self.n_boom_nodes
        return np.asarray(q)[self.index(component, np.arange(n), field)]

    def expand(self, q_free: np.ndarray) -> np.ndarray:
        """Full global vector(s) from free-DOF values (fixed DOFs set to zero)."""
        q_free = np.asarray(q_free)
        out = np.zeros((self.size,) + q_free.shape[1:], dtype=q_free.dtype)
        out[self.free] = q_free
        return out
