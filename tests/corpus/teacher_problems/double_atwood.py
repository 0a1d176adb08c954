r"""A double Atwood machine whose pulleys have mass -- a teacher's own problem.

Sign convention::

              ___O___              O.x right, O.y up.  Fixed pulley A (mass M, radius a,
             /   A   \             uniform disk, I_A = M a^2/2) on an axle at O.
            |         |            x: how far m1 has gone DOWN (and pulley B up), so A turns
           m1        _B_           by x/a counterclockwise.  Movable pulley B (mass M_B,
                    /   \          radius b, I_B = M_B b^2/2) hangs on the right-hand string;
                   m2    m3        y: how far m2 has gone down relative to B (m3 up), so B
                                   turns by y/b counterclockwise.

Heights: m1 at -x, B at x, m2 at x - y, m3 at x + y (constants dropped).  Strings light and
inextensible, no slip on the pulleys; tensions T1 (left of A), T2 (right of A, holding B),
T3 (left of B, holding m2), T4 (right of B, holding m3); the axle pushes A up with R_A.

Direct form (by hand), up positive::

    m1:  T1 - m1 g = -m1 x''                 m2:  T3 - m2 g = m2 (x'' - y'')
    A:   (T1 - T2) a = I_A x''/a             m3:  T4 - m3 g = m3 (x'' + y'')
         R_A - T1 - T2 - M g = 0             B:   T2 - T3 - T4 - M_B g = M_B x''
                                                  (T3 - T4) b = I_B y''/b

Lagrangian (by hand)::

    T = (m1 + M/2 + M_B + m2 + m3) x'^2/2 + (M_B/2 + m2 + m3) y'^2/2 + (m3 - m2) x' y'
    V = -g x (m1 - M_B - m2 - m3) - g y (m2 - m3)
    x:  (m1 + M/2 + M_B + m2 + m3) x'' + (m3 - m2) y'' - g (m1 - M_B - m2 - m3) = 0
    y:  (M_B/2 + m2 + m3) y'' + (m3 - m2) x'' - g (m2 - m3) = 0

The pulley A's weight M g appears only in R_A (a reaction-only term).  With m2 = m3 = m
the two rows decouple: y'' = 0 and x'' = g (m1 - M_B - 2 m)/(m1 + M/2 + M_B + 2 m).
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Particle, Point, Problem, Published, Reaction,
                      RigidBody, coordinate, rate, rot_z, thin_disk)

m1, m2, m3, M, MB, a, b, g = sp.symbols("m1 m2 m3 M M_B a b g", positive=True)
x, y = coordinate("x"), coordinate("y")


class _Scene:
    def __init__(self):
        O = self.O = Frame.ground("O")
        o = Point.origin(O)
        self.A = RigidBody("pulley A", M, o, O.child("A", rot_z(x / a)), thin_disk(M, a))
        self.left, self.right = o.locate("A left", -a * O.x), o.locate("A right", a * O.x)
        cB = o.locate("B", a * O.x + x * O.y)
        self.B = RigidBody("pulley B", MB, cB, O.child("B", rot_z(y / b)), thin_disk(MB, b))
        self.B_left, self.B_right = cB.locate("B left", -b * O.x), cB.locate("B right", b * O.x)
        self.m1 = Particle("m1", m1, o.locate("P1", -a * O.x - x * O.y))
        self.m2 = Particle("m2", m2, cB.locate("P2", -b * O.x - y * O.y))
        self.m3 = Particle("m3", m3, cB.locate("P3", b * O.x + y * O.y))


class DoubleAtwood(Problem):
    name = "double_atwood"
    title = "Double Atwood machine with massive pulleys"
    source = "my notes: pulleys, ex. 7"
    parameters = (Parameter(m1, MASS, 4.0, (0.5, 10.0)), Parameter(m2, MASS, 1.0, (0.1, 5.0)),
                  Parameter(m3, MASS, 1.5, (0.1, 5.0)), Parameter(M, MASS, 1.0, (0.1, 5.0)),
                  Parameter(MB, MASS, 0.5, (0.1, 5.0)), Parameter(a, LENGTH, 0.2, (0.05, 0.5)),
                  Parameter(b, LENGTH, 0.1, (0.05, 0.5)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
    coordinates = (Coordinate(x, LENGTH, (-0.5, 0.5)), Coordinate(y, LENGTH, (-0.5, 0.5)))
    reactions = (Reaction("T1", FORCE, "string on m1, up"),
                 Reaction("T2", FORCE, "string on pulley B, up"),
                 Reaction("T3", FORCE, "string on m2, up"),
                 Reaction("T4", FORCE, "string on m3, up"),
                 Reaction("R_A", FORCE, "axle on pulley A, up"))
    unilateral = {"T1": "the left string goes slack", "T2": "the right string goes slack",
                  "T3": "m2's string goes slack", "T4": "m3's string goes slack"}

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.reaction("T1", sc.m1, sc.O.y, against=sc.A, against_at=sc.left)
        ne.reaction("T2", sc.B, sc.O.y, against=sc.A, against_at=sc.right)
        ne.reaction("T3", sc.m2, sc.O.y, against=sc.B, against_at=sc.B_left)
        ne.reaction("T4", sc.m3, sc.O.y, against=sc.B, against_at=sc.B_right)
        ne.reaction("R_A", sc.A, sc.O.y)

    def balances(self, ne, sc):
        ne.linear_momentum(sc.m1, sc.O.y)
        ne.linear_momentum(sc.A, sc.O.y)
        ne.angular_momentum(sc.A, sc.O.z)
        ne.linear_momentum(sc.B, sc.O.y)
        ne.angular_momentum(sc.B, sc.O.z)
        ne.linear_momentum(sc.m2, sc.O.y)
        ne.linear_momentum(sc.m3, sc.O.y)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x, y], ground=sc.O)
        self.loads(ne, sc)
        self.balances(ne, sc)
        return ne.equations()

    def kinetic(self, lg):
        xd, yd = rate(x), rate(y)
        lg.kinetic("T of m1", m1 * xd**2 / 2)
        lg.kinetic("T of pulley A", M * a**2 / 2 * (xd / a)**2 / 2)
        lg.kinetic("T of pulley B", MB * xd**2 / 2 + MB * b**2 / 2 * (yd / b)**2 / 2)
        lg.kinetic("T of m2", m2 * (xd - yd)**2 / 2)
        lg.kinetic("T of m3", m3 * (xd + yd)**2 / 2)

    def potential(self, lg):
        lg.potential("gravity", -g * x * (m1 - MB - m2 - m3) - g * y * (m2 - m3))

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, y])
        self.kinetic(lg)
        self.potential(lg)
        return lg.equations()

    def published(self):
        return [Published("equations of motion", "motion", (
            (m1 + M / 2 + MB + m2 + m3) * rate(x, 2) + (m3 - m2) * rate(y, 2)
            - g * (m1 - MB - m2 - m3),
            (MB / 2 + m2 + m3) * rate(y, 2) + (m3 - m2) * rate(x, 2) - g * (m2 - m3)),
            where="my notes, (7.4)")]


PROBLEMS = (DoubleAtwood,)
