'''Atwood machine with a massive pulley: a teacher's problem outside the catalogue.

The tests of the referee write this file into a temporary folder, with one mistake switched on
by ``MISTAKE`` (``""``: none), and check it with ``dualmech check FILE``.

    pulley: uniform disk mp, radius r, fixed axle at O; R J on it from the axle
    m1 hangs at -r I - (d + x) J (x grows as m1 goes down), string tension T1 J on m1
    m2 hangs at +r I - (d - x) J, tension T2 J on m2; the pulley turns x/r about K

By hand: (m1 + m2 + mp/2) x'' = (m1 - m2) g,  T1 = m1 (g - x''),  T2 = m2 (g + x''),
R = T1 + T2 + mp g.
'''
import sympy as sp

from dualmech import (Coordinate, Frame, Lagrangian, NewtonEuler, Parameter, Particle, Point,
                      Problem, Reaction, RigidBody, coordinate, rate, rot_z, thin_disk,
                      ACCELERATION, FORCE, LENGTH, MASS)

MISTAKE = ""
m1, m2, mp, r, d, g = sp.symbols("m1 m2 m_p r d g", positive=True)
x = coordinate("x")


class Atwood(Problem):
    name = "atwood_teacher"
    title = "Atwood machine with a massive pulley"
    source = "a teacher's own problem"
    parameters = (Parameter(m1, MASS, 2.0, (0.5, 5.0)), Parameter(m2, MASS, 1.0, (0.5, 5.0)),
                  Parameter(mp, MASS, 0.5, (0.1, 2.0)), Parameter(r, LENGTH, 0.1, (0.05, 0.5)),
                  Parameter(d, LENGTH, 1.0, (0.5, 2.0)),
                  Parameter(g, ACCELERATION, 9.81, (9.0, 10.0)))
    coordinates = (Coordinate(x, LENGTH, (-0.4, 0.4), (-1.0, 1.0)),)
    reactions = (Reaction("T1", FORCE, "string on m1, along J"),
                 Reaction("T2", FORCE, "string on m2, along J"),
                 Reaction("R", FORCE, "axle on the pulley, along J"))

    def newton_euler(self):
        O = Frame.ground("O")
        P = O.child("P", rot_z(x / r))
        o = Point.origin(O, "o")
        heavy = 2 * m1 if MISTAKE == "doubled mass" else m1
        b1 = Particle("m1", heavy, o.locate("B1", -r * O.x - (d + x) * O.y))
        b2 = Particle("m2", m2, o.locate("B2", r * O.x - (d - x) * O.y))
        pulley = RigidBody("pulley", mp, o, P, thin_disk(mp, r, normal="z"))
        ne = NewtonEuler(coordinates=[x], ground=O)
        ne.gravity(-g * O.y)
        up = 2 * O.y if MISTAKE == "non-unit direction" else O.y
        T1 = ne.reaction("T1", b1, up, against=pulley, against_at=o.locate("A1", -r * O.x))
        T2 = ne.reaction("T2", b2, O.y, against=pulley, against_at=o.locate("A2", r * O.x))
        R = ne.reaction("R", pulley, O.y)
        if MISTAKE == "dropped term":      # m1's balance by hand, its weight left out
            ne.equation("m1 along J (by hand)", {"T1": T1, "inertia of m1": m1 * rate(x, 2)})
        else:
            ne.linear_momentum(b1, O.y)
        ne.linear_momentum(b2, O.y)
        ne.angular_momentum(pulley, O.z)
        if MISTAKE == "dropped pulley weight":   # the axle balance by hand, no weight
            ne.equation("pulley along J (by hand)", {"R": R, "T1": -T1, "T2": -T2})
        else:
            ne.linear_momentum(pulley, O.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[x])
        lg.kinetic("T", (m1 + m2) * rate(x)**2 / 2 + mp * r**2 / 4 * (rate(x) / r)**2)
        sign = -1 if MISTAKE == "load sign" else 1
        lg.potential("gravity", sign * g * x * (m2 - m1))
        return lg.equations()


PROBLEMS = (Atwood,)
