r"""A spherical pendulum: a bob on a light rod free to swing in any direction -- a teacher's
own problem.

Sign convention::

            O  (pivot)           O.x, O.y horizontal, O.z up.  phi: azimuth of the vertical
            |\                   plane holding the rod, about O.z from O.x (frame ``h`` is O
            | \  l               turned by phi).  theta: angle of the rod from the downward
            |th\                 vertical, in that plane (frame ``arm`` is h turned by -theta
            |   o bob m          about h.y, so the bob is at -l arm.z
                                  = l sin th h.x - l cos th O.z).

The rod (length l, massless) pulls the bob towards O with ``T``.  Direct form (by hand),
``m a`` of the bob in the arm frame (arm.x tangent to the swing, h.y across it)::

    arm.x:  -m g sin th = m (l th'' - l sin th cos th phi'^2)
    h.y:     0 = m (l sin th phi'' + 2 l cos th th' phi')
    arm.z:   T - m g cos th = m l (th'^2 + sin^2 th phi'^2)

Lagrangian (by hand)::

    T = m l^2 (th'^2 + sin^2 th phi'^2)/2,     V = -m g l cos th
    theta:  m l^2 th'' - m l^2 sin th cos th phi'^2 + m g l sin th = 0
    phi:    d/dt (m l^2 sin^2 th phi') = 0

The azimuthal momentum ``p_phi = m l^2 sin^2 th phi'`` is conserved (printed below).
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Particle, Point, Problem, Published, Reaction,
                      coordinate, rate, rot_y, rot_z, t)

m, l, g = sp.symbols("m l g", positive=True)
theta, phi = coordinate("theta"), coordinate("phi")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.h = self.O.child("h", rot_z(phi))
        self.arm = self.h.child("arm", rot_y(-theta))
        self.bob = Particle("bob", m, Point.origin(self.O).locate("P", -l * self.arm.z))


class SphericalPendulum(Problem):
    name = "spherical_pendulum"
    title = "Spherical pendulum"
    source = "my notes: 3D motion, ex. 2"
    parameters = (Parameter(m, MASS, 1.0, (0.1, 10.0)), Parameter(l, LENGTH, 1.0, (0.1, 3.0)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
    coordinates = (Coordinate(theta, ANGLE, (0.2, 2.5), (-3.0, 3.0)),
                   Coordinate(phi, ANGLE, (-3.0, 3.0), (-3.0, 3.0)))
    reactions = (Reaction("T", FORCE, "rod on bob, towards the pivot"),)
    singular = (sp.sin(theta),)
    initial_state = {theta: 1.0, phi: 0.0, rate(theta): 0.0, rate(phi): 2.0}

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.z)
        ne.reaction("T", sc.bob, sc.arm.z)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta, phi], ground=sc.O)
        self.loads(ne, sc)
        for axis in (sc.arm.x, sc.h.y, sc.arm.z):
            ne.linear_momentum(sc.bob, axis)
        return ne.equations()

    def kinetic(self, lg):
        lg.kinetic("T of bob", m * l**2 * (rate(theta)**2
                                           + sp.sin(theta)**2 * rate(phi)**2) / 2)

    def potential(self, lg):
        lg.potential("gravity", -m * g * l * sp.cos(theta))

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[theta, phi])
        self.kinetic(lg)
        self.potential(lg)
        return lg.equations()

    def published(self):
        p_phi = m * l**2 * sp.sin(theta)**2 * rate(phi)
        return [
            Published("azimuthal momentum is conserved", "equation", (p_phi.diff(t),),
                      where="my notes, (2.5)"),
            Published("tension", "equation",
                      (sp.Symbol("T", real=True) - m * g * sp.cos(theta)
                       - m * l * (rate(theta)**2 + sp.sin(theta)**2 * rate(phi)**2),),
                      where="my notes, (2.6)"),
        ]


PROBLEMS = (SphericalPendulum,)
