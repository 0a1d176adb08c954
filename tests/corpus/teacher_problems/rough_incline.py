r"""A block sliding down a rough incline, held back by a spring and a viscous damper -- a
teacher's own problem.

Sign convention::

        anchor                       O.x right, O.y up; the incline (angle alpha) is fixed.
          \  k, c                    Frame ``n`` is O turned by -alpha: n.x points down the
           \__                       slope, n.y out of it.  s: distance of the block down the
            |_| block m              slope from where the spring is unstretched.  While the
           /  \                      block slides DOWN (s' > 0: the declared rate range),
          /    \ alpha               Coulomb friction mu N acts up the slope.

Direct form (by hand)::

    n.x:  m g sin alpha - k s - c s' - mu N = m s''
    n.y:  N - m g cos alpha = 0

Lagrangian (by hand): T = m s'^2/2, V = k s^2/2 - m g s sin alpha, Rayleigh's dissipation
c s'^2/2, and the friction's virtual work -mu N ds with N = m g cos alpha from the normal
balance (the incline does not move)::

    m s'' + c s' + k s - m g sin alpha + mu m g cos alpha = 0

The block comes to rest (if it does) at s* = m g (sin alpha - mu cos alpha)/k (printed).
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, DAMPING, DIMENSIONLESS, FORCE, LENGTH, MASS,
                      STIFFNESS, Coordinate, Frame, Lagrangian, NewtonEuler, Parameter,
                      Particle, Point, Problem, Published, Reaction, coordinate, rate, rot_z)

m, k, c, mu, alpha, g = sp.symbols("m k c mu alpha g", positive=True)
s = coordinate("s")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.n = self.O.child("n", rot_z(-alpha))
        self.block = Particle("block", m, Point.origin(self.O).locate("B", s * self.n.x))


class RoughIncline(Problem):
    name = "rough_incline"
    title = "Block on a rough incline with a spring and a damper"
    source = "my notes: friction, ex. 5"
    parameters = (Parameter(m, MASS, 2.0, (0.1, 10.0)), Parameter(k, STIFFNESS, 20.0, (1, 100)),
                  Parameter(c, DAMPING, 0.5, (0.0, 5.0)),
                  Parameter(mu, DIMENSIONLESS, 0.2, (0.0, 0.5)),
                  Parameter(alpha, ANGLE, 0.6, (0.2, 1.2)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
    coordinates = (Coordinate(s, LENGTH, (-0.5, 0.5), (0.05, 2.0),
                              "down the slope from the unstretched spring"),)
    reactions = (Reaction("N", FORCE, "incline on block, out of the slope"),)
    unilateral = {"N": "the block leaves the incline"}
    initial_state = {s: -0.2, rate(s): 0.5}

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.linear_spring("spring", sc.block, k, s, sc.n.x)
        ne.linear_damper("damper", sc.block, c, rate(s), sc.n.x)
        N = ne.reaction("N", sc.block, sc.n.y)
        ne.force("friction", sc.block, -mu * N * sc.n.x)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[s], ground=sc.O)
        self.loads(ne, sc)
        ne.linear_momentum(sc.block, sc.n.x)
        ne.linear_momentum(sc.block, sc.n.y)
        return ne.equations()

    def potential(self, lg):
        lg.potential("spring", k * s**2 / 2)
        lg.potential("gravity", -m * g * s * sp.sin(alpha))

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[s])
        lg.kinetic("T of block", m * rate(s)**2 / 2)
        self.potential(lg)
        lg.dissipation("damper", c * rate(s)**2 / 2)
        lg.generalized_force("friction", [-mu * m * g * sp.cos(alpha)])
        return lg.equations()

    def published(self):
        return [Published("equation of motion", "motion",
                          (m * rate(s, 2) + c * rate(s) + k * s - m * g * sp.sin(alpha)
                           + mu * m * g * sp.cos(alpha),), where="my notes, (5.1)")]


PROBLEMS = (RoughIncline,)
