r"""Inverted pendulum held up by two horizontal springs: equilibrium and its stability.

Source: ``sources/004_f75aa9bb64d0737a.txt``, elaboration exam "Dynamics and Stability",
question 4 (a)-(c).  A point mass ``m`` on a massless rod of length ``l`` stands above a hinge
O; two springs ``k`` (one on each side, zero free length, staying horizontal) hold the rod at
height ``a``.  Is the upright position stable?

Sign convention::

              m  (tip, l from O)             j
              o                              ^
             /                               +--> i     gravity -m g j
      k     /  a: spring point S               theta: rod angle from the upward vertical
   |-/\/\--o--/\/\-|   (both springs pull S back to the vertical line by k x_S each)
           /
          /theta                             x_S = -a sin(theta)   (horizontal shift of S)
   ======O======     hinge, pivot force R_x i + R_y j on the rod

Frames.  ``O`` inertial (``i`` right, ``j`` up); rod ``B = O.child(rot_z(theta))``, the rod
along ``B.y``: tip at ``l B.y = l (-sin(theta), cos(theta))``, spring point at ``a B.y``.

Body: the rod with its tip mass, a rigid body of mass ``m`` centred at the tip with no inertia
about it (the source's ``T = m (l theta')^2/2``).

Free-body diagram: weight ``-m g j`` at the tip; two spring forces ``-k x_S i`` at S; the
pivot force ``R`` at O.  Direct form, ``sum F = m a_tip`` on ``i, j`` and moments about O on
``k``::

    k:  m l^2 theta'' = m g l sin(theta) - 2 k a^2 sin(theta) cos(theta)
    R_x = m l (theta'^2 sin(theta) - theta'' cos(theta)) - 2 k a sin(theta)
    R_y = m g - m l (theta'' sin(theta) + theta'^2 cos(theta))

Lagrangian, written independently (the source's)::

    T = m (l theta')^2/2,   V = 2 (k/2)(a sin(theta))^2 + m g l cos(theta)
    m l^2 theta'' + k a^2 sin(2 theta) - m g l sin(theta) = 0

The pivot force once more: free the hinge (``xp, yp``) and hold it with the multipliers
``R_x``, ``R_y`` (the springs' points move with it: ``x_S = xp - a sin(theta)``).

Stability (derived by the library in the tests, not typed in): ``theta = 0`` is an
equilibrium; linearised, ``m l^2 theta'' + (2 k a^2 - m g l) theta = 0``; with ``K = 2 k a^2 -
m g l > 0`` the eigenvalues are imaginary and ``V`` has a strict minimum there
(Lagrange--Dirichlet: stable), with ``K < 0`` one eigenvalue is positive (unstable).  So
``k > m g l/(2 a^2)``: the source's condition.

The source's argument "stable if lambda is not real" is, on its own, only marginal stability
of the linearisation; the conclusion is right because ``K`` is also the curvature of ``V``.

Errata: none.  Garbled: in (c) the second state ``U = theta'`` is extracted as ``U``, ``l``
and a script ``l``.

Example
-------
>>> p = InvertedPendulumSprings(); p.validate()
>>> p.model("lagrange").linearize()[2]
Matrix([[2*a**2*k - g*l*m]])
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z, t,
                      ACCELERATION, ANGLE, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["InvertedPendulumSprings", "PROBLEMS", "frames", "m", "l", "a", "k", "g", "theta"]

m, l, a, k, g = sp.symbols("m l a k g", positive=True)
theta = coordinate("theta")
xp, yp = coordinate("xp"), coordinate("yp")


def frames() -> SimpleNamespace:
    """Frames ``O``, ``B``; points ``o`` (hinge), ``s`` (springs), ``tip``; the body."""
    O = Frame.ground("O")
    B = O.child("B", rot_z(theta))
    o = Point.origin(O, "O")
    s = o.locate("S", a * B.y)
    tip = o.locate("tip", l * B.y)
    body = RigidBody("pendulum", m, tip, B, sp.zeros(3, 3))
    return SimpleNamespace(O=O, B=B, o=o, s=s, tip=tip, body=body)


class InvertedPendulumSprings(Problem):
    """Inverted point-mass pendulum braced by two horizontal springs (see module doc)."""

    name = "inverted_pendulum_springs"
    title = "Inverted pendulum held by two springs"
    source = "004_f75aa9bb64d0737a.txt: question 4 (a)-(c)"
    summary = ("Upright equilibrium, linearisation and the stability condition "
               "k > m g l/(2 a^2), all derived by the library; pivot force twice.")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "tip mass"),
        Parameter(l, LENGTH, 1.0, (0.2, 3.0), "rod length"),
        Parameter(a, LENGTH, 0.6, (0.05, 3.0), "height of the springs on the rod"),
        Parameter(k, STIFFNESS, 30.0, (1.0, 500.0), "stiffness of each spring"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-1.2, 1.2), (-3.0, 3.0), "rod angle from the upward vertical"),
    )
    extra_coordinates = (
        Coordinate(xp, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "hinge off O, along i"),
        Coordinate(yp, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "hinge off O, along j"),
    )
    reactions = (
        Reaction("R_x", FORCE, "hinge on the rod, along i"),
        Reaction("R_y", FORCE, "hinge on the rod, along j (up)"),
    )
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, xp: 0, yp: 0}}

    def newton_euler(self) -> EquationSet:
        """``sum F = m a_tip`` on ``i, j``; moments about O on ``k``."""
        f = frames()
        O = f.O
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=O,
                         description="rod with tip mass: Newton on i, j; moments about O")
        ne.gravity(-g * O.y)
        x_s = f.s.pos_from(f.o).dot(O.x)
        ne.linear_spring("spring 1", f.body, k, x_s, O.x, at=f.s)
        ne.linear_spring("spring 2", f.body, k, x_s, O.x, at=f.s)
        ne.reaction_vector("R", f.body, O, "xy", at=f.o)
        ne.linear_momentum(f.body, O.x)
        ne.linear_momentum(f.body, O.y)
        ne.angular_momentum(f.body, O.z, about=f.o)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """The source's ``T`` and ``V``."""
        lg = Lagrangian("lagrange", coordinates=[theta], description="(a), (b) by hand")
        lg.kinetic("T of tip mass", m * (l * rate(theta))**2 / 2)
        lg.spring("spring 1", k, a * sp.sin(theta))
        lg.spring("spring 2", k, a * sp.sin(theta))
        lg.potential("gravity", m * g * l * sp.cos(theta))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The hinge freed (``xp, yp``) and held by ``R_x``, ``R_y``."""
        tip = sp.Matrix([xp - l * sp.sin(theta), yp + l * sp.cos(theta)])
        x_s = xp - a * sp.sin(theta)
        lg = Lagrangian("multiplier", coordinates=[theta, xp, yp],
                        description="hinge freed, held by two multipliers")
        lg.kinetic("T of tip mass", m * (rate(tip).T * rate(tip))[0, 0] / 2)
        lg.spring("spring 1", k, x_s)
        lg.spring("spring 2", k, x_s)
        lg.potential("gravity", m * g * tip[1])
        lg.constraint("R_x", xp)
        lg.constraint("R_y", yp)
        return lg.equations()

    def published(self) -> list[Published]:
        f = frames()
        O = f.O
        s, c = sp.sin(theta), sp.cos(theta)
        th1, th2 = rate(theta), rate(theta, 2)
        T = f.body.kinetic_energy(O)
        V_springs = 2 * k * f.s.pos_from(f.o).dot(O.x)**2 / 2
        V_gravity = m * g * f.tip.pos_from(f.o).dot(O.y)
        L = T - V_springs - V_gravity
        lg = self.model("lagrange")
        accel = lg.accelerations_solved()[th2]          # theta'' as a function of the state
        M, _, K = lg.linearize()
        where = "question 4"
        return [
            Published("(a) T", "expression", (m * (l * th1)**2 / 2,), (T,), where=where + " a"),
            Published("(a) V", "expression",
                      (2 * k * (a * s)**2 / 2, k * a**2 * s**2, m * g * l * c,
                       k * a**2 * s**2 + m * g * l * c),
                      (V_springs, V_springs, V_gravity, V_springs + V_gravity),
                      where=where + " a: springs, gravity, total"),
            Published("(a) L", "expression",
                      (m * l**2 * th1**2 / 2 - k * a**2 * s**2 - m * g * l * c,), (L,),
                      where=where + " a"),
            Published("(b) derivatives of L", "expression",
                      (m * l**2 * th1, m * l**2 * th2, -2 * k * a**2 * s * c + m * g * l * s,
                       -k * a**2 * sp.sin(2 * theta) + m * g * l * s),
                      (L.diff(th1), L.diff(th1).diff(t), L.diff(theta), L.diff(theta)),
                      where=where + " b"),
            Published("(b) equation of motion", "motion",
                      (m * l**2 * th2 + k * a**2 * sp.sin(2 * theta) - m * g * l * s,),
                      where=where + " b"),
            Published("(c) first-order form", "expression",
                      (-k * a**2 / (m * l**2) * sp.sin(2 * theta) + g / l * s,), (th2,),
                      where=where + " c: U' = ..."),
            Published("(c) Jacobian entry", "expression",
                      (-2 * k * a**2 / (m * l**2) * sp.cos(2 * theta) + g / l * c,),
                      (accel.diff(theta),), where=where + " c: d(U')/d(theta)"),
            Published("(c) Jacobian at theta = 0", "expression",
                      (-2 * k * a**2 / (m * l**2) + g / l,), (-K[0, 0] / M[0, 0],),
                      where=where + " c: reference from EquationSet.linearize"),
            Published("(c) eigenvalues squared", "expression",
                      (g / l - 2 * k * a**2 / (m * l**2),), (-K[0, 0] / M[0, 0],),
                      where=where + " c: lambda^2 from |A - lambda I| = 0"),
        ]


PROBLEMS = (InvertedPendulumSprings,)
