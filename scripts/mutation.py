#!/usr/bin/env python3
"""Mutation testing of flexshaft's physics: does the test suite notice a wrong formula?

Each mutation in ``scripts/mutations.toml`` is one physically meaningful mistake (a flipped
sign, a coefficient 2 → 1, a dropped term, sin ↔ cos, an off-by-one DOF, a wrong unit
conversion) written as an exact text replacement in one module. For every mutation the script

1. copies ``src/flexshaft`` once into a temporary directory (the working tree is never written),
2. applies the replacement to that copy (and restores the copy's file afterwards),
3. runs only the test files mapped to the mutated module (``[modules]`` table of the TOML file,
   or the mutation's own ``tests``) with ``PYTHONPATH`` pointing at the copy:
   ``python -m pytest -p no:cacheprovider -x -q <tests>``, one BLAS thread, a timeout per mutant,
4. records the mutant as **caught** (a test failed or errored), **timeout** (the tests did not
   finish: counted as caught, listed apart), or **survived** (every test passed).

Before the mutants, every test set used is run once on the unmutated copy: a set that fails
there cannot judge a mutant, and its mutants are reported as "baseline failed" (not scored).
A mutation marked ``equivalent = "<reason>"`` cannot change any result; it is listed with its
reason and left out of the score (never drop a surviving mutation to raise the score: add the
test that catches it).

Score = caught (incl. timeouts) / mutants run. The report prints every mutant with its
mutation text; ``--json`` and ``--markdown`` write it to files.

Usage (from the repository root, with the project's venv)::

    .venv/bin/python scripts/mutation.py                      # every mutation (~40 min, 1 core)
    .venv/bin/python scripts/mutation.py --list               # the mutations and their tests
    .venv/bin/python scripts/mutation.py --only verdict-zero-margin-fails thermal-h-radius
    .venv/bin/python scripts/mutation.py --module thermal.shaft --timeout 120
    .venv/bin/python scripts/mutation.py --check              # validate the list only (no tests)
    .venv/bin/python scripts/mutation.py --only ID --tests tests/test_a.py tests/test_b.py   # coverage
    .venv/bin/python scripts/mutation.py --markdown /tmp/mutation.md --json /tmp/mutation.json

Extending: add a ``[[mutation]]`` to scripts/mutations.toml (``id``, ``module``, ``find``,
``replace``, ``why``; optional ``occurrence`` when ``find`` appears more than once, ``tests`` to
override the module's test files). When a module moves (e.g. the studies refactor), change its
``path`` in the ``[modules]`` table only. Run ``--check`` after editing.

No third-party dependency beyond pytest; the standard library's tomllib (Python ≥ 3.11).
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import json
import os
import platform
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
from dataclasses import asdict, dataclass, field
from datetime import UTC, datetime
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "flexshaft"
DEFAULT_LIST = Path(__file__).with_name("mutations.toml")
PYTEST_ARGS = ["-p", "no:cacheprovider", "-x", "-q", "--no-header", "-W", "ignore::DeprecationWarning"]


@dataclass(frozen=True)
class Mutation:
    id: str
    module: str
    path: str  # relative to src/flexshaft
    find: str
    replace: str
    why: str
    tests: tuple[str, ...]
    occurrence: int | None = None
    equivalent: str | None = None


@dataclass
class Outcome:
    id: str
    module: str
    status: str  # caught, timeout, survived, equivalent, baseline failed
    seconds: float = 0.0
    tests: tuple[str, ...] = ()
    find: str = ""
    replace: str = ""
    why: str = ""
    detail: str = ""
    failed_test: str = ""


@dataclass
class Campaign:
    outcomes: list[Outcome] = field(default_factory=list)
    started: str = ""
    commit: str = ""
    dirty: bool = False
    python: str = ""
    command: str = ""
    seconds: float = 0.0

    @property
    def scored(self) -> list[Outcome]:
        return [o for o in self.outcomes if o.status in ("caught", "timeout", "survived")]

    @property
    def caught(self) -> int:
        return sum(o.status in ("caught", "timeout") for o in self.outcomes)

    @property
    def score(self) -> float:
        return self.caught / len(self.scored) if self.scored else float("nan")


# ------------------------------------------------------------------------------------------------
# The mutation list


def load_mutations(path: Path) -> list[Mutation]:
    """Mutations of ``path`` (TOML) with each module's file and tests resolved; refuses an
    unknown module, a missing test file, a duplicate id or a replacement equal to its text."""
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    modules = data.get("modules", {})
    out, seen = [], set()
    for k, entry in enumerate(data.get("mutation", [])):
        where = f"{path.name}: mutation {k + 1} ({entry.get('id', '?')})"
        for key in ("id", "module", "find", "replace", "why"):
            if not isinstance(entry.get(key), str) or not entry[key]:
                raise SystemExit(f"{where}: needs a non-empty string '{key}'")
        if entry["id"] in seen:
            raise SystemExit(f"{where}: duplicate id")
        seen.add(entry["id"])
        if entry["module"] not in modules:
            raise SystemExit(f"{where}: module {entry['module']!r} is not in [modules] ({', '.join(sorted(modules))})")
        if entry["find"] == entry["replace"]:
            raise SystemExit(f"{where}: replace equals find")
        module = modules[entry["module"]]
        tests = tuple(entry.get("tests", module["tests"]))
        for test in tests:
            if not (ROOT / test.split("::")[0]).is_file():
                raise SystemExit(f"{where}: test file {test!r} does not exist")
        out.append(
            Mutation(
                id=entry["id"],
                module=entry["module"],
                path=module["path"],
                find=entry["find"],
                replace=entry["replace"],
                why=entry["why"],
                tests=tests,
                occurrence=entry.get("occurrence"),
                equivalent=entry.get("equivalent"),
            )
        )
    return out


def mutate(text: str, m: Mutation) -> str:
    """``text`` with ``m.find`` replaced once; exactly one occurrence unless ``m.occurrence``
    (1-based) picks one of several."""
    count = text.count(m.find)
    if count == 0:
        raise ValueError(f"{m.id}: text not found in {m.path}: {m.find!r}")
    if m.occurrence is None:
        if count != 1:
            raise ValueError(f"{m.id}: text occurs {count} times in {m.path}; give occurrence = 1..{count}")
        index = text.index(m.find)
    else:
        if not 1 <= m.occurrence <= count:
            raise ValueError(f"{m.id}: occurrence {m.occurrence} of {count} in {m.path}")
        index = -1
        for _ in range(m.occurrence):
            index = text.index(m.find, index + 1)
    return text[:index] + m.replace + text[index + len(m.find) :]


def check(mutations: list[Mutation]) -> None:
    """Every mutation applies to the current source and compiles, and no two make the same
    program (an exact copy scores one blind spot twice); refuses with every stale or copied
    mutation listed (not only the first), so that one pass after a refactor finds them all."""
    problems = []
    programs: dict[tuple[str, str], str] = {}  # (module path, digest of the mutated text) -> first id
    for m in mutations:
        source = PACKAGE / m.path
        if not source.is_file():
            problems.append(f"{m.id}: module file {source} does not exist (update [modules] in mutations.toml)")
            continue
        try:
            mutated = mutate(source.read_text(encoding="utf-8"), m)
            compile(mutated, str(source), "exec")
            first = programs.setdefault((m.path, hashlib.sha256(mutated.encode()).hexdigest()), m.id)
            if first != m.id:
                problems.append(f"{m.id}: makes the same program as {first} (drop one of them)")
        except ValueError as error:
            problems.append(str(error))
        except SyntaxError as error:
            problems.append(f"{m.id}: the mutated module does not compile: {error}")
    if problems:
        raise SystemExit(f"{len(problems)} of {len(mutations)} mutations do not apply:\n" + "\n".join(problems))


# ------------------------------------------------------------------------------------------------
# Running


def environment(copy_root: Path) -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(copy_root), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    env["MPLBACKEND"] = "Agg"
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        env[var] = "1"
    return env


def run_tests(python: str, tests: tuple[str, ...], env: dict[str, str], timeout: float) -> tuple[str, float, str]:
    """(status, seconds, last lines) of pytest on ``tests``; the process group is killed on timeout."""
    start = time.monotonic()
    proc = subprocess.Popen(
        [python, "-m", "pytest", *PYTEST_ARGS, *tests],
        cwd=ROOT,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,
    )
    try:
        output, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        output, _ = proc.communicate()
        return "timeout", time.monotonic() - start, (output or "")[-2000:]
    seconds = time.monotonic() - start
    if proc.returncode == 0:
        return "passed", seconds, output[-2000:]
    if proc.returncode == 5:
        return "no tests", seconds, output[-2000:]
    return "failed", seconds, output[-2000:]


def first_failure(output: str) -> str:
    for line in output.splitlines():
        if line.startswith(("FAILED ", "ERROR ")):
            return line.split(" - ")[0]
    return ""


def git_state() -> tuple[str, bool]:
    try:
        commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
        status = subprocess.run(
            ["git", "status", "--porcelain", "--", "src", "tests"], cwd=ROOT, capture_output=True, text=True
        ).stdout
        return commit, bool(status.strip())
    except OSError:
        return "", False


def campaign(
    mutations: list[Mutation], python: str, timeout: float, baseline_timeout: float, verbose: bool = True
) -> Campaign:
    result = Campaign(
        started=datetime.now(UTC).isoformat(timespec="seconds"),
        python=f"{platform.python_version()} ({python})",
        command=" ".join(["scripts/mutation.py", *sys.argv[1:]]),
    )
    result.commit, result.dirty = git_state()
    t0 = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="flexshaft-mutants-") as tmp:
        copy_root = Path(tmp)
        shutil.copytree(PACKAGE, copy_root / "flexshaft", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        env = environment(copy_root)
        probe = subprocess.run(
            [python, "-c", "import flexshaft, sys; sys.stdout.write(flexshaft.__file__)"],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
        )
        if not probe.stdout.startswith(str(copy_root)):
            raise SystemExit(
                f"the tests would import flexshaft from {probe.stdout or probe.stderr!r}, not from the mutated copy "
                f"in {copy_root}: PYTHONPATH is overridden (an editable install with an import hook?)"
            )
        # baselines: every test set once, unmutated
        baseline: dict[tuple[str, ...], str] = {}
        for tests in dict.fromkeys(m.tests for m in mutations if m.equivalent is None):
            status, seconds, output = run_tests(python, tests, env, baseline_timeout)
            baseline[tests] = status
            if verbose:
                print(f"baseline {status:>8} {seconds:6.1f} s  {' '.join(tests)}", flush=True)
                if status != "passed":
                    print(output, flush=True)
        for m in mutations:
            outcome = Outcome(m.id, m.module, "", tests=m.tests, find=m.find, replace=m.replace, why=m.why)
            if m.equivalent is not None:
                outcome.status, outcome.detail = "equivalent", m.equivalent
            elif baseline[m.tests] != "passed":
                outcome.status = "baseline failed"
            else:
                target = copy_root / "flexshaft" / m.path
                original = target.read_text(encoding="utf-8")
                try:
                    target.write_text(mutate(original, m), encoding="utf-8")
                    status, outcome.seconds, output = run_tests(python, m.tests, env, timeout)
                finally:
                    target.write_text(original, encoding="utf-8")
                outcome.status = {"failed": "caught", "timeout": "timeout"}.get(status, "survived")
                outcome.failed_test = first_failure(output)
                if status == "no tests":
                    outcome.detail = "no test collected"
            result.outcomes.append(outcome)
            if verbose:
                print(f"{outcome.status:>15} {outcome.seconds:6.1f} s  {m.id}  {outcome.failed_test}", flush=True)
    result.seconds = time.monotonic() - t0
    return result


# ------------------------------------------------------------------------------------------------
# Reports


def markdown(result: Campaign) -> str:
    lines = [
        f"Mutation score: **{result.caught} / {len(result.scored)} caught ({100 * result.score:.1f} %)**, "
        f"{sum(o.status == 'equivalent' for o in result.outcomes)} equivalent excluded, "
        f"{sum(o.status == 'baseline failed' for o in result.outcomes)} not run (baseline failed).",
        "",
        f"Command `{result.command}`, {result.started}, commit {result.commit[:12]}"
        f"{' + uncommitted changes' if result.dirty else ''}, Python {result.python.split(' ')[0]}, "
        f"{result.seconds / 60:.1f} min.",
        "",
        "| status | mutation | module | change | why | first failing test |",
        "|---|---|---|---|---|---|",
    ]

    def cell(text: str) -> str:
        return text.replace("|", "\\|").replace("\n", "⏎")

    for o in result.outcomes:
        change = f"`{cell(o.find)}` → `{cell(o.replace)}`"
        why = o.why if o.status != "equivalent" else f"{o.why} (equivalent: {o.detail})"
        lines.append(f"| {o.status} | {o.id} | {o.module} | {change} | {cell(why)} | {cell(o.failed_test)} |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--list-file", type=Path, default=DEFAULT_LIST, help="mutation list (TOML)")
    parser.add_argument("--only", nargs="+", metavar="ID", help="run these mutation ids only")
    parser.add_argument("--module", nargs="+", metavar="NAME", help="run the mutations of these modules only")
    parser.add_argument(
        "--tests",
        nargs="+",
        metavar="FILE",
        help="run these test files for every selected mutation (exploring coverage)",
    )
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per mutant (default 300)")
    parser.add_argument("--baseline-timeout", type=float, default=900.0, help="seconds per unmutated test set")
    parser.add_argument("--python", default=sys.executable, help="interpreter that runs pytest")
    parser.add_argument("--list", action="store_true", help="print the mutations and exit")
    parser.add_argument("--check", action="store_true", help="validate that every mutation applies, then exit")
    parser.add_argument("--json", type=Path, help="write the outcomes as JSON")
    parser.add_argument("--markdown", type=Path, help="write the report as a Markdown table")
    args = parser.parse_args(argv)

    mutations = load_mutations(args.list_file)
    if args.only:
        unknown = set(args.only) - {m.id for m in mutations}
        if unknown:
            raise SystemExit(f"unknown mutation ids: {', '.join(sorted(unknown))}")
        mutations = [m for m in mutations if m.id in args.only]
    if args.module:
        mutations = [m for m in mutations if m.module in args.module]
    if args.tests:
        mutations = [dataclasses.replace(m, tests=tuple(args.tests)) for m in mutations]
    check(mutations)
    if args.list or args.check:
        for m in mutations:
            flag = f"  [equivalent: {m.equivalent}]" if m.equivalent else ""
            print(f"{m.id:40s} {m.module:22s} {m.why}{flag}")
            if args.list:
                print(f"{'':40s} {m.find!r} -> {m.replace!r}\n{'':40s} tests: {' '.join(m.tests)}")
        print(f"{len(mutations)} mutations apply to the current source", file=sys.stderr)
        return 0

    result = campaign(mutations, args.python, args.timeout, args.baseline_timeout)
    report = markdown(result)
    print()
    print(report)
    if args.markdown:
        args.markdown.write_text(report, encoding="utf-8")
    if args.json:
        payload = {k: v for k, v in asdict(result).items() if k != "outcomes"}
        payload.update(score=result.score, caught=result.caught, scored=len(result.scored))
        payload["outcomes"] = [asdict(o) for o in result.outcomes]
        args.json.write_text(json.dumps(payload, indent=1, ensure_ascii=False), encoding="utf-8")
    survivors = [o.id for o in result.outcomes if o.status == "survived"]
    if survivors:
        print(f"survived: {', '.join(survivors)}", file=sys.stderr)
    return 0 if not survivors else 1


if __name__ == "__main__":
    sys.exit(main())
