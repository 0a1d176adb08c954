r"""Rigid-rod pendulum: a uniform rod hinged at one end (Lagrange, Euler, and the pivot force).

Source: ``sources/003_d6818267b4d96a20.txt``, lecture 18, "Rigid-body pendulum with Lagrange
I/II".  A uniform rod of mass ``m`` and length ``l`` turns about a fixed horizontal axis
through its end O.

Sign convention (as :mod:`dualmech.problems.pendulum_particle`)::

        i2 (up)
        ^        R_x i1 + R_y i2  (pivot on the rod)
        |      O
        +------o------> i1          b1 =  cos(theta) i1 + sin(theta) i2
               |\                   b2 = -sin(theta) i1 + cos(theta) i2   (from the rod to O)
               | \                  r_C = -(l/2) b2,  the rod's far end at -l b2
               |th\ C (mass centre, l/2 from O)
               |   \
                    \  rod, length l, mass m         gravity -m g i2

Frames.  ``O`` inertial; ``B = O.child(rot_z(theta))`` fixed in the rod.  ``w = theta' b3``.

Body: the rod, mass ``m``, mass centre ``C``, inertia about ``C`` in ``B`` axes
``diag(m l^2/12, 0, m l^2/12)`` (it lies along ``b2``), so ``I_z = m l^2/12``.

Free-body diagram: weight ``-m g i2`` at ``C``; the pivot's force ``R_x i1 + R_y i2`` at O.

Direct form: ``sum F = m a_C`` on ``i1, i2`` and Euler's equation about ``C`` on ``b3``, with
``a_C = (l/2)(theta'' b1 + theta'^2 b2)``::

    i1:  R_x = m (l/2) (theta'' cos(theta) - theta'^2 sin(theta))
    i2:  R_y - m g = m (l/2) (theta'' sin(theta) + theta'^2 cos(theta))
    b3:  (l/2) (R_x cos(theta) + R_y sin(theta)) = (m l^2/12) theta''

Putting the first two into the third: ``(m l^2/3) theta'' + m g (l/2) sin(theta) = 0``, and
with ``theta'' = -(3 g/(2 l)) sin(theta)`` the pivot force is::

    R_x = -(3/4) m g sin(theta) cos(theta) - (m l/2) theta'^2 sin(theta)
    R_y =  m g (1 - (3/4) sin^2(theta))   + (m l/2) theta'^2 cos(theta)

Lagrangian, written independently (the source's slide)::

    T = m (l/2)^2 theta'^2/2 + I_z theta'^2/2 = m l^2 theta'^2/6,   U = -m g (l/2) cos(theta)
    (1/3) m l^2 theta'' + m g (l/2) sin(theta) = 0,   theta'' + (3/2)(g/l) sin(theta) = 0

The pivot force once more, independently: free the end O with two coordinates ``(xp, yp)``
(its position), ``C = (xp + (l/2) sin(theta), yp - (l/2) cos(theta))``, and hold it with the
constraints ``xp = 0`` (multiplier ``R_x``) and ``yp = 0`` (``R_y``): the pivot's force does
virtual work ``R_x d(xp) + R_y d(yp)``, so the multipliers are its components.

Small oscillations: ``omega^2 = (3/2) g/l`` (the library's :meth:`EquationSet.natural_frequencies`
derives it; see the tests).

Errata: none in the formulas.  The extraction garbles two labels: the first line prints
``r_c = (l/2) theta' b1`` (it is the velocity ``v_c``), and the column ``v_c^b`` reads
``[e/2 theta'; 0 0]`` (it is ``(l theta'/2, 0, 0)``); both are transcribed as meant.

Example
-------
>>> p = RigidRodPendulum(); p.validate()
>>> p.model("lagrange").natural_frequencies()
[sqrt(6)*sqrt(g)/(2*sqrt(l))]
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z, thin_rod,
                      ACCELERATION, ANGLE, FORCE, LENGTH, MASS)

__all__ = ["RigidRodPendulum", "PROBLEMS", "frames", "hand_reactions", "m", "l", "g", "theta"]

m, l, g = sp.symbols("m l g", positive=True)
theta = coordinate("theta")
xp, yp = coordinate("xp"), coordinate("yp")


def hand_reactions() -> dict:
    """``{"R_x": ..., "R_y": ...}`` solved by hand (module docstring)."""
    s, c, w2 = sp.sin(theta), sp.cos(theta), rate(theta)**2
    return {"R_x": -sp.Rational(3, 4) * m * g * s * c - m * l / 2 * w2 * s,
            "R_y": m * g * (1 - sp.Rational(3, 4) * s**2) + m * l / 2 * w2 * c}


def frames() -> SimpleNamespace:
    """Frames ``O``, ``B``; points ``o`` (pivot), ``C`` (mass centre); the body ``rod``."""
    O = Frame.ground("O")
    B = O.child("B", rot_z(theta))
    o = Point.origin(O, "O")
    C = o.locate("C", -l / 2 * B.y)
    rod = RigidBody("rod", m, C, B, thin_rod(m, l, axis="y"))
    return SimpleNamespace(O=O, B=B, o=o, C=C, rod=rod)


class RigidRodPendulum(Problem):
    """Uniform rod hinged at one end, swinging in a vertical plane (see module doc)."""

    name = "rigid_rod_pendulum"
    title = "Rigid-rod pendulum"
    source = "003_d6818267b4d96a20.txt: lecture 18, Rigid-body pendulum with Lagrange I/II"
    summary = ("Uniform rod about its end: Euler about the mass centre, Lagrange, and the "
               "pivot force twice (free-body diagram and multipliers).")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "mass of the rod"),
        Parameter(l, LENGTH, 1.0, (0.1, 5.0), "length of the rod"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "rod angle from the downward vertical"),
    )
    extra_coordinates = (
        Coordinate(xp, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "horizontal position of the rod's end"),
        Coordinate(yp, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "height of the rod's end"),
    )
    reactions = (
        Reaction("R_x", FORCE, "pivot on the rod, along i1"),
        Reaction("R_y", FORCE, "pivot on the rod, along i2 (up)"),
    )
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, xp: 0, yp: 0}}

    def newton_euler(self) -> EquationSet:
        """``sum F = m a_C`` on ``i1, i2``; Euler's equation about ``C`` on ``b3``."""
        f = frames()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=f.O,
                         description="Newton on i1, i2 and Euler about the mass centre")
        ne.gravity(-g * f.O.y)
        ne.reaction_vector("R", f.rod, f.O, "xy", at=f.o)
        ne.linear_momentum(f.rod, f.O.x)
        ne.linear_momentum(f.rod, f.O.y)
        ne.angular_momentum(f.rod, f.B.z)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """The source's ``T`` and ``U``, by hand."""
        lg = Lagrangian("lagrange", coordinates=[theta], description="T and U of the rod by hand")
        lg.kinetic("T of rod, translation", m * (l / 2 * rate(theta))**2 / 2)
        lg.kinetic("T of rod, rotation about C", m * l**2 / 12 * rate(theta)**2 / 2)
        lg.potential("gravity", -m * g * l / 2 * sp.cos(theta))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The end O freed (``xp``, ``yp``) and held by the multipliers ``R_x``, ``R_y``."""
        C = sp.Matrix([xp + l / 2 * sp.sin(theta), yp - l / 2 * sp.cos(theta)])
        lg = Lagrangian("multiplier", coordinates=[theta, xp, yp],
                        description="the rod's end freed, held at O by two multipliers")
        lg.kinetic("T of rod, translation", m * (rate(C).T * rate(C))[0, 0] / 2)
        lg.kinetic("T of rod, rotation about C", m * l**2 / 12 * rate(theta)**2 / 2)
        lg.potential("gravity", m * g * C[1])
        lg.constraint("R_x", xp)
        lg.constraint("R_y", yp)
        return lg.equations()

    def published(self) -> list[Published]:
        f = frames()
        O, B = f.O, f.B
        th1, th2 = rate(theta), rate(theta, 2)
        inB = lambda v: tuple(v.express(B).components)  # noqa: E731
        Iz = f.rod.inertia[2, 2]
        T = f.rod.kinetic_energy(O)
        U = m * g * f.C.pos_from(f.o).dot(O.y)
        L = T - U
        where = "Rigid-body pendulum with Lagrange I"
        where2 = "Rigid-body pendulum with Lagrange II"
        return [
            Published("v_c", "expression", inB(l / 2 * th1 * B.x), inB(f.C.vel(O)),
                      where=where + " (labelled r_c and, as a column, garbled)"),
            Published("w_ib", "expression", (0, 0, th1) + (0, 0, th1),
                      tuple(f.rod.angular_velocity(O).express(O).components) + inB(
                          f.rod.angular_velocity(O)), where=where + ": theta' i3 = theta' b3"),
            Published("I_z", "expression", (m * l**2 / 12,), (Iz,), where=where),
            Published("T", "expression",
                      (m * l**2 / 4 * th1**2 / 2 + Iz * th1**2 / 2,
                       (m / 4 + Iz / l**2) * l**2 * th1**2 / 2, m * l**2 * th1**2 / 6),
                      (T, T, T), where=where2 + ": the three forms"),
            Published("U", "expression", (-m * g * l / 2 * sp.cos(theta),), (U,), where=where2),
            Published("L", "expression",
                      (m * l**2 * th1**2 / 6 + m * g * l / 2 * sp.cos(theta),), (L,),
                      where=where2),
            Published("dL/dtheta', dL/dtheta", "expression",
                      (m * l**2 * th1 / 3, -m * g * l / 2 * sp.sin(theta)),
                      (L.diff(th1), L.diff(theta)), where=where2),
            Published("equation of motion", "equation",
                      (m * l**2 * th2 / 3 + m * g * l / 2 * sp.sin(theta),), where=where2),
            Published("equation of motion, final", "motion",
                      (th2 + sp.Rational(3, 2) * g / l * sp.sin(theta),), where=where2),
        ]


PROBLEMS = (RigidRodPendulum,)
