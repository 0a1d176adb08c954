r"""Compound double pendulum: a rigid body on a light link (Cambridge 3C5, Lagrangian mechanics).

Source: ``sources/002_df41972c66c4514e.txt``, section 3, "Lagrange example: Double Pendulum"
("Example: Lagrange's equation for a compound pendulum").

The system, as the printed ``T`` and ``V`` describe it (the figure is missing): a light
(massless) link of length ``a`` hangs from a fixed pivot O; at its end A hangs a rigid body of
mass ``m`` and moment of inertia ``I0`` about its mass centre G, which lies a distance ``b``
from A.  Both angles are measured from the downward vertical.

Sign convention::

              O  pivot                 i (right), j (up), k = i x j out of the page
              |\                       gravity -g j
              | \  a  (light link)     link frame L1 = rot_z(theta1), body frame L2 = rot_z(theta2)
              |th1\                    r_A = -a L1.y = a (sin th1, -cos th1)
              |    A  hinge            r_G = r_A - b L2.y
              |    |\
              |    |th2\  b
                         G  body: mass m, I0 about G (axis k)

Frames.  ``O`` inertial; ``L1 = O`` rotated by ``theta1`` about ``k``; ``L2 = O`` rotated by
``theta2`` about ``k`` (absolute angles, as the source uses).

Bodies.  The body: a rigid body ``m`` fixed in ``L2`` with ``I_zz = I0`` about G (the other
moments never enter plane motion).  The link: a massless rigid body in ``L1``.

Free-body diagrams (Newton--Euler).  Body: weight ``-m g j`` at G, the hinge force
``R = R_x i + R_y j`` at A.  Link: ``-R`` at A and the pivot's force at O (it has no moment
about O and is not needed).  With ``a_G = d^2 r_G / dt^2``::

        body . i:        m a_G . i = R_x
        body . j:        m a_G . j = R_y - m g
        body, about G:   I0 th2''  = ((r_A - r_G) x R) . k
        link, about O:   0         = (r_A x (-R)) . k        (R is along the link)

A second direct derivation without reactions: moments about O for link + body (the hinge
force is internal, the pivot's passes through O), and about the moving hinge A for the body.

The hinge force a second time, independently (``multiplier``): free the hinge by a gap
``(u, v)`` between the link's end A and the body's hinge point, so that
``r_G = r_A + (u, v) - b L2.y``, and close it by ``u = 0`` (multiplier ``R_x``) and ``v = 0``
(multiplier ``R_y``): the pair ``R`` on the body and ``-R`` on the link does the virtual work
``R_x du + R_y dv``, so the multipliers are the hinge force on the body.

Lagrangian (written independently; the source's second form of T)::

        T = m (a^2 th1'^2 + b^2 th2'^2 + 2 a b th1' th2' cos(th1 - th2)) / 2 + I0 th2'^2 / 2
        V = -m g (a cos th1 + b cos th2)

        th1:  m a^2 th1'' + m a b th2'' cos(th1 - th2) + m a b th2'^2 sin(th1 - th2)
                + m g a sin th1 = 0
        th2:  (m b^2 + I0) th2'' + m a b th1'' cos(th1 - th2) - m a b th1'^2 sin(th1 - th2)
                + m g b sin th2 = 0

Errata found in the printed solution (see :meth:`CompoundDoublePendulum.published`):

* The ``theta1`` equation "divided through" is printed
  ``a th1'' + b th2'' cos(th1 - th2) + b th2'^2 sin(th1 - th2) + g a sin th1 = 0``: dividing
  by ``m a`` gives ``g sin th1``; the printed gravity term keeps a factor ``a`` (it has
  dimension L^2 T^-2 where the rest has L T^-2).
* The ``theta2`` equation "finally" is printed
  ``3 b th2'' + a th1'' cos(th1 - th2) - a th1'^2 sin(th1 - th2) + g b sin th2 = 0``.  The
  sentence before it is unreadable ("ship has I_0 . 3mb^2"); the coefficient ``3 b`` is what
  ``(m b^2 + I0)/(m b)`` becomes for ``I0 = 2 m b^2`` (i.e. ``I0 + m b^2 = 3 m b^2``).  Even
  then the gravity term must be ``g sin th2``: the printed ``g b sin th2`` keeps a factor
  ``b``, as in the ``theta1`` equation.  For any other ``I0`` the coefficient ``3 b`` is wrong
  too.  The tests pin both.
* ``dT/dth2'`` is printed ``m b^2 th1' + m a b th1' cos(th1 - th2) + I0 th2'``: the first term
  must be ``m b^2 th2'`` (the next line differentiates it as ``m b^2 th2''``, so this may be a
  slip of the pen or of the extraction).

Reading the extraction.  ``T`` is printed ``1/(2m) [...]`` for ``(m/2) [...]`` (the ``m`` slid
under the fraction bar).  In the two printed Lagrange's equations the extraction renders every
dotted angle alike (``\vec\theta``), and the ``theta2`` equation shows ``th1''^2``; they are
read with the dots the preceding lines (``d/dt dT/dth'`` and ``dT/dth``) imply.  The
``theta2`` derivative lines are headed by garbled labels (``1_0``, ``10 mgb sin``), read as
``dT/dth2'``, ``d/dt [dT/dth2']``, ``dT/dth2`` and ``dV/dth2`` from their content.

Example
-------
>>> p = CompoundDoublePendulum(); p.validate()
>>> p.model("newton_euler").unknowns
(R_x, R_y)
>>> p.model("lagrange").mass_matrix()[1, 1]
I0 + b**2*m
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, Drawing, EquationSet, Frame, Lagrangian, NewtonEuler,
                      Parameter, Point, Problem, Published, Reaction, RigidBody, coordinate,
                      rate, rot_z, t, ACCELERATION, ANGLE, FORCE, INERTIA, LENGTH, MASS)

__all__ = ["CompoundDoublePendulum", "PROBLEMS", "m", "a", "b", "I0", "g", "theta1", "theta2",
           "printed_reduced", "scene"]

m, a, b, I0, g = sp.symbols("m a b I0 g", positive=True)
theta1, theta2 = coordinate("theta1"), coordinate("theta2")
u, v = coordinate("u"), coordinate("v")   # the hinge freed (multiplier model only)


def printed_reduced() -> tuple[sp.Expr, sp.Expr]:
    """The two equations the source prints last ("divided through"), left sides."""
    d = theta1 - theta2
    e1 = (a * rate(theta1, 2) + b * rate(theta2, 2) * sp.cos(d) + b * rate(theta2)**2 * sp.sin(d)
          + g * a * sp.sin(theta1))
    e2 = (3 * b * rate(theta2, 2) + a * rate(theta1, 2) * sp.cos(d) - a * rate(theta1)**2 * sp.sin(d)
          + g * b * sp.sin(theta2))
    return e1, e2


class _Scene:
    """Frames, points and bodies of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.L1 = self.O.child("L1", rot_z(theta1))
        self.L2 = self.O.child("L2", rot_z(theta2))
        self.o = Point.origin(self.O, "pivot")
        self.A = self.o.locate("A", -a * self.L1.y)
        self.G = self.A.locate("G", -b * self.L2.y)
        self.body = RigidBody("body", m, self.G, self.L2, sp.diag(0, 0, I0))
        self.link = RigidBody("link", sp.Integer(0), self.o.locate("mid", -a / 2 * self.L1.y),
                              self.L1, sp.zeros(3, 3))


def scene() -> _Scene:
    """Frames ``O, L1, L2``, points ``o, A, G`` and bodies ``body, link`` of the direct form."""
    return _Scene()


class CompoundDoublePendulum(Problem):
    """Rigid body (``m``, ``I0``, centre ``b`` below the hinge) on a light link ``a``."""

    name = "compound_double_pendulum"
    title = "Compound double pendulum"
    source = "002_df41972c66c4514e.txt: section 3, Lagrange example: double pendulum"
    summary = ("A rigid body hinged to a light link: hinge force from the free-body "
               "diagrams; the printed 'divided through' equations keep a length in the "
               "gravity term.")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "mass of the body"),
        Parameter(a, LENGTH, 0.5, (0.1, 2.0), "length of the light link"),
        Parameter(b, LENGTH, 0.3, (0.05, 2.0), "distance of the body's mass centre from the hinge"),
        Parameter(I0, INERTIA, 0.02, (0.001, 2.0), "moment of inertia of the body about G"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta1, ANGLE, (-2.5, 2.5), (-4.0, 4.0), "link angle from the downward vertical"),
        Coordinate(theta2, ANGLE, (-2.5, 2.5), (-4.0, 4.0), "body angle (A to G) from the downward vertical"),
    )
    reactions = (
        Reaction("R_x", FORCE, "hinge on body, along i"),
        Reaction("R_y", FORCE, "hinge on body, along j"),
    )
    extra_coordinates = (
        Coordinate(u, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "hinge gap along i (body from link)"),
        Coordinate(v, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "hinge gap along j (body from link)"),
    )
    extra_models = ("moments", "multiplier")
    chaotic_state = (2.0, 2.5, 0.0, 0.0)   # both released at rest, high: a chaotic motion
    # pictures: the link from the pivot to the hinge A, the body from A to its centre G
    drawing = Drawing({"O": (0, 0), "A": (a * sp.sin(theta1), -a * sp.cos(theta1)),
                       "G": (a * sp.sin(theta1) + b * sp.sin(theta2),
                             -a * sp.cos(theta1) - b * sp.cos(theta2))},
                      lines=(("O", "A", "G"),), view=("x", "y"))

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta1: theta1, theta2: theta2, u: 0, v: 0}}

    def newton_euler(self) -> EquationSet:
        """Body: forces along ``i``, ``j`` and moments about G; light link: moments about O."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta1, theta2], ground=sc.O,
                         description="free-body diagrams of the body and the light link")
        ne.gravity(-g * sc.O.y)
        ne.reaction_vector("R", sc.body, sc.O, "xy", at=sc.A, against=sc.link, against_at=sc.A)
        ne.linear_momentum(sc.body, sc.O.x)
        ne.linear_momentum(sc.body, sc.O.y)
        ne.angular_momentum(sc.body, sc.O.z)
        ne.angular_momentum(sc.link, sc.O.z, about=sc.o)
        return ne.equations()

    def moments(self) -> EquationSet:
        """No reactions: link + body about the pivot O, the body about the moving hinge A."""
        sc = _Scene()
        ne = NewtonEuler("moments", coordinates=[theta1, theta2], ground=sc.O,
                         description="moments about O (whole system) and about A (body)")
        ne.gravity(-g * sc.O.y)
        ne.angular_momentum([sc.link, sc.body], sc.O.z, about=sc.o)
        ne.angular_momentum(sc.body, sc.O.z, about=sc.A)
        return ne.equations()

    def multiplier(self) -> EquationSet:
        """The hinge freed by a gap ``(u, v)`` between link end and body, closed again by the
        multipliers ``R_x``, ``R_y`` (module doc): the hinge force a second time."""
        lg = Lagrangian("multiplier", coordinates=[theta1, theta2, u, v],
                        description="hinge freed by (u, v), held by R_x and R_y")
        G = sp.Matrix([a * sp.sin(theta1) + u + b * sp.sin(theta2),
                       -a * sp.cos(theta1) + v - b * sp.cos(theta2)])
        lg.kinetic("T of body (translation)", m * (rate(G).T * rate(G))[0, 0] / 2)
        lg.kinetic("T of body (rotation)", I0 * rate(theta2)**2 / 2)
        lg.potential("gravity", m * g * G[1])
        lg.constraint("R_x", u)
        lg.constraint("R_y", v)
        return lg.equations()

    def lagrange(self) -> EquationSet:
        """The source's second form of ``T`` and its ``V``."""
        lg = Lagrangian("lagrange", coordinates=[theta1, theta2], description="T and V by hand")
        lg.kinetic("T of body (translation)",
                   m * (a**2 * rate(theta1)**2 + b**2 * rate(theta2)**2
                        + 2 * a * b * rate(theta1) * rate(theta2) * sp.cos(theta1 - theta2)) / 2)
        lg.kinetic("T of body (rotation)", I0 * rate(theta2)**2 / 2)
        lg.potential("gravity", -m * g * (a * sp.cos(theta1) + b * sp.cos(theta2)))
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        rG, vG = sc.G.pos_from(sc.o), sc.G.vel(sc.O)
        T_ref = sc.body.kinetic_energy(sc.O)
        V_ref = m * g * rG.dot(sc.O.y)
        d = theta1 - theta2
        c, s = sp.cos(d), sp.sin(d)
        th1, th2, w1, w2, al1, al2 = (theta1, theta2, rate(theta1), rate(theta2), rate(theta1, 2),
                                      rate(theta2, 2))
        e1, e2 = printed_reduced()
        where = "section 3, double pendulum"
        return [
            Published("horizontal position and velocity of G", "expression",
                      (a * sp.sin(th1) + b * sp.sin(th2), a * w1 * sp.cos(th1) + b * w2 * sp.cos(th2)),
                      (rG.dot(sc.O.x), vG.dot(sc.O.x)), where=where),
            # measured downwards: the printed velocity is d/dt of the printed position
            Published("vertical position and velocity of G (downwards)", "expression",
                      (a * sp.cos(th1) + b * sp.cos(th2), -a * w1 * sp.sin(th1) - b * w2 * sp.sin(th2)),
                      (-rG.dot(sc.O.y), -vG.dot(sc.O.y)), where=where),
            Published("T", "expression",
                      (m * ((a * w1 * sp.cos(th1) + b * w2 * sp.cos(th2))**2
                            + (a * w1 * sp.sin(th1) + b * w2 * sp.sin(th2))**2) / 2
                       + I0 * w2**2 / 2,), (T_ref,),
                      where=where + " (printed '1/(2m) [...]' for (m/2) [...])"),
            Published("T (expanded)", "expression",
                      (m * (a**2 * w1**2 + b**2 * w2**2 + 2 * a * b * w1 * w2 * c) / 2
                       + I0 * w2**2 / 2,), (T_ref,), where=where),
            Published("V", "expression", (-m * g * (a * sp.cos(th1) + b * sp.cos(th2)),),
                      (V_ref,), where=where),
            Published("theta1: dT/dth1', d/dt, dT/dth1, dV/dth1", "expression",
                      (m * a**2 * w1 + m * a * b * w2 * c,
                       m * a**2 * al1 + m * a * b * al2 * c - m * a * b * w2 * (w1 - w2) * s,
                       -m * a * b * w2 * s * w1, m * g * a * sp.sin(th1)),
                      (T_ref.diff(w1), T_ref.diff(w1).diff(t), T_ref.diff(th1),
                       V_ref.diff(th1)), where=where),
            Published("theta1: Lagrange's equation", "equation",
                      (m * a**2 * al1 + m * a * b * al2 * c + m * a * b * w2**2 * s
                       + m * g * a * sp.sin(th1),), where=where),
            Published("theta1: divided through", "equation", (e1,),
                      where=where + ": WRONG, gravity term g a sin(theta1); dividing by m a "
                      "gives g sin(theta1)"),
            Published("theta2: dT/dth2'", "expression",
                      (m * b**2 * w1 + m * a * b * w1 * c + I0 * w2,), (T_ref.diff(w2),),
                      where=where + ": WRONG as extracted, m b^2 theta1' where m b^2 theta2' "
                      "belongs"),
            Published("theta2: d/dt, dT/dth2, dV/dth2", "expression",
                      (m * b**2 * al2 + m * a * b * al1 * c - m * a * b * w1 * (w1 - w2) * s
                       + I0 * al2, m * a * b * w1 * s * w2, m * g * b * sp.sin(th2)),
                      (T_ref.diff(w2).diff(t), T_ref.diff(th2), V_ref.diff(th2)), where=where),
            Published("theta2: Lagrange's equation", "equation",
                      (m * b**2 * al2 + m * a * b * al1 * c - m * a * b * w1**2 * s + I0 * al2
                       + m * g * b * sp.sin(th2),), where=where),
            Published("theta2: finally", "equation", (e2,),
                      where=where + ": WRONG, 3 b theta2'' holds only for I0 = 2 m b^2, and "
                      "even then the gravity term is g sin(theta2), not g b sin(theta2)"),
        ]


PROBLEMS = (CompoundDoublePendulum,)
