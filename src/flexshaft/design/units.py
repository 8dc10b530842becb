"""Unit conversions and string parsers used at the design-file edge.

SI floats inside, units at the edges (STYLE.md principle 5): rev/min and degrees are converted
here and nowhere else in the design package.

The layup parser is a private copy of the laminate notation grammar so that the design schema
does not depend on :mod:`flexshaft.laminate`; the two are to be merged later.
"""

from __future__ import annotations

import math
import re

__all__ = [
    "LayupError",
    "MAX_PLIES",
    "parse_layup_degrees",
    "rad_s_to_rpm",
    "rpm_to_rad_s",
]

#: Upper bound on the number of plies a layup string may expand to.
MAX_PLIES = 1000
#: Upper bound on a single repetition count such as the ``3`` in ``[0/90]3``.
_MAX_REPEAT = 100


def rpm_to_rad_s(speed_rpm: float) -> float:
    """Convert a rotational speed from [rev/min] to [rad/s]."""
    return speed_rpm * 2.0 * math.pi / 60.0


def rad_s_to_rpm(speed: float) -> float:
    """Convert a rotational speed from [rad/s] to [rev/min]."""
    return speed * 60.0 / (2.0 * math.pi)


class LayupError(ValueError):
    """A layup string that does not follow the laminate stacking notation."""


# Tokens: groups, separators, the repetition/symmetry suffix and signed angles.
_TOKEN = re.compile(
    r"""
    \s*(?:
      (?P<open>[(\[])
    | (?P<close>[)\]])
    | (?P<sep>[/,])
    | (?P<pm>±|∓|\+-|-\+|\+/-|-/\+)
    | (?P<number>[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)
    | (?P<deg>°|deg\b)
    | (?P<sub>_)
    | (?P<sym>[sS])
    )
    """,
    re.VERBOSE,
)


def _tokenize(text: str) -> list[tuple[str, str, int]]:
    tokens: list[tuple[str, str, int]] = []
    pos = 0
    stripped = text.rstrip()
    while pos < len(stripped):
        match = _TOKEN.match(stripped, pos)
        if match is None or match.end() == pos:
            bad = stripped[pos:].lstrip()[:1]
            raise LayupError(f"unexpected character {bad!r} at position {pos + 1}")
        kind = match.lastgroup
        assert kind is not None
        tokens.append((kind, match.group(kind), match.start(kind)))
        pos = match.end()
    return tokens


class _Parser:
    """Recursive-descent parser for the stacking notation.

    Grammar (whitespace ignored)::

        layup    := sequence
        sequence := item (("/" | ",") item)*
        item     := group | angle
        group    := ("(" sequence ")" | "[" sequence "]") suffix
        suffix   := [INT] ["s"]          # repeat INT times, then mirror
        angle    := [("±" | "∓" | "+-" | "-+")] NUMBER ["°"] ["_" INT]
    """

    def __init__(self, text: str) -> None:
        self.text = text
        self.tokens = _tokenize(text)
        self.index = 0

    def peek(self) -> tuple[str, str, int] | None:
        return self.tokens[self.index] if self.index < len(self.tokens) else None

    def take(self) -> tuple[str, str, int]:
        token = self.tokens[self.index]
        self.index += 1
        return token

    def fail(self, what: str) -> LayupError:
        token = self.peek()
        where = f"{token[1]!r} at position {token[2] + 1}" if token else "end of text"
        return LayupError(f"expected {what}, found {where}")

    def parse(self) -> list[float]:
        if not self.tokens:
            raise LayupError("empty layup")
        plies = self.sequence(depth=0)
        if self.peek() is not None:
            raise self.fail("'/' or the end of the layup")
        return plies

    def sequence(self, depth: int) -> list[float]:
        plies = self.item(depth)
        while (token := self.peek()) is not None and token[0] == "sep":
            self.take()
            plies = plies + self.item(depth)
            _check_count(plies)
        return plies

    def item(self, depth: int) -> list[float]:
        token = self.peek()
        if token is None:
            raise self.fail("a ply angle or '('")
        if token[0] == "open":
            if depth > 20:
                raise LayupError("groups nested too deeply")
            opener = self.take()[1]
            inner = self.sequence(depth + 1)
            closing = self.peek()
            expected = ")" if opener == "(" else "]"
            if closing is None or closing[0] != "close" or closing[1] != expected:
                raise self.fail(f"{expected!r}")
            self.take()
            return self.suffix(inner)
        return self.angle()

    def suffix(self, plies: list[float]) -> list[float]:
        token = self.peek()
        if token is not None and token[0] == "number":
            plies = plies * self.count(self.take())
            _check_count(plies)
            token = self.peek()
        if token is not None and token[0] == "sym":
            self.take()
            plies = plies + plies[::-1]
            _check_count(plies)
        return plies

    def count(self, token: tuple[str, str, int]) -> int:
        if not token[1].isdigit():
            raise LayupError(f"repetition count must be a positive integer, got {token[1]!r}")
        repeat = int(token[1])
        if not 1 <= repeat <= _MAX_REPEAT:
            raise LayupError(f"repetition count must be in [1, {_MAX_REPEAT}], got {repeat}")
        return repeat

    def angle(self) -> list[float]:
        sign_pair: tuple[float, float] | None = None
        token = self.peek()
        if token is not None and token[0] == "pm":
            symbol = self.take()[1]
            sign_pair = (1.0, -1.0) if symbol in ("±", "+-", "+/-") else (-1.0, 1.0)
            token = self.peek()
        if token is None or token[0] != "number":
            raise self.fail("a ply angle in degrees")
        text = self.take()[1]
        if sign_pair is not None and text[0] in "+-":
            raise LayupError(f"a signed angle cannot follow '±': {text!r}")
        value = float(text)
        if not math.isfinite(value) or not -90.0 <= value <= 90.0:
            raise LayupError(f"ply angle {text} deg is outside [-90, 90] deg")
        value = value + 0.0  # turn -0.0 into 0.0
        if (token := self.peek()) is not None and token[0] == "deg":
            self.take()
        plies = [value] if sign_pair is None else [sign_pair[0] * value + 0.0, sign_pair[1] * value + 0.0]
        if (token := self.peek()) is not None and token[0] == "sub":
            self.take()
            token = self.peek()
            if token is None or token[0] != "number":
                raise self.fail("a repetition count after '_'")
            plies = plies * self.count(self.take())
        return plies


def _check_count(plies: list[float]) -> None:
    if len(plies) > MAX_PLIES:
        raise LayupError(f"layup expands to more than {MAX_PLIES} plies")


def parse_layup_degrees(text: str) -> tuple[float, ...]:
    """Expand a laminate stacking string into ply angles, inner ply first.

    Parameters
    ----------
    text
        Stacking notation with angles in [deg] measured from the shaft axis, e.g.
        ``"(55/-55/0/0)s"``, ``"[45/-45]s"``, ``"(±45)s"``, ``"+-45"``, ``"(0/90)2s"``,
        ``"[0/90]3"``, ``"[0_2/90]s"``, ``"55/-55/0/0"`` or ``"90"``. A suffix ``n`` repeats a
        group n times, ``s`` mirrors it about the mid-plane (``2s`` repeats, then mirrors);
        ``±a`` expands to ``a/-a``; ``a_n`` repeats one angle n times.

    Returns
    -------
    tuple of float
        Ply angles [deg] in stacking order, each within [-90, 90].

    Raises
    ------
    LayupError
        On any syntax error, an angle outside [-90, 90] deg, or more than ``MAX_PLIES`` plies.
    """
    if not isinstance(text, str):
        raise LayupError(f"layup must be a string, got {type(text).__name__}")
    return tuple(_Parser(text).parse())
