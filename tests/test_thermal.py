"""Thermal analysis: finite-difference shaft, heat generation, correlations, tailboom balance,
self-heating fixed point. Each test names its independent reference and why its tolerance."""

from __future__ import annotations

import math

import numpy as np
import pytest

import flexshaft as fs
from flexshaft.thermal.air import air_properties
from flexshaft.thermal.analysis import shaft_thermal
from flexshaft.thermal.correlations import (
    churchill_bernstein_nusselt,
    churchill_chu_nusselt,
    hilpert_nusselt,
    rotating_cylinder_nusselt,
    rotating_cylinder_nusselt_becker,
)
from flexshaft.thermal.environment import ThermalEnvironment
from flexshaft.thermal.heat import (
    harmonic_loss_power,
    heat_sources,
    shaft_loss_matrices,
    split_whirl,
    static_circular_amplitude,
)
from flexshaft.thermal.selfheating import MatrixTemperatureLaw, fixed_point, self_heating
from flexshaft.thermal.shaft import solve_shaft_temperature
from flexshaft.thermal.tailboom import boom_equivalent_diameter, ellipse_perimeter, tailboom_temperature


@pytest.fixture(scope="module")
def model():
    return fs.build_model(fs.baseline_design())


# ------------------------------------------------------------------ finite-difference shaft
FIN = {
    "k": 167.0,
    "A": 9.3e-4,
    "P": math.pi * 0.1016,
    "h": 5.0,
    "L": 2.0,
    "q": 2.0,
    "T_inf": 316.0,
    "T_end": 320.0,
}  # m L = 6.4


def _fin_exact(x):
    """Fin with uniform generation q' [W/m], ends at T_end: θ'' − m²θ + q'/(kA) = 0."""
    m = math.sqrt(FIN["h"] * FIN["P"] / (FIN["k"] * FIN["A"]))
    theta_p = FIN["q"] / (FIN["h"] * FIN["P"])
    theta_b = FIN["T_end"] - FIN["T_inf"]
    return FIN["T_inf"] + theta_p + (theta_b - theta_p) * np.cosh(m * (x - FIN["L"] / 2)) / np.cosh(m * FIN["L"] / 2)


def _fin_fd(n):
    x = np.linspace(0.0, FIN["L"], n + 1)
    r = solve_shaft_temperature(
        x, FIN["q"] * np.diff(x), FIN["k"], FIN["A"], FIN["P"], FIN["h"], FIN["T_inf"], (FIN["T_end"], FIN["T_end"])
    )
    return x, r


def test_fd_matches_cosh_fin_solution_with_second_order_convergence():
    # Reference: the analytic fin solution with uniform generation and fixed end temperatures
    # (Incropera §3.6 plus a particular solution). The observed order on successive halvings must
    # be 2 within ±0.05 (asymptotic range from n = 10 for m L = 6.4).
    errors = []
    ns = [10, 20, 40, 80, 160]
    for n in ns:
        x, r = _fin_fd(n)
        errors.append(np.max(np.abs(r.temperature - _fin_exact(x))))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(np.abs(orders - 2.0) < 0.05), orders
    # and the finest mesh is accurate to a few mK on a 5 K rise
    assert errors[-1] < 2e-3 * (_fin_exact(np.array([FIN["L"] / 2]))[0] - FIN["T_inf"])


def test_energy_balance_closes_on_a_nonuniform_mesh():
    # Generated = convected + conducted out of the ends, by construction of the finite volumes:
    # only round-off may remain (1e-9 relative).
    rng = np.random.default_rng(1)
    x = np.cumsum(np.r_[0.0, rng.uniform(0.05, 0.4, 40)])
    P = rng.uniform(0.0, 5.0, 40)
    r = solve_shaft_temperature(x, P, 3.0, 1e-3, 0.3, 25.0, 310.0, (315.0, 305.0))
    assert abs(r.balance_error) < 1e-9


def test_energy_balance_closes_on_the_baseline(model):
    for loss in ("thesis", "rotating"):
        r = shaft_thermal(model, loss_model=loss)
        assert r.sources.total.sum() > 0
        assert abs(r.temperature.balance_error) < 1e-9


def test_zero_loss_factor_stays_at_the_boom_temperature():
    # A shaft with no hysteretic loss generates no heat, so it sits at its air/end temperature.
    design = fs.with_overrides(
        fs.baseline_design(),
        {
            "materials.t700_adiprene.loss_E_L": 0.0,
            "materials.t700_adiprene.loss_E_T": 0.0,
            "materials.t700_adiprene.loss_G_LT": 0.0,
        },
    )
    lossless = fs.build_model(design)
    for loss in ("thesis", "rotating"):
        r = shaft_thermal(lossless, loss_model=loss, air_temperature=317.0)
        assert np.all(r.sources.total == 0.0)
        assert np.max(np.abs(r.temperature.temperature - 317.0)) < 1e-10


# ------------------------------------------------------------------ heat generation
def _random_spd(rng, n=12):
    A = rng.normal(size=(n, n))
    return A @ A.T


def test_harmonic_loss_power_equals_time_averaged_work():
    # Reference: direct time average of ẋᵀ f over one period, f = Re((K' + iK'') X e^{iωt}).
    rng = np.random.default_rng(2)
    Kp, Kpp = _random_spd(rng), 0.05 * _random_spd(rng)
    X = rng.normal(size=12) + 1j * rng.normal(size=12)
    omega = 37.0
    t = np.linspace(0, 2 * np.pi / omega, 4096, endpoint=False)
    e = np.exp(1j * omega * t)
    xdot = (1j * omega * X[:, None] * e).real
    force = ((Kp + 1j * Kpp) @ X[:, None] * e).real
    direct = np.mean(np.sum(xdot * force, axis=0))
    assert harmonic_loss_power(X[None], Kpp[None], omega)[0] == pytest.approx(direct, rel=1e-10)


def _rotating_frame_power(Kpp, X, Xs, Omega, N=64):
    """Reference: sample the element DOFs over one revolution, rotate the lateral pairs (v, w)
    and (γ, −β) into the frame spinning with the shaft, Fourier-analyse and sum (kΩ/2)·X_kᴴK''X_k."""
    t = np.arange(N) * 2 * np.pi / (Omega * N)
    q = (X[:, None] * np.exp(1j * Omega * t)).real + Xs[:, None]
    c, s = np.cos(Omega * t), np.sin(Omega * t)
    r = q.copy()
    for node in (0, 6):
        v, w, b, g = node + 1, node + 2, node + 4, node + 5
        r[v], r[w] = q[v] * c + q[w] * s, -q[v] * s + q[w] * c
        a_, bb = q[g], -q[b]
        r[g], r[b] = a_ * c + bb * s, -(-a_ * s + bb * c)
    F = np.fft.fft(r, axis=1) / N
    return sum(0.5 * k * Omega * np.real(np.conj(2 * F[:, k]) @ Kpp @ (2 * F[:, k])) for k in range(1, N // 2))


def test_rotating_frame_loss_matches_a_direct_rotating_frame_analysis(model):
    # Reference: the same element motion transformed into the rotating frame in the time domain.
    Kpp = shaft_loss_matrices(model)[5]
    rng = np.random.default_rng(3)
    X = (rng.normal(size=12) + 1j * rng.normal(size=12)) * 1e-4
    Xs = rng.normal(size=12) * 1e-4
    Omega = model.speed
    axial, fwd, bwd = split_whirl(X)
    assert np.allclose(axial + fwd + bwd, X)
    ours = (
        harmonic_loss_power(axial[None], Kpp[None], Omega)
        + harmonic_loss_power(bwd[None], Kpp[None], 2 * Omega)
        + harmonic_loss_power(static_circular_amplitude(Xs)[None], Kpp[None], Omega)
    )[0]
    assert ours == pytest.approx(_rotating_frame_power(Kpp, X, Xs, Omega), rel=1e-9)
    # forward synchronous whirl does not cycle the material
    assert harmonic_loss_power(split_whirl(fwd)[2][None], Kpp[None], 2 * Omega)[0] == pytest.approx(0.0, abs=1e-18)


def test_static_deflection_in_rotation_dissipates_twice_the_planar_vibration(model):
    # Every fibre of a rotating bent shaft passes the extreme strain; a planar vibration of the
    # same amplitude cycles a fibre at angle ψ by |cos ψ| only: mean square ratio 2.
    Kpp = shaft_loss_matrices(model)[3]
    Xs = np.zeros(12)
    Xs[[1, 2, 4, 5, 7, 8, 10, 11]] = np.random.default_rng(4).normal(size=8) * 1e-3
    planar = harmonic_loss_power(Xs[None], Kpp[None], 1.0)[0]
    rotating = harmonic_loss_power(static_circular_amplitude(Xs)[None], Kpp[None], 1.0)[0]
    assert rotating == pytest.approx(2 * planar, rel=1e-12)


def test_rotating_model_sees_no_heat_from_a_pure_forward_synchronous_whirl(model):
    Kpp = shaft_loss_matrices(model)
    q = np.zeros(model.dofs.size, dtype=complex)
    nodes = np.arange(model.dofs.n_shaft_nodes)
    shape = np.sin(np.pi * (model.dofs.shaft_x - model.dofs.shaft_x[0]) / np.ptp(model.dofs.shaft_x))
    q[model.dofs.shaft(nodes, "v")] = 1e-3 * shape
    q[model.dofs.shaft(nodes, "w")] = -1j * 1e-3 * shape
    slope = np.gradient(1e-3 * shape, model.dofs.shaft_x)
    q[model.dofs.shaft(nodes, "gamma")] = slope
    q[model.dofs.shaft(nodes, "beta")] = -(-1j * slope)
    zero = np.zeros(model.dofs.size)
    rot = heat_sources(model, "rotating", q, zero, Kpp)
    thesis = heat_sources(model, "thesis", q, zero, Kpp)
    assert rot.total.sum() < 1e-12 * thesis.total.sum()


# ------------------------------------------------------------------ correlations and air
#: Hilpert's constants, Incropera & DeWitt Table 7.2 (Nu = C Re^m Pr^(1/3)): (Re_min, Re_max, C, m).
#: Typed here from the table as reproduced in independent public implementations (the book
#: itself was not at hand), not from flexshaft's own table.
HILPERT_PUBLISHED = (
    (0.4, 4.0, 0.989, 0.330),
    (4.0, 40.0, 0.911, 0.385),
    (40.0, 4000.0, 0.683, 0.466),
    (4000.0, 40000.0, 0.193, 0.618),
    (40000.0, 400000.0, 0.027, 0.805),
)


def test_hilpert_incropera_example():
    # Incropera & DeWitt Example 7.4 (6th ed.; 7.3 in later): Re = 6071, Pr = 0.70,
    # Hilpert C = 0.193, m = 0.618 → Nu = 37.3 (book to 3 figures: rel 2e-3).
    nu = hilpert_nusselt(6071, 0.70)
    assert nu.value == pytest.approx(37.3, rel=2e-3) and nu.in_range
    # every row of the published table, inside its Reynolds range (round-off: 1e-12)
    for lo, hi, C, m in HILPERT_PUBLISHED:
        for Re in (1.01 * lo, math.sqrt(lo * hi), 0.99 * hi):
            assert hilpert_nusselt(Re, 0.7).value == pytest.approx(C * Re**m * 0.7 ** (1 / 3), rel=1e-12), Re
    out = hilpert_nusselt(5.2e5, 0.71)
    assert not out.in_range and "outside" in out.note


def test_churchill_bernstein_and_churchill_chu_published_examples():
    # Churchill-Bernstein, same Incropera example: Nu = 40.6 (3 figures).
    assert churchill_bernstein_nusselt(6071, 0.70).value == pytest.approx(40.6, rel=2e-3)
    # Churchill-Chu, Bergman et al. 6th ed. Example 9.2 as quoted in ht: Nu = 139 at
    # Pr = 0.69, Gr = 2.63e9 (3 figures).
    assert churchill_chu_nusselt(0.69, 2.63e9).value == pytest.approx(139.0, rel=2e-3)


def test_rotating_cylinder_correlations():
    # Kendoush's form as the thesis writes it (eq. 2.63): h = (k_air/D_o) C √(Re Pr), i.e. Nu
    # grows as the square root of Re and of Pr. The constant C did not survive the thesis's text
    # extraction and no copy of Kendoush (1996) or Becker (1963) was at hand, so neither
    # correlation's constant is verified here (the module docstring says so for Kendoush);
    # what the sources fix is checked: the thesis's scaling, and Becker's stated validity range.
    kendoush = [rotating_cylinder_nusselt(Re, Pr, "kendoush").value for Re, Pr in ((1e4, 0.7), (4e4, 0.7), (1e4, 2.8))]
    assert kendoush[1] == pytest.approx(2 * kendoush[0], rel=1e-12)
    assert kendoush[2] == pytest.approx(2 * kendoush[0], rel=1e-12)
    assert rotating_cylinder_nusselt_becker(4.2e5, 0.7).in_range
    assert not rotating_cylinder_nusselt_becker(5e5, 0.7).in_range
    assert rotating_cylinder_nusselt(1e5, 0.7, "becker") == rotating_cylinder_nusselt_becker(1e5, 0.7)
    with pytest.raises(ValueError, match="becker"):
        rotating_cylinder_nusselt(1e5, 0.7, "nope")


@pytest.mark.parametrize(
    "T, mu, k, nu, Pr",
    [
        (250.0, 159.6e-7, 22.3e-3, 11.44e-6, 0.720),
        (300.0, 184.6e-7, 26.3e-3, 15.89e-6, 0.707),
        (350.0, 208.2e-7, 30.0e-3, 20.92e-6, 0.700),
        (400.0, 230.1e-7, 33.8e-3, 26.41e-6, 0.690),
    ],
)
def test_air_properties_against_incropera_table_a4(T, mu, k, nu, Pr):
    # μ, k, Pr within 1 %; ν within 2.5 % because the table's density sits 1.3-1.9 % below the
    # ideal gas at 1 atm used here.
    air = air_properties(T)
    assert air.viscosity == pytest.approx(mu, rel=0.01)
    assert air.conductivity == pytest.approx(k, rel=0.01)
    assert air.prandtl == pytest.approx(Pr, rel=0.01)
    assert air.kinematic_viscosity == pytest.approx(nu, rel=0.025)


# ------------------------------------------------------------------ tailboom
def test_ellipse_perimeter_against_quadrature():
    from scipy.integrate import quad

    a, b = 0.375, 0.3
    exact = (
        4 * a * quad(lambda t: math.sqrt(1 - (1 - (b / a) ** 2) * math.sin(t) ** 2), 0, math.pi / 2, epsabs=1e-14)[0]
    )
    assert ellipse_perimeter(a, b) == pytest.approx(exact, rel=1e-9)


@pytest.mark.parametrize("condition", ["hover", "parked"])
def test_tailboom_balance_closes_and_no_sun_no_gradient_stays_at_ambient(condition):
    D = boom_equivalent_diameter(fs.baseline_design().tailboom)
    r = tailboom_temperature(condition, D)
    assert r.absorbed_solar == pytest.approx(r.net_radiation + r.convection, rel=1e-9)
    # no sun and a sky at the air temperature: the skin sits at ambient
    env = ThermalEnvironment(solar_fraction=0.0, sky_temperature=300.0, ambient_temperature=300.0)
    assert tailboom_temperature(condition, D, env).temperature == pytest.approx(300.0, abs=1e-6)


def test_baseline_tailboom_temperatures_are_the_thesis_findings():
    # The thesis's Table 2.1 results, 44 °C hovering and 89 °C parked (stated to the degree:
    # ±0.5 °C). The baseline's sunlit share is calibrated to the 89 °C parked, so that one only
    # checks the calibration holds; the 44 °C hover is then a prediction (ambient from
    # Swinbank's clear sky, Hilpert as in the thesis's eq. 2.57). The hover downwash is the
    # momentum-theory closed form V = √(W/(2ρπR²)) (DESIGN.md §2.8) with the thesis's Table 2.1
    # rotorcraft, m_rc = 6838 kg, R_r = 7.315 m, and ρ = 1.225 kg/m³ (DESIGN.md §5).
    from flexshaft.thermal.options import thermal_options

    design = fs.baseline_design()
    options = thermal_options(design.thermal)
    D = boom_equivalent_diameter(design.tailboom)
    hover = tailboom_temperature("hover", D, options.environment, options.boom_convection)
    parked = tailboom_temperature("parked", D, options.environment, options.boom_convection)
    assert hover.celsius == pytest.approx(44.0, abs=0.5)
    assert parked.celsius == pytest.approx(89.0, abs=0.5)
    downwash = math.sqrt(6838.0 * 9.80665 / (2 * 1.225 * math.pi * 7.315**2))
    assert hover.velocity == pytest.approx(downwash, rel=1e-12)
    assert hover.nusselt.method == "hilpert" and not hover.nusselt.in_range  # Re 5.3e5 > 4e5, flagged


# ------------------------------------------------------------------ self-heating
def test_fixed_point_linear_case_converges_to_the_analytic_answer_or_reports_runaway():
    # T = T∞ + R P0 (1 + a (T − T∞)) has the fixed point T∞ + R P0 / (1 − a R P0) when the loop
    # gain g = a R P0 < 1, none above T∞ otherwise. Picard error shrinks by g per step.
    T_inf, R, P0 = 300.0, 2.0, 5.0
    for gain in (0.2, 0.5, 0.8):
        a = gain / (R * P0)
        fp = fixed_point(
            lambda T, a=a: T_inf + R * P0 * (1 + a * (T - T_inf)), [T_inf], 1000.0, tol=1e-10, max_iter=500
        )
        assert fp.converged
        assert fp.temperature[0] == pytest.approx(T_inf + R * P0 / (1 - gain), abs=1e-8)
    a = 1.1 / (R * P0)
    fp = fixed_point(lambda T: T_inf + R * P0 * (1 + a * (T - T_inf)), [T_inf], 400.0, max_iter=500)
    assert fp.status == "runaway"
    # a fixed point above the allowable temperature is also runaway (none below it)
    a = 0.9 / (R * P0)  # fixed point at 400 K
    fp = fixed_point(lambda T: T_inf + R * P0 * (1 + a * (T - T_inf)), [T_inf], 380.0, max_iter=500)
    assert fp.status == "runaway"


def test_fixed_point_on_the_finite_difference_model_with_linear_heat():
    # Per element: P_e(T) = P0_e (1 + a (T_e − T∞)). The FD model is linear, T_el = T∞ + S P, so
    # the fixed point is the solution of (I − a S diag(P0)) θ = S P0 (θ = T_el − T∞).
    x = np.linspace(0, 7.0, 31)
    P0 = np.linspace(1.0, 3.0, 30)
    args = (3.5, 9.3e-4, 0.32, 20.0, 316.0)

    def el(P):
        return solve_shaft_temperature(x, P, *args).element_temperature

    S = np.column_stack([el(np.eye(30)[e]) - 316.0 for e in range(30)])
    a = 0.05
    exact = 316.0 + np.linalg.solve(np.eye(30) - a * S @ np.diag(P0), S @ P0)
    fp = fixed_point(lambda T: el(P0 * (1 + a * (T - 316.0))), np.full(30, 316.0), 500.0, tol=1e-11, max_iter=500)
    assert fp.converged
    assert np.max(np.abs(fp.temperature - exact)) < 1e-9


def test_matrix_law_is_identity_at_reference_and_softens_when_hot(model):
    law = MatrixTemperatureLaw()
    lam = model.shaft.laminate.lamina
    same = law.lamina(lam, law.reference_temperature)
    assert same.E_T == pytest.approx(lam.E_T) and same.G_LT == pytest.approx(lam.G_LT) and same.E_L == lam.E_L
    hot = law.lamina(lam, law.reference_temperature + 40.0)
    assert hot.E_T.real == pytest.approx(lam.E_T.real / math.e)
    assert hot.E_T.imag / hot.E_T.real > lam.E_T.imag / lam.E_T.real


def test_baseline_self_heating_has_an_equilibrium_and_large_loads_run_away(model):
    ok = self_heating(model, loss_model="rotating")
    assert ok.status == "converged" and ok.margin > 50.0
    # loads ×500: the heat grows as the square (×2.5e5) and the matrix softens and dissipates more
    # as it warms; no equilibrium below the allowable (the baseline converges at ×150)
    hot = self_heating(model, loss_model="rotating", imbalance_scale=500.0, static_scale=500.0)
    assert hot.status == "runaway" and hot.margin < 0


def test_thermal_schema_defaults_equal_the_runtime_defaults():
    from flexshaft.design.thermal_schema import Thermal
    from flexshaft.thermal.options import ThermalOptions, environment_from, matrix_law_from, thermal_options

    assert environment_from(Thermal()) == ThermalEnvironment()
    assert matrix_law_from(Thermal()) == MatrixTemperatureLaw()
    assert thermal_options(Thermal()) == ThermalOptions()
    # the shipped baseline's [thermal] table is the schema's default table
    assert fs.baseline_design().thermal == Thermal()
    with pytest.raises(Exception, match="emissivity"):
        Thermal(emissivity=1.5)
