r"""A disk rolling down a rough incline, the rolling declared in both models -- a teacher's own
problem.

Sign convention::

           \  (C)              O.x right, O.y up; frame ``n`` is O turned by -alpha: n.x down
            \   \ x            the slope, n.y out of it.  x: the centre C's distance down the
             \___P___ alpha    slope; phi: the disk's turn, clockwise (its frame is O turned by
                               -phi), so rolling at P is x' = r phi'.

The incline pushes at P with ``N`` along n.y and holds the disk with the friction ``F`` up the
slope (along -n.x).  Direct form (by hand), the rolling declared with ``ne.rolling``::

    n.x:  m g sin alpha - F = m x''
    n.y:  N - m g cos alpha = 0
    C:    (-r n.y) x (-F n.x) = -r F O.z;  -r F = I_C (-phi'') = -(m r^2/2) phi''
    rolling: x' - r phi' = 0

Lagrangian (by hand), both coordinates kept and the rolling closed by a multiplier::

    T = m x'^2/2 + (m r^2/2) phi'^2/2,   V = -m g x sin alpha
    constraint  -x' + r phi' = 0, multiplier F:  Q = F (-1, r)
    x:    m x'' - m g sin alpha = -F        phi:  (m r^2/2) phi'' = r F

(the multiplier's force on x is -F: the friction's own sign), so x'' = (2/3) g sin alpha,
F = m g sin alpha/3 and N = m g cos alpha (printed below).
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Point, Problem, Published, Reaction, RigidBody,
                      coordinate, rate, rot_z, thin_disk)

m, r, g, alpha = sp.symbols("m r g alpha", positive=True)
x, phi = coordinate("x"), coordinate("phi")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.n = self.O.child("n", rot_z(-alpha))
        self.C = Point.origin(self.O).locate("C", x * self.n.x + r * self.n.y)
        self.P = self.C.locate("P", -r * self.n.y)
        self.disk = RigidBody("disk", m, self.C, self.O.child("disk", rot_z(-phi)),
                              thin_disk(m, r))


class RollingDownIncline(Problem):
    name = "rolling_down_incline"
    title = "Disk rolling down a rough incline"
    source = "my notes: rolling, ex. 1"
    parameters = (Parameter(m, MASS, 1.0, (0.1, 10.0)), Parameter(r, LENGTH, 0.2, (0.05, 1.0)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)),
                  Parameter(alpha, ANGLE, 0.3, (0.1, 1.2)))
    coordinates = (Coordinate(x, LENGTH, (-1.0, 1.0)), Coordinate(phi, ANGLE, (-3.0, 3.0)))
    reactions = (Reaction("N", FORCE, "incline on disk at P, out of the slope"),
                 Reaction("F", FORCE, "friction, incline on disk at P, up the slope"))
    unilateral = {"N": "the disk leaves the incline"}

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.reaction("N", sc.disk, sc.n.y, at=sc.P)
        ne.reaction("F", sc.disk, -sc.n.x, at=sc.P)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x, phi], ground=sc.O)
        self.loads(ne, sc)
        ne.rolling("no slip", sc.disk, sc.P, [sc.n.x])
        ne.linear_momentum(sc.disk, sc.n.x)
        ne.linear_momentum(sc.disk, sc.n.y)
        ne.angular_momentum(sc.disk, sc.O.z)
        return ne.equations()

    def constraint(self, lg):
        lg.velocity_constraint("F", [-1, r])

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, phi])
        lg.kinetic("T of disk", m * rate(x)**2 / 2 + m * r**2 / 4 * rate(phi)**2)
        lg.potential("gravity", -m * g * x * sp.sin(alpha))
        self.constraint(lg)
        return lg.equations()

    def published(self):
        return [Published("acceleration and friction", "equation",
                          (3 * rate(x, 2) - 2 * g * sp.sin(alpha),
                           sp.Symbol("F", real=True) - m * g * sp.sin(alpha) / 3),
                          where="my notes, (1.3)")]


PROBLEMS = (RollingDownIncline,)
