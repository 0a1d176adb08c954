r"""A rod hanging from the axle of a wheel that rolls on the floor -- a teacher's own problem.

Sign sketch::

           ( C )        wheel M, radius R         O.x right, O.y up, O.z out of the page.
            \ \         rolling on the floor      x: the axle C along the floor (C = x O.x
             \ \ rod m, length L                  + R O.y); the wheel turns by -x/R.
              \ G        theta from the downward   theta: the rod about O.z; B = O turned by
               \         vertical                   theta, the rod along -B.y, G = C - (L/2) B.y.
     ===P=============

The wheel is a uniform disk (I_C = M R^2/2); the rod is uniform (I_G = m L^2/12) on a smooth
pin at the axle.  The pin pushes the rod with ``H_x, H_y`` (along O.x, O.y; the rod pushes the
wheel back); the floor pushes the wheel at P with ``N`` (up) and the friction ``Fr`` (O.x).

Direct form (by hand): the wheel along O.x, O.y and about C; the rod along O.x, O.y and
about G.

Lagrangian (by hand)::

    T = M x'^2/2 + (M R^2/2)(x'/R)^2/2 + m (x'^2 + L cos(theta) x' theta' + L^2 theta'^2/4)/2
        + (m L^2/12) theta'^2/2
    V = -m g (L/2) cos(theta)
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Point, Problem, Reaction, RigidBody, coordinate,
                      rate, rot_z, thin_disk, thin_rod)

M, m, R, L, g = sp.symbols("M m R L g", positive=True)
x, theta = coordinate("x"), coordinate("theta")


class RodOnRollingWheel(Problem):
    """A rod pendulum hanging from the axle of a rolling wheel."""

    name = "rod_on_rolling_wheel"
    title = "Rod hanging from the axle of a rolling wheel"
    source = "my notes: plane motion, ex. 7"
    parameters = (Parameter(M, MASS, 2.0, (0.5, 10.0), "mass of the wheel"),
                  Parameter(m, MASS, 1.0, (0.1, 5.0), "mass of the rod"),
                  Parameter(R, LENGTH, 0.3, (0.1, 1.0), "radius of the wheel"),
                  Parameter(L, LENGTH, 0.6, (0.1, 2.0), "length of the rod"),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"))
    coordinates = (Coordinate(x, LENGTH, (-2.0, 2.0), (-3.0, 3.0), "position of the axle"),
                   Coordinate(theta, ANGLE, (-1.5, 1.5), (-4.0, 4.0), "angle of the rod"))
    reactions = (Reaction("H_x", FORCE, "pin on rod, along O.x"),
                 Reaction("H_y", FORCE, "pin on rod, along O.y"),
                 Reaction("N", FORCE, "floor on wheel, up"),
                 Reaction("Fr", FORCE, "friction, floor on wheel, along O.x"))

    def newton_euler(self):
        O = Frame.ground("O")
        B = O.child("B", rot_z(theta))
        C = Point.origin(O, "O").locate("C", x * O.x + R * O.y)
        P = C.locate("P", -R * O.y)
        G = C.locate("G", -L / 2 * B.y)
        wheel = RigidBody("wheel", M, C, O.child("wheel", rot_z(-x / R)), thin_disk(M, R))
        rod = RigidBody("rod", m, G, B, thin_rod(m, L, "y"))
        ne = NewtonEuler("newton_euler", coordinates=[x, theta], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction_vector("H", rod, O, "xy", at=C, against=wheel, against_at=C)
        ne.reaction("N", wheel, O.y, at=P)
        ne.reaction("Fr", wheel, O.x, at=P)
        ne.linear_momentum(wheel, O.x)
        ne.linear_momentum(wheel, O.y)
        ne.angular_momentum(wheel, O.z)
        ne.linear_momentum(rod, O.x)
        ne.linear_momentum(rod, O.y)
        ne.angular_momentum(rod, O.z)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, theta])
        lg.kinetic("T of wheel", M * rate(x)**2 / 2 + M * R**2 / 2 * (rate(x) / R)**2 / 2)
        lg.kinetic("T of rod", m * (rate(x)**2 + L * sp.cos(theta) * rate(x) * rate(theta)
                                    + L**2 * rate(theta)**2 / 4) / 2
                   + m * L**2 / 12 * rate(theta)**2 / 2)
        lg.potential("gravity", -m * g * L / 2 * sp.cos(theta))
        return lg.equations()


PROBLEMS = (RodOnRollingWheel,)
