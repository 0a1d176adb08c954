r"""Parallelogram four-bar linkage with a spring: loop closure against multipliers.

A dualmech problem of its own (no course source prints it): the parallelogram four-bar, the
simplest closed loop whose constraints are nonlinear in maximal coordinates.  Two massless
cranks of length ``r`` turn about the fixed pivots ``O1 = (0, 0)`` and ``O2 = (d, 0)``; their
pins carry point masses ``m1`` at A and ``m2`` at B, joined by a massless coupler AB of length
``d``.  A spring ``k`` pulls B horizontally towards the vertical through O2 (force
``-k (x_B - d) I``, unstretched with the cranks vertical).  Gravity ``-g J``.  On the
parallelogram branch the coupler stays parallel to the ground: one degree of freedom, the
crank angle ``phi``; the cranks hang below the ground line (``-pi < phi < 0``).

Sign convention (plane I-J, K out of the page)::

      J ^
        |    O1 = (0, 0)                 O2 = (d, 0)
     ---+----o---------------------------o--------> I
              \  phi < 0                  \
             r \                         r \        i_A = cos(phi) I + sin(phi) J
                \                           \       O1 r_A = r i_A
           (m1)  A------------ d ------------B (m2) --/\/\/-- k (horizontal, to x = d)
                 coupler, e = I (A to B)

Free-body diagrams (cranks and coupler are massless two-force members: their forces lie
along them)::

    m1:  weight -m1 g J,  crank 1  F1 i_A (F1 > 0: pushes m1 out),  coupler  -F3 e
    m2:  weight -m2 g J,  crank 2  F2 i_A,  coupler  F3 e (F3 > 0: compression),
         spring  -k r cos(phi) I

Direct form (``sum F = m a`` on I and J for each mass; both pins move alike,
``a = r (phi'' j_A - phi'^2 i_A)``, ``j_A = -sin(phi) I + cos(phi) J``; unknowns ``phi''``,
``F1``, ``F2``, ``F3``).  Along ``j_A`` (``e . j_A = -sin(phi)``)::

    m1 r phi'' =  F3 sin(phi) - m1 g cos(phi)
    m2 r phi'' = -F3 sin(phi) - m2 g cos(phi) + k r cos(phi) sin(phi)

and along ``i_A`` (``e . i_A = cos(phi)``)::

    -m1 r phi'^2 = F1 - F3 cos(phi) - m1 g sin(phi)
    -m2 r phi'^2 = F2 + F3 cos(phi) - m2 g sin(phi) - k r cos^2(phi)

Sum and difference of the first pair give the equation of motion and the coupler force::

    (m1 + m2) r phi'' = -(m1 + m2) g cos(phi) + k r cos(phi) sin(phi)
    F3 = m1 (r phi'' + g cos(phi))/sin(phi) = m1 k r cos(phi)/(m1 + m2)

(the coupler carries the spring's pull on B, shared in the masses' ratio).  At
``sin(phi) = 0`` the bars are collinear: the coupler force is undetermined there and the
linkage can leave the parallelogram branch (a change point) -- the declared singular set.

Lagrangian in ``phi`` (minimal coordinate through the loop closure ``r_B = r_A + d I``;
written by hand)::

    T = (m1 + m2) r^2 phi'^2/2,    V = (m1 + m2) g r sin(phi) + k r^2 cos^2(phi)/2

Maximal coordinates ``(xa, ya, xb, yb)`` with the three bar lengths as constraints (each
``|grad| = 1`` on the manifold in the unit of its bar's direction, so each multiplier is that
bar's force)::

    g1 = (xa^2 + ya^2 - r^2)/(2 r)                   multiplier F1 (crank 1 on m1)
    g2 = ((xb - d)^2 + yb^2 - r^2)/(2 r)             multiplier F2 (crank 2 on m2)
    g3 = ((xb - xa)^2 + (yb - ya)^2 - d^2)/(2 d)     multiplier F3 (coupler on m2)
    T = m1 (xa'^2 + ya'^2)/2 + m2 (xb'^2 + yb'^2)/2,   V = g (m1 ya + m2 yb) + k (xb - d)^2/2

Example
-------
>>> p = FourBar(); p.validate()
>>> sorted(p.models())
['lagrange', 'multiplier', 'newton_euler']
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_z, ACCELERATION,
                      ANGLE, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["FourBar", "PROBLEMS", "scene", "m1", "m2", "r", "d", "k", "g", "phi",
           "xa", "ya", "xb", "yb"]

m1, m2, r, d, k, g = sp.symbols("m1 m2 r d k g", positive=True)
phi = coordinate("phi")
xa, ya, xb, yb = (coordinate(n) for n in ("xa", "ya", "xb", "yb"))


def scene() -> SimpleNamespace:
    """Frames, points and particles of the direct form (see the module doc)."""
    O = Frame.ground("O")
    A = O.child("A", rot_z(phi))           # both cranks: i_A = A.x
    o1 = Point.origin(O, "O1")
    o2 = o1.locate("O2", d * O.x)
    pA = o1.locate("A", r * A.x)
    pB = o2.locate("B", r * A.x)
    return SimpleNamespace(O=O, A=A, o1=o1, o2=o2, pA=pA, pB=pB,
                           m1=Particle("m1", m1, pA), m2=Particle("m2", m2, pB))


class FourBar(Problem):
    """Parallelogram four-bar: point masses at the crank pins, spring on B."""

    name = "four_bar"
    title = "Parallelogram four-bar linkage: loop closure and bar forces"
    source = "dualmech: closed-loop linkage of its own (parallelogram four-bar, no course source)"
    summary = ("One degree of freedom through the loop closure (crank angle) and in four "
               "Cartesian coordinates with the three bar lengths as constraints; the bar "
               "forces twice; singular where the bars are collinear.")
    parameters = (
        Parameter(m1, MASS, 1.0, (0.1, 10.0), "point mass at the pin A of crank 1"),
        Parameter(m2, MASS, 2.0, (0.1, 10.0), "point mass at the pin B of crank 2"),
        Parameter(r, LENGTH, 0.5, (0.1, 2.0), "crank length"),
        Parameter(d, LENGTH, 1.5, (0.2, 5.0), "ground and coupler length"),
        Parameter(k, STIFFNESS, 40.0, (0.0, 500.0), "horizontal spring on B"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(phi, ANGLE, (-2.9, -0.25), (-8.0, 8.0), "crank angle from the ground line",
                   domain=(-3.141592653589793, 0.0)),   # below the line, off the change points
    )
    extra_coordinates = (
        Coordinate(xa, LENGTH, (-2.0, 2.0), (-16.0, 16.0), "horizontal position of A"),
        Coordinate(ya, LENGTH, (-2.0, 0.0), (-16.0, 16.0), "height of A"),
        Coordinate(xb, LENGTH, (-1.0, 7.0), (-16.0, 16.0), "horizontal position of B"),
        Coordinate(yb, LENGTH, (-2.0, 0.0), (-16.0, 16.0), "height of B"),
    )
    reactions = (
        Reaction("F1", FORCE, "crank 1 on m1, along i_A (O1 to A); compression > 0"),
        Reaction("F2", FORCE, "crank 2 on m2, along i_A (O2 to B); compression > 0"),
        Reaction("F3", FORCE, "coupler on m2, along I (A to B); compression > 0"),
    )
    singular = (sp.sin(phi),)
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        c, s = r * sp.cos(phi), r * sp.sin(phi)
        return {"multiplier": {xa: c, ya: s, xb: d + c, yb: s}}

    # -- direct form -----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on I and J for m1 and for m2."""
        s = scene()
        O = s.O
        ne = NewtonEuler(coordinates=[phi], ground=O,
                         description="sum F = m a on m1 and on m2, along I and J")
        ne.gravity(-g * O.y)
        ne.linear_spring("spring", s.m2, k, r * sp.cos(phi), O.x)
        ne.reaction("F1", s.m1, s.A.x)
        ne.reaction("F2", s.m2, s.A.x)
        ne.reaction("F3", s.m2, O.x, against=s.m1)
        for body in (s.m1, s.m2):
            ne.linear_momentum(body, O.x)
            ne.linear_momentum(body, O.y)
        return ne.equations()

    # -- indirect forms --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` in ``phi`` by hand (both pins move alike)."""
        lg = Lagrangian(coordinates=[phi], description="T, V in the crank angle, by hand")
        lg.kinetic("T of m1, m2", (m1 + m2) * r**2 * rate(phi)**2 / 2)
        lg.potential("gravity", (m1 + m2) * g * r * sp.sin(phi))
        lg.spring("spring", k, r * sp.cos(phi))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """A and B free in the plane; the three bar lengths as constraints."""
        lg = Lagrangian("multiplier", coordinates=[xa, ya, xb, yb],
                        description="pins in Cartesian coordinates, bars as constraints")
        lg.kinetic("T of m1", m1 * (rate(xa)**2 + rate(ya)**2) / 2)
        lg.kinetic("T of m2", m2 * (rate(xb)**2 + rate(yb)**2) / 2)
        lg.potential("gravity", g * (m1 * ya + m2 * yb))
        lg.spring("spring", k, xb - d)
        lg.constraint("F1", (xa**2 + ya**2 - r**2) / (2 * r))
        lg.constraint("F2", ((xb - d)**2 + yb**2 - r**2) / (2 * r))
        lg.constraint("F3", ((xb - xa)**2 + (yb - ya)**2 - d**2) / (2 * d))
        return lg.equations()

    # -- the hand derivation's results (module docstring) --------------------------------------
    def published(self) -> list[Published]:
        c, s = sp.cos(phi), sp.sin(phi)
        return [
            Published("equation of motion", "equation",
                      ((m1 + m2) * r * rate(phi, 2) + (m1 + m2) * g * c - k * r * c * s,),
                      where="module docstring: sum of the j_A balances"),
            Published("m1 along j_A", "equation",
                      (m1 * r * rate(phi, 2) - sp.Symbol("F3", real=True) * s + m1 * g * c,),
                      where="module docstring: m1's balance across its crank"),
        ]


PROBLEMS = (FourBar,)
