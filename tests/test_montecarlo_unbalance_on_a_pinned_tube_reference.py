"""Monte-Carlo imbalance on a pinned tube below its first critical: each sample's peak orbit
is the static deflection under the sample's own unbalance force, where along the bay it was
drawn, with the eccentricity read in the unit the dataset states.

References (closed forms; docs/transient.md "Monte-Carlo imbalance"):

* **Unbalance.** docs/transient.md: bay b carries U_b = e_b m_b at an angle uniform on
  [0, 2π) "at mid-bay or uniformly along the bay (``placement``)", its position recorded as the
  fraction of the bay; with a balance grade e_b follows the ``disk`` distribution scaled by
  ``e_per Ω = G``, G in mm/s (ISO 21940-11 §5.3), so every e_b lies in [0, G/Ω] metres. One
  bay here (bearings at both ends of the tube), so m_b is the tube's mass ρ A L.
* **Quasi-static response.** The unbalance force F = e m Ω² rotates with the shaft; on an
  isotropic rotor its steady response is a forward circle of radius |F| times the static
  compliance, amplified by at most 1/(1 − (Ω/ω₁)²). A simply supported uniform beam under a
  point load F at x = a (b = L − a) deflects (Euler–Bernoulli statics, derived here: reactions
  F b/L and F a/L, EI w'' = −M integrated twice with w = 0 at both supports and w, w'
  continuous under the load)

      w(x) = F b x (L² − b² − x²) / (6 L EI)              for x ≤ a,
      w(x) = F a (L − x) (L² − a² − (L − x)²) / (6 L EI)   for x ≥ a,

  and the sample's ``shaft_peak`` is the largest radius over the nodes, so its reference is
  e m Ω² max_nodes w(x)/F. Below the first critical the orbit grows with Ω at every node,
  so the peak is at the top of the grid, the operating speed.

Numbers: steel tube D = 50 mm, wall 5 mm, L = 2 m: EI = 3.80e4 N m², ρA = 5.55 kg/m,
ω₁ = (π/L)² √(EI/ρA) = 204 rad/s; operating speed 100 rpm = 10.5 rad/s, so
(Ω/ω₁)² = 2.6e-3. The elements are Euler–Bernoulli (docs/model.md: shear off by default), and
their rotary inertia does not enter the statics. Other deviations from the closed form: the
bearings' compliance 1e-11 m/N against the tube's 4e-6 m/N at mid-span (measured 1.2e-6 to
1.1e-5 of the peak, against the same tube on stiffer bearings); the gyroscopic coupling at
10 rad/s, below the amplification term; the complex64 storage of the unit responses, 6e-8.
Tolerance 1 % relative: four times the largest of them, the dynamic amplification
(Ω/ω₁)² = 2.6e-3 (measured 0.26 %). A sampler that solved its unit
responses at mid-bay whatever position was drawn is off by the ratio of the two static
deflections (seed 0: a draw at 0.04 of the bay deflects the tube 8.0 times less than the same
unbalance at mid-bay, one at 0.80 1.7 times less); an eccentricity written in another unit than
the one stated is off by that unit's factor.
About 0.3 s CPU (6 samples, 20 spin-up speeds, 20 elements).
"""

from __future__ import annotations

import numpy as np

from flexshaft.assembly import build_model
from flexshaft.design import loads_design
from flexshaft.montecarlo.steady import run_montecarlo

E, RHO, L, D_OUT, WALL = 210e9, 7850.0, 2.0, 0.05, 0.005
PINNED_TUBE = f"""
name = "pinned tube"
[materials.steel]
kind = "isotropic"
E = {E}
G = 80e9
density = {RHO}
loss_factor = 0.002
[shaft]
x_start = 0.0
x_end = {L}
outer_diameter = {D_OUT}
wall_thickness = {WALL}
material = "steel"
fixed_start = ["u", "theta"]
[[bearings]]
name = "left"
kind = "contact"
x = 0.0
stiffness = {{ v = 1e11, w = 1e11 }}
[[bearings]]
name = "right"
kind = "contact"
x = {L}
stiffness = {{ v = 1e11, w = 1e11 }}
[operating]
speed_rpm = 100.0
power = 0.0
[mesh]
shaft_elements = 20
"""
GRADE_MM_S = 6.3
#: metres per unit of the lengths a dataset may state (CF/UDUNITS spellings)
METRES_PER = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6}


def _influence_peak(a: float, nodes: np.ndarray) -> float:
    """max over the nodes of the simply supported deflection per unit load at x = a [m/N]."""
    d_in = D_OUT - 2 * WALL
    ei = E * np.pi / 64 * (D_OUT**4 - d_in**4)
    b = L - a
    left = b * nodes * (L**2 - b**2 - nodes**2)
    right = a * (L - nodes) * (L**2 - a**2 - (L - nodes) ** 2)
    return float(np.max(np.where(nodes <= a, left, right)) / (6 * L * ei))


def test_each_sample_deflects_the_tube_as_its_own_unbalance_force_statically():
    design = loads_design(PINNED_TUBE)
    model = build_model(design)
    omega = design.operating.speed_rad_s
    tube_mass = RHO * np.pi / 4 * (D_OUT**2 - (D_OUT - 2 * WALL) ** 2) * L
    result = run_montecarlo(design, 6, seed=0, grade_mm_s=GRADE_MM_S, n_speeds=20, strength=False)
    ds = result.dataset
    assert "eccentricity_bay2" not in ds  # one bay: the span between the two bearings

    e = ds["eccentricity_bay1"]
    metres = np.asarray(e.values, dtype=float) * METRES_PER[e.attrs["units"]]
    e_per = GRADE_MM_S * 1e-3 / omega  # ISO 21940-11: e_per Ω = G, G in mm/s
    assert np.all((metres >= 0.0) & (metres <= e_per * (1 + 1e-12)))

    positions = np.asarray(ds["position_bay1"].values, dtype=float)
    assert np.ptp(positions) > 0.5  # the draws reach both halves of the bay (seed 0)
    nodes = np.asarray(model.dofs.shaft_x, dtype=float)
    expected = [ek * tube_mass * omega**2 * _influence_peak(p * L, nodes) for ek, p in zip(metres, positions)]
    np.testing.assert_allclose(ds["shaft_peak"].values, expected, rtol=1e-2)
    np.testing.assert_allclose(ds["shaft_peak_speed"].values, omega, rtol=1e-12)
