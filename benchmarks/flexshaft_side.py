"""The flexshaft half of the ROSS comparison: model building and the three timed analyses.

Every flexshaft call lives in one small function here, so that when the package grows faster
sweep functions only these functions change. Sweep functions are used when
``flexshaft.analyses`` provides them (``imbalance_response``, ``campbell``); otherwise the
per-point fallbacks (``frequency_response`` per speed, ``modes`` per speed) are used, and the
result says which path ran.

Run as a script it is the worker of ``compare_ross.py``: one case on one mesh in a fresh
process, cold (first build and call) then warm (repeats), as JSON on stdout::

    .venv/bin/python benchmarks/flexshaft_side.py unbalance 100 --repeats 3
"""

from __future__ import annotations

import inspect
import time

_T0 = time.perf_counter()

import numpy as np  # noqa: E402
import shaft_case as case  # noqa: E402

import flexshaft  # noqa: E402
import flexshaft.analyses as fa  # noqa: E402

_IMPORT_S = time.perf_counter() - _T0  # numpy + flexshaft import, for the worker's cold time

DESIGN_TEMPLATE = """
name = "uniform steel tube on two end bearings (ROSS benchmark)"
[materials.steel]
kind = "isotropic"
E = {E!r}
G = {G!r}
density = {rho!r}

[shaft]
x_start = 0.0
x_end = {L!r}
outer_diameter = {Do!r}
wall_thickness = {t!r}
material = "steel"
fixed_start = ["u", "theta"]
shear_deformation = false

[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = {{ v = {k!r}, w = {k!r} }}
damping = {{ v = {c!r}, w = {c!r} }}

[[bearings]]
name = "right"
kind = "contact"
x = {L!r}
stiffness = {{ v = {k!r}, w = {k!r} }}
damping = {{ v = {c!r}, w = {c!r} }}

[operating]
speed_rpm = 0.0
power = 0.0

[mesh]
shaft_elements = {n}
"""


def design_text(n_el: int) -> str:
    return DESIGN_TEMPLATE.format(
        E=case.E,
        G=case.G,
        rho=case.DENSITY,
        L=case.LENGTH,
        Do=case.OUTER_DIAMETER,
        t=(case.OUTER_DIAMETER - case.INNER_DIAMETER) / 2,
        k=case.BEARING_STIFFNESS,
        c=case.BEARING_DAMPING,
        n=n_el,
    )


def build(n_el: int):
    """Design (TOML text) -> model; checks the mesh is the uniform n_el-element one."""
    model = flexshaft.build_model(flexshaft.loads_design(design_text(n_el)))
    x = np.asarray(model.dofs.shaft_x)
    if len(x) != n_el + 1 or not np.allclose(np.diff(x), case.LENGTH / n_el):
        raise RuntimeError(f"flexshaft mesh is not {n_el} uniform elements: {x}")
    return model


def mid_node(model) -> int:
    return int(model.dofs.node_at("shaft", case.LENGTH / 2))


def lateral_dofs(model, node: int) -> tuple[int, int]:
    return model.dofs.shaft(node, "v"), model.dofs.shaft(node, "w")


def has_imbalance_sweep() -> bool:
    return hasattr(fa, "imbalance_response")


def has_campbell_sweep() -> bool:
    # a function, not the submodule ``flexshaft.analyses.campbell`` (an attribute once imported)
    f = getattr(fa, "campbell", None)
    return callable(f) and not inspect.ismodule(f)


def unbalance_loads(model) -> np.ndarray:
    """Load per Ω²: forward-rotating m·e at the mid node, Q_v = m e, Q_w = −i m e."""
    Q = np.zeros(model.dofs.size, dtype=complex)
    v, w = lateral_dofs(model, mid_node(model))
    Q[v] = case.UNBALANCE
    Q[w] = -1j * case.UNBALANCE
    return Q


def unbalance_response(model, speeds: np.ndarray) -> np.ndarray:
    """Synchronous response (ndof, n_speeds) to the rotating imbalance Ω²·Q."""
    Q = unbalance_loads(model)
    if has_imbalance_sweep():
        return fa.imbalance_response(model, speeds, Q)
    out = np.empty((model.dofs.size, len(speeds)), dtype=complex)
    for k, s in enumerate(speeds):
        out[:, k] = flexshaft.frequency_response(model, s * s * Q, float(s), speed=float(s))
    return out


def frf(model, omegas: np.ndarray, speed: float) -> np.ndarray:
    """Response (ndof, n_ω) to a unit-amplitude lateral-1 (v) force at the mid node."""
    Q = np.zeros(model.dofs.size)
    Q[model.dofs.shaft(mid_node(model), "v")] = case.FRF_FORCE
    return flexshaft.frequency_response(model, Q, omegas, speed=speed)


def _campbell_call(model, speeds, n_modes):
    params = inspect.signature(fa.campbell).parameters
    kwargs = {"n_modes": n_modes} if "n_modes" in params else {}
    return fa.campbell(model, speeds, **kwargs)


def _lateral_mask(model, shapes: np.ndarray) -> np.ndarray:
    """True for bending modes (columns), False for axial/torsional ones (exactly uncoupled here)."""
    d = model.dofs
    n = np.arange(d.n_shaft_nodes)
    lat = sum(np.sum(np.abs(shapes[d.shaft(n, f)]) ** 2, axis=0) for f in ("v", "w", "beta", "gamma"))
    other = sum(np.sum(np.abs(shapes[d.shaft(n, f)]) ** 2, axis=0) for f in ("u", "theta"))
    return lat > other


def nonlateral_frequencies(model, n_modes: int = case.N_CAMPBELL_FREQ + 6) -> np.ndarray:
    """Frequencies [Hz] of the axial/torsional modes among the lowest ``n_modes`` at rest.

    They do not depend on speed or on the (lateral) bearing damping here, so they identify the
    sweep's tracked curves that are not bending modes. Post-processing: called after the timed
    :func:`campbell_sweep`.
    """
    m = flexshaft.modes(model, 0.0, n_modes=n_modes, damped=False)
    return m.frequencies[~_lateral_mask(model, m.shapes)]


def campbell_sweep(model, speeds: np.ndarray, n_freq: int):
    """The timed part of the Campbell case: the analysis call only.

    Extra modes are requested because flexshaft's clamped-in-twist shaft has torsional and
    axial modes in the band (ROSS's free-free ones sit higher); :func:`campbell_lateral` drops
    them afterwards. Without the sweep function, the per-speed fallback returns its lateral
    frequencies directly.
    """
    n_req = n_freq + 6
    if has_campbell_sweep():
        return _campbell_call(model, speeds, n_req)
    out_f = np.empty((len(speeds), n_freq))
    out_w = np.empty((len(speeds), n_freq), dtype=object)
    for i, s in enumerate(speeds):
        m = flexshaft.modes(model, float(s), n_modes=n_req, damped=True)
        keep = _lateral_mask(model, m.shapes)
        out_f[i] = m.frequencies[keep][:n_freq]
        out_w[i] = m.whirl[keep][:n_freq]
    return out_f, out_w


def campbell_lateral(model, raw, n_freq: int) -> tuple[np.ndarray, np.ndarray]:
    """Lowest ``n_freq`` lateral damped natural frequencies [Hz] per speed (sorted) and whirl,
    from the output of :func:`campbell_sweep` (untimed post-processing)."""
    if isinstance(raw, tuple):
        return raw
    freqs = np.asarray(raw.frequencies)
    whirl = np.asarray(raw.whirl)
    other = nonlateral_frequencies(model, n_freq + 6)
    f0 = freqs[0]
    lateral = np.array([not np.any(np.abs(other - f) <= 1e-6 * f) for f in f0])
    freqs, whirl = freqs[:, lateral], whirl[:, lateral]
    order = np.argsort(freqs, axis=1)[:, :n_freq]
    return np.take_along_axis(freqs, order, 1), np.take_along_axis(whirl, order, 1)


#: Every REFERENCE_STEP-th Campbell speed gets the full dense reference (1.5 s a speed at 100
#: elements: 50 would take over a minute; 8 span the range, both ends included).
REFERENCE_STEP = 7


def campbell_reference(model, speeds: np.ndarray, n_freq: int) -> dict:
    """The full (unreduced) eigenproblem's lowest ``n_freq`` lateral damped frequencies [Hz] at
    every :data:`REFERENCE_STEP`-th speed and the last: every eigenvalue of
    ``(s²M + s(ΩG + C) + K) x = 0`` on all free DOFs from a dense eigen-solve of its companion
    matrix (LAPACK ``dgeev``), lateral modes picked by their eigenvectors. Untimed: the yardstick
    both codes' Campbell results are measured against."""
    import scipy.linalg as la

    from flexshaft.assembly.sparse import restrict

    free = model.dofs.free
    M, G, C, K = (
        restrict(A.tocsr(), free).toarray() for A in (model.M, model.G, model.C + model.Kd, model.K + model.Kp)
    )
    n = M.shape[0]
    picks = sorted(set(range(0, len(speeds), REFERENCE_STEP)) | {len(speeds) - 1})
    out = []
    for i in picks:
        A = np.zeros((2 * n, 2 * n))
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -la.solve(M, K, assume_a="pos")
        A[n:, n:] = -la.solve(M, speeds[i] * G + C, assume_a="pos")
        lam, vec = la.eig(A)
        keep = lam.imag > 0
        lam, vec = lam[keep], vec[:n, keep]
        shapes = np.zeros((model.dofs.size, lam.size), dtype=complex)
        shapes[free] = vec
        lat = _lateral_mask(model, shapes)
        f = np.sort(lam[lat].imag / (2 * np.pi))[:n_freq]
        out.append(f.tolist())
    return {"speed_index": picks, "wd_hz": out}


def campbell(model, speeds: np.ndarray, n_freq: int) -> tuple[np.ndarray, np.ndarray]:
    """Lowest ``n_freq`` lateral damped natural frequencies [Hz] per speed and whirl labels."""
    return campbell_lateral(model, campbell_sweep(model, speeds, n_freq), n_freq)


# -------------------------------------------------------------------------------------------------
# worker: one (case, mesh) in a fresh process, cold and warm, JSON on stdout


def _c(z) -> dict:
    z = np.asarray(z)
    return {"re": z.real.tolist(), "im": z.imag.tolist()}


def _case_call(name: str, model):
    """(the timed call, post-processing of its output into ROSS's result layout)."""
    iv, iw = lateral_dofs(model, mid_node(model))
    if name == "unbalance":
        speeds = np.array(case.unbalance_speeds())
        return (
            lambda: unbalance_response(model, speeds),
            lambda q: {"x": _c(q[iv]), "y": _c(q[iw]), "path": "sweep" if has_imbalance_sweep() else "fallback"},
        )
    if name == "frf":
        freqs = np.array(case.frf_frequencies())
        return (
            lambda: frf(model, freqs, case.FRF_SPEED),
            lambda q: {"x": _c(q[iv]), "y": _c(q[iw]), "path": "frequency_response"},
        )
    if name == "campbell":
        speeds = np.array(case.campbell_speeds())
        n = case.N_CAMPBELL_FREQ

        def post(raw):
            f, w = campbell_lateral(model, raw, n)
            out = {
                "wd_hz": np.asarray(f, dtype=float).tolist(),
                "whirl": np.asarray(w).tolist(),
                "path": "sweep" if has_campbell_sweep() else "fallback",
            }
            estimate = getattr(raw, "error_estimate", None)
            if estimate is not None:  # flexshaft's own a-posteriori estimate, every tracked mode
                out["error_estimate_max"] = float(np.nanmax(estimate))
                out["basis_size"] = getattr(raw, "basis_size", None)
                out["tolerance"] = getattr(raw, "tolerance", None)
            return out

        return (lambda: campbell_sweep(model, speeds, n)), post
    raise ValueError(f"case must be unbalance, frf or campbell, got {name!r}")


def run_single(name: str, n_el: int, repeats: int, import_s: float) -> dict:
    """Cold: first build and first call in this fresh process. Warm: ``repeats`` calls, each on
    a freshly built model (the build outside the clock), after the cold call has warmed up the
    process, as on the ROSS side (whose rotors cache their results)."""
    import bench_util as bu

    rss_import = bu.current_rss_mb()
    build_s, _, model = bu.timed(lambda: build(n_el))
    call, post = _case_call(name, model)
    cold_wall, cold_cpu, raw = bu.timed(call)
    result = post(raw)
    peak_cold = bu.maxrss_mb()
    walls, cpus = [], []
    for _ in range(repeats):
        model = build(n_el)
        call, _ = _case_call(name, model)
        w, c, _ = bu.timed(call)
        walls.append(w)
        cpus.append(c)
    peak = bu.maxrss_mb()  # before the reference below, which is no part of the case
    if name == "campbell":
        result["reference"] = campbell_reference(model, np.array(case.campbell_speeds()), case.N_CAMPBELL_FREQ)
    return {
        "code": "flexshaft",
        "version": flexshaft.__version__,
        "case": name,
        "n_el": n_el,
        "ndof": int(model.dofs.size),
        "import_s": import_s,
        "build_s": build_s,
        "cold_s": cold_wall,
        "cold_cpu_s": cold_cpu,
        "warm": {**bu.stats(walls), "cpu": bu.stats(cpus)},
        "rss_after_import_mb": rss_import,
        "peak_rss_cold_mb": peak_cold,
        "peak_rss_mb": peak,
        "path": result.pop("path"),
        "result": result,
        "numpy": np.__version__,
        "scipy": _scipy_version(),
    }


def _scipy_version() -> str:
    import scipy

    return scipy.__version__


if __name__ == "__main__":
    import argparse
    import json
    import sys

    p = argparse.ArgumentParser(
        description="flexshaft worker of compare_ross.py: one case, one mesh, cold then warm; JSON on stdout"
    )
    p.add_argument("case", choices=["unbalance", "frf", "campbell"])
    p.add_argument("n_el", type=int)
    p.add_argument("--repeats", type=int, default=3)
    a = p.parse_args()
    json.dump(run_single(a.case, a.n_el, a.repeats, _IMPORT_S), sys.stdout)
