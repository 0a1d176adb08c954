r"""A block on a pushed base, held to it by a spring and a damper -- a teacher's own problem.

Sign sketch::

                 +-----+                    O.x right, O.y up.  x: the base on the smooth
        k  /\/\/-|  m  |                    floor; u: the block relative to the base
        c  [==]--+-----+                    (spring k and damper c slack at u = 0).  The
   F -> +---------------------+             push F(t) acts on the base along O.x.
        |        base M       |
        o---------------------o

The block slides on the base without friction.  The base pushes the block up with ``N`` (and
the block pushes it down); the floor pushes the base up with ``Nf``.

Direct form (by hand)::

    block O.x:  -k u - c u' = m (x'' + u'')      block O.y:  N - m g = 0
    base O.x:   F + k u + c u' = M x''           base O.y:   Nf - N - M g = 0

Lagrangian (by hand)::

    T = M x'^2/2 + m (x' + u')^2/2,   V = k u^2/2,   D = c u'^2/2,   Q_x = F

so ``Nf = (M + m) g``.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, DAMPING, FORCE, LENGTH, MASS, STIFFNESS, Coordinate, Frame,
                      Input, Lagrangian, NewtonEuler, Parameter, Particle, Point, Problem,
                      Reaction, coordinate, rate, t)

M, m, k, c, g = sp.symbols("M m k c g", positive=True)
F = sp.Symbol("F", real=True)
x, u = coordinate("x"), coordinate("u")


class PushedBaseDamper(Problem):
    """A spring-and-damper block on a pushed base."""

    name = "pushed_base_damper"
    title = "Block held by a spring and a damper on a pushed base"
    source = "my notes: vibrations, ex. 2"
    parameters = (Parameter(M, MASS, 5.0, (0.5, 20.0), "mass of the base"),
                  Parameter(m, MASS, 1.0, (0.1, 5.0), "mass of the block"),
                  Parameter(k, STIFFNESS, 100.0, (1.0, 1000.0), "spring"),
                  Parameter(c, DAMPING, 2.0, (0.1, 20.0), "damper"),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"))
    coordinates = (Coordinate(x, LENGTH, (-1.0, 1.0), (-2.0, 2.0), "position of the base"),
                   Coordinate(u, LENGTH, (-0.2, 0.2), (-1.0, 1.0), "block relative to the base"))
    reactions = (Reaction("N", FORCE, "base on block, up"),
                 Reaction("Nf", FORCE, "floor on base, up"))
    inputs = (Input(F, FORCE, "push on the base", history=5 * sp.sin(4 * t)),)

    def newton_euler(self):
        O = Frame.ground("O")
        o = Point.origin(O, "O")
        B = o.locate("B", x * O.x)
        base = Particle("base", M, B)
        block = Particle("block", m, B.locate("b", u * O.x))
        ne = NewtonEuler("newton_euler", coordinates=[x, u], ground=O)
        ne.gravity(-g * O.y)
        ne.force("push", base, F * O.x)
        ne.linear_spring("spring", block, k, u, O.x, against=base)
        ne.linear_damper("damper", block, c, rate(u), O.x, against=base)
        ne.reaction("N", block, O.y, against=base)
        ne.reaction("Nf", base, O.y)
        ne.linear_momentum(block, O.x)
        ne.linear_momentum(block, O.y)
        ne.linear_momentum(base, O.x)
        ne.linear_momentum(base, O.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, u])
        lg.kinetic("T of base", M * rate(x)**2 / 2)
        lg.kinetic("T of block", m * (rate(x) + rate(u))**2 / 2)
        lg.potential("spring", k * u**2 / 2)
        lg.dissipation("damper", c * rate(u)**2 / 2)
        lg.generalized_force("push", [F, 0])
        return lg.equations()


PROBLEMS = (PushedBaseDamper,)
