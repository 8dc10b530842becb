"""Property test: malformed design input is either accepted or refused with a DesignError.

Whatever a user feeds :func:`loads_design`, :func:`load_design` or :func:`with_overrides`, the
result is a validated :class:`Design` or a :class:`DesignError` whose message lists problems as
``path: message`` lines; never a pydantic ``ValidationError``, ``KeyError``, ``TypeError``, ...

Example budget (derandomized, no example database, so CI runs the same cases every time):

    mutated baseline tables (junk values, scaled numbers, deletions, extra keys)    500
    baseline lines dropped or shuffled                                              200
    random text as a whole file                                                     300
    random bytes as a whole file, via load_design                                   300
    random override paths and values for with_overrides                            1000
    extreme designs validated or refused                                            500
    extreme designs through build and modes                                         120
    ------------------------------------------------------------------------------------
    total                                                                          2920

Each test also checks that hypothesis really ran at least 90 % of its budget. The suite's CPU
budget (issue 23) sets the first, sixth and seventh budgets (1500, 1600 and 400 before: 15 s of
the file's 20); ``FLEXSHAFT_FUZZ_FACTOR=4 pytest tests/test_design_fuzz.py`` multiplies every
budget for a deeper search (the derandomized examples of a larger budget include the smaller's).
"""

from __future__ import annotations

import dataclasses
import datetime
import json
import math
import os
import pickle
import re
import resource
import tomllib
import tracemalloc
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from flexshaft.assembly import build_model
from flexshaft.assembly.size import check_problem_size
from flexshaft.design import (
    Design,
    DesignError,
    baseline_design,
    baseline_text,
    load_design,
    loads_design,
    with_overrides,
)
from flexshaft.design.schema import format_value
from flexshaft.resolution import REPORT

BASELINE_TEXT = baseline_text()
BASELINE_DATA = tomllib.loads(BASELINE_TEXT)
_BASELINE_PICKLE = pickle.dumps(BASELINE_DATA)


def baseline_data() -> dict[str, Any]:
    """A fresh deep copy of :data:`BASELINE_DATA` (plain TOML data: dicts, lists, strings,
    numbers): unpickled from bytes made once, 5x cheaper than ``copy.deepcopy`` (CPU budget,
    issue 23)."""
    return pickle.loads(_BASELINE_PICKLE)


BASELINE_DESIGN = baseline_design()


def fuzz_settings(max_examples: int) -> settings:
    return settings(
        max_examples=max_examples,
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much],
    )


# ------------------------------------------------------------------------------------------------
# A minimal TOML writer (everything as inline tables) so mutated dicts become real TOML text


_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")
#: A basic string's escapes: the quote and the backslash, and every control character as \uXXXX.
_ESCAPES = str.maketrans({'"': '\\"', "\\": "\\\\", **{chr(c): f"\\u{c:04x}" for c in (*range(0x20), 0x7F)}})


def toml_key(key: str) -> str:
    return key if _BARE_KEY.fullmatch(key) else toml_string(key)


def toml_string(text: str) -> str:
    return '"' + text.translate(_ESCAPES) + '"'


def toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return toml_string(value)
    if isinstance(value, (datetime.date, datetime.datetime)):
        return value.isoformat()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(item) for item in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{toml_key(k)} = {toml_value(v)}" for k, v in value.items()) + "}"
    raise TypeError(type(value))


def toml_document(data: dict[str, Any]) -> str:
    return "".join(f"{toml_key(key)} = {toml_value(value)}\n" for key, value in data.items())


def test_toml_writer_round_trips_the_baseline() -> None:
    assert tomllib.loads(toml_document(BASELINE_DATA)) == BASELINE_DATA
    assert loads_design(toml_document(BASELINE_DATA)) == BASELINE_DESIGN


# ------------------------------------------------------------------------------------------------
# The property

QUOTED = r'"(?:[^"\\]|\\.)*"'
SEGMENT = rf"(?:[A-Za-z0-9_-]+|{QUOTED})"
FIELD_PATH = re.compile(rf"{SEGMENT}(?:\[\d+\]|\.{SEGMENT})*")


def check(thunk: Callable[[], Any], *, schema_only: bool = False) -> None:
    """The call returns a Design or raises a DesignError naming a path in every line."""
    try:
        result = thunk()
    except DesignError as error:
        text = str(error)
        assert text.strip(), "empty DesignError message"
        assert error.problems, "DesignError without problems"
        assert len(text.splitlines()) == len(error.problems)
        for problem in error.problems:
            assert problem.path.strip() and problem.message.strip(), repr(problem)
            assert str(problem) in text
            if schema_only:  # the TOML was valid, so every problem must name a field
                assert FIELD_PATH.fullmatch(problem.path), f"not a field path: {problem}"
        return
    assert isinstance(result, Design)


# ------------------------------------------------------------------------------------------------
# Strategies

NAMES = [
    "3",
    "",
    " ",
    "nan",
    "inf",
    "-1",
    "(95)s",
    "(55/-55)s",
    "t700_adiprene",
    "al6061_t6",
    "boom_aluminium",
    "lamina",
    "isotropic",
    "contact",
    "active",
    "mid_bay",
    "worst",
    "end_mass",
    "boom",
    "shaft",
    "theta",
    "u",
    "kp",
    "kind",
    "x",
]
FIELD_NAMES = [
    "kind",
    "x",
    "x_boom",
    "kp",
    "kd",
    "controller",
    "stiffness",
    "damping",
    "offset",
    "layup",
    "speed",
    "speed_rpm",
    "F12",
    "end_mass",
    "name",
    "tailboom",
    "disks",
    "point",
    "line",
    "theta",
]
scalars = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, -1.0, -1e-300, 1e300, 1.7e308, 5e-324, 90.0001, -90.0, 0.5, 1.0]),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.sampled_from([0, -1, 1, 2000, 2001, 10**400]),
    st.booleans(),
    st.text(max_size=12),
    st.sampled_from(NAMES),
    st.dates(),
)
containers = st.recursive(
    scalars,
    lambda children: st.one_of(
        st.lists(children, max_size=4),
        st.dictionaries(st.one_of(st.text(max_size=6), st.sampled_from(FIELD_NAMES)), children, max_size=4),
    ),
    max_leaves=8,
)
junk = st.one_of(scalars, containers)  # scalars about half of the time
FACTORS = [-1.0, 0.0, 1e-9, 0.5, 0.999, 1.001, 2.0, 10.0, 1e9, math.nan, math.inf, -math.inf]


def all_paths(node: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    paths = [prefix]
    if isinstance(node, dict):
        for key, value in node.items():
            paths += all_paths(value, prefix + (key,))
    elif isinstance(node, list):
        for index, value in enumerate(node):
            paths += all_paths(value, prefix + (index,))
    return paths


PATHS = all_paths(BASELINE_DATA)
MUTABLE_PATHS = [path for path in PATHS if path]


def resolve(data: Any, path: tuple[Any, ...]) -> tuple[Any, Any] | None:
    """(container, key) of path in data, or None when the path no longer exists."""
    node = data
    for part in path[:-1]:
        if isinstance(node, dict) and part in node:
            node = node[part]
        elif isinstance(node, list) and isinstance(part, int) and part < len(node):
            node = node[part]
        else:
            return None
    last = path[-1]
    if isinstance(node, dict) and last in node or isinstance(node, list) and isinstance(last, int) and last < len(node):
        return node, last
    return None


def apply(data: dict[str, Any], operation: tuple[str, tuple[Any, ...], Any, str]) -> None:
    kind, path, value, new_key = operation
    if kind == "add":
        node = resolve(data, path) if path else (None, None)
        table = data if not path else (node[0][node[1]] if node else None)
        if isinstance(table, dict):
            table[new_key] = value
        return
    found = resolve(data, path)
    if found is None:
        return
    container, key = found
    if kind == "replace":
        container[key] = value
    elif kind == "scale":  # keep the type, move the number across its bounds
        old = container[key]
        if isinstance(old, (int, float)) and not isinstance(old, bool):
            factor = FACTORS[len(new_key) % len(FACTORS)]
            try:
                scaled = (old if old != 0 else 1.0) * factor
            except OverflowError:  # an int beyond float range (from an earlier "replace")
                scaled = math.inf
            container[key] = int(scaled) if isinstance(old, int) and math.isfinite(scaled) else scaled
    elif kind == "delete":
        del container[key]


operations = st.tuples(
    st.sampled_from(["replace", "scale", "scale", "delete", "add"]),
    st.sampled_from(PATHS),
    junk,
    st.one_of(st.sampled_from(FIELD_NAMES), st.text(max_size=8)),
).filter(lambda op: op[0] == "add" or op[1] != ())


# ------------------------------------------------------------------------------------------------
# The tests


#: Multiplies every example budget (a deeper search than the suite's: see the module docstring).
FUZZ_FACTOR = float(os.environ.get("FLEXSHAFT_FUZZ_FACTOR", "1"))


def run_counted(max_examples: int, strategy: st.SearchStrategy[Any], body: Callable[[Any], None]) -> None:
    max_examples = max(1, round(max_examples * FUZZ_FACTOR))
    calls = 0

    @fuzz_settings(max_examples)
    @given(strategy)
    def property_test(example: Any) -> None:
        nonlocal calls
        calls += 1
        body(example)

    property_test()
    assert calls >= 0.9 * max_examples, f"hypothesis ran only {calls} of {max_examples} examples"


def test_mutated_baseline_tables() -> None:
    def body(ops: list[tuple[str, tuple[Any, ...], Any, str]]) -> None:
        data = baseline_data()
        for operation in ops:
            apply(data, operation)
        text = toml_document(data)
        check(lambda: loads_design(text), schema_only=True)

    run_counted(500, st.lists(operations, min_size=1, max_size=3), body)


def test_dropped_and_shuffled_baseline_lines() -> None:
    lines = BASELINE_TEXT.splitlines(keepends=True)
    dropped = st.sets(st.integers(0, len(lines) - 1), min_size=1, max_size=8).map(
        lambda drop: "".join(line for index, line in enumerate(lines) if index not in drop)
    )
    shuffled = st.lists(st.sampled_from(lines), max_size=60).map("".join)
    run_counted(200, st.one_of(dropped, shuffled), lambda text: check(lambda: loads_design(text)))


def test_random_text_files() -> None:
    texts = st.one_of(
        st.text(max_size=300),
        st.text(alphabet=st.sampled_from('[]{}="\n .,abxyz0123456789-+einf'), max_size=200),
        st.builds(
            lambda cut, tail: BASELINE_TEXT[:cut] + tail, st.integers(0, len(BASELINE_TEXT)), st.text(max_size=20)
        ),
    )
    run_counted(300, texts, lambda text: check(lambda: loads_design(text)))


def test_random_bytes_files(tmp_path: Path) -> None:
    file = tmp_path / "fuzz.toml"
    raw = BASELINE_TEXT.encode("utf-8")
    flipped = st.tuples(st.integers(0, len(raw) - 1), st.binary(min_size=1, max_size=4)).map(
        lambda edit: raw[: edit[0]] + edit[1] + raw[edit[0] + len(edit[1]) :]
    )

    def body(blob: bytes) -> None:
        file.write_bytes(blob)
        check(lambda: load_design(file))

    run_counted(300, st.one_of(st.binary(max_size=300), flipped), body)


def override_path(path: tuple[Any, ...]) -> str:
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text


OVERRIDE_PATHS = [override_path(path) for path in MUTABLE_PATHS]
paths = st.one_of(
    st.sampled_from(OVERRIDE_PATHS),
    st.sampled_from(OVERRIDE_PATHS),
    st.builds(
        lambda base, suffix: base + suffix,
        st.sampled_from(OVERRIDE_PATHS),
        st.sampled_from(["[0]", "[99]", ".x", ".kind", "..", "]", "[", '."q"', ".", " ", "[-1]"]),
    ),
    st.text(max_size=20),
)
override_values = st.one_of(junk, st.none(), st.sampled_from([0.002, 2e6, "(45/-45)s", 3000, "isotropic"]))


def test_random_overrides() -> None:
    def body(mapping: Any) -> None:
        check(lambda: with_overrides(BASELINE_DESIGN, mapping))

    existing_paths = st.sampled_from(OVERRIDE_PATHS)
    run_counted(600, st.dictionaries(existing_paths, st.one_of(override_values, scalars), min_size=1, max_size=3), body)
    run_counted(250, st.dictionaries(paths, override_values, min_size=1, max_size=3), body)
    not_a_path_mapping = st.one_of(
        st.dictionaries(st.one_of(st.integers(), st.none(), st.floats()), override_values, max_size=2), junk
    )
    run_counted(150, not_a_path_mapping, body)


# ------------------------------------------------------------------------------------------------
# Exhaustive companions: every number and every table of the baseline, one at a time


def value_at(data: Any, path: tuple[Any, ...]) -> Any:
    for part in path:
        data = data[part]
    return data


NUMBER_PATHS = [
    path
    for path in MUTABLE_PATHS
    if isinstance(value_at(BASELINE_DATA, path), (int, float)) and not isinstance(value_at(BASELINE_DATA, path), bool)
]
TABLE_PATHS = [path for path in PATHS if isinstance(value_at(BASELINE_DATA, path), dict) and path != ("materials",)]


@pytest.mark.parametrize(
    "bad", [math.nan, math.inf, -math.inf, "3", True], ids=["nan", "inf", "-inf", "string", "bool"]
)
def test_every_number_refuses_non_numbers(bad: Any) -> None:
    assert len(NUMBER_PATHS) > 50
    for path in NUMBER_PATHS:
        data = baseline_data()
        container, key = resolve(data, path)  # type: ignore[misc]
        container[key] = bad
        with pytest.raises(DesignError) as info:
            loads_design(toml_document(data))
        assert [problem.path for problem in info.value.problems] == [override_path(path)], str(info.value)
        assert format_value(bad) in str(info.value)


def test_every_table_refuses_an_unknown_key() -> None:
    assert len(TABLE_PATHS) > 10
    for path in TABLE_PATHS:
        data = baseline_data()
        value_at(data, path)["zz_extra"] = 1.5
        with pytest.raises(DesignError) as info:
            loads_design(toml_document(data))
        expected = override_path(path + ("zz_extra",))
        assert str(info.value).startswith(f"{expected}: unknown key (got 1.5; allowed: "), str(info.value)


# ------------------------------------------------------------------------------------------------
# Extreme numbers through the analyses (project issue 12): check -> build -> modes -> run
#
# Every example edits the baseline (made small: 2 to 6 shaft elements, 2 to 4 boom elements) with
# extreme values, structural edits that once broke the analyses (stations a hair apart, a
# transfer-function controller, the "worst" placement with many bays, a tiny sensor offset) or
# both, and goes as far as the validation lets it:
#
#     validation only (what `flexshaft check` runs)                             1600 examples
#     validation, build_model and modes(n_modes=4) at the operating speed        400 examples
#     validation, problem-size check, build_model and assess (RUN_RESOLUTION)      4 examples
#
# Allowed outcomes: a validated Design and finite results, or a DesignError / ValueError whose
# message is not empty (SingularSystemError and NonFiniteResultError are ValueErrors too).
# Anything else (a traceback) or a NaN or inf in a result fails the test. Memory: after every
# example the resident peak since the test began (VmHWM) must stay below MEMORY_CAP_BYTES,
# so no example went above it; every 20th analysis example is also traced (tracemalloc sees
# every numpy array; it slows the analyses fourfold, hence not all of them) and its peak must
# stay below TRACED_CAP_BYTES.
#
# Time (2 shared cores): about 12 s, 30 s and 30 s (assess spends 5-10 s in the whirl
# studies whatever the mesh). OUTCOMES collects the outcome classes (printed with -s).


#: Largest resident peak of the test process [bytes], checked after every example.
MEMORY_CAP_BYTES = 1024**3
#: Largest traced allocation peak of one sampled analysis example [bytes].
TRACED_CAP_BYTES = 256 * 1024**2
OUTCOMES: dict[str, dict[str, Any]] = {}


def _resident_peak() -> int:
    """The process's resident peak [bytes] since the test started (Linux's VmHWM, reset by
    :func:`_fresh_resident_peak`); the peak of the process's whole life (ru_maxrss, KiB on Linux)
    where /proc cannot say."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


@pytest.fixture(autouse=True)
def _fresh_resident_peak() -> None:
    """Each test's memory cap holds for its own examples: the kernel's resident high-water mark
    is reset to the current resident size before it (``5 > /proc/self/clear_refs``, Linux 4.0+).
    The peak of the whole process would also count what earlier tests of the same worker held
    (the suite in one process reaches about 1 GB before this module, on no example of its own)."""
    try:
        with open("/proc/self/clear_refs", "w", encoding="ascii") as refs:
            refs.write("5")
    except OSError:  # not Linux, or not allowed: the lifetime peak stands in (ru_maxrss)
        pass


EXTREMES = [
    0.0,
    -0.0,
    5e-324,
    1e-300,
    1e-12,
    1e-6,
    1.0,
    1e6,
    1e12,
    1e15,
    1e300,
    1.7e308,
    float(2**63),
    -1.0,
    math.nan,
    math.inf,
]
RELATIVE = [-1.0, 1e-9, 1e-3, 0.999, 1.0 - 1e-9, 1.0 + 1e-9, 1.001, 1e3, 1e9]
SMALL_MESH = st.tuples(st.integers(2, 6), st.integers(2, 4))


def _bounds(path: tuple[Any, ...]) -> list[float]:
    """The schema's bounds of the number at ``path`` (and values just inside them)."""
    from flexshaft.design.messages import _locate  # the error translator's own lookup of field metadata

    loc: list[Any] = []
    for depth, part in enumerate(path):
        loc.append(part)
        if depth == 1 and path[0] in ("materials", "bearings"):  # pydantic's location names the union tag
            loc.append(value_at(BASELINE_DATA, path[:2])["kind"])
    limits = _locate(tuple(loc)).limits
    out = []
    for key in ("ge", "gt", "le", "lt"):
        if key in limits:
            bound = float(limits[key])
            out += [bound, bound * (1 + 1e-9) if bound > 0 else bound + 1e-12, bound * (1 - 1e-9)]
    return out or [0.0]


BOUND_VALUES = {path: _bounds(path) for path in NUMBER_PATHS}


def _number_edit() -> st.SearchStrategy[tuple[str, tuple[Any, ...], Any]]:
    absolute = st.tuples(st.just("set"), st.sampled_from(NUMBER_PATHS), st.sampled_from(EXTREMES))
    relative = st.tuples(st.just("scale"), st.sampled_from(NUMBER_PATHS), st.sampled_from(RELATIVE))
    at_bound = st.sampled_from(NUMBER_PATHS).flatmap(
        lambda path: st.tuples(st.just("set"), st.just(path), st.sampled_from(BOUND_VALUES[path]))
    )
    return st.one_of(absolute, relative, at_bound, at_bound)


STRUCTURAL = [
    "amb_at_hanger",
    "amb_near_hanger",
    "two_ambs_close",
    "tf_controller",
    "pid_controller",
    "worst",
    "worst_many_bays",
    "tiny_sensor_offset",
    "disk_near_bearing",
    "no_tailboom",
    "distributed",
    "line_load",
]


def _structural(data: dict[str, Any], edit: str, tiny: float) -> None:
    bearings = data["bearings"]
    amb = bearings[1]
    if edit == "amb_at_hanger":
        amb["x"] = bearings[0]["x"]
    elif edit == "amb_near_hanger":
        amb["x"] = bearings[0]["x"] + tiny
    elif edit == "two_ambs_close":
        bearings[2]["x"] = amb["x"] + tiny
    elif edit == "tf_controller":
        for key in ("kp", "kd"):
            amb.pop(key, None)
        amb["controller"] = {"numerator": [2.0e3, 1.0e7], "denominator": [1.0 / 6000.0, 1.0]}
    elif edit == "pid_controller":
        amb.update({"integral_gain": 1e8, "derivative_cutoff": 800.0, "amplifier_bandwidth": 2000.0, "kd": 1e3})
    elif edit in ("worst", "worst_many_bays"):
        data["loads"]["imbalance_placement"] = "worst"
        if edit == "worst_many_bays":
            start, end = data["shaft"]["x_start"], data["shaft"]["x_end"]
            for k in range(12):
                bearings.append(
                    {
                        "name": f"extra_{k}",
                        "kind": "contact",
                        "x": start + (k + 0.5) * (end - start) / 12,
                        "stiffness": {"v": 1e7, "w": 1e7},
                    }
                )
    elif edit == "tiny_sensor_offset":
        amb["sensor_offset"] = tiny
    elif edit == "disk_near_bearing":
        data["disks"] = [
            {"name": "disk", "x": amb["x"] - tiny, "mass": 5.0, "diametral_inertia": 0.1, "polar_inertia": 0.2}
        ]
    elif edit == "no_tailboom":
        data.pop("tailboom", None)
        data["loads"].pop("point", None)
    elif edit == "distributed":
        data["loads"]["imbalance_placement"] = "distributed"
    elif edit == "line_load":
        data["loads"]["line"] = [
            {
                "name": "gust",
                "on": "shaft",
                "x_start": amb["x"],
                "x_end": amb["x"] + tiny,
                "force_per_length": [0.0, 100.0, 0.0],
            }
        ]


def _edited_design_data(example: tuple[Any, ...]) -> dict[str, Any]:
    numbers, structure, tiny, (shaft_elements, boom_elements) = example
    data = baseline_data()
    data["mesh"] = {"shaft_elements": shaft_elements, "boom_elements": boom_elements}
    for edit in structure:
        _structural(data, edit, tiny)
    for kind, path, value in numbers:
        found = resolve(data, path)
        if found is None:
            continue
        container, key = found
        old = container[key]
        container[key] = value if kind == "set" else (old if old != 0 else 1.0) * value
        if isinstance(old, int) and not isinstance(old, bool) and math.isfinite(container[key]):
            container[key] = int(container[key]) if abs(container[key]) < 2**62 else container[key]
    return data


extreme_designs = st.tuples(
    st.lists(_number_edit(), min_size=0, max_size=3),
    st.lists(st.sampled_from(STRUCTURAL), min_size=0, max_size=2, unique=True),
    st.sampled_from([1e-12, 1e-9, 1e-6, 1e-3, 0.05]),
    SMALL_MESH,
).filter(lambda example: example[0] or example[1])


def _count(stage: str, outcome: str) -> None:
    OUTCOMES.setdefault(stage, {})
    OUTCOMES[stage][outcome] = OUTCOMES[stage].get(outcome, 0) + 1


def _refused(error: BaseException) -> str:
    """The outcome class of an allowed refusal (the test fails on anything else)."""
    assert isinstance(error, ValueError), f"{type(error).__name__} escaped: {error}"
    assert str(error).strip(), f"{type(error).__name__} without a message"
    if isinstance(error, DesignError):
        assert error.problems and all(p.path.strip() and p.message.strip() for p in error.problems)
    return type(error).__name__


def _all_finite(name: str, value: Any) -> None:
    array = np.asarray(value)
    if array.dtype.kind in "fc":
        assert np.all(np.isfinite(array)), f"{name} holds NaN or inf"


def _validated(text: str) -> Design | str:
    try:
        return loads_design(text)
    except Exception as error:  # noqa: BLE001 - classified, anything but a ValueError fails
        return _refused(error)


def _traced(body: Callable[[], Any]) -> tuple[Any, int]:
    tracemalloc.start()
    try:
        return body(), tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_extreme_designs_are_validated_or_refused() -> None:
    def body(example: tuple[Any, ...]) -> None:
        design = _validated(toml_document(_edited_design_data(example)))
        _count("check", design if isinstance(design, str) else "valid")

    run_counted(500, extreme_designs, body)


def _modes_outcome(design: Design) -> str:
    from flexshaft.analyses import modes

    try:
        model = build_model(design)
        result = modes(model, model.speed, 4)
    except Exception as error:  # noqa: BLE001
        return _refused(error)
    _all_finite("eigenvalues", result.eigenvalues)
    _all_finite("mode shapes", result.shapes)
    _all_finite("frequencies", result.frequencies)
    return "modes"


def test_extreme_designs_through_build_and_modes() -> None:
    def body(example: tuple[Any, ...]) -> None:
        design = _validated(toml_document(_edited_design_data(example)))
        if isinstance(design, str):
            _count("modes", f"refused by check ({design})")
            return
        nonlocal examples
        examples += 1
        if examples % 20 == 0:
            outcome, peak = _traced(lambda: _modes_outcome(design))
            assert peak <= TRACED_CAP_BYTES, f"modes: traced peak {peak / 1e6:.0f} MB"
            peaks = OUTCOMES.setdefault("traced_peak_bytes", {})
            peaks["modes"] = max(peaks.get("modes", 0), peak)
        else:
            outcome = _modes_outcome(design)
        assert _resident_peak() <= MEMORY_CAP_BYTES, f"resident peak {_resident_peak() / 1e6:.0f} MB"
        _count("modes", outcome)

    examples = 0

    run_counted(120, extreme_designs, body)


def _run_outcome(design: Design) -> str:
    from flexshaft.analyses.summary import modes_table
    from flexshaft.verdict.assess import assess

    try:
        check_problem_size(design, "run")
        results = assess(design, RUN_RESOLUTION)
    except Exception as error:  # noqa: BLE001
        return _refused(error)
    spinup = results.spinup
    for name, values in (
        ("speeds", spinup.speeds),
        ("shaft_peak", spinup.shaft_peak),
        ("shaft_envelope", spinup.envelope),
        ("static_displacement", results.static_displacement),
        ("imbalance_at_speed", results.imbalance_at_speed),
    ):
        _all_finite(name, values)
    _all_finite("Campbell eigenvalues", results.campbell.eigenvalues)
    _all_finite("mode shapes", results.modes_at_speed.shapes)
    for name, values in {**spinup.actuator_displacement, **spinup.actuator_force}.items():
        _all_finite(f"actuator {name}", values)
    for row in modes_table(results.modes_at_rest) + modes_table(results.modes_at_speed):
        assert all(math.isfinite(value) for value in row.values() if isinstance(value, float)), row
    for strength in (results.strength_static, results.strength_total):
        if strength is not None:
            assert not math.isnan(strength.safety_factor)
    return "run"


#: The run share's resolution: the report's (its Campbell diagram, modes at rest and every detail
#: of the report), with the spin-up and whirl-stability grids thinned to every 5th and every 4th
#: of the report's speeds (:func:`test_the_run_resolution_thins_the_reports_grids`): every analysis
#: of ``flexshaft run`` at every point of the envelope, on fewer speeds (CPU budget, issue 23:
#: 5.2 s instead of 6.8 for the four examples).
RUN_RESOLUTION = dataclasses.replace(REPORT, name="fuzz run", spinup_speeds=131, whirl_speeds=11)


def test_the_run_resolution_thins_the_reports_grids() -> None:
    for speed in (0.0, 502.65):  # at rest (the ranges scale 1 rad/s) and at 4800 rpm
        np.testing.assert_allclose(RUN_RESOLUTION.spin_speeds(speed), REPORT.spin_speeds(speed)[::5], rtol=1e-14)
        np.testing.assert_allclose(
            RUN_RESOLUTION.stability_speeds(speed), REPORT.stability_speeds(speed)[::4], rtol=1e-14, atol=1e-300
        )
    assert (RUN_RESOLUTION.campbell_speeds, RUN_RESOLUTION.report_detail) == (REPORT.campbell_speeds, True)
    assert (RUN_RESOLUTION.modes, RUN_RESOLUTION.campbell_modes) == (REPORT.modes, REPORT.campbell_modes)


#: The run share: one example of each kind that reaches assess (the baseline made small, a
#: transfer-function bearing a hair from the hanger, the "worst" placement, extreme numbers).
RUN_EXAMPLES = [
    ([], ["amb_near_hanger", "tf_controller"], 1e-9, (4, 2)),
    ([("scale", ("bearings", 0, "stiffness", "v"), 1e3)], ["worst", "tiny_sensor_offset"], 1e-6, (3, 2)),
    (
        [("set", ("materials", "t700_adiprene", "density"), 1e-6), ("set", ("loads", "eccentricity"), 1e-12)],
        ["no_tailboom", "disk_near_bearing"],
        1e-3,
        (4, 2),
    ),
    (
        [("scale", ("operating", "speed_rpm"), 1e-3), ("set", ("bearings", 1, "kp"), 1e10)],
        ["pid_controller"],
        1e-12,
        (2, 2),
    ),
]


@pytest.mark.parametrize("example", RUN_EXAMPLES, ids=["tf_bearing_near_hanger", "worst", "massless_no_boom", "pid"])
def test_extreme_designs_through_run(example: tuple[Any, ...]) -> None:
    design = _validated(toml_document(_edited_design_data(example)))
    assert not isinstance(design, str), design
    outcome = _run_outcome(design)
    assert outcome == "run", outcome
    assert _resident_peak() <= MEMORY_CAP_BYTES, f"resident peak {_resident_peak() / 1e6:.0f} MB"
    _count("run", outcome)


def test_fuzz_outcomes_summary() -> None:
    """Print the outcome classes of the fuzz tests that ran in this process (run with -s): every
    class counted at least once."""
    print("\nfuzz outcomes:", json.dumps(OUTCOMES, indent=1, default=str))
    counts = [n for stage, classes in OUTCOMES.items() if stage != "traced_peak_bytes" for n in classes.values()]
    assert all(isinstance(n, int) and n > 0 for n in counts)
