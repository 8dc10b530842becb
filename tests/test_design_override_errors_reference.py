"""Override and design-text errors: every problem listed, never a traceback, the file named.

References (hand-written):

* flexshaft.design.io's module docstring: every entry point "either returns a validated Design or
  raises DesignError; no pydantic ValidationError, TOMLDecodeError or OSError escapes for bad
  user input. The error message lists every problem found, one per line".
* README.md, Python API: ``fs.with_overrides(design, {"shaft.wall_thickness": 0.002,
  "bearings[1].kp": 2e6})``: ``[i]`` indexes the design file's ``[[bearings]]`` from 0 (the tuned
  design's bearings[1] is its first magnetic bearing, amb_1; the file lists four bearings).
* DesignError's docstring: ``source`` is "the file the design came from, ``"<string>"`` or
  ``"<overrides>"``"; ``flexshaft check --json`` prints it as ``source``.

The expected counts and names are read from the tuned design file by hand; no numerics.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from flexshaft.design.io import DesignError, embedded_text, load_design, loads_design, tuned_design, with_overrides


def test_every_bad_override_path_is_listed() -> None:
    """Three bad paths, of three kinds (unknown key, index out of range, malformed), give three
    problems, each naming its own path: the error lists every problem, not the last one."""
    paths = ["shaft.no_such_table.x", "bearings[7].kp", "bearings..kp"]
    with pytest.raises(DesignError) as caught:
        with_overrides(tuned_design(), dict.fromkeys(paths, 1.0))
    assert [problem.path for problem in caught.value.problems] == paths


def test_an_index_equal_to_the_number_of_items_is_out_of_range() -> None:
    """The tuned design has four [[bearings]] (indices 0 to 3, counted in the file). bearings[4]
    is one past the end: a DesignError naming the index and the four items, not an IndexError
    traceback; bearings[3], the last, is accepted."""
    design = tuned_design()
    assert embedded_text("tuned").count("[[bearings]]") == 4
    with pytest.raises(DesignError) as caught:
        with_overrides(design, {"bearings[4].mass": 1.0})
    (problem,) = caught.value.problems
    assert problem.path == "bearings[4].mass"
    assert "index 4" in problem.message and "4 items" in problem.message
    assert with_overrides(design, {"bearings[3].mass": 1.5}).bearings[3].mass == 1.5


def test_a_schema_problem_names_the_file_it_came_from(tmp_path: Path) -> None:
    """A design file whose TOML is valid but breaks the schema (a negative kp on bearings[1]) is
    refused with ``source`` the file's path, and text given a source name keeps that name: the
    field problem is reported against the file the user wrote, not an anonymous dict."""
    text = embedded_text("tuned").replace("kp = 5.0e5                # N/m", "kp = -5.0e5  # N/m", 1)
    assert text != embedded_text("tuned")
    path = tmp_path / "negative_kp.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(DesignError) as caught:
        load_design(path)
    assert caught.value.source == str(path)
    assert [problem.path for problem in caught.value.problems] == ["bearings[1].kp"]
    with pytest.raises(DesignError) as caught:
        loads_design(text, source="mine.toml")
    assert caught.value.source == "mine.toml"
