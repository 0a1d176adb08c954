r"""Helicopter rotor blade flapping about its hinge, with the aerodynamic generalised force.

Source: ``sources/002_df41972c66c4514e.txt``, Cambridge 3C5 notes, handwritten "Helicopter
Rotor Blade Example" at the end ("length = L, Mass/unit length = M, Generalised Force (take
beta small): Lift proportional to angle of attack x velocity?" -- the square is lost in the
extraction and restored from the expansion printed next, ``alpha0 x^2 Omega^2 - ...``).

A uniform blade (length ``L``, mass ``M`` per unit length) is hinged at the rotor axis and
turns with it at the constant rate ``Omega``; it flaps up by the angle ``beta`` about the
hinge, which is horizontal and across the blade.  Its pitch is ``alpha0``.  A station at
``x`` from the hinge moves at ``Omega x`` (beta small) and, flapping, at ``x beta'`` up: the
air meets it at ``alpha0 - x beta' / (x Omega)`` and lifts it with ``A (alpha - ...) (x
Omega)^2`` per unit length (``A`` lumps density, chord and lift slope)::

      side view in the rotating hub frame H (Omega about Z)
                                   . tip
                  z_b         .                lift per unit length at x, along z_b:
                   ^     .   L                   w(x) = A (alpha0 Omega^2 x^2 - Omega x^2 beta')
                   | .  beta
      Z   hinge ---o----------------> x_H       (weight neglected, as in the source)
      |            |
      +-- x_H      | rotor axis, Omega

Frames (columns = the child's unit vectors in the parent)::

    O = ground (Z up);  H = O.child(rot_z(Omega t)) turns with the rotor;
    b = H.child(rot_y(-beta)):  x_b along the blade, z_b its normal in the flap plane,
    y_b = y_H the hinge axis (the blade's direction of travel); positive beta is a turn
    about -y_b, so the blade rises.

Body: the blade, a thin rod of mass ``M L`` along ``x_b``, centre at ``L/2 x_b``.

Free-body diagram (the source neglects the blade's weight; so does this model): the lift,
``w(x) z_b`` along the span,
replaced by its resultant ``F = int_0^L w dx = A L^3 (alpha0 Omega^2 - Omega beta') / 3`` at
the centre of pressure ``x_p = int x w dx / F = 3 L / 4``; at the hinge the pin force and the
moments about ``x_b`` and ``z_b`` (none about the hinge axis) -- all without moment about
``y_b`` at the hinge, so left out of the one equation used.

Direct form: ``sum tau_hinge = dH_hinge/dt`` on ``-y_b`` (the hinge is fixed)::

    (M L^3 / 3) (beta'' + Omega^2 sin(beta) cos(beta)) = F x_p = A L^4 (alpha0 Omega^2 - Omega beta') / 4

Lagrangian, written independently: a station at ``x`` moves at ``x beta'`` across the blade
and ``Omega x cos(beta)`` round the axis::

    T = int_0^L M (x^2 beta'^2 + Omega^2 x^2 cos^2 beta) / 2 dx = M L^3 (beta'^2 + Omega^2 cos^2 beta) / 6
    V = 0 (no weight)
    delta W = int_0^L w(x) (x delta beta) dx   =>   Q = int_0^L w(x) x dx = A L^4 (alpha0 Omega^2 - Omega beta') / 4

Small flapping (``alpha0 = 0``): ``(M L^3/3) beta'' + (A Omega L^4/4) beta' + (M L^3/3)
Omega^2 beta = 0`` -- the flapping frequency is the rotor speed and the damping ratio
``3 A L / (8 M)`` (the Lock number over 16).  With pitch the blade cones at
``sin(2 beta0) = 3 A alpha0 L / (2 M)``.

Where the model departs from the source, and the richer variant: nowhere in the equations --
the source's "Mass/unit length = M" and its lift are all it takes into account, and the
reference follows it.  The blade's weight (``V = M g L^2 sin(beta)/2``, a moment
``(M g L^2/2) cos(beta)`` about the hinge) is the next rung of this scene's fidelity ladder,
:class:`HelicopterBladeWeighted` (``helicopter_blade_weighted``; ``dualmech fidelity
helicopter_blade`` shows what it adds: next to the centrifugal stiffness ``M L^3 Omega^2/3``
it is small at rotor speed, and it lowers the coning angle).

The rotor speed is prescribed; the torque that keeps it constant, like the pin force, is
not asked for by the source and is not modelled.

Errata and unreadable formulas:

* Angle of attack: the extraction prints the lift as ``A dx (alpha0 + x beta' / (x Omega))
  (x Omega)^2`` but expands it on the same line to ``A dx [alpha0 x^2 Omega^2 - x beta' x
  Omega]``.  Rising (``beta' > 0``) the blade meets the air from above, so the angle of
  attack is ``alpha0 - beta' / Omega``: the ``+`` of the factored form is WRONG (the
  expansion, which the rest uses, is right).  Whether the sign is the handwriting's or the
  extraction's cannot be told from the text.
* The generalised force is printed as "Q = 3Adx^3A^2 - 3AAL^3 beta"; read as the virtual-work
  integral ``Q = int_0^L (A alpha0 x^3 Omega^2 - A Omega x^3 beta') dx`` (the ``S``/``3`` of
  the extraction are integral signs elsewhere in the same line).  So read, it is right.  Its
  evaluated form, and T, V and the equation of motion, are not in the extracted text.
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, FidelityRung, Frame, Lagrangian, NewtonEuler,
                      Parameter, Point, Problem, Published, RigidBody, coordinate, rate, rot_y,
                      rot_z, t, thin_rod, ACCELERATION, ANGLE, FREQUENCY, LENGTH, MASS)

__all__ = ["HelicopterBlade", "HelicopterBladeWeighted", "PROBLEMS", "frames", "lift_per_length", "first_order", "M", "L",
           "Omega", "A", "alpha0", "g", "beta", "x"]

M, L, Omega, A, g = sp.symbols("M L Omega A g", positive=True)
alpha0 = sp.Symbol("alpha0", real=True)
beta = coordinate("beta")
x = sp.Symbol("x", positive=True)   # station along the blade (integration variable)


def frames() -> SimpleNamespace:
    """Ground ``O``, hub ``H`` (turning at ``Omega``), blade ``b``, the hinge and station ``x``."""
    O = Frame.ground("O")
    H = O.child("H", rot_z(Omega * t))
    b = H.child("b", rot_y(-beta))
    hinge = Point.origin(O, "hinge")
    return SimpleNamespace(O=O, H=H, b=b, hinge=hinge, station=hinge.locate("x", x * b.x))


def lift_per_length():
    """The source's lift per unit length at station ``x`` (beta small), along ``z_b``."""
    return A * (alpha0 * Omega**2 * x**2 - Omega * x**2 * rate(beta))


def first_order(expr):
    """``expr`` to first order in ``beta`` and ``beta'`` about 0 (the source's "beta small")."""
    b0, b1 = sp.symbols("b0 b1", real=True)
    e = expr.subs(rate(beta), b1).subs(beta, b0)
    at0 = {b0: 0, b1: 0}
    out = e.subs(at0) + b0 * e.diff(b0).subs(at0) + b1 * e.diff(b1).subs(at0)
    return sp.expand(out.subs({b0: beta, b1: rate(beta)}))


class HelicopterBlade(Problem):
    """Rotor blade flapping about a hinge on the rotor axis (see module doc)."""

    name = "helicopter_blade"
    title = "Helicopter blade flapping"
    source = "002_df41972c66c4514e.txt: handwritten helicopter rotor blade example"
    summary = ("Hinged blade turning at a fixed rotor speed, flapping under centrifugal and "
               "aerodynamic loads (weight neglected, as in the source); the lift's generalised "
               "force by virtual work against its resultant at the centre of pressure.")
    parameters = (
        Parameter(M, MASS / LENGTH, 10.0, (1.0, 50.0), "blade mass per unit length"),
        Parameter(L, LENGTH, 5.0, (1.0, 10.0), "blade length, hinge to tip"),
        Parameter(Omega, FREQUENCY, 30.0, (5.0, 60.0), "rotor speed"),
        Parameter(A, MASS / LENGTH**2, 0.3, (0.01, 2.0),
                  "lift per unit length per unit angle of attack per unit speed squared"),
        Parameter(alpha0, ANGLE, 0.1, (-0.3, 0.3), "blade pitch"),
    )
    coordinates = (
        Coordinate(beta, ANGLE, (-0.6, 0.6), (-3.0, 3.0), "flapping angle, up from the hub plane"),
    )
    reactions = ()
    singular = ()
    # the ladder both variants share (the weighted one is defined below)
    fidelity_ladder = (
        FidelityRung("source: weight neglected", lambda: HelicopterBlade(),
                     "the blade's weight, M g L^2 cos(beta)/2 about the hinge"),
        FidelityRung("blade's weight kept", lambda: HelicopterBladeWeighted()),
    )

    weight = False   # the source neglects the blade's weight (HelicopterBladeWeighted keeps it)

    # -- direct form: moments about the hinge on the hinge axis --------------------------------
    def newton_euler(self) -> EquationSet:
        """Lift as its resultant at the centre of pressure (integrals taken here, by sympy)."""
        f = frames()
        blade = RigidBody("blade", M * L, f.hinge.locate("G", L / 2 * f.b.x), f.b,
                          thin_rod(M * L, L, axis="x"))
        w = lift_per_length()
        resultant = sp.integrate(w, (x, 0, L))
        x_p = sp.cancel(sp.integrate(x * w, (x, 0, L)) / resultant)
        ne = NewtonEuler(coordinates=[beta], ground=f.O,
                         description="sum tau_hinge = dH_hinge/dt on the flap axis -y_b")
        if self.weight:
            ne.gravity(-g * f.O.z)
        ne.force("lift", blade, resultant * f.b.z, at=f.hinge.locate("cp", x_p * f.b.x))
        ne.angular_momentum(blade, -f.b.y, about=f.hinge)
        return ne.equations()

    # -- indirect form ---------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """T, V by hand; Q from the virtual work of the lift, ``int w(x) x dx``."""
        lg = Lagrangian(coordinates=[beta], description="T, V of the blade by hand; lift by "
                                                        "virtual work")
        lg.kinetic("T of blade", M * L**3 * (rate(beta)**2 + Omega**2 * sp.cos(beta)**2) / 6)
        if self.weight:
            lg.potential("gravity", M * g * L**2 * sp.sin(beta) / 2)
        lg.generalized_force("lift", [sp.integrate(lift_per_length() * x, (x, 0, L))])
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        v = f.station.vel(f.O)
        v_n, v_t = v.dot(f.b.z), v.dot(f.b.y)          # up across the blade; along its travel
        alpha = alpha0 - sp.atan(sp.cancel(v_n / v_t))
        lift = A * alpha * v.dot(v)                     # angle of attack x speed^2
        at_tip = {x: L}
        printed_lift = A * (alpha0 + x * rate(beta) / (x * Omega)) * (x * Omega)**2
        expanded = A * (alpha0 * x**2 * Omega**2 - x * rate(beta) * x * Omega)
        Q_printed = sp.integrate(A * alpha0 * x**3 * Omega**2 - A * Omega * x**3 * rate(beta),
                                 (x, 0, L))
        Q_ref = sp.integrate(lift_per_length() * f.b.z.dot(v.diff(rate(beta), f.b)), (x, 0, L))
        return [
            Published("angle of attack", "expression",
                      (alpha0 + x * rate(beta) / (x * Omega),), (first_order(alpha),),
                      where="helicopter example, lift line: WRONG as extracted, alpha0 + x beta'"
                      "/(x Omega); a rising blade meets the air from above: alpha0 - beta'/Omega"),
            Published("lift per unit length, factored (at the tip)", "expression",
                      (printed_lift.subs(at_tip),), (first_order(lift).subs(at_tip),),
                      where="helicopter example: A dx (alpha0 + x beta'/(x Omega)) (x Omega)^2, "
                      "printed for any x, judged at x = L: WRONG, the sign of the angle above"),
            Published("lift per unit length, expanded (at the tip)", "expression",
                      (expanded.subs(at_tip),), (first_order(lift).subs(at_tip),),
                      where="helicopter example: A dx [alpha0 x^2 Omega^2 - x beta' x Omega], "
                      "judged at x = L"),
            Published("generalised force Q", "expression", (Q_printed,), (Q_ref,),
                      where="helicopter example, virtual work: Q = int_0^L (A alpha0 x^3 Omega^2"
                      " - A Omega x^3 beta') dx (read from a garbled line)"),
        ]


class HelicopterBladeWeighted(HelicopterBlade):
    """The richer variant: the blade's weight kept (``V = M g L^2 sin(beta)/2``; module doc)."""

    name = "helicopter_blade_weighted"
    title = "Helicopter blade flapping, with the blade's weight"
    source = "002_df41972c66c4514e.txt: handwritten helicopter rotor blade example (weight added)"
    summary = ("The helicopter blade with its weight, which the source neglects: the next rung "
               "of the blade's fidelity ladder.")
    parameters = HelicopterBlade.parameters + (
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(beta, ANGLE, (-0.6, 0.6), (-3.0, 3.0), "flapping angle, up from the hub plane"),
    )
    weight = True   # the printed answers (lift, Q) do not involve the weight: inherited


PROBLEMS = (HelicopterBlade, HelicopterBladeWeighted)
