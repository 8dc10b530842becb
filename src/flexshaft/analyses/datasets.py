"""``to_dataset()`` of the analysis results: labelled arrays with CF-style attributes.

Every function takes a result and returns an :class:`xarray.Dataset` (SI units in ``units``
attributes, ``long_name`` on every variable, coded labels with ``flag_values`` and
``flag_meanings``, global ``Conventions``), ready for ``.to_netcdf``. Complex quantities are
stored as real and imaginary parts (netCDF has no complex type).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from flexshaft.analyses.results import coded, new_dataset
from flexshaft.units import rad_s_to_rpm

__all__ = ["KINDS", "WHIRLS", "COMPONENTS", "modes_dataset", "curves_dataset", "response_dataset", "strength_dataset"]

KINDS = ("lateral", "torsional", "axial")
WHIRLS = ("forward", "backward", "planar", "none")
COMPONENTS = ("shaft", "boom", "coupled")


def _labels(values, meanings, long_name, dims):
    codes, attrs = coded(values, meanings, long_name)
    return dims, codes, attrs


def _translations(dofs, shapes: np.ndarray, dims_before: tuple[str, ...]) -> tuple[dict, dict]:
    """Shaft and boom translations (real, imaginary parts) of full-DOF vectors (ndof, ...)."""
    variables, coords = (
        {},
        {"x_shaft": ("x_shaft", np.asarray(dofs.shaft_x, float), {"units": "m", "long_name": "shaft node station"})},
    )
    nodes = np.arange(dofs.n_shaft_nodes)
    members: list[tuple[str, np.ndarray, Any, tuple[str, ...]]] = [("shaft", nodes, dofs.shaft, ("u", "v", "w"))]
    if dofs.n_boom_nodes:
        coords["x_boom"] = (
            "x_boom",
            np.asarray(dofs.boom_x, float),
            {"units": "m", "long_name": "tailboom node station"},
        )
        members.append(("boom", np.arange(dofs.n_boom_nodes), dofs.boom, ("v", "w")))
    for member, index, lookup, fields in members:
        for field in fields:
            values = np.moveaxis(np.asarray(shapes)[lookup(index, field)], 0, -1)  # (..., nodes)
            dims = dims_before + (f"x_{member}",)
            for part, take in (("real", np.real), ("imag", np.imag)):
                variables[f"{member}_{field}_{part}"] = (
                    dims,
                    take(values),
                    {
                        "units": "m",
                        "long_name": f"{member} {field} translation, {'real' if part == 'real' else 'imaginary'} part",
                    },
                )
    return variables, coords


def modes_dataset(m):
    """Dataset of :class:`flexshaft.analyses.modal.Modes` (dims ``mode``, ``x_shaft``, ``x_boom``)."""
    n = m.eigenvalues.size
    variables = {
        "frequency": ("mode", m.frequencies, {"units": "Hz", "long_name": "damped natural frequency"}),
        "growth_rate": (
            "mode",
            m.eigenvalues.real,
            {"units": "s-1", "long_name": "real part of the eigenvalue (positive: unstable)"},
        ),
        "damping_ratio": ("mode", m.damping_ratios, {"units": "1", "long_name": "damping ratio"}),
        "log_decrement": ("mode", m.log_decrements, {"units": "1", "long_name": "logarithmic decrement"}),
        "shaft_energy_share": (
            "mode",
            m.shaft_fractions,
            {"units": "1", "long_name": "share of kinetic energy in the shaft"},
        ),
        "kind": _labels(m.kind, KINDS, "mode kind", "mode"),
        "whirl": _labels(m.whirl, WHIRLS, "whirl direction", "mode"),
        "component": _labels(m.component, COMPONENTS, "dominant member", "mode"),
    }
    shapes, coords = _translations(m.dofs, m.shapes, ("mode",))
    variables.update(shapes)
    coords["mode"] = ("mode", np.arange(1, n + 1), {"long_name": "mode number (1 = lowest)"})
    return new_dataset(
        variables,
        coords,
        "natural frequencies and mode shapes",
        speed=float(m.speed),
        speed_units="rad/s",
        speed_rpm=float(rad_s_to_rpm(m.speed)),
        internal_damping=m.internal_damping,
    )


def curves_dataset(c, title: str, **attrs):
    """Dataset of tracked eigenvalue curves (Campbell, stability): dims ``speed``, ``mode``."""
    variables = {
        "frequency": (("speed", "mode"), c.frequencies, {"units": "Hz", "long_name": "damped natural frequency"}),
        "growth_rate": (
            ("speed", "mode"),
            c.real_parts,
            {"units": "s-1", "long_name": "real part of the eigenvalue (positive: unstable)"},
        ),
        "damping_ratio": (("speed", "mode"), c.damping_ratios, {"units": "1", "long_name": "damping ratio"}),
        "log_decrement": (("speed", "mode"), c.log_decrements, {"units": "1", "long_name": "logarithmic decrement"}),
        "whirl": _labels(c.whirl, WHIRLS, "whirl direction", ("speed", "mode")),
    }
    if getattr(c, "kind", None) is not None:
        variables["kind"] = _labels(c.kind, KINDS, "mode kind", ("speed", "mode"))
    if getattr(c, "component", None) is not None:
        variables["component"] = _labels(c.component, COMPONENTS, "dominant member", ("speed", "mode"))
    crit = getattr(c, "critical_speeds", ())
    if crit:
        variables.update(
            {
                "critical_speed": (
                    "critical",
                    np.array([k.speed for k in crit]),
                    {"units": "rad/s", "long_name": "critical speed"},
                ),
                "critical_mode": (
                    "critical",
                    np.array([k.mode + 1 for k in crit]),
                    {"long_name": "tracked mode number (1-based)"},
                ),
                "critical_harmonic": (
                    "critical",
                    np.array([k.harmonic for k in crit]),
                    {"units": "1", "long_name": "excitation order"},
                ),
                "critical_whirl": _labels(
                    [k.whirl for k in crit], WHIRLS, "whirl direction at the crossing", "critical"
                ),
            }
        )
    coords = {
        "speed": ("speed", c.speeds, {"units": "rad/s", "long_name": "spin speed"}),
        "speed_rpm": ("speed", rad_s_to_rpm(c.speeds), {"units": "rpm", "long_name": "spin speed"}),
        "mode": ("mode", np.arange(1, c.eigenvalues.shape[1] + 1), {"long_name": "tracked mode number (1-based)"}),
    }
    return new_dataset(variables, coords, title, internal_damping=c.internal_damping, **attrs)


def response_dataset(r):
    """Dataset of a :class:`flexshaft.analyses.response.HarmonicResponse`: translations at every
    node, dims (``case``, ``frequency``, ``x_shaft``/``x_boom``)."""
    q = (
        np.asarray(r).reshape(r.shape[0], -1, r.shape[-1])
        if np.ndim(r) == 3
        else np.asarray(r).reshape(r.shape[0], 1, -1)
    )
    variables, coords = _translations(r.dofs, q, ("case", "frequency"))
    coords["frequency"] = (
        "frequency",
        np.asarray(r.frequencies, float),
        {"units": "rad/s", "long_name": "excitation frequency"},
    )
    coords["spin_speed"] = (
        "frequency",
        np.asarray(r.spin_speeds, float),
        {"units": "rad/s", "long_name": "spin speed"},
    )
    coords["case"] = ("case", np.arange(1, q.shape[1] + 1), {"long_name": "load case (1-based)"})
    return new_dataset(
        variables, coords, f"{r.excitation} response", excitation=r.excitation, internal_damping=r.internal_damping
    )


def strength_dataset(s):
    """Dataset of a :class:`flexshaft.analyses.shaft_strength.StrengthResult` along the shaft."""
    variables = {
        "safety_factor_along": (
            "station",
            s.along_shaft,
            {"units": "1", "long_name": "smallest Tsai-Wu safety factor over plies, phases and signs"},
        )
    }
    coords = {"station": ("station", s.x_along, {"units": "m", "long_name": "shaft element end station"})}
    attrs = {
        "safety_factor": float(s.safety_factor),
        "critical_station_m": float(s.x),
        "critical_ply": int(s.ply) + 1,
        "critical_ply_angle_deg": float(s.ply_angle_deg),
        "critical_phase_deg": float(s.phase_deg),
        "dominant_stress": str(s.dominant_stress),
    }
    for name, share in (s.load_shares or {}).items():
        attrs[f"failure_index_share_{name}"] = float(share)
    return new_dataset(variables, coords, "ply Tsai-Wu safety factor along the shaft", **attrs)
