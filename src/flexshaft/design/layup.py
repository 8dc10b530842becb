"""The layup parser: the one place where ply angles are written in degrees.

``parse_layup("(55/-55/0/0)s")`` expands the shorthand of a design file into ply angles [deg]
from the shaft axis, inner ply first. It belongs to the design layer (a data leaf); the
laminate physics (:mod:`flexshaft.laminate`) converts the degrees to radians. Only ASCII digits
count as numbers (a layup written with other scripts' digits is refused, not guessed).
"""

from __future__ import annotations

import re
from typing import NamedTuple

__all__ = ["AngleToken", "angle_tokens", "parse_layup"]

# --------------------------------------------------------------------------------------------
# Layup strings (the only place where angles are in degrees)

#: Upper bound on a repetition count such as the ``3`` in ``[0/90]3`` or the ``2`` in ``0_2``.
_MAX_REPEAT = 100
#: Upper bound on the number of plies a layup string may expand to.
_MAX_PLIES = 1000
#: Upper bound on the nesting depth of groups.
_MAX_DEPTH = 20
_ALLOWED = (
    "allowed: ply angles in degrees within [-90, 90] separated by '/' (or ','), each optionally "
    "followed by '°' and by '_n' for n equal plies; '±45', '+-45' or '+/-45' (and '∓45', '-+45', "
    "'-/+45') for a pair; groups in '(...)' or '[...]', nestable, followed by an optional repeat "
    f"count (1 to {_MAX_REPEAT}) and/or 's' (symmetric), at most {_MAX_PLIES} plies in all; e.g. "
    "'(55/-55/0/0)s', '[45/-45]s', '(0/90)2s', '[0/90]3', '[0_2/90]s', '55/-55/0/0', '90'"
)
# Tokens: groups, separators, sign pairs, single signs, unsigned numbers, the degree mark, the
# ply-repeat mark and the symmetry suffix. Sign pairs come before single signs and separators.
_TOKEN = re.compile(
    r"""
    \s*(?:
      (?P<open>[(\[])
    | (?P<close>[)\]])
    | (?P<pair>±|∓|\+/-|-/\+|\+-|-\+)
    | (?P<sign>[+-])
    | (?P<sep>[/,])
    | (?P<number>(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)
    | (?P<deg>°|deg\b)
    | (?P<sub>_)
    | (?P<sym>[sS])
    )
    """,
    re.VERBOSE,
)
_SIGNS = {
    "±": (1.0, -1.0),
    "+-": (1.0, -1.0),
    "+/-": (1.0, -1.0),
    "∓": (-1.0, 1.0),
    "-+": (-1.0, 1.0),
    "-/+": (-1.0, 1.0),
    "+": (1.0,),
    "-": (-1.0,),
}
_CLOSING = {"(": ")", "[": "]"}


class AngleToken(NamedTuple):
    """Where one ply angle is written in a layup string (:func:`angle_tokens`)."""

    start: int
    """Index of the angle's first digit in the string."""
    end: int
    """Index just after its last digit."""
    magnitude: float
    """The number as written [deg], without its sign."""
    signed: bool
    """True when a sign or a pair (``-``, ``+``, ``±``, ``∓``, ...) is written before it."""


class _LayupParser:
    """Recursive-descent parser of the stacking notation; whitespace is ignored.

    Grammar::

        sequence := item (("/" | ",") item)*
        item     := group | angle
        group    := ("(" sequence ")" | "[" sequence "]") [INT] ["s"]   # repeat, then mirror
        angle    := [SIGN | PAIR] NUMBER ["°" | "deg"] ["_" INT]
    """

    def __init__(self, text: str) -> None:
        self.tokens: list[tuple[str, str, int]] = []  # (kind, text, position)
        self.index = 0
        self.angle_tokens: list[AngleToken] = []  # every ply angle's number, in the order written
        stripped, position = text.rstrip(), 0
        while position < len(stripped):
            match = _TOKEN.match(stripped, position)
            if match is None:
                where = len(stripped) - len(stripped[position:].lstrip())
                raise self.error(f"unexpected character {stripped[where]!r} at position {where + 1}")
            kind = match.lastgroup
            assert kind is not None
            self.tokens.append((kind, match.group(kind), match.start(kind)))
            position = match.end()

    @staticmethod
    def error(what: str) -> ValueError:
        return ValueError(f"{what}; {_ALLOWED}")

    def expected(self, what: str) -> ValueError:
        token = self.peek()
        found = f"{token[1]!r} at position {token[2] + 1}" if token else "end of text"
        return self.error(f"expected {what}, found {found}")

    def peek(self, kind: str | None = None) -> tuple[str, str, int] | None:
        token = self.tokens[self.index] if self.index < len(self.tokens) else None
        return token if kind is None or (token is not None and token[0] == kind) else None

    def take(self) -> str:
        self.index += 1
        return self.tokens[self.index - 1][1]

    def parse(self) -> tuple[float, ...]:
        if not self.tokens:
            raise self.error("empty layup")
        angles = self.sequence(depth=0)
        if self.peek() is not None:
            raise self.expected("'/' or the end of the layup")
        return tuple(angles)

    def sequence(self, depth: int) -> list[float]:
        angles = self.item(depth)
        while self.peek("sep"):
            self.take()
            angles += self.item(depth)
            self.check_count(angles)
        return angles

    def item(self, depth: int) -> list[float]:
        if not self.peek("open"):
            return self.angle()
        if depth >= _MAX_DEPTH:
            raise self.error(f"groups nested more than {_MAX_DEPTH} deep")
        opening = self.take()
        body = self.sequence(depth + 1)
        closing = self.peek("close")
        if closing is None or closing[1] != _CLOSING[opening]:
            raise self.expected(f"{_CLOSING[opening]!r} closing the group opened with {opening!r}")
        self.take()
        if self.peek("number"):
            body = body * self.count()
            self.check_count(body)
        if self.peek("sym"):
            self.take()
            body = body + body[::-1]
            self.check_count(body)
        return body

    def count(self) -> int:
        text = self.take()
        if not (text.isascii() and text.isdigit()) or not 1 <= int(text) <= _MAX_REPEAT:
            raise self.error(f"repeat count must be an integer in [1, {_MAX_REPEAT}], got {text!r}")
        return int(text)

    def angle(self) -> list[float]:
        signs: tuple[float, ...] = (1.0,)
        signed = False
        if self.peek("pair") or self.peek("sign"):
            signed = True
            symbol = self.take()
            signs = _SIGNS[symbol]
            if len(signs) == 2 and (self.peek("sign") or self.peek("pair")):
                raise self.error(f"a signed angle cannot follow {symbol!r}")
        if not self.peek("number"):
            raise self.expected("a ply angle in degrees")
        position = self.tokens[self.index][2]
        text = self.take()
        value = float(text)
        if not value <= 90.0:  # also refuses inf from a huge exponent
            raise self.error(f"ply angle {'-' if signs[0] < 0 else ''}{text} deg is outside [-90, 90] deg")
        self.angle_tokens.append(AngleToken(position, position + len(text), value, signed))
        if self.peek("deg"):
            self.take()
        angles = [sign * value + 0.0 for sign in signs]  # + 0.0 turns -0.0 into 0.0
        if self.peek("sub"):
            self.take()
            if not self.peek("number"):
                raise self.expected("a ply count after '_'")
            angles = angles * self.count()
        return angles

    @staticmethod
    def check_count(angles: list[float]) -> None:
        if len(angles) > _MAX_PLIES:
            raise _LayupParser.error(f"layup expands to more than {_MAX_PLIES} plies")


def parse_layup(text: str) -> tuple[float, ...]:
    """Ply angles in DEGREES, inner to outer, from a layup string.

    Parameters
    ----------
    text : str
        e.g. ``"(55/-55/0/0)s"`` -> (55, -55, 0, 0, 0, 0, -55, 55); ``"(±45)s"``, ``"+-45"``
        and ``"+/-45"`` expand the pair to 45/-45 (``"∓45"`` to -45/45); ``"(0/90)2s"``
        repeats then mirrors; ``"[0/90]3"`` repeats; ``"[0_2/90]s"`` repeats one ply;
        ``"55/-55/0/0"``; ``"45°/-45°"``; ``"90"``. Groups may nest; ``,`` may replace ``/``.

    Returns
    -------
    tuple of float
        Ply angles [deg], each within [-90, 90].

    Raises
    ------
    ValueError
        On malformed text, an angle outside [-90, 90] deg, a repeat count outside [1, 100] or
        more than 1000 plies. The message reads ``"<reason>; allowed: <the accepted forms>"``.
    """
    if not isinstance(text, str):
        raise ValueError(f"layup must be a string, got {type(text).__name__}; {_ALLOWED}")
    return _LayupParser(text).parse()


def angle_tokens(text: str) -> tuple[AngleToken, ...]:
    """Where each ply angle is written in a valid layup string, in the order written (repeat
    and ply counts are not angles): what a template that rewrites a layup's angles and keeps
    its notation needs (:func:`flexshaft.optimize.variables.layup_template`).

    Raises
    ------
    ValueError
        As :func:`parse_layup`.
    """
    if not isinstance(text, str):
        raise ValueError(f"layup must be a string, got {type(text).__name__}; {_ALLOWED}")
    parser = _LayupParser(text)
    parser.parse()
    return tuple(parser.angle_tokens)
