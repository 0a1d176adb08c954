r"""Symmetric top on a fixed point under gravity, in z-y-z Euler angles; its steady precession.

Source: ``sources/002_df41972c66c4514e.txt``, Cambridge 3C5 notes, section 5, "Example:
Symmetrical top" (after Euler's equations via Euler angles).

A top spins about its symmetry axis z; its tip O is a fixed frictionless point.  Moments of
inertia about O: ``A`` about any axis across the symmetry axis (the source's ``A = B``), ``C``
about it.  The mass centre G lies on the axis at distance ``h`` from O; mass ``M``; gravity
``-g Z``.  Euler angles as in section 5: ``phi`` (precession) about Z, ``theta`` (nutation,
the tilt of z from the upward vertical Z) about y_1, ``psi`` (spin) about z::

               Z                         z_b (symmetry axis)
               |        theta        .
               |   .--------------. /  G at h z_b, weight -M g Z
               |  /                /
               | /                / .
               |/  phi' (precession about Z)
               O ---------- Y     psi' (spin about z_b)
              /
             X

Frames (columns = the child's unit vectors in the parent)::

    O  = ground,  F1 = O.child(rot_z(phi)),  F2 = F1.child(rot_y(theta)),  b = F2.child(rot_z(psi))
    G  = O + h z_b

F2 is the "nutation frame": it tilts with the axis but does not spin, and z_2 = z_b.

Body and free-body diagram: the top, inertia about G in body axes
``diag(A - M h^2, A - M h^2, C)`` (so ``diag(A, A, C)`` about O by the parallel-axis theorem);
its weight ``-M g Z`` at G; the pivot force at O (no moment about O, so left out).

Direct form: ``sum tau_O = d/dt H_O`` (O fixed) projected on the nutation frame F2 (model
``newton_euler``) and, once more, on the body axes x, y, z (model ``body_axes``: the
source's Euler equations with ``A = B`` and the gravity torque as ``Q``).  By hand, with
``w3 = psi' + phi' cos(theta)``: in F2 the body turns at ``(-phi' sin(theta), theta', w3)``
and F2 itself at ``(-phi' sin(theta), theta', phi' cos(theta))``; ``H_O = (-A phi'
sin(theta), A theta', C w3)``; the weight's moment is ``h z_2 x (-M g Z) = M g h sin(theta)
y_2``; ``dH_O/dt = (dH_O/dt in F2) + w_F2 x H_O`` gives::

    x_2:  -A phi'' sin(theta) - 2 A phi' theta' cos(theta) + C w3 theta' = 0
    y_2:  A theta'' - A phi'^2 sin(theta) cos(theta) + C w3 phi' sin(theta) = M g h sin(theta)
    z_2:  C w3' = 0

Lagrangian, written independently::

    T = A (theta'^2 + phi'^2 sin^2 theta) / 2 + C (psi' + phi' cos theta)^2 / 2
    V = M g h cos(theta)

    theta:  A theta'' - A phi'^2 sin(theta) cos(theta) + C w3 phi' sin(theta) - M g h sin(theta) = 0
    phi, psi are ignorable: p_phi = A phi' sin^2 theta + C w3 cos theta and p_psi = C w3 are
    conserved (section 3.1: Q = 0, dV/dq = 0 and dT/dq = 0 for these two).

Steady precession (theta constant: theta'' = theta' = 0; phi', psi' constant), theta != 0::

    (C - A) cos(theta) phi'^2 + C psi' phi' - M g h = 0        (equivalently
    -A cos(theta) phi'^2 + C w3 phi' - M g h = 0)

computed by :func:`steady_precession_rates` from the verified equations.  Its two limits are
the source's two results: fast spin, ``psi' >> phi'``: the slow root ``phi' -> M g h / (C
psi')`` ("Precession"); gravity negligible: ``A cos(theta) phi' - C (psi' + phi' cos theta)
= 0``, ``phi' = C psi' / ((A - C) cos theta)`` ("Nutation").

Singular set: ``det M = A^2 C sin^2(theta)`` -- gimbal lock of the Euler angles at the
upright (and hanging) position, where phi and psi turn about the same axis.

Errata and unreadable formulas:

* The source's top section is mostly lost in the extraction: the figure, T and V, the theta
  equation after "Then theta'' = 0 and:-", and the precession formula after "high spin
  rate. Then:" cannot be read.  The precession rate ``M g h / (C psi')`` is the standard
  fast-top result the text announces (its symbols ``M, h`` are ours); the test checks the
  library's exact slow root against it as ``psi' -> oo``.
* The "Nutation" line reads "assume [M g h] is negligibly small = A cos(theta) [phi'] -
  C([psi'] + [phi'] cos(theta)) [= 0]" with the dots and the gravity term garbled; read so,
  it is right (the nonzero steady rate with ``g = 0``).
* "Now suppose theta != 0 (top not vertical) and that [psi'] >> [phi'] (high spin rate)": the
  extraction shows ``Y >> theta`` with hats, read as ``psi' >> phi'`` (on a steady
  precession ``theta' = 0``, so the condition can only compare the spin with the precession
  rate); the fast-top limit needs exactly that.
* Printed and right: T of section 5 with ``A = B``.
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, RigidBody, coordinate, rate, rot_y, rot_z, ACCELERATION,
                      ANGLE, INERTIA, LENGTH, MASS)
from dualmech.model.steady import steady_rates

__all__ = ["SymmetricTop", "PROBLEMS", "frames", "steady_precession_rates", "momenta",
           "A", "C", "M", "g", "h", "phi", "theta", "psi"]

A, C, M, g, h = sp.symbols("A C M g h", positive=True)
phi, theta, psi = coordinate("phi"), coordinate("theta"), coordinate("psi")


def frames() -> SimpleNamespace:
    """The z-y-z chain ``O -> F1 -> F2 -> b``, the tip ``o`` and the mass centre ``G``."""
    O = Frame.ground("O")
    F1 = O.child("F1", rot_z(phi))
    F2 = F1.child("F2", rot_y(theta))
    b = F2.child("b", rot_z(psi))
    o = Point.origin(O, "O")
    return SimpleNamespace(O=O, F1=F1, F2=F2, b=b, o=o, G=o.locate("G", h * b.z))


def _top(f: SimpleNamespace) -> RigidBody:
    across = A - M * h**2  # about G, from A about O (parallel-axis theorem)
    return RigidBody("top", M, f.G, f.b, sp.diag(across, across, C))


def momenta() -> tuple:
    """``(p_phi, p_psi)``: the momenta of the ignorable angles, by hand from T."""
    w3 = rate(psi) + rate(phi) * sp.cos(theta)
    return A * rate(phi) * sp.sin(theta)**2 + C * w3 * sp.cos(theta), C * w3


def steady_precession_rates(eqs: EquationSet, values: dict | None = None) -> list:
    """Precession rates ``phi'`` of the steady motions of ``eqs`` with ``theta`` constant.

    ``theta'' = theta' = 0`` and constant ``phi', psi'`` in the given (verified) equations;
    see :func:`dualmech.model.steady.steady_rates`.

    >>> rates = steady_precession_rates(SymmetricTop().model("lagrange"), {g: 0})
    >>> sorted(map(str, rates))
    ['0', 'C*Derivative(psi(t), t)/((A - C)*cos(theta(t)))']
    """
    return [sp.factor(r) for r in steady_rates(eqs, [theta], rate(phi), values)]


class SymmetricTop(Problem):
    """Symmetric top with a fixed tip under gravity (see module doc)."""

    name = "symmetric_top"
    title = "Symmetric top: Euler angles, steady precession"
    source = "002_df41972c66c4514e.txt: section 5, example: symmetrical top"
    summary = ("Heavy symmetric top about its fixed tip in z-y-z Euler angles: moments about "
               "the tip on the nutation frame and on body axes against the Lagrangian; "
               "steady precession rates from the verified equations; gimbal lock upright.")
    parameters = (
        Parameter(A, INERTIA, 4e-3, (1e-3, 1.0), "moment of inertia about O across the axis"),
        Parameter(C, INERTIA, 2e-3, (5e-4, 1.0), "moment of inertia about the symmetry axis"),
        Parameter(M, MASS, 0.5, (0.05, 5.0), "mass of the top"),
        Parameter(h, LENGTH, 0.05, (0.01, 0.5), "distance of the mass centre from the tip"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-3.0, 3.0), "precession, about Z"),
        Coordinate(theta, ANGLE, (0.3, 2.8), (-3.0, 3.0), "nutation: tilt from the vertical"),
        Coordinate(psi, ANGLE, (-3.0, 3.0), (-60.0, 60.0), "spin, about the symmetry axis"),
    )
    reactions = ()
    singular = (sp.sin(theta),)
    extra_models = ("body_axes",)

    def _moments_about_tip(self, name: str, axes: str) -> EquationSet:
        f = frames()
        top = _top(f)
        frame = getattr(f, axes)
        ne = NewtonEuler(name, coordinates=[phi, theta, psi], ground=f.O,
                         description=f"sum tau_O = dH_O/dt on the {axes} axes; pivot force "
                                     "has no moment about O")
        ne.gravity(-g * f.O.z)
        for axis in (frame.x, frame.y, frame.z):
            ne.angular_momentum(top, axis, about=f.o)
        return ne.equations()

    # -- direct form: moments about the fixed tip -------------------------------------------
    def newton_euler(self) -> EquationSet:
        """``sum tau_O = dH_O/dt`` on the nutation frame F2 (tilts, does not spin)."""
        return self._moments_about_tip("newton_euler", "F2")

    def body_axes(self) -> EquationSet:
        """The same balance on the body axes: Euler's equations with ``A = B``."""
        return self._moments_about_tip("body_axes", "b")

    # -- indirect form ---------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """T and V by hand (see the module docstring); nothing of the frames is reused."""
        lg = Lagrangian(coordinates=[phi, theta, psi],
                        description="T = A(theta'^2 + phi'^2 sin^2)/2 + C w3^2/2, V = M g h cos")
        lg.kinetic("T of top", A * (rate(theta)**2 + rate(phi)**2 * sp.sin(theta)**2) / 2
                   + C * (rate(psi) + rate(phi) * sp.cos(theta))**2 / 2)
        lg.potential("gravity", M * g * h * sp.cos(theta))
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        st = sp.sin(theta)
        w1 = rate(theta) * sp.sin(psi) - rate(phi) * st * sp.cos(psi)
        w2 = rate(theta) * sp.cos(psi) + rate(phi) * st * sp.sin(psi)
        w3 = rate(psi) + rate(phi) * sp.cos(theta)
        return [
            Published("(5) T with A = B", "expression",
                      ((A * w1**2 + A * w2**2 + C * w3**2) / 2,),
                      (_top(f).kinetic_energy(f.O),),
                      where="section 5: T = (A w1^2 + B w2^2 + C w3^2)/2 and 'A = B for "
                      "symmetrical top' (A, C about the fixed tip)"),
        ]


PROBLEMS = (SymmetricTop,)
