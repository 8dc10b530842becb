"""Numbers a documentation page quotes from the code: check them, or write them anew.

A page's prose keeps its own words; each number the code computes is declared once as a
:class:`Quote`: a template of the page's text in which every ``{}`` stands for one printed number,
the function that computes those numbers (in the units the page prints) and the format each is
printed with. :func:`check` finds every template exactly once in the page and compares each
printed number with the computed one; :func:`regenerate` writes the computed numbers into the
page (the test modules that declare the quotes do it when run as scripts).

Tolerance: one unit of the last printed digit (``44.1`` is within 0.1 of the computed value).
Rounding alone gives half a unit; the other half lets a value that sits on a rounding boundary
round the other way on another machine (BLAS, compiler) without a stale page being missed: a
page whose number is off by more than its last digit is stale.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass

__all__ = ["Quote", "check", "parse_number", "regenerate", "render"]

_SUPERSCRIPT = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")
_TO_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
#: One printed number: optional sign (ASCII or Unicode minus), digits, an optional decimal part,
#: an optional exponent written ``e-4`` or ``×10⁵``.
NUMBER = r"([+−-]?\d+(?:\.\d+)?(?:e[+-]?\d+|×10[⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)"


@dataclass(frozen=True)
class Quote:
    """Numbers of one passage of a page.

    Parameters
    ----------
    name : str
        What the numbers are (the test's id).
    template : str
        The page's text with ``{}`` in place of each number, matched literally otherwise except
        that white space matches any white space (line breaks included).
    compute : callable
        ``() -> sequence of float``: the numbers, in the units and order the page prints them.
    formats : sequence of str
        One format per number for :func:`regenerate`: a ``format()`` spec (``".1f"``, ``".3g"``)
        ``"×10:N"``, a mantissa with N decimals times a power of ten (``5.3×10⁵``), or ``"eK:spec"``,
        the value over 10^K printed with ``spec`` and ``eK`` after it (``"e6:.3f"``: ``738.906e6``).
    """

    name: str
    template: str
    compute: Callable[[], Sequence[float]]
    formats: Sequence[str]

    @property
    def pattern(self) -> re.Pattern:
        """The template as a regular expression: literal text, any run of white space matching
        any other (the page's line breaks fall where its wrapping puts them)."""

        def literal(part: str) -> str:
            return r"\s+".join(re.escape(piece) for piece in re.split(r"\s+", part))

        return re.compile(NUMBER.join(literal(p) for p in self.template.split("{}")))

    @property
    def size(self) -> int:
        return self.template.count("{}")


def parse_number(text: str) -> tuple[float, float]:
    """(value, one unit of its last digit) of a number as printed (``−0.0015``, ``5.3×10⁵``)."""
    text = text.replace("−", "-")
    exponent = 0
    if "×10" in text:
        text, power = text.split("×10")
        exponent = int(power.translate(_SUPERSCRIPT))
    elif "e" in text:
        text, power = text.split("e")
        exponent = int(power)
    decimals = len(text.split(".")[1]) if "." in text else 0
    return float(text) * 10.0**exponent, 10.0 ** (exponent - decimals)


def render(value: float, spec: str) -> str:
    """``value`` printed with ``spec`` (see :class:`Quote`), a negative sign as "−"."""
    if spec.startswith("×10:"):
        decimals = int(spec.split(":")[1])
        exponent = math.floor(math.log10(abs(value))) if value else 0
        mantissa = round(value / 10.0**exponent, decimals)
        if abs(mantissa) >= 10.0:
            exponent, mantissa = exponent + 1, round(value / 10.0 ** (exponent + 1), decimals)
        text = f"{mantissa:.{decimals}f}×10{str(exponent).translate(_TO_SUPERSCRIPT)}"
    elif re.fullmatch(r"e\d+:.+", spec):
        power, inner = spec[1:].split(":", 1)
        text = f"{format(value / 10.0 ** int(power), inner)}e{power}"
    else:
        text = format(value, spec)
        if "e" in text:  # a format's exponent, printed as the pages print it: 7.5e-06 -> 7.5×10⁻⁶
            mantissa, power = text.split("e")
            text = f"{mantissa}×10{str(int(power)).translate(_TO_SUPERSCRIPT)}"
    return "−" + text[1:] if text.startswith("-") else text


def _one_match(page: str, quote: Quote) -> re.Match:
    matches = list(quote.pattern.finditer(page))
    if len(matches) != 1:
        raise AssertionError(
            f"{quote.name}: the page has {len(matches)} passages matching {quote.template!r} (expected exactly 1)"
        )
    return matches[0]


def check(page: str, quote: Quote) -> list[str]:
    """Messages for each printed number of ``quote`` more than one unit of its last digit away
    from the computed one (empty: the page is current)."""
    match = _one_match(page, quote)
    values = list(quote.compute())
    if len(values) != quote.size or len(quote.formats) != quote.size:
        raise AssertionError(f"{quote.name}: {quote.size} numbers in the template, {len(values)} computed")
    problems = []
    for k, (printed, value) in enumerate(zip(match.groups(), values)):
        number, unit = parse_number(printed)
        if not math.isfinite(value) or abs(number - value) > unit * (1.0 + 1e-9):
            problems.append(
                f"{quote.name}, number {k + 1}: the page prints {printed}, the code gives {value:.6g} "
                f"(now {render(value, quote.formats[k])})"
            )
    return problems


def regenerate(page: str, quotes: Sequence[Quote]) -> str:
    """``page`` with every quoted number replaced by the computed one, printed in its format."""
    for quote in quotes:
        match = _one_match(page, quote)
        values = list(quote.compute())
        pieces, last = [], match.start()
        for k, value in enumerate(values):
            pieces.append(page[last : match.start(k + 1)])
            pieces.append(render(value, quote.formats[k]))
            last = match.end(k + 1)
        page = page[: match.start()] + "".join(pieces) + page[last:]
    return page
