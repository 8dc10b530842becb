"""The explorer's verdict payload from a hand-made verdict (nothing is assessed): the page shows
"the smallest whirl log decrement" (docs/explorer.md, *Results at screening resolution*), the
design's value, never the required one; and its JSON is strict (RFC 8259 has no NaN or
Infinity; Starlette's JSONResponse refuses them), so a check passed with nothing to measure
(normalised margin +inf, :func:`flexshaft.verdict.result.normalised_margin`'s docstring) is sent
as null with its status "pass".

References: docs/requirements.md, ``min_log_decrement = 0.1``, "δ ≥ 0.1 ... API 617's
acceptance level": the check's limit is the required decrement and its value the design's
smallest; a riveted tailboom's δ ≈ 0.063 (the same table) is taken here as the design's value, so
the check fails with margin 0.063 - 0.1 = -0.037 and normalised margin -0.037/0.1 = -0.37
(derived here: margin / |limit|, docs/explorer.md "the normalised margin ... negative fails").
"""

from __future__ import annotations

import json
from types import SimpleNamespace

import numpy as np
import pytest

pytest.importorskip("starlette")
pytest.importorskip("plotly")

from flexshaft.explore import compute
from flexshaft.verdict.result import Check, Verdict

REQUIRED = 0.1  # API 617 log decrement (docs/requirements.md)
DESIGN = 0.063  # the design's smallest whirl log decrement (hand-made)


@pytest.fixture
def stand_ins(monkeypatch):
    """The table's text, the inventory and the figures replaced (tested elsewhere)."""
    monkeypatch.setattr(compute, "verdict_rows", lambda verdict: [() for _ in verdict.checks])
    monkeypatch.setattr(compute, "driveline_inventory", lambda model: SimpleNamespace(total_mass=9.0, mass={}))
    monkeypatch.setattr(compute, "assessment_figures", lambda a: {})


def _assessment(checks: tuple[Check, ...]) -> SimpleNamespace:
    return SimpleNamespace(
        design=SimpleNamespace(name="hand-made"),
        resolution=SimpleNamespace(name="explore"),
        verdict=Verdict(checks=checks),
        model=SimpleNamespace(shaft_mass=4.5),
        stability=SimpleNamespace(onset_speed=None, speeds=np.linspace(0.0, 600.0, 21)),
        operating_speed=500.0,
    )


def _damping() -> Check:
    return Check(
        "whirl_damping",
        "whirl log decrement",
        "log_decrement",
        "at least",
        "fail",
        value=DESIGN,
        limit=REQUIRED,
        margin=DESIGN - REQUIRED,
    )


def test_the_smallest_log_decrement_is_the_designs(stand_ins) -> None:
    """min_log_decrement is the check's value 0.063, not the required 0.1; the failing check
    makes the page's verdict fail with normalised margin -0.37. Tolerances: the value is passed
    through (exact); the normalised margin is one subtraction and one division of numbers of
    order 0.1 (1e-12 relative)."""
    payload = compute.update_payload(_assessment((_damping(),)))
    assert payload["numbers"]["min_log_decrement"] == DESIGN
    assert payload["passed"] is False
    (row,) = payload["checks"]
    assert (row["key"], row["status"]) == ("whirl_damping", "fail")
    assert row["normalised_margin"] == pytest.approx(-0.37, rel=1e-12)


def test_no_damping_check_no_number(stand_ins) -> None:
    """A verdict without the whirl-damping check (none asked) shows no decrement, and with no
    failing check the page's verdict passes."""
    speed = Check(
        "whirl_onset", "whirl onset speed", "speed", "at least", "pass", value=700.0, limit=575.0, margin=125.0
    )
    payload = compute.update_payload(_assessment((speed,)))
    assert payload["numbers"]["min_log_decrement"] is None
    assert payload["passed"] is True


def test_a_margin_with_nothing_to_measure_is_strict_json(stand_ins) -> None:
    """A separation check that passed with no critical speed in range has no margin: its
    normalised margin is +inf, sent as null (the status says it passed), and the payload encodes
    as strict JSON (allow_nan=False, as Starlette's JSONResponse)."""
    separation = Check("separation", "critical-speed separation", "fraction", "at least", "pass")
    payload = compute.update_payload(_assessment((separation, _damping())))
    rows = {row["key"]: row for row in payload["checks"]}
    assert rows["separation"]["status"] == "pass"
    assert rows["separation"]["normalised_margin"] is None
    json.dumps(payload, allow_nan=False)  # raises ValueError on NaN or Infinity
