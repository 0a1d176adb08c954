"""A teacher's forced block: a push F(t), given only as a function of time, at 30 degrees
below the horizontal, on a block on a smooth floor held by a spring."""
import sympy as sp
from dualmech import (Frame, Input, Lagrangian, NewtonEuler, Particle, Point, Problem,
                      Parameter, Coordinate, Reaction, coordinate, MASS, LENGTH, FORCE,
                      STIFFNESS, ACCELERATION)

m, k, g = sp.symbols("m k g", positive=True)
F = sp.Symbol("F", real=True)
x = coordinate("x")
O = Frame.ground("O")
block = Particle("block", m, Point.origin(O).locate("P", x * O.x))
push = F * (sp.sqrt(3) / 2 * O.x - O.y / 2)


class ForcedBlock(Problem):
    name, title, source = "forced_block", "Block on a spring pushed by F(t)", "my notes: ex. 3"
    parameters = (Parameter(m, MASS, 2, (0.1, 10)), Parameter(k, STIFFNESS, 8, (0.1, 100)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(x, LENGTH, (-1, 1)),)
    reactions = (Reaction("N", FORCE, "floor on block, up"),)
    inputs = (Input(F, FORCE, "push on the block, 30 degrees below the horizontal"),)
    initial_state = {x: 0.0}

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[x], ground=O)
        ne.gravity(-g * O.y)
        ne.force("spring", block, -k * x * O.x)
        ne.force("push", block, push)
        ne.reaction("N", block, O.y)
        ne.linear_momentum(block, O.x)
        ne.linear_momentum(block, O.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[x])
        lg.kinetic_of(block, O)
        lg.potential("spring", k * x**2 / 2)
        lg.generalized_force("push", [sp.sqrt(3) / 2 * F])
        return lg.equations()


PROBLEMS = (ForcedBlock,)
