"""The guards applied to design text before the TOML parser, against docs/limits.md section 4.

docs/limits.md, "4. The design file" (hand-written): "``load_design`` reads regular files only
... of at most 1 MB (the baseline is 9 KB). Before the TOML parser runs, the text is refused if a
line is longer than 10,000 characters, a dotted key or table header has more than 32 parts, or
arrays and inline tables nest more than 32 deep". The guards' own documented rule
(flexshaft.design.reading's module docstring): "Each limit is reported as one Problem line naming
the file (and the line), the value found and the limit".

Each test builds its input by hand, so the expected line numbers and sizes are counted here, not
taken from the code. No numerics: the comparisons are exact integers and strings.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from flexshaft.design.io import DesignError, load_design, loads_design, tuned_design
from flexshaft.design.reading import text_problems

#: docs/limits.md's "1 MB", read as SI 10^6 bytes (README: 1,000,000 bytes); one byte above
#: 2^20 is too large under either reading of "MB".
ABOVE_BOTH_LIMITS = 2**20 + 1
#: Well below either reading (the baseline is 9 KB).
BELOW_BOTH_LIMITS = 900_000


def _padded_design(total: int) -> str:
    """The packaged tuned design, valid, padded with comment lines to exactly ``total``
    characters (its UTF-8 bytes are as many plus one per extra byte of its few non-ASCII
    characters). Comment lines of 100 characters keep every line far below the 10,000-character
    line limit, so only the size can be refused."""
    from flexshaft.design.io import embedded_text

    text = embedded_text("tuned")
    if not text.endswith("\n"):
        text += "\n"
    missing = total - len(text)
    line = "#" + "x" * 98 + "\n"  # 100 characters with its line break
    padding = line * (missing // len(line))
    rest = missing - len(padding)
    if rest:
        padding += "#" * (rest - 1) + "\n" if rest > 1 else "\n"
    padded = text + padding
    assert len(padded) == total
    return padded


def test_a_design_file_over_one_megabyte_is_refused_naming_the_limit(tmp_path: Path) -> None:
    """A valid design padded to 2^20 + 1 bytes of comments exceeds the documented "at most 1 MB":
    load_design and loads_design refuse it with one problem naming the limit as docs/limits.md
    states it, SI 10^6 = "1,000,000" bytes, before parsing. The same design padded to 900,000
    bytes is below the limit and loads (where between the two the refusal starts is left open)."""
    big = _padded_design(ABOVE_BOTH_LIMITS)
    path = tmp_path / "big.toml"
    path.write_text(big, encoding="utf-8")
    with pytest.raises(DesignError) as caught:
        load_design(path)
    assert len(caught.value.problems) == 1
    assert "1,000,000" in caught.value.problems[0].message
    with pytest.raises(DesignError) as caught:
        loads_design(big)
    assert len(caught.value.problems) == 1
    assert "1,000,000" in caught.value.problems[0].message

    small = tmp_path / "padded.toml"
    small.write_text(_padded_design(BELOW_BOTH_LIMITS), encoding="utf-8")
    assert small.stat().st_size < 10**6
    assert load_design(small).name == tuned_design().name


def _nested(depth: int) -> str:
    """``x = [[...[1]...]]`` with ``depth`` arrays, one inside the other (valid TOML)."""
    return "x = " + "[" * depth + "1" + "]" * depth + "\n"


def test_nesting_of_exactly_32_is_accepted_and_33_refused() -> None:
    """docs/limits.md refuses arrays and inline tables that "nest more than 32 deep": 32 nested
    arrays pass the guard (the schema judges them later), 33 are refused on line 1 naming the
    limit 32. Inline tables count alike: 32 nested ``{a = ...}`` pass."""
    assert text_problems(_nested(32)) == []
    refused = text_problems(_nested(33))
    assert len(refused) == 1
    assert refused[0].startswith("line 1:")
    assert "at most 32" in refused[0]
    tables = "x = " + "{a = " * 32 + "1" + "}" * 32 + "\n"
    assert text_problems(tables) == []


def test_a_32_deep_array_in_a_design_reaches_the_schema_not_the_guard() -> None:
    """The product path: a design text with a 32-deep array under an unknown key is parsed and
    refused by the schema (naming the key), not by the nesting guard, which only refuses more
    than 32 levels (docs/limits.md)."""
    from flexshaft.design.io import embedded_text

    text = "zz_extra = " + "[" * 32 + "1" + "]" * 32 + "\n" + embedded_text("tuned")
    with pytest.raises(DesignError) as caught:
        loads_design(text)
    messages = [str(problem) for problem in caught.value.problems]
    assert any(message.startswith("zz_extra:") for message in messages), messages
    assert not any("nested" in message for message in messages), messages


@pytest.mark.parametrize("quote", ['"""', "'''"])
def test_line_numbers_count_the_lines_of_a_multiline_string(quote: str) -> None:
    """A refusal names the line of the file where it is: after a multi-line string spanning lines
    1 to 4 (three line breaks inside it), a 33-part dotted key on line 6 is reported as line 6,
    counted by hand on the text below; likewise a 33-deep array on line 7."""
    key = ".".join(["a"] * 33)
    text = (
        f"notes = {quote}first\n"  # line 1
        "second\n"  # line 2
        "third\n"  # line 3
        f"fourth{quote}\n"  # line 4
        "name = 'x'\n"  # line 5
        f"{key} = 1\n"  # line 6
    )
    refused = text_problems(text)
    assert len(refused) == 1
    assert refused[0].startswith("line 6:"), refused
    assert "33 parts" in refused[0]
    with pytest.raises(DesignError) as caught:
        loads_design(text)
    assert caught.value.problems[0].message.startswith("line 6:")

    nested = text.replace(f"{key} = 1\n", "ok = 1\n") + _nested(33)  # the array on line 7
    refused = text_problems(nested)
    assert len(refused) == 1
    assert refused[0].startswith("line 7:"), refused
