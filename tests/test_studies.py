"""Thesis chapter-3 studies: labelled outputs with units, a closed form (eq. 3.3), and the
``design_studies`` on a reduced mesh and small grids, pooled and in process, with its report
section rendered."""

from __future__ import annotations

import json

import numpy as np
import pytest

xr = pytest.importorskip("xarray")
pytest.importorskip("matplotlib")

from flexshaft.design import baseline_design, with_overrides
from flexshaft.thesis.ply_angle import DOMINANT_STRESS_CODES, ply_angle_study
from flexshaft.thesis.wall import wall_thickness_study

COARSE = {"mesh.shaft_elements": 18, "mesh.boom_elements": 12}


@pytest.fixture(scope="module")
def coarse():
    return with_overrides(baseline_design(), COARSE)


def test_ply_angle_study_is_labelled_and_peaks_at_45_degrees(coarse):
    # alpha_T = alpha_L: no thermal residual stress, whose uniform sigma2 (~0.7 MPa) would hide
    # the vanishing bending sigma2 checked below; G_LT ≪ E_L: the σ2 left at 45° scales with
    # 1 − ν_xy ≈ 8 G_LT/E_L (0.24 % here; 5 % of the neighbouring angles' σ2, 12 % with the
    # baseline's G_LT = 0.1 GPa)
    soft = with_overrides(coarse, {"materials.t700_adiprene.alpha_T": -0.4e-6, "materials.t700_adiprene.G_LT": 0.035e9})
    ds = ply_angle_study([30.0, 40.0, 45.0, 50.0, 60.0], design=soft, progress=False)
    assert ds["safety_factor"].dims == ("alpha",)
    assert ds.alpha.attrs["units"] == "deg"
    for name, units in (
        ("safety_factor", "1"),
        ("sigma1", "Pa"),
        ("sigma2", "Pa"),
        ("tau12", "Pa"),
        ("critical_ply_angle", "deg"),
        ("critical_x", "m"),
    ):
        assert ds[name].attrs["units"] == units and ds[name].attrs["long_name"]
    assert set(ds["dominant_stress"].values.astype(int)) <= set(DOMINANT_STRESS_CODES)
    # no imbalance in study 1: the total equals the static safety factor
    np.testing.assert_allclose(ds["safety_factor"], ds["safety_factor_static"])
    # the critical ply is one of the laminate's (±α)
    np.testing.assert_allclose(np.abs(ds["critical_ply_angle"].values), ds.alpha.values)
    # the cusp at 45°: scissoring of a (±45) wall is pure ply shear, σ2 from bending vanishes
    sf = ds["safety_factor"].values
    assert np.argmax(sf) == 2
    s2 = np.abs(ds["sigma2"].values)
    assert s2[2] < 0.1 * s2[[0, 1, 3, 4]].min()


def test_two_angle_map_equals_each_order_computed_on_its_own(coarse):
    """The study solves each unordered pair (α, β) once and gives its mirror the same values
    (thesis/two_angles.py); the reference builds every point's own (α/−α/β/−β)s model. Both
    orders hold the same plies (the same A matrix, the same membrane ply stresses): they differ
    by the round-off of the ply sums only (3.5e-13 measured on the tuned design), so 1e-9."""
    from flexshaft.analyses.response import static_response
    from flexshaft.analyses.shaft_strength import shaft_safety_factor
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import external_static_load, torque_load
    from flexshaft.thesis.two_angles import two_angle_layup, two_angle_study

    angles = np.array([0.0, 30.0, 55.0])
    ds = two_angle_study(angles, angles, design=coarse, progress=False)
    for i, a in enumerate(angles):
        for j, b in enumerate(angles):
            model = build_model(with_overrides(coarse, {"loads.eccentricity": 0.0, **two_angle_layup((a, b))}))
            q = static_response(model, external_static_load(model) + torque_load(model))
            own = shaft_safety_factor(model, q).safety_factor
            assert ds["safety_factor"].values[i, j] == pytest.approx(own, rel=1e-9)
            assert ds["safety_factor_static"].values[i, j] == pytest.approx(own, rel=1e-9)


def _plain_shaft(design):
    """Aluminium tube on two stiff contact bearings at its ends, no tailboom, no actuators."""
    b = design.bearings
    return with_overrides(
        design,
        {
            "shaft.x_start": b[0].x,
            "shaft.x_end": b[-1].x,
            "tailboom": None,
            "loads.point": [],
            "shaft.material": "al6061_t6",
            "shaft.layup": None,
            "bearings": [b[0].model_dump(exclude_none=True), b[-1].model_dump(exclude_none=True)],
            "mesh.shaft_elements": 40,
        },
    )


def test_wall_study_first_frequency_follows_eq_3_3():
    """At fixed D_o, a pinned-pinned isotropic tube's ω_n = A_n √(E/ρ) √(D_o² + D_i²) / L²
    (thesis eq. 3.3): the frequency falls as the wall thickens."""
    plain = _plain_shaft(baseline_design())
    walls = np.array([0.0015, 0.003, 0.006, 0.012])
    ds = wall_thickness_study(walls, design=plain, progress=False)
    f = ds["natural_frequency_1"]
    assert f.attrs["units"] == "Hz" and ds.wall_thickness.attrs["units"] == "m"
    assert np.isnan(ds["safety_factor"]).all()  # no ply strength for an isotropic shaft
    do = plain.shaft.outer_diameter
    di = do - 2 * walls
    closed = np.sqrt(do**2 + di**2)
    np.testing.assert_allclose(f.values / f.values[0], closed / closed[0], rtol=2e-3)
    assert np.all(np.diff(f.values) < 0)
    # and the absolute value: (π/L)² √(EI/ρA) / 2π, pinned-pinned Euler-Bernoulli
    mat = plain.materials["al6061_t6"]
    L = plain.shaft.length
    area = np.pi / 4 * (do**2 - di**2)
    inertia = np.pi / 64 * (do**4 - di**4)
    exact = (np.pi / L) ** 2 * np.sqrt(mat.E * inertia / (mat.density * area)) / (2 * np.pi)
    np.testing.assert_allclose(f.values, exact, rtol=5e-3)


#: A resolution of a few points per grid (CPU budget, issue 23): the report's grids cut down to
#: the angles the headline and Table 3.3 read (30°, 45°, 55°, 60°, the pair (55°, 0°)) and a
#: few walls and gains across the report's ranges. What the tests below check (the studies' labels, units and
#: dimensions, the headline numbers against the datasets, the pool against this process, the
#: report section's figures and tables, the saved files) does not depend on the grids' sizes;
#: the report's own grids run end to end in tests/test_run.py (the quick start's
#: ``flexshaft run``, whose report holds these studies at the report resolution).
TINY = {
    "angles": np.array([30.0, 45.0, 55.0, 60.0]),
    "two_angles": np.array([0.0, 45.0, 55.0]),
    "walls": np.array([2.0, 3.0, 4.0]) * 1e-3,
    "kp": np.logspace(5, 8, 4),
    "map_kp": np.logspace(5, 8, 4),
    "map_kd": np.concatenate([[0.0], np.logspace(1, 4.5, 3)]),
    "map_speeds": 40,
    "forced_speeds": 40,
    "stab_kp": np.array([3e5, 2e6]),
    "stab_kd": np.array([0.0, 300.0]),
    "stab_speeds": 6,
}


@pytest.fixture(scope="module")
def tiny_studies(coarse):
    """``design_studies`` of the coarse design in this process at :data:`TINY` (the report's
    grids otherwise), set as a resolution of its own, ``"tiny"``, for the module's tests (a
    pool's workers fork with it), and the progress labels it reported. Computed once: the pool
    test compares its pooled run with it, the section test draws it."""
    from flexshaft.thesis.design_studies import STUDY_GRIDS, design_studies

    with pytest.MonkeyPatch.context() as patch:
        patch.setitem(STUDY_GRIDS, "tiny", {**STUDY_GRIDS["report"], **TINY})
        labels = []
        # its run time is measured by benchmarks/studies_timing.py, not asserted here
        yield design_studies(coarse, "tiny", progress=labels.append), labels


def test_design_studies_on_a_worker_pool_equal_those_in_process(coarse, tiny_studies):
    """The studies as independent tasks on two forked workers (how `flexshaft run` computes
    them) give exactly the datasets and headline numbers computed in this process (the module's
    ``tiny_studies``). On grids of a few points each (an equivalence of two ways to run the
    same functions, which does not depend on the grids' sizes; each study is one task either
    way)."""
    from flexshaft.parallel.pool import worker_pool
    from flexshaft.thesis.design_studies import _DATASETS, design_studies, headline

    serial, _ = tiny_studies
    with worker_pool(2, ("xarray",)) as pool:
        if pool is None:
            pytest.skip("no fork on this platform")
        pooled = design_studies(coarse, "tiny", executor=pool)
    for name in _DATASETS:
        a, b = getattr(serial, name), getattr(pooled, name)
        assert a is not None, name  # every study ran
        assert a.identical(b), name
    ha, hb = headline(serial), headline(pooled)
    for h in (ha, hb):
        h.pop("timings_s"), h.pop("elapsed_s")
    assert ha == hb
    assert set(pooled.timings) == set(serial.timings)


def test_design_studies_render_as_the_report_section(tiny_studies, tmp_path):
    """The studies' labelled datasets and headline numbers; the report's "Design studies"
    section drawn from them (its 12 figures as PNG and SVG, Table 3.3) on a page; the data
    files written and read back. The module's ``tiny_studies``: the section draws whatever grid
    it is given (the report resolution's section: tests/test_run.py's quick start)."""
    from flexshaft.report.html import render_report
    from flexshaft.report.studies_section import design_studies_section
    from flexshaft.thesis.design_studies import headline, save_study_data

    res, labels = tiny_studies
    assert labels and labels[0].startswith("study 1")
    # labelled datasets with units
    assert res.ply_angle["safety_factor"].attrs["units"] == "1"
    assert res.two_angle["safety_factor"].dims == ("alpha", "beta")
    assert res.wall["spinup_peak_deflection"].attrs["units"] == "m"
    assert res.forced_response["shaft_peak"].dims == ("wall_thickness", "speed")
    assert res.gain.kp.attrs["units"] == "N/m"
    assert res.buckling["buckling_safety_factor"].dims == ("wall_thickness",)
    assert res.spinup_map["shaft_peak"].attrs["units"] == "m"
    assert res.surfaces["shaft_orbit"].dims == ("case", "x", "speed")
    assert res.stability_map["onset_speed"].attrs["units"] == "rad/s"
    # headline numbers: consistent with the datasets
    assert res.optimal_angle == float(res.ply_angle["safety_factor"].idxmax("alpha"))
    assert res.best_two_angle_safety_factor == pytest.approx(float(res.two_angle["safety_factor"].max()))
    assert res.best_wall == float(res.wall["safety_factor"].idxmax("wall_thickness"))
    assert res.gains_before == (1e7, 0.0)
    assert res.peak_after <= res.peak_before
    assert float(res.tuned["refined_peak"][0]) == pytest.approx(res.peak_before)
    # the refined peak is at least the sampled one
    assert res.peak_before >= float(res.tuned["shaft_peak"][0].max()) * (1 - 1e-12)
    data = headline(res)
    text = json.dumps(data, allow_nan=False)
    assert data["thesis"]["optimal_angle_deg"] == 55.0 and "peak_deflection_after_m" in text

    section = design_studies_section(res, tmp_path)
    assert len(section.figures) == 12
    for fig in section.figures:
        assert fig.path_png.is_file() and fig.path_png.with_suffix(".svg").is_file()
    captions = " ".join(t.caption for t in section.tables)
    assert "Table 3.3" in captions
    page = render_report("studies", [section])
    assert page.count("<figure") == 12 and "Design studies" in page

    paths = save_study_data(res, tmp_path / "data")
    back = xr.load_dataset(paths["spinup_map"])
    assert back["shaft_peak"].attrs["units"] == "m" and back.kd.attrs["units"] == "N s/m"
    assert json.loads(paths["headline"].read_text())["optimal_angle_deg"] == res.optimal_angle


def test_unknown_resolution_is_refused():
    from flexshaft.thesis.design_studies import design_studies

    with pytest.raises(ValueError, match="resolution"):
        design_studies(None, "huge")


def test_study_commands_write_results_and_figures(tmp_path):
    """Each `flexshaft study` command writes its netCDF and its thesis-style figure."""
    from typer.testing import CliRunner

    from flexshaft.cli import app

    runner = CliRunner()
    for args, stem in ((["ply-angle", "--step", "30"], "ply_angle"), (["two-angle", "--step", "45"], "two_angle")):
        out = tmp_path / stem
        result = runner.invoke(app, ["study", *args, "--out", str(out)])
        assert result.exit_code == 0, result.output
        assert (out / "results.nc").is_file()
        assert (out / f"{stem}.png").stat().st_size > 10_000


def test_tuned_gains_are_the_best_refined_candidate(coarse):
    """The spin-up study refines only the candidate gain pairs that can still win (a refined
    peak is never below the sampled one); refining every one of the 8 best sampled pairs by
    brute force picks the same tuned pair and the same peak, bit for bit."""
    from flexshaft.analyses.spinup import clustered_receptance, spinup_curves, spinup_speeds
    from flexshaft.assembly import build_model
    from flexshaft.assembly.model import Controller
    from flexshaft.thesis.design_studies import STUDY_GRIDS
    from flexshaft.thesis.spinup_maps import _refined_peak, spinup_studies

    model = build_model(coarse)
    grid = {**STUDY_GRIDS["report"], **TINY}
    out = spinup_studies(model, grid, None)
    before = [a.controller for a in model.actuators]
    rec = clustered_receptance(model, before, spinup_speeds(model, grid["map_speeds"]))
    sampled = out["spinup_map"]["shaft_peak"].values
    refined = {}
    for flat in np.argsort(sampled, axis=None)[:8]:
        i, j = np.unravel_index(int(flat), sampled.shape)
        pair = (float(grid["map_kp"][i]), float(grid["map_kd"][j]))
        law = [Controller.pd(*pair)] * rec.n_actuators
        curve = spinup_curves(rec, law).shaft_peak
        refined[pair] = _refined_peak(model, law, rec.speeds, curve)[0]
        assert refined[pair] >= curve.max()
    best = min(refined, key=refined.get)
    assert out["gains_after"] == best
    assert out["peak_after"] == refined[best]


def test_the_two_angle_figure_marks_the_laminate_the_study_names():
    """The two-angle map is symmetric in α ↔ β, so its best plies tie exactly in both orders:
    ``best_pair`` names the larger angle first, and the figure marks that laminate when given
    it (the report and ``flexshaft study two-angle`` pass it), not the first of the tie in
    (α, β) order, which the figure marks by default. A hand-made symmetric map, R = 58 at
    (30, 55) and (55, 30)."""
    import matplotlib.pyplot as plt

    from flexshaft.plot.studies import two_angle_figure
    from flexshaft.thesis.two_angles import best_pair

    angles = np.array([0.0, 30.0, 55.0, 90.0])
    sf = np.array([[5.0, 10.0, 20.0, 3.0], [10.0, 40.0, 58.0, 7.0], [20.0, 58.0, 30.0, 9.0], [3.0, 7.0, 9.0, 1.0]])
    assert np.array_equal(sf, sf.T)
    i, j = best_pair(sf, angles, angles)
    assert (angles[i], angles[j]) == (55.0, 30.0)

    def marked(fig) -> list[str]:
        labels = [line.get_label() for line in fig.axes[0].get_lines() if line.get_label().startswith("best")]
        plt.close(fig)
        return labels

    assert marked(two_angle_figure(angles, angles, sf, best=(angles[i], angles[j]))) == [
        "best (55/−55/30/−30)s: R = 58"
    ]
    assert marked(two_angle_figure(angles, angles, sf)) == ["best (30/−30/55/−55)s: R = 58"]


@pytest.mark.parametrize("pair", [(55.0, 30.0), (45.0, 0.0), (0.0, 60.0), (90.0, 15.0)])
def test_the_two_angle_studys_layup_name_is_a_balanced_symmetric_laminate(pair):
    """The two-angle study's best layup, by name: (α/−α/β/−β)s. Balanced (every ±θ ply pair
    has an equal and opposite partner, 0° and 90° plies their own) and symmetric: the
    laminate's A₁₆ = A₂₆ = 0, since Q̄₁₆(θ) and Q̄₂₆(θ) are odd in θ and vanish at 0° and 90°
    (derived), and B = 0. Parsed by the design file's own grammar."""
    from flexshaft.design.layup import parse_layup
    from flexshaft.thesis.design_studies import two_angle_name

    angles = parse_layup(two_angle_name(pair))
    assert list(angles) == list(angles)[::-1]  # symmetric about the mid-plane
    half = list(angles)[: len(angles) // 2]
    assert sorted(abs(a) for a in half) == sorted([pair[0], pair[0], pair[1], pair[1]])
    for theta in {abs(a) for a in half if abs(a) not in (0.0, 90.0)}:
        assert half.count(theta) == half.count(-theta)  # balanced
