r"""A rod sliding in a tube that a motor turns at a constant rate in a vertical plane -- a
teacher's own problem.

Sign convention::

              O.y                   O.x right, O.y up, O.z out of the page.  The tube (mass
               |    / tube          M, length L, pivoted at its end O, centre at L/2) is
               |   /=rod=           turned by a motor: its angle from O.x is Omega t
               |  /                 (prescribed).  Frame ``u`` is O turned by Omega t; the
               | / Omega t          rod (mass m, length b) slides inside it, its centre at
               O-------- O.x        r u.x, and turns with the tube.

The tube's wall pushes the rod with ``N`` along u.y; the motor drives the tube with the
couple ``tau`` along O.z.  Direct form (by hand): the rod along u.x and u.y, the tube about
the fixed pivot O (its angular momentum (M L^2/3) Omega is constant)::

    rod u.x:  -m g sin(Omega t) = m (r'' - r Omega^2)
    rod u.y:  N - m g cos(Omega t) = 2 m Omega r'
    tube O:   tau - N r - M g (L/2) cos(Omega t) = 0

Lagrangian (by hand), coordinates r and the tube angle phi, phi = Omega t prescribed::

    T = m (r'^2 + r^2 phi'^2)/2 + (m b^2/12) phi'^2/2 + (M L^2/3) phi'^2/2
    V = m g r sin phi + M g (L/2) sin phi
    r:  m r'' - m r Omega^2 + m g sin(Omega t) = 0

The motor's couple, ``tau = r (m g cos(Omega t) + 2 m Omega r') + M g (L/2) cos(Omega t)``,
is printed below; the tube's weight is in it and nowhere else.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, FREQUENCY, LENGTH, MASS, TORQUE, Coordinate,
                      Frame, Lagrangian, NewtonEuler, Parameter, Point, Problem, Published,
                      Reaction, RigidBody, coordinate, rate, rot_z, t, thin_rod)

m, M, b, L, g, Omega = sp.symbols("m M b L g Omega", positive=True)
r, phi = coordinate("r"), coordinate("phi")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.u = self.O.child("u", rot_z(Omega * t))
        o = Point.origin(self.O)
        self.C = o.locate("C", r * self.u.x)
        self.rod = RigidBody("rod", m, self.C, self.u, thin_rod(m, b, axis="x"))
        self.tube = RigidBody("tube", M, o.locate("G", L / 2 * self.u.x), self.u,
                              thin_rod(M, L, axis="x"))
        self.pivot = o


class RodInRotatingTube(Problem):
    name = "rod_in_rotating_tube"
    title = "Rod sliding in a motor-driven rotating tube"
    source = "my notes: rotating frames, ex. 3"
    parameters = (Parameter(m, MASS, 0.5, (0.1, 5.0)), Parameter(M, MASS, 2.0, (0.1, 10.0)),
                  Parameter(b, LENGTH, 0.2, (0.05, 0.5)), Parameter(L, LENGTH, 1.0, (0.5, 3.0)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)),
                  Parameter(Omega, FREQUENCY, 2.0, (0.5, 10.0)))
    coordinates = (Coordinate(r, LENGTH, (0.1, 0.9), (-2.0, 2.0), "rod centre from the pivot"),)
    reactions = (Reaction("N", FORCE, "tube wall on rod, along u.y"),
                 Reaction("tau", TORQUE, "motor on tube, about O.z"))
    initial_state = {r: 0.3, rate(r): 0.0}

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.reaction("N", sc.rod, sc.u.y, against=sc.tube, against_at=sc.C)
        ne.reaction_torque("tau", sc.tube, sc.O.z)

    def balances(self, ne, sc):
        ne.linear_momentum(sc.rod, sc.u.x)
        ne.linear_momentum(sc.rod, sc.u.y)
        ne.angular_momentum(sc.tube, sc.O.z, about=sc.pivot)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[r], ground=sc.O)
        self.loads(ne, sc)
        self.balances(ne, sc)
        return ne.equations()

    def kinetic(self, lg):
        lg.kinetic("T of rod", m * (rate(r)**2 + r**2 * rate(phi)**2) / 2
                   + m * b**2 / 12 * rate(phi)**2 / 2)
        lg.kinetic("T of tube", M * L**2 / 3 * rate(phi)**2 / 2)

    def potential(self, lg):
        lg.potential("gravity", m * g * r * sp.sin(phi) + M * g * L / 2 * sp.sin(phi))

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[r, phi])
        self.kinetic(lg)
        self.potential(lg)
        lg.prescribe(phi, Omega * t)
        return lg.equations()

    def published(self):
        tau = sp.Symbol("tau", real=True)
        c = sp.cos(Omega * t)
        return [
            Published("equation of motion", "motion",
                      (rate(r, 2) - r * Omega**2 + g * sp.sin(Omega * t),),
                      where="my notes, (3.2)"),
            Published("motor couple", "equation",
                      (tau - r * (m * g * c + 2 * m * Omega * rate(r)) - M * g * L / 2 * c,),
                      where="my notes, (3.4)"),
        ]


PROBLEMS = (RodInRotatingTube,)
