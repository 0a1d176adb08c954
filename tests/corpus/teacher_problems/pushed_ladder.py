r"""A teacher's ladder whose foot is pulled away from the wall by a given force F(t): a uniform
rod (mass m, length L) against a smooth wall (x = 0) on a smooth floor (y = 0), released
from rest at theta = 0.3 from the wall while a rope at its foot pulls along +x.

Sign convention::

      O.y
       |  top
       |\      theta: the ladder's angle from the wall
       | \     C: its centre, (L/2 sin theta, L/2 cos theta) on the wall
       |  \ C
       |   \
       |    \ bottom ---> F(t)
    ===+=========================== O.x (floor)

Phase 1, on wall and floor (one coordinate theta): the wall pushes N_w along +x at the top,
the floor N_f up at the bottom, the rope F(t) along +x at the bottom.  By hand::

    m L^2/3 theta'' = m g L/2 sin(theta) + F L cos(theta)    (Lagrange, Q = F L cos(theta))
    N_w = m x_C'' - F,  x_C = L/2 sin(theta)

Phase 2, after N_w reaches zero: the ladder slides on the floor alone, its centre's
horizontal position x free, its height L/2 cos(theta); the foot at x + L/2 sin(theta), so
Q_x = F, Q_theta = F L/2 cos(theta).  The same rope pulls on through the switch.
"""
import sympy as sp
from dualmech import (Coordinate, Frame, Input, Lagrangian, NewtonEuler, Parameter, Phase,
                      Point, Problem, Reaction, RigidBody, coordinate, rate, rot_z, t,
                      thin_rod, ACCELERATION, ANGLE, FORCE, LENGTH, MASS)

m, L, g, P = sp.symbols("m L g P", positive=True)
F = sp.Symbol("F", real=True)
theta, x = coordinate("theta"), coordinate("x")
PARAMETERS = (Parameter(m, MASS, 10, (0.1, 100), "mass of the ladder"),
              Parameter(L, LENGTH, 4, (0.5, 10), "length of the ladder"),
              Parameter(g, ACCELERATION, 9.81, (1, 20)),
              Parameter(P, FORCE, 8, (0, 100), "the rope's mean pull"))
ROPE = (Input(F, FORCE, "rope on the foot, along +x", P * (1 - sp.cos(3 * t))),)
# the model holds while the ladder stands: 0 < theta < pi/2 (at pi/2 its top hits the floor)
ANGLE_ = Coordinate(theta, ANGLE, (0.05, 1.5), (-5, 5), "ladder from the wall",
                    domain=(0.0, float(sp.pi / 2)))


def ladder(centre):
    """The ground, the ladder's frame and body, its top and its bottom."""
    O = Frame.ground("O")
    B = O.child("B", rot_z(theta))              # B.y: from the bottom to the top
    C = Point.origin(O, "O").locate("C", centre(O))
    rod = RigidBody("ladder", m, C, B, thin_rod(m, L, axis="y"))
    return O, B, rod, C.locate("top", L / 2 * B.y), C.locate("bottom", -L / 2 * B.y)


def balances(ne, O, B, rod, bottom):
    ne.force("rope", rod, F * O.x, at=bottom)
    ne.linear_momentum(rod, O.x)
    ne.linear_momentum(rod, O.y)
    ne.angular_momentum(rod, B.z)
    return ne.equations()


class PulledFreeLadder(Problem):
    name, title, source = ("pulled_free_ladder", "Ladder pulled along a smooth floor",
                           "my notes: ex. 9d")
    parameters = PARAMETERS
    coordinates = (Coordinate(x, LENGTH, (-10, 10), (-20, 20), "centre, horizontally"), ANGLE_)
    reactions = (Reaction("N_f", FORCE, "floor on the bottom, up"),)
    unilateral = {"N_f": "the ladder leaves the floor"}
    inputs = ROPE

    def newton_euler(self):
        O, B, rod, top, bottom = ladder(lambda O: x * O.x + L / 2 * sp.cos(theta) * O.y)
        ne = NewtonEuler(coordinates=[x, theta], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("N_f", rod, O.y, at=bottom)
        return balances(ne, O, B, rod, bottom)

    def lagrange(self):
        lg = Lagrangian(coordinates=[x, theta])
        lg.kinetic("translation", m * (rate(x)**2 + (L / 2 * sp.sin(theta) * rate(theta))**2) / 2)
        lg.kinetic("rotation", m * L**2 / 12 * rate(theta)**2 / 2)
        lg.potential("gravity", m * g * L / 2 * sp.cos(theta))
        lg.generalized_force("rope", [F, F * L / 2 * sp.cos(theta)])
        return lg.equations()


class PulledWallLadder(Problem):
    name, title, source = ("pulled_wall_ladder", "Ladder on a smooth wall, its foot pulled",
                           "my notes: ex. 9c")
    parameters = PARAMETERS
    coordinates = (ANGLE_,)
    reactions = (Reaction("N_w", FORCE, "wall on the top, along +x"),
                 Reaction("N_f", FORCE, "floor on the bottom, up"))
    unilateral = {"N_w": "the ladder leaves the wall", "N_f": "the ladder leaves the floor"}
    inputs = ROPE
    phases = {"N_w": Phase(PulledFreeLadder, {x: L / 2 * sp.sin(theta), theta: theta},
                           "the ladder leaves the wall and slides on the floor alone")}
    initial_state = {theta: 0.3}

    def newton_euler(self):
        O, B, rod, top, bottom = ladder(lambda O: L / 2 * (sp.sin(theta) * O.x
                                                          + sp.cos(theta) * O.y))
        ne = NewtonEuler(coordinates=[theta], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("N_w", rod, O.x, at=top)
        ne.reaction("N_f", rod, O.y, at=bottom)
        return balances(ne, O, B, rod, bottom)

    def lagrange(self):
        lg = Lagrangian(coordinates=[theta])
        lg.kinetic("T", m * L**2 / 6 * rate(theta)**2)
        lg.potential("gravity", m * g * L / 2 * sp.cos(theta))
        lg.generalized_force("rope", [F * L * sp.cos(theta)])
        return lg.equations()


PROBLEMS = (PulledWallLadder, PulledFreeLadder)
