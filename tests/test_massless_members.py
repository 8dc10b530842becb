"""The modal basis of a nearly massless member (issue 27): the Jeffcott idealisation, density 1e-6.

The schema documents a density of 1e-6 kg/m³ as "the massless-member idealisation of a Jeffcott
rotor". The dense basis used to reduce ``K φ = ω² M φ`` on M (Cholesky of a nearly singular M)
and gave the Jeffcott frequency 17 % low and 19 % high with damping ratios 0.038 and 0.0196
instead of 0.02; it now solves the shift-inverted problem ``M φ = μ (K + M) φ`` (see
:func:`flexshaft.analyses.reduced_basis.modal_basis`).

References, written out here:

* the Jeffcott rotor of tests/rotors.py (20 kg disk at mid-span of a pinned-pinned steel tube,
  k = 48 E I / L³): with a tube of mass m_s the Rayleigh quotient of the static deflection
  shape gives the effective disk mass ``m_e = m + (17/35) m_s + 4.8 ρ I / L`` (translation,
  and the tube's rotary inertia ρ I ∫ w'² over w(L/2)²: 2 ∫₀^{L/2} (3L² − 12x²)² dx / L⁶ =
  4.8/L), exact to first order in m_s/m because cubic beam elements with a node at the load
  reproduce the static shape; so ``ω_n = √(k/m_e)`` and, with a dashpot c at the disk,
  ``ζ = c / (2 √(k m_e))``, to ``(m_s/m)²`` (Rayleigh's second-order error);
* the hysteretic shaft at rest: the loss stiffness η k condenses exactly onto the disk, so
  ``m_e s² + k (1 + iη) = 0``: ``|s| = ω_n (1 + η²)^¼`` and ``ζ = sin(½ atan η)``;
* for the ordinary (embedded) designs: the a-posteriori residual bound of each computed
  eigenpair of the symmetric-definite pencil, independent of how the pair was computed.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as la
from rotors import DI, DO, K_SHAFT, M_DISK, L, jeffcott_text

from flexshaft.analyses.eigen import reduce
from flexshaft.analyses.guards import RefusedInputError
from flexshaft.analyses.modal import modes
from flexshaft.analyses.reduced_basis import modal_basis
from flexshaft.assembly import build_model
from flexshaft.assembly.sparse import restrict
from flexshaft.design import EMBEDDED_DESIGNS, embedded_design, loads_design

AREA = np.pi * (DO**2 - DI**2) / 4
#: Newton's method on T(s) y = 0 (flexshaft.analyses.eigen.newton) stops at a step of 1e-10 |s|.
NEWTON_STEP = 1e-10
INERTIA = np.pi * (DO**4 - DI**4) / 64
EPS = np.finfo(float).eps
SHIFT = 1.0  # σ of the basis's shift-invert [rad²/s²]


def jeffcott(density: float, eta: float = 0.0, c_e: float = 0.0):
    text = jeffcott_text(eta, c_e).replace("density = 0.1", f"density = {density!r}")
    return build_model(loads_design(text))


def effective_mass(density: float) -> float:
    """m + (17/35) ρ A L + 4.8 ρ I / L (module docstring)."""
    return M_DISK + 17 / 35 * density * AREA * L + 4.8 * density * INERTIA / L


def basis_matrices(model):
    free = model.dofs.free
    K = restrict((model.K + model.Kp).tocsr(), free).toarray()
    M = restrict(model.M, free).toarray()
    return K, M


def residual_bound(K: np.ndarray, M: np.ndarray, w2: np.ndarray, Phi: np.ndarray) -> np.ndarray:
    """A-posteriori bound on |λ − λ̃| / (λ̃ + σ) for each pair (λ̃, φ) of ``K φ = λ M φ``.

    With ``K_σ = K + σM`` positive definite the pencil ``(M, K_σ)`` has the eigenvalues
    ``μ = 1/(λ + σ)``; for any vector φ and ``μ̃ = 1/(λ̃ + σ)`` some μ satisfies
    ``|μ − μ̃| ≤ ‖M φ − μ̃ K_σ φ‖_{K_σ⁻¹} / ‖φ‖_{K_σ}`` (the residual theorem of the
    symmetric-definite problem), and ``M φ − μ̃ K_σ φ = −μ̃ (K − λ̃ M) φ``. The K_σ⁻¹-norm is
    computed with a Cholesky factor of the well-conditioned K_σ. The residual is itself computed
    in double precision, with an error up to ``ε (|K| |φ| + |λ̃| |M| |φ|)`` elementwise (the
    cancellation in K φ of a low mode: up to 100 % of the residual of a converged pair here),
    whose K_σ⁻¹-norm is added.
    """
    factor = la.cho_factor(K + SHIFT * M)
    R = K @ Phi - (M @ Phi) * w2
    rounding = EPS * (np.abs(K) @ np.abs(Phi) + np.abs(w2) * (np.abs(M) @ np.abs(Phi)))

    def norm(X):
        return np.sqrt(np.einsum("ij,ij->j", X, la.cho_solve(factor, X)))

    size = np.sqrt(np.einsum("ij,ij->j", Phi, (K + SHIFT * M) @ Phi))
    return (norm(R) + norm(rounding)) / size  # ≥ |δμ|/μ̃, i.e. |δλ|/(λ̃ + σ) to first order


# ---------------------------------------------------------------------------------------------
# The Jeffcott idealisation


@pytest.mark.parametrize("density", [1e-6, 1e-5, 1e-4, 1e-3, 1e-2])
def test_jeffcott_modes_of_a_massless_tube_match_the_closed_form(density):
    """Both whirls at rest at ω_n = √(k/m_e) with ζ = c/(2√(k m_e)) (ζ = 0.02 here).

    Tolerance: (m_s/m)² (Rayleigh's second-order error; 1.2e-13 at 1e-2) plus the basis's
    residual bound on this model (the solver's own error, ≤ 1e-13 here) plus the Newton
    refinement's stopping step, NEWTON_STEP of |s|, times 10: the last step bounds the error only
    if the iteration contracts, by at most r/(1 − r) = 9 steps for a contraction ratio r ≤ 0.9,
    which this pencil's conditioning (K's top eigenvalue 3.6e13 ω_n² at 1e-4) allows; the modes'
    stated accuracy is 1e-6 (docs/model.md). Before the fix: |s|/ω_n = 0.83 and 1.19 at 1e-6."""
    m_e = effective_mass(density)
    omega = np.sqrt(K_SHAFT / m_e)
    c = 2 * 0.02 * np.sqrt(K_SHAFT * M_DISK)
    model = jeffcott(density, c_e=c)
    K, M = basis_matrices(model)
    w2, Phi = modal_basis(model, 2)
    solver = float(residual_bound(K, M, w2, Phi).max())
    tolerance = 10 * ((density * AREA * L / M_DISK) ** 2 + solver + NEWTON_STEP)
    result = modes(model, 0.0, 2)
    assert np.abs(result.eigenvalues) / omega == pytest.approx([1.0, 1.0], abs=tolerance)
    assert result.damping_ratios / (c / (2 * np.sqrt(K_SHAFT * m_e))) == pytest.approx([1.0, 1.0], abs=tolerance)
    assert np.all(result.kind == "lateral")


def test_jeffcott_basis_seen_at_the_disk_is_the_disk_mass_and_the_beam_stiffness():
    """What the run-up integrates: the two-mode basis seen at the disk's (v, w) is ``m_e I`` and
    ``k I`` (with P the disk rows of the mass-normalised basis, M = P⁻ᵀP⁻¹, K = P⁻ᵀΛP⁻¹). Before
    the fix the basis frequencies at 1e-6 were 1.085 ω_n: the run-up peak came out 22 % high.
    Tolerance as in the test above, with no Newton step: (m_s/m)² + 10 × the residual bound."""
    for density in (1e-6, 1e-4, 1e-2):
        model = jeffcott(density)
        red = reduce(model, 2)
        dm = model.dofs
        pos = np.full(dm.size, -1)
        pos[dm.free] = np.arange(dm.free.size)
        node = dm.node_at("shaft", L / 2)
        rows = [pos[dm.shaft(node, "v")], pos[dm.shaft(node, "w")]]
        Pinv = np.linalg.inv(red.Phi[rows])
        K, M = basis_matrices(model)
        tolerance = (density * AREA * L / M_DISK) ** 2 + 10 * float(residual_bound(K, M, red.w2, red.Phi).max())
        m_e = effective_mass(density)
        np.testing.assert_allclose(Pinv.T @ Pinv / m_e, np.eye(2), atol=tolerance + 1e-12)
        np.testing.assert_allclose(Pinv.T @ np.diag(red.w2) @ Pinv / K_SHAFT, np.eye(2), atol=tolerance + 1e-12)


def test_hysteretic_massless_jeffcott_at_rest_has_the_complex_stiffness_root():
    """η = 0.02 in the tube alone: ``s = iω_n √(1 + iη)``, so |s| = ω_n (1 + η²)^¼ and
    ζ = sin(½ atan η) (0.009999), at density 1e-6; the Newton refinement converges to 1e-10
    of |s|, and the residual tube mass is 3.5e-11 of the disk's."""
    eta = 0.02
    model = jeffcott(1e-6, eta=eta)
    result = modes(model, 0.0, 2)
    omega = np.sqrt(K_SHAFT / effective_mass(1e-6))
    assert np.abs(result.eigenvalues) == pytest.approx(np.full(2, omega * (1 + eta**2) ** 0.25), rel=1e-9)
    assert result.damping_ratios == pytest.approx(np.full(2, np.sin(0.5 * np.arctan(eta))), rel=1e-8)


def test_a_degenerate_pair_is_resolved_into_forward_and_backward_whirl():
    """The two whirls of the axisymmetric Jeffcott rotor at rest share one eigenvalue, so any
    combination is a mode; the circular ones (whirl ratio ±1 exactly, W = ∓iV) are returned,
    forward first, instead of the solver's arbitrary pair (flexshaft.analyses.classify)."""
    result = modes(jeffcott(1e-6, c_e=10.0), 0.0, 2)
    assert list(result.whirl) == ["forward", "backward"]
    assert result.whirl_ratios == pytest.approx([1.0, -1.0], abs=1e-9)


def test_a_free_massless_member_is_refused_with_the_reason():
    """A free rigid-body motion of a member with almost no mass or inertia makes K + M
    singular to working precision (no supports, no fixed DOF, density 1e-6): a ValueError naming
    the cause, not a traceback from the factorisation."""
    text = (
        jeffcott_text(0.0, 0.0)
        .replace("density = 0.1", "density = 1e-6")
        .replace('fixed_start = ["u", "v", "w", "theta"]', "")
        .replace('fixed_end = ["v", "w"]', "")
    )
    model = build_model(loads_design(text))
    for method in ("dense", "sparse"):
        with pytest.raises(RefusedInputError, match="rigid-body motion carries almost no mass"):
            modal_basis(model, 4, method)


# ---------------------------------------------------------------------------------------------
# The ordinary designs do not move


@pytest.mark.parametrize("name", EMBEDDED_DESIGNS)
def test_embedded_designs_basis_is_within_its_error_bound_and_moves_only_by_the_old_solvers_error(name):
    """The basis of each embedded design against the a-posteriori residual bound.

    * Each computed pair's residual bound ``|δλ|/(λ + σ)`` lies below the a-priori bound of
      the Cholesky-reduced inverted problem, ``n ε ‖M‖₂ ‖K_σ⁻¹‖₂ (λ + σ)`` (the solver is
      backward stable on the well-conditioned K_σ).
    * The previous solver (``eigh(K, M)``, Cholesky of M: a priori ``n ε ‖K‖ ‖M⁻¹‖`` in λ,
      0.1-0.2 of f1² here, no bound at all) differs from the new one by no more than the sum of
      the two solutions' residual bounds: the ordinary designs' modes move within the previous
      solver's own error (by 8e-9 at most, in the current driveline's f1²), nothing else.
    """
    model = build_model(embedded_design(name))
    K, M = basis_matrices(model)
    n, nb = K.shape[0], 60
    w2, Phi = modal_basis(model, nb, "dense")
    new = residual_bound(K, M, w2, Phi)
    a_priori = n * EPS * la.norm(M, 2) / la.eigvalsh(K + SHIFT * M, subset_by_index=[0, 0])[0] * (w2 + SHIFT)
    assert np.all(new <= a_priori)
    w2_old, Phi_old = la.eigh(K, M, subset_by_index=[0, nb - 1])
    old = residual_bound(K, M, w2_old, Phi_old)
    # first-order bounds in μ = 1/(λ + σ): the second-order term, (bound)², is below 1e-15
    assert np.all(np.abs(w2 - w2_old) / (w2 + SHIFT) <= old + new + 1e-15)
