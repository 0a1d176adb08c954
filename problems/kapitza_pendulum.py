r"""Kapitza's pendulum: a pendulum whose pivot is shaken vertically, with the rod's tension.

Source: none of the course notes; this is the classic textbook problem -- Landau & Lifshitz,
*Mechanics*, section 5 problem 3(c) (the Lagrangian of a pendulum whose point of support
oscillates vertically) and section 30 problem 1 (its stable positions under fast shaking: the
inverted position ``theta = pi`` is stable when ``a^2 Omega^2 > 2 g l``).  The linearised
motion about either position is Mathieu's equation (NIST DLMF chapter 28), whose stability
chart the atlas draws.

Sign convention::

               ^ j (up)        P: pivot, height y_p(t) = a cos(Omega t) above O
               |               (prescribed: the shaker does whatever work it takes)
          P  --o--             arm frame = O rotated by theta about k:
               |\                arm.y points from the bob to the pivot,
               | \  l            arm.x = e_theta = (cos th, sin th)
               |th\
               |   o  bob m    r_B = y_p j - l arm.y = (l sin th, y_p - l cos th)
          O  --+--> i          gravity -g j;  k = i x j out of the page

``theta`` is measured from the downward vertical, counterclockwise about ``k``; the inverted
position is ``theta = pi``.

Frames.  ``O`` inertial; ``arm = O`` rotated by ``theta`` about ``k`` (``rot_z(theta)``).

Body and free-body diagram.  A particle ``m`` at ``B``; the rod is massless and pinned at P.
Forces on the bob: weight ``-m g j`` and the rod's pull ``T arm.y`` (towards the pivot; a
massless rod pinned at both ends carries force along itself only).  With
``a_B = y_p'' j + l theta'' arm.x + l theta'^2 arm.y`` and ``j . arm.x = sin th``,
``j . arm.y = cos th``::

        arm.x:  m (y_p'' sin th + l theta'')   = -m g sin th
        arm.y:  m (y_p'' cos th + l theta'^2)  = T - m g cos th
                =>  T = m ((g + y_p'') cos th + l theta'^2),   y_p'' = -a Omega^2 cos(Omega t)

Lagrangian (written independently)::

        T = m (l^2 theta'^2 + y_p'^2 + 2 l y_p' theta' sin th) / 2
        V = m g (y_p - l cos th)
        m l^2 theta'' + m l (g - a Omega^2 cos(Omega t)) sin th = 0

The rod's tension once more, independently: free the bob from the rod with its distance
``r`` from P and close it with the constraint ``l - r = 0``, multiplier ``T`` (the pull
``-T e_r`` does virtual work ``-T dr``, which is ``T d(l - r)``).

Stability (Landau & Lifshitz section 30 problem 1).  About ``theta = pi`` (``phi = theta -
pi``) the linearised equation is ``phi'' - (g/l - a Omega^2/l cos Omega t) phi = 0``; with
``tau = Omega t / 2`` it is Mathieu's ``phi_tautau + (alpha - 2 q cos 2 tau) phi = 0``,
``alpha = -4 g / (l Omega^2)``, ``q = -2 a / l``.  Fast shaking (``q`` small) stabilises it
when ``alpha > a_0(q) = -q^2/2 + O(q^4)``, i.e. ``a^2 Omega^2 > 2 g l``.  The defaults
(``a^2 Omega^2 = 6.3 m^2/s^2 > 2 g l = 3.9 m^2/s^2``) hold it up.

Published.  Landau & Lifshitz measure ``y`` downwards (their section 5 problem 1 puts the bob
at ``y = l cos phi``), so their support ``y = a cos(gamma t)`` is ours with ``a -> -a``;
their Lagrangian ``m l^2 phi'^2/2 + m l a gamma^2 cos(gamma t) cos phi + m g l cos phi``
(ours up to a total time derivative) gives ``m l^2 phi'' + m l (g + a gamma^2 cos gamma t)
sin phi = 0``, transcribed with that substitution.  No errata.

Example
-------
>>> p = KapitzaPendulum(); p.validate()
>>> p.model("lagrange").accelerations_solved()
{Derivative(theta(t), (t, 2)): (Omega**2*a*cos(Omega*t) - g)*sin(theta(t))/l}
"""
from __future__ import annotations

import sympy as sp

from dualmech import (ChartScene, Coordinate, Drawing, EquationSet, Frame, Lagrangian, NewtonEuler,
                      Parameter, Particle, Point, Problem, Published, Reaction, coordinate, rate,
                      rot_z, t,
                      ACCELERATION, ANGLE, FORCE, FREQUENCY, LENGTH, MASS)

__all__ = ["KapitzaPendulum", "PROBLEMS", "m", "l", "a", "Omega", "g", "theta", "r",
           "pivot_height", "hand_tension", "mathieu_parameters"]

m, l, a, Omega, g = sp.symbols("m l a Omega g", positive=True)
theta = coordinate("theta")
r = coordinate("r")  # distance of the bob from the pivot, only in the multiplier model


#: Height of the pivot above O.
pivot_height = a * sp.cos(Omega * t)


def hand_tension() -> sp.Expr:
    """The rod's pull on the bob, solved by hand: ``m ((g + y_p'') cos theta + l theta'^2)``."""
    return m * ((g + rate(pivot_height, 2)) * sp.cos(theta) + l * rate(theta)**2)


def mathieu_parameters(values: dict, inverted: bool = True) -> tuple[float, float]:
    """``(alpha, q)`` of Mathieu's equation for the linearised motion about ``theta = pi``
    (``inverted``) or ``theta = 0``, at parameter ``values`` (``{symbol or name: value}``)."""
    v = {getattr(k, "name", k): float(x) for k, x in values.items()}
    alpha = 4 * v["g"] / (v["l"] * v["Omega"]**2)
    return (-alpha if inverted else alpha), (-2 if inverted else 2) * v["a"] / v["l"]


class _Scene:
    """Frames, points and the bob of the direct form."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.arm = self.O.child("arm", rot_z(theta))
        self.P = Point.origin(self.O).locate("P", pivot_height * self.O.y)
        self.B = self.P.locate("B", -l * self.arm.y)
        self.bob = Particle("bob", m, self.B)


class KapitzaPendulum(Problem):
    """Bob ``m`` on a massless rod ``l`` whose pivot moves as ``a cos(Omega t)`` (module doc)."""

    name = "kapitza_pendulum"
    title = "Kapitza's pendulum (vertically shaken pivot)"
    source = ("textbook: Landau & Lifshitz, Mechanics, section 5 problem 3(c) and section 30 "
              "problem 1")
    summary = ("A pendulum on a vertically shaken pivot: a periodically driven scene whose "
               "inverted position is stable when a^2 Omega^2 > 2 g l (Floquet multipliers).")
    parameters = (
        Parameter(m, MASS, 0.1, (0.01, 5.0), "mass of the bob"),
        Parameter(l, LENGTH, 0.2, (0.05, 2.0), "length of the rod"),
        Parameter(a, LENGTH, 0.01, (0.001, 0.1), "amplitude of the pivot's motion"),
        Parameter(Omega, FREQUENCY, 80 * sp.pi.evalf(), (10.0, 1000.0),
                  "angular frequency of the pivot's motion"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-3.5, 3.5), (-10.0, 10.0),
                   "angle of the rod from the downward vertical (pi: inverted)"),
    )
    extra_coordinates = (
        Coordinate(r, LENGTH, (0.05, 2.0), (-1.0, 1.0), "distance of the bob from the pivot"),
    )
    reactions = (Reaction("T", FORCE, "rod on bob, along arm.y (towards the pivot)"),)
    extra_models = ("multiplier",)
    # the lesson: released 0.14 rad from upside down, the fast shaking holds it up (it
    # rocks about theta = pi); shaken half as fast (a^2 Omega^2 = 1.6 < 2 g l = 3.9 m^2/s^2)
    # the same pendulum falls
    initial_state = {theta: 3.0}
    chart_scenes = (ChartScene({"Omega": float(40 * sp.pi)}, {theta: 3.0},
                               "shaken too slowly (a^2 Omega^2 < 2 g l): it falls"),)
    drawing = Drawing({"pivot": (0, pivot_height),
                       "bob": (l * sp.sin(theta), pivot_height - l * sp.cos(theta))},
                      lines=(("pivot", "bob"),), view=("x", "y"))

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, r: l}}

    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on the bob along ``arm.x`` and ``arm.y``."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=sc.O,
                         description="sum F = m a on the bob, across and along the rod")
        ne.gravity(-g * sc.O.y)
        ne.reaction("T", sc.bob, sc.arm.y)
        ne.linear_momentum(sc.bob, sc.arm.x)
        ne.linear_momentum(sc.bob, sc.arm.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` by hand, the pivot's motion prescribed."""
        yp = pivot_height
        lg = Lagrangian("lagrange", coordinates=[theta], description="T and V by hand")
        lg.kinetic("T of bob", m * ((l * rate(theta))**2 + rate(yp)**2
                                    + 2 * l * rate(yp) * rate(theta) * sp.sin(theta)) / 2)
        lg.potential("gravity", m * g * (yp - l * sp.cos(theta)))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Lagrange in ``(theta, r)`` with the rod as the constraint ``l - r = 0``."""
        bob = sp.Matrix([r * sp.sin(theta), pivot_height - r * sp.cos(theta)])
        lg = Lagrangian("multiplier", coordinates=[theta, r],
                        description="the bob freed from the rod, held by a multiplier")
        lg.kinetic("T of bob", m * (rate(bob).T * rate(bob))[0, 0] / 2)
        lg.potential("gravity", m * g * bob[1])
        lg.constraint("T", l - r)
        return lg.equations()

    def published(self) -> list[Published]:
        a_ll = -a  # Landau & Lifshitz's amplitude: their y points down (module docstring)
        where = ("Landau & Lifshitz, Mechanics, section 5 problem 3(c): L = m l^2 phi'^2/2 "
                 "+ m l a gamma^2 cos(gamma t) cos(phi) + m g l cos(phi), y measured down")
        return [
            # Right: Lagrange's equation of their Lagrangian, with their a = -(our a).
            Published("equation of motion", "motion",
                      (m * l**2 * rate(theta, 2)
                       + m * l * (g + a_ll * Omega**2 * sp.cos(Omega * t)) * sp.sin(theta),),
                      where=where),
        ]


PROBLEMS = (KapitzaPendulum,)
