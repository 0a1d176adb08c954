r"""A uniform rod hanging from a pin on a pushed cart -- a teacher's file, outside the catalogue.

Sign convention::

        F -->  +-----------+          O.x right, O.y up, O.z out of the page
               |  cart M   |          x: position of the cart (and of the pin)
               +-----o-----+          theta: rod angle from the downward vertical,
                      \               counterclockwise about O.z
                       \  rod m, length l, centre G at l/2 from the pin
                        \

Direct form: cart along O.x (F and the pin's force); rod along O.x, O.y and about its centre
G (Euler's equation, I_G = m l^2/12), the pin force ``R`` unknown.  Lagrangian (by hand)::

    T = M x'^2/2 + m (x'^2 + l x' th' cos th + l^2 th'^2/4)/2 + m l^2 th'^2/24
    V = -m g (l/2) cos th,     Q = (F, 0)

``MISTAKES`` lists variants that each inject one mistake, with what a diagnosis must name:
the quantity (a body's T, a load's V or virtual work, a row of a balance) and the term (the
hand derivation of the difference, in the variant's docstring).
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ANGLE, ACCELERATION, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Particle, Point, Problem, RigidBody, coordinate,
                      rate, rot_z, thin_rod)

M, m, l, g, F = sp.symbols("M m l g F", positive=True)
x, theta = coordinate("x"), coordinate("theta")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        self.rodf = self.O.child("rod", rot_z(theta))
        self.pin = Point.origin(self.O).locate("pin", x * self.O.x)
        self.G = self.pin.locate("G", -l / 2 * self.rodf.y)
        self.cart = Particle("cart", M, self.pin)
        self.rod = RigidBody("rod", m, self.G, self.rodf, thin_rod(m, l, axis="y"))


class CartRod(Problem):
    name = "teacher_cart_rod"
    title = "Uniform rod pinned to a pushed cart"
    source = "teacher's own problem (test corpus)"
    parameters = (Parameter(M, MASS, 2.0, (0.5, 5.0)), Parameter(m, MASS, 1.0, (0.2, 3.0)),
                  Parameter(l, LENGTH, 0.8, (0.2, 2.0)), Parameter(g, ACCELERATION, 9.81, (1, 20)),
                  Parameter(F, FORCE, 3.0, (0.1, 20.0)))
    coordinates = (Coordinate(x, LENGTH, (-0.4, 0.4), (-1.0, 1.0)),
                   Coordinate(theta, ANGLE, (-1.2, 1.2), (-2.0, 2.0)))
    from dualmech import Reaction as _R
    reactions = (_R("R_x", FORCE, "pin on rod along O.x"), _R("R_y", FORCE, "pin on rod, O.y"))

    def balances(self, ne, sc):
        ne.linear_momentum(sc.cart, sc.O.x)
        ne.linear_momentum(sc.rod, sc.O.x)
        ne.linear_momentum(sc.rod, sc.O.y)
        ne.angular_momentum(sc.rod, sc.O.z)

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.force("F on cart", sc.cart, F * sc.O.x)
        ne.reaction_vector("R", sc.rod, sc.O, "xy", at=sc.pin, against=sc.cart)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x, theta], ground=sc.O)
        self.loads(ne, sc)
        self.balances(ne, sc)
        return ne.equations()

    def kinetic(self, lg):
        c = sp.cos(theta)
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of rod", m * (rate(x)**2 + l * rate(x) * rate(theta) * c
                                    + l**2 * rate(theta)**2 / 4) / 2
                   + m * l**2 * rate(theta)**2 / 24)

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, theta])
        self.kinetic(lg)
        lg.potential("gravity", -m * g * l / 2 * sp.cos(theta))
        lg.generalized_force("F on cart", [F, 0])
        return lg.equations()


class NoTransportTerm(CartRod):
    """T of the rod written as if the pin were fixed: the term m l x' th' cos th / 2 is
    missing."""

    def kinetic(self, lg):
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of rod", m * (rate(x)**2 + l**2 * rate(theta)**2 / 4) / 2
                   + m * l**2 * rate(theta)**2 / 24)


class InertiaAboutTheEnd(CartRod):
    """I_G taken as m l^2/3 (the inertia about the end): the th'^2 coefficient of T of rod
    is m l^2/8 + m l^2/6 = 7 m l^2/24 where m l^2/6 belongs."""

    def kinetic(self, lg):
        c = sp.cos(theta)
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of rod", m * (rate(x)**2 + l * rate(x) * rate(theta) * c
                                    + l**2 * rate(theta)**2 / 4) / 2
                   + m * l**2 * rate(theta)**2 / 6)


class PushReversed(CartRod):
    """The direct form pushes the cart with -F: its virtual work is -F dx where the
    Lagrangian has F dx."""

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.force("F on cart", sc.cart, -F * sc.O.x)
        ne.reaction_vector("R", sc.rod, sc.O, "xy", at=sc.pin, against=sc.cart)


class MomentAboutMovingPin(CartRod):
    """The rod's moments taken about the pin as if it were fixed:
    ``-m g (l/2) sin th - (m l^2/3) th'' = 0``; about the moving pin the term
    ``-m (l/2) cos th x''`` (``-m (r_pin,G x a_pin) . k``) is missing."""

    def balances(self, ne, sc):
        ne.linear_momentum(sc.cart, sc.O.x)
        ne.linear_momentum(sc.rod, sc.O.x)
        ne.linear_momentum(sc.rod, sc.O.y)
        ne.equation("sum tau_pin . O.z (rod), pin taken as fixed",
                    {"gravity on rod": -m * g * l / 2 * sp.sin(theta),
                     "inertia of rod": -m * l**2 / 3 * rate(theta, 2)})


#: (variant, the quantity named, a term of the edit (either side), hand-derived)
MISTAKES = [
    (NoTransportTerm, "T of rod", m * l * rate(x) * rate(theta) * sp.cos(theta) / 2),
    (InertiaAboutTheEnd, "T of rod", m * l**2 * rate(theta)**2 / 6),
    (PushReversed, "F on cart", F * sp.Symbol("δx", real=True)),
    (MomentAboutMovingPin, "pin taken as fixed", m * l / 2 * sp.cos(theta) * rate(x, 2)),
]
