r"""A ladder sliding on a smooth floor against a smooth wall -- a teacher's file, outside the
catalogue.

Sign convention::

        |B                    O.x right, O.y up; wall at x = 0, floor at y = 0
        | \                   theta: angle of the ladder from the wall, so that the centre
        |  \  G               G = (l/2) (sin th, cos th), foot A = (l sin th, 0), top B =
        |   \                 (0, l cos th); the ladder frame is O turned by theta about O.z
        |____\A______         (its y axis points from A to B)

Direct form: the ladder along O.x, O.y and about G (I_G = m l^2/12); the floor pushes up at A
(``N_A`` along O.y), the wall pushes right at B (``N_B`` along O.x).  Lagrangian (by hand)::

    T = m (l/2)^2 th'^2/2 + m l^2 th'^2/24 = m l^2 th'^2/6,     V = m g (l/2) cos th
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Point, Problem, Reaction, RigidBody, coordinate,
                      rate, rot_z, thin_rod)

m, l, g = sp.symbols("m l g", positive=True)
theta = coordinate("theta")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.f = self.O.child("ladder", rot_z(theta))
        self.G = Point.origin(self.O).locate(
            "G", l / 2 * sp.sin(theta) * self.O.x + l / 2 * sp.cos(theta) * self.O.y)
        self.A = self.G.locate("A", -l / 2 * self.f.y)
        self.B = self.G.locate("B", l / 2 * self.f.y)
        self.ladder = RigidBody("ladder", m, self.G, self.f, thin_rod(m, l, axis="y"))


class Ladder(Problem):
    name = "teacher_ladder"
    title = "Ladder on a smooth floor against a smooth wall"
    source = "teacher's own problem (test corpus)"
    parameters = (Parameter(m, MASS, 10.0, (1.0, 50.0)), Parameter(l, LENGTH, 3.0, (0.5, 6.0)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
    coordinates = (Coordinate(theta, ANGLE, (0.1, 1.4), (-2.0, 2.0)),)
    reactions = (Reaction("N_A", FORCE, "floor on the foot, up"),
                 Reaction("N_B", FORCE, "wall on the top, to the right"))

    def wall(self, sc):
        return sc.O.x

    def balances(self, ne, sc):
        ne.linear_momentum(sc.ladder, sc.O.x)
        ne.linear_momentum(sc.ladder, sc.O.y)
        ne.angular_momentum(sc.ladder, sc.O.z)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=sc.O)
        ne.gravity(-g * sc.O.y)
        ne.reaction("N_A", sc.ladder, sc.O.y, at=sc.A)
        ne.reaction("N_B", sc.ladder, self.wall(sc), at=sc.B)
        self.balances(ne, sc)
        return ne.equations()

    def kinetic(self, lg):
        lg.kinetic("T of ladder", m * l**2 * rate(theta)**2 / 8 + m * l**2 * rate(theta)**2 / 24)

    def potential(self, lg):
        lg.potential("gravity", m * g * l / 2 * sp.cos(theta))

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta])
        self.kinetic(lg)
        self.potential(lg)
        return lg.equations()


class InertiaAboutTheEnd(Ladder):
    """I_G = m l^2/3 (about the end) where m l^2/12 belongs: T = 7 m l^2 th'^2/24 where
    m l^2 th'^2/6 belongs."""

    def kinetic(self, lg):
        lg.kinetic("T of ladder", m * l**2 * rate(theta)**2 / 8 + m * l**2 * rate(theta)**2 / 6)


class CentreSpeedForgotten(Ladder):
    """Only the rotation counted: T = m l^2 th'^2/24, the centre's m l^2 th'^2/8 missing."""

    def kinetic(self, lg):
        lg.kinetic("T of ladder", m * l**2 * rate(theta)**2 / 24)


class GravitySign(Ladder):
    """V = -m g (l/2) cos th."""

    def potential(self, lg):
        lg.potential("gravity", -m * g * l / 2 * sp.cos(theta))


class WallForceVertical(Ladder):
    """The wall's push drawn along O.y (as if it were a floor): it does virtual work
    -N_B l sin th dth."""

    def wall(self, sc):
        return sc.O.y


class MomentsAboutTheMovingFoot(Ladder):
    """Moments about the foot A, which slides, taken as if A were fixed:
    ``N_B l cos th + m g (l/2) sin th - (m l^2/3) th'' = 0``; the term ``-m (r_AG x a_A) .
    k`` = ``-m (l/2) cos th x_A''`` with ``x_A = l sin th`` is missing, i.e.
    ``m l^2/2 cos th (cos th th'' - sin th th'^2)`` with its sign."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.ladder, sc.O.x)
        ne.linear_momentum(sc.ladder, sc.O.y)
        ne.equation("sum tau_A . O.z (ladder), A taken as fixed",
                    {"reaction N_B": sp.Symbol("N_B", real=True) * l * sp.cos(theta),
                     "gravity on ladder": m * g * l / 2 * sp.sin(theta),
                     "inertia of ladder": -m * l**2 / 3 * rate(theta, 2)})


MISTAKES = [
    (InertiaAboutTheEnd, "T of ladder", m * l**2 * rate(theta)**2 / 6),
    (CentreSpeedForgotten, "T of ladder", m * l**2 * rate(theta)**2 / 6),
    (GravitySign, "V of gravity", m * g * l / 2 * sp.cos(theta)),
    (WallForceVertical, "N_B", -sp.Symbol("N_B", real=True) * l * sp.sin(theta)
     * sp.Symbol("δθ", real=True)),
    (MomentsAboutTheMovingFoot, "A taken as fixed",
     m * l**2 / 2 * sp.cos(theta) * (sp.cos(theta) * rate(theta, 2)
                                     - sp.sin(theta) * rate(theta)**2)),
]
