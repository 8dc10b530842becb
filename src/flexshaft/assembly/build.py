"""Build the assembled :class:`~flexshaft.assembly.model.Model` from a validated design.

Steps: estimate the problem size and refuse a design above the caps
(:func:`~flexshaft.assembly.size.check_problem_size`); mesh both members with nodes at every
bearing, disk and point load (:mod:`flexshaft.assembly.mesh`, close stations merged); stack
each kind of element and scatter it once (sparse COO); add lumped inertias and bearing links;
constrain the boom root and the shaft end DOFs named in the design; check the derived numbers
(:mod:`flexshaft.assembly.checks`: bearing stiffness against the shaft's element stiffness,
actuator gains, finite matrices), raising :class:`~flexshaft.design.DesignError`.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from flexshaft.assembly.checks import check_actuator_law, check_bearing_stiffness, check_finite_model, check_magnet
from flexshaft.assembly.dofs import BOOM_FIELDS, DofMap
from flexshaft.assembly.mesh import design_mesh, segment_mesh
from flexshaft.assembly.model import Actuator, BearingLink, Controller, Model, ShaftProperties
from flexshaft.assembly.size import check_problem_size
from flexshaft.assembly.sparse import scatter_blocks
from flexshaft.elements import magnetic
from flexshaft.elements import (
    TubeSection,
    boom_element_matrices,
    cowper_shear_coefficient,
    disk_matrices,
    ellipse_section,
    end_mass_matrix,
    relative_rows,
    shaft_element_matrices,
)
from flexshaft.laminate import Lamina, Laminate, equivalent_moduli

__all__ = ["build_model", "segment_mesh", "shaft_properties", "boom_semi_axes"]

_RELATIVE = ("u", "v", "w", "beta", "gamma")


def shaft_properties(design) -> ShaftProperties:
    """Equivalent complex moduli and density of the shaft tube (CLT for a laminate)."""
    shaft = design.shaft
    mat = design.materials[shaft.material]
    Do = shaft.outer_diameter
    Di = Do - 2 * shaft.wall_thickness
    if mat.kind == "lamina":
        lamina = Lamina.from_loss_factors(
            E_L=mat.E_L, E_T=mat.E_T, G_LT=mat.G_LT, nu_LT=mat.nu_LT, density=mat.density,
            loss_E_L=mat.loss_E_L, loss_E_T=mat.loss_E_T, loss_G_LT=mat.loss_G_LT,
            G_13=mat.G_13, G_23=mat.G_23, shear_correction=mat.shear_correction,
            alpha_L=mat.alpha_L, alpha_T=mat.alpha_T,
        )
        angles = np.radians(np.asarray(shaft.ply_angles_deg, dtype=float))
        plies = np.full(angles.size, shaft.wall_thickness / angles.size)
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
    es, xis, Ls = dm.locate("shaft", x_shaft)
    shaft_dofs = dm.element_dofs("shaft")[es]
    if design.tailboom is None:
        local, dofs, xb, h = relative_rows(xis, Ls), shaft_dofs, None, 0.0
    else:
        xb = bearing.boom_x
        if bearing.offset is not None:
            h = bearing.offset
        else:
            h = float(boom_semi_axes(design.tailboom, xb)[0]) + design.tailboom.shaft_clearance
        xb = xb + offset
        eb, xib, Lb = dm.locate("boom", xb)
        local = relative_rows(xis, Ls, xib, Lb, h)
        dofs = np.concatenate([shaft_dofs, dm.element_dofs("boom")[eb]])
    rows = sp.coo_matrix(
        (local.ravel(), (np.repeat(np.arange(5), dofs.size), np.tile(dofs, 5))), shape=(5, dm.size)
    ).tocsr()
    if bearing.kind == "contact":
        link = BearingLink(bearing.name, bearing.kind, x_shaft, xb, h, rows,
                           _coefficients(bearing.stiffness), _coefficients(bearing.damping))
    else:
        link = BearingLink(bearing.name, bearing.kind, x_shaft, xb, h, rows)
    return link, local, dofs


def _actuator(design, dm: DofMap, bearing, link: BearingLink) -> Actuator:
    """The magnetic bearing of an active-bearing table (see :class:`~flexshaft.assembly.model.Actuator`)."""
    index = design.bearings.index(bearing)
    ctrl = Controller(*(tuple(float(c) for c in part) for part in bearing.transfer_function()))
    if bearing.uses_magnet_geometry:
        geometry = (bearing.coil_turns, bearing.pole_area, bearing.bias_current, bearing.air_gap, bearing.pole_angle_rad)
        k_i, k_s = magnetic.current_gain(*geometry), magnetic.force_slope(*geometry)
    else:
        k_i = 1.0 if bearing.ki is None else float(bearing.ki)
        k_s = 0.0 if bearing.ks is None else float(bearing.ks)
    saturation = None
    if bearing.saturation_flux_density is not None:
        saturation = magnetic.saturation_force(bearing.saturation_flux_density, bearing.pole_area, bearing.pole_angle_rad)
    sensor = _bearing_link(design, dm, bearing, bearing.sensor_offset) if bearing.sensor_offset != 0.0 else None
    check_magnet(design, index, k_i, k_s)
    actuator = Actuator(link, ctrl, current_gain=k_i, negative_stiffness=k_s,
                        amplifier_bandwidth=bearing.amplifier_bandwidth_rad_s, sensor=sensor,
                        air_gap=bearing.air_gap, bias_current=bearing.bias_current, saturation_force=saturation)
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
    from flexshaft.design import Design

    if not isinstance(design, Design):
        raise ValueError(f"build_model needs a validated flexshaft.design.Design (got {type(design).__name__}); "
                         "use load_design, loads_design or design_from_dict")
    check_problem_size(design, "model", stacklevel=4)  # the caller of flexshaft.assembly.build_model
    shaft_x, boom_x = design_mesh(design)
    dm = DofMap(shaft_x, boom_x, _fixed_dofs(design, shaft_x, boom_x))
    n = dm.size

    props = shaft_properties(design)
    check_bearing_stiffness(design, props)
    section = TubeSection(props.outer_diameter, props.inner_diameter)
    kappa = None
    if design.shaft.shear_deformation:
        nu = float(np.clip(props.youngs_modulus.real / (2 * props.shear_modulus.real) - 1, 0.0, 0.5))
        kappa = cowper_shear_coefficient(section, nu)
    Ms, Ks, Gs = shaft_element_matrices(np.diff(shaft_x), section, props.youngs_modulus, props.shear_modulus, props.density, kappa)
    sdofs = dm.element_dofs("shaft")
    parts: dict[str, list] = {"M": [(Ms, sdofs)], "K": [(Ks.real, sdofs)], "C": [], "G": [(Gs, sdofs)],
                              "shaft_loss": [(Ks.imag, sdofs)], "boom_loss": []}

    if design.tailboom is not None:
        tb = design.tailboom
        mat = design.materials[tb.material]
        eta = mat.loss_factor

        def section_at(x):
            a, b = boom_semi_axes(tb, x)
            return ellipse_section(a, b, tb.wall_thickness)

        Mb, Kb = boom_element_matrices(boom_x, section_at, mat.E * (1 + 1j * eta), mat.G * (1 + 1j * eta), mat.density)
        bdofs = dm.element_dofs("boom")
        parts["M"].append((Mb, bdofs))
        parts["K"].append((Kb.real, bdofs))
        parts["boom_loss"].append((Kb.imag, bdofs))
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
    M, K, C, G, shaft_loss, boom_loss = (scatter_blocks(parts[k], n) for k in ("M", "K", "C", "G", "shaft_loss", "boom_loss"))

    model = Model(
        dofs=dm,
        M=M.tocsr(),
        K=K.astype(float).tocsr(),
        C=C.tocsr(),
        G=G.tocsr(),
        bearings=tuple(links),
        actuators=tuple(actuators),
        shaft=props,
        speed=float(design.operating.speed_rad_s),
        power=float(design.operating.power),
        design=design,
        shaft_loss_stiffness=shaft_loss.tocsr(),
        boom_loss_stiffness=boom_loss.tocsr(),
        internal_damping=design.analysis.internal_damping,
    )
    check_finite_model(model)
    return model
