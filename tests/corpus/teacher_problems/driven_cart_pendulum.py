"""A teacher's driven cart pendulum: a cart pushed by F(t) on a smooth rail carries a uniform
rod hinged at its centre-top P, turned by a motor torque tau(t) at the pivot, and the rod's
tip feels a given wind force Fx(t) O.x + Fy(t) O.y.

::

        F(t) -->  [   cart M   ]         x: cart position;  theta: rod from the downward
        =========[=====o P=====]=====        vertical, counter-clockwise;  tau(t): motor on
                        \\ theta               the rod, about O.z
                         \\ rod m, length L
                          o tip  ---> Fx(t) O.x + Fy(t) O.y (wind)

Frames: O inertial (x right, y up), B turned by theta about O.z; the rod lies along -B.y.
Free-body diagrams: cart: -M g O.y, N O.y (rail), F O.x, -R (rod on cart at P);
rod: -m g O.y at G, R = Rx O.x + Ry O.y at P (cart on rod), tau O.z, wind at the tip.
"""
import sympy as sp
from dualmech import (Frame, Input, Lagrangian, NewtonEuler, Particle, Point, Problem,
                      Parameter, Coordinate, Reaction, RigidBody, coordinate, rot_z, thin_rod,
                      t, MASS, LENGTH, FORCE, TORQUE, ACCELERATION, ANGLE)

M, m, L, g = sp.symbols("M m L g", positive=True)
F, tau, Fx, Fy = sp.symbols("F tau F_x F_y", real=True)
x, theta = coordinate("x"), coordinate("theta")
O = Frame.ground("O")
B = O.child("B", rot_z(theta))
P = Point.origin(O).locate("P", x * O.x)
G = P.locate("G", -L / 2 * B.y)
tip = P.locate("tip", -L * B.y)
cart = Particle("cart", M, P)
rod = RigidBody("rod", m, G, B, thin_rod(m, L, axis="y"))
wind = Fx * O.x + Fy * O.y


class DrivenCartPendulum(Problem):
    name, title, source = ("driven_cart_pendulum", "Cart pendulum with a push, a motor and wind",
                           "my notes: ex. 7")
    parameters = (Parameter(M, MASS, 2, (0.5, 10)), Parameter(m, MASS, 0.5, (0.1, 5)),
                  Parameter(L, LENGTH, 0.8, (0.2, 2)), Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(x, LENGTH, (-1, 1)), Coordinate(theta, ANGLE, (-1.2, 1.3)))
    reactions = (Reaction("N", FORCE, "rail on cart, up"),
                 Reaction("R_x", FORCE, "cart on rod at P, along O.x"),
                 Reaction("R_y", FORCE, "cart on rod at P, along O.y"))
    inputs = (Input(F, FORCE, "push on the cart", 2 * sp.sin(3 * t)),
              Input(tau, TORQUE, "motor torque on the rod at the pivot", sp.Rational(1, 2)),
              Input(Fx, FORCE, "wind on the tip, along O.x", sp.Rational(3, 10) * t),
              Input(Fy, FORCE, "wind on the tip, along O.y", -sp.Rational(1, 5)))
    initial_state = {x: 0.0, theta: 0.3}

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[x, theta], ground=O)
        ne.gravity(-g * O.y)
        ne.force("push", cart, F * O.x)
        ne.torque("motor", rod, tau * O.z)
        ne.force("wind", rod, wind, at=tip)
        ne.reaction("N", cart, O.y)
        ne.reaction_vector("R", rod, O, "xy", at=P, against=cart, against_at=P)
        ne.linear_momentum(cart, O.x)
        ne.linear_momentum(cart, O.y)
        ne.linear_momentum(rod, O.x)
        ne.linear_momentum(rod, O.y)
        ne.angular_momentum(rod, O.z)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[x, theta])
        lg.kinetic_of(cart, O)
        lg.kinetic_of(rod, O)
        lg.gravity(-g * O.y, [rod], O)
        lg.force_at("push", F * O.x, P, O)
        lg.torque_on("motor", tau * O.z, B, O)
        lg.force_at("wind", wind, tip, O)
        return lg.equations()


PROBLEMS = (DrivenCartPendulum,)
