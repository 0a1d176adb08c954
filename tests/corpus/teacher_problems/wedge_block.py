r"""A block sliding down a smooth wedge that is free to slide on a smooth floor, the wedge
pushed by a given force F(t) -- a teacher's own problem, written from the README alone.

Sign convention::

            O.y                        O.x right, O.y up.  The wedge (mass M) slides on the
             |   block m               floor, its position X along O.x; its face makes the
             |  \\  /e (down the face)  angle alpha with the floor, falling to the right.
             |   \\/                   The block (mass m) slides on that face: s is its
             |   /\\ alpha             distance down the face, along e = I.x, where I is O
             |  /  \\                  turned by -alpha; n = I.y is the face's outward
    F(t) --> | / M  \\                 normal.
    =========+========================= O.x  (floor)

Free-body diagrams: block: -m g O.y, N n (face on block); wedge: -M g O.y, -N n (block on
face), N_f O.y (floor), F O.x.  By hand, a_block = X'' O.x + s'' e, and along e and n::

    X:  (M + m) X'' + m cos(alpha) s'' = F
    s:  m s'' + m cos(alpha) X'' - m g sin(alpha) = 0
    N   = m g cos(alpha) + m sin(alpha) X''
        = m (M g cos(alpha) + F sin(alpha)) / (M + m sin(alpha)^2)
    N_f = M g + N cos(alpha)

Lagrangian (by hand): T = M X'^2/2 + m (X'^2 + 2 cos(alpha) X' s' + s'^2)/2,
V = -m g s sin(alpha), Q_X = F, Q_s = 0.
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ACCELERATION, ANGLE, FORCE, LENGTH, MASS, Coordinate, Frame, Input,
                      Lagrangian, NewtonEuler, Parameter, Particle, Point, Problem, Published,
                      Reaction, coordinate, rate, rot_z, t)

m, M, g, alpha = sp.symbols("m M g alpha", positive=True)
F = sp.Symbol("F", real=True)
X, s = coordinate("X"), coordinate("s")

O = Frame.ground("O")
I = O.child("I", rot_z(-alpha))            # I.x = e down the face, I.y = n its normal
W = Point.origin(O).locate("W", X * O.x)   # the wedge's mass centre (it only translates)
B = W.locate("B", s * I.x)                 # the block on the face
wedge = Particle("wedge", M, W)
block = Particle("block", m, B)


class WedgeBlock(Problem):
    name, title, source = ("wedge_block", "Block sliding on a free wedge pushed by F(t)",
                           "my notes: ex. 9")
    parameters = (Parameter(m, MASS, 1, (0.1, 5)), Parameter(M, MASS, 3, (0.5, 10)),
                  Parameter(alpha, ANGLE, 0.5, (0.2, 1.2)),
                  Parameter(g, ACCELERATION, 9.81, (1, 20)))
    coordinates = (Coordinate(X, LENGTH, (-1, 1), (-2, 2), "wedge position"),
                   Coordinate(s, LENGTH, (-0.5, 0.8), (-2, 2), "block down the face"))
    reactions = (Reaction("N", FORCE, "face on block, along n = I.y"),
                 Reaction("N_f", FORCE, "floor on wedge, up"))
    unilateral = {"N": "the block leaves the face"}
    inputs = (Input(F, FORCE, "push on the wedge, along O.x", sp.sin(2 * t) / 2),)
    initial_state = {X: 0.0, s: 0.0}

    def newton_euler(self):
        ne = NewtonEuler(coordinates=[X, s], ground=O)
        ne.gravity(-g * O.y)
        ne.force("push", wedge, F * O.x)
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
        lg.kinetic("T of block", m * (rate(X)**2 + 2 * sp.cos(alpha) * rate(X) * rate(s)
                                      + rate(s)**2) / 2)
        lg.potential("gravity", -m * g * s * sp.sin(alpha))
        lg.generalized_force("push", [F, 0])
        return lg.equations()

    def published(self):
        N = sp.Symbol("N", real=True)
        ca, sa = sp.cos(alpha), sp.sin(alpha)
        return [
            Published("equations of motion", "motion",
                      ((M + m) * rate(X, 2) + m * ca * rate(s, 2) - F,
                       rate(s, 2) + ca * rate(X, 2) - g * sa), where="my notes, (9.1)"),
            Published("normal force", "equation",
                      (N - m * (M * g * ca + F * sa) / (M + m * sa**2),),
                      where="my notes, (9.3)"),
        ]


PROBLEMS = (WedgeBlock,)
