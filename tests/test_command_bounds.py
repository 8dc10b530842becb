"""The work of every command is bounded before it computes (issue 27, "Bound the work of every
command"): options and design together, refused with the numbers and what to change.

The hangs the issue reproduced at the CLI's own limits are refused up front (exit 2, naming the
options) in well under a second of work: a monkeypatched analysis that fails if called proves
that nothing was computed. The estimates' constants and the commands at their documented
maxima are measured in docs/limits.md (benchmarks/command_limits.py).
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flexshaft.cli import app

runner = CliRunner()


@pytest.fixture()
def nothing_computed(monkeypatch):
    """Make every analysis these commands run an internal fault: exit 2 then proves the refusal
    came first."""
    import importlib

    def forbidden(*args, **kwargs):
        raise AssertionError("computed before bounding the work")

    # the modules that define the analyses, and what they import, are imported before any is
    # patched: they bind the real functions and stay for the next test (as in a run of the
    # whole suite, where earlier tests imported them; importing them again for each test was
    # about 0.4 s of CPU a test, CPU budget, issue 23)
    targets = [
        (importlib.import_module(module), name)
        for module, name in (
            ("flexshaft.analyses.stability", "stability"),
            ("flexshaft.thesis.spinup_maps", "spinup_map"),
            ("flexshaft.analyses.spinup", "actuator_receptance"),
            ("flexshaft.analyses.transient", "run_up"),
            ("flexshaft.montecarlo.steady", "run_sweep"),
            ("flexshaft.optimize.nsga", "optimize"),
            ("flexshaft.thesis.two_angles", "two_angle_study"),
        )
    ]
    before = set(sys.modules)
    for module, name in targets:
        monkeypatch.setattr(module, name, forbidden)
    yield
    # a module first imported during the test bound the forbidden stand-in by name (``from ...
    # import stability``) and would keep it for the rest of the session: forget it, so that the
    # next import runs it again with the real function
    for module in set(sys.modules) - before:
        if module.startswith("flexshaft"):
            del sys.modules[module]


def refused_quickly(args: list[str], *words: str) -> str:
    start = time.process_time()
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output and "computed before" not in result.output
    assert time.process_time() - start < 5.0
    for word in words:
        assert word in result.output, (word, result.output)
    return result.output


@pytest.mark.parametrize(
    "args, words",
    [
        (
            ["study", "spinup-map", "--n-gains", "400", "--n-speeds", "10000"],
            ["--n-gains 400", "160,000 gain pairs", "--n-speeds 10,000", "allowed: 10 min"],
        ),
        (["stability", "--n-speeds", "2000", "--n-modes", "100"], ["--n-speeds 2000 × --n-modes 100", "allowed"]),
        (["runup", "--duration", "3600"], ["--duration 3600 s", "2,304,001 output samples", "at most 312.5 s"]),
        (["runup", "--dwell", "3600"], ["--dwell 3600 s", "output samples"]),
        (["optimize", "--budget", "100000"], ["--budget 100,000", "allowed: 4 h"]),
    ],
    ids=["spinup-map", "stability", "runup duration", "runup dwell", "optimize"],
)
def test_the_reproduced_hangs_are_refused_before_computing(args, words, tmp_path: Path, nothing_computed) -> None:
    """Was: spinup-map 400 × 20000 (> 180 s, 2.6 GiB when killed), stability 2000 × 100
    (> 180 s), runup --duration 320 (exit 4 after building the run)."""
    if args[0] == "optimize":
        pytest.importorskip("pymoo")
    refused_quickly([*args, "--out", str(tmp_path / "o")] if args[0] != "stability" else args, *words)
    assert not (tmp_path / "o").exists()


def test_an_option_beyond_its_documented_range_is_a_usage_error(tmp_path: Path) -> None:
    """Was: `study spinup-map --n-gains 400 --n-speeds 20000` ran out of memory (2.6 GiB when
    killed): 20000 is now above the option's range, whose maximum runs (docs/limits.md)."""
    output = refused_quickly(
        ["study", "spinup-map", "--n-gains", "400", "--n-speeds", "20000", "--out", str(tmp_path / "o")], "--n-speeds"
    )
    assert "10000" in output


def test_a_small_design_takes_the_work_a_large_one_is_refused(tmp_path: Path, nothing_computed) -> None:
    """The bound is the options and the design together: 400 spin-up gains squared at 400 speeds
    run on the baseline's 38 shaft nodes (141 s of CPU measured), not on 1,000 nodes."""
    from flexshaft.design import baseline_text

    fine = tmp_path / "fine.toml"
    fine.write_text(baseline_text().replace("shaft_elements = 36", "shaft_elements = 1000", 1), encoding="utf-8")
    refused_quickly(
        ["study", "spinup-map", str(fine), "--n-gains", "400", "--out", str(tmp_path / "o")],
        "shaft nodes",
        "use fewer gains",
    )


def test_a_million_samples_run_on_the_baseline_not_on_a_thousand_nodes(tmp_path: Path, nothing_computed) -> None:
    """Monte-Carlo keeps its finished chunks (resumable): a million samples of the baseline take
    about 2 h on one core (6 ms a sample, docs/limits.md) and are accepted; on 1,000 shaft
    elements they would take 50 h and are refused with the numbers."""
    from flexshaft.cli.bounds import check_montecarlo
    from flexshaft.design import baseline_design, baseline_text

    check_montecarlo(baseline_design(), 1_000_000, 1)  # no refusal
    fine = tmp_path / "fine.toml"
    fine.write_text(baseline_text().replace("shaft_elements = 36", "shaft_elements = 1000", 1), encoding="utf-8")
    refused_quickly(
        ["montecarlo", str(fine), "--samples", "1000000", "--out", str(tmp_path / "o")],
        "--samples 1,000,000",
        "allowed: 4 h",
        "--jobs",
    )


def test_the_longest_run_up_of_the_refusal_is_its_closed_form() -> None:
    """At most 200,000 output samples 2π/(8 Ω) apart: 199,999 × 2π/(8 × 4800 rpm) = 312.5 s."""
    from flexshaft.analyses.transient import MAX_OUTPUTS, default_output_step
    from flexshaft.units import rpm_to_rad_s

    step = default_output_step(rpm_to_rad_s(4800.0))
    assert step == pytest.approx(2 * math.pi / (8 * rpm_to_rad_s(4800.0)), rel=1e-15)
    assert (MAX_OUTPUTS - 1) * step == pytest.approx(312.49844, rel=1e-6)


@pytest.mark.parametrize(
    "command, option",
    [(["stability"], "--n-speeds"), (["study", "spinup-map"], "--n-speeds"), (["runup"], "--duration")],
)
def test_the_help_states_the_bound(command, option) -> None:
    result = runner.invoke(app, [*command, "--help"])
    assert result.exit_code == 0
    text = " ".join(result.output.split())
    assert option in text and ("refused" in text or "at most" in text)


@pytest.mark.slow  # the documented maxima themselves: about 8 s of CPU (docs/limits.md lists all)
@pytest.mark.parametrize("args", [["modes", "--n-modes", "500"], ["stability", "--n-speeds", "2000"]])
def test_the_documented_maxima_run(args) -> None:
    result = runner.invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output


def test_the_eigen_bounds_cover_the_largest_basis_the_accuracy_loop_reaches() -> None:
    """``stability`` and ``modes`` grow their basis (doubling) until the estimated eigenvalue
    error meets the tolerance: asked for 1e-15, below round-off, the loop can only stop at its
    cap, which the memory bound must cover (the time bound assumes the first basis tried).

    The baseline on a coarse mesh (16 shaft, 8 boom elements, 142 free DOFs; CPU budget, issue
    23: 0.5 s of CPU instead of 3.3): the bound is a function of the free DOFs, and on the
    design's own mesh (342 free DOFs) as on this one the largest basis the bound allows is the
    whole model, which the grown bases (measured 125 and 136 vectors here, 227 and 306 there)
    stay strictly inside, above the first basis (60 and 88 vectors on both meshes)."""
    import numpy as np

    import flexshaft
    from flexshaft.analyses.stability import stability
    from flexshaft.cli.bounds import eigen_basis_range
    from flexshaft.design import baseline_design, with_overrides

    model = flexshaft.build_model(
        with_overrides(baseline_design(), {"mesh.shaft_elements": 16, "mesh.boom_elements": 8})
    )
    free = int(model.dofs.free.size)
    first, largest = eigen_basis_range(4, free, actuators=2)
    speeds = np.array([0.0, 300.0])
    assert stability(model, speeds, n_modes=4).basis_size <= first
    for n_modes in (4, 12):
        first, largest = eigen_basis_range(n_modes, free, actuators=2)
        grown = stability(model, speeds, n_modes=n_modes, tolerance=1e-15)
        assert first < grown.basis_size <= largest
