r"""A rod sliding in the radial slot of a turntable driven by a motor -- a teacher's own
problem.

Sign sketch (seen from above; the table is horizontal, weights balanced by it)::

          O.y                       O.x, O.y horizontal, O.z up.  phi: turn of the table
           |     S.y  S.x           (and its slot) about O.z, driven by the motor torque
           |      \  /              tau.  S = O turned by phi; the slot runs along S.x.
           |   ====[==C==]==        r: the rod's centre C along the slot, C = r S.x; a
           O--------------- O.x     spring k from the axis pulls it back to r = r0.

The rod (m, length L, I_C = m L^2/12 about O.z) turns with the slot.  The slot's walls push
it with ``N`` along S.y through C and hold it with the couple ``Q`` about O.z; the rod pushes
back on the table.  The table's inertia about its axis is J.

Direct form (by hand)::

    rod S.x:    -k (r - r0) = m (r'' - r phi'^2)
    rod S.y:    N = m (r phi'' + 2 r' phi')
    rod C:      Q = (m L^2/12) phi''
    table O:    tau - r N - Q = J phi''

Lagrangian (by hand)::

    T = J phi'^2/2 + m (r'^2 + r^2 phi'^2)/2 + (m L^2/12) phi'^2/2,   V = k (r - r0)^2/2,
    Q_phi = tau
"""
from __future__ import annotations

import sympy as sp

from dualmech import (FORCE, LENGTH, MASS, STIFFNESS, TORQUE, ANGLE, Coordinate, Frame, Input,
                      Lagrangian, NewtonEuler, Parameter, Point, Problem, Reaction, RigidBody,
                      coordinate, rate, rot_z, thin_rod, INERTIA, t)

m, L, J, k, r0, Mt = sp.symbols("m L J k r0 M_t", positive=True)
tau = sp.Symbol("tau", real=True)
r, phi = coordinate("r"), coordinate("phi")


class RodInDrivenSlot(Problem):
    """A rod in the slot of a turntable with a motor."""

    name = "rod_in_driven_slot"
    title = "Rod sliding in the slot of a motor-driven turntable"
    source = "my notes: rotating frames, ex. 3"
    parameters = (Parameter(m, MASS, 0.5, (0.1, 5.0), "mass of the rod"),
                  Parameter(L, LENGTH, 0.2, (0.05, 0.5), "length of the rod"),
                  Parameter(J, INERTIA, 0.3, (0.05, 2.0), "table about its axis"),
                  Parameter(Mt, MASS, 3.0, (0.5, 10.0), "mass of the table"),
                  Parameter(k, STIFFNESS, 40.0, (1.0, 200.0), "spring to the axis"),
                  Parameter(r0, LENGTH, 0.3, (0.1, 0.5), "free length of the spring"))
    coordinates = (Coordinate(r, LENGTH, (0.05, 0.6), (-2.0, 2.0), "rod's centre from the axis"),
                   Coordinate(phi, ANGLE, (-3.0, 3.0), (-5.0, 5.0), "turn of the table"))
    reactions = (Reaction("N", FORCE, "slot on rod, along S.y"),
                 Reaction("Q", TORQUE, "slot on rod, couple about O.z"))
    inputs = (Input(tau, TORQUE, "motor torque on the table", history=sp.sin(2 * t) / 10),)

    def newton_euler(self):
        O = Frame.ground("O")
        S = O.child("S", rot_z(phi))
        o = Point.origin(O, "O")
        C = o.locate("C", r * S.x)
        rod = RigidBody("rod", m, C, S, thin_rod(m, L, "x"))
        table = RigidBody("table", Mt, o, S, sp.diag(J / 2, J / 2, J))
        ne = NewtonEuler("newton_euler", coordinates=[r, phi], ground=O)
        ne.linear_spring("spring", rod, k, r - r0, S.x)
        ne.torque("motor", table, tau * O.z)
        ne.reaction("N", rod, S.y, against=table, against_at=C)
        ne.reaction_torque("Q", rod, O.z, against=table)
        ne.linear_momentum(rod, S.x)
        ne.linear_momentum(rod, S.y)
        ne.angular_momentum(rod, O.z)
        ne.angular_momentum(table, O.z)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[r, phi])
        lg.kinetic("T of table", J * rate(phi)**2 / 2)
        lg.kinetic("T of rod", m * (rate(r)**2 + r**2 * rate(phi)**2) / 2
                   + m * L**2 / 12 * rate(phi)**2 / 2)
        lg.potential("spring", k * (r - r0)**2 / 2)
        lg.generalized_force("motor", [0, tau])
        return lg.equations()


PROBLEMS = (RodInDrivenSlot,)
