r"""A gyroscope: a disk on a light axle whose end rests in a fixed pivot -- a teacher's own
problem, in 3-D with Euler angles.

Sign sketch::

          O.z                       O: the pivot, fixed; O.z up.  Euler angles z-x-z:
           |    . G (disk)          A = O turned by phi about O.z (precession),
           |  .  axle B.z           B = A turned by theta about A.x (nutation: the axle
           |.theta                  B.z from O.z), D = B turned by psi about B.z (spin).
           O-------- O.y            The disk's centre G = L B.z.

The disk (m, radius a, thin: I = m a^2/2 about its axle, m a^2/4 across, at G) spins on the
axle; the axle is light.  The pivot pushes the axle with ``R_x, R_y, R_z`` along O.x, O.y,
O.z.

Direct form (by hand): the disk along O.x, O.y, O.z (``R + m g = m a_G``) and its angular
momentum about G along B.x, B.y, B.z (the pivot force's moment ``(-L B.z) x R``).

Lagrangian (by hand), with ``I1 = m a^2/4 + m L^2`` about the pivot and ``I3 = m a^2/2``::

    T = I1 (theta'^2 + phi'^2 sin(theta)^2)/2 + I3 (psi' + phi' cos(theta))^2/2
    V = m g L cos(theta)
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Point, Problem, Reaction, RigidBody, coordinate,
                      rate, rot_x, rot_z, FORCE)

m, a, L, g = sp.symbols("m a L g", positive=True)
phi, theta, psi = coordinate("phi"), coordinate("theta"), coordinate("psi")


class TopOnPivot(Problem):
    """A gyroscope on a fixed pivot."""

    name = "top_on_pivot"
    title = "Gyroscope on a fixed pivot (Euler angles)"
    source = "my notes: rigid bodies in 3-D, ex. 5"
    parameters = (Parameter(m, MASS, 0.5, (0.1, 5.0), "mass of the disk"),
                  Parameter(a, LENGTH, 0.05, (0.01, 0.2), "radius of the disk"),
                  Parameter(L, LENGTH, 0.1, (0.02, 0.5), "pivot to the disk's centre"),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"))
    coordinates = (Coordinate(phi, ANGLE, (-3.0, 3.0), (-10.0, 10.0), "precession"),
                   Coordinate(theta, ANGLE, (0.2, 2.9), (-5.0, 5.0), "nutation"),
                   Coordinate(psi, ANGLE, (-3.0, 3.0), (-100.0, 100.0), "spin"))
    reactions = (Reaction("R_x", FORCE, "pivot on axle, along O.x"),
                 Reaction("R_y", FORCE, "pivot on axle, along O.y"),
                 Reaction("R_z", FORCE, "pivot on axle, along O.z"))

    def newton_euler(self):
        O = Frame.ground("O")
        A = O.child("A", rot_z(phi))
        B = A.child("B", rot_x(theta))
        D = B.child("D", rot_z(psi))
        o = Point.origin(O, "O")
        G = o.locate("G", L * B.z)
        disk = RigidBody("disk", m, G, D, sp.diag(m * a**2 / 4, m * a**2 / 4, m * a**2 / 2))
        ne = NewtonEuler("newton_euler", coordinates=[phi, theta, psi], ground=O)
        ne.gravity(-g * O.z)
        ne.reaction_vector("R", disk, O, "xyz", at=o)
        for e in (O.x, O.y, O.z):
            ne.linear_momentum(disk, e)
        for e in (B.x, B.y, B.z):
            ne.angular_momentum(disk, e)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[phi, theta, psi])
        I1, I3 = m * a**2 / 4 + m * L**2, m * a**2 / 2
        lg.kinetic("T of disk", I1 * (rate(theta)**2 + rate(phi)**2 * sp.sin(theta)**2) / 2
                   + I3 * (rate(psi) + rate(phi) * sp.cos(theta))**2 / 2)
        lg.potential("gravity", m * g * L * sp.cos(theta))
        return lg.equations()


PROBLEMS = (TopOnPivot,)
