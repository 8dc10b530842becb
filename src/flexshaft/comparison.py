"""Two drivelines side by side: the thesis's comparison (``flexshaft compare``).

:func:`compare` assesses two designs at their operating points
(:func:`flexshaft.verdict.assess.assess` at the report's resolution; a design already assessed
is taken as it is) and collects what a
designer weighs: mass and part count by kind (:func:`driveline_inventory`), every requirement
of both verdicts with value, limit and margin, the lateral critical speeds with their API 684
separation margins, whirl onset and the smallest log decrement, the spin-up peak, the strength
safety factors and temperatures. The default compares the embedded tuned FMC design with the
embedded current (segmented aluminium) driveline.

Part kinds: ``segments`` (separate shaft tubes: one more than the couplings), ``couplings``,
``hangers`` and ``dampers`` (contact bearings by their ``role``), ``actuators`` (active
bearings). A bearing of role ``"gearbox"`` ends the driveline and is not a driveline part.
Masses come from the geometry (tubes) and the design's ``mass`` fields (couplings, bearings);
a part without a mass counts 0 kg and is listed in :attr:`Inventory.mass_not_given`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import TypeVar

import numpy as np

from flexshaft.analyses.results import ResultMixin, coded, dataframe, html_table, new_dataset
from flexshaft.assembly.model import Model
from flexshaft.design import Design, embedded_design
from flexshaft.resolution import REPORT, Resolution
from flexshaft.thermal.options import thermal_options
from flexshaft.thermal.tailboom import boom_equivalent_diameter, tailboom_temperatures
from flexshaft.verdict.assess import Assessment, assess
from flexshaft.verdict.result import SI_UNITS, Check

__all__ = ["PART_KINDS", "Comparison", "Inventory", "Metric", "compare", "driveline_inventory"]

#: Part kinds of the mass breakdown and part count, in report order.
PART_KINDS: tuple[str, ...] = ("segments", "couplings", "hangers", "dampers", "actuators")

T = TypeVar("T")


@dataclass(frozen=True)
class Inventory:
    """Mass [kg] and number of parts of each kind (:data:`PART_KINDS`) of one driveline."""

    mass: dict[str, float]
    count: dict[str, int]
    mass_not_given: tuple[str, ...] = ()

    @property
    def total_mass(self) -> float:
        """[kg]."""
        return float(sum(self.mass.values()))

    @property
    def total_count(self) -> int:
        return int(sum(self.count.values()))


def driveline_inventory(model: Model) -> Inventory:
    """Mass and count of the driveline's parts by kind (see the module docstring)."""
    design = model.design
    mass = dict.fromkeys(PART_KINDS, 0.0)
    count = dict.fromkeys(PART_KINDS, 0)
    missing = []
    mass["segments"], count["segments"] = float(model.shaft_mass), len(design.couplings) + 1
    for coupling in design.couplings:
        mass["couplings"] += coupling.mass
        count["couplings"] += 1
        if coupling.mass == 0.0:
            missing.append(f"coupling {coupling.name}")
    for bearing in design.bearings:
        if bearing.kind == "active":
            kind = "actuators"
        elif bearing.role == "gearbox":
            continue
        else:
            kind = "hangers" if bearing.role == "hanger" else "dampers"
        mass[kind] += bearing.mass
        count[kind] += 1
        if bearing.mass == 0.0:
            missing.append(f"{kind[:-1]} {bearing.name}")
    return Inventory(mass, count, tuple(missing))


@dataclass(frozen=True)
class Metric:
    """One compared quantity: SI ``values`` of both designs (None: not available), its unit,
    and a note per design (where, or why it is missing)."""

    key: str
    title: str
    unit: str
    values: tuple[float | None, float | None]
    notes: tuple[str, str] = ("", "")
    lower_bounds: tuple[bool, bool] = (False, False)  # the true value is larger (e.g. no onset up to the top)


@dataclass(frozen=True)
class Comparison(ResultMixin):
    """Two designs analysed at their operating points.

    Attributes
    ----------
    labels : tuple of str
        Short names of the two designs (column headings).
    runs : tuple of Assessment
        The two assessments (:class:`flexshaft.verdict.assess.Assessment`).
    inventories : tuple of Inventory
    boom_temperatures : tuple of mapping
        ``{"hover": K, "parked": K}`` of each design's tailboom (empty without a boom).
    """

    labels: tuple[str, str]
    runs: tuple[Assessment, Assessment]
    inventories: tuple[Inventory, Inventory]
    boom_temperatures: tuple[Mapping[str, float], Mapping[str, float]] = ({}, {})

    def __repr__(self) -> str:
        a, b = self.labels
        verdicts = [("PASS" if r.verdict.passed else "FAIL") for r in self.runs]
        return (
            f"Comparison({a}: {self.inventories[0].total_mass:.1f} kg, {self.inventories[0].total_count} parts, "
            f"{verdicts[0]}; {b}: {self.inventories[1].total_mass:.1f} kg, {self.inventories[1].total_count} "
            f"parts, {verdicts[1]})"
        )

    # -- the verdicts ------------------------------------------------------------------------------

    @property
    def check_keys(self) -> tuple[str, ...]:
        """Every requirement of either verdict, in report order (design A's order first)."""
        keys: list[str] = []
        for run in self.runs:
            previous = None
            for c in run.verdict.checks:
                if c.key not in keys:  # after the check that precedes it in this verdict
                    keys.insert(keys.index(previous) + 1 if previous is not None else 0, c.key)
                previous = c.key
        return tuple(keys)

    def check(self, key: str, design: int) -> Check | None:
        """The check ``key`` of design 0 or 1, or None when its verdict does not list it."""
        try:
            return self.runs[design].verdict.check(key)
        except KeyError:
            return None

    def critical_speeds(self, design: int) -> list[dict]:
        """Lateral critical speeds of one design with AF and separation margin (SI, fractions)."""
        check = self.check("separation", design)
        if check is None:
            return []
        return [
            {
                "speed": f.location.get("speed"),
                "amplification_factor": f.location.get("amplification_factor"),
                "margin": f.value,
                "required": f.limit,
                "passed": f.passed,
                "station": f.location.get("station"),
                "mode": f.location.get("mode", ""),
            }
            for f in check.findings
        ]

    # -- the key numbers ---------------------------------------------------------------------------

    def to_dataframe(self):
        """:meth:`metrics` as a table indexed by the quantity's title: its SI unit and both
        designs' values (None: not available; pandas, imported here, comes with xarray)."""
        found = self.metrics()
        a, b = self.labels
        return dataframe(
            {
                "quantity": [m.title for m in found],
                "unit": [m.unit for m in found],
                a: [m.values[0] for m in found],
                b: [m.values[1] for m in found],
            },
            index="quantity",
        )

    def _repr_html_(self) -> str:
        a, b = self.labels
        verdicts = [f"{label}: {run.verdict.headline}" for label, run in zip(self.labels, self.runs)]
        rows = [[m.title, m.unit, m.values[0], m.values[1]] for m in self.metrics()]
        return html_table(("quantity", "SI unit", a, b), rows, title="; ".join(verdicts))

    def metrics(self) -> list[Metric]:
        """The compared quantities, SI units (see :class:`Metric`)."""
        out = []
        for kind in PART_KINDS:
            out.append(Metric(f"mass_{kind}", f"mass: {kind}", "kg", _pair(inv.mass[kind] for inv in self.inventories)))
        out.append(
            Metric(
                "mass_total",
                "mass: driveline total",
                "kg",
                _pair(inv.total_mass for inv in self.inventories),
                _pair(_missing_note(inv) for inv in self.inventories),
            )
        )
        for kind in PART_KINDS:
            out.append(
                Metric(
                    f"count_{kind}", f"parts: {kind}", "1", _pair(float(inv.count[kind]) for inv in self.inventories)
                )
            )
        out.append(
            Metric("count_total", "parts: total", "1", _pair(float(inv.total_count) for inv in self.inventories))
        )
        out.append(self._from_checks("strength", "smallest strength safety factor", "1", ("tsai_wu", "metal_strength")))
        out.append(self._from_checks("buckling", "torsional buckling safety factor", "1", ("buckling",)))
        out.append(self._critical("critical_below", "highest lateral critical below the operating speed", below=True))
        out.append(self._critical("critical_above", "lowest lateral critical above the operating speed", below=False))
        out.append(self._from_checks("separation", "smallest API 684 separation margin", "1", ("separation",)))
        out.append(self._from_checks("whirl_onset", "whirl onset speed", "rad/s", ("whirl_onset",)))
        out.append(self._from_checks("log_decrement", "smallest log decrement at Ω_op", "1", ("whirl_damping",)))
        out.append(
            self._from_checks("spinup_peak", "spin-up peak shaft orbit", "m", ("spinup_deflection",), largest=True)
        )
        out.append(
            self._from_checks(
                "coupling_angle", "largest coupling misalignment", "rad", ("coupling_angle",), largest=True
            )
        )
        out.append(
            Metric(
                "static_deflection",
                "largest static shaft deflection",
                "m",
                _pair(_static_deflection(run) for run in self.runs),
            )
        )
        out.append(
            self._from_checks("shaft_temperature", "largest shaft temperature", "K", ("temperature",), largest=True)
        )
        for condition in ("hover", "parked"):
            out.append(
                Metric(
                    f"boom_temperature_{condition}",
                    f"tailboom temperature, {condition}",
                    "K",
                    _pair(t.get(condition) for t in self.boom_temperatures),
                )
            )
        return out

    def _from_checks(self, key: str, title: str, unit: str, checks: tuple[str, ...], largest: bool = False) -> Metric:
        """The governing value of the first of ``checks`` each verdict evaluates (the smallest, or
        with ``largest`` the largest, when several are evaluated)."""
        values: list[float | None] = []
        notes: list[str] = []
        bounds: list[bool] = []
        for design in (0, 1):
            found = [
                (c.value, c) for c in (self.check(k, design) for k in checks) if c is not None and c.value is not None
            ]
            if found:
                value, c = (max if largest else min)(found, key=lambda item: item[0])
                values.append(float(value))
                notes.append(c.title + _where(c.location) + (f"; {c.note}" if c.lower_bound and c.note else ""))
                bounds.append(bool(c.lower_bound))
            else:
                listed = [c for c in (self.check(k, design) for k in checks) if c is not None]
                values.append(None)
                notes.append(listed[0].note if listed else "no such part")
                bounds.append(False)
        return Metric(key, title, unit, (values[0], values[1]), (notes[0], notes[1]), (bounds[0], bounds[1]))

    def _critical(self, key: str, title: str, below: bool) -> Metric:
        values: list[float | None] = []
        notes: list[str] = []
        for design in (0, 1):
            op = self.runs[design].model.speed
            found = [c for c in self.critical_speeds(design) if c["speed"] is not None and (c["speed"] < op) == below]
            if found:
                c = max(found, key=lambda c: c["speed"]) if below else min(found, key=lambda c: c["speed"])
                values.append(float(c["speed"]))
                notes.append(
                    f"AF {c['amplification_factor']:.3g}, margin {100 * c['margin']:.1f} % "
                    f"(needs {100 * c['required']:.1f} %)"
                )
            else:
                values.append(None)
                top = self.runs[design].resolution.scan_top
                notes.append("none found" if below else f"none up to {top:g} × Ω_op")
        return Metric(key, title, "rad/s", (values[0], values[1]), (notes[0], notes[1]))

    # -- data --------------------------------------------------------------------------------------

    def to_dataset(self):
        """Both designs: part masses and counts, every check, every metric (xarray, SI)."""
        keys = self.check_keys
        status_labels, value, limit, margin = (
            [],
            np.full((2, len(keys)), np.nan),
            np.full((2, len(keys)), np.nan),
            np.full((2, len(keys)), np.nan),
        )
        for d in (0, 1):
            row = []
            for k, key in enumerate(keys):
                c = self.check(key, d)
                row.append("not_listed" if c is None else c.status.replace(" ", "_"))
                if c is not None:
                    value[d, k], limit[d, k], margin[d, k] = (
                        np.nan if v is None else v for v in (c.value, c.limit, c.margin)
                    )
            status_labels.append(row)
        status, status_attrs = coded(
            status_labels, ("pass", "fail", "not_evaluated", "not_listed"), "requirement status"
        )
        metrics = self.metrics()
        metric_values = np.array([[np.nan if m.values[d] is None else m.values[d] for m in metrics] for d in (0, 1)])
        return new_dataset(
            {
                "part_mass": (
                    ("design", "part_kind"),
                    np.array([[inv.mass[k] for k in PART_KINDS] for inv in self.inventories]),
                    {"units": "kg", "long_name": "mass of the parts of each kind"},
                ),
                "part_count": (
                    ("design", "part_kind"),
                    np.array([[inv.count[k] for k in PART_KINDS] for inv in self.inventories], dtype=np.int32),
                    {"units": "1", "long_name": "number of parts of each kind"},
                ),
                "check_value": (("design", "check"), value, {"long_name": "worst value (unit: check_units)"}),
                "check_limit": (("design", "check"), limit, {"long_name": "required limit"}),
                "check_margin": (("design", "check"), margin, {"long_name": "signed margin (negative: fails)"}),
                "check_status": (("design", "check"), status, status_attrs),
                "metric_value": (("design", "metric"), metric_values, {"long_name": "value (unit: metric_units)"}),
            },
            {
                "design": ("design", list(self.labels), {"long_name": "design"}),
                "design_name": ("design", [r.model.design.name for r in self.runs], {"long_name": "design name"}),
                "part_kind": ("part_kind", list(PART_KINDS), {"long_name": "part kind"}),
                "check": ("check", list(keys), {"long_name": "requirement"}),
                "check_units": ("check", [_check_unit(self, key) for key in keys], {"long_name": "SI unit"}),
                "metric": ("metric", [m.key for m in metrics], {"long_name": "compared quantity"}),
                "metric_title": ("metric", [m.title for m in metrics], {"long_name": "compared quantity"}),
                "metric_units": ("metric", [m.unit for m in metrics], {"long_name": "SI unit"}),
            },
            "driveline comparison",
            verdict_a=self.runs[0].verdict.summary,
            verdict_b=self.runs[1].verdict.summary,
        )


def _pair(values: Iterable[T]) -> tuple[T, T]:
    """The two designs' values as a pair."""
    a, b = values
    return a, b


def _check_unit(comparison: Comparison, key: str) -> str:
    c = comparison.check(key, 0) or comparison.check(key, 1)
    assert c is not None  # a key of check_keys: one design's verdict at least has it
    return SI_UNITS.get(c.kind, "-").replace("-", "1")


def _where(location) -> str:
    parts = [str(location[k]) for k in ("case", "mode", "actuator") if k in location]
    if "station" in location:
        parts.append(f"x = {location['station']:.2f} m")
    return f" ({', '.join(parts)})" if parts else ""


def _missing_note(inventory: Inventory) -> str:
    if not inventory.mass_not_given:
        return ""
    return "mass not given (0 kg): " + ", ".join(inventory.mass_not_given)


def _static_deflection(run: Assessment) -> float:
    dm = run.model.dofs
    q = np.real(run.static_displacement)
    return float(np.max(np.hypot(dm.values(q, "shaft", "v"), dm.values(q, "shaft", "w"))))


def _boom_temperatures(design: Design, run: Assessment) -> dict[str, float]:
    """Hover and parked tailboom skin temperatures [K] (from the run's thermal result, else computed)."""
    if design.tailboom is None:
        return {}
    thermal = run.thermal
    if thermal is not None and thermal.tailboom:
        return {k: float(v.temperature) for k, v in thermal.tailboom.items()}
    options = thermal_options(design.thermal)
    found = tailboom_temperatures(
        boom_equivalent_diameter(design.tailboom), options.environment, options.boom_convection
    )
    return {k: float(v.temperature) for k, v in found.items()}


def _design(value) -> Design:
    if isinstance(value, Assessment):
        return value.design
    if isinstance(value, Design):
        return value
    if isinstance(value, str):
        return embedded_design(value)
    raise TypeError(
        f"design: expected a Design, an Assessment or the name of an embedded design, got {type(value).__name__}"
    )


def _check_resolution(value, resolution: Resolution, which: str) -> None:
    """An Assessment given to :func:`compare` must be at the comparison's resolution (the two
    columns are judged at the same grids)."""
    if isinstance(value, Assessment) and value.resolution != resolution:
        raise ValueError(
            f"{which}: an assessment at the {value.resolution.name} resolution cannot be compared at the "
            f"{resolution.name} resolution (assess it at {resolution.name}, or pass "
            f"resolution=<its resolution> to compare)"
        )


def compare(
    design_a="tuned",
    design_b="current",
    *,
    labels: tuple[str, str] | None = None,
    resolution: Resolution = REPORT,
    progress: Callable[[str], None] | None = None,
) -> Comparison:
    """Analyse two designs and put them side by side.

    Parameters
    ----------
    design_a, design_b : Design, Assessment or str
        Designs, names of embedded designs (default: the tuned FMC design and the current
        segmented aluminium driveline: the thesis's comparison), or designs already assessed
        at ``resolution`` (:func:`flexshaft.verdict.assess.assess`: used as they are, not
        assessed again).
    labels : tuple of str, optional
        Column headings; default the embedded names, else "A" and "B".
    resolution : Resolution
        Grids of each assessment (:func:`flexshaft.verdict.assess.assess`).
    progress : callable, optional
        Called with a short label before each step.

    Returns
    -------
    Comparison
    """
    designs = (_design(design_a), _design(design_b))
    for value, which in ((design_a, "design_a"), (design_b, "design_b")):
        _check_resolution(value, resolution, which)
    if labels is None:
        labels = (design_a if isinstance(design_a, str) else "A", design_b if isinstance(design_b, str) else "B")
    if len(labels) != 2 or labels[0] == labels[1]:
        raise ValueError(f"labels: expected two different names, got {labels!r}")
    step = progress or (lambda label: None)

    def labelled(label: str) -> Callable[[str], None]:
        return lambda s: step(f"{label}: {s}")

    runs = [
        value if isinstance(value, Assessment) else assess(design, resolution, progress=labelled(label))
        for label, value, design in zip(labels, (design_a, design_b), designs)
    ]
    return Comparison(
        labels=(str(labels[0]), str(labels[1])),
        runs=_pair(runs),
        inventories=_pair(driveline_inventory(run.model) for run in runs),
        boom_temperatures=_pair(_boom_temperatures(d, r) for d, r in zip(designs, runs)),
    )
