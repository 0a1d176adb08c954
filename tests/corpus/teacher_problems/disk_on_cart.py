r"""A disk rolling without slipping on a cart that a spring holds to a wall -- a teacher's own
problem.

Sign convention::

                    ( C )  disk m, radius r       O.x right, O.y up, O.z out of the page.
        |/\/\/\/ +----P-------+                   x: the cart's position (spring k to the
        |   k    |   cart M   |                   wall unstretched at x = 0).  s: the disk's
        |        o------------o                   centre C ahead of the cart's reference
                                                  point, so C = (x + s, r) above the deck.

The disk (I_C = m r^2/2) rolls on the deck without slipping: its contact point P has the
cart's velocity, x' + s' + r phi' = x' with phi its turn about O.z, so phi = -s/r.  The deck
pushes the disk up with ``N`` and along O.x with the friction ``F``; the floor pushes the cart
up with ``N_f`` (smooth floor).

Direct form (by hand)::

    disk O.x:  F = m (x'' + s'')             cart O.x:  -k x - F = M x''
    disk O.y:  N - m g = 0                   cart O.y:  N_f - N - M g = 0
    disk C:    (-r O.y) x (F O.x) = r F O.z = I_C phi'' = -(m r/2) s''

Lagrangian (by hand)::

    T = M x'^2/2 + m (x' + s')^2/2 + (m r^2/2) (s'/r)^2/2,    V = k x^2/2
    x:  (M + m) x'' + m s'' + k x = 0
    s:  m x'' + (3/2) m s'' = 0

so s'' = -2 x''/3, (M + m/3) x'' + k x = 0 (printed below), F = m x''/3 and
N_f = (M + m) g: the cart's weight is only in the floor's push.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, FORCE, LENGTH, MASS, STIFFNESS, Coordinate, Frame,
                      Lagrangian, NewtonEuler, Parameter, Particle, Point, Problem, Published,
                      Reaction, RigidBody, SteadyMotion, coordinate, rate, rot_z, thin_disk)

M, m, r, k, g = sp.symbols("M m r k g", positive=True)
x, s = coordinate("x"), coordinate("s")


class _Scene:
    def __init__(self):
        self.O = Frame.ground("O")
        o = Point.origin(self.O)
        self.deck = o.locate("D", x * self.O.x)
        self.cart = Particle("cart", M, self.deck)
        self.C = self.deck.locate("C", s * self.O.x + r * self.O.y)
        self.P = self.C.locate("P", -r * self.O.y)
        self.disk = RigidBody("disk", m, self.C, self.O.child("disk", rot_z(-s / r)),
                              thin_disk(m, r))


class DiskOnCart(Problem):
    name = "disk_on_cart"
    title = "Disk rolling on a cart held by a spring"
    source = "my notes: rolling, ex. 6"
    parameters = (Parameter(M, MASS, 3.0, (0.5, 10.0)), Parameter(m, MASS, 1.0, (0.1, 5.0)),
                  Parameter(r, LENGTH, 0.1, (0.02, 0.5)), Parameter(k, STIFFNESS, 50, (1, 500)),
                  Parameter(g, ACCELERATION, 9.81, (1.0, 20.0)))
    coordinates = (Coordinate(x, LENGTH, (-0.2, 0.2)), Coordinate(s, LENGTH, (-0.5, 0.5)))
    reactions = (Reaction("N", FORCE, "deck on disk, up"),
                 Reaction("F", FORCE, "friction, deck on disk, along O.x"),
                 Reaction("N_f", FORCE, "floor on cart, up"))
    unilateral = {"N": "the disk hops off the deck", "N_f": "the cart lifts off"}
    initial_state = {x: 0.1, s: 0.0}
    steady_motion = SteadyMotion({x: 0, s: 0}, "k", (1, 500, 5), "the cart at rest, spring slack")

    def loads(self, ne, sc):
        ne.gravity(-g * sc.O.y)
        ne.linear_spring("spring", sc.cart, k, x, sc.O.x)
        ne.reaction("N", sc.disk, sc.O.y, at=sc.P, against=sc.cart)
        ne.reaction("F", sc.disk, sc.O.x, at=sc.P, against=sc.cart)
        ne.reaction("N_f", sc.cart, sc.O.y)

    def balances(self, ne, sc):
        ne.linear_momentum(sc.disk, sc.O.x)
        ne.linear_momentum(sc.disk, sc.O.y)
        ne.angular_momentum(sc.disk, sc.O.z)
        ne.linear_momentum(sc.cart, sc.O.x)
        ne.linear_momentum(sc.cart, sc.O.y)

    def newton_euler(self):
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x, s], ground=sc.O)
        self.loads(ne, sc)
        self.balances(ne, sc)
        return ne.equations()

    def kinetic(self, lg):
        lg.kinetic("T of cart", M * rate(x)**2 / 2)
        lg.kinetic("T of disk", m * (rate(x) + rate(s))**2 / 2 + m * r**2 / 4 * (rate(s) / r)**2)

    def lagrange(self):
        lg = Lagrangian("lagrange", coordinates=[x, s])
        self.kinetic(lg)
        lg.potential("spring", k * x**2 / 2)
        return lg.equations()

    def published(self):
        return [Published("cart's equation", "equation",
                          ((M + m / 3) * rate(x, 2) + k * x,), where="my notes, (6.3)"),
                Published("friction", "equation",
                          (sp.Symbol("F", real=True) - m * rate(x, 2) / 3,),
                          where="my notes, (6.4)")]


PROBLEMS = (DiskOnCart,)
