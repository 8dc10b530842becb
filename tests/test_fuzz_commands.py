"""Property test: every command, on generated designs and options, ends cleanly (issue 27).

The design fuzz (tests/test_design_fuzz.py) covers the design file through ``check``, ``modes``
and the assessment. Here each command of the CLI runs on designs generated from the embedded
ones (the one-piece FMC baseline and tuned designs with their active bearings; the segmented
``current`` driveline with its couplings, hangers and damper) with structural edits (a
transfer-function or PID controller, an active bearing on the segmented driveline, a damper on
the FMC one, a disk, no tailboom, the "worst" imbalance placement), extreme values that broke
a command once (issue 27: a coupling's polar inertia of 1e7, K_i = 1e15, a design at rest, a
sky at 400 °C) and its own options, from their defaults to their documented limits.

Every example must

* end with exit code 0, 2 (a user error, its message naming what to change) or 3 (a failed
  requirement), never 4 (an internal error) and never with a traceback;
* end within :data:`TIMEOUT` seconds (SIGALRM; a hang fails the example);
* write nothing outside its output folder (the working folder and the design files are
  compared before and after);
* print strict JSON with ``--json`` (no NaN or infinity).

Budget: the examples of each command are sized to about 5 s of CPU on the development machine
(derandomized, no example database: CI runs the same examples every time). A command with at
most :data:`COVERING_UP_TO` examples gets them from :func:`covering_examples` instead of from
hypothesis, whose first example is always its simplest (the plain baseline, no edit, no option):
with two examples ``run``, ``compare``, ``study all`` and ``optimize`` saw only the plain embedded
designs. ``study all`` and
``compare`` run their assessments at the report's resolution and are marked slow, as are
``run`` and ``optimize``. The commands that judge a design at each point of its envelope
(``run``, ``compare``, ``optimize``) get the design with one of its envelope's points, a
different one from example to example (:func:`design_text`).
"""

from __future__ import annotations

import contextlib
import copy
import json
import signal
import tomllib
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_design_fuzz import toml_document
from typer.testing import CliRunner

from flexshaft.cli import app
from flexshaft.design import embedded_text

runner = CliRunner()

#: Longest an example may take [s] (the slowest accepted example runs in about 10 s).
TIMEOUT = 120
BASES = {name: tomllib.loads(embedded_text(name)) for name in ("baseline", "tuned", "current")}


class Hang(BaseException):
    """Raised by SIGALRM in an example that ran longer than TIMEOUT (a BaseException, so that
    the CLI's error boundary does not report it as a user error or a fault)."""


@contextlib.contextmanager
def time_limit(seconds: int):
    def alarm(signum, frame):
        raise Hang(f"the command ran longer than {seconds} s")

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


# ------------------------------------------------------------------------------------------------
# Designs


def _active(data: dict) -> dict | None:
    return next((b for b in data["bearings"] if b.get("kind") == "active"), None)


def _edit(data: dict, edit: str) -> None:
    amb = _active(data)
    one_piece = "segments" not in data["shaft"]
    if edit == "tf_controller" and amb is not None:
        for key in ("kp", "kd", "integral_gain"):
            amb.pop(key, None)
        amb["controller"] = {"numerator": [2.0e3, 1.0e7], "denominator": [1.0 / 6000.0, 1.0]}
    elif edit == "pid_controller" and amb is not None:
        amb.update({"integral_gain": 1e8, "derivative_cutoff": 800.0, "amplifier_bandwidth": 2000.0, "kd": 1e3})
    elif edit == "amb_on_segments" and not one_piece:
        x = data["bearings"][1]["x"] + 0.4
        data["bearings"].append({"name": "amb", "kind": "active", "x": x, "kp": 1e6, "kd": 500.0, "gap": 2.5e-4})
    elif edit == "damper" and one_piece:
        x = 0.5 * (data["shaft"]["x_start"] + data["shaft"]["x_end"])
        data["bearings"].append(
            {
                "name": "damper",
                "kind": "contact",
                "role": "damper",
                "x": x,
                "stiffness": {"v": 2e4, "w": 2e4},
                "damping": {"v": 150.0, "w": 150.0},
            }
        )
    elif edit == "disk":
        x = 0.3 * data["shaft"]["x_start"] + 0.7 * data["shaft"]["x_end"]
        data["disks"] = [{"name": "disk", "x": x, "mass": 5.0, "diametral_inertia": 0.1, "polar_inertia": 0.2}]
    elif edit == "no_tailboom":
        data.pop("tailboom", None)
        data["loads"].pop("point", None)
    elif edit == "worst":
        data["loads"]["imbalance_placement"] = "worst"


STRUCTURAL = ["tf_controller", "pid_controller", "amb_on_segments", "damper", "disk", "no_tailboom", "worst"]


def _extreme(data: dict, edit: str) -> None:
    amb = _active(data)
    if edit == "heavy_coupling" and data.get("couplings"):
        data["couplings"][-1]["polar_inertia"] = 1.0e7
    elif edit == "integral_gain" and amb is not None and "controller" not in amb:
        amb["integral_gain"] = 1e15
    elif edit == "at_rest":
        data["operating"].update(speed_rpm=0.0, power=0.0)
    elif edit == "hot_sky":
        data.setdefault("thermal", {})["sky_temperature_c"] = 400.0
    elif edit == "fast":
        data["operating"]["speed_rpm"] = 9.0e5
    elif edit == "soft_hangers":
        for bearing in data["bearings"]:
            if bearing.get("kind") == "contact":
                bearing["stiffness"] = {k: v * 1e-6 for k, v in bearing["stiffness"].items()}


EXTREME = ["heavy_coupling", "integral_gain", "at_rest", "hot_sky", "fast", "soft_hangers"]

designs = st.tuples(
    st.sampled_from(sorted(BASES)),
    st.lists(st.sampled_from(STRUCTURAL), max_size=2, unique=True),
    st.lists(st.sampled_from(EXTREME), max_size=1),
    st.integers(3, 6),
)


#: Commands that assess a design at each of its envelope points (the embedded designs have three
#: or four): their designs keep one point of the envelope (:func:`design_text`).
ENVELOPE = {"run", "optimize", "compare"}


def design_text(example: tuple, one_point: bool = False) -> str:
    """The example's design file. With ``one_point`` its envelope keeps one of its points, the
    ``elements % n``-th: the examples go through the envelope's points in turn, and the drawn
    examples are the same as with the whole envelope. Each point is one more assessment of the
    same design; an envelope of several points is judged end to end by the README's quick start
    (tests/test_run.py: the tuned design's four points) and the comparison of the embedded
    designs (tests/test_compare.py)."""
    base, structure, extreme, elements = example
    data = copy.deepcopy(BASES[base])
    data["mesh"]["shaft_elements"], data["mesh"]["boom_elements"] = elements, 3
    for edit in structure:
        _edit(data, edit)
    for edit in extreme:
        _extreme(data, edit)
    if one_point and data.get("envelope"):
        points = data["envelope"]["points"]
        data["envelope"]["points"] = [points[elements % len(points)]]
    return toml_document(data)


# ------------------------------------------------------------------------------------------------
# Options: from the defaults to the documented limits (where an accepted maximum takes more
# than seconds, the limit is paired with a value that the command's bound refuses up front)


#: Each command's options as independent choices: one alternative of each list is taken.
CHOICES: dict[str, list[list[list[str]]]] = {
    "check": [[[], ["--json"]]],
    "modes": [
        [[], ["--speed-rpm", "0"], ["--speed-rpm", "1000000"]],
        [[], ["--n-modes", "1"], ["--n-modes", "500"]],
        [[], ["--json"]],
    ],
    "stability": [
        [["--n-speeds", "3", "--n-modes", "2"], ["--n-speeds", "30", "--n-modes", "100"]],
        [[], ["--damping-model", "viscous"], ["--max-rpm", "1000000"]],
        [[], ["--json"]],
    ],
    "thermal": [
        [[], ["--self-heating"]],
        [[], ["--sweeps"]],
        [[], ["--loss-model", "rotating", "--convection", "kendoush"]],
        [[], ["--json"]],
    ],
    "runup": [
        [["--duration", "0.05"], ["--duration", "3600"]],
        [[], ["--start-rpm", "1000"], ["--stop-rpm", "1000000"], ["--stop-rpm", "0", "--start-rpm", "2000"]],
        [[], ["--dwell", "0.05"], ["--dwell", "3600"]],
        [[], ["--json"]],
    ],
    "montecarlo": [
        [["--samples", "10"]],
        [[], ["--grade", "4000"], ["--gap-mm", "0.000001", "--force-limit", "1000000000"]],
        [[], ["--seed", "4611686018427387904"]],
        [[], ["--json"]],
    ],
    "study ply-angle": [[["--step", "45"], ["--step", "30"]], [[], ["--json"]]],
    "study two-angle": [[["--step", "45"]], [[], ["--json"]]],
    "study wall": [[[], ["--json"]]],
    "study gain": [[[], ["--json"]]],
    "study buckling": [[[], ["--json"]]],
    "study spinup-map": [
        [
            ["--n-gains", "2", "--n-speeds", "10"],
            ["--n-gains", "3", "--n-speeds", "20"],
            ["--n-gains", "400", "--n-speeds", "10000"],
        ],
        [[], ["--json"]],
    ],
    "study all": [[[], ["--json"]]],
    "run": [[["--studies", "none"]], [[], ["--strict"]], [[], ["--json"]]],
    "compare": [[[], ["--json"]]],
    "optimize": [[["--budget", "2", "--fidelity", "screening", "--no-verify"]], [[], ["--seed", "7"]]],
    "validate": [[["--list"], ["--case", "gibert-spinning-rod"]], [[], ["--json"]]],
}


def _options(*choices: list) -> st.SearchStrategy:
    return st.tuples(*(st.sampled_from(c) for c in choices)).map(lambda parts: [a for part in parts for a in part])


OPTIONS = {command: _options(*choices) for command, choices in CHOICES.items()}

#: Examples per command: about 5 s of CPU each.
EXAMPLES = {
    "check": 25,
    "modes": 12,
    "stability": 8,
    "thermal": 8,
    "runup": 8,
    "montecarlo": 3,
    "study ply-angle": 4,
    "study two-angle": 3,
    "study wall": 2,
    "study gain": 2,
    "study buckling": 2,
    "study spinup-map": 4,
    "study all": 2,
    "run": 2,
    "compare": 2,
    "optimize": 2,
    "validate": 3,
}


def _snapshot(root: Path, skip: Path) -> dict[str, bytes | None]:
    """Every file under ``root`` outside ``skip`` with its content (None for a folder)."""
    out = {}
    for path in sorted(root.rglob("*")):
        if path == skip or skip in path.parents:
            continue
        out[str(path.relative_to(root))] = None if path.is_dir() else path.read_bytes()
    return out


def _strict(text: str) -> Any:
    def refuse(constant: str) -> Any:
        raise AssertionError(f"{constant} in the JSON output")

    return json.loads(text, parse_constant=refuse)


def run_command(root: Path, command: str, example: tuple, options: list[str]) -> int:
    """Run one example in ``root`` and check every property; returns the exit code."""
    import shutil

    designs, work = root / "designs", root / "work"
    out = work / "out"
    shutil.rmtree(work, ignore_errors=True)
    designs.mkdir(exist_ok=True)
    work.mkdir()
    files = []
    for k, part in enumerate([example] if command != "compare" else [example, (*example[:1], [], [], 3)]):
        path = designs / f"d{k}.toml"
        path.write_text(design_text(part, one_point=command in ENVELOPE), encoding="utf-8")
        files.append(str(path))
    args = command.split()
    if command in ("validate",):
        files = []
    elif command not in ("check", "modes", "stability", "thermal"):
        args += ["--out", str(out)]
    before = _snapshot(root, out)
    with contextlib.chdir(work), time_limit(TIMEOUT):
        result = runner.invoke(app, [*args, *files, *options])
    message = f"{command} {options} on {example}: exit {result.exit_code}\n{result.output[-3000:]}"
    assert result.exit_code in (0, 2, 3), message
    assert "Traceback" not in result.output and "internal error" not in result.output, message
    if result.exit_code == 2:
        assert result.stderr.startswith("error: ") and len(result.stderr) > 20, message
    assert _snapshot(root, out) == before, f"files written outside the output folder: {message}"
    if "--json" in options and result.exit_code in (0, 3) and result.stdout.strip():
        _strict(result.stdout)
    return result.exit_code


#: Commands with at most this many examples take :func:`covering_examples` (hypothesis's first
#: example is its simplest: the plain baseline with no edit and the first options).
COVERING_UP_TO = 4
#: :data:`STRUCTURAL` in the order :func:`covering_examples` pairs them (2k with 2k + 1, modulo
#: 7): never the two controllers together, which the schema refuses (a PID's cutoffs with a
#: transfer function) before any command runs.
_PAIRED = ["tf_controller", "amb_on_segments", "pid_controller", "damper", "disk", "no_tailboom", "worst"]


def covering_examples(command: str) -> list[tuple[tuple, list[str]]]:
    """``EXAMPLES[command]`` examples that go through the edits, the extreme values, the bases
    and the options in turn, each command starting elsewhere in the turn (its place in
    :data:`CHOICES`): its n-th example (k = j + n) has the base k, the structural edits 2k and
    2k + 1 of :data:`_PAIRED`, for an odd k the extreme value (k - 1)/2 (an even k keeps the edited design's own
    values, so that its command runs through, not refused up front), the option alternatives
    k + i (i: the choice's place; each list modulo its length) and 3 + k % 4 shaft elements.
    The twelve commands of at most :data:`COVERING_UP_TO` examples take 31 examples: every
    structural edit eight times or more, every extreme value twice or more, every base ten
    times or more (an edit that does not apply to a base leaves it as it is, as in the drawn
    examples)."""
    j = list(CHOICES).index(command)
    bases = sorted(BASES)
    out = []
    for k in range(j, j + EXAMPLES[command]):
        structure = sorted({_PAIRED[(2 * k) % len(_PAIRED)], _PAIRED[(2 * k + 1) % len(_PAIRED)]})
        extreme = [EXTREME[(k // 2) % len(EXTREME)]] if k % 2 else []
        design = (bases[k % len(bases)], structure, extreme, 3 + k % 4)
        options = [a for i, choice in enumerate(CHOICES[command]) for a in choice[(k + i) % len(choice)]]
        out.append((design, options))
    return out


def _fuzz(command: str, tmp_path_factory: pytest.TempPathFactory) -> dict[int, int]:
    root = tmp_path_factory.mktemp("fuzz")
    codes: dict[int, int] = {}
    if EXAMPLES[command] <= COVERING_UP_TO:
        for design, options in covering_examples(command):
            code = run_command(root, command, design, options)
            codes[code] = codes.get(code, 0) + 1
        return codes
    strategy = st.tuples(designs, OPTIONS[command])

    @settings(
        max_examples=EXAMPLES[command],
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    @given(strategy)
    def body(example) -> None:
        design, options = example
        code = run_command(root, command, design, options)
        codes[code] = codes.get(code, 0) + 1

    body()
    assert sum(codes.values()) >= 0.9 * EXAMPLES[command]
    return codes


FAST = [
    pytest.param(
        c, marks=pytest.mark.slow(reason="two examples, each a full assessment with its report (~2-5 s of CPU)")
    )
    if c in ENVELOPE
    else c
    for c in OPTIONS
    if c not in ("study all", "compare")
]


@pytest.mark.parametrize("command", FAST)
def test_every_command_ends_cleanly(command: str, tmp_path_factory: pytest.TempPathFactory) -> None:
    if command == "optimize":
        pytest.importorskip("pymoo")
    codes = _fuzz(command, tmp_path_factory)
    assert set(codes) <= {0, 2, 3}


@pytest.mark.slow  # two assessments at the report's resolution per example: ~3 s of CPU each
@pytest.mark.parametrize("command", ["study all", "compare"])
def test_the_assessing_commands_end_cleanly(command: str, tmp_path_factory: pytest.TempPathFactory) -> None:
    codes = _fuzz(command, tmp_path_factory)
    assert set(codes) <= {0, 2, 3}
