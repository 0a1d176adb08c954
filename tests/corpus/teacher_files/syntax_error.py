"""A pendulum file with a bracket left open (SyntaxError)."""
import sympy as sp
from dualmech import (Frame, Lagrangian, NewtonEuler, Particle, Point, Problem, Parameter,
                      Coordinate, Reaction, coordinate, rot_z, MASS, LENGTH, ACCELERATION,
                      ANGLE, FORCE)

m, l, g = sp.symbols("m l g", positive=True)
th = coordinate("theta")
O = Frame.ground("O")
arm = O.child("arm", rot_z(th))
bob = Particle("bob", m, Point.origin(O).locate("P", -l * arm.y))


class Pendulum(Problem):
    name, title, source = "my_pendulum", "Simple pendulum", "my notes: example 1"
    parameters = (Parameter(m, MASS, 1, (0.1, 10)), Parameter(l, LENGTH, 1, (0.1, 2)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(th, ANGLE, (-1, 1)),)
    reactions = (Reaction("T", FORCE, "rod on bob, towards the pivot"),)

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[th], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("T", bob, arm.y)
        ne.linear_momentum(bob, arm.x)
        ne.linear_momentum(bob, arm.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[th])
        lg.kinetic_of(bob, O  # <- error
        lg.potential("gravity", -m * g * l * sp.cos(th))
        return lg.equations()
