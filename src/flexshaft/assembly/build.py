"""Build the assembled :class:`~flexshaft.assembly.model.Model` from a validated design.

Steps: estimate the problem size and refuse a design above the caps
(:func:`~flexshaft.assembly.size.check_problem_size`); mesh both members with nodes at every
bearing, disk and point load (:mod:`flexshaft.assembly.mesh`, close stations merged); stack
each kind of element and scatter it once (sparse COO); add lumped inertias and bearing links;
constrain the boom root and the shaft end DOFs named in the design; check the derived numbers
(:mod:`flexshaft.assembly.checks`: bearing stiffness against the shaft's element stiffness,
actuator gains, finite matrices), raising :class:`~flexshaft.design.DesignError`.

A segmented shaft (``[[shaft.segments]]``, ``[[couplings]]``, docs/segmented-driveline.md) has
nodes at every segment boundary and coupling (kept exactly: stations closer than the merge
tolerance move onto them); each segment's elements use its own tube; at each coupling the
station gets two nodes (one per side) joined by the coupling element instead of a shaft element.
A ``"rigid"`` coupling direction is an exact constraint: the aft node's DOF is tied to the
forward node's (:attr:`~flexshaft.assembly.dofs.DofMap.tied`). A penalty spring would not do:
the dense modal basis loses about ``eps · k_penalty / (I_node ω²)`` of relative accuracy, which
meets the penalty's own compliance error (``k_shaft / k_penalty``) near 1e-6 at best
(docs/segmented-driveline.md gives the measurements).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import scipy.sparse as sp

from flexshaft.assembly.checks import (
    check_actuator_law,
    check_bearing_stiffness,
    check_finite_model,
    check_magnet,
    magnet_gains,
)
from flexshaft.assembly.dofs import BOOM_FIELDS, SHAFT_FIELDS, DofMap
from flexshaft.assembly.drive import drive_extra_dofs, drive_terms, gearbox_holds_twist
from flexshaft.assembly.mesh import design_mesh, design_stations, merge_tolerance, segment_mesh
from flexshaft.assembly.model import (
    Actuator,
    BearingLink,
    Controller,
    CouplingLink,
    Model,
    SegmentProperties,
    ShaftProperties,
)
from flexshaft.assembly.size import check_problem_size
from flexshaft.assembly.sparse import scatter_blocks
from flexshaft.design import Design, DesignError, Problem
from flexshaft.elements import (
    TubeSection,
    boom_element_matrices,
    cowper_shear_coefficient,
    disk_matrices,
    ellipse_section,
    end_mass_matrix,
    magnetic,
    relative_rows,
    shaft_element_matrices,
)
from flexshaft.elements.coupling import coupling_matrices
from flexshaft.laminate import Lamina, Laminate, equivalent_moduli

__all__ = ["build_model", "segment_mesh", "shaft_properties", "segment_properties", "boom_semi_axes"]

_COUPLING_DIRECTIONS = {
    "u": "axial",
    "v": "lateral",
    "w": "lateral",
    "theta": "torsional",
    "beta": "angular",
    "gamma": "angular",
}

_RELATIVE = ("u", "v", "w", "beta", "gamma")


def shaft_properties(design) -> ShaftProperties:
    """Equivalent complex moduli and density of the ``[shaft]`` tube (CLT for a laminate).

    For a segmented shaft this is the nominal tube of the ``[shaft]`` table; each segment's own
    tube is in :func:`segment_properties`.
    """
    return _tube_properties(design.shaft, design.materials[design.shaft.material])


def segment_properties(design) -> tuple[SegmentProperties, ...]:
    """Every zone of the shaft (:attr:`~flexshaft.design.components.Shaft.tubes`) with its tube."""
    return tuple(
        SegmentProperties(
            tube.name,
            float(tube.x_start),
            float(tube.x_end),
            tube.material,
            _tube_properties(tube, design.materials[tube.material]),
        )
        for tube in design.shaft.tubes
    )


def _tube_properties(shaft, mat) -> ShaftProperties:
    """Properties of one tube (``[shaft]`` or a resolved segment) of material ``mat``."""
    angles = tuple(float(a) for a in shaft.ply_angles_deg) if mat.kind == "lamina" else ()
    return _tube_of(float(shaft.outer_diameter), float(shaft.wall_thickness), angles, mat)


@functools.lru_cache(maxsize=256)
def _tube_of(Do: float, wall: float, ply_angles_deg: tuple, mat) -> ShaftProperties:
    """:func:`_tube_properties` by value, cached: a one-piece shaft's ``[shaft]`` table and its one
    tube are the same tube (the laminate's arrays are read-only, shared by the models)."""
    Di = Do - 2 * wall
    if mat.kind == "lamina":
        lamina = Lamina.from_loss_factors(
            E_L=mat.E_L,
            E_T=mat.E_T,
            G_LT=mat.G_LT,
            nu_LT=mat.nu_LT,
            density=mat.density,
            loss_E_L=mat.loss_E_L,
            loss_E_T=mat.loss_E_T,
            loss_G_LT=mat.loss_G_LT,
            G_13=mat.G_13,
            G_23=mat.G_23,
            shear_correction=mat.shear_correction,
            alpha_L=mat.alpha_L,
            alpha_T=mat.alpha_T,
        )
        angles = np.radians(np.asarray(ply_angles_deg, dtype=float))
        plies = np.full(angles.size, wall / angles.size)
        angles.flags.writeable = plies.flags.writeable = False
        laminate = Laminate(angles=angles, thicknesses=plies, lamina=lamina)
        E, G = equivalent_moduli(laminate)
        return ShaftProperties(Do, Di, complex(E), complex(G), mat.density, laminate)
    eta = mat.loss_factor
    return ShaftProperties(Do, Di, mat.E * (1 + 1j * eta), mat.G * (1 + 1j * eta), mat.density, None)


def boom_semi_axes(tailboom, x):
    """Vertical and lateral mid-line semi-axes [m] of the linearly tapered boom at ``x``."""
    s = np.asarray(x, dtype=float) / tailboom.length
    a = (1 - s) * tailboom.root_semi_axes[0] + s * tailboom.tip_semi_axes[0]
    b = (1 - s) * tailboom.root_semi_axes[1] + s * tailboom.tip_semi_axes[1]
    return a, b


def _fixed_dofs(design, shaft_x, boom_x) -> np.ndarray:
    dm = DofMap(shaft_x, boom_x)
    fixed = [dm.shaft(0, f) for f in design.shaft.fixed_start]
    fixed += [dm.shaft(-1, f) for f in design.shaft.fixed_end]
    if gearbox_holds_twist(design):
        fixed.append(dm.shaft(0, "theta"))  # a rigid [main_gearbox] holds the forward twist
    if len(boom_x):
        fixed += [dm.boom(0, f) for f in BOOM_FIELDS]  # cantilevered from the fuselage
    return np.array(sorted(set(fixed)), dtype=int)


def _bearing_link(design, dm: DofMap, bearing, offset: float = 0.0) -> BearingLink:
    """Relative-displacement rows of ``bearing``; ``offset`` [m] shifts both the shaft and the
    boom station along x (a sensor beside an active bearing) at the bearing's height h."""
    return _bearing_rows(design, dm, bearing, offset)[0]


def _bearing_rows(design, dm: DofMap, bearing, offset: float = 0.0) -> tuple[BearingLink, np.ndarray, np.ndarray]:
    """:func:`_bearing_link` with the local rows (5, n_local) and their global DOFs."""
    x_shaft = bearing.x + offset
    if design.tailboom is None:
        xb, h = None, 0.0
    else:
        xb = bearing.boom_x
        if bearing.offset is not None:
            h = bearing.offset
        else:
            h = float(boom_semi_axes(design.tailboom, xb)[0]) + design.tailboom.shaft_clearance
        xb = xb + offset
    local, dofs, rows = _relative_rows(dm, float(x_shaft), None if xb is None else float(xb), float(h))
    if bearing.kind == "contact":
        link = BearingLink(
            bearing.name,
            bearing.kind,
            x_shaft,
            xb,
            h,
            rows,
            _coefficients(bearing.stiffness),
            _coefficients(bearing.damping),
        )
    else:
        link = BearingLink(bearing.name, bearing.kind, x_shaft, xb, h, rows)
    return link, local, dofs


#: Pieces of a model that depend on the geometry only, kept for the next build of the same
#: geometry: a report's ply-angle, gain and wall sweeps build about 150 models, most of them on one
#: mesh, and the boom's element matrices and the bearings' rows were a third of each build.
#: Entries are read-only; keys hold the stations' bytes.
_GEOMETRY_CACHE = 64


def _relative_rows(dm: DofMap, x_shaft: float, x_boom: float | None, h: float):
    """(local rows (5, n_local), their global DOFs, sparse (5, ndof) rows) of a link between the
    shaft at ``x_shaft`` and the boom at ``x_boom`` (None: ground) at height ``h``, cached for
    the DOF map's geometry (:func:`_geometry_rows`)."""
    arrays = (dm.shaft_x, dm.boom_x, dm.fixed, dm.shaft_joints, dm.tied)
    key = tuple((np.asarray(a).dtype.str, np.shape(a), np.asarray(a).tobytes()) for a in arrays)
    return _geometry_rows(key, dm.extra, x_shaft, x_boom, h)


@functools.lru_cache(maxsize=4 * _GEOMETRY_CACHE)
def _geometry_rows(key: tuple, extra: tuple[str, ...], x_shaft: float, x_boom: float | None, h: float):
    """:func:`_relative_rows` on the DOF map whose arrays ``key`` holds (dtype, shape, bytes) and
    whose extra (drive-train twist) DOFs are ``extra``: they set the global size."""
    shaft_x, boom_x, fixed, joints, tied = (
        np.frombuffer(data, dtype=np.dtype(dtype)).reshape(shape) for dtype, shape, data in key
    )
    dm = DofMap(shaft_x, boom_x, fixed, joints, tied, extra=extra)
    es, xis, Ls = dm.locate("shaft", x_shaft)
    shaft_dofs = dm.element_dofs("shaft")[es]
    if x_boom is None:
        local, dofs = relative_rows(xis, Ls), shaft_dofs
    else:
        eb, xib, Lb = dm.locate("boom", x_boom)
        local = relative_rows(xis, Ls, xib, Lb, h)
        dofs = np.concatenate([shaft_dofs, dm.element_dofs("boom")[eb]])
    rows = sp.coo_matrix(
        (local.ravel(), (np.repeat(np.arange(5), dofs.size), np.tile(dofs, 5))), shape=(5, dm.size)
    ).tocsr()
    for array in (local, dofs, rows.data, rows.indices, rows.indptr):  # shared by the models of one mesh
        array.flags.writeable = False
    return local, dofs, rows


@functools.lru_cache(maxsize=_GEOMETRY_CACHE)
def _boom_blocks(boom_x: bytes, tailboom, material) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mass, stiffness and loss stiffness (imaginary part) of the boom elements on stations
    ``boom_x`` (float64 bytes), cached (read-only arrays)."""
    eta = material.loss_factor

    def section_at(x):
        a, b = boom_semi_axes(tailboom, x)
        return ellipse_section(a, b, tailboom.wall_thickness)

    Mb, Kb = boom_element_matrices(
        np.frombuffer(boom_x), section_at, material.E * (1 + 1j * eta), material.G * (1 + 1j * eta), material.density
    )
    blocks = (Mb, np.ascontiguousarray(Kb.real), np.ascontiguousarray(Kb.imag))
    for block in blocks:
        block.flags.writeable = False
    return blocks


def _actuator(design, dm: DofMap, bearing, link: BearingLink) -> Actuator:
    """The magnetic bearing of an active-bearing table (see :class:`~flexshaft.assembly.model.Actuator`)."""
    index = design.bearings.index(bearing)
    ctrl = Controller(*(tuple(float(c) for c in part) for part in bearing.transfer_function()))
    k_i, k_s = magnet_gains(bearing)
    saturation = None
    if bearing.saturation_flux_density is not None:
        saturation = magnetic.saturation_force(
            bearing.saturation_flux_density, bearing.pole_area, bearing.pole_angle_rad
        )
    sensor = _bearing_link(design, dm, bearing, bearing.sensor_offset) if bearing.sensor_offset != 0.0 else None
    check_magnet(design, index, k_i, k_s)
    actuator = Actuator(
        link,
        ctrl,
        current_gain=k_i,
        negative_stiffness=k_s,
        amplifier_bandwidth=bearing.amplifier_bandwidth_rad_s,
        sensor=sensor,
        air_gap=bearing.air_gap,
        bias_current=bearing.bias_current,
        saturation_force=saturation,
    )
    check_actuator_law(design, index, actuator, design.operating.speed_rad_s)
    return actuator


def _coefficients(table) -> np.ndarray:
    if hasattr(table, "as_dict"):
        table = table.as_dict()
    table = table or {}
    return np.array([float(table.get(f, 0.0) or 0.0) for f in _RELATIVE])


def build_model(design) -> Model:
    """Assemble the global model of a validated :class:`~flexshaft.design.Design`.

    Raises
    ------
    DesignError
        When the problem is too large (:func:`~flexshaft.assembly.size.check_problem_size`,
        ``"model"``) or a derived number is out of range (:mod:`flexshaft.assembly.checks`).
    ValueError
        When ``design`` is not a validated Design.

    Warns
    -----
    ProblemSizeWarning
        When the model is large (above the soft caps).
    """

    if not isinstance(design, Design):
        raise ValueError(
            f"build_model needs a validated flexshaft.design.Design (got {type(design).__name__}); "
            "use load_design, loads_design or design_from_dict"
        )
    check_problem_size(design, "model", stacklevel=4)  # the caller of flexshaft.assembly.build_model
    shaft_x, boom_x = design_mesh(design) if not design.segmented else _segmented_mesh(design)
    shaft_x, joints = _split_at_couplings(design, shaft_x)
    dm = DofMap(
        shaft_x,
        boom_x,
        _fixed_dofs(design, shaft_x, boom_x),
        joints,
        _tied_dofs(design, shaft_x, boom_x, joints),
        drive_extra_dofs(design),
    )
    n = dm.size

    props = shaft_properties(design)
    check_bearing_stiffness(design, props)
    segments = segment_properties(design)
    parts: dict[str, list] = {"M": [], "K": [], "C": [], "G": [], "shaft_loss": [], "boom_loss": []}
    _shaft_elements(design, dm, segments, parts)
    couplings = _couplings(design, dm, parts)

    if design.tailboom is not None:
        tb = design.tailboom
        Mb, Kb, Kb_loss = _boom_blocks(np.asarray(boom_x, dtype=float).tobytes(), tb, design.materials[tb.material])
        bdofs = dm.element_dofs("boom")
        parts["M"].append((Mb, bdofs))
        parts["K"].append((Kb, bdofs))
        parts["boom_loss"].append((Kb_loss, bdofs))
        if tb.end_mass is not None:
            em = tb.end_mass
            tip = np.array([dm.boom(-1, f) for f in BOOM_FIELDS])
            parts["M"].append((end_mass_matrix(em.mass, em.offset, em.inertia)[None], tip[None]))

    for disk in design.disks:
        node = dm.node_at("shaft", disk.x)
        Md, Gd = disk_matrices(disk.mass, disk.diametral_inertia, disk.polar_inertia)
        dofs = np.array([dm.shaft(node, f) for f in ("u", "v", "w", "theta", "beta", "gamma")])
        parts["M"].append((Md[None], dofs[None]))
        parts["G"].append((Gd[None], dofs[None]))

    drive = drive_terms(design, dm, parts)

    links, actuators = [], []
    for bearing in design.bearings:
        link, local, dofs = _bearing_rows(design, dm, bearing)
        links.append(link)
        if bearing.kind == "contact":
            parts["K"].append((((local.T * link.stiffness) @ local)[None], dofs[None]))
            if np.any(link.damping):
                parts["C"].append((((local.T * link.damping) @ local)[None], dofs[None]))
        else:
            actuators.append(_actuator(design, dm, bearing, link))
    M, K, C, G, shaft_loss, boom_loss = (
        scatter_blocks(parts[k], n) for k in ("M", "K", "C", "G", "shaft_loss", "boom_loss")
    )

    model = Model(
        dofs=dm,
        M=M.tocsr(),
        K=K.astype(float).tocsr(),
        C=C.tocsr(),
        G=G.tocsr(),
        bearings=tuple(links),
        actuators=tuple(actuators),
        shaft=props if not design.segmented else dataclasses.replace(props, laminate=None),
        segments=segments,
        couplings=couplings,
        speed=float(design.operating.speed_rad_s),
        power=float(design.operating.power),
        design=design,
        shaft_loss_stiffness=shaft_loss.tocsr(),
        boom_loss_stiffness=boom_loss.tocsr(),
        internal_damping=design.analysis.internal_damping,
        drive=drive,
    )
    check_finite_model(model)
    return model


# ------------------------------------------------------------------------------------------------
# Segmented shafts: mesh, shaft elements per segment, couplings


def _segmented_mesh(design) -> tuple[np.ndarray, np.ndarray]:
    """:func:`~flexshaft.assembly.mesh.design_mesh` with the segment boundaries and couplings
    kept exactly: a station closer to one of them than the merge tolerance moves onto it (a
    bearing still acts at its own station through the shape functions)."""
    shaft_pts, _ = design_stations(design)
    sh = design.shaft
    hard = sorted({t.x_start for t in sh.tubes[1:]} | {c.x for c in design.couplings})
    tol = merge_tolerance(sh.x_end - sh.x_start, design.mesh.shaft_elements)
    ends = (sh.x_start, sh.x_end)
    crowded = [x for x in hard if min(abs(x - e) for e in ends) < tol]
    crowded += [b for a, b in zip(hard[:-1], hard[1:]) if b - a < tol]
    if crowded:
        raise DesignError(
            [
                Problem(
                    "mesh.shaft_elements",
                    f"the segment boundary or coupling at x = {x:.6g} m is "
                    f"closer than {tol:.3g} m (5 % of an element) to another one or to a shaft end; "
                    "raise shaft_elements or move it",
                )
                for x in crowded
            ],
            "<model>",
        )
    soft = [x for x in shaft_pts if min(abs(x - h) for h in hard) >= tol]
    shaft_x = segment_mesh(soft + hard, design.mesh.shaft_elements)
    boom_x = design_mesh(design)[1]
    return shaft_x, boom_x


def _split_at_couplings(design, shaft_x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Shaft stations with each coupling station doubled (one node per side), and the joints:
    the indices j of the node pairs (j, j + 1) that are joints."""
    joints = []
    for coupling in sorted(design.couplings, key=lambda c: c.x):
        j = int(np.argmin(np.abs(shaft_x - coupling.x)))
        shaft_x = np.insert(shaft_x, j + 1, shaft_x[j])
        joints.append(j)
    return shaft_x, np.array(joints, dtype=int)


def _shaft_elements(design, dm: DofMap, segments, parts: dict) -> None:
    """Shaft element matrices, each segment's elements with its own tube."""
    ends = dm.shaft_element_x
    lengths = ends[:, 1] - ends[:, 0]
    zone = np.searchsorted([seg.x_end for seg in segments[:-1]], 0.5 * (ends[:, 0] + ends[:, 1]))
    sdofs = dm.element_dofs("shaft")
    for index, seg in enumerate(segments):
        mine = np.flatnonzero(zone == index)
        if not mine.size:
            continue
        props = seg.properties
        section = TubeSection(props.outer_diameter, props.inner_diameter)
        kappa = None
        if design.shaft.shear_deformation:
            nu = float(np.clip(props.youngs_modulus.real / (2 * props.shear_modulus.real) - 1, 0.0, 0.5))
            kappa = cowper_shear_coefficient(section, nu)
        Ms, Ks, Gs = shaft_element_matrices(
            lengths[mine], section, props.youngs_modulus, props.shear_modulus, props.density, kappa
        )
        dofs = sdofs[mine]
        parts["M"].append((Ms, dofs))
        parts["K"].append((Ks.real, dofs))
        parts["G"].append((Gs, dofs))
        parts["shaft_loss"].append((Ks.imag, dofs))


def _coupling_values(coupling) -> list:
    """The coupling's stiffness per shaft field (a number or "rigid"), in SHAFT_FIELDS order."""
    return [getattr(coupling, f"{_COUPLING_DIRECTIONS[f]}_stiffness") for f in SHAFT_FIELDS]


def _tied_dofs(design, shaft_x, boom_x, joints) -> np.ndarray:
    """(tied, equals) raw DOF pairs of the rigid coupling directions: aft node = forward node."""
    raw = DofMap(shaft_x, boom_x)
    pairs = [
        (raw.shaft(j + 1, f), raw.shaft(j, f))
        for coupling, j in zip(sorted(design.couplings, key=lambda c: c.x), joints)
        for f, value in zip(SHAFT_FIELDS, _coupling_values(coupling))
        if value == "rigid"
    ]
    return np.array(pairs, dtype=int).reshape(-1, 2)


def _couplings(design, dm: DofMap, parts: dict) -> tuple[CouplingLink, ...]:
    """Coupling elements on the node pairs of the joints (in order of station); a rigid
    direction is tied (:func:`_tied_dofs`) and gets no spring."""
    links = []
    for coupling, j in zip(sorted(design.couplings, key=lambda c: c.x), dm.shaft_joints):
        values = _coupling_values(coupling)
        rigid = np.array([v == "rigid" for v in values])
        stiffness = np.array([0.0 if r else float(v) for v, r in zip(values, rigid)])
        K, M, G = coupling_matrices(stiffness, coupling.mass, coupling.diametral_inertia, coupling.polar_inertia)
        dofs = np.array([dm.shaft(node, f) for node in (j, j + 1) for f in SHAFT_FIELDS])
        parts["K"].append((K[None], dofs[None]))
        parts["M"].append((M[None], dofs[None]))
        parts["G"].append((G[None], dofs[None]))
        allowable = None if coupling.allowable_angle_deg is None else float(np.radians(coupling.allowable_angle_deg))
        links.append(
            CouplingLink(
                coupling.name,
                float(dm.shaft_x[j]),
                int(j),
                int(j + 1),
                np.where(rigid, np.inf, stiffness),
                rigid,
                float(coupling.mass),
                allowable,
            )
        )
    return tuple(links)
