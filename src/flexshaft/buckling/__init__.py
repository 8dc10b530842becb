"""Torsional buckling of a thin laminated circular tube with simply supported ends (thesis sec. 2.7).

Model
-----
Thin shell of radius R (mid-surface), length L, laminate stiffness A, B, D (storage parts),
loaded by a torque T about the axis, which gives the uniform membrane shear flow
N_xy = T / (2 pi R^2) (membrane pre-buckling state; the pre-buckling rotations are neglected).
x is axial, y = R theta circumferential, w outward; ply angles are measured from x towards y, so a
positive torque (vector along +x on the end x = L) puts +45 deg fibres in tension.

Two shell theories (``theory=``):

* ``"shear"`` (default, :mod:`flexshaft.buckling.shear`): first-order shear deformation
  (Reissner-Mindlin normal rotations) with the transverse shear stiffness A44, A55, A45 from the
  plies' G_13, G_23 and a shear correction factor. The thesis names low transverse shear stiffness
  as the main cause of torsional instability in composite shafts and used Bauchau's shear-
  deformable shell; soft-matrix FMC walls buckle by short-wave shear crimping, T -> 2 pi R^2
  (sqrt(A44 A55) -/+ A45).
* ``"classical"`` (:mod:`flexshaft.buckling.classical`): Kirchhoff-Love, no transverse shear;
  unconservative for FMC, kept for comparison and for stiff-matrix laminates.

Both use Donnell's or Sanders' kinematics (``kinematics=``, Sanders by default) and a Rayleigh-
Ritz (Galerkin) solution with a full Fourier harmonic e^{i n theta} around the circumference
(n >= 2) and sine/cosine series along the axis that satisfy v = w = 0 (and phi_y = 0) at both
ends, with N_x = M_x = 0 natural (classical simple support "SS3", as in Batdorf's solutions). The
first-derivative terms of the torsion load and of the 16/26 (and 45) stiffnesses couple odd and
even axial terms, so a helical mode is built from many terms; the complex circumferential
harmonic lets the helix lean either way, and the extreme eigenvalues of K a = T G a of either
sign give the critical torque of each sense. The exact single-helix solution of the infinitely
long tube (:func:`infinite_cylinder_torque`) sets the number of axial terms and bounds the
finite tube from below.

Assumptions and limits: linear pre-buckling state, perfect geometry (no knock-down factor), thin
shell (R >> t), elastic storage moduli.

References
----------
Donnell, L. H. (1933). Stability of thin-walled tubes under torsion. NACA Report 479.
Batdorf, S. B., Stein, M., Schildcrout, M. (1947). Critical stress of thin-walled cylinders in
torsion. NACA TN 1344.
Sanders, J. L. (1963). Nonlinear theories for thin shells. Q. Appl. Math. 21, 21-36.
Timoshenko, S. P. and Gere, J. M. (1961). *Theory of Elastic Stability*, 2nd ed., sec. 11.12.
Jones, R. M. (2006). *Buckling of Bars, Plates, and Shells*, Bull Ridge, ch. 7.
Reddy, J. N. (2004). *Mechanics of Laminated Composite Plates and Shells*, 2nd ed., ch. 10.
Bauchau, O. A., Krafchack, T. M. and Hayes, J. F. (1988). Torsional buckling analysis and
damage tolerance of graphite/epoxy shafts. J. Compos. Mater. 22, 258-270.
Ocalan, M. (2002). MS thesis, Penn State, sec. 2.7.
"""

from flexshaft.buckling._common import Kinematics, ShellTheory, shell_stiffness
from flexshaft.buckling.shear import crimping_torques
from flexshaft.buckling.torque import (
    BucklingResult,
    buckling_safety_factor,
    galerkin_matrices,
    infinite_cylinder_torque,
    torsional_buckling_torque,
)

__all__ = [
    "ShellTheory",
    "Kinematics",
    "BucklingResult",
    "shell_stiffness",
    "galerkin_matrices",
    "infinite_cylinder_torque",
    "torsional_buckling_torque",
    "buckling_safety_factor",
    "crimping_torques",
]
