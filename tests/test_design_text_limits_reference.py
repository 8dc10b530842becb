"""The design-file text limits at their documented edges (docs/limits.md, section 4).

docs/limits.md: "the text is refused if a line is longer than 10,000 characters, a dotted key
or table header has more than 32 parts, or arrays and inline tables nest more than 32 deep".
So a line of exactly 10,000 characters, a 32-part key and any number of inline tables that are
each closed on their line are accepted; one more character or part is refused. The schema's
own deepest key has 4 parts (``materials.<name>.temperature_table.E_T``), which a design file
may write as one dotted key. Text only: no design is built (microseconds each).
"""

from __future__ import annotations

from flexshaft.design.reading import text_problems


def test_a_line_of_exactly_ten_thousand_characters_is_accepted() -> None:
    line = "# " + "x" * 9_998
    assert len(line) == 10_000 and text_problems(line + "\n") == []
    problems = text_problems(line + "x\n")
    assert len(problems) == 1 and "line 1 is 10,001 characters long" in problems[0]


def test_dotted_keys_up_to_32_parts_and_the_schema_s_four() -> None:
    assert text_problems("materials.cf.temperature_table.E_T = [1.0, 2.0]\n") == []
    assert text_problems(".".join(f"k{i}" for i in range(32)) + " = 1\n") == []
    problems = text_problems(".".join(f"k{i}" for i in range(33)) + " = 1\n")
    assert len(problems) == 1 and "33 parts" in problems[0]


def test_many_closed_inline_tables_are_not_nesting() -> None:
    """40 inline tables, each closed on its line: the nesting depth is 1 on every line."""
    text = "".join(f"t{i} = {{a = 1, b = [2, 3]}}\n" for i in range(40))
    assert text_problems(text) == []
    nested = "x = " + "{a = " * 33 + "1" + "}" * 33 + "\n"
    problems = text_problems(nested)
    assert len(problems) == 1 and "nested more than 32" in problems[0]
