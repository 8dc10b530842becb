"""Three documented edges, checked exactly where an open/closed swap or a lax grammar shows.

* Mesh merging (docs/limits.md, section 3, verbatim): "Stations closer than 5 % of the nominal
  element length h = member length / elements are merged into one node (the member ends are
  always kept)." A station exactly 5 % of h from its neighbour is not closer, so it stays a node.
  With a member 20 m long meshed by 1 element, h = 20 m and 5 % of h = 1 m; 0.05 x 20 = 1.0 is
  exact in binary floating point (0.05 rounds to 0.05 + 2.8e-18, and the product rounds back to
  1.0), so stations at 1 m from the aft end of the member or from its fore end sit exactly on the
  tolerance. A station 0.999 m away is closer and is merged.
  Segment element counts: max(1, round(n L_seg / L)) = 1 for each segment (module docstring of
  flexshaft.assembly.mesh's segment_mesh), so the nodes are the kept stations themselves.
* Speed range (docs/limits.md, [operating] table, verbatim): "speed-range fractions | above 0,
  up to 10". 10 is allowed, and with Ω = 100 rad/s the range (0.5, 10) gives the limits
  0.5 x 100 = 50 and 10 x 100 = 1000 rad/s (Operating.speed_limits docstring: the lowest and
  highest operating speeds of speed_range).
* Override paths (flexshaft.design.io.with_overrides docstring): "Paths use dots for table keys
  and [i] for list items", i.e. keys joined by "."; a path ending in a dot names no key after the
  dot, so it is malformed: with_overrides refuses it, value_at_path returns ``missing`` ("or
  missing when the path is malformed") and paths_overlap says it overlaps nothing ("A malformed
  path overlaps nothing").

All exact comparisons: no arithmetic beyond the binary-exact products above. Pure schema and
mesh-station work, a few ms each.
"""

from __future__ import annotations

import numpy as np
import pytest
from pydantic import ValidationError

from flexshaft.assembly.mesh import segment_mesh
from flexshaft.design import DesignError, baseline_design
from flexshaft.design.io import paths_overlap, value_at_path, with_overrides
from flexshaft.design.loads import Operating


@pytest.mark.parametrize(
    ("station", "kept"),
    [
        (1.0, True),  # exactly 5 % of h from the fore end: not closer, a node
        (19.0, True),  # exactly 5 % of h from the aft end: a node
        (0.999, False),  # closer than 5 % of h: merged into the end
        (19.001, False),
    ],
)
def test_a_station_exactly_five_percent_of_an_element_away_is_a_node(station: float, kept: bool) -> None:
    nodes = segment_mesh([0.0, station, 20.0], 1)
    expected = [0.0, station, 20.0] if kept else [0.0, 20.0]
    np.testing.assert_array_equal(nodes, expected)


def test_a_speed_range_fraction_of_ten_is_allowed() -> None:
    operating = Operating(speed=100.0, power=0.0, speed_range=(0.5, 10.0))
    assert operating.speed_limits == (50.0, 1000.0)
    with pytest.raises(ValidationError, match="speed_range"):
        Operating(speed=100.0, power=0.0, speed_range=(0.5, 10.5))


def test_an_override_path_ending_in_a_dot_is_malformed() -> None:
    design = baseline_design()
    with pytest.raises(DesignError, match="malformed override path"):
        with_overrides(design, {"shaft.wall_thickness.": 0.002})
    dump = design.model_dump(mode="python")
    missing = object()
    assert value_at_path(dump, "shaft.wall_thickness.", missing) is missing
    assert value_at_path(dump, "shaft.wall_thickness", missing) == design.shaft.wall_thickness
    assert not paths_overlap("shaft.wall_thickness.", "shaft.wall_thickness")
    assert paths_overlap("shaft.wall_thickness", "shaft")  # a well-formed pair does overlap
