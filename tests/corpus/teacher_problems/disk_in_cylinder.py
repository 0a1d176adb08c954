r"""A disk rolling without slipping inside a fixed cylinder -- a teacher's own problem.

Sign convention::

          .-''''-.          O.x right, O.y up, O.z out of the page; cylinder of radius R,
        /          \        centre O.  theta: angle of the line O -> C (the disk's centre)
       |     O      |       from the downward vertical, counterclockwise.  The radial frame
       |      \     |       ``e`` is O turned by theta: C = -(R - r) e.y, the contact point
        \      (C)  /       P = -R e.y.  The disk (mass m, radius r, I_C = m r^2/2) turns by
          '-.__P_.-'        phi about O.z; rolling at P: (R - r) th' + r phi' = 0, so
                            phi = -(R - r) theta / r.

Direct form: the disk along e.x and e.y and about C; the cylinder pushes at P with ``N``
along e.y (towards O) and the friction ``F`` along e.x.  By hand::

    e.x:  F - m g sin th = m (R - r) th''
    e.y:  N - m g cos th = m (R - r) th'^2
    C:    (-r e.y) x (F e.x) = r F O.z,  r F = I_C phi'' = -(m r/2) (R - r) th''
          =>  F = -m (R - r) th''/2

Lagrangian (by hand)::

    T = m (R - r)^2 th'^2/2 + (m r^2/2) ((R - r) th'/r)^2/2 = 3 m (R - r)^2 th'^2/4
    V = -m g (R - r) cos th
    =>  (3/2) m (R - r)^2 th'' + m g (R - r) sin th = 0,  th'' = -2 g sin th/(3 (R - r))

so F = m g sin th/3 (the e.x row agrees: F = m g sin th + m (R - r) th'') and
N = m g cos th + m (R - r) th'^2 (printed below).
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Point, Problem, Published, Reaction, RigidBody,
                      coordinate, rate, rot_z, thin_disk)

m, R, r, g = sp.symbols("m R r g", positive=True)
theta = coordinate("theta")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.e = self.O.child("e", rot_z(theta))
        self.disk_frame = self.O.child("disk", rot_z(-(R - r) * theta / r))
        self.C = Point.origin(self.O).locate("C", -(R - r) * self.e.y)
        self.P = self.C.locate("P", -r * self.e.y)
        self.disk = RigidBody("disk", m, self.C, self.disk_frame, thin_disk(m, r))


class DiskInCylinder(Problem):
    name = "disk_in_cylinder"
    title = "Disk rolling without slipping inside a cylinder"
    source = "my notes: rolling, ex. 4"
    parameters = (Parameter(m, MASS, 1.0, (0.1, 10.0)),
                  Parameter(R, LENGTH, 1.0, (0.6, 3.0)),
                  Parameter(r, LENGTH, 0.2, (0.05, 0.5)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
    coordinates = (Coordinate(theta, ANGLE, (-1.5, 1.5), (-3.0, 3.0)),)
    reactions = (Reaction("N", FORCE, "cylinder on disk at P, towards O"),
                 Reaction("F", FORCE, "friction, cylinder on disk at P, along e.x"))
    unilateral = {"N": "the disk leaves the cylinder wall"}
    initial_state = {theta: 1.0}

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.reaction("N", sc.disk, sc.e.y, at=sc.P)
        ne.reaction("F", sc.disk, sc.e.x, at=sc.P)

    def balances(self, ne, sc):
        ne.linear_momentum(sc.disk, sc.e.x)
        ne.linear_momentum(sc.disk, sc.e.y)
        ne.angular_momentum(sc.disk, sc.O.z)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=sc.O)
        self.loads(ne, sc)
        self.balances(ne, sc)
        return ne.equations()

    def kinetic(self, lg):
        lg.kinetic("T of disk", m * (R - r)**2 * rate(theta)**2 / 2
                   + m * r**2 / 4 * ((R - r) * rate(theta) / r)**2)

    def potential(self, lg):
        lg.potential("gravity", -m * g * (R - r) * sp.cos(theta))

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta])
        self.kinetic(lg)
        self.potential(lg)
        return lg.equations()

    def published(self):
        N, F = sp.Symbol("N", real=True), sp.Symbol("F", real=True)
        return [
            Published("equation of motion", "motion",
                      (3 * (R - r) * rate(theta, 2) + 2 * g * sp.sin(theta),),
                      where="my notes, (4.2)"),
            Published("friction and normal force", "equation",
                      (F - m * g * sp.sin(theta) / 3,
                       N - m * g * sp.cos(theta) - m * (R - r) * rate(theta)**2),
                      where="my notes, (4.3)"),
        ]


PROBLEMS = (DiskInCylinder,)
