"""Building blocks shared by the design-file models: field types, messages, the problem collector.

Floats are strict (no ``"3"`` -> 3.0, no ``true`` -> 1.0; integers are accepted) and finite
(no nan, inf). Every model of the schema derives from :class:`FrozenModel` (unknown keys are
refused, instances are immutable). Constraints involving several fields are checked in
``model_validator(mode="after")`` hooks that collect every problem in a :class:`Problems` and
raise them at once as one pydantic error of type :data:`PROBLEMS_ERROR_TYPE`, whose context
carries the (sub-path, message) pairs that :mod:`flexshaft.design.io` turns into field paths.

This module is internal to :mod:`flexshaft.design`; the public names are re-exported by
:mod:`flexshaft.design.schema`.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field
from pydantic_core import PydanticCustomError

from flexshaft.design.quantities import MAX_DESIGN_NAME_LENGTH, MAX_NAME_LENGTH, ControllerCoefficient, SemiAxis

__all__ = [
    "BearingDirection",
    "Coefficients",
    "DesignName",
    "DofName",
    "ElementCount",
    "FieldPath",
    "Finite",
    "FrozenModel",
    "ImbalancePlacement",
    "LAYUP_ERROR_TYPE",
    "LossFactor",
    "Name",
    "NonNegative",
    "NonNegativeVector3",
    "PROBLEMS_ERROR_TYPE",
    "Positive",
    "Problems",
    "SemiAxes",
    "Vector3",
    "ZERO3",
    "check_interval",
    "check_unique",
    "format_number",
    "format_value",
]

# ------------------------------------------------------------------------------------------------
# Field types

Finite = Annotated[float, Field(strict=True, allow_inf_nan=False)]
Positive = Annotated[float, Field(strict=True, allow_inf_nan=False, gt=0.0)]
NonNegative = Annotated[float, Field(strict=True, allow_inf_nan=False, ge=0.0)]
LossFactor = Annotated[
    float,
    Field(
        strict=True,
        allow_inf_nan=False,
        ge=0.0,
        lt=1.0,
        description=("hysteretic loss factor η in [0, 1) (polyurethane matrices reach 0.1-0.3)"),
        json_schema_extra={"unit": "-"},
    ),
]
Vector3 = tuple[Finite, Finite, Finite]
NonNegativeVector3 = tuple[NonNegative, NonNegative, NonNegative]
SemiAxes = tuple[SemiAxis, SemiAxis]
Name = Annotated[
    str,
    Field(
        strict=True,
        min_length=1,
        max_length=MAX_NAME_LENGTH,
        description=f"identifier, 1 to {MAX_NAME_LENGTH} characters",
    ),
]
DesignName = Annotated[
    str,
    Field(
        strict=True,
        max_length=MAX_DESIGN_NAME_LENGTH,
        description=f"title of the design, at most {MAX_DESIGN_NAME_LENGTH} characters",
    ),
]
ElementCount = Annotated[
    int,
    Field(
        strict=True,
        ge=1,
        le=2000,
        description="approximate element count, 1 to 2000 "
        "(the problem-size estimate of flexshaft.assembly.size bounds the total)",
    ),
]
Coefficients = Annotated[tuple[ControllerCoefficient, ...], Field(min_length=1, max_length=21)]

#: Degree-of-freedom names of a shaft node, in the order of docs/model.md (coordinates and DOFs).
DofName = Literal["u", "v", "w", "theta", "beta", "gamma"]
#: Relative-displacement directions of a bearing (docs/model.md, elements); no twist (theta).
BearingDirection = Literal["u", "v", "w", "beta", "gamma"]
#: Where the imbalance force of each bay is applied (docs/model.md, forced response).
ImbalancePlacement = Literal["mid_bay", "distributed", "worst"]

#: pydantic error type carrying several (sub-path, message) problems from one model validator.
PROBLEMS_ERROR_TYPE = "flexshaft_problems"
#: pydantic error type of an unparsable layup string.
LAYUP_ERROR_TYPE = "flexshaft_layup"

#: Path of a field below the model that reports it, e.g. ``("bearings", 2, "x")``.
FieldPath = tuple[str | int, ...]
#: Default of optional 3-vectors (moments, load factors, inertias).
ZERO3 = (0.0, 0.0, 0.0)


class FrozenModel(BaseModel):
    """Base of every design-file model: unknown keys are refused, instances are immutable."""

    model_config = ConfigDict(extra="forbid", frozen=True, validate_default=True)


# ------------------------------------------------------------------------------------------------
# Messages


def format_value(value: Any, limit: int = 60) -> str:
    """Render a user value TOML-like and short, for error messages."""
    if value is None:
        text = "nothing"
    elif isinstance(value, bool):
        text = "true" if value else "false"
    elif isinstance(value, float):
        text = repr(value)
    elif isinstance(value, int):
        digits = str(abs(value)) if abs(value) < 10**40 else ""
        text = str(value) if digits else f"an integer with {len(str(abs(value)))} digits"
    elif isinstance(value, str):
        shown = value if len(value) <= limit else value[: limit - 3] + "..."
        text = '"' + shown.encode("unicode_escape").decode("ascii").replace('"', '\\"') + '"'
    elif isinstance(value, (list, tuple)):
        parts: list[str] = []
        length = 2
        for item in value:
            part = format_value(item, limit=20)
            if length + len(part) > limit:
                parts.append("...")
                break
            parts.append(part)
            length += len(part) + 2
        text = "[" + ", ".join(parts) + "]"
    elif isinstance(value, dict):
        keys = ", ".join(format_value(str(k), limit=20) for k in list(value)[:6])
        more = ", ..." if len(value) > 6 else ""
        text = "a table {" + keys + more + "}" if value else "an empty table"
    else:
        text = f"{type(value).__name__} {value!s}"
    return text if len(text) <= limit + 40 else text[: limit + 37] + "..."


def format_number(value: float) -> str:
    """Short rendering of a computed number (a bound or a limit) for error messages."""
    return f"{value:.6g}"


class Problems:
    """Collects (sub-path, message) pairs and raises them as one pydantic error."""

    def __init__(self) -> None:
        self.items: list[tuple[FieldPath, str]] = []

    def add(self, path: FieldPath, message: str) -> None:
        self.items.append((path, message))

    def raise_if_any(self) -> None:
        if self.items:
            summary = "; ".join(".".join(str(part) for part in path) + ": " + message for path, message in self.items)
            raise PydanticCustomError(
                PROBLEMS_ERROR_TYPE, "{summary}", {"summary": summary, "problems": tuple(self.items)}
            )


def check_interval(problems: Problems, x_start: float, x_end: float) -> bool:
    """Report ``x_end`` unless it lies above ``x_start`` [m]; True when the interval is valid."""
    if x_start < x_end:
        return True
    problems.add(("x_end",), f"must be greater than x_start = {format_number(x_start)} m (got {format_value(x_end)})")
    return False


def check_unique(problems: Problems, prefix: FieldPath, names: Sequence[str]) -> None:
    """Report every repeated name after its first occurrence, at ``prefix + (index, "name")``."""
    counts = Counter(names)
    for index, name in enumerate(names):
        if counts[name] > 1 and names.index(name) != index:
            message = f"duplicate name (got {format_value(name)}; names must be unique)"
            problems.add(prefix + (index, "name"), message)
