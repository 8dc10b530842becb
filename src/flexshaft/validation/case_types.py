"""The record of a validation case: the publication and what flexshaft computes against it.

:class:`Source` and :class:`Case` are shared by the case tables
(:mod:`flexshaft.validation.cases`, :mod:`flexshaft.validation.cases_vm`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

__all__ = ["Case", "Source"]


@dataclass(frozen=True)
class Source:
    """A publication (or standard) that validation cases take numbers from."""

    key: str
    citation: str


@dataclass(frozen=True)
class Case:
    """One published result and how flexshaft reproduces it.

    Attributes
    ----------
    id : str
        Short, unique name (``flexshaft validate --case`` and the JSON use it).
    title : str
        What the case is.
    part : str
        The part of flexshaft's model it exercises.
    source : str
        Key of :data:`SOURCES`.
    where : str
        Where in the source the number is printed (example, table, figure, page, equation).
    via : str
        How the number reached us when not read in the source itself ("" when it was).
    reference_kind : str
        What the published number is: ``"textbook example, peer-code values"``,
        ``"worked example"`` or ``"closed form"``.
    design : str or None
        Design file (``flexshaft/validation/designs/<design>``) with the case's inputs; None
        when the quantity takes plain numbers (``arguments``).
    quantity : str
        Key of :data:`flexshaft.validation.quantities.QUANTITIES`.
    arguments : dict
        Keyword arguments of the quantity.
    labels : tuple of str
        One label per compared value.
    published : tuple of float
        The published values, in ``unit``, in the order of ``labels``.
    unit : str
        Display unit of the values: ``"rad/s"``, ``"Hz"``, ``"rpm"``, ``"N/m"``, ``"g mm"`` or ``"-"``.
    tolerance : float
        Largest accepted relative difference |flexshaft/published − 1| of every value.
    tolerance_basis : str
        Why that tolerance: the source's own accuracy.
    note : str
        Where flexshaft's model differs from the source's, and other remarks.
    """

    id: str
    title: str
    part: str
    source: str
    where: str
    via: str
    reference_kind: str
    design: str | None
    quantity: str
    arguments: dict[str, Any]
    labels: tuple[str, ...]
    published: tuple[float, ...]
    unit: str
    tolerance: float
    tolerance_basis: str
    note: str = field(default="")
