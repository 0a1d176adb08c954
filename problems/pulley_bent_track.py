r"""Two masses and a pulley on a bent track (MIT 2.003J, spring 2011, final exam, problem 4).

``M1`` slides on massless rollers along a horizontal track, tied to the left wall by a spring
``k`` and a dashpot ``c``.  An inextensible massless string runs from ``M1`` over a uniform
pulley (mass ``m``, radius ``r``, fixed frictionless axle at the bend) to ``M2``, which slides
on a track inclined at the fixed angle ``theta0`` below the horizontal.  A horizontal force
``F(t) I`` pushes ``M2``; gravity ``-g J``.  The string is taut and does not slip on the
pulley.  One degree of freedom: ``x``, the displacement of ``M1`` from the spring's unstretched
position (``M2`` moves ``x`` down the incline, the pulley turns ``x/r`` clockwise).

``F(t)`` is left general in the source; it is ``F0 cos(omega t)`` here (a model needs a known
function of time; nothing below depends on its form).

Sign convention (plane I-J, K out of the page)::

                                      A1     J
       |/|--/\/\/\--+------+  T1 ->  .--.    ^
       |/|  k       |  M1  |--------( C  )   +--> I
       |/|---[ c ---+------+         '--' \  A2
       ============================== \    \  T2           e = cos(th0) I - sin(th0) J
              x -->                    \  +----+              (down the incline)
                                        \ | M2 | --> F(t) I   n = sin(th0) I + cos(th0) J
                                         \+----+                (incline's outward normal)
                                          \  theta0 below the horizontal

Frames (rotation matrices about K)::

    O  = (O, I, J, K)             ground
    S  = O.child(rot_z(-theta0))  incline:  i_S = e,  j_S = n
    P  = O.child(rot_z(-x/r))     pulley (turns clockwise as x grows)

Bodies: ``M1`` and ``M2`` translate: particles at ``x I`` and ``x e`` (each from its own
position at ``x = 0``).  The pulley: a rigid body (thin disk, ``m r^2/2`` about its axle) at
the fixed centre C.  The string leaves the pulley at ``A1 = C + r J`` (towards ``M1``) and at
``A2 = C + r n`` (along ``e``).

Free-body diagrams::

    M1:      -M1 g J,  N1 J (track),  -k x I,  -c x' I,  T1 I (string)
    M2:      -M2 g J,  N2 n (track),  F(t) I,  -T2 e (string)
    pulley:  -T1 I at A1,  T2 e at A2,  weight and axle force at C (no moment about C)

Direct form: ``sum F = m a`` for ``M1`` on I and J, for ``M2`` on ``e`` and ``n``; Euler for
the pulley about its fixed centre on K.  Solved by hand (``x''`` the true acceleration)::

    T1 = M1 x'' + c x' + k x,      T2 = T1 + m x''/2
    N1 = M1 g,                     N2 = M2 g cos(theta0) - F(t) sin(theta0)

Lagrangian (written independently, as the source writes it)::

    T = (M1 + M2 + m/2) x'^2 / 2,   V = k x^2/2 - M2 g x sin(theta0),   R = c x'^2/2
    Xi_x = F(t) cos(theta0)          (virtual work of F along e)

    (M1 + M2 + m/2) x'' + c x' + k x - M2 g sin(theta0) - F(t) cos(theta0) = 0

The reactions once more, as multipliers: free the string (``x1`` for ``M1``, ``x2`` for ``M2``
along ``e``, ``phi`` for the pulley) and lift both masses off their tracks (``y1`` along ``J``,
``y2`` along ``n``); close with ``x1 - r phi = 0`` (``T1``), ``r phi - x2 = 0`` (``T2``),
``y1 = 0`` (``N1``), ``y2 = 0`` (``N2``).  The tensions' virtual work is
``T1 (d x1 - r d phi) + T2 (r d phi - d x2)``; each constraint has unit gradient along its
force, so each multiplier is the force.

The source asks for no reaction; the four above are the free-body diagrams' unknowns.  No
errata found: the printed ``T``, ``V``, ``L``, ``Xi_x`` and the equation of motion are right.

Example
-------
>>> p = PulleyBentTrack(); p.validate()
>>> p.model("lagrange").mass_matrix()
Matrix([[M1 + M2 + m/2]])
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, RigidBody, coordinate, rate, rot_z, t,
                      thin_disk, ACCELERATION, ANGLE, DAMPING, FORCE, FREQUENCY, LENGTH, MASS,
                      STIFFNESS)

__all__ = ["PulleyBentTrack", "PROBLEMS", "scene", "hand_reactions", "drive", "M1", "M2", "m",
           "k", "c", "r", "theta0", "g", "F0", "omega", "x"]

M1, M2, m, k, c, r, g, F0, omega = sp.symbols("M1 M2 m k c r g F0 omega", positive=True)
theta0 = sp.Symbol("theta0", positive=True)
x = coordinate("x")
x1, x2, phi = coordinate("x1"), coordinate("x2"), coordinate("phi")
y1, y2 = coordinate("y1"), coordinate("y2")
drive = F0 * sp.cos(omega * t)   # F(t)


def scene() -> SimpleNamespace:
    """Frames, points and bodies of the direct form (see the module doc)."""
    O = Frame.ground("O")
    S = O.child("S", rot_z(-theta0))
    P = O.child("P", rot_z(-x / r))
    centre = Point.origin(O, "C")
    p1 = Point.origin(O, "M1_0").locate("M1", x * O.x)
    p2 = Point.origin(O, "M2_0").locate("M2", x * S.x)
    pulley = RigidBody("pulley", m, centre, P, thin_disk(m, r, normal="z"))
    return SimpleNamespace(O=O, S=S, P=P, centre=centre, p1=p1, p2=p2,
                           A1=centre.locate("A1", r * O.y), A2=centre.locate("A2", r * S.y),
                           mass1=Particle("M1", M1, p1), mass2=Particle("M2", M2, p2),
                           pulley=pulley)


def hand_reactions() -> dict:
    """``{name: expression}`` by hand, in ``x, x', x''`` (module docstring)."""
    T1 = M1 * rate(x, 2) + c * rate(x) + k * x
    return {"T1": T1, "T2": T1 + m * rate(x, 2) / 2, "N1": M1 * g,
            "N2": M2 * g * sp.cos(theta0) - drive * sp.sin(theta0)}


class PulleyBentTrack(Problem):
    """Two sliders joined by a string over a pulley at the bend of a track."""

    name = "pulley_bent_track"
    title = "Two masses and a pulley on a bent track"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, final exam, problem 4"
    summary = ("One degree of freedom; string tensions and track forces from the free bodies "
               "and as multipliers; the printed answers are right.")
    parameters = (
        Parameter(M1, MASS, 1.5, (0.1, 10.0), "mass on the horizontal track"),
        Parameter(M2, MASS, 1.0, (0.1, 10.0), "mass on the incline"),
        Parameter(m, MASS, 0.4, (0.01, 5.0), "mass of the pulley (uniform disk)"),
        Parameter(k, STIFFNESS, 30.0, (1.0, 500.0), "spring constant"),
        Parameter(c, DAMPING, 2.0, (0.1, 20.0), "dashpot constant"),
        Parameter(r, LENGTH, 0.1, (0.02, 1.0), "radius of the pulley"),
        Parameter(theta0, ANGLE, 0.5, (0.1, 1.4), "angle of the incline below the horizontal"),
        Parameter(g, ACCELERATION, 9.81, (9.0, 10.0), "gravitational acceleration"),
        Parameter(F0, FORCE, 3.0, (0.1, 20.0), "amplitude of F(t) = F0 cos(omega t)"),
        Parameter(omega, FREQUENCY, 2.0, (0.1, 20.0), "frequency of F(t)"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-0.5, 1.0), (-2.0, 2.0), "displacement of M1 from the "
                   "unstretched spring"),
    )
    extra_coordinates = (
        Coordinate(x1, LENGTH, (-0.5, 1.0), (-2.0, 2.0), "displacement of M1"),
        Coordinate(x2, LENGTH, (-0.5, 1.0), (-2.0, 2.0), "displacement of M2 along e"),
        Coordinate(phi, ANGLE, (-5.0, 10.0), (-20.0, 20.0), "pulley angle, clockwise"),
        Coordinate(y1, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "M1 off its track, along J"),
        Coordinate(y2, LENGTH, (-0.1, 0.1), (-0.5, 0.5), "M2 off its track, along n"),
    )
    reactions = (
        Reaction("T1", FORCE, "string tension between M1 and the pulley (on M1 along I)"),
        Reaction("T2", FORCE, "string tension between the pulley and M2 (on M2 along -e)"),
        Reaction("N1", FORCE, "horizontal track on M1, along J"),
        Reaction("N2", FORCE, "incline on M2, along its outward normal n"),
    )
    extra_models = ("multiplier",)
    unilateral = {"T1": "the string to M1 goes slack", "T2": "the string to M2 goes slack",
                  "N1": "M1 lifts off its track", "N2": "M2 lifts off the incline"}

    def coordinate_maps(self) -> dict:
        return {"multiplier": {x1: x, x2: x, phi: x / r, y1: 0, y2: 0}}

    # -- direct form -----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """M1 on I and J, M2 on e and n, the pulley about its fixed centre."""
        s = scene()
        O, S = s.O, s.S
        ne = NewtonEuler(coordinates=[x], ground=O,
                         description="two sliders and the pulley, each a free body")
        ne.gravity(-g * O.y)
        ne.linear_spring("spring", s.mass1, k, x, O.x)
        ne.linear_damper("dashpot", s.mass1, c, rate(x), O.x)
        ne.force("F(t)", s.mass2, drive * O.x)
        ne.reaction("N1", s.mass1, O.y)
        ne.reaction("N2", s.mass2, S.y)
        ne.reaction("T1", s.mass1, O.x, against=s.pulley, against_at=s.A1)
        ne.reaction("T2", s.pulley, S.x, at=s.A2, against=s.mass2)
        ne.linear_momentum(s.mass1, O.x)
        ne.linear_momentum(s.mass1, O.y)
        ne.linear_momentum(s.mass2, S.x)
        ne.linear_momentum(s.mass2, S.y)
        ne.angular_momentum(s.pulley, O.z, about=s.centre)
        return ne.equations()

    # -- indirect forms --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """``T``, ``V``, ``R`` and ``Xi_x`` by hand, as the source writes them."""
        lg = Lagrangian(coordinates=[x], description="T, V, R and Xi by hand")
        lg.kinetic("T of M1", M1 * rate(x)**2 / 2)
        lg.kinetic("T of M2", M2 * rate(x)**2 / 2)
        lg.kinetic("T of pulley", (m * r**2 / 2) * (rate(x) / r)**2 / 2)
        lg.spring("spring", k, x)
        lg.potential("gravity", -M2 * g * x * sp.sin(theta0))
        lg.damper("dashpot", c, rate(x))
        lg.generalized_force("F(t)", [drive * sp.cos(theta0)])
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """String and tracks freed; tensions and track forces as multipliers."""
        q = [x1, x2, phi, y1, y2]
        lg = Lagrangian("multiplier", coordinates=q,
                        description="string and tracks closed by multipliers")
        lg.kinetic("T of M1", M1 * (rate(x1)**2 + rate(y1)**2) / 2)
        lg.kinetic("T of M2", M2 * (rate(x2)**2 + rate(y2)**2) / 2)
        lg.kinetic("T of pulley", m * r**2 * rate(phi)**2 / 4)
        lg.spring("spring", k, x1)
        lg.damper("dashpot", c, rate(x1))
        s0, c0 = sp.sin(theta0), sp.cos(theta0)
        lg.potential("gravity", M1 * g * y1 + M2 * g * (-x2 * s0 + y2 * c0))
        # F(t) I at M2 = x2 e + y2 n: Q = F I . d(M2)/dq
        lg.generalized_force("F(t)", [0, drive * c0, 0, 0, drive * s0])
        lg.constraint("T1", x1 - r * phi)
        lg.constraint("T2", r * phi - x2)
        lg.constraint("N1", y1)
        lg.constraint("N2", y2)
        return lg.equations()

    # -- the source's answers --------------------------------------------------------------
    def published(self) -> list[Published]:
        s = scene()
        O = s.O
        x1d, x2d = rate(x), rate(x, 2)
        T = sum(b.kinetic_energy(O) for b in (s.mass1, s.mass2, s.pulley))
        V = k * x**2 / 2 + M2 * g * s.p2.pos_from(Point.origin(O)).dot(O.y)
        Xi = ((-c * x1d * O.x).dot(s.p1.vel(O).diff(x1d, O))
              + (drive * O.x).dot(s.p2.vel(O).diff(x1d, O)))
        where = "final exam, problem 4"
        return [
            Published("(b) T", "expression",
                      (M1 * x1d**2 / 2 + M2 * x1d**2 / 2 + (m * r**2 / 2) * (x1d / r)**2 / 2,),
                      (T,), where=f"{where} (b)"),
            Published("(b) V", "expression", (k * x**2 / 2 - M2 * g * x * sp.sin(theta0),),
                      (V,), where=f"{where} (b)"),
            Published("(b) L", "expression",
                      ((M1 + M2 + m / 2) * x1d**2 / 2 - k * x**2 / 2
                       + M2 * g * x * sp.sin(theta0),), (T - V,), where=f"{where} (b)"),
            Published("(c) Xi_x", "expression", (-c * x1d + drive * sp.cos(theta0),), (Xi,),
                      where=f"{where} (c), boxed; F(t) = F0 cos(omega t)"),
            Published("(d) equation of motion", "motion",
                      ((M1 + M2 + m / 2) * x2d - (-k * x + M2 * g * sp.sin(theta0))
                       - (-c * x1d + drive * sp.cos(theta0)),),
                      where=f"{where} (d); F(t) = F0 cos(omega t)"),
        ]


PROBLEMS = (PulleyBentTrack,)
