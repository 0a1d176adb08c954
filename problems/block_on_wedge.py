"""Example 16: a block sliding without friction on a wedge that slides on the ground.

Source: ``sources/000_203248afac9714e6.txt``, "Example 16: A Block Sliding on a Wedge".

Geometry (the source's figure is missing; this is the one used here)
--------------------------------------------------------------------
::

        j (up)
        ^
        |   A = top of the incline, fixed in the wedge; heights are measured from A's level
   -----+---A-------------------------------> i     (O's origin: A at q2 = 0)
        |   |\\
        |   | \\  q1: distance of the block down the slope from A, relative to the wedge
        |   |  \\ +---+
        |   |   \\| m | --> S.y = ( sin a, cos a)   outward normal of the incline
        |   | M  \\---+
        |   |     \\      S.x = ( cos a, -sin a)   down the slope
        |   |      \\
        |   |  alpha\\ (angle of the incline with the ground, at the toe)
   =========+========+=========  ground (frictionless)
            q2: horizontal position of the wedge (of A)

The equations hold while the block is on the incline (``0 <= q1 <= `` its length).

Frames.  ``O`` inertial (``i`` right, ``j`` up), origin at the height of A.  ``W`` moves with
the wedge: ``W = O`` translated by ``q2 i`` (no rotation).  ``S`` is fixed in the wedge,
``S = W`` rotated by ``-alpha`` about ``k``, so ``S.x`` runs down the slope and ``S.y`` is
the incline's outward normal.

Bodies.  Neither body rotates, so both are particles: the block ``m`` at
``P = q2 i + q1 S.x`` and the wedge ``M`` at A (any point fixed in the wedge has the
wedge's acceleration ``q2'' i``).  The block's velocity is
``(q2' + q1' cos a) i - q1' sin a j``.

Free-body diagrams (Newton--Euler)::

        block m:   -m g j,   N1 S.y   (wedge on block, normal to the incline)
        wedge M:   -M g j,  -N1 S.y   (block on wedge),   N2 j   (ground on wedge)

        block . S.x:   m (q1'' + q2'' cos a) = m g sin a
        block . S.y:   m q2'' sin a          = N1 - m g cos a
        wedge . i  :   M q2''                = -N1 sin a
        wedge . j  :   0                     = N2 - M g - N1 cos a

Solved by hand (write ``s = sin a``, ``c = cos a``, ``Delta = M + m s^2``)::

        N1    = m M g c / Delta
        q2''  = -N1 s / M                 = -m g s c / Delta
        q1''  = g s - q2'' c              = (M + m) g s / Delta
        N2    = M g + N1 c                = M (M + m) g / Delta

(check: the whole system's vertical balance ``N2 - (M + m) g = -m q1'' s`` holds).

Lagrangian (written independently)::

        T = M q2'^2/2 + m ((q2' + q1' c)^2 + (q1' s)^2)/2,      V = -m g q1 s

        q1:  m (q1'' + q2'' c) - m g s = 0
        q2:  (M + m) q2'' + m c q1''   = 0       (horizontal momentum is conserved)

Lagrange with multipliers (the normal forces, independently of the free-body diagrams).
Give each contact a separation coordinate: ``d1`` = the block's distance off the incline
along ``S.y``, ``d2`` = the wedge's height off the ground.  Then the wedge is at
``A = q2 i + d2 j`` and the block at ``A + q1 S.x + d1 S.y``::

        T = M (q2'^2 + d2'^2)/2 + m |d/dt (A + q1 S.x + d1 S.y)|^2/2
        V = M g d2 + m g (d2 - q1 s + d1 c)
        constraints  d1 = 0  (multiplier N1),   d2 = 0  (multiplier N2)

The virtual work of ``N1 S.y`` (on the block; ``-N1 S.y`` on the wedge) is ``N1 delta d1``
and that of ``N2 j`` is ``N2 delta d2``, so with unit gradients the multipliers *are* the
normal forces.  Mapped back (``d1 = d2 = 0``) the model must give the motion and the
reactions of the direct form.

Published answers.  The source prints the accelerations explicitly,
``q1'' = g s / (1 - m c^2/(M + m))`` and ``q2'' = -m/(M + m) q1'' c``.  They are transcribed
as ``kind="expression"`` with the acceleration itself as reference: the printed formulas are
*values* of the accelerations, and the comparator replaces every acceleration (including the
``q1''`` inside the second formula) by the true one.  Both are right:
``(M + m) - m c^2 = M + m s^2 = Delta``.  No errata.

Example
-------
>>> p = BlockOnWedge(); p.validate()
>>> sp.simplify(p.model("newton_euler").reactions_solved()[sp.Symbol("N1", real=True)])
M*g*m*cos(alpha)/(M + m*sin(alpha)**2)
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_z, ACCELERATION,
                      ANGLE, FORCE, LENGTH, MASS)

__all__ = ["BlockOnWedge", "PROBLEMS", "hand_reactions", "hand_accelerations"]

m, M, g, alpha = sp.symbols("m M g alpha", positive=True)
q1, q2 = coordinate("q1"), coordinate("q2")
d1, d2 = coordinate("d1"), coordinate("d2")


def _delta():
    return M + m * sp.sin(alpha)**2


def hand_accelerations() -> dict:
    """``{q1'': ..., q2'': ...}`` solved by hand (see the module docstring)."""
    s, c = sp.sin(alpha), sp.cos(alpha)
    return {rate(q1, 2): (M + m) * g * s / _delta(), rate(q2, 2): -m * g * s * c / _delta()}


def hand_reactions() -> dict:
    """``{"N1": ..., "N2": ...}`` solved by hand (see the module docstring)."""
    return {"N1": m * M * g * sp.cos(alpha) / _delta(), "N2": M * (M + m) * g / _delta()}


class _Scene:
    """Frames, points and particles of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.W = self.O.child("W", origin=q2 * self.O.x)
        self.S = self.W.child("S", rot_z(-alpha))
        self.A = Point.origin(self.W, "A")
        self.P = self.A.locate("P", q1 * self.S.x)
        self.block = Particle("block", m, self.P)
        self.wedge = Particle("wedge", M, self.A)


class BlockOnWedge(Problem):
    """Block ``m`` on the frictionless incline (angle ``alpha``) of a free wedge ``M``."""

    name = "block_on_wedge"
    title = "Block sliding on a free wedge"
    source = "000_203248afac9714e6.txt: Example 16"
    summary = ("Two particles, two unknown normal forces; the printed accelerations are right "
               "and the direct form adds the normal forces.")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 5.0), "mass of the block"),
        Parameter(M, MASS, 3.0, (0.5, 10.0), "mass of the wedge"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
        Parameter(alpha, ANGLE, 0.6, (0.1, 1.4), "angle of the incline"),
    )
    coordinates = (
        Coordinate(q1, LENGTH, (0.0, 2.0), (-1.0, 3.0),
                   "distance of the block down the slope, relative to the wedge"),
        Coordinate(q2, LENGTH, (-1.0, 1.0), (-2.0, 1.0), "horizontal position of the wedge"),
    )
    extra_coordinates = (
        Coordinate(d1, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "separation of block and incline"),
        Coordinate(d2, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "height of the wedge off the ground"),
    )
    reactions = (
        Reaction("N1", FORCE, "wedge on block, along the incline's outward normal S.y"),
        Reaction("N2", FORCE, "ground on wedge, along j"),
    )
    extra_models = ("lagrange_multipliers",)
    unilateral = {"N1": "the block lifts off the incline",
                  "N2": "the wedge lifts off the ground"}

    def newton_euler(self) -> EquationSet:
        """Block along the slope and its normal; wedge along ``i`` and ``j``."""
        sc = _Scene()
        O, S = sc.O, sc.S
        ne = NewtonEuler("newton_euler", coordinates=[q1, q2], ground=O)
        ne.gravity(-g * O.y)
        ne.reaction("N1", sc.block, S.y, against=sc.wedge)
        ne.reaction("N2", sc.wedge, O.y)
        ne.linear_momentum(sc.block, S.x)
        ne.linear_momentum(sc.block, S.y)
        ne.linear_momentum(sc.wedge, O.x)
        ne.linear_momentum(sc.wedge, O.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` as the source writes them."""
        s, c = sp.sin(alpha), sp.cos(alpha)
        lg = Lagrangian("lagrange", coordinates=[q1, q2])
        lg.kinetic("T of wedge", M * rate(q2)**2 / 2)
        lg.kinetic("T of block", m * ((rate(q2) + rate(q1) * c)**2 + (rate(q1) * s)**2) / 2)
        lg.potential("gravity", -m * g * q1 * s)
        return lg.equations()

    def lagrange_multipliers(self) -> EquationSet:
        """Separations ``d1``, ``d2`` held at zero by the multipliers ``N1``, ``N2``."""
        s, c = sp.sin(alpha), sp.cos(alpha)
        wedge = sp.Matrix([q2, d2])
        block = wedge + q1 * sp.Matrix([c, -s]) + d1 * sp.Matrix([s, c])
        lg = Lagrangian("lagrange_multipliers", coordinates=[q1, q2, d1, d2])
        lg.kinetic("T of wedge", M * (rate(wedge).T * rate(wedge))[0, 0] / 2)
        lg.kinetic("T of block", m * (rate(block).T * rate(block))[0, 0] / 2)
        lg.potential("gravity", M * g * wedge[1] + m * g * block[1])
        lg.constraint("N1", d1)
        lg.constraint("N2", d2)
        return lg.equations()

    def coordinate_maps(self) -> dict:
        return {"lagrange_multipliers": {q1: q1, q2: q2, d1: 0, d2: 0}}

    def published(self) -> list[Published]:
        s, c = sp.sin(alpha), sp.cos(alpha)
        sc = _Scene()
        v = sc.P.vel(sc.O)
        where = "Example 16"
        return [
            # Right: v_P = q2' i + q1' S.x, S.x = (cos a, -sin a).
            Published("v_block^2", "expression",
                      ((rate(q2) + rate(q1) * c)**2 + (rate(q1) * s)**2,), (v.dot(v),), where=where),
            # Right: the block is q1 sin a below A; the wedge keeps its height.
            Published("U", "expression", (-m * g * q1 * s,),
                      (m * g * sc.P.pos_from(sc.A).dot(sc.O.y),), where=where),
            # Right: (M + m) - m cos^2 a = M + m sin^2 a (see the docstring).
            Published("q1''", "expression", (g * s / (1 - m / (M + m) * c**2),), (rate(q1, 2),),
                      where=where),
            # Right: it is the q2 Lagrange equation (horizontal momentum) divided by M + m.
            Published("q2''", "expression", (-m / (M + m) * rate(q1, 2) * c,), (rate(q2, 2),),
                      where=where),
        ]


PROBLEMS = (BlockOnWedge,)
