"""A block on a rough floor tied to a wall by a spring, Coulomb friction written with sign()."""
import sympy as sp
from dualmech import (Frame, Lagrangian, NewtonEuler, Particle, Point, Problem, Parameter,
                      Coordinate, Reaction, coordinate, rate, MASS, LENGTH, ACCELERATION,
                      STIFFNESS, FORCE, DIMENSIONLESS)

m, k, g, mu = sp.symbols("m k g mu", positive=True)
x = coordinate("x")
O = Frame.ground("O")
block = Particle("block", m, Point.origin(O).locate("B", x * O.x))


class SlidingBlock(Problem):
    name, title, source = "sliding_block", "Block on a rough floor", "my notes: example 2"
    parameters = (Parameter(m, MASS, 1, (0.1, 10)), Parameter(k, STIFFNESS, 10, (1, 100)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)),
                  Parameter(mu, DIMENSIONLESS, 0.3, (0.01, 1)))
    coordinates = (Coordinate(x, LENGTH, (-1, 1)),)
    reactions = (Reaction("N", FORCE, "floor on block, up"),)

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[x], ground=O)
        ne.gravity(-g * O.y)
        N = ne.reaction("N", block, O.y)
        ne.force("spring", block, -k * x * O.x)
        ne.force("friction", block, -mu * N * sp.sign(rate(x)) * O.x)  # <- error
        ne.linear_momentum(block, O.x)
        ne.linear_momentum(block, O.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[x])
        lg.kinetic_of(block, O)
        lg.potential("spring", k * x**2 / 2)
        lg.generalized_force("friction", [-mu * m * g * sp.sign(rate(x))])
        return lg.equations()
