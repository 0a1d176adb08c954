r"""Rolling cylinder with an offset point mass (MIT 2.003J, spring 2011, final exam, problem 1).

A uniform cylinder (mass ``M``, radius ``R``; its length does not enter) rolls without slip on
a horizontal plane along ``I``.  A small point mass ``m`` is fixed to its circular base at
distance ``r < R`` from the axis.  Gravity ``-g J``.  One degree of freedom: the angle of
rotation ``theta``.

Sign convention (the source's: ``O v_C = -R theta' I``, so ``theta`` turns counter-clockwise
about K and the cylinder rolls towards ``-I``)::

                 J
                 ^          C = -R theta I + R J        (C above O at theta = 0)
            .----|----.     P = C - r j_B = C + r (sin(theta) I - cos(theta) J)
          /      |      \
         |       C       |   theta: rotation of the body frame B about K
         |        \ r    |
          \        P    /    at theta = 0 the mass hangs straight below C
            '---------'
     ------------Q---------------> I        Q = C - R J, contact point
                F ->  N ^                   ground on cylinder: friction F I, normal N J

Frames::

    O = (O, I, J, K)           ground
    B = O.child(rot_z(theta))  cylinder: i_B, j_B, k_B = K   (j_B = -sin(theta) I + cos(theta) J)

Bodies: the cylinder, a rigid body of mass ``M`` at C with ``M R^2/2`` about its axis; the point
mass, a particle ``m`` at P.  Rolling is built into the kinematics: ``C = -R theta I + R J``.

Free-body diagram of cylinder + mass (one rigid system; the pin force between them is
internal)::

    -M g J at C,   -m g J at P,   F I + N J at Q

Direct form: ``sum F = sum m a`` on I and J, and moments about the moving centre C,
``sum tau_C = dH_C/dt + m_tot v_C x v_G``.  With
``a_C = -R theta'' I`` and ``a_P = a_C + r theta'' (cos I + sin J) + r theta'^2 (-sin I + cos J)``
the forces follow by hand::

    F = -(M + m) R theta'' + m r (theta'' cos(theta) - theta'^2 sin(theta))
    N = (M + m) g + m r (theta'' sin(theta) + theta'^2 cos(theta))

Lagrangian (written independently; ``|v_P|^2 = theta'^2 (R^2 + r^2 - 2 r R cos(theta))``)::

    T = (3/4) M R^2 theta'^2 + (m/2) theta'^2 (R^2 + r^2 - 2 r R cos(theta))
    V = m g (R - r cos(theta))          (the cylinder's height is constant)

    f(theta) theta'' + m r R sin(theta) theta'^2 + m g r sin(theta) = 0,
    f(theta) = (3/2) M R^2 + m (R^2 + r^2 - 2 r R cos(theta)) >= (3/2) M R^2 + m (R - r)^2 > 0

Equilibria ``sin(theta) = 0``: ``theta = 2 n pi`` (mass below C) with stiffness ``m g r > 0``,
stable; ``theta = (2 n + 1) pi`` with ``-m g r``, unstable.  Small oscillations about
``theta = 0``: ``omega_n^2 = m g r / ((3/2) M R^2 + m (R - r)^2)``.

The contact forces once more, as multipliers: free the cylinder's centre ``(x_c, y_c)`` and
close the contact with ``x_c + R theta = 0`` (the contact point's slip: the body point at Q
moves by ``d x_c + R d theta``, so the virtual work of ``F I`` is ``F d(x_c + R theta)``) and
``y_c - R = 0`` (work ``N d y_c``).

Errata found in the printed solution (see :meth:`RollingCylinder.published`):

* (a) the second form of the Lagrangian prints ``m (R^2 + r^2 + 2 r R cos(theta))``; the line
  before it expands to ``m (R^2 + r^2 - 2 r R cos(theta))``.
* (a) the printed equation of motion ``f(theta) theta'' + m g r sin(theta) = 0`` drops the
  term ``m r R sin(theta) theta'^2`` (``d/dt (f theta') - f'(theta) theta'^2/2`` leaves
  ``f'(theta) theta'^2/2 = m r R sin(theta) theta'^2``).  The equilibria, their stability, the
  linearised equations and the period do not depend on that term and are right.

Example
-------
>>> p = RollingCylinder(); p.validate()
>>> p.model("lagrange").equilibria()
[{theta(t): 0}, {theta(t): pi}]
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z,
                      thin_disk, ACCELERATION, ANGLE, FORCE, LENGTH, MASS)

__all__ = ["RollingCylinder", "PROBLEMS", "scene", "hand_reactions", "M", "m", "R", "r", "g",
           "theta", "xc", "yc"]

M, m, R, r, g = sp.symbols("M m R r g", positive=True)
theta = coordinate("theta")
xc, yc = coordinate("x_c"), coordinate("y_c")   # centre of the cylinder, multiplier model only


def scene() -> SimpleNamespace:
    """Frames, points and bodies of the direct form (rolling built into C's position)."""
    O = Frame.ground("O")
    B = O.child("B", rot_z(theta))
    o = Point.origin(O, "O")
    C = o.locate("C", -R * theta * O.x + R * O.y)
    P = C.locate("P", -r * B.y)
    Q = C.locate("Q", -R * O.y)
    # about its axis a uniform cylinder has M R^2/2 whatever its length (the thin disk's value)
    cylinder = RigidBody("cylinder", M, C, B, thin_disk(M, R, normal="z"))
    return SimpleNamespace(O=O, B=B, o=o, C=C, P=P, Q=Q, cylinder=cylinder,
                           mass=Particle("m", m, P))


def hand_reactions() -> dict:
    """``{"F": ..., "N": ...}`` by hand, in ``theta, theta', theta''`` (module docstring)."""
    th1, th2 = rate(theta), rate(theta, 2)
    s, c = sp.sin(theta), sp.cos(theta)
    return {"F": -(M + m) * R * th2 + m * r * (th2 * c - th1**2 * s),
            "N": (M + m) * g + m * r * (th2 * s + th1**2 * c)}


class RollingCylinder(Problem):
    """Cylinder rolling without slip with a point mass fixed off its axis."""

    name = "rolling_cylinder"
    title = "Rolling cylinder with an offset point mass"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, final exam, problem 1"
    summary = ("Rolling without slip; friction and normal force twice; equilibria, stability "
               "and period by the library; the printed equation of motion drops a term.")
    parameters = (
        Parameter(M, MASS, 2.0, (0.2, 10.0), "mass of the cylinder"),
        Parameter(m, MASS, 0.5, (0.05, 5.0), "point mass"),
        Parameter(R, LENGTH, 0.3, (0.2, 1.0), "radius of the cylinder"),
        Parameter(r, LENGTH, 0.15, (0.02, 0.19), "distance of the point mass from the axis"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "rotation of the cylinder"),
    )
    extra_coordinates = (
        Coordinate(xc, LENGTH, (-1.0, 1.0), (-2.0, 2.0), "horizontal position of the centre"),
        Coordinate(yc, LENGTH, (0.1, 1.0), (-0.5, 0.5), "height of the centre"),
    )
    reactions = (
        Reaction("F", FORCE, "friction, ground on cylinder at the contact point, along I"),
        Reaction("N", FORCE, "normal force, ground on cylinder at the contact point, along J"),
    )
    extra_models = ("multiplier",)
    unilateral = {"N": "the cylinder lifts off the ground"}

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, xc: -R * theta, yc: R}}

    # -- direct form -----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """Cylinder + mass: forces on I and J, moments about the centre C on K."""
        s = scene()
        O = s.O
        ne = NewtonEuler(coordinates=[theta], ground=O,
                         description="cylinder and mass as one free body")
        ne.gravity(-g * O.y)
        ne.reaction("F", s.cylinder, O.x, at=s.Q)
        ne.reaction("N", s.cylinder, O.y, at=s.Q)
        system = [s.cylinder, s.mass]
        ne.linear_momentum(system, O.x)
        ne.linear_momentum(system, O.y)
        ne.angular_momentum(system, O.z, about=s.C)
        return ne.equations()

    # -- indirect forms --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` by hand, rolling built in (``v_C = -R theta'``)."""
        lg = Lagrangian(coordinates=[theta], description="T and V by hand")
        lg.kinetic("T of cylinder", M * (R * rate(theta))**2 / 2 + M * R**2 * rate(theta)**2 / 4)
        lg.kinetic("T of m", m * rate(theta)**2 * (R**2 + r**2 - 2 * r * R * sp.cos(theta)) / 2)
        lg.potential("gravity", m * g * (R - r * sp.cos(theta)))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Centre freed; rolling and contact closed by the multipliers ``F`` and ``N``."""
        lg = Lagrangian("multiplier", coordinates=[theta, xc, yc],
                        description="contact freed, closed by multipliers F and N")
        P = sp.Matrix([xc + r * sp.sin(theta), yc - r * sp.cos(theta)])
        lg.kinetic("T of cylinder", M * (rate(xc)**2 + rate(yc)**2) / 2 + M * R**2 * rate(theta)**2 / 4)
        lg.kinetic("T of m", m * (rate(P).T * rate(P))[0, 0] / 2)
        lg.potential("gravity", M * g * yc + m * g * P[1])
        lg.constraint("F", xc + R * theta)
        lg.constraint("N", yc - R)
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        s = scene()
        O = s.O
        I, J = O.x, O.y
        st, ct = sp.sin(theta), sp.cos(theta)
        th1, th2 = rate(theta), rate(theta, 2)
        inO = lambda v: tuple(v.express(O).components[:2])  # noqa: E731
        T = s.cylinder.kinetic_energy(O) + s.mass.kinetic_energy(O)
        V = m * g * s.P.pos_from(s.o).dot(J)       # the source's -m r_P . g
        lag = self.model("lagrange")
        M0, _, K0 = lag.linearize({theta: 0})
        Mpi, _, Kpi = lag.linearize({theta: sp.pi})
        (w_n,) = lag.natural_frequencies({theta: 0})
        f = sp.Rational(3, 2) * M * R**2 + m * (R**2 + r**2 - 2 * r * R * ct)
        sigma, mu = R / r, M / m
        where = "final exam, problem 1"
        return [
            Published("(a) v_C", "expression", (-R * th1, 0), inO(s.C.vel(O)),
                      where=f"{where} (a)"),
            Published("(a) v_P", "expression", inO(-R * th1 * I + r * th1 * (ct * I + st * J)),
                      inO(s.P.vel(O)), where=f"{where} (a)"),
            Published("(a) r_P", "expression",
                      inO(-R * theta * I + R * J + r * (st * I - ct * J)),
                      inO(s.P.pos_from(s.o)), where=f"{where} (a)"),
            Published("(a) L", "expression",
                      (M * R**2 * th1**2 / 2 + M * R**2 * th1**2 / 4
                       + m * th1**2 * ((R - r * ct)**2 + r**2 * st**2) / 2
                       - m * g * (R - r * ct),), (T - V,),
                      where=f"{where} (a), first form (constant M g R left out)"),
            Published("(a) L, second form", "expression",
                      ((sp.Rational(3, 2) * M * R**2 + m * (R**2 + r**2 + 2 * r * R * ct))
                       * th1**2 / 2 - m * g * (R - r * ct),), (T - V,),
                      where=f"{where} (a): WRONG, + 2 r R cos(theta); the first form expands "
                      "to - 2 r R cos(theta)"),
            Published("(a) equation of motion", "motion", (f * th2 + m * g * r * st,),
                      where=f"{where} (a), (b), (c): WRONG, the term m r R sin(theta) "
                      "theta'^2 is missing"),
            Published("(c) f(theta), h(theta)", "expression", (f, m * g * r * st),
                      (lag.mass_matrix()[0], V.diff(theta)),
                      where=f"{where} (c): f = mass matrix, h = dV/dtheta"),
            Published("(c) linearised, n even", "expression",
                      (sp.Rational(3, 2) * M * R**2 + m * (R - r)**2, m * g * r),
                      (M0[0], K0[0]), where=f"{where} (c), about theta = 0"),
            Published("(c) linearised, n odd", "expression",
                      (sp.Rational(3, 2) * M * R**2 + m * (R + r)**2, -m * g * r),
                      (Mpi[0], Kpi[0]), where=f"{where} (c), about theta = pi"),
            Published("(c) omega_n", "expression",
                      (sp.sqrt(m * g * r / (sp.Rational(3, 2) * M * R**2 + m * (R - r)**2)),),
                      (w_n,), where=f"{where} (c)"),
            Published("(c) T_n", "expression",
                      (2 * sp.pi * sp.sqrt((sp.Rational(3, 2) * M * R**2 + m * (R - r)**2)
                                           / (m * g * r)),), (2 * sp.pi / w_n,),
                      where=f"{where} (c)"),
            Published("(c) T_n in sigma, mu", "expression",
                      (2 * sp.pi * sp.sqrt(r / g)
                       * sp.sqrt((sigma - 1)**2 + sp.Rational(3, 2) * mu * sigma**2),),
                      (2 * sp.pi / w_n,), where=f"{where} (c), sigma = R/r, mu = M/m"),
        ]


PROBLEMS = (RollingCylinder,)
