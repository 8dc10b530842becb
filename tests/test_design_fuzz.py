"""Property test: malformed design input is either accepted or refused with a DesignError.

Whatever a user feeds :func:`loads_design`, :func:`load_design` or :func:`with_overrides`, the
result is a validated :class:`Design` or a :class:`DesignError` whose message lists problems as
``path: message`` lines; never a pydantic ``ValidationError``, ``KeyError``, ``TypeError``, ...

Example budget (derandomized, no example database, so CI runs the same cases every time):

    mutated baseline tables (junk values, scaled numbers, deletions, extra keys)   1500
    baseline lines dropped or shuffled                                              400
    random text as a whole file                                                     300
    random bytes as a whole file, via load_design                                   300
    random override paths and values for with_overrides                            1000
    ------------------------------------------------------------------------------------
    total                                                                          3500

Each test also checks that hypothesis really ran at least 90 % of its budget. With the exhaustive
per-number and per-table checks at the end, the file takes about 7 s (2-core machine).
"""

from __future__ import annotations

import copy
import datetime
import math
import re
import tomllib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from flexshaft.design import Design, DesignError, baseline_design, baseline_text, load_design, loads_design, with_overrides
from flexshaft.design.schema import format_value

BASELINE_TEXT = baseline_text()
BASELINE_DATA = tomllib.loads(BASELINE_TEXT)
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


def toml_key(key: str) -> str:
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else toml_string(key)


def toml_string(text: str) -> str:
    out = []
    for char in text:
        if char in '"\\':
            out.append("\\" + char)
        elif ord(char) < 0x20 or ord(char) == 0x7F:
            out.append(f"\\u{ord(char):04x}")
        else:
            out.append(char)
    return '"' + "".join(out) + '"'


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
    "3", "", " ", "nan", "inf", "-1", "(95)s", "(55/-55)s", "t700_adiprene", "al6061_t6",
    "boom_aluminium", "lamina", "isotropic", "contact", "active", "mid_bay", "worst", "end_mass",
    "boom", "shaft", "theta", "u", "kp", "kind", "x",
]
FIELD_NAMES = [
    "kind", "x", "x_boom", "kp", "kd", "controller", "stiffness", "damping", "offset", "layup",
    "speed", "speed_rpm", "F12", "end_mass", "name", "tailboom", "disks", "point", "line", "theta",
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


def run_counted(max_examples: int, strategy: st.SearchStrategy[Any], body: Callable[[Any], None]) -> None:
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
        data = copy.deepcopy(BASELINE_DATA)
        for operation in ops:
            apply(data, operation)
        text = toml_document(data)
        check(lambda: loads_design(text), schema_only=True)

    run_counted(1500, st.lists(operations, min_size=1, max_size=3), body)


def test_dropped_and_shuffled_baseline_lines() -> None:
    lines = BASELINE_TEXT.splitlines(keepends=True)
    dropped = st.sets(st.integers(0, len(lines) - 1), min_size=1, max_size=8).map(
        lambda drop: "".join(line for index, line in enumerate(lines) if index not in drop)
    )
    shuffled = st.lists(st.sampled_from(lines), max_size=60).map("".join)
    run_counted(400, st.one_of(dropped, shuffled), lambda text: check(lambda: loads_design(text)))


def test_random_text_files() -> None:
    texts = st.one_of(
        st.text(max_size=300),
        st.text(alphabet=st.sampled_from('[]{}="\n .,abxyz0123456789-+einf'), max_size=200),
        st.builds(lambda cut, tail: BASELINE_TEXT[:cut] + tail, st.integers(0, len(BASELINE_TEXT)), st.text(max_size=20)),
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
    path for path in MUTABLE_PATHS
    if isinstance(value_at(BASELINE_DATA, path), (int, float)) and not isinstance(value_at(BASELINE_DATA, path), bool)
]
TABLE_PATHS = [path for path in PATHS if isinstance(value_at(BASELINE_DATA, path), dict) and path != ("materials",)]


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, "3", True], ids=["nan", "inf", "-inf", "string", "bool"])
def test_every_number_refuses_non_numbers(bad: Any) -> None:
    assert len(NUMBER_PATHS) > 50
    for path in NUMBER_PATHS:
        data = copy.deepcopy(BASELINE_DATA)
        container, key = resolve(data, path)  # type: ignore[misc]
        container[key] = bad
        with pytest.raises(DesignError) as info:
            loads_design(toml_document(data))
        assert [problem.path for problem in info.value.problems] == [override_path(path)], str(info.value)
        assert format_value(bad) in str(info.value)


def test_every_table_refuses_an_unknown_key() -> None:
    assert len(TABLE_PATHS) > 10
    for path in TABLE_PATHS:
        data = copy.deepcopy(BASELINE_DATA)
        value_at(data, path)["zz_extra"] = 1.5
        with pytest.raises(DesignError) as info:
            loads_design(toml_document(data))
        expected = override_path(path + ("zz_extra",))
        assert str(info.value).startswith(f"{expected}: unknown key (got 1.5; allowed: "), str(info.value)
