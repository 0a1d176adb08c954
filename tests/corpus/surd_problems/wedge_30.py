r"""A block sliding down a smooth 30-degree wedge that is free to slide on a smooth floor -- a
teacher's own problem whose models hold the surd ``cos 30 deg = sqrt(3)/2``.

Sign convention::

            O.y                        O.x right, O.y up.  The wedge (mass M) slides on the
             |   block m               floor, its position X along O.x; its face makes 30
             |  \\  /e (down the face)  degrees with the floor, falling to the right.  The
             |   \\/                   block (mass m) slides on that face: s is its distance
             |   /\\ 30 deg            down the face, along e = I.x, where I is O turned by
             |  /  \\                  -30 degrees; n = I.y is the face's outward normal.
    =========+========================= O.x  (floor)

By hand, with cos 30 = sqrt(3)/2 and sin 30 = 1/2, the block's velocity is X' O.x + s' e and
e . O.x = sqrt(3)/2, so::

    T = (M + m) X'^2/2 + (sqrt(3)/2) m X' s' + m s'^2/2,    V = -m g s/2
    X:  (M + m) X'' + (sqrt(3)/2) m s'' = 0
    s:  m s'' + (sqrt(3)/2) m X'' - m g/2 = 0
    N   = (sqrt(3)/2) m g + m X''/2        (block along n: N - m g cos 30 = m a . n)
    N_f = M g + (sqrt(3)/2) N
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, FORCE, LENGTH, MASS, Coordinate, Frame, Lagrangian,
                      NewtonEuler, Parameter, Particle, Point, Problem, Reaction, coordinate,
                      rate, rot_z)

m, M, g = sp.symbols("m M g", positive=True)
X, s = coordinate("X"), coordinate("s")

O = Frame.ground("O")
I = O.child("I", rot_z(-sp.pi / 6))        # I.x = e down the face, I.y = n its normal
W = Point.origin(O).locate("W", X * O.x)   # the wedge's mass centre (it only translates)
B = W.locate("B", s * I.x)                 # the block on the face
wedge = Particle("wedge", M, W)
block = Particle("block", m, B)


class Wedge30(Problem):
    name, title, source = ("wedge_30", "Block sliding on a free 30-degree wedge",
                           "my notes: ex. 9, alpha = 30 degrees")
    parameters = (Parameter(m, MASS, 1, (0.1, 5)), Parameter(M, MASS, 3, (0.5, 10)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(X, LENGTH, (-1, 1), (-2, 2), "wedge position"),
                   Coordinate(s, LENGTH, (-0.5, 0.8), (-2, 2), "block down the face"))
    reactions = (Reaction("N", FORCE, "face on block, along n = I.y"),
                 Reaction("N_f", FORCE, "floor on wedge, up"))
    initial_state = {X: 0.0, s: 0.0}

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[X, s], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("N", block, I.y, against=wedge, against_at=B)
        ne.reaction("N_f", wedge, O.y)
        ne.linear_momentum(block, I.x)
        ne.linear_momentum(block, I.y)
        ne.linear_momentum(wedge, O.x)
        ne.linear_momentum(wedge, O.y)
        return ne.equations()

    def lagrange(self):
        lg = Lagrangian(coordinates=[X, s])
        lg.kinetic("T of wedge", M * rate(X)**2 / 2)
        lg.kinetic("T of block", m * (rate(X)**2 + sp.sqrt(3) * rate(X) * rate(s)
                                      + rate(s)**2) / 2)
        lg.potential("gravity", -m * g * s / 2)
        return lg.equations()


PROBLEMS = (Wedge30,)
