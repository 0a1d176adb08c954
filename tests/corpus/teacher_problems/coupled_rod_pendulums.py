r"""Two rod pendulums side by side, their tips joined by a spring -- a teacher's own problem.

Sign sketch::

        O1 ----- d ----- O2         O.x right, O.y up, O.z out of the page.
         \                \         theta1, theta2: each rod from the downward vertical,
          \ rod 1 (m1, l)  \ rod 2   about O.z.  B_i = O turned by theta_i, so the rod runs
           A1 ~~~~k~~~~~~~~ A2       from its pivot along -B_i.y; G_i = O_i - (l/2) B_i.y,
                                     tip A_i = O_i - l B_i.y.

Uniform rods (I_G = m l^2/12 about O.z), smooth pins at O1 = (0, 0) and O2 = (d, 0) with
reactions ``P1_x, P1_y`` and ``P2_x, P2_y`` along O.x, O.y.  A spring of stiffness ``k`` and
negligible free length joins the tips: on rod 1 the force ``-k (A1 - A2)``, on rod 2 the
opposite.

Direct form (by hand): each rod along O.x, O.y and about its centre G_i (with the pin force
and the spring force at the tip).

Lagrangian (by hand)::

    T = (m1 l^2/3) theta1'^2/2 + (m2 l^2/3) theta2'^2/2
    V = -m1 g (l/2) cos(theta1) - m2 g (l/2) cos(theta2)
        + k ((l sin(theta1) - l sin(theta2) - d)^2 + l^2 (cos(theta2) - cos(theta1))^2)/2
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, LENGTH, MASS, STIFFNESS, Coordinate, Frame,
                      Lagrangian, NewtonEuler, Parameter, Point, Problem, Reaction, RigidBody,
                      coordinate, rate, rot_z, thin_rod, FORCE)

m1, m2, l, d, k, g = sp.symbols("m1 m2 l d k g", positive=True)
theta1, theta2 = coordinate("theta1"), coordinate("theta2")


class CoupledRodPendulums(Problem):
    """Two rod pendulums coupled by a spring between their tips."""

    name = "coupled_rod_pendulums"
    title = "Two rod pendulums coupled by a spring"
    source = "my notes: oscillations, ex. 4"
    parameters = (Parameter(m1, MASS, 1.0, (0.1, 5.0), "mass of rod 1"),
                  Parameter(m2, MASS, 1.5, (0.1, 5.0), "mass of rod 2"),
                  Parameter(l, LENGTH, 0.8, (0.2, 2.0), "length of each rod"),
                  Parameter(d, LENGTH, 0.5, (0.1, 2.0), "distance between the pivots"),
                  Parameter(k, STIFFNESS, 20.0, (1.0, 200.0), "spring between the tips"),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"))
    coordinates = (Coordinate(theta1, ANGLE, (-1.0, 1.0), (-3.0, 3.0), "angle of rod 1"),
                   Coordinate(theta2, ANGLE, (-1.0, 1.0), (-3.0, 3.0), "angle of rod 2"))
    reactions = (Reaction("P1_x", FORCE, "pin O1 on rod 1, along O.x"),
                 Reaction("P1_y", FORCE, "pin O1 on rod 1, along O.y"),
                 Reaction("P2_x", FORCE, "pin O2 on rod 2, along O.x"),
                 Reaction("P2_y", FORCE, "pin O2 on rod 2, along O.y"))

    def newton_euler(self):
        O = Frame.ground("O")
        B1, B2 = O.child("B1", rot_z(theta1)), O.child("B2", rot_z(theta2))
        O1 = Point.origin(O, "O1")
        O2 = O1.locate("O2", d * O.x)
        G1, A1 = O1.locate("G1", -l / 2 * B1.y), O1.locate("A1", -l * B1.y)
        G2, A2 = O2.locate("G2", -l / 2 * B2.y), O2.locate("A2", -l * B2.y)
        rod1 = RigidBody("rod 1", m1, G1, B1, thin_rod(m1, l, "y"))
        rod2 = RigidBody("rod 2", m2, G2, B2, thin_rod(m2, l, "y"))
        ne = NewtonEuler("newton_euler", coordinates=[theta1, theta2], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction_vector("P1", rod1, O, "xy", at=O1)
        ne.reaction_vector("P2", rod2, O, "xy", at=O2)
        ne.spring_between("spring", k, 0, (rod1, A1), (rod2, A2))
        for rod in (rod1, rod2):
            ne.linear_momentum(rod, O.x)
            ne.linear_momentum(rod, O.y)
            ne.angular_momentum(rod, O.z)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta1, theta2])
        lg.kinetic("T of rod 1", m1 * l**2 / 3 * rate(theta1)**2 / 2)
        lg.kinetic("T of rod 2", m2 * l**2 / 3 * rate(theta2)**2 / 2)
        lg.potential("gravity", -m1 * g * l / 2 * sp.cos(theta1) - m2 * g * l / 2 * sp.cos(theta2))
        lg.potential("spring", k * ((l * sp.sin(theta1) - l * sp.sin(theta2) - d)**2
                                    + l**2 * (sp.cos(theta2) - sp.cos(theta1))**2) / 2)
        return lg.equations()


PROBLEMS = (CoupledRodPendulums,)
