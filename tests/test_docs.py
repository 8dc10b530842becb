"""The documentation agrees with the code.

* ``docs/design-reference.md`` and ``docs/design.schema.json`` are what
  :mod:`flexshaft.design.reference` renders from the schema now (regenerate them with the two
  commands in that module's docstring), and the reference covers every key of every table
  with a description;
* the JSON schema accepts the packaged designs and refuses what the pydantic schema refuses
  key by key (an unknown key, a value out of range, a wrong type, an unknown kind);
* the docstring examples of the package run (doctest);
* the docs, the README, the sources and the packaged TOML files name no file that is not in
  the repository, and the Markdown links of the docs resolve.
"""

from __future__ import annotations

import copy
import doctest
import importlib
import json
import re
import tomllib
from pathlib import Path

import pytest

import flexshaft
from flexshaft.design import Design, baseline_text, design_from_dict, embedded_text
from flexshaft.design.reference import (
    REGENERATE_JSON,
    REGENERATE_MARKDOWN,
    design_json_schema,
    design_reference,
    design_tables,
)

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = Path(flexshaft.__file__).resolve().parent
DOCS = ROOT / "docs"


# ------------------------------------------------------------------------------------------------
# The generated reference


def test_committed_reference_matches_the_schema():
    committed = (DOCS / "design-reference.md").read_text(encoding="utf-8")
    assert committed == design_reference(), f"docs/design-reference.md is stale: run `{REGENERATE_MARKDOWN}`"


def test_committed_json_schema_matches_the_schema():
    committed = json.loads((DOCS / "design.schema.json").read_text(encoding="utf-8"))
    assert committed == design_json_schema(), f"docs/design.schema.json is stale: run `{REGENERATE_JSON}`"


def _models_in_json_schema() -> set[str]:
    schema = Design.model_json_schema()
    return {"Design", *schema["$defs"]}


def test_reference_covers_every_table_and_key():
    """Independent of the generator's walk: every model pydantic exports has a section, and each
    section lists exactly the model's fields, each with a description."""
    tables = design_tables()
    assert {table.model.__name__ for table in tables} == _models_in_json_schema()
    for table in tables:
        assert [f.key for f in table.fields] == list(table.model.model_fields), table.header
        undocumented = [f.key for f in table.fields if not f.description]
        assert not undocumented, f"{table.title}: no description for {undocumented}"


def test_every_number_has_a_unit():
    missing = [
        f"{table.title} {field.key}"
        for table in design_tables()
        for field in table.fields
        if field.type.split(",")[0] in ("float", "array of 2 floats", "array of 3 floats", "inline table of floats")
        and not field.unit
    ]
    assert not missing, missing


def test_reference_names_the_baseline_keys():
    """Every key used by the packaged baseline appears in the reference (a spot check that the
    rendering reached the nested tables and the arrays of tables)."""
    text = design_reference()
    data = tomllib.loads(baseline_text())

    def keys(node):
        if isinstance(node, dict):
            for key, value in node.items():
                yield key
                yield from keys(value)
        elif isinstance(node, list):
            for item in node:
                yield from keys(item)

    names = set(keys(data)) - set(data["materials"])  # material names are the user's
    missing = [key for key in sorted(names) if f"`{key}`" not in text]
    assert not missing, missing


# ------------------------------------------------------------------------------------------------
# The JSON schema against the packaged designs (needs the jsonschema package)


@pytest.fixture(scope="module")
def validator():
    jsonschema = pytest.importorskip("jsonschema")
    schema = json.loads((DOCS / "design.schema.json").read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


@pytest.mark.parametrize("name", ["baseline", "tuned"])
def test_json_schema_accepts_the_packaged_designs(validator, name):
    assert list(validator.iter_errors(tomllib.loads(embedded_text(name)))) == []


@pytest.mark.parametrize(
    "change",
    [
        lambda d: d["shaft"].update(bogus=1.0),  # unknown key
        lambda d: d["shaft"].update(outer_diameter=-0.1),  # out of range
        lambda d: d["operating"].update(speed_rpm="4800"),  # a string for a number
        lambda d: d["bearings"][0].update(kind="hanger"),  # unknown kind
        lambda d: d["analysis"].update(internal_damping="none"),  # not a choice
        lambda d: d.pop("shaft"),  # required table missing
    ],
)
def test_json_schema_refuses_what_the_schema_refuses(validator, change):
    data = copy.deepcopy(tomllib.loads(baseline_text()))
    change(data)
    with pytest.raises(ValueError):
        design_from_dict(data)  # the pydantic schema refuses it ...
    assert list(validator.iter_errors(data))  # ... and so does the JSON schema


# ------------------------------------------------------------------------------------------------
# Doctests


def _modules_with_examples() -> list[str]:
    names = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if ">>> " in path.read_text(encoding="utf-8"):
            parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
            names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


def test_some_modules_have_examples():
    assert len(_modules_with_examples()) >= 3


@pytest.mark.parametrize("name", _modules_with_examples())
def test_docstring_examples_run(name, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # an example that writes files writes them here
    module = importlib.import_module(name)
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testmod(module, optionflags=flags, verbose=False, report=True)
    assert result.attempted > 0
    assert result.failed == 0, f"{result.failed} docstring example(s) of {name} fail (see the output above)"


# ------------------------------------------------------------------------------------------------
# References to files


def _documents() -> list[Path]:
    files = [
        ROOT / "README.md",
        *sorted(DOCS.glob("*.md")),
        *sorted(PACKAGE.rglob("*.py")),
        *sorted(PACKAGE.rglob("*.toml")),
        *sorted((ROOT / "examples").glob("*.py")),
    ]
    return [path for path in files if path.exists()]


_MARKDOWN_FILE = re.compile(r"(?<![\w/.-])((?:[\w.-]+/)*[\w.-]+\.md)\b")


def test_no_reference_to_a_missing_markdown_file():
    missing = []
    for path in _documents():
        for match in _MARKDOWN_FILE.finditer(path.read_text(encoding="utf-8")):
            name = match.group(1)
            candidates = [ROOT / name, DOCS / name, path.parent / name]
            if not any(candidate.exists() for candidate in candidates):
                missing.append(f"{path.relative_to(ROOT)}: {name}")
    assert not missing, "\n".join(missing)


def _anchors(path: Path) -> set[str]:
    """Explicit ``<a id>`` anchors and GitHub's heading slugs of a Markdown file."""
    text = path.read_text(encoding="utf-8")
    headings = re.findall(r"^#+\s+(.+?)\s*$", text, flags=re.MULTILINE)
    slugs = {re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-") for heading in headings}
    return slugs | set(re.findall(r'<a id="([^"]+)"', text))


def test_markdown_links_resolve():
    broken = []
    for path in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]:
        text = path.read_text(encoding="utf-8")
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+://", target) or target.startswith("mailto:"):
                continue
            file, _, anchor = target.partition("#")
            linked = (path.parent / file) if file else path
            if not linked.exists():
                broken.append(f"{path.relative_to(ROOT)}: {target}")
            elif anchor and linked.suffix == ".md" and anchor not in _anchors(linked):
                broken.append(f"{path.relative_to(ROOT)}: {target} (no such heading)")
    assert not broken, "\n".join(broken)


# ------------------------------------------------------------------------------------------------
# Hand-written tables of design keys


@pytest.mark.parametrize("page, header", [("thermal.md", "[thermal]"), ("requirements.md", "[requirements]")])
def test_hand_written_key_tables_name_every_key(page, header):
    """docs/thermal.md and docs/requirements.md explain their tables key by key: each key of
    the schema appears there, and no key that the schema does not have."""
    text = (DOCS / page).read_text(encoding="utf-8")
    table = next(t for t in design_tables() if t.header == header)
    keys = {field.key for field in table.fields}
    missing = [key for key in sorted(keys) if f"`{key}`" not in text]
    assert not missing, f"docs/{page} does not explain {missing}"
    section = text.split(f"`{header}` table", 1)[-1].split("\n## ", 1)[0]  # the section on the table
    rows = re.findall(r"^\| `([a-z_]+)`", section, flags=re.MULTILINE)
    unknown = sorted(set(rows) - keys)
    assert not unknown, f"docs/{page} lists keys the schema does not have: {unknown}"
