r"""The pendulum as a particle: inertial Cartesian coordinates (index-3 DAE) and body coordinates.

Source: ``sources/003_d6818267b4d96a20.txt``, lecture 18, "Example: Pendulum" (the slides
"Pendulum - inertial", "Differential index I/II", "Pendulum - body I/II", "Pendulum -
Lagrange").  A bob of mass ``m`` on a massless rod of length ``l`` hinged at the fixed point O.

Sign convention (the source's)::

        i2 (up)
        ^
        |      O (pivot)
        +------o------> i1                 r = x i1 - y i2      (y is measured DOWN from O)
               |\                          b1 =  cos(theta) i1 + sin(theta) i2
               | \  l                      b2 = -sin(theta) i1 + cos(theta) i2   (bob -> O)
               |th\                        x = l sin(theta),  y = l cos(theta)
               |   o bob m   ---> b1
                    \
                     S b2 (rod force on the bob, S > 0 in tension)      gravity -m g i2

Frames.  ``O`` inertial (``i1 = O.x``, ``i2 = O.y``); ``B = O.child(rot_z(theta))`` turns
with the rod, ``b1 = B.x``, ``b2 = B.y``; the bob is at ``r = -l b2``.

Free-body diagram of the bob: weight ``-m g i2`` and the rod force ``S b2`` (unknown).

Direct form, inertial axes (slide "Pendulum - inertial"), with ``sin(theta) = x/l``,
``cos(theta) = y/l``::

    (1)  i1:   m x''  = -S sin(theta)
    (2)  i2:  -m y''  =  S cos(theta) - m g
    (3)        x^2 + y^2 = l^2

Unknowns ``x, y`` (differential) and ``S`` (algebraic): a DAE.  The constraint (3) holds no
``S``, nor does its first derivative ``x x' + y y' = 0``; its second derivative with (1), (2)
put in does, ``S = m l (x'^2 + y'^2 + g y)/(x^2 + y^2)``, and one more derivative gives
``S'``: differentiation index 3.

Direct form, body axes (slide "Pendulum - body")::

    a = l theta'' b1 + l theta'^2 b2
    b1:  m l theta''   = -m g sin(theta)
    b2:  m l theta'^2  =  S - m g cos(theta)

Lagrangian, written independently (slide "Pendulum - Lagrange")::

    T = m (l theta')^2 / 2,   U = -m g l cos(theta),   m l^2 theta'' + m g l sin(theta) = 0

The rod force once more, independently: Lagrange in ``(x, y)`` with the rod as the constraint
``g = (l^2 - x^2 - y^2)/(2 l) = 0`` and multiplier ``S``::

    T = m (x'^2 + y'^2)/2,   U = -m g y
    x:  m x'' + S x/l = 0,     y:  m y'' - m g + S y/l = 0,
    constraint (acceleration level): -(x x'' + x'^2 + y y'' + y'^2)/l = 0

On the constraint ``|grad g| = 1`` and ``S b2 . dr = S dg`` (with ``dr = dx i1 - dy i2``):
the multiplier is the rod force.  (``g`` is the rod length's deficit to first order; it is
written as a polynomial rather than ``l - sqrt(x^2 + y^2)`` so that the models stay rational
and the comparator decides them exactly.)  The inertial direct form (1), (2) is kept in
``(x, y)``; the rod length (3) is imposed by the coordinate map ``x = l sin(theta)``,
``y = l cos(theta)`` onto the reference model.

Errata (see :meth:`PendulumParticle.published`)
-----------------------------------------------
* "Pendulum - inertial": ``x'' = -l cos(theta) theta'' - l sin(theta) theta'^2`` -- the first
  term's sign is wrong: ``x'' = l cos(theta) theta'' - l sin(theta) theta'^2``.
* "Differential index II": the first derivative of (3) is printed ``0 = 2 x' x'' + 2 y' y''``
  (and again ``x' x'' + y' y''``); it is ``2 x x' + 2 y y'`` -- ``x' x'' + y' y''`` is half
  the rate of ``x'^2 + y'^2``, which is not zero (``l^2 theta' theta''``).  The second
  derivative printed below it is right, so the slip (or the extraction) is in the dots.
* "Pendulum - body I": the acceleration is printed ``d/dt(theta' b1) = theta'' b1 +
  theta' theta' b2``; the factor ``l`` is missing throughout (it is ``l theta'' b1 +
  l theta'^2 b2``, as the next slide uses).
* "Pendulum - Lagrange": ``dL/dtheta' = m l^2 theta''`` as extracted; it is ``m l^2 theta'``
  (the next line, ``d/dt`` of it, is right).  A dot misread by the PDF extraction cannot be
  ruled out for this one.

Garbled beyond reading: the intermediate line of "Differential index II",
``0 = x'^2 + x(-(S/m)(x'/l)) + ...``, has doubled dots and ``x'/l`` where (1) gives ``x/l``;
only the result on the next line (``S = m l (...)``) is transcribed.  The label of the first
formula of the rigid-rod slide belongs to :mod:`dualmech.problems.rigid_rod_pendulum`.

Example
-------
>>> p = PendulumParticle(); p.validate()
>>> p.model("newton_euler").reactions_solved()[S]
m*(g*cos(theta(t)) + l*Derivative(theta(t), t)**2)
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_z, ACCELERATION,
                      ANGLE, FORCE, LENGTH, MASS)

__all__ = ["PendulumParticle", "PROBLEMS", "frames", "hand_rod_force", "m", "l", "g", "theta",
           "x", "y", "S"]

m, l, g = sp.symbols("m l g", positive=True)
theta = coordinate("theta")
x, y = coordinate("x"), coordinate("y")
S = sp.Symbol("S", real=True)


def hand_rod_force():
    """``S = m (g cos(theta) + l theta'^2)``: the b2 balance of the body form, solved by hand."""
    return m * (g * sp.cos(theta) + l * rate(theta)**2)


def frames() -> SimpleNamespace:
    """Frames ``O`` (inertial), ``B`` (rod), points ``o`` (pivot), ``bob`` and the particle."""
    O = Frame.ground("O")
    B = O.child("B", rot_z(theta))
    o = Point.origin(O, "O")
    bob = o.locate("bob", -l * B.y)
    return SimpleNamespace(O=O, B=B, o=o, bob=bob, particle=Particle("bob", m, bob))


class PendulumParticle(Problem):
    """Point-mass pendulum in inertial (x, y) and body (theta) coordinates (see module doc)."""

    name = "pendulum_particle"
    title = "Pendulum as a particle: inertial DAE and body coordinates"
    source = "003_d6818267b4d96a20.txt: lecture 18, Example: Pendulum"
    summary = ("The bob in Cartesian coordinates with the rod force as multiplier (index-3 "
               "DAE) and in the rod angle; same motion, same rod force; three printed slips.")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "mass of the bob"),
        Parameter(l, LENGTH, 1.0, (0.1, 5.0), "length of the rod"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-2.8, 2.8), (-4.0, 4.0), "rod angle from the downward vertical"),
    )
    extra_coordinates = (
        Coordinate(x, LENGTH, (-5.0, 5.0), (-10.0, 10.0), "horizontal position of the bob"),
        Coordinate(y, LENGTH, (-5.0, 5.0), (-10.0, 10.0), "depth of the bob below O"),
    )
    reactions = (Reaction("S", FORCE, "rod on the bob, along b2 (towards O); tension > 0"),)
    extra_models = ("newton_euler_inertial", "cartesian")

    def coordinate_maps(self) -> dict:
        to_theta = {x: l * sp.sin(theta), y: l * sp.cos(theta)}
        return {"newton_euler_inertial": dict(to_theta), "cartesian": dict(to_theta)}

    # -- direct form ---------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """Body axes: ``sum F = m a`` on ``b1`` and ``b2`` (slide "Pendulum - body II")."""
        f = frames()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=f.O,
                         description="sum F = m a on the bob, projected on b1, b2")
        ne.gravity(-g * f.O.y)
        ne.reaction("S", f.particle, f.B.y)
        ne.linear_momentum(f.particle, f.B.x)
        ne.linear_momentum(f.particle, f.B.y)
        return ne.equations()

    def newton_euler_inertial(self) -> EquationSet:
        """Inertial axes, equations (1), (2): bob at ``x i1 - y i2``, ``b2 = (-x i1 + y i2)/l``."""
        O = Frame.ground("O")
        bob = Particle("bob", m, Point.origin(O).locate("bob", x * O.x - y * O.y))
        ne = NewtonEuler("newton_euler_inertial", coordinates=[x, y], ground=O,
                         description="sum F = m a on the bob in i1, i2 (rod length by the map)")
        ne.gravity(-g * O.y)
        ne.reaction("S", bob, (-x * O.x + y * O.y) / l)
        ne.linear_momentum(bob, O.x)
        ne.linear_momentum(bob, O.y)
        return ne.equations()

    # -- indirect form -------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T = m (l theta')^2/2``, ``U = -m g l cos(theta)``, by hand."""
        lg = Lagrangian("lagrange", coordinates=[theta], description="T and U of the bob by hand")
        lg.kinetic("T of bob", m * (l * rate(theta))**2 / 2)
        lg.potential("gravity", -m * g * l * sp.cos(theta))
        return lg.equations()

    def cartesian(self) -> EquationSet:
        """The index-3 DAE: ``(x, y)`` with the rod as constraint, multiplier ``S``."""
        lg = Lagrangian("cartesian", coordinates=[x, y],
                        description="bob in inertial coordinates, rod length by a multiplier")
        lg.kinetic("T of bob", m * (rate(x)**2 + rate(y)**2) / 2)
        lg.potential("gravity", -m * g * y)
        lg.constraint("S", (l**2 - x**2 - y**2) / (2 * l))
        return lg.equations()

    # -- the source's answers ------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        O, B = f.O, f.B
        i2, b1, b2 = O.y, B.x, B.y
        s, c = sp.sin(theta), sp.cos(theta)
        th1, th2 = rate(theta), rate(theta, 2)
        inB = lambda v: tuple(v.express(B).components)  # noqa: E731
        v = f.bob.vel(O)
        a = f.bob.acc(O)
        L = f.particle.kinetic_energy(O) - (-m * g * l * c)
        inertial = "newton_euler_inertial"
        law = m * (l * th2 * b1 + l * th1**2 * b2) - (S * b2 - m * g * i2)
        return [
            Published("inertial (1), (2)", "equation",
                      (m * rate(x, 2) + S * s, -m * rate(y, 2) - S * c + m * g),
                      where="Pendulum - inertial: i1 and i2 components",
                      coordinates=inertial),
            Published("x, x'", "expression", (l * s, l * c * th1), (x, rate(x)),
                      where="Pendulum - inertial", coordinates=inertial),
            Published("x''", "expression", (-l * c * th2 - l * s * th1**2,), (rate(x, 2),),
                      where="Pendulum - inertial: WRONG, -l cos(theta) theta''; it is "
                      "+l cos(theta) theta''", coordinates=inertial),
            Published("constraint, 1st derivative", "equation",
                      (2 * rate(x) * rate(x, 2) + 2 * rate(y) * rate(y, 2),),
                      where="Differential index II: WRONG as extracted, 2 x' x'' + 2 y' y''; "
                      "the derivative of x^2 + y^2 is 2 x x' + 2 y y'", coordinates=inertial),
            Published("constraint, 2nd derivative", "equation",
                      (rate(x)**2 + x * rate(x, 2) + rate(y)**2 + y * rate(y, 2),),
                      where="Differential index II", coordinates=inertial),
            Published("rod force from the 2nd derivative", "expression",
                      (m * l * (rate(x)**2 + rate(y)**2 + y * g) / (x**2 + y**2),), (S,),
                      where="Differential index II, result", coordinates=inertial),
            Published("velocity, body", "expression", inB(l * th1 * b1), inB(v),
                      where="Pendulum - body I: theta' b3 x (-l b2)"),
            Published("acceleration, body", "expression", inB(th2 * b1 + th1 * th1 * b2),
                      inB(a), where="Pendulum - body I: WRONG, the factor l is missing "
                      "(l theta'' b1 + l theta'^2 b2)"),
            Published("body, vector equation", "equation", inB(law)[:2],
                      where="Pendulum - body II, on b1 and b2"),
            Published("body, b1 and b2", "equation",
                      (m * l * th2 + m * g * s, m * l * th1**2 - S + m * g * c),
                      where="Pendulum - body II"),
            Published("T, U", "expression", (m * (l * th1)**2 / 2, -m * g * l * c),
                      (f.particle.kinetic_energy(O), m * g * f.bob.pos_from(f.o).dot(i2)),
                      where="Pendulum - Lagrange"),
            Published("dL/dtheta'", "expression", (m * l**2 * th2,), (L.diff(th1),),
                      where="Pendulum - Lagrange: WRONG as extracted, m l^2 theta''; it is "
                      "m l^2 theta'"),
            Published("dL/dtheta", "expression", (-m * g * l * s,), (L.diff(theta),),
                      where="Pendulum - Lagrange"),
            Published("equation of motion", "equation", (m * l**2 * th2 + m * g * l * s,),
                      where="Pendulum - Lagrange"),
            Published("equation of motion, final", "motion", (l * th2 + g * s,),
                      where="Pendulum - Lagrange, last line"),
            Published("r, v, v.v", "expression",
                      (l * s, -l * c, l * c * th1, l * s * th1, l**2 * th1**2),
                      tuple(f.bob.pos_from(f.o).express(O).components[:2])
                      + tuple(v.express(O).components[:2]) + (v.dot(v),),
                      where="Pendulum - Lagrange, side calculation"),
        ]


PROBLEMS = (PendulumParticle,)
