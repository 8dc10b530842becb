"""Thesis study 2: the Tsai-Wu safety factor over the two ply angles of (α/−α/β/−β)s, without
imbalance, on the sweep engine.

The map is symmetric in α ↔ β: (α/−α/β/−β)s and (β/−β/α/−α)s hold the same plies, the beam
model sees the laminate through its A matrix (where the ply order does not enter) and the
strength check uses the outer wall's membrane strains, so both orders have the same static
response and the same safety factor (docs/studies.md; computed apart, they differ by round-off,
3.5e-13 relative on the tuned design). Each unordered pair is therefore solved once, as
(larger/−larger/smaller/−smaller)s, and its mirror point reuses it: 28 of the 64 points of the
report's 8 × 8 map."""

from __future__ import annotations

import functools

import numpy as np

from flexshaft.design import with_overrides
from flexshaft.sweep.run import run_sweep
from flexshaft.sweep.study import Point, Study, Variable
from flexshaft.thesis.strength import STRENGTH_OUTPUTS, strength_outputs

__all__ = ["best_pair", "two_angle_layup", "two_angle_study"]


def two_angle_layup(angles) -> dict:
    """``(α/−α/β/−β)s`` [deg] from a pair (α, β)."""
    a, b = (f"{float(x):g}" for x in angles)
    return {"shaft.layup": f"({a}/-{a}/{b}/-{b})s".replace("--", "")}


def two_angle_study(alphas=None, betas=None, design=None, **run):
    """Safety factor over (α/−α/β/−β)s, no imbalance (thesis study 2); ``alphas`` and ``betas``
    [deg], default every 15° from 0° to 90°."""
    alphas = np.arange(0.0, 91.0, 15.0) if alphas is None else alphas
    betas = np.arange(0.0, 91.0, 15.0) if betas is None else betas
    study = Study(
        "two ply angles (a/-a/b/-b)s",
        (Variable("alpha", alphas, units="deg"), Variable("beta", betas, units="deg")),
        STRENGTH_OUTPUTS,
        _two_angle_strength,
        base=design,
        fixed={"loads.eccentricity": 0.0, "loads.balance_grade": None},
    )
    _pair_strength.cache_clear()  # the pairs are shared within one study, never across calls
    return run_sweep(study, **run)


def _two_angle_strength(point) -> dict:
    alpha, beta = float(point.axes["alpha"]), float(point.axes["beta"])
    return dict(_pair_strength(_DesignKey(point.design), max(alpha, beta), min(alpha, beta)))


class _DesignKey:
    """A design as a cache key: equal to another when their JSON texts are (a Design does not
    hash; its JSON takes about 0.04 ms)."""

    __slots__ = ("design", "text")

    def __init__(self, design) -> None:
        self.design = design
        self.text = design.model_dump_json()

    def __hash__(self) -> int:
        return hash(self.text)

    def __eq__(self, other) -> bool:
        return isinstance(other, _DesignKey) and other.text == self.text


@functools.lru_cache(maxsize=256)  # every pair of a 19 x 19 map (190) until its mirror comes up
def _pair_strength(base: _DesignKey, high: float, low: float) -> tuple[tuple[str, float], ...]:
    """:func:`~flexshaft.thesis.strength.strength_outputs` of (high/−high/low/−low)s [deg] on
    ``base``'s design, as (name, value) pairs."""
    design = with_overrides(base.design, two_angle_layup((high, low)))
    return tuple(strength_outputs(Point(0, {}, {}, design)).items())


def best_pair(sf: np.ndarray, alpha: np.ndarray, beta: np.ndarray) -> tuple[int, int]:
    """(i, j) of the largest safety factor of a two-angle map ``sf[i, j]`` over ``alpha[i]``,
    ``beta[j]`` [deg]. The map is symmetric in α ↔ β (module docstring): of the two orders of
    the best plies, which tie exactly, the one with the larger angle first (α >= β) is named, as
    in docs/studies.md: the study's headline, its figure and ``flexshaft study two-angle`` name
    the same laminate. Raises ValueError when every point is NaN."""
    sf = np.asarray(sf, dtype=float)
    top = sf.flat[np.nanargmax(sf)]
    best = np.argwhere(sf == top)
    first = [k for k, (i, j) in enumerate(best) if alpha[i] >= beta[j]]
    i, j = best[first[0] if first else 0]
    return int(i), int(j)
