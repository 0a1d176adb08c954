r"""Two pendulums joined by a spring (MIT 2.003J, spring 2011, final exam, problem 3).

Two identical pendulums -- massless rigid rods of length ``3l`` with point masses ``m`` -- hang
from frictionless pivots O and O' a distance ``d`` apart.  A spring ``k``, unstretched when
both hang vertically, joins the rods at distance ``l`` below the pivots.  ``theta1``,
``theta2``: counter-clockwise rotations from the vertical.  Gravity ``-g J``.

Sign convention (plane I-J, K out of the page)::

          O ----------- d ----------- O'
          |\                          |\
          | \  l                      | \          attachment points, l below the pivots:
          |  *------/\/\/\/\/\--------|--*         S1 = l (sin th1, -cos th1)
          |th1\        k              |th2\        S2 = d I + l (sin th2, -cos th2)
          |    \ 2l                   |    \
          |     (m)  B1 = 3l (sin th1, -cos th1)   B2 = d I + 3l (sin th2, -cos th2)

Modelling assumption (the source's hint): the spring force is horizontal, of magnitude ``k``
times the change of the horizontal distance between the attachment points,
``e = l (sin(theta2) - sin(theta1))``.  It is exact to first order: the true spring (length
``|S2 - S1|``, free length ``d``) has the same linearisation, which
:func:`geometric_spring_model` and the tests show; the source solves only the linear problem.

Frames::

    O = (O, I, J, K)              ground
    P1 = O.child(rot_z(theta1))   pendulum 1: the rod along -j_P1
    P2 = O.child(rot_z(theta2))   pendulum 2 (pivot O' = O + d I)

Bodies: each pendulum is one rigid body (massless rod + point mass): mass ``m`` at its bob,
no inertia about the bob.  The spring acts on the rod, not on the bob, so the pendulum is not a
particle.

Free-body diagrams::

    pendulum 1:  -m g J at B1,   k e I at S1,    pivot force at O (no moment about O)
    pendulum 2:  -m g J at B2,  -k e I at S2,    pivot force at O'

Direct form: Euler's equation about each fixed pivot, ``sum tau_O = dH_O/dt`` on K::

    9 m l^2 theta1'' = -3 m g l sin(theta1) + k l^2 (sin(theta2) - sin(theta1)) cos(theta1)
    9 m l^2 theta2'' = -3 m g l sin(theta2) - k l^2 (sin(theta2) - sin(theta1)) cos(theta2)

Lagrangian (written independently)::

    T = (9/2) m l^2 (theta1'^2 + theta2'^2)
    V = 3 m g l (2 - cos(theta1) - cos(theta2)) + k l^2 (sin(theta1) - sin(theta2))^2 / 2

Linearised about ``theta1 = theta2 = 0`` and divided by ``l`` (the source's form)::

    9 m l theta1'' + (k l + 3 m g) theta1 - k l theta2 = 0,   and the same with 1 <-> 2

Modes: in phase ``(1, 1)``, ``omega^2 = g/(3 l)`` (the spring is not stretched); in
antiphase ``(1, -1)``, ``omega^2 = g/(3 l) + 2 k/(9 m)``.

The source prints the constants and the general frequency equation and its roots; its text
ends before the numbers of the modes (the mode shapes and frequencies above are derived here,
and computed by the library in the tests).  No errata found.

Example
-------
>>> p = CoupledPendulums(); p.validate()
>>> M0, C0, K0 = p.model("lagrange").linearize()
>>> (K0 / l).applyfunc(sp.expand)
Matrix([
[3*g*m + k*l,        -k*l],
[       -k*l, 3*g*m + k*l]])
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, RigidBody, coordinate, rate, rot_z, ACCELERATION, ANGLE,
                      LENGTH, MASS, STIFFNESS)

__all__ = ["CoupledPendulums", "PROBLEMS", "scene", "geometric_spring_model", "m", "k", "l",
           "d", "g", "theta1", "theta2"]

m, k, l, d, g = sp.symbols("m k l d g", positive=True)
theta1, theta2 = coordinate("theta1"), coordinate("theta2")


def scene() -> SimpleNamespace:
    """Frames, points and the two pendulums (rigid bodies) of the direct form."""
    O = Frame.ground("O")
    P1, P2 = O.child("P1", rot_z(theta1)), O.child("P2", rot_z(theta2))
    o1 = Point.origin(O, "O")
    o2 = o1.locate("O'", d * O.x)
    S1, S2 = o1.locate("S1", -l * P1.y), o2.locate("S2", -l * P2.y)
    B1, B2 = o1.locate("B1", -3 * l * P1.y), o2.locate("B2", -3 * l * P2.y)
    pend1 = RigidBody("pendulum 1", m, B1, P1, sp.zeros(3, 3))
    pend2 = RigidBody("pendulum 2", m, B2, P2, sp.zeros(3, 3))
    return SimpleNamespace(O=O, P1=P1, P2=P2, o1=o1, o2=o2, S1=S1, S2=S2, B1=B1, B2=B2,
                           pend1=pend1, pend2=pend2)


def _euler_about_pivots(ne: NewtonEuler, s: SimpleNamespace) -> NewtonEuler:
    ne.gravity(-g * s.O.y)
    ne.angular_momentum(s.pend1, s.O.z, about=s.o1)
    ne.angular_momentum(s.pend2, s.O.z, about=s.o2)
    return ne


def geometric_spring_model() -> EquationSet:
    """The direct form with the true spring (length ``|S2 - S1|``, free length ``d``).

    Not one of the problem's models (the source solves the hinted, horizontal spring); it
    shows that the hint is exact to first order: both linearise to the same matrices.
    """
    s = scene()
    ne = NewtonEuler("geometric_spring", coordinates=[theta1, theta2], ground=s.O)
    ne.spring_between("spring", k, d, (s.pend1, s.S1), (s.pend2, s.S2))
    return _euler_about_pivots(ne, s).equations()


class CoupledPendulums(Problem):
    """Two identical pendulums coupled by a spring between their rods."""

    name = "coupled_pendulums"
    title = "Two pendulums coupled by a spring"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, final exam, problem 3"
    summary = ("Euler about each pivot against the Lagrangian; modes and natural frequencies "
               "by the library; the hinted horizontal spring is exact to first order.")
    parameters = (
        Parameter(m, MASS, 0.5, (0.05, 5.0), "mass of each bob"),
        Parameter(k, STIFFNESS, 20.0, (1.0, 500.0), "spring constant"),
        Parameter(l, LENGTH, 0.3, (0.05, 2.0), "depth of the spring's ends below the pivots"),
        Parameter(d, LENGTH, 0.8, (0.1, 3.0), "distance between the pivots (free length)"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta1, ANGLE, (-1.2, 1.2), (-3.0, 3.0), "left pendulum from the vertical"),
        Coordinate(theta2, ANGLE, (-1.2, 1.2), (-3.0, 3.0), "right pendulum from the vertical"),
    )

    def newton_euler(self) -> EquationSet:
        """Euler's equation about each pivot; the spring force horizontal (the source's hint)."""
        s = scene()
        ne = NewtonEuler(coordinates=[theta1, theta2], ground=s.O,
                         description="Euler about each fixed pivot, spring force along I")
        stretch = (s.S2.pos_from(s.o1) - s.S1.pos_from(s.o1)).dot(s.O.x) - d
        ne.linear_spring("spring", s.pend2, k, stretch, s.O.x, at=s.S2, against=s.pend1,
                         against_at=s.S1)
        return _euler_about_pivots(ne, s).equations()

    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` by hand."""
        lg = Lagrangian(coordinates=[theta1, theta2], description="T and V by hand")
        lg.kinetic("T of bob 1", 9 * m * l**2 * rate(theta1)**2 / 2)
        lg.kinetic("T of bob 2", 9 * m * l**2 * rate(theta2)**2 / 2)
        lg.potential("gravity", 3 * m * g * l * (2 - sp.cos(theta1) - sp.cos(theta2)))
        lg.spring("spring", k, l * (sp.sin(theta1) - sp.sin(theta2)))
        return lg.equations()

    def published(self) -> list[Published]:
        M0, _, K0 = self.model("lagrange").linearize()
        m1 = m2 = 9 * m * l
        k1 = k4 = k * l + 3 * m * g
        k2 = k3 = -k * l
        s = m1 * k4 + m2 * k1
        root = sp.sqrt(s**2 - 4 * m1 * m2 * (k1 * k4 - k2 * k3))
        w2 = [(s - root) / (2 * m1 * m2), (s + root) / (2 * m1 * m2)]
        omegas = self.model("lagrange").natural_frequencies()
        low, high = sorted(omegas, key=lambda w: float(w.subs(self.defaults())))
        tau1 = -k * l * (l * theta1 - l * theta2) - m * g * 3 * l * theta1
        where = "final exam, problem 3"
        return [
            Published("(a) torque about O, linearised", "expression", (tau1,),
                      (-(K0[0, 0] * theta1 + K0[0, 1] * theta2),), where=f"{where} (a)"),
            Published("(a) m1, m2", "expression", (m1, 0, 0, m2), tuple(M0 / l),
                      where=f"{where} (a): the linear equations divided by l"),
            Published("(a) k1, k2, k3, k4", "expression", (k1, k2, k3, k4), tuple(K0 / l),
                      where=f"{where} (a): the linear equations divided by l"),
            Published("(b) omega^2", "expression", tuple(w2), (low**2, high**2),
                      where=f"{where} (b): roots of the frequency equation, - then +"),
            Published("(b) mode ratio a1/a2", "expression",
                      tuple(-k2 / (k1 - m1 * w) for w in w2),
                      tuple(-(K0[0, 1] - w * M0[0, 1]) / (K0[0, 0] - w * M0[0, 0])
                            for w in (low**2, high**2)),
                      where=f"{where} (b): -k2/(k1 - m1 omega^2) at each root"),
            Published("(b) mode ratio a1/a2, second form", "expression",
                      tuple((k4 - m2 * w) / -k3 for w in w2),
                      tuple(-(K0[1, 1] - w * M0[1, 1]) / (K0[1, 0] - w * M0[1, 0])
                            for w in (low**2, high**2)),
                      where=f"{where} (b): (k4 - m2 omega^2)/(-k3) at each root"),
        ]


PROBLEMS = (CoupledPendulums,)
