r"""Slider-crank linkage: a closed loop, in the crank angle and in maximal coordinates.

A dualmech problem of its own (no course source prints it): the classical slider-crank
mechanism, the simplest closed kinematic loop with a nonlinear constraint.  A massless crank
OA of length ``r`` turns about the fixed pivot O and carries a point mass ``m1`` at its pin A;
a massless connecting rod AB of length ``L > r`` joins A to a slider of mass ``m2`` at B,
which runs without friction on the horizontal guide through O.  Gravity ``-g J``.  One degree
of freedom; every pin frictionless, no driving torque.

Sign convention (plane I-J, K out of the page)::

            J
            ^        A (m1)
            |       /  \
            |    r /    \  L                 O r_A = r (cos(phi) I + sin(phi) J)
            |     /      \                   O r_B = x_B I
            |    / phi    \                  x_B = r cos(phi) + sqrt(L^2 - r^2 sin^2(phi))
      ------O-------------[B m2]------> I    (the slider right of A: the branch used)
                 guide

Unit vectors: ``i_A = cos(phi) I + sin(phi) J`` (along the crank, O to A) and the rod's
``e = (r_B - r_A)/L = (sqrt(L^2 - r^2 sin^2 phi) I - r sin(phi) J)/L`` (A to B).

Free-body diagrams (the crank and the rod are massless two-force members: their forces lie
along them)::

    m1:  weight -m1 g J,  crank  F_C i_A (F_C > 0: the crank pushes m1 outwards),
         rod  -F e
    m2:  weight -m2 g J,  guide  N J,  rod  F e  (F > 0: the rod in compression)

Kinematics: ``x_B' = J1 phi'`` and ``x_B'' = J1 phi'' + J2 phi'^2`` with, writing
``s = sqrt(L^2 - r^2 sin^2 phi)``::

    J1 = dx_B/dphi = -r sin(phi) - r^2 sin(phi) cos(phi)/s
    J2 = dJ1/dphi  = -r cos(phi) - r^2 cos(2 phi)/s - r^4 sin^2(phi) cos^2(phi)/s^3

Direct form (``sum F = m a`` on I and J for each mass; unknowns ``phi''``, ``F``, ``F_C``,
``N``)::

    m1:  m1 r (phi'' j_A - phi'^2 i_A) = F_C i_A - F e - m1 g J        (i_A x K = -j_A)
    m2, I:  m2 x_B'' = F e_I
    m2, J:  0 = N - m2 g + F e_J

Lagrangian in ``phi`` (minimal coordinate through the loop closure; written by hand)::

    T = m1 r^2 phi'^2/2 + m2 J1^2 phi'^2/2,      V = m1 g r sin(phi)
    (m1 r^2 + m2 J1^2) phi'' + m2 J1 J2 phi'^2 + m1 g r cos(phi) = 0

Maximal coordinates ``(phi, x, y)`` (B freed from the rod and from the guide) with the rod
length and the guide as constraints, multipliers ``F`` and ``N``::

    T = m1 r^2 phi'^2/2 + m2 (x'^2 + y'^2)/2,      V = m1 g r sin(phi) + m2 g y
    g_F = ((x - r cos phi)^2 + (y - r sin phi)^2 - L^2)/(2 L) = 0,      g_N = y = 0

On the manifold ``grad_(x, y) g_F = e`` (unit length): the multiplier is the rod force ``F``
along ``e`` on the slider, and ``N`` the guide's force along ``J``.  The reactions of the two
forms are the same forces, which the tests check against the hand formulas
``F = m2 x_B''/e_I`` and ``N = m2 g - F e_J``.

Example
-------
>>> p = SliderCrank(); p.validate()
>>> sorted(p.models())
['lagrange', 'multiplier', 'newton_euler']
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import Frame, Lagrangian, NewtonEuler, Particle, Point, coordinate, rot_z, t
from dualmech.dimensions import ACCELERATION, ANGLE, FORCE, LENGTH, MASS
from dualmech.equations import EquationSet
from dualmech.problem import Coordinate, Parameter, Problem, Published, Reaction

__all__ = ["SliderCrank", "PROBLEMS", "scene", "slider_position", "m1", "m2", "r", "L", "g",
           "phi", "x", "y"]

m1, m2, r, L, g = sp.symbols("m1 m2 r L g", positive=True)
phi = coordinate("phi")
x = coordinate("x")   # the slider's freed position (maximal coordinates)
y = coordinate("y")   # its height off the guide (maximal coordinates)

D = lambda q, n=1: q.diff(t, n)  # noqa: E731  (q', q'')


def slider_position(angle=phi):
    """``x_B = r cos(phi) + sqrt(L^2 - r^2 sin^2(phi))``: the loop closure, slider right of A."""
    return r * sp.cos(angle) + sp.sqrt(L**2 - r**2 * sp.sin(angle)**2)


def scene() -> SimpleNamespace:
    """Frames, points, particles and the rod's unit vector ``e`` (see the module doc)."""
    O = Frame.ground("O")
    A = O.child("A", rot_z(phi))
    o = Point.origin(O, "O")
    pA = o.locate("A", r * A.x)
    xB = slider_position()
    pB = o.locate("B", xB * O.x)
    e = (sp.sqrt(L**2 - r**2 * sp.sin(phi)**2) * O.x - r * sp.sin(phi) * O.y) / L
    return SimpleNamespace(O=O, A=A, o=o, pA=pA, pB=pB, e=e, xB=xB,
                           pin=Particle("m1", m1, pA), slider=Particle("m2", m2, pB))


class SliderCrank(Problem):
    """Slider-crank linkage: crank pin mass m1, slider m2, massless crank and rod."""

    name = "slider_crank"
    title = "Slider-crank linkage: loop closure and multipliers"
    source = "dualmech: closed-loop linkage of its own (a textbook slider-crank, no course source)"
    summary = ("One degree of freedom through the loop closure (crank angle) and in maximal "
               "coordinates with the rod length and the guide as constraints; rod and guide "
               "forces twice.")
    parameters = (
        Parameter(m1, MASS, 1.0, (0.1, 10.0), "point mass at the crank pin A"),
        Parameter(m2, MASS, 2.0, (0.1, 10.0), "mass of the slider"),
        Parameter(r, LENGTH, 0.5, (0.1, 1.0), "crank length OA"),
        Parameter(L, LENGTH, 1.2, (1.1, 3.0), "connecting rod length AB (> r)"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-12.0, 12.0), "crank angle from the guide"),
    )
    extra_coordinates = (
        Coordinate(x, LENGTH, (0.1, 4.0), (-8.0, 8.0), "slider position along the guide"),
        Coordinate(y, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "slider height off the guide"),
    )
    reactions = (
        Reaction("F", FORCE, "connecting rod on the slider, along e (A to B); compression > 0"),
        Reaction("N", FORCE, "guide on the slider, along J"),
        Reaction("F_C", FORCE, "crank on m1, along i_A (O to A); compression > 0"),
    )
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {phi: phi, x: slider_position(), y: 0}}

    # -- direct form -----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on I and J for m1 and for m2 (slider on the loop closure)."""
        s = scene()
        O = s.O
        ne = NewtonEuler(coordinates=[phi], ground=O,
                         description="sum F = m a on m1 and on m2, along I and J")
        ne.gravity(-g * O.y)
        ne.reaction("N", s.slider, O.y)
        ne.reaction("F", s.slider, s.e, against=s.pin)
        ne.reaction("F_C", s.pin, s.A.x)
        for body in (s.pin, s.slider):
            ne.linear_momentum(body, O.x)
            ne.linear_momentum(body, O.y)
        return ne.equations()

    # -- indirect forms --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` in ``phi`` by hand, the slider's speed ``J1 phi'``."""
        sn = sp.sqrt(L**2 - r**2 * sp.sin(phi)**2)
        J1 = -r * sp.sin(phi) - r**2 * sp.sin(phi) * sp.cos(phi) / sn
        lg = Lagrangian(coordinates=[phi], description="T, V in the crank angle, by hand")
        lg.kinetic("T of m1", m1 * r**2 * D(phi)**2 / 2)
        lg.kinetic("T of m2", m2 * J1**2 * D(phi)**2 / 2)
        lg.potential("gravity", m1 * g * r * sp.sin(phi))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """B freed from the rod and the guide; ``F`` and ``N`` as multipliers."""
        lg = Lagrangian("multiplier", coordinates=[phi, x, y],
                        description="rod length and guide as constraints with multipliers")
        lg.kinetic("T of m1", m1 * r**2 * D(phi)**2 / 2)
        lg.kinetic("T of m2", m2 * (D(x)**2 + D(y)**2) / 2)
        lg.potential("gravity", m1 * g * r * sp.sin(phi) + m2 * g * y)
        lg.constraint("F", ((x - r * sp.cos(phi))**2 + (y - r * sp.sin(phi))**2 - L**2)
                      / (2 * L))
        lg.constraint("N", y)
        return lg.equations()

    # -- the hand derivation's results (module docstring) --------------------------------------
    def published(self) -> list[Published]:
        sn = sp.sqrt(L**2 - r**2 * sp.sin(phi)**2)
        J1 = -r * sp.sin(phi) - r**2 * sp.sin(phi) * sp.cos(phi) / sn
        J2 = -r * sp.cos(phi) - r**2 * sp.cos(2 * phi) / sn \
            - r**4 * sp.sin(phi)**2 * sp.cos(phi)**2 / sn**3
        return [
            Published("x_B'", "expression", (J1 * D(phi),), (slider_position().diff(t),),
                      where="module docstring: the slider's speed through the loop closure"),
            Published("x_B''", "expression", (J1 * D(phi, 2) + J2 * D(phi)**2,),
                      (slider_position().diff(t, 2),),
                      where="module docstring: the slider's acceleration"),
            Published("equation of motion", "equation",
                      ((m1 * r**2 + m2 * J1**2) * D(phi, 2) + m2 * J1 * J2 * D(phi)**2
                       + m1 * g * r * sp.cos(phi),),
                      where="module docstring: Lagrange in phi"),
        ]


PROBLEMS = (SliderCrank,)
