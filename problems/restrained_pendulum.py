r"""Example 12: a plane pendulum restrained by a spring at distance b and a dashpot at distance a.

Source: ``sources/000_203248afac9714e6.txt``, "Example 12: Pair-Share: Restrained Plane
Pendulum": a bob ``m`` on a rigid massless link of length ``l`` hinged without friction at O,
restrained by a linear spring ``k`` and a linear dashpot ``c``.

Geometry (the source's figure is missing; this is the one used here)
--------------------------------------------------------------------
The usual drawing: spring and dashpot horizontal, from the link to a wall; the original
exercise adds "assume small angular changes so that the spring and damper forces always act
horizontally" (that sentence is not in the lecture text).  Here the forces are horizontal
*exactly*: the wall ends of spring and dashpot ride in vertical guides, so both stay
horizontal, and the spring is unstretched at ``theta = 0``::

               O  pivot (frictionless), reaction H i + V j on the link
          |/|  |\
          |/|  | \  theta (from the downward vertical, counter-clockwise about k)
          |/|--/\/\/\--o S     spring k at distance b:  S = b (sin th, -cos th)
          |/|  |   \
          |/|--[ c ----o D     dashpot c at distance a: D = a (sin th, -cos th)
          |/|  |     \
                      (m)  B   bob at distance l:     B = l (sin th, -cos th)
          j
          ^   gravity -g j
          +--> i

Frames.  ``O`` inertial (``i`` right, ``j`` up, ``k`` out of the page).  The link frame
``A = O.child(rot_z(theta))``: ``A.y = (-sin th, cos th)`` points from the bob to the pivot,
so ``S = -b A.y``, ``D = -a A.y``, ``B = -l A.y``.

Bodies.  The bob is a particle ``m`` at B.  The link is massless; it is kept as a body only
because it carries the loads (a rigid body of zero mass and inertia).  Link and bob are taken
as one system, so the force between them does not appear.

Free-body diagram of link + bob::

      spring   -k (b sin th) i           at S    (extension = horizontal travel of S)
      dashpot  -c (a th' cos th) i       at D    (rate = horizontal velocity of D)
      weight   -m g j                    at B
      pivot    H i + V j                 at O    (unknown reaction on the link)

``sum F = m a_B`` and ``sum tau_O = dh_O/dt``, with
``a_B = l th'' (cos th, sin th) + l th'^2 (-sin th, cos th)``::

      i:  H - k b sin th - c a th' cos th = m l (th'' cos th - th'^2 sin th)
      j:  V - m g                         = m l (th'' sin th + th'^2 cos th)
      k:  m l^2 th'' + c a^2 th' cos^2 th + k b^2 sin th cos th + m g l sin th = 0

so the pivot reaction, with ``th''`` from the third line, is
``H = k b sin th + c a th' cos th + m l (th'' cos th - th'^2 sin th)`` and
``V = m g + m l (th'' sin th + th'^2 cos th)``.

Lagrangian (written independently)::

      T = m (l th')^2 / 2
      U = m g l (1 - cos th) + k (b sin th)^2 / 2
      R = c (a th' cos th)^2 / 2

The pivot reaction a second time (multiplier model): free the pivot by two coordinates
``(u, v)`` (its displacement along ``i`` and ``j``) and close it with the constraints
``u = 0`` (multiplier ``H``) and ``v = 0`` (multiplier ``V``).  Then
``B = (u + l sin th, v - l cos th)``, the spring extension is ``u + b sin th``, the dashpot
rate ``u' + a th' cos th``.  The virtual work of ``H i + V j`` at the pivot is
``H du + V dv``: with unit gradients the multipliers are the reaction components.  (The
mass matrix in ``(th, u, v)`` alone is singular -- the massless link can turn about the bob --
but the constraints make the augmented system regular.)

Errata
------
The source's ``U = m g l - m g l cos th + k (b th)^2/2`` and ``R = c (a th')^2/2`` are the
small-angle forms of the spring's and dashpot's terms (travel ``b th`` for ``b sin th``, rate
``a th'`` for ``a th' cos th``), while the weight is kept exact (``sin th``).  The printed
nonlinear equation ``m l^2 th'' + c a^2 th' + m g l sin th + k b^2 th = 0`` therefore mixes
orders: with horizontal elements the exact terms are ``c a^2 th' cos^2 th`` and
``k b^2 sin th cos th``.  It holds only to first order in ``th`` -- which is what the
printed *linearised* equation ``m l^2 th'' + c a^2 th' + (m g l + k b^2) th = 0`` keeps, and
that one is right (the library's linearisation of the exact model gives it).  The printed
nonlinear equation would be exact only for elements that act along the tangent of their
attachment point's arc (spring travel = arc ``b th``): a test shows that reading too.

Example
-------
>>> p = RestrainedPendulum(); p.validate()
>>> p.model("lagrange").linearize()[2]
Matrix([[b**2*k + g*l*m]])
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Frame, Lagrangian, NewtonEuler, Particle, Point, RigidBody, coordinate,
                      rot_z, t)
from dualmech.dimensions import ACCELERATION, ANGLE, DAMPING, FORCE, LENGTH, MASS, STIFFNESS
from dualmech.equations import EquationSet
from dualmech.problem import Coordinate, Parameter, Problem, Published, Reaction

__all__ = ["RestrainedPendulum", "PROBLEMS", "hand_reactions", "m", "l", "k", "c", "a", "b",
           "g", "theta", "u", "v"]

m, l, k, c, a, b, g = sp.symbols("m l k c a b g", positive=True)
theta = coordinate("theta")
u, v = coordinate("u"), coordinate("v")  # pivot displacement, multiplier model only

D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731


def hand_reactions(thdd) -> dict:
    """``{"H": ..., "V": ...}`` from the free-body diagram, given the true ``theta''``."""
    s, co, thd = sp.sin(theta), sp.cos(theta), D(theta)
    return {"H": k * b * s + c * a * thd * co + m * l * (thdd * co - thd**2 * s),
            "V": m * g + m * l * (thdd * s + thd**2 * co)}


def _scene() -> SimpleNamespace:
    O = Frame.ground("O")
    A = O.child("A", rot_z(theta))
    pivot = Point.origin(O, "O")
    S = pivot.locate("S", -b * A.y)
    Dp = pivot.locate("D", -a * A.y)
    B = pivot.locate("B", -l * A.y)
    link = RigidBody("link", sp.Integer(0), pivot.locate("G", -l / 2 * A.y), A, sp.zeros(3, 3))
    return SimpleNamespace(O=O, A=A, pivot=pivot, S=S, D=Dp, B=B, link=link,
                           bob=Particle("bob", m, B))


class RestrainedPendulum(Problem):
    """Bob on a massless link, held by a horizontal spring and dashpot (see module doc)."""

    name = "restrained_pendulum"
    title = "Plane pendulum restrained by a spring and a dashpot"
    source = "000_203248afac9714e6.txt: Example 12"
    summary = ("Pendulum with a horizontal spring at distance b and dashpot at distance a; "
               "pivot reaction twice (free-body diagram, multipliers). The printed nonlinear "
               "equation mixes small-angle spring/dashpot terms with exact gravity.")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "mass of the bob"),
        Parameter(l, LENGTH, 1.0, (0.2, 3.0), "length of the link"),
        Parameter(k, STIFFNESS, 40.0, (1.0, 500.0), "spring constant"),
        Parameter(c, DAMPING, 2.0, (0.1, 20.0), "dashpot constant"),
        Parameter(a, LENGTH, 0.4, (0.05, 3.0), "distance of the dashpot from the pivot"),
        Parameter(b, LENGTH, 0.6, (0.05, 3.0), "distance of the spring from the pivot"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-1.4, 1.4), (-3.0, 3.0), "link angle from the downward "
                   "vertical"),
    )
    extra_coordinates = (
        Coordinate(u, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "pivot displacement along i"),
        Coordinate(v, LENGTH, (-0.05, 0.05), (-0.2, 0.2), "pivot displacement along j"),
    )
    reactions = (
        Reaction("H", FORCE, "pivot on link, along i (horizontal)"),
        Reaction("V", FORCE, "pivot on link, along j (up)"),
    )
    extra_models = ("multiplier",)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, u: 0, v: 0}}

    # -- direct form ----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """Link + bob: ``sum F = m a_B`` on ``i`` and ``j``, moments about the pivot on ``k``."""
        sc = _scene()
        O = sc.O
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=O,
                         description="free-body diagram of link and bob together")
        ne.gravity(-g * O.y, bodies=[sc.bob])
        x_S = sc.S.pos_from().dot(O.x)            # horizontal travel of the spring's end
        rate_D = sc.D.vel(O).dot(O.x)             # horizontal velocity of the dashpot's end
        ne.linear_spring("spring", sc.link, k, x_S, O.x, at=sc.S)
        ne.linear_damper("dashpot", sc.link, c, rate_D, O.x, at=sc.D)
        ne.reaction("H", sc.link, O.x, at=sc.pivot)
        ne.reaction("V", sc.link, O.y, at=sc.pivot)
        system = [sc.link, sc.bob]
        ne.linear_momentum(system, O.x)
        ne.linear_momentum(system, O.y)
        ne.angular_momentum(system, O.z, about=sc.pivot)
        return ne.equations()

    # -- indirect form --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T``, ``U`` and ``R`` by hand, horizontal spring and dashpot (module docstring)."""
        lg = Lagrangian("lagrange", coordinates=[theta],
                        description="T, U, R with the spring and dashpot horizontal")
        lg.kinetic("T of bob", m * (l * D(theta))**2 / 2)
        lg.potential("gravity", m * g * l * (1 - sp.cos(theta)))
        lg.spring("spring", k, b * sp.sin(theta))
        lg.damper("dashpot", c, a * D(theta) * sp.cos(theta))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The pivot freed by ``(u, v)`` and held by the multipliers ``H``, ``V``."""
        lg = Lagrangian("multiplier", coordinates=[theta, u, v],
                        description="pivot freed, closed again by two multipliers")
        bob = sp.Matrix([u + l * sp.sin(theta), v - l * sp.cos(theta)])
        lg.kinetic("T of bob", m * (D(bob).T * D(bob))[0, 0] / 2)
        lg.potential("gravity", m * g * bob[1])
        lg.spring("spring", k, u + b * sp.sin(theta))
        lg.damper("dashpot", c, D(u) + a * D(theta) * sp.cos(theta))
        lg.constraint("H", u)
        lg.constraint("V", v)
        return lg.equations()

    # -- the source's answers -------------------------------------------------------------
    def published(self) -> list[Published]:
        sc = _scene()
        O = sc.O
        rate_D = sc.D.vel(O).dot(O.x)
        x_S = sc.S.pos_from().dot(O.x)
        height_B = sc.B.pos_from().dot(O.y) + l     # above the bob's lowest position
        M, C, K = self.model("lagrange").linearize()
        s, co = sp.sin(theta), sp.cos(theta)
        where = "Example 12"
        return [
            Published("T", "expression", (m * (l * D(theta))**2 / 2,),
                      (sc.bob.kinetic_energy(O),), where=where),
            Published("R", "expression", (c * (a * D(theta))**2 / 2,), (c * rate_D**2 / 2,),
                      where=where + ": WRONG beyond first order, the dashpot's rate is "
                      "a th' cos(th), not a th' (small-angle form)"),
            Published("U", "expression",
                      (m * g * l - m * g * l * co + k * (b * theta)**2 / 2,),
                      (m * g * height_B + k * x_S**2 / 2,),
                      where=where + ": WRONG beyond first order, the spring's travel is "
                      "b sin(th), not b th (small-angle form)"),
            Published("equation of motion", "motion",
                      (m * l**2 * DD(theta) + c * a**2 * D(theta) + m * g * l * s
                       + k * b**2 * theta,),
                      where=where + ": WRONG beyond first order, small-angle spring and "
                      "dashpot terms (k b^2 th, c a^2 th') beside the exact m g l sin(th); "
                      "exact: k b^2 sin(th) cos(th), c a^2 th' cos^2(th)"),
            Published("linearised equation: M, C, K", "expression",
                      (m * l**2, c * a**2, m * g * l + k * b**2),
                      (M[0, 0], C[0, 0], K[0, 0]),
                      where=where + ", 'Linearize sin th ~ th': the coefficients of th'', "
                      "th', th"),
        ]


PROBLEMS = (RestrainedPendulum,)
