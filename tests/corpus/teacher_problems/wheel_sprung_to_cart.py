r"""A pushed cart pulling a wheel through a spring; the wheel rolls on the floor -- a teacher's
own problem.

Sign sketch::

        F -> +--------+                      O.x right, O.y up, O.z out of the page.
             | cart M |--/\/\/\/\--( C )     x: the cart; y: the wheel's axle C (r above the
             o--------o     k       \P/      floor); the spring k, free length L0, stretches
        ===================================  by y - x - L0.  The push F(t) acts on the cart.

The wheel (m, radius r, I_C = m r^2/2) rolls without slipping: its turn about O.z is
``-y/r``.  The floor pushes the wheel at its contact P with ``N`` (up) and the friction ``Ff``
(along O.x); the smooth floor pushes the cart up with ``Nc``.

Direct form (by hand)::

    cart O.x:   F + k (y - x - L0) = M x''          cart O.y:  Nc - M g = 0
    wheel O.x:  -k (y - x - L0) + Ff = m y''        wheel O.y: N - m g = 0
    wheel C:    r Ff = (m r^2/2) (-y''/r)

Lagrangian (by hand)::

    T = M x'^2/2 + m y'^2/2 + (m r^2/2) (y'/r)^2/2,   V = k (y - x - L0)^2/2,   Q_x = F

so ``Ff = -m y''/2``.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, FORCE, LENGTH, MASS, STIFFNESS, Coordinate, Frame, Input,
                      Lagrangian, NewtonEuler, Parameter, Particle, Point, Problem, Reaction,
                      RigidBody, coordinate, rate, rot_z, t, thin_disk)

M, m, r, k, L0, g = sp.symbols("M m r k L0 g", positive=True)
F = sp.Symbol("F", real=True)
x, y = coordinate("x"), coordinate("y")


class WheelSprungToCart(Problem):
    """A pushed cart and a rolling wheel joined by a spring."""

    name = "wheel_sprung_to_cart"
    title = "Pushed cart pulling a rolling wheel through a spring"
    source = "my notes: rolling, ex. 11"
    parameters = (Parameter(M, MASS, 2.0, (0.5, 10.0), "mass of the cart"),
                  Parameter(m, MASS, 1.0, (0.1, 5.0), "mass of the wheel"),
                  Parameter(r, LENGTH, 0.15, (0.05, 0.5), "radius of the wheel"),
                  Parameter(k, STIFFNESS, 30.0, (1.0, 300.0), "spring"),
                  Parameter(L0, LENGTH, 0.5, (0.2, 1.0), "free length of the spring"),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"))
    coordinates = (Coordinate(x, LENGTH, (-1.0, 1.0), (-2.0, 2.0), "position of the cart"),
                   Coordinate(y, LENGTH, (-0.5, 1.5), (-2.0, 2.0), "position of the axle"))
    reactions = (Reaction("N", FORCE, "floor on wheel, up"),
                 Reaction("Ff", FORCE, "friction, floor on wheel, along O.x"),
                 Reaction("Nc", FORCE, "floor on cart, up"))
    inputs = (Input(F, FORCE, "push on the cart", history=2 * sp.sin(3 * t)),)

    def newton_euler(self):
        O = Frame.ground("O")
        o = Point.origin(O, "O")
        cart = Particle("cart", M, o.locate("B", x * O.x))
        C = o.locate("C", y * O.x + r * O.y)
        P = C.locate("P", -r * O.y)
        wheel = RigidBody("wheel", m, C, O.child("wheel", rot_z(-y / r)), thin_disk(m, r))
        ne = NewtonEuler("newton_euler", coordinates=[x, y], ground=O)
        ne.gravity(-g * O.y)
        ne.force("push", cart, F * O.x)
        ne.linear_spring("spring", wheel, k, y - x - L0, O.x, against=cart)
        ne.reaction("N", wheel, O.y, at=P)
        ne.reaction("Ff", wheel, O.x, at=P)
        ne.reaction("Nc", cart, O.y)
        ne.linear_momentum(cart, O.x)
        ne.linear_momentum(cart, O.y)
        ne.linear_momentum(wheel, O.x)
        ne.linear_momentum(wheel, O.y)
        ne.angular_momentum(wheel, O.z)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, y])
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of wheel", m * rate(y)**2 / 2 + m * r**2 / 2 * (rate(y) / r)**2 / 2)
        lg.potential("spring", k * (y - x - L0)**2 / 2)
        lg.generalized_force("push", [F, 0])
        return lg.equations()


PROBLEMS = (WheelSprungToCart,)
