"""The ``flexshaft compare`` report's tables and mass figure say what each design's run found,
under its own design and in its own column (report/compare.py, plot/compare.py, cli/compare.py):
the verdict table's status of a requirement a design does not evaluate, the separation margin in
percent, the metal-tube table's yield and buckling columns per tube, the coupling table's moment
and torque columns, the run notes under their design, the mass bars named after their design and
the default output folder named A-vs-B.

References (hand-written docs and arithmetic by hand, on stand-in results with distinct values per
design, per tube and per column, so a value from the wrong place is seen):

* docs/requirements.md, "The checks": "a status (`pass`, `fail` or `not evaluated`)" — a check a
  design does not evaluate is not a pass;
* the module docstring: "converts SI to engineering units (rpm, mm, °C, degrees, %)", and
  docs/segmented-driveline.md's comparison table gives the separation margin in percent
  ("19.0 % (14.8 %)"): a margin of 0.254 reads 25.4 %;
* docs/segmented-driveline.md: "Each isotropic segment also gets its torsional-buckling factor
  T_cr/T between its ends", and the yield factor n_y and the fatigue factor n_f are two criteria
  (eqs. 7-7 and 7-16 there);
* docs/segmented-driveline.md: "The coupling carries the moment k_ang α ... the axial force
  k_ax Δu and the torque k_t Δθ": the moment column is k_ang α computed here by hand;
* plot/compare.py's docstring: "Design A is drawn in blue, design B in orange, in the order of
  the mapping"; the bar total is the sum of its parts, added by hand;
* the ``--out`` help of ``flexshaft compare``: "Default: A-vs-B-compare (the design files'
  names)".

Figures are replaced by stubs except the mass figure (Agg, drawn). CPU about 0.1 s in all.
"""

from __future__ import annotations

import importlib
import math
from pathlib import Path
from types import SimpleNamespace as NS

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from flexshaft.comparison import Metric  # noqa: E402
from flexshaft.plot.compare import mass_breakdown_figure  # noqa: E402
from flexshaft.report import compare  # noqa: E402
from tests.test_compare_report_columns_reference import _comparison  # noqa: E402

# the package re-exports the command function under the module's name: the module itself
cli_compare = importlib.import_module("flexshaft.cli.compare")


def _stub_figures(monkeypatch):
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    for name in ("safety_factor_overlay_figure", "static_deflection_overlay_figure"):
        monkeypatch.setattr(compare, name, lambda *args, **kwargs: None)


def _column(table, name):
    return [row[list(table.columns).index(name)] for row in table.rows]


def test_a_requirement_not_evaluated_is_not_shown_as_pass():
    """Design A (a metal shaft) has no plies: its Tsai-Wu check is "not evaluated"; design B's
    passes. The A status column reads "not evaluated", B's "PASS" (docs/requirements.md: the
    three statuses are distinct)."""
    checks = {
        0: NS(
            title="ply strength",
            kind="factor",
            value=None,
            margin=None,
            status="not evaluated",
            lower_bound=False,
            limit=1.5,
            sense="at least",
            location={},
            note="no laminated segment",
        ),
        1: NS(
            title="ply strength",
            kind="factor",
            value=2.0,
            margin=0.5,
            status="pass",
            lower_bound=False,
            limit=1.5,
            sense="at least",
            location={"station": 1.0},
            note="",
        ),
    }
    comparison = _comparison([])
    comparison.check_keys = ["tsai_wu"]
    comparison.check = lambda key, d: checks[d]
    (table,) = compare._verdict_section(comparison).tables
    assert _column(table, "A status") == ["not evaluated"]
    assert _column(table, "B status") == ["PASS"]
    assert _column(table, "A value") == ["—"]  # nothing measured: no value


def test_separation_margin_reads_in_percent():
    """A separation margin of 0.254 (SI: a fraction) reads 25.4 % (0.254 × 100, by hand), B's
    0.19 reads 19.0 %, in the key-numbers table as in docs/segmented-driveline.md."""
    assert compare.format_metric("separation", "1", 0.254) == "25.4 %"
    metric = Metric("separation", "smallest API 684 separation margin", "1", (0.254, 0.19), ("", ""))
    table = compare._metrics_table(_comparison([metric]))
    assert table.rows[0][1:3] == ["25.4 %", "19.0 %"]


def _metal(buckling):
    worst = {
        ("fatigue", "tube_1"): {
            "safety_factor": 6.8,
            "station": 1.2,
            "sigma_alternating": 40e6,
            "sigma_mean": 10e6,
            "tau_mean": 5e6,
        },
        ("fatigue", "tube_2"): {
            "safety_factor": 9.1,
            "station": 3.4,
            "sigma_alternating": 30e6,
            "sigma_mean": 20e6,
            "tau_mean": 6e6,
        },
        ("yield", "tube_1"): {"safety_factor": 12.0, "station": 1.1},
        ("yield", "tube_2"): {"safety_factor": 15.0, "station": 3.3},
    }
    return NS(
        evaluated=True,
        segments=["tube_1", "tube_2"],
        worst=lambda criterion, segment: worst[(criterion, segment)],
        buckling=buckling,
        along_shaft=lambda: (np.array([0.0, 1.0]), np.array([7.0, 8.0])),
    )


def test_metal_tube_table_yield_and_buckling_per_tube(monkeypatch, tmp_path):
    """Each tube's row: its fatigue n_f with its σ_a, σ_m, τ_m in MPa (Pa / 1e6, by hand: 40, 10,
    5 for tube_1; 30, 20, 6 for tube_2), its own yield n_y (12 and 15, not the fatigue 6.8 and
    9.1) and its own buckling T_cr/T (5.96 and 7.5; the buckling list is stored tube_2 first, so
    matching by tube counts)."""
    _stub_figures(monkeypatch)
    buckling = [NS(segment="tube_2", safety_factor=7.5), NS(segment="tube_1", safety_factor=5.96)]
    runs = tuple(
        NS(
            strength_total=None,
            metal_strength=metal,
            points=(),
            model=NS(design=NS(requirements=NS(min_safety_factor=1.5))),
        )
        for metal in (_metal(buckling), None)
    )
    (table,) = compare._strength_section(_comparison([], runs=runs), tmp_path).tables
    assert table.caption.startswith("A:")  # B has no metal tube: no table for it
    assert _column(table, "segment") == ["tube_1", "tube_2"]
    assert _column(table, "fatigue n_f") == [6.8, 9.1]
    # One division each (Pa / 1e6): at most an ulp; measured error 0, so rel 1e-12 is ample.
    assert _column(table, "σ_a [MPa]") == pytest.approx([40.0, 30.0], rel=1e-12)
    assert _column(table, "σ_m [MPa]") == pytest.approx([10.0, 20.0], rel=1e-12)
    assert _column(table, "τ_m [MPa]") == pytest.approx([5.0, 6.0], rel=1e-12)
    assert _column(table, "yield n_y") == [12.0, 15.0]
    assert _column(table, "buckling T_cr/T") == [5.96, 7.5]


def test_coupling_table_moment_is_k_alpha_and_torque_its_own(monkeypatch, tmp_path):
    """The stand-in's static moment, 12 N m (distinct from the 150 N m torque), is in the
    'moment k α' column and the torque it transmits in the 'torque' column: the columns are
    checked, not the product's k α (the stand-in hands the moment over). The static angle
    0.01 rad reads 0.01 × 180/π ° (0.573°)."""
    _stub_figures(monkeypatch)

    def run(cm):
        x = np.array([0.0, 1.0, 2.0])
        dofs = NS(shaft_x=x, values=lambda q, part, name: np.zeros(3))
        return NS(model=NS(dofs=dofs, couplings=[NS(x=1.0)]), static_displacement=np.zeros(6), coupling_misalignment=cm)

    cm = NS(
        names=["coupling_1"],
        stations=[1.0],
        static_angle=[0.01],
        dynamic_angle=[0.002],
        allowable_angle=np.array([math.radians(0.5)]),
        static_moment=[12.0],
        axial_force=[30.0],
        torque=[150.0],
    )
    (table,) = compare._deflection_section(_comparison([], runs=(run(cm), run(None))), tmp_path).tables
    # The moment is passed through; the angle is one multiplication and one division (a few ulp
    # at most): rel 1e-12 is ample, measured error 0.
    assert _column(table, "moment k α [N m]") == pytest.approx([12.0], rel=1e-12)
    assert _column(table, "torque [N m]") == [150.0]
    assert _column(table, "axial force [N]") == [30.0]
    assert _column(table, "static angle [°]") == pytest.approx([0.01 * 180.0 / math.pi], rel=1e-12)


def test_run_notes_under_their_own_design():
    """A's note (no couplings) under A, B's (no shaft temperature model) under B."""
    runs = tuple(
        NS(notes=[note], model=NS(design=NS(name=name)), verdict=NS(summary="PASS"))
        for name, note in (("fmc", "no couplings: coupling angle not evaluated"), ("alu", "temperature not modelled"))
    )
    (table,) = compare._notes_section(_comparison([], runs=runs)).tables
    assert table.rows == [["A", "no couplings: coupling angle not evaluated"], ["B", "temperature not modelled"]]


def test_mass_bars_named_after_their_design():
    """A: 10 + 4 = 14.0 kg, B: 30 + 0 = 30.0 kg (by hand); bar 0 is A's (the mapping's order),
    named A and topped by 14.0 kg, bar 1 is B's."""
    fig = mass_breakdown_figure({"A": {"tubes": 10.0, "actuators": 4.0}, "B": {"tubes": 30.0, "actuators": 0.0}})
    try:
        ax = fig.axes[0]
        names = {round(float(x)): t.get_text() for x, t in zip(ax.get_xticks(), ax.get_xticklabels())}
        totals = {round(t.xy[0]): t.get_text() for t in ax.texts}
        assert names == {0: "A", 1: "B"}
        assert totals == {0: "14.0 kg", 1: "30.0 kg"}
    finally:
        plt.close(fig)


def test_default_folder_is_a_vs_b():
    """`flexshaft compare fmc.toml alu.toml`: the --out help's default "A-vs-B-compare" from the
    files' names is fmc-vs-alu-compare; the embedded pair's is flexshaft-compare."""
    assert cli_compare._default_folder((Path("fmc.toml"), Path("alu.toml"))) == Path("fmc-vs-alu-compare")
    assert cli_compare._default_folder((None, None)) == Path("flexshaft-compare")


def test_missing_mass_note_names_only_the_design_missing_one(monkeypatch, tmp_path):
    """comparison.py's docstring: "a part without a mass counts 0 kg and is listed in
    Inventory.mass_not_given". A lists its dampers there, B lists nothing: the parts section
    notes A's dampers and says nothing of B."""
    monkeypatch.setattr(compare, "save_figure", lambda fig, folder, stem: {"png": Path(folder) / f"{stem}.png"})
    monkeypatch.setattr(compare, "mass_breakdown_figure", lambda *args: None)
    comparison = _comparison([])
    a, b = comparison.inventories
    comparison.inventories = (NS(**{**vars(a), "mass_not_given": ["dampers"]}), b)
    paragraphs = compare._parts_section(comparison, tmp_path).paragraphs
    notes = [p for p in paragraphs if "without a mass" in p]
    assert len(notes) == 1
    assert notes[0].startswith("A:") and "dampers" in notes[0]


def _check(status, station, note):
    return NS(
        title="spin-up orbit",
        kind="length",
        value=6e-3,
        margin=-1e-3,
        status=status,
        lower_bound=False,
        limit=5e-3,
        sense="at most",
        location={"station": station},
        note=note,
    )


def test_where_column_locates_a_failing_check():
    """docs/requirements.md: every check has "a status ... and a location". A fails at x = 1.25 m,
    B passes at x = 3.5 m: the 'where (A / B)' cell gives both stations (1.25 m and 3.50 m), not
    A's free-text note."""
    checks = {0: _check("fail", 1.25, "A's note"), 1: _check("pass", 3.5, "B's note")}
    comparison = _comparison([])
    comparison.check_keys = ["spinup_deflection"]
    comparison.check = lambda key, d: checks[d]
    (table,) = compare._verdict_section(comparison).tables
    (where,) = _column(table, "where (A / B)")
    first, second = where.split(" / ")
    assert "1.25 m" in first and "note" not in first
    assert "3.50 m" in second and "note" not in second


def test_command_verdict_lines_name_their_own_design(capsys, tmp_path):
    """The command's last lines print each design's verdict summary after its own label: A's run
    fails, B's passes (distinct summaries), so 'A: ' precedes A's summary."""
    runs = tuple(
        NS(model=NS(design=NS(name=name)), verdict=NS(summary=summary, passed=passed))
        for name, summary, passed in (("fmc", "FAIL, 1 of 13 fails", False), ("alu", "PASS, 8 pass", True))
    )
    result = NS(labels=("A", "B"), runs=runs, metrics=list)
    cli_compare._print_comparison(result, tmp_path / "report.html", 1.0, (Path("fmc.toml"), Path("alu.toml")))
    lines = capsys.readouterr().out.splitlines()
    assert "A: FAIL, 1 of 13 fails" in lines
    assert "B: PASS, 8 pass" in lines
