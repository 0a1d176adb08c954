r"""Rod-and-disk pendulum on a spring-mounted mass (MIT 2.003J, spring 2011, quiz 2, problem 1).

A mass ``M`` slides without friction in a vertical shaft, hung from the ceiling O by a spring
``k`` (unstretched when ``O r_A = -l0 J``).  At A hangs a rigid pendulum: a thin rod (mass
``m``, length ``4r``) with a thin disk (mass ``2m``, radius ``r``, face in the plane of motion)
centred on its end, 5r from A.  The pivot A is frictionless; the motion is planar.

Sign convention (motion in the I-J plane, K out of the page)::

        ///////////  O (ceiling)
             |             J
             >  k          ^
             <             |
           +-+-+           +--> I
           | M | A         y grows downwards: O r_A = -(l0 + y) J
           +-+-+
              \            theta from the downward vertical, counter-clockwise (about K):
               \ rod 4r     A r_B = 5r (sin(theta) I - cos(theta) J) = -5r j_A
                \
                 ( B )  disk, radius r, centre B; mass centre C of the pendulum at -4r j_A

Frames::

    O = (O, I, J, K)                           ground, gravity -g J
    A = O.child(rot_z(theta), -(l0 + y) J)     pendulum: i_A, j_A, k_A = K

Bodies: ``M`` is a particle at A (it only translates); the pendulum is one rigid body of mass
``3m`` with mass centre ``C = A - 4r j_A`` and, by :func:`~dualmech.model.bodies.composite`, inertia
about A ``m r^2 diag(335/6, 1/2, 169/3)`` in A axes (about C: ``169/3 - 3*16 = 25/3`` on K).

Free-body diagrams (as the source draws them)::

    M:         spring  k y J,  weight -M g J,  shaft -F_N I,  pivot  F_Rx I + F_Ry J
    pendulum:  weight -3 m g J (at C),          pivot -F_Rx I - F_Ry J (at A)

Direct form: Newton for M on I and J, Newton for the pendulum on I and J, Euler for the
pendulum about the moving pivot A on K (``sum tau_A = dH_A/dt + 3m v_A x v_C``)::

    J, M:     M y'' + k y + F_Ry = M g
    J, pend: -3m y'' + 12 r m (theta'' sin(theta) + theta'^2 cos(theta)) = -3 m g - F_Ry
    I, M:     F_Rx - F_N = 0
    I, pend:  12 r m (theta'' cos(theta) - theta'^2 sin(theta)) = -F_Rx
    K, A:     (169/3) m r^2 theta'' + 12 m g r sin(theta) = 12 m r y'' sin(theta)

Lagrangian, written independently, with
``v_C = 4 r theta' cos(theta) I + (4 r theta' sin(theta) - y') J``::

    T = M y'^2/2 + (3/2) m [(4 r theta' sin(theta) - y')^2 + 16 r^2 theta'^2 cos^2(theta)]
        + (25/6) m r^2 theta'^2
    V = -M g y - 3 m g (y + 4 r cos(theta)) + k y^2/2

The reactions a second time, independently (``multiplier``): free M from the shaft by ``x``
(M at ``(x, -(l0 + y))``) and the pendulum from M by a pivot gap ``(p, q)`` (its pin at
M's pin plus ``(p, q)``), and close them by ``-x = 0`` (multiplier ``F_N``: the shaft pushes M
along ``-I``), ``-p = 0`` and ``-q = 0`` (multipliers ``F_Rx``, ``F_Ry``: the pair ``F_R`` on
M, ``-F_R`` on the pendulum does the virtual work ``-F_R . (dp, dq)``)::

    T = M (x'^2 + y'^2)/2 + (3/2) m |v_C|^2 + (25/6) m r^2 theta'^2,
    C = (x + p + 4 r sin(theta), -(l0 + y) + q - 4 r cos(theta))

The mass matrix ``[[M + 3m, -12 m r sin], [-12 m r sin, 169/3 m r^2]]`` has determinant
``m r^2 (169/3 M + 169 m - 144 m sin^2) > 0``: no singular configuration.

Errata found in the printed solution (see :meth:`PendulumOnMass.published`):

* (b) the inertia tensor about A is printed ``m r^2 diag(331/6, 1/2, 169/3)`` (and
  ``(1/6) m r^2 diag(331, 3, 338)``); the ``i_A`` entry is ``16/3 + 1/2 + 50 = 335/6``:
  rod ``4/3 + 4``, disk across a diameter ``1/2``, parallel axis ``2m (5r)^2 = 50``.
  The K-K component ``169/3 m r^2`` asked for is right.
* (c) the torque of gravity about A is multiplied out as ``(-4r j_A) x (-m g J)``; the weight
  of the pendulum is ``-3 m g J``.  The printed result ``-12 r m g sin(theta) K`` is right.
* (c) Lagrange: ``dL/dtheta'`` is printed ``48 m r^2 theta' - 12 m r y' sin(theta)
  + (25/6) m r^2 theta'``; the last term is ``(25/3) m r^2 theta'`` (its derivative on the next
  line is printed right).
* (c) ``V`` drops the constant ``-(M + 3m) g l0``; harmless (Lagrange's equations ignore it).
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, MassProperties, NewtonEuler,
                      Parameter, Particle, Point, Problem, Published, Reaction, RigidBody,
                      composite, coordinate, rate, rot_z, t, thin_disk, thin_rod, ACCELERATION,
                      ANGLE, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["PendulumOnMass", "PROBLEMS", "frames", "pendulum_mass_properties", "kinetic_energy",
           "potential_energy",
           "M", "m", "r", "k", "g", "l0", "y", "theta"]

M, m, r, k, g, l0 = sp.symbols("M m r k g l0", positive=True)
y, theta = coordinate("y"), coordinate("theta")
# multiplier model only: M off the shaft by x; the pendulum's pivot off M by the gap (p, q)
x, p, q = coordinate("x"), coordinate("p"), coordinate("q")
F_N, F_Rx, F_Ry = sp.symbols("F_N F_Rx F_Ry", real=True)


def pendulum_mass_properties() -> MassProperties:
    """Rod (``m``, length ``4r``, centre ``-2r j_A``) + disk (``2m``, radius ``r``, at ``-5r j_A``).

    Components in A axes, positions from the pivot A.

    >>> pendulum_mass_properties().center.T
    Matrix([[0, -4*r, 0]])
    """
    return composite([(m, thin_rod(m, 4 * r, axis="y"), sp.Matrix([0, -2 * r, 0])),
                      (2 * m, thin_disk(2 * m, r, normal="z"), sp.Matrix([0, -5 * r, 0]))])


def frames() -> SimpleNamespace:
    """Frames, points and bodies of the direct form.

    ``O``, ``A`` (frames); ``a`` (pivot, where M is), ``c`` (pendulum's mass centre), ``b``
    (disk centre); ``mass`` (particle M) and ``pendulum`` (rigid body in A).
    """
    O = Frame.ground("O")
    A = O.child("A", rot_z(theta), origin=-(l0 + y) * O.y)
    a = Point.origin(O, "O").locate("A", -(l0 + y) * O.y)
    props = pendulum_mass_properties()
    c = a.locate("C", A.vector(props.center))
    b = a.locate("B", -5 * r * A.y)
    mass = Particle("M", M, a)
    pendulum = RigidBody("pendulum", props.mass, c, A, props.inertia)
    return SimpleNamespace(O=O, A=A, a=a, b=b, c=c, mass=mass, pendulum=pendulum)


class PendulumOnMass(Problem):
    """Spring-mounted sliding mass carrying a rod-and-disk pendulum (see module doc)."""

    name = "pendulum_on_mass"
    title = "Rod-and-disk pendulum on a spring-mounted mass"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, quiz 2, problem 1"
    summary = ("Mass on a vertical spring in a shaft carrying a compound pendulum: Euler's "
               "equation about a moving pivot; pivot and shaft forces recovered.")
    parameters = (
        Parameter(M, MASS, 1.0, (0.1, 10.0), "sliding mass"),
        Parameter(m, MASS, 0.2, (0.01, 5.0), "mass of the rod (the disk has 2m)"),
        Parameter(r, LENGTH, 0.1, (0.01, 1.0), "disk radius (rod 4r, pivot to disk 5r)"),
        Parameter(k, STIFFNESS, 100.0, (1.0, 1.0e4), "spring constant"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(l0, LENGTH, 1.0, (0.1, 5.0), "ceiling to A, spring unstretched"),
    )
    coordinates = (
        Coordinate(y, LENGTH, (-0.5, 0.5), (-2.0, 2.0), "drop of M from the unstretched spring"),
        Coordinate(theta, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "pendulum angle from the vertical"),
    )
    reactions = (
        Reaction("F_N", FORCE, "along -I, shaft on M"),
        Reaction("F_Rx", FORCE, "along I, pendulum on M at A (-F_Rx I on the pendulum)"),
        Reaction("F_Ry", FORCE, "along J, pendulum on M at A (-F_Ry J on the pendulum)"),
    )
    extra_coordinates = (
        Coordinate(x, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "M off the shaft, along I"),
        Coordinate(p, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "pivot gap along I (pendulum from M)"),
        Coordinate(q, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "pivot gap along J (pendulum from M)"),
    )
    extra_models = ("multiplier",)
    singular = ()

    def coordinate_maps(self) -> dict:
        return {"multiplier": {y: y, theta: theta, x: 0, p: 0, q: 0}}

    # -- direct form (question c) ----------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        f = frames()
        O, mass, pend = f.O, f.mass, f.pendulum
        ne = NewtonEuler(coordinates=[y, theta], ground=O,
                         description="Newton for M and the pendulum, Euler about the pivot A")
        ne.gravity(-g * O.y)
        ne.linear_spring("spring", mass, k, y, -O.y)  # y grows as M moves along -J
        ne.reaction("F_N", mass, -O.x)
        ne.reaction("F_Rx", mass, O.x, against=pend, against_at=f.a)
        ne.reaction("F_Ry", mass, O.y, against=pend, against_at=f.a)
        ne.linear_momentum(mass, O.x)
        ne.linear_momentum(mass, O.y)
        ne.linear_momentum(pend, O.x)
        ne.linear_momentum(pend, O.y)
        ne.angular_momentum(pend, O.z, about=f.a)
        return ne.equations()

    # -- the reactions a second time -------------------------------------------------------
    def multiplier(self) -> EquationSet:
        """M freed from the shaft by ``x`` and the pendulum from M by a pivot gap ``(p, q)``;
        ``F_N``, ``F_Rx``, ``F_Ry`` are the multipliers that close them (module doc)."""
        lg = Lagrangian("multiplier", coordinates=[y, theta, x, p, q],
                        description="shaft and pivot freed, closed by F_N, F_Rx, F_Ry")
        s, c = sp.sin(theta), sp.cos(theta)
        A_M = sp.Matrix([x, -(l0 + y)])                     # M (and its pin)
        C = A_M + sp.Matrix([p, q]) + 4 * r * sp.Matrix([s, -c])   # pendulum's mass centre
        lg.kinetic("T of M", M * (rate(A_M).T * rate(A_M))[0, 0] / 2)
        lg.kinetic("T of pendulum (mass centre)", 3 * m * (rate(C).T * rate(C))[0, 0] / 2)
        lg.kinetic("T of pendulum (spin about C)", sp.Rational(25, 3) * m * r**2
                   * rate(theta)**2 / 2)
        lg.potential("gravity", M * g * A_M[1] + 3 * m * g * C[1])
        lg.spring("spring", k, y)
        lg.constraint("F_N", -x)        # shaft on M along -I: gradient -I at M
        lg.constraint("F_Rx", -p)       # F_R on M, -F_R on the pendulum: work -F_R . d(p, q)
        lg.constraint("F_Ry", -q)
        return lg.equations()

    # -- indirect form ---------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        lg = Lagrangian(coordinates=[y, theta], description="T and V written by hand")
        for key, T in kinetic_energy().items():
            lg.kinetic(key, T)
        for key, V in potential_energy().items():
            lg.potential(key, V)
        return lg.equations()

    # -- the source's answers ---------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        O, A, pend = f.O, f.A, f.pendulum
        s, c = sp.sin(theta), sp.cos(theta)
        y1, y2, th1, th2 = rate(y), rate(y, 2), rate(theta), rate(theta, 2)
        mr2 = m * r**2
        I_A = pend.inertia_about(f.a).applyfunc(sp.trigsimp)  # A r_C in A axes: (0, -4r, 0)
        T_ref = (f.mass.kinetic_energy(O) + pend.kinetic_energy(O))
        V_ref = (M * g * f.a.pos_from().dot(O.y) + 3 * m * g * f.c.pos_from().dot(O.y)
                 + k * y**2 / 2)
        L = sum(kinetic_energy().values()) - sum(potential_energy().values())
        tau_A = f.c.pos_from(f.a).cross(-3 * m * g * O.y).dot(O.z)
        return [
            Published("(b) inertia about A", "expression",
                      tuple(mr2 * sp.diag(sp.Rational(331, 6), sp.Rational(1, 2),
                                          sp.Rational(169, 3))), tuple(I_A),
                      where="quiz 2 (b): WRONG, i_A entry printed 331/6, is 16/3 + 1/2 + 50 "
                      "= 335/6 (rod 4/3 + 4, disk 1/2, parallel axis 2m(5r)^2)"),
            Published("(b) K-K component", "expression", (sp.Rational(169, 3) * mr2,),
                      (I_A[2, 2],), where="quiz 2 (b), boxed"),
            Published("(c) mass centre", "expression", (0, -4 * r, 0),
                      tuple(pendulum_mass_properties().center), where="quiz 2 (c): A r_C"),
            Published("(c) Newton, M, J", "equation", (M * y2 + k * y + F_Ry - M * g,),
                      where="quiz 2 (c), underlined"),
            Published("(c) Newton, pendulum, J", "equation",
                      (-3 * m * y2 + 12 * r * m * (th2 * s + th1**2 * c) + 3 * m * g + F_Ry,),
                      where="quiz 2 (c), underlined"),
            Published("(c) combined y equation", "equation",
                      ((M + 3 * m) * y2 - 12 * r * m * (th2 * s + th1**2 * c) + k * y
                       - (M + 3 * m) * g,), where="quiz 2 (c), and again from Lagrange"),
            Published("(c) torque about A, multiplied out", "expression",
                      ((-4 * r * A.y).cross(-m * g * O.y).dot(O.z),), (tau_A,),
                      where="quiz 2 (c): WRONG, (-4r j_A) x (-m g J); the weight is -3 m g J"),
            Published("(c) torque about A", "expression", (-12 * r * m * g * s,), (tau_A,),
                      where="quiz 2 (c): -12 r m g sin(theta) K"),
            Published("(c) theta equation", "equation",
                      (sp.Rational(169, 3) * mr2 * th2 + 12 * m * g * r * s
                       - 12 * m * r * y2 * s,), where="quiz 2 (c), Euler about A and Lagrange"),
            Published("(c) T", "expression",
                      (M * y1**2 / 2 + sp.Rational(3, 2) * m * ((4 * r * th1 * s - y1)**2
                                                                 + 16 * r**2 * th1**2 * c**2)
                       + sp.Rational(25, 6) * mr2 * th1**2,), (T_ref,),
                      where="quiz 2 (c), Lagrange; reference from the direct model's bodies"),
            Published("(c) V", "expression",
                      (-M * g * y - 3 * m * g * (y + 4 * r * c) + k * y**2 / 2,),
                      (V_ref + (M + 3 * m) * g * l0,),
                      where="quiz 2 (c): right up to the dropped constant -(M + 3m) g l0"),
            Published("(c) dL/dtheta'", "expression",
                      (48 * mr2 * th1 - 12 * m * r * y1 * s + sp.Rational(25, 6) * mr2 * th1,),
                      (L.diff(th1),),
                      where="quiz 2 (c): WRONG, 25/6 m r^2 theta' should be 25/3 m r^2 theta'"),
            Published("(c) d/dt dL/dtheta'", "expression",
                      (48 * mr2 * th2 - 12 * m * r * y2 * s - 12 * m * r * th1 * y1 * c
                       + sp.Rational(25, 3) * mr2 * th2,), (L.diff(th1).diff(t),),
                      where="quiz 2 (c), Lagrange"),
            Published("(c) dL/dtheta", "expression",
                      (-12 * m * r * th1 * y1 * c - 12 * m * g * r * s,),
                      (L.diff(theta),),
                      where="quiz 2 (c), Lagrange"),
        ]


def kinetic_energy() -> dict:
    """``T`` by hand, as the source writes it: M, the pendulum's mass centre, its spin about C."""
    y1, th1 = rate(y), rate(theta)
    s, c = sp.sin(theta), sp.cos(theta)
    return {
        "T of M": M * y1**2 / 2,
        "T of pendulum, translation": sp.Rational(3, 2) * m * ((4 * r * th1 * s - y1)**2
                                                                + 16 * r**2 * th1**2 * c**2),
        "T of pendulum, rotation about C": sp.Rational(25, 6) * m * r**2 * th1**2,
    }


def potential_energy() -> dict:
    """``V`` by hand: heights of A and C (constant ``l0`` dropped), spring extension ``y``."""
    return {"gravity": -M * g * y - 3 * m * g * (y + 4 * r * sp.cos(theta)),
            "spring": k * y**2 / 2}


PROBLEMS = (PendulumOnMass,)
