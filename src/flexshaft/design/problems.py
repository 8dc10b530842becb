"""Input problems: :class:`Problem` (where and what) and :class:`DesignError` (all of them).

The design layer's one error type for bad user input; :mod:`flexshaft.design.io` raises it and
:mod:`flexshaft.design.messages` words pydantic's validation errors as problems.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

__all__ = ["DesignError", "Problem"]


@dataclass(frozen=True)
class Problem:
    """One input problem: where (a field path such as ``bearings[2].x``, or a file) and what."""

    path: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}: {self.message}"


class DesignError(ValueError):
    """A design file or design override that cannot be accepted.

    Attributes
    ----------
    problems
        Every problem found, each with a field path and a message.
    source
        The file the design came from, ``"<string>"`` or ``"<overrides>"``.
    """

    def __init__(self, problems: list[Problem] | tuple[Problem, ...], source: str = "<string>") -> None:
        unique = tuple(dict.fromkeys(Problem(_one_line(p.path), _one_line(p.message)) for p in problems))
        self.problems: tuple[Problem, ...] = unique
        self.source = source
        super().__init__("\n".join(str(problem) for problem in unique))

    def __reduce__(self) -> tuple[Any, ...]:  # picklable across worker processes
        return (type(self), (self.problems, self.source))


_LINE_BREAKS = re.compile("[\x00-\x1f\x7f\x85\u2028\u2029]")


def _one_line(text: str) -> str:
    """Escape control and line-break characters so that each problem stays on one line."""
    return _LINE_BREAKS.sub(lambda match: match.group().encode("unicode_escape").decode("ascii"), text)
