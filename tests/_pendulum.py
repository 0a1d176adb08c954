"""A plane pendulum written three ways, for testing the comparator on a problem we derive here.

Hand derivation (bob m on a massless rod l, theta from the downward vertical, rod tension S
pulling the bob towards the pivot):
    m l theta'' + m g sin(theta) = 0,        S = m g cos(theta) + m l theta'^2.
In Cartesian coordinates (x, y) of the bob with the constraint x^2 + y^2 = l^2 and multiplier
lam: m x'' = 2 lam x, m y'' = 2 lam y - m g  (lam = -S / (2 l)).
"""
import sympy as sp

from dualmech import Frame, Lagrangian, NewtonEuler, Particle, Point, coordinate, rot_z, t
from dualmech.model.dimensions import ACCELERATION, ANGLE, FORCE, LENGTH, MASS
from dualmech.model.problem import Coordinate, Parameter, Problem, Published, Reaction

m, l, g = sp.symbols("m l g", positive=True)
th = coordinate("theta")
r = coordinate("r")


class Pendulum(Problem):
    name, title, source = "pendulum", "Simple pendulum", "tests (hand derivation)"
    parameters = (Parameter(m, MASS, 1, (0.1, 5)), Parameter(l, LENGTH, 1, (0.2, 3)),
                  Parameter(g, ACCELERATION, sp.Rational(981, 100), (1, 20)))
    coordinates = (Coordinate(th, ANGLE, (-2.5, 2.5), (-3, 3)),)
    reactions = (Reaction("S", FORCE, "rod tension, towards the pivot"),)
    extra_models = ("multiplier",)
    extra_coordinates = (Coordinate(r, LENGTH, (0.2, 3), (-1, 1)),)

    def coordinate_maps(self):
        return {"multiplier": {th: th, r: l}}

    def multiplier(self):
        """Polar coordinates (theta, r) with the constraint l - r = 0; its multiplier is S.

        Generalised force of the tension S (along -e_r) on r is -S; the constraint adds
        lam * d(l - r)/dr = -lam, so lam = S.
        """
        lg = Lagrangian("multiplier", coordinates=[th, r])
        lg.kinetic("T", m * (r.diff(t)**2 + r**2 * th.diff(t)**2) / 2)
        lg.potential("gravity", -m * g * r * sp.cos(th))
        lg.constraint("S", l - r)
        return lg.equations()

    def newton_euler(self):
        O = Frame.ground()
        A = O.child("A", rot_z(th))           # A.y points from the bob up to the pivot
        bob = Particle("bob", m, Point.origin(O).locate("bob", -l * A.y))
        ne = NewtonEuler(coordinates=[th], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("S", bob, A.y)
        ne.linear_momentum(bob, A.x)
        ne.linear_momentum(bob, A.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[th])
        lg.kinetic("T", m * l**2 * th.diff(t)**2 / 2)
        lg.potential("gravity", -m * g * l * sp.cos(th))
        return lg.equations()

    def published(self):
        return [
            Published("EoM", "equation", [l * th.diff(t, 2) + g * sp.sin(th)]),
            Published("tension", "expression", [m * g * sp.cos(th) + m * l * th.diff(t)**2],
                      [sp.Symbol("S", real=True)]),
            Published("wrong tension", "expression", [m * g * sp.cos(th)],
                      [sp.Symbol("S", real=True)]),
            Published("small-angle EoM", "equation", [l * th.diff(t, 2) + g * th]),
            Published("dimension slip", "equation", [l * th.diff(t, 2) + g * l * sp.sin(th)]),
        ]


x, y = coordinate("x"), coordinate("y")


def cartesian():
    """The pendulum in maximal coordinates with a multiplier (an index-3 DAE)."""
    lg = Lagrangian("cartesian", coordinates=[x, y])
    lg.kinetic("T", m * (x.diff(t)**2 + y.diff(t)**2) / 2)
    lg.potential("gravity", m * g * y)
    lg.constraint("lam", x**2 + y**2 - l**2)
    return lg.equations()
