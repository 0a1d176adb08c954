r"""A disk rolling inside a ring that spins freely about its fixed centre -- a teacher's own
problem.

Sign sketch::

            .-''''-.          O.x right, O.y up, O.z out of the page; the ring (hoop M,
          /    O    \         radius R) turns about its fixed centre O by psi (about O.z).
         |     \     |        theta: the line O -> C from the downward vertical, about O.z.
          \  th \(C) /        A = O turned by theta: A.x = e_theta, A.y = -e_r (from the
            '-.__P_-'         contact P back towards O).  C = -(R - r) A.y, P = -R A.y.

The disk (m, radius r, I_C = m r^2/2) rolls on the inside of the ring without slipping: the
disk's material point at P has the ring's velocity at P,
``(R - r) theta' + r phi' = R psi'``, so its turn is ``phi = (R psi - (R - r) theta)/r``.
The ring pushes the disk at P with ``N`` along A.y (towards O) and the friction ``F`` along
A.x; the disk pushes back on the ring.  The ring's pin at O takes no moment about O.

Direct form (by hand)::

    disk A.x:  F - m g sin(theta) = m (R - r) theta''
    disk A.y:  N - m g cos(theta) = m (R - r) theta'^2
    disk C:    r F = (m r^2/2) phi''
    ring O:    -R F = M R^2 psi''

Lagrangian (by hand)::

    T = M R^2 psi'^2/2 + m (R - r)^2 theta'^2/2 + (m r^2/2) phi'^2/2,
    V = -m g (R - r) cos(theta)

so ``N = m g cos(theta) + m (R - r) theta'^2`` and ``F = -M R psi''``.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Point, Problem, Reaction, RigidBody, coordinate,
                      rate, rot_z)

M, m, R, r, g = sp.symbols("M m R r g", positive=True)
theta, psi = coordinate("theta"), coordinate("psi")


class DiskInSpinningRing(Problem):
    """A disk rolling inside a freely spinning ring."""

    name = "disk_in_spinning_ring"
    title = "Disk rolling inside a freely spinning ring"
    source = "my notes: rolling, ex. 9"
    parameters = (Parameter(M, MASS, 2.0, (0.5, 10.0), "mass of the ring"),
                  Parameter(m, MASS, 1.0, (0.1, 5.0), "mass of the disk"),
                  Parameter(R, LENGTH, 0.5, (0.3, 1.0), "radius of the ring"),
                  Parameter(r, LENGTH, 0.1, (0.02, 0.25), "radius of the disk"),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"))
    coordinates = (Coordinate(theta, ANGLE, (-1.5, 1.5), (-4.0, 4.0), "where the disk is"),
                   Coordinate(psi, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "turn of the ring"))
    reactions = (Reaction("N", FORCE, "ring on disk, along A.y (towards O)"),
                 Reaction("F", FORCE, "friction, ring on disk, along A.x"))

    def newton_euler(self):
        O = Frame.ground("O")
        A = O.child("A", rot_z(theta))
        o = Point.origin(O, "O")
        C = o.locate("C", -(R - r) * A.y)
        P = o.locate("P", -R * A.y)
        phi = (R * psi - (R - r) * theta) / r
        disk = RigidBody("disk", m, C, O.child("disk", rot_z(phi)),
                         sp.diag(m * r**2 / 4, m * r**2 / 4, m * r**2 / 2))
        ring = RigidBody("ring", M, o, O.child("ring", rot_z(psi)),
                         sp.diag(M * R**2 / 2, M * R**2 / 2, M * R**2))
        ne = NewtonEuler("newton_euler", coordinates=[theta, psi], ground=O)
        ne.gravity(-g * O.y, [disk])
        ne.reaction("N", disk, A.y, at=P, against=ring, against_at=P)
        ne.reaction("F", disk, A.x, at=P, against=ring, against_at=P)
        ne.linear_momentum(disk, A.x)
        ne.linear_momentum(disk, A.y)
        ne.angular_momentum(disk, O.z)
        ne.angular_momentum(ring, O.z)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta, psi])
        phi_dot = (R * rate(psi) - (R - r) * rate(theta)) / r
        lg.kinetic("T of ring", M * R**2 * rate(psi)**2 / 2)
        lg.kinetic("T of disk",
                   m * (R - r)**2 * rate(theta)**2 / 2 + m * r**2 / 2 * phi_dot**2 / 2)
        lg.potential("gravity", -m * g * (R - r) * sp.cos(theta))
        return lg.equations()


PROBLEMS = (DiskInSpinningRing,)
