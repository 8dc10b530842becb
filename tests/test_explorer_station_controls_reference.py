"""Which bearings the explorer offers to move: the hangers, the dampers and the active
bearings, never the gearbox's bearing.

References: docs/explorer.md, "Controls for the variables that move a verdict: ... each active
bearing's station [m], K_p [N/m] and K_d [N s/m], each hanger's and each damper's station [m]
(a gearbox's bearing stays with its gearbox)"; the bearing roles as the packaged
current-driveline design file states them ("role = "hanger" (a shaft support), "damper" (spring
and viscous damper) or "gearbox" (the bearing of a gearbox that ends the driveline)"), read here
from the file itself with ``tomllib``, not through the schema. The bearing indices and names
below are the file's, counted by hand: hanger_1 to hanger_4 are bearings 0 to 3, damper_3 is 4,
gearbox_input is 5. (The damper had no control before: the file places it at the antinode of
the tube's first bending mode, a station an engineer moves.)
"""

from __future__ import annotations

import tomllib
from importlib import resources

import pytest

from flexshaft.design import DesignError, loads_design, tuned_design, with_overrides

pytest.importorskip("starlette")

from flexshaft.explore.controls import control_overrides, design_controls


def _station_keys(design) -> set[str]:
    return {c.key for c in design_controls(design) if c.key.startswith("bearings[") and c.key.endswith("].x")}


def test_the_current_driveline_offers_its_hangers_and_damper_not_its_gearbox() -> None:
    """current_driveline.toml: six contact bearings, four with role "hanger" (indices 0-3), a
    damper (4) and the gearbox input (5). The page offers the four hangers' and the damper's
    stations, each label naming its bearing (the label's format is the code's, so only the name
    is checked), and refuses the gearbox's station key as
    no such control."""
    text = resources.files("flexshaft.design").joinpath("current_driveline.toml").read_text(encoding="utf-8")
    bearings = tomllib.loads(text)["bearings"]
    hangers = [i for i, b in enumerate(bearings) if b.get("role", "hanger") == "hanger"]
    assert hangers == [0, 1, 2, 3]  # the file as read by hand
    assert [bearings[i]["role"] for i in (4, 5)] == ["damper", "gearbox"]
    design = loads_design(text, source="current_driveline.toml")
    assert _station_keys(design) == {f"bearings[{i}].x" for i in (*hangers, 4)}
    controls = {c.key: c for c in design_controls(design)}
    for i in (*hangers, 4):
        # the label format is the code's (no hand-written doc gives it): only that it names the bearing
        assert bearings[i]["name"] in controls[f"bearings[{i}].x"].label
    moved = control_overrides(design, {"bearings[4].x": bearings[4]["x"] + 0.1})
    assert moved["bearings[4].x"] == pytest.approx(bearings[4]["x"] + 0.1, rel=1e-12)  # metres, as the file
    with pytest.raises(DesignError, match="no such control"):
        control_overrides(design, {"bearings[5].x": bearings[5]["x"] + 0.1})


@pytest.mark.parametrize(("role", "kept"), [("damper", True), ("gearbox", False)])
def test_a_support_given_another_role_keeps_or_loses_its_station_control(role, kept) -> None:
    """The tuned design: hanger_forward (0) and hanger_aft (3) are hangers, amb_1 (1) and
    amb_2 (2) active. Giving hanger_aft the role ``damper`` keeps its station control; the role
    ``gearbox`` removes it and nothing else."""
    tuned = tuned_design()
    assert _station_keys(tuned) == {"bearings[0].x", "bearings[1].x", "bearings[2].x", "bearings[3].x"}
    design = with_overrides(tuned, {"bearings[3].role": role})
    expected = {"bearings[0].x", "bearings[1].x", "bearings[2].x"} | ({"bearings[3].x"} if kept else set())
    assert _station_keys(design) == expected
