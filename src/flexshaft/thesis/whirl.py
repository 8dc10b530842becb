"""Whirl-stability studies: the thesis's three shafts (figures 4.2-4.4) and margin maps over the
actuator gains.

Thesis chapter 4 compares an aluminium shaft, a (45/−45)s FMC shaft and a (45/−45/0/0)s FMC
shaft on the same driveline; its abstract says adding 0° plies improves stability.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from flexshaft.analyses.campbell import default_basis_size
from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.labelled import LabelledArrays
from flexshaft.analyses.stability import DampingModel, StabilityResult, stability
from flexshaft.assembly import build_model
from flexshaft.design import with_overrides

__all__ = [
    "THESIS_SHAFTS",
    "thesis_shaft_designs",
    "compare_shafts",
    "shaft_stability",
    "shaft_whirl",
    "StabilityMap",
    "gain_stability_map",
    "stability_dataset",
    "stack_maps",
]

#: (label, overrides) of the thesis figure 4.2-4.4 shafts; the wall and D_o stay the design's.
THESIS_SHAFTS = (
    ("aluminium 6061-T6", {"shaft.material": "al6061_t6", "shaft.layup": None}),
    ("(45/-45)s FMC", {"shaft.layup": "(45/-45)s"}),
    ("(45/-45/0/0)s FMC", {"shaft.layup": "(45/-45/0/0)s"}),
)


def thesis_shaft_designs(design) -> dict:
    """The three thesis shafts on ``design``'s driveline. The aluminium shaft needs an
    isotropic material named ``al6061_t6`` and the FMC shafts a lamina shaft material."""
    return {label: with_overrides(design, ov) for label, ov in THESIS_SHAFTS}


def compare_shafts(
    design,
    speeds,
    damping_model: DampingModel = "hysteretic",
    n_modes: int = 10,
    reference_frequency: float | None = None,
) -> dict[str, StabilityResult]:
    """Stability of each thesis shaft over ``speeds`` [rad/s]."""
    return {
        label: shaft_stability(d, speeds, damping_model, n_modes, reference_frequency)
        for label, d in thesis_shaft_designs(design).items()
    }


def shaft_stability(
    design,
    speeds,
    damping_model: DampingModel = "hysteretic",
    n_modes: int = 10,
    reference_frequency: float | None = None,
) -> StabilityResult:
    """Stability of one design over ``speeds`` [rad/s] (one task of :func:`compare_shafts`)."""
    return stability(build_model(design), speeds, n_modes, damping_model, reference_frequency)


def shaft_whirl(
    design, speeds, damping_models=("viscous", "hysteretic"), n_modes: int = 10
) -> dict[str, StabilityResult]:
    """:func:`shaft_stability` of one design with each damping model, ``{model: result}``: one
    model and one modal basis for all of them (the basis does not depend on the damping)."""
    model = build_model(design)
    return {damping: stability(model, speeds, n_modes, damping) for damping in damping_models}


@dataclass(frozen=True)
class StabilityMap:
    """Onset speed [rad/s] (NaN: stable up to ``max_speed``) and the smallest damping ratio at
    the operating speed over a grid of actuator gains, arrays (n_kp, n_kd)."""

    kp: np.ndarray
    kd: np.ndarray
    onset_speed: np.ndarray
    margin_at_operating: np.ndarray
    max_speed: float


def gain_stability_map(
    design,
    kp_values,
    kd_values,
    speeds,
    damping_model: DampingModel = "hysteretic",
    n_modes: int = 10,
    reference_frequency: float | None = None,
) -> StabilityMap:
    """Onset speed over (K_p, K_d) applied to every active bearing (same values on each).

    One model and modal basis per K_p (it sets the basis stiffness). Where every active bearing
    is a collocated PD law on an ideal amplifier, each K_d only changes the projected damping
    ``Σ k_i K_d B̃ᵀB̃`` (the force law is k_i C(s), k_i the current gain [N/A]), so the basis is
    reused; otherwise (a derivative filter, a controller, an amplifier lag or a sensor offset put
    K_d in the law's states) each point's model is built and reduced. The map keeps the onset
    and the margin of each point, not the eigenvalues' error estimates: none is computed
    (``estimate`` of :func:`~flexshaft.analyses.stability.stability`; the map 1.17x faster).
    """
    speeds = np.asarray(speeds, dtype=float)
    active = [i for i, b in enumerate(design.bearings) if b.kind == "active"]
    if not active:
        raise ValueError("the design has no active bearing")
    onset = np.full((len(kp_values), len(kd_values)), np.nan)
    margin = np.full_like(onset, np.nan)
    basis = max(default_basis_size(n_modes), 48)
    for i, kp in enumerate(kp_values):
        ov = {f"bearings[{a}].{k}": float(v) for a in active for k, v in (("kp", kp), ("kd", 0.0))}
        model = build_model(with_overrides(design, ov))
        shared = _kd_only_damps(design, model)
        if shared:  # the basis of K_d = 0 and the projected damping of a unit K_d, k_i B̃ᵀB̃
            base = reduce(model, basis)
            unit = sum(a.current_gain * (r.rows.T @ r.rows) for a, r in zip(model.actuators, base.actuators))
        for j, kd in enumerate(kd_values):
            if shared:
                red = dataclasses.replace(base, C=base.C + float(kd) * unit)
            else:  # K_d in the law's states: the point's own model
                model = build_model(with_overrides(design, {**ov, **{f"bearings[{a}].kd": float(kd) for a in active}}))
                red = reduce(model, basis)
            res = stability(model, speeds, n_modes, damping_model, reference_frequency, reduced=red, estimate=False)
            if res.onset_speed is not None:
                onset[i, j] = res.onset_speed
            margin[i, j] = res.stability_margin[int(np.argmin(np.abs(speeds - model.speed)))]
    return StabilityMap(np.asarray(kp_values, float), np.asarray(kd_values, float), onset, margin, float(speeds[-1]))


def _kd_only_damps(design, model) -> bool:
    """True when K_d enters the model only as the damping ``k_i K_d B̃ᵀB̃`` of each active
    bearing: a PD law (no controller, no derivative filter) measured at its magnet (collocated)
    through an ideal amplifier. Otherwise K_d is in the law's states."""
    laws = [b for b in design.bearings if b.kind == "active"]
    return not (
        any(b.controller is not None or b.derivative_cutoff is not None for b in laws)
        or any(not a.collocated or a.amplifier_bandwidth is not None for a in model.actuators)
    )


def stack_maps(rows) -> StabilityMap:
    """One map from maps over the same K_d values and speeds, each over its own K_p values
    (e.g. one :func:`gain_stability_map` per K_p, computed in parallel), in the given order."""
    rows = list(rows)
    if not rows:
        raise ValueError("stack_maps: no map given")
    kd, top = rows[0].kd, rows[0].max_speed
    for row in rows[1:]:
        if row.kd.shape != kd.shape or not np.array_equal(row.kd, kd) or row.max_speed != top:
            raise ValueError("stack_maps: the maps must share their K_d values and top speed")
    return StabilityMap(
        np.concatenate([r.kp for r in rows]),
        kd.copy(),
        np.vstack([r.onset_speed for r in rows]),
        np.vstack([r.margin_at_operating for r in rows]),
        top,
    )


def stability_dataset(smap: StabilityMap):
    """The stability margin map as labelled arrays (``.to_dataset()``: the xarray Dataset)."""
    return LabelledArrays(
        {
            "onset_speed": (
                ("kp", "kd"),
                smap.onset_speed,
                {"units": "rad/s", "long_name": "whirl onset speed (NaN: stable)"},
            ),
            "damping_ratio": (
                ("kp", "kd"),
                smap.margin_at_operating,
                {"units": "1", "long_name": "smallest damping ratio at the operating speed"},
            ),
        },
        coords={"kp": ("kp", smap.kp, {"units": "N/m"}), "kd": ("kd", smap.kd, {"units": "N s/m"})},
        attrs={"title": "whirl-stability margin over the actuator gains", "max_speed_rad_s": smap.max_speed},
    )
