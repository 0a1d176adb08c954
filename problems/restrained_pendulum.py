r"""Example 12: a plane pendulum restrained by a spring at distance b and a dashpot at distance a.

Source: ``sources/000_203248afac9714e6.txt``, "Example 12: Pair-Share: Restrained Plane
Pendulum": a bob ``m`` on a rigid massless link of length ``l`` hinged without friction at O,
restrained by a linear spring ``k`` and a linear dashpot ``c``.

The source's model (the reference here)
---------------------------------------
The source's figure is missing; its energies say what the elements are::

      U = m g l (1 - cos th) + k (b th)^2 / 2,      R = c (a th')^2 / 2

the spring stretches by the *arc* ``b th`` swept by its attachment point and the dashpot
works at that point's *speed along the arc* ``a th'``: both act along the tangent of their
attachment point's circle (for instance a cord wound on a quadrant of radius ``b``, resp.
``a``, centred at O and pulled by the element) -- perpendicular to the link, with
magnitudes ``k b th`` and ``c a th'``.  Those energies give the printed equation exactly,
``m l^2 th'' + c a^2 th' + m g l sin th + k b^2 th = 0``, and that model is the reference::

               O  pivot (frictionless), reaction H i + V j on the link
               |\
               | \  theta (from the downward vertical, counter-clockwise about k)
               |  o S     spring k at distance b, force -k b th A.x (tangent at S)
               |   \
               |    o D   dashpot c at distance a, force -c a th' A.x (tangent at D)
               |     \
                      (m)  B   bob at distance l:  B = l (sin th, -cos th)
          j
          ^   gravity -g j
          +--> i

Frames.  ``O`` inertial (``i`` right, ``j`` up, ``k`` out of the page).  The link frame
``A = O.child(rot_z(theta))``: ``A.x = (cos th, sin th)`` is the tangent of the arcs (the
direction in which S, D, B move as ``th`` grows), ``A.y = (-sin th, cos th)`` points from the
bob to the pivot, so ``S = -b A.y``, ``D = -a A.y``, ``B = -l A.y``.

Bodies.  The bob is a particle ``m`` at B.  The link is massless; it is kept as a body only
because it carries the loads (a rigid body of zero mass and inertia).  Link and bob are taken
as one system, so the force between them does not appear.

Free-body diagram of link + bob::

      spring   -k b th A.x               at S    (extension = arc b th)
      dashpot  -c a th' A.x              at D    (rate = speed along the arc)
      weight   -m g j                    at B
      pivot    H i + V j                 at O    (unknown reaction on the link)

``sum F = m a_B`` and ``sum tau_O = dh_O/dt``, with
``a_B = l th'' (cos th, sin th) + l th'^2 (-sin th, cos th)`` and the moment of a force
``-F A.x`` at distance ``r`` equal to ``-F r`` (it is perpendicular to the link)::

      i:  H - (k b th + c a th') cos th     = m l (th'' cos th - th'^2 sin th)
      j:  V - m g - (k b th + c a th') sin th = m l (th'' sin th + th'^2 cos th)
      k:  m l^2 th'' + c a^2 th' + k b^2 th + m g l sin th = 0

so the pivot reaction, with ``th''`` from the third line, is
``H = (k b th + c a th') cos th + m l (th'' cos th - th'^2 sin th)`` and
``V = m g + (k b th + c a th') sin th + m l (th'' sin th + th'^2 cos th)``.

Lagrangian (written independently, the source's own energies)::

      T = m (l th')^2 / 2
      U = m g l (1 - cos th) + k (b th)^2 / 2
      R = c (a th')^2 / 2

The pivot reaction a second time (multiplier model): free the pivot by two coordinates
``(u, v)`` (its displacement along ``i`` and ``j``) and close it with the constraints
``u = 0`` (multiplier ``H``) and ``v = 0`` (multiplier ``V``).  Then
``B = (u + l sin th, v - l cos th)``; the spring's force ``-k b th A.x`` at
``S = (u + b sin th, v - b cos th)`` does the virtual work ``-k b th (cos th du + sin th dv +
b dth)``, the dashpot's ``-c a th' (cos th du + sin th dv + a dth)``: generalised forces, not a
potential (an element that stays tangent to a moving arc is not conservative once the pivot
moves).  The virtual work of ``H i + V j`` at the pivot is ``H du + V dv``: with unit
gradients the multipliers are the reaction components.  (The mass matrix in ``(th, u, v)``
alone is singular -- the massless link can turn about the bob -- but the constraints make the
augmented system regular.)

Where the model departs from the source, and the richer variant
---------------------------------------------------------------
Nowhere in the equations: the reference is the source's statement.  The source does not say
how its elements are attached; the usual drawing has them horizontal, from the link to a
wall, and the original exercise adds "assume small angular changes so that the spring and
damper forces always act horizontally".  That variant -- elements *exactly* horizontal (their
wall ends ride in vertical guides) -- is :class:`RestrainedPendulumHorizontal`
(``restrained_pendulum_horizontal``), the top rung of this scene's fidelity ladder
(``dualmech fidelity restrained_pendulum``): its exact terms are ``k b^2 sin th cos th`` and
``c a^2 th' cos^2 th``, which agree with the source's ``k b^2 th`` and ``c a^2 th'`` to first
order in ``th`` only, so the printed nonlinear equation is not that variant's motion.  The
printed *linearised* equation ``m l^2 th'' + c a^2 th' + (m g l + k b^2) th = 0`` holds for
both.

Example
-------
>>> p = RestrainedPendulum(); p.validate()
>>> p.model("lagrange").equations[0]
a**2*c*Derivative(theta(t), t) + b**2*k*theta(t) + g*l*m*sin(theta(t)) + l**2*m*Derivative(theta(t), (t, 2))
>>> p.model("lagrange").linearize()[2]
Matrix([[b**2*k + g*l*m]])
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, FidelityRung, Frame, Lagrangian, NewtonEuler,
                      Parameter, Particle, Point, Problem, Published, Reaction, RigidBody,
                      coordinate, rate, rot_z, ACCELERATION, ANGLE, DAMPING, FORCE, LENGTH, MASS,
                      STIFFNESS)

__all__ = ["RestrainedPendulum", "RestrainedPendulumHorizontal", "PROBLEMS", "hand_reactions",
           "hand_reactions_horizontal", "m", "l", "k", "c", "a", "b", "g", "theta", "u", "v"]

m, l, k, c, a, b, g = sp.symbols("m l k c a b g", positive=True)
theta = coordinate("theta")
u, v = coordinate("u"), coordinate("v")  # pivot displacement, multiplier model only


def hand_reactions(thdd) -> dict:
    """``{"H": ..., "V": ...}`` of the source's model (tangential elements), given ``theta''``."""
    s, co, thd = sp.sin(theta), sp.cos(theta), rate(theta)
    tangential = k * b * theta + c * a * thd
    return {"H": tangential * co + m * l * (thdd * co - thd**2 * s),
            "V": m * g + tangential * s + m * l * (thdd * s + thd**2 * co)}


def hand_reactions_horizontal(thdd) -> dict:
    """``{"H": ..., "V": ...}`` of the horizontal variant, given the true ``theta''``."""
    s, co, thd = sp.sin(theta), sp.cos(theta), rate(theta)
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
    """Bob on a massless link, held by a spring and a dashpot acting along the arcs of their
    attachment points -- the source's energies (see the module doc)."""

    name = "restrained_pendulum"
    title = "Plane pendulum restrained by a spring and a dashpot"
    source = "000_203248afac9714e6.txt: Example 12"
    summary = ("Pendulum with a spring at distance b and a dashpot at distance a acting along "
               "their arcs (the source's U and R); pivot reaction twice (free-body diagram, "
               "multipliers). The horizontal-element variant is the next rung of its ladder.")
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
    # the ladder both variants share (the horizontal one is defined below)
    fidelity_ladder = (
        FidelityRung("source: spring and dashpot along their arcs (Example 12's U, R)",
                     lambda: RestrainedPendulum(), "the elements' turn away from horizontal "
                     "(travel b th for b sin th, rate a th' for a th' cos th)"),
        FidelityRung("spring and dashpot horizontal", lambda: RestrainedPendulumHorizontal()),
    )

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, u: 0, v: 0}}

    # -- direct form ----------------------------------------------------------------------
    def _elements(self, sc) -> tuple:
        """``(spring travel, its direction, dashpot rate, its direction)`` on the link: here
        along the arc (the variant overrides this)."""
        return b * theta, sc.A.x, a * rate(theta), sc.A.x

    def newton_euler(self) -> EquationSet:
        """Link + bob: ``sum F = m a_B`` on ``i`` and ``j``, moments about the pivot on ``k``."""
        sc = _scene()
        O = sc.O
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=O,
                         description="free-body diagram of link and bob together")
        ne.gravity(-g * O.y, bodies=[sc.bob])
        travel, along_s, speed, along_d = self._elements(sc)
        ne.linear_spring("spring", sc.link, k, travel, along_s, at=sc.S)
        ne.linear_damper("dashpot", sc.link, c, speed, along_d, at=sc.D)
        ne.reaction("H", sc.link, O.x, at=sc.pivot)
        ne.reaction("V", sc.link, O.y, at=sc.pivot)
        system = [sc.link, sc.bob]
        ne.linear_momentum(system, O.x)
        ne.linear_momentum(system, O.y)
        ne.angular_momentum(system, O.z, about=sc.pivot)
        return ne.equations()

    # -- indirect form --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """The source's ``T``, ``U`` and ``R`` (arc-length spring and dashpot)."""
        lg = Lagrangian("lagrange", coordinates=[theta],
                        description="the source's T, U, R: spring travel b th, dashpot rate a th'")
        lg.kinetic("T of bob", m * (l * rate(theta))**2 / 2)
        lg.potential("gravity", m * g * l * (1 - sp.cos(theta)))
        lg.spring("spring", k, b * theta)
        lg.damper("dashpot", c, a * rate(theta))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The pivot freed by ``(u, v)`` and held by the multipliers ``H``, ``V``; the
        tangential elements by their virtual work (module doc)."""
        lg = Lagrangian("multiplier", coordinates=[theta, u, v],
                        description="pivot freed, closed again by two multipliers")
        bob = sp.Matrix([u + l * sp.sin(theta), v - l * sp.cos(theta)])
        lg.kinetic("T of bob", m * (rate(bob).T * rate(bob))[0, 0] / 2)
        lg.potential("gravity", m * g * bob[1])
        s, co = sp.sin(theta), sp.cos(theta)
        for key, force, arm in (("spring", k * b * theta, b), ("dashpot", c * a * rate(theta), a)):
            # -F A.x at distance `arm`: virtual work -F (cos th du + sin th dv + arm dth)
            lg.generalized_force(key, [-force * arm, -force * co, -force * s])
        lg.constraint("H", u)
        lg.constraint("V", v)
        return lg.equations()

    # -- the source's answers -------------------------------------------------------------
    def published(self) -> list[Published]:
        sc = _scene()
        O = sc.O
        height_B = sc.B.pos_from().dot(O.y) + l     # above the bob's lowest position
        arc_S = b * theta                           # the spring's travel along its arc
        speed_D = sc.D.vel(O).dot(sc.A.x)           # the dashpot's rate: speed along its arc
        M, C, K = self.model("lagrange").linearize()
        where = "Example 12"
        return [
            Published("T", "expression", (m * (l * rate(theta))**2 / 2,),
                      (sc.bob.kinetic_energy(O),), where=where),
            Published("R", "expression", (c * (a * rate(theta))**2 / 2,), (c * speed_D**2 / 2,),
                      where=where),
            Published("U", "expression",
                      (m * g * l - m * g * l * sp.cos(theta) + k * (b * theta)**2 / 2,),
                      (m * g * height_B + k * arc_S**2 / 2,), where=where),
            Published("equation of motion", "motion",
                      (m * l**2 * rate(theta, 2) + c * a**2 * rate(theta) + m * g * l * sp.sin(theta)
                       + k * b**2 * theta,), where=where),
            Published("linearised equation: M, C, K", "expression",
                      (m * l**2, c * a**2, m * g * l + k * b**2),
                      (M[0, 0], C[0, 0], K[0, 0]),
                      where=where + ", 'Linearize sin th ~ th': the coefficients of th'', "
                      "th', th"),
        ]


class RestrainedPendulumHorizontal(RestrainedPendulum):
    """The richer variant: spring and dashpot exactly horizontal (module doc, last section)."""

    name = "restrained_pendulum_horizontal"
    title = "Plane pendulum restrained by a horizontal spring and dashpot"
    source = "000_203248afac9714e6.txt: Example 12 (the usual drawing, not the source's energies)"
    summary = ("Example 12 with the spring and dashpot horizontal, from the link to a wall "
               "(their wall ends in vertical guides): exact terms k b^2 sin th cos th and "
               "c a^2 th' cos^2 th; the source's model is its small-angle form.")
    coordinates = (
        Coordinate(theta, ANGLE, (-1.4, 1.4), (-3.0, 3.0), "link angle from the downward "
                   "vertical"),
    )
    reactions = (
        Reaction("H", FORCE, "pivot on link, along i (horizontal)"),
        Reaction("V", FORCE, "pivot on link, along j (up)"),
    )

    def _elements(self, sc) -> tuple:
        """Horizontal: the travel of the spring's end and the velocity of the dashpot's end
        along ``i``, read off the scene's points (the direct form's own kinematics)."""
        O = sc.O
        return sc.S.pos_from().dot(O.x), O.x, sc.D.vel(O).dot(O.x), O.x

    def lagrange(self) -> EquationSet:
        """``T``, ``U`` and ``R`` by hand, horizontal spring and dashpot."""
        lg = Lagrangian("lagrange", coordinates=[theta],
                        description="T, U, R with the spring and dashpot horizontal")
        lg.kinetic("T of bob", m * (l * rate(theta))**2 / 2)
        lg.potential("gravity", m * g * l * (1 - sp.cos(theta)))
        lg.spring("spring", k, b * sp.sin(theta))
        lg.damper("dashpot", c, a * rate(theta) * sp.cos(theta))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The pivot freed by ``(u, v)`` and held by the multipliers ``H``, ``V``."""
        lg = Lagrangian("multiplier", coordinates=[theta, u, v],
                        description="pivot freed, closed again by two multipliers")
        bob = sp.Matrix([u + l * sp.sin(theta), v - l * sp.cos(theta)])
        lg.kinetic("T of bob", m * (rate(bob).T * rate(bob))[0, 0] / 2)
        lg.potential("gravity", m * g * bob[1])
        lg.spring("spring", k, u + b * sp.sin(theta))
        lg.damper("dashpot", c, rate(u) + a * rate(theta) * sp.cos(theta))
        lg.constraint("H", u)
        lg.constraint("V", v)
        return lg.equations()

    def published(self) -> list[Published]:
        """The source's answers read for horizontal elements: right to first order only."""
        sc = _scene()
        O = sc.O
        rate_D = sc.D.vel(O).dot(O.x)               # horizontal velocity of the dashpot's end
        x_S = sc.S.pos_from().dot(O.x)              # horizontal travel of the spring's end
        height_B = sc.B.pos_from().dot(O.y) + l
        M, C, K = self.model("lagrange").linearize()
        where = "Example 12, read with horizontal elements"
        return [
            Published("T", "expression", (m * (l * rate(theta))**2 / 2,),
                      (sc.bob.kinetic_energy(O),), where=where),
            Published("R", "expression", (c * (a * rate(theta))**2 / 2,), (c * rate_D**2 / 2,),
                      where=where + ": WRONG for this reading beyond first order, the "
                      "dashpot's rate is a th' cos(th)"),
            Published("U", "expression",
                      (m * g * l - m * g * l * sp.cos(theta) + k * (b * theta)**2 / 2,),
                      (m * g * height_B + k * x_S**2 / 2,),
                      where=where + ": WRONG for this reading beyond first order, the "
                      "spring's travel is b sin(th)"),
            Published("equation of motion", "motion",
                      (m * l**2 * rate(theta, 2) + c * a**2 * rate(theta) + m * g * l * sp.sin(theta)
                       + k * b**2 * theta,),
                      where=where + ": WRONG for this reading beyond first order; exact: "
                      "k b^2 sin(th) cos(th), c a^2 th' cos^2(th)"),
            Published("linearised equation: M, C, K", "expression",
                      (m * l**2, c * a**2, m * g * l + k * b**2),
                      (M[0, 0], C[0, 0], K[0, 0]), where=where),
        ]


PROBLEMS = (RestrainedPendulum, RestrainedPendulumHorizontal)
