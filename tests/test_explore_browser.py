"""The explorer in a real browser: headless Chromium (Debian's, /usr/bin/chromium) driven by
playwright, against ``flexshaft explore`` started as a user would start it.

One session of the page, in order: it opens on the tuned design (PASS); K_p of one actuator
lowered to 2e5 N/m turns the verdict to FAIL on the actuator excursion (the design the
screening assessment judges so, tests/test_explore.py) within the update latency; a wall of
60 mm typed while an update computes shows the schema's message at the wall's field, and keeps
it when that update answers; the design file downloads, loads back as
the base and gives the same verdict; ``flexshaft run --strict`` judges the downloaded file to
the same verdict, check by check (exit code 3 for FAIL), and its ``interactive.html`` draws its
figures offline; a sweep of K_p draws every check's margin; the page's full-resolution run
writes the report folder with its progress; a Pareto point of an optimizer run loads its
design. The browser may reach only the explorer's own address: every other request is refused
and recorded, and none is made.

The explorer starts from the tuned design's file with one point of its envelope, the cold day
(:data:`COLD_DAY_TUNED`: where K_p 2e5 puts actuator 1 beyond its gap, tests/test_explore.py),
for the CPU budget (issue 23): every update, sweep point and run here is one assessment per
envelope point, and what this test checks is the page (its controls, messages, download, load,
sweep, run and Pareto front), not the envelope, whose updates on the server's workers are
tests/test_explore.py's (``test_an_envelope_update_on_two_workers_is_the_serial_update``).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import threading
import time
from pathlib import Path
from urllib.parse import urlparse

import pytest
from chromium_probe import chromium_or_skip
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import embedded_text, loads_design

if os.environ.get("CI"):  # CI installs the extras (scripts/test.sh): a missing one is a failure there
    import playwright.sync_api as playwright_api
    import plotly  # noqa: F401
    import starlette  # noqa: F401
else:
    playwright_api = pytest.importorskip("playwright.sync_api")
    pytest.importorskip("starlette")
    pytest.importorskip("plotly")

#: Chromium's flags for a machine without a display or network (tests/chromium_probe.py).
FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-quic",
    "--no-first-run",
]
_FLEXSHAFT = "import sys; from flexshaft.cli import app; sys.exit(app())"
#: The embedded tuned design's file with the cold day the only point of its envelope.
COLD_DAY_TUNED = re.sub(
    r'\[\[envelope\.points\]\]\nname = "(standard_day|hot_day|hot_soak_start)".*?(?=\[\[envelope|\n# -+\n\[mesh\])',
    "",
    embedded_text("tuned"),
    flags=re.S,
)


def _environment() -> dict:
    return {**os.environ, "OPENBLAS_NUM_THREADS": "1", "PYTHONUNBUFFERED": "1"}


@pytest.fixture(scope="module")
def explorer(tmp_path_factory):
    """``flexshaft explore`` of :data:`COLD_DAY_TUNED` on a free port (its address read from what
    it prints), with a tiny optimizer run's Pareto front; stopped after the module."""
    chromium_or_skip()
    folder = tmp_path_factory.mktemp("explore")
    design = folder / "tuned.toml"
    design.write_text(COLD_DAY_TUNED, encoding="utf-8")
    assert [p.name for p in loads_design(COLD_DAY_TUNED).envelope.points] == ["cold_day"]
    pareto = _tiny_optimizer_run(folder / "optimize")
    server = subprocess.Popen(
        [sys.executable, "-c", _FLEXSHAFT, "explore", str(design), "--port", "0", "--workers", "2"]
        + ["--studies", "none", "--out", str(folder / "runs"), "--pareto", str(pareto)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=_environment(),
        cwd=folder,
    )
    line = _first_line(server, timeout=60)
    assert "http://127.0.0.1:" in line, line + server.stderr.read() if server.poll() is not None else line
    url = line.split("flexshaft explore: ", 1)[1].split()[0]
    yield url, folder
    server.terminate()
    try:
        server.wait(timeout=20)
    except subprocess.TimeoutExpired:
        server.kill()


def _first_line(process: subprocess.Popen, timeout: float) -> str:
    out: list[str] = []
    reader = threading.Thread(target=lambda: out.append(process.stdout.readline()), daemon=True)
    reader.start()
    reader.join(timeout)
    return out[0] if out else ""


def _tiny_optimizer_run(folder: Path) -> Path:
    """Four screening evaluations of the explored design's shared K_p, on a coarse mesh (8
    shaft, 4 boom elements; CPU budget, issue 23: 1.9 s of CPU on the design's own): what the
    page checks of the front is that a point's design loads with its K_p, which does not depend
    on the model's size (tests/test_explore.py's Pareto test reads a coarse front back too)."""
    pytest.importorskip("pymoo")
    from flexshaft.design import with_overrides
    from flexshaft.optimize import DesignProblem, DesignVariable, optimize

    problem = DesignProblem(
        variables=(DesignVariable(("bearings[1].kp", "bearings[2].kp"), 3e5, 1e6, log=True, name="kp"),),
        base=with_overrides(loads_design(COLD_DAY_TUNED), {"mesh.shaft_elements": 8, "mesh.boom_elements": 4}),
        fidelity="screening",
    )
    optimize(problem, 4, folder, pop_size=2).save()
    return folder


@pytest.fixture(scope="module")
def browser():
    executable = chromium_or_skip()
    with playwright_api.sync_playwright() as p:
        chromium = p.chromium.launch(executable_path=executable, args=FLAGS)
        yield chromium
        chromium.close()


def _verdict(page) -> dict[str, str]:
    return page.evaluate(
        "Object.fromEntries([...document.querySelectorAll('#verdict-table tbody tr')]"
        ".map(r => [r.dataset.key, r.dataset.status]))"
    )


def _until(page, expression: str, timeout: float = 60.0) -> None:
    """Poll ``expression`` in the page until it is true (wait_for_function's string predicates
    are compiled with eval, which the page's Content-Security-Policy forbids, as it should)."""
    deadline = time.monotonic() + timeout
    while not page.evaluate(expression):
        assert time.monotonic() < deadline, f"timed out waiting for {expression}"
        page.wait_for_timeout(50)


def _wait_update(page, before: int) -> None:
    _until(page, f"Number(document.body.dataset.seq || -1) > {before}")


def _seq(page) -> int:
    return int(page.evaluate("Number(document.body.dataset.seq || -1)"))


def _set(page, selector: str, value: str) -> None:
    page.fill(selector, value)
    page.press(selector, "Enter")  # a committed value: the input's change event


@pytest.mark.slow  # the server and its workers, the updates, two full-resolution runs: about 13 s of CPU
def test_the_explorer_in_a_browser(explorer, browser, tmp_path):
    url, folder = explorer
    host = urlparse(url).hostname
    elsewhere: list[str] = []

    def only_here(route):
        where = urlparse(route.request.url)
        if where.hostname == host or where.scheme == "file":  # the server, or a file of this machine
            route.continue_()
        else:
            elsewhere.append(route.request.url)
            route.abort()

    context = browser.new_context(accept_downloads=True)
    context.route("**/*", only_here)
    page = context.new_page()
    errors: list[str] = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.goto(url)
    _wait_update(page, -1)
    assert page.text_content("#verdict-status") == "PASS"
    assert "Tuned design" in page.text_content("#design-name")
    assert page.locator("#fig-campbell .main-svg").count() > 0  # plotly drew the figures

    # K_p of actuator 1 down to 2e5 N/m: the verdict turns to FAIL on its excursion
    before = _seq(page)
    _set(page, "[id='ctl-bearings[1].kp']", "200000")
    _wait_update(page, before)
    assert page.text_content("#verdict-status") == "FAIL"
    verdict = _verdict(page)
    assert verdict["actuator_orbit"] == "fail"
    # the page measures its round trip (benchmarks/explore_latency.py reports it; speed is a
    # benchmark's business, not a timed test's)
    assert float(page.evaluate("document.body.dataset.roundTrip")) > 0.0

    # an invalid value typed while an update (K_d 1250 -> 1251 N s/m) is still computing: the
    # schema's message at the field, kept when that older update answers after the refusal
    before = _seq(page)
    _set(page, "[id='ctl-bearings[1].kd']", "1251")
    _set(page, "[id='ctl-shaft.wall_thickness']", "60")
    _wait_update(page, before)
    _until(page, "document.getElementById('err-shaft.wall_thickness').textContent.length > 0")
    message = page.text_content("[id='err-shaft.wall_thickness']")
    assert "shaft.wall_thickness: must be less than outer_diameter/2" in message
    assert page.input_value("[id='ctl-shaft.wall_thickness']") == "60"
    assert page.input_value("[id='ctl-bearings[1].kd']") == "1251"
    assert _verdict(page) == verdict

    # a sweep of K_p: every check's normalised margin at three gains
    page.select_option("#sweep-control", "bearings[2].kp")
    page.fill("#sweep-points", "3")
    page.click("#sweep-run")
    _until(page, "document.getElementById('sweep-status').textContent.startsWith('3 points')")
    traces = page.evaluate("document.getElementById('fig-sweep').data.map(t => t.name)")
    assert "actuator excursion" in traces and len(traces) == len(verdict)

    # the design file: download, then load it back as the base: the same verdict
    with page.expect_download() as download:
        page.click("#download")
    saved = tmp_path / download.value.suggested_filename
    download.value.save_as(saved)
    text = saved.read_text(encoding="utf-8")
    assert "CHANGED bearings[1].kp = 200000.0  (was 500000.0)" in text
    assert "CHANGED bearings[1].kd = 1251.0  (was 1250.0)" in text
    assert page.text_content("#run-command").startswith("flexshaft run ")
    before = _seq(page)
    page.set_input_files("#load-file", str(saved))
    _wait_update(page, before)
    assert _verdict(page) == verdict
    assert page.input_value("[id='ctl-bearings[1].kp']") == "200000"

    # flexshaft run --strict on the downloaded file: the same verdict, check by check; its
    # interactive figures are what this test opens (the PNGs are the quick start's, test_run.py:
    # --no-figures, CPU budget, issue 23). In this process (typer's CliRunner, as the other CLI
    # tests; CPU budget, issue 23: no second interpreter and pool importing flexshaft again): what
    # it checks is the downloaded file's verdict, not a process (test_run.py's quick start runs
    # `flexshaft run` as one)
    run = CliRunner().invoke(
        app,
        ["run", str(saved), "--strict", "--studies", "none", "--interactive", "--no-figures", "--json"]
        + ["--out", str(tmp_path / "report")],
    )
    assert run.exit_code == 3, run.output  # --strict: a requirement fails
    checks = {c["key"]: c["status"] for c in json.loads(run.stdout)["verdict"]["checks"]}
    assert checks == verdict

    # its interactive figures, offline
    offline = context.new_page()
    offline.goto((tmp_path / "report" / "interactive.html").as_uri())
    _until(offline, "document.body.dataset.plotted === '5'")
    offline.close()

    # the page's full-resolution run, with its stages, through flexshaft run's pipeline
    page.click("#full-run")
    page.wait_for_selector("#full-run-verdict", timeout=300_000)
    assert page.get_attribute("#full-run-verdict", "data-passed") == "false"
    assert page.locator("#run-steps li").count() >= 5
    runs = sorted((folder / "runs").iterdir())
    assert (runs[-1] / "report.html").is_file() and (runs[-1] / "interactive.html").is_file()
    assert json.loads((runs[-1] / "results.json").read_text())["verdict"]["passed"] is False

    # a Pareto point of the optimizer run: its design loads (its K_p in the field)
    before = _seq(page)
    page.evaluate("window.flexshaftExplore.loadParetoPoint(0)")
    _wait_update(page, before)
    kp = float(page.input_value("[id='ctl-bearings[1].kp']"))
    assert 3e5 <= kp <= 1e6

    assert elsewhere == [], f"requests off this machine: {elsewhere}"
    assert errors == []
    context.close()
