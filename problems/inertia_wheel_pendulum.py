r"""Gyroscopic (inertia-wheel) pendulum: a physical pendulum carrying a motor-driven disc.

Source: ``sources/003_d6818267b4d96a20.txt``, lecture 18, "Gyroscopic pendulum (Inertia wheel
pendulum)", old exam problem 1 (a)-(d).  A stiff rod (mass ``m1``, length ``l1``, moment of
inertia ``I1`` about its mass centre, mass centre ``l_c1`` from the pivot) turns about a fixed
axis through O.  At its far end a symmetric disc (mass ``m2``, moment of inertia ``I2`` about
its axis) spins about an axis parallel to the pivot's, driven by a motor torque ``tau`` that
reacts on the rod.

Sign convention (the source's axes: positions ``l (cos q1, sin q1)`` and ``U = -m g l cos q1``
put gravity along ``+x``, i.e. ``x`` points down)::

            O (pivot) -------> y = i2
            |\
            | \  rod: mass centre C1 at l_c1 b1
            |q1\
            |   \         disc, centre C2 at l1 b1, turned by q2 relative to the rod;
            v    (o)      motor: +tau i3 on the disc, -tau i3 on the rod
      x = i1 (down, gravity +g i1)                  i3 = i1 x i2 (out of the page)

Frames.  ``O`` inertial (``i1`` down, ``i2``, ``i3``); rod ``B = O.child(rot_z(q1))``,
``b1 = cos q1 i1 + sin q1 i2``; disc ``C = B.child(rot_z(q2))``.  So ``w_ib = q1' i3``,
``w_bc = q2' b3`` and ``w_ic = (q1' + q2') i3``.

Bodies.  Rod: ``m1``, centre ``C1 = l_c1 b1``, inertia ``diag(0, I1, I1)`` in ``B`` (thin, along
``b1``; only ``I1`` about ``i3`` enters).  Disc: ``m2``, centre ``C2 = l1 b1``, inertia
``diag(I2/2, I2/2, I2)`` in ``C`` (only ``I2`` enters).

Free-body diagrams::

    rod:   m1 g i1 at C1;  pivot R_x i1 + R_y i2 at O;  -(F_x i1 + F_y i2) at C2;  -tau i3
    disc:  m2 g i1 at C2;  bearing F_x i1 + F_y i2 at C2;                        +tau i3

Direct form: ``sum F = m a_C`` on ``i1, i2`` for each body; the rod's angular momentum about
O and the disc's about its centre, on ``i3``::

    disc, i3:   I2 (q1'' + q2'') = tau
    rod, i3:    (I1 + m1 l_c1^2) q1'' = -m1 g l_c1 sin q1 + l1 (F_x sin q1 - F_y cos q1) - tau
    disc:       F = m2 (a_C2 - g i1),   a_C2 = l1 (q1'' b2 - q1'^2 b1)

Eliminating ``F``: ``J q1'' = -tau - M g sin q1`` with ``J = I1 + m1 l_c1^2 + m2 l1^2`` and
``M = m1 l_c1 + m2 l1``.  The pivot's force from the whole system's momentum::

    R = m1 a_C1 + m2 a_C2 - (m1 + m2) g i1
    R_x = -M (q1'' sin q1 + q1'^2 cos q1) - (m1 + m2) g,   R_y = M (q1'' cos q1 - q1'^2 sin q1)

Lagrangian, written independently (the source's (c), (d))::

    T = m1 (l_c1 q1')^2/2 + I1 q1'^2/2 + m2 (l1 q1')^2/2 + I2 (q1' + q2')^2/2
    U = -m1 l_c1 g cos q1 - m2 l1 g cos q1,           Q = (0, tau)
    (J) q1'' + I2 (q1'' + q2'') + M g sin q1 = 0,       I2 (q1'' + q2'') = tau

The reactions once more, independently: free the rod's end (``xp, yp``) and the disc's centre
from the rod (offset ``dx, dy``), held by the constraints ``xp = yp = 0`` (multipliers
``R_x, R_y``: the pivot force does virtual work ``R . d(xp, yp)``) and ``dx = dy = 0``
(``F_x, F_y``: the bearing pair does ``F . d(dx, dy)``).

Errata (see :meth:`InertiaWheelPendulum.published`)
----------------------------------------------------
* (d): ``dL/dq1' = m1 l_c1 q1'' + I1 q1'' + m2 l1^2 q1'' + I2 (q1' + q2')`` -- ``l_c1`` must be
  squared and the first three terms carry ``q1''`` for ``q1'``; it is
  ``(m1 l_c1^2 + I1 + m2 l1^2) q1' + I2 (q1' + q2')``.
* (d): the ``q1`` equation keeps ``m1 l_c1 q1''`` (a force among torques): it must be
  ``m1 l_c1^2 q1''``; the dimension audit flags it.
* (d II): ``dL/dq2' = I2 (q1'' + q2'')`` as extracted; it is ``I2 (q1' + q2')``.  A misread dot
  cannot be ruled out here (nor for the ``q''`` in the first item); the missing square can.
* The source writes the rod length as ``l`` in (b), (c) and ``l_1`` in (d); both are ``l1``.

Example
-------
>>> p = InertiaWheelPendulum(); p.validate()
>>> sp.factor(p.model("lagrange").mass_matrix().det())
I2*(I1 + l1**2*m2 + l_c1**2*m1)
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z,
                      ACCELERATION, ANGLE, FORCE, INERTIA, LENGTH, MASS, TORQUE)

__all__ = ["InertiaWheelPendulum", "PROBLEMS", "frames", "hand_reactions", "m1", "m2", "l1",
           "l_c1", "I1", "I2", "g", "tau", "q1", "q2"]

m1, m2, l1, l_c1, I1, I2, g, tau = sp.symbols("m1 m2 l1 l_c1 I1 I2 g tau", positive=True)
q1, q2 = coordinate("q1"), coordinate("q2")
xp, yp, dx, dy = (coordinate(n) for n in ("xp", "yp", "dx", "dy"))


def hand_reactions(q1dd) -> dict:
    """Pivot and bearing forces by hand (module docstring), given the true ``q1''``."""
    s, c, w2 = sp.sin(q1), sp.cos(q1), rate(q1)**2
    M = m1 * l_c1 + m2 * l1
    return {"R_x": -M * (q1dd * s + w2 * c) - (m1 + m2) * g,
            "R_y": M * (q1dd * c - w2 * s),
            "F_x": m2 * l1 * (-q1dd * s - w2 * c) - m2 * g,
            "F_y": m2 * l1 * (q1dd * c - w2 * s)}


def frames() -> SimpleNamespace:
    """Frames ``O, B, C``; points ``o, c1, c2``; bodies ``rod`` and ``disc``."""
    O = Frame.ground("O")
    B = O.child("B", rot_z(q1))
    C = B.child("C", rot_z(q2))
    o = Point.origin(O, "O")
    c1 = o.locate("C1", l_c1 * B.x)
    c2 = o.locate("C2", l1 * B.x)
    rod = RigidBody("rod", m1, c1, B, sp.diag(0, I1, I1))
    disc = RigidBody("disc", m2, c2, C, sp.diag(I2 / 2, I2 / 2, I2))
    return SimpleNamespace(O=O, B=B, C=C, o=o, c1=c1, c2=c2, rod=rod, disc=disc)


class InertiaWheelPendulum(Problem):
    """Physical pendulum with a motor-driven disc at its end (see module doc)."""

    name = "inertia_wheel_pendulum"
    title = "Gyroscopic (inertia-wheel) pendulum with motor torque"
    source = "003_d6818267b4d96a20.txt: lecture 18, Gyroscopic pendulum, problem 1 (a)-(d)"
    summary = ("Rod and motor-driven disc: two angles, pivot and bearing forces twice; the "
               "printed q1 equation lacks a square on l_c1.")
    parameters = (
        Parameter(m1, MASS, 0.5, (0.05, 5.0), "mass of the rod"),
        Parameter(m2, MASS, 0.3, (0.05, 5.0), "mass of the disc"),
        Parameter(l1, LENGTH, 0.4, (0.1, 2.0), "length of the rod (pivot to disc centre)"),
        Parameter(l_c1, LENGTH, 0.2, (0.05, 1.0), "pivot to the rod's mass centre"),
        Parameter(I1, INERTIA, 0.007, (1e-4, 1.0), "rod's moment of inertia about its centre"),
        Parameter(I2, INERTIA, 0.002, (1e-4, 1.0), "disc's moment of inertia about its axis"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(tau, TORQUE, 0.05, (0.001, 2.0), "motor torque on the disc (reacts on the rod)"),
    )
    coordinates = (
        Coordinate(q1, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "rod angle from the downward vertical"),
        Coordinate(q2, ANGLE, (-6.0, 6.0), (-50.0, 50.0), "disc angle relative to the rod"),
    )
    extra_coordinates = (
        Coordinate(xp, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "rod end off the pivot, along i1"),
        Coordinate(yp, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "rod end off the pivot, along i2"),
        Coordinate(dx, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "disc centre off the rod end, i1"),
        Coordinate(dy, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "disc centre off the rod end, i2"),
    )
    reactions = (
        Reaction("R_x", FORCE, "pivot on the rod, along i1 (down)"),
        Reaction("R_y", FORCE, "pivot on the rod, along i2"),
        Reaction("F_x", FORCE, "rod's bearing on the disc, along i1"),
        Reaction("F_y", FORCE, "rod's bearing on the disc, along i2"),
    )
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {q1: q1, q2: q2, xp: 0, yp: 0, dx: 0, dy: 0}}

    def newton_euler(self) -> EquationSet:
        """Newton on ``i1, i2`` for both bodies; the rod about O, the disc about its centre."""
        f = frames()
        O = f.O
        ne = NewtonEuler("newton_euler", coordinates=[q1, q2], ground=O,
                         description="rod and disc: Newton, Euler about O and about C2")
        ne.gravity(g * O.x)
        ne.reaction_vector("R", f.rod, O, "xy", at=f.o)
        ne.reaction_vector("F", f.disc, O, "xy", at=f.c2, against=f.rod, against_at=f.c2)
        ne.torque("motor", f.disc, tau * O.z)
        ne.torque("motor", f.rod, -tau * O.z)
        for body in (f.rod, f.disc):
            ne.linear_momentum(body, O.x)
            ne.linear_momentum(body, O.y)
        ne.angular_momentum(f.rod, O.z, about=f.o)
        ne.angular_momentum(f.disc, O.z)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """The source's ``T``, ``U`` and generalised forces ``(0, tau)``."""
        lg = Lagrangian("lagrange", coordinates=[q1, q2], description="(c), (d) by hand")
        lg.kinetic("T of rod", m1 * (l_c1 * rate(q1))**2 / 2 + I1 * rate(q1)**2 / 2)
        lg.kinetic("T of disc", m2 * (l1 * rate(q1))**2 / 2 + I2 * (rate(q1) + rate(q2))**2 / 2)
        lg.potential("gravity", -m1 * l_c1 * g * sp.cos(q1) - m2 * l1 * g * sp.cos(q1))
        lg.generalized_force("motor", [0, tau])
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Pivot and bearing freed; four multipliers hold them (see module doc)."""
        b1 = sp.Matrix([sp.cos(q1), sp.sin(q1)])
        end = sp.Matrix([xp, yp])
        c1 = end + l_c1 * b1
        c2 = end + l1 * b1 + sp.Matrix([dx, dy])
        lg = Lagrangian("multiplier", coordinates=[q1, q2, xp, yp, dx, dy],
                        description="pivot and bearing freed, held by multipliers")
        lg.kinetic("T of rod", m1 * (rate(c1).T * rate(c1))[0, 0] / 2 + I1 * rate(q1)**2 / 2)
        lg.kinetic("T of disc", m2 * (rate(c2).T * rate(c2))[0, 0] / 2 + I2 * (rate(q1) + rate(q2))**2 / 2)
        lg.potential("gravity", -m1 * g * c1[0] - m2 * g * c2[0])
        lg.generalized_force("motor", [0, tau, 0, 0, 0, 0])
        for name, q in (("R_x", xp), ("R_y", yp), ("F_x", dx), ("F_y", dy)):
            lg.constraint(name, q)
        return lg.equations()

    def published(self) -> list[Published]:
        f = frames()
        O, B = f.O, f.B
        w_rod, w_disc = B.ang_vel_in(O), f.C.ang_vel_in(O)
        torque_pair = [tau * O.z.dot(w_disc.diff(rate(q), O)) - tau * O.z.dot(w_rod.diff(rate(q), O))
                       for q in (q1, q2)]
        inO = lambda v: tuple(v.express(O).components)  # noqa: E731
        xy = lambda v: inO(v)[:2]  # noqa: E731
        T = f.rod.kinetic_energy(O) + f.disc.kinetic_energy(O)
        U = -g * (m1 * f.c1.pos_from(f.o).dot(O.x) + m2 * f.c2.pos_from(f.o).dot(O.x))
        L = T - U
        s, c = sp.sin(q1), sp.cos(q1)
        a1, a2, v1, v2 = rate(q1, 2), rate(q2, 2), rate(q1), rate(q2)
        return [
            Published("(a) generalised forces", "expression", (0, tau), tuple(torque_pair),
                      where="(a): 0; tau (virtual power of the motor's torque pair)"),
            Published("(b) angular velocities", "expression",
                      (0, 0, v1) + (0, 0, v2) + (0, 0, v1 + v2),
                      inO(w_rod) + tuple(f.C.ang_vel_in(B).express(B).components) + inO(w_disc),
                      where="(b): w_ib = q1' i3, w_bc = q2' b3, w_ic = (q1' + q2') i3"),
            Published("(b) positions and velocities", "expression",
                      (l_c1 * c, l_c1 * s, l1 * c, l1 * s,
                       -l_c1 * s * v1, l_c1 * c * v1, -l1 * s * v1, l1 * c * v1),
                      xy(f.c1.pos_from(f.o)) + xy(f.c2.pos_from(f.o)) + xy(f.c1.vel(O))
                      + xy(f.c2.vel(O)), where="(b): r_C1, r_C2, v_C1, v_C2 in i"),
            Published("(c) T1, T2", "expression",
                      (m1 * (l_c1 * v1)**2 / 2 + I1 * v1**2 / 2,
                       m2 * (l1 * v1)**2 / 2 + I2 * (v1 + v2)**2 / 2),
                      (f.rod.kinetic_energy(O), f.disc.kinetic_energy(O)), where="(c)"),
            Published("(c) U1, U2", "expression",
                      (-m1 * l_c1 * g * c, -m2 * l1 * g * c),
                      (-m1 * g * f.c1.pos_from(f.o).dot(O.x),
                       -m2 * g * f.c2.pos_from(f.o).dot(O.x)), where="(c)"),
            Published("(d) dL/dq1'", "expression",
                      (m1 * l_c1 * a1 + I1 * a1 + m2 * l1**2 * a1 + I2 * (v1 + v2),),
                      (L.diff(v1),), where="(d): WRONG, l_c1 not squared and q1'' for q1' "
                      "in the first three terms"),
            Published("(d) dL/dq1", "expression",
                      (-m1 * l_c1 * g * s - m2 * l1 * g * s,), (L.diff(q1),), where="(d)"),
            Published("(d) q1 equation", "equation",
                      (m1 * l_c1 * a1 + I1 * a1 + m2 * l1**2 * a1 + I2 * (a1 + a2)
                       + m1 * l_c1 * g * s + m2 * l1 * g * s,),
                      where="(d): WRONG, m1 l_c1 q1'' must be m1 l_c1^2 q1''"),
            Published("(d II) dL/dq2', dL/dq2", "expression", (I2 * (a1 + a2), 0),
                      (L.diff(v2), L.diff(q2)),
                      where="(d II): WRONG as extracted, I2 (q1'' + q2'') for I2 (q1' + q2')"),
            Published("(d II) q2 equation", "equation", (I2 * (a1 + a2) - tau,),
                      where="(d II)"),
            Published("(d) equations of motion", "motion",
                      (m1 * l_c1 * a1 + I1 * a1 + m2 * l1**2 * a1 + I2 * (a1 + a2)
                       + m1 * l_c1 * g * s + m2 * l1 * g * s, I2 * (a1 + a2) - tau),
                      where="(d), (d II) together: WRONG, the q1 equation (m1 l_c1 q1'')"),
        ]


PROBLEMS = (InertiaWheelPendulum,)
