r"""A bead on a parabolic wire spinning about the vertical -- a teacher's file, outside the
catalogue.

Sign convention::

          O.z (up, the spin axis)
           |      wire z = c r^2, turned at the constant rate Omega about O.z
           |   o  bead m at distance r from the axis, in the wire's plane (spin.x, O.z)
        ---+-------> spin.x

Direct form: the bead along the wire's tangent ``spin.x + 2 c r O.z``, along the normal in
the wire's plane ``-2 c r spin.x + O.z`` (reaction ``N``, along that normal) and across the
plane ``spin.y`` (reaction ``S``).  Lagrangian (by hand)::

    T = m (r'^2 + 4 c^2 r^2 r'^2 + Omega^2 r^2)/2,     V = m g c r^2
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Particle, Point, Problem, Reaction, coordinate,
                      rate, rot_z, t)
from dualmech.model.dimensions import Dimension

m, c, g, Omega = sp.symbols("m c g Omega", positive=True)
r = coordinate("r")
PER_LENGTH = Dimension(length=-1)
RATE = Dimension(time=-1) * Dimension(angle=1)


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.spin = self.O.child("spin", rot_z(Omega * t))
        self.P = Point.origin(self.O).locate("bead", r * self.spin.x + c * r**2 * self.O.z)
        self.bead = Particle("bead", m, self.P)
        self.tangent = self.spin.x + 2 * c * r * self.O.z
        self.normal = -2 * c * r * self.spin.x + self.O.z


class SpinningParabola(Problem):
    name = "teacher_spinning_parabola"
    title = "Bead on a spinning parabolic wire"
    source = "teacher's own problem (test corpus)"
    parameters = (Parameter(m, MASS, 0.1, (0.01, 1.0)),
                  Parameter(c, PER_LENGTH, 2.0, (0.5, 5.0)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)),
                  Parameter(Omega, RATE, 5.0, (0.5, 10.0)))
    coordinates = (Coordinate(r, LENGTH, (0.0, 0.5), (-1.0, 1.0)),)
    reactions = (Reaction("N", FORCE, "wire on bead, normal in the wire's plane"),
                 Reaction("S", FORCE, "wire on bead, across the plane (spin.y)"))

    def normal(self, sc):
        return sc.normal

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[r], ground=sc.O)
        ne.gravity(-g * sc.O.z)
        ne.reaction("N", sc.bead, self.normal(sc))
        ne.reaction("S", sc.bead, sc.spin.y)
        ne.linear_momentum(sc.bead, sc.tangent, "sum F . tangent (bead)")
        ne.linear_momentum(sc.bead, sc.normal, "sum F . normal (bead)")
        ne.linear_momentum(sc.bead, sc.spin.y, "sum F . spin.y (bead)")
        return ne.equations()

    def kinetic(self, lg):
        lg.kinetic("T of bead", m * (rate(r)**2 + 4 * c**2 * r**2 * rate(r)**2
                                     + Omega**2 * r**2) / 2)

    def potential(self, lg):
        lg.potential("gravity", m * g * c * r**2)

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[r])
        self.kinetic(lg)
        self.potential(lg)
        return lg.equations()


class SpinForgotten(SpinningParabola):
    """T written in the wire's (rotating) frame: the transport term m Omega^2 r^2/2 is
    missing."""

    def kinetic(self, lg):
        lg.kinetic("T of bead", m * (rate(r)**2 + 4 * c**2 * r**2 * rate(r)**2) / 2)


class HeightSquaredMissed(SpinningParabola):
    """The vertical speed 2 c r r' forgotten: 2 m c^2 r^2 r'^2 missing from T of bead."""

    def kinetic(self, lg):
        lg.kinetic("T of bead", m * (rate(r)**2 + Omega**2 * r**2) / 2)


class GravitySign(SpinningParabola):
    """V = -m g c r^2: the sign of the gravity potential."""

    def potential(self, lg):
        lg.potential("gravity", -m * g * c * r**2)


class NormalDrawnVertical(SpinningParabola):
    """The wire's normal force drawn along O.z (vertical) instead of the wire's normal: it
    then does virtual work N 2 c r dr."""

    def normal(self, sc):
        return sc.O.z


MISTAKES = [
    (SpinForgotten, "T of bead", m * Omega**2 * r**2 / 2),
    (HeightSquaredMissed, "T of bead", 2 * m * c**2 * r**2 * rate(r)**2),
    (GravitySign, "V of gravity", m * g * c * r**2),
    (NormalDrawnVertical, "reaction N",
     2 * sp.Symbol("N", real=True) * c * r * sp.Symbol("δr", real=True)),
]
