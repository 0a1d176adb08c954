r"""Trolley carrying a pendulum, with applied forces (Cambridge 3C5, Lagrangian mechanics).

Source: ``sources/002_df41972c66c4514e.txt``, section 2.1 ("generalised coordinate options"
for a trolley/pendulum system) and section 2.2 ("Example: Generalised forces associated with
the trolley/pendulum system", "Generalised Forces For trolley/pendulum ... Other cases are
similar"); the lecture plan's "Pendulum with force applied".

What could not be read.  The figure, the coordinate options and every formula of the
generalised-force example are missing from the extraction (only the headings survive), and
so is the formula ``delta W = ...`` of section 2.2.  The system below is the one those
headings describe -- a trolley on a horizontal track with a pendulum hanging from it, a force
on each -- and its generalised forces are computed the way the source says to compute them:
"the work done by a change ``delta q_i`` alone ... equated to ``Q_i delta q_i``".  What *is*
printed and applies here -- Lagrange's equation in its two forms and the appendix's energy
balance -- is transcribed and judged.

Sign convention::

        F -->  +-----------------+          i (right), j (up), k = i x j out of the page
               |    trolley M    |          gravity -g j
               +-------o---------+          x: trolley position (of the pivot o)
           ====(O)=====|\=====(O)========   X: horizontal position of the bob (option 2)
                       | \  a
                       |th\                 arm.y points from the bob to the pivot,
                       |   \                arm.x = e_theta (direction of increasing theta)
                            o bob m  --> P  (horizontal force on the bob)

``theta`` is measured from the downward vertical, counterclockwise about ``k``.  The rod is
massless, the track frictionless; ``F`` and ``P`` are steady, horizontal.

Frames.  ``O`` inertial; ``arm = O`` rotated by ``theta`` about ``k``.  Trolley: a particle
``M`` at ``x i`` (it does not rotate).  Bob: a particle ``m`` at ``x i - a arm.y``.

Free-body diagrams (Newton--Euler).  Bob: ``-m g j``, ``P i``, the rod's pull ``T arm.y``.
Trolley: ``F i``, ``-T arm.y`` at the pivot (massless rod: it passes the pull on), weight
and the track's normal force along ``j`` (they enter only the trolley's vertical balance,
which is not needed for the motion and is not written)::

        trolley . i:  M x''                                 = F + T sin th
        bob . arm.x:  m (x'' cos th + a th'')                 = P cos th - m g sin th
        bob . arm.y:  m (a th'^2 - x'' sin th)                = T - m g cos th - P sin th

Lagrangian, coordinates ``(x, theta)`` (written independently)::

        T = (M + m) x'^2/2 + m a x' th' cos th + m a^2 th'^2/2,      V = -m g a cos th
        delta W = F delta x + P delta(x + a sin th)
        =>  Q_x = F + P,      Q_th = P a cos th

        (M + m) x'' + m a (th'' cos th - th'^2 sin th)   = F + P
        m a^2 th'' + m a x'' cos th + m g a sin th       = P a cos th

Second coordinate option, ``(X, theta)`` with ``X = x + a sin th`` the bob's horizontal
position (the trolley is at ``X - a sin th``)::

        T = M (X' - a th' cos th)^2/2 + m (X'^2 + a^2 th'^2 sin^2 th)/2,   V = -m g a cos th
        delta W = F delta(X - a sin th) + P delta X
        =>  Q_X = F + P,      Q_th = -F a cos th

The generalised force conjugate to ``theta`` changes with the other coordinate: at fixed
``x`` a change of ``theta`` moves the bob (``P`` works), at fixed ``X`` it moves the trolley
(``F`` works).  Mapped by ``X = x + a sin th``, both options give the same motion.

The rod's pull once more, independently: free the bob's distance ``r`` from the pivot and
close it with ``a - r = 0`` (multiplier ``T``; ``T arm.y`` does virtual work ``-T delta r``).

Errata (as extracted).  Section 2.2 prints the second form of Lagrange's equation as
``d/dt [dL/dq'_i] - dL/dq'_i = Q_i``; the second term must be ``dL/dq_i``.  Applied to this
system the printed form is wrong (a slip of the notes or of the extraction -- the dot is
clearly in the extracted formula).  The first form, ``d/dt [dT/dq'_i] - dT/dq_i + dV/dq_i =
Q_i``, is printed with ``.`` for ``=`` (an extraction artefact) and is right.

Example
-------
>>> p = TrolleyPendulum(); p.validate()
>>> sp.factor(sp.trigsimp(p.model("lagrange").mass_matrix().det()))
a**2*m*(M + m*sin(theta(t))**2)
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_z, t,
                      ACCELERATION, ANGLE, FORCE, LENGTH, MASS)

__all__ = ["TrolleyPendulum", "PROBLEMS", "M", "m", "a", "g", "F", "P", "x", "theta", "X", "r",
           "energies", "hand_generalised_forces", "hand_tension"]

M, m, a, g, F, P = sp.symbols("M m a g F P", positive=True)
x, theta = coordinate("x"), coordinate("theta")
X = coordinate("X")  # horizontal position of the bob (second coordinate option)
r = coordinate("r")  # distance of the bob from the pivot (multiplier model)


def energies() -> tuple[sp.Expr, sp.Expr]:
    """``(T, V)`` in ``(x, theta)``, by hand (module docstring)."""
    c = sp.cos(theta)
    T = ((M + m) * rate(x)**2 / 2 + m * a * rate(x) * rate(theta) * c + m * a**2 * rate(theta)**2 / 2)
    return T, -m * g * a * c


def hand_generalised_forces(option: str = "x") -> tuple[sp.Expr, sp.Expr]:
    """``(Q_1, Q_theta)`` by virtual work, for coordinates ``(x, theta)`` or ``(X, theta)``."""
    if option == "x":
        return F + P, P * a * sp.cos(theta)
    if option == "X":
        return F + P, -F * a * sp.cos(theta)
    raise ValueError(f"`option` must be 'x' or 'X', got {option!r}.")


def hand_tension() -> sp.Expr:
    """The rod's pull on the bob in terms of the true ``x''`` (bob's ``arm.y`` balance)."""
    s, c = sp.sin(theta), sp.cos(theta)
    return m * (a * rate(theta)**2 - rate(x, 2) * s) + m * g * c + P * s


class _Scene:
    """Frames, points and particles of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.arm = self.O.child("arm", rot_z(theta))
        self.pivot = Point.origin(self.O).locate("pivot", x * self.O.x)
        self.B = self.pivot.locate("bob", -a * self.arm.y)
        self.trolley = Particle("trolley", M, self.pivot)
        self.bob = Particle("bob", m, self.B)


class TrolleyPendulum(Problem):
    """Trolley ``M`` with a pendulum (massless rod ``a``, bob ``m``), forces ``F`` and ``P``."""

    name = "trolley_pendulum"
    title = "Trolley with a pendulum, forces on both"
    source = "002_df41972c66c4514e.txt: sections 2.1-2.2, trolley/pendulum generalised forces"
    summary = ("Generalised forces by virtual work in two coordinate options (trolley or bob "
               "position); the extracted second form of Lagrange's equation is wrong.")
    parameters = (
        Parameter(M, MASS, 3.0, (0.5, 10.0), "mass of the trolley"),
        Parameter(m, MASS, 1.0, (0.1, 5.0), "mass of the bob"),
        Parameter(a, LENGTH, 0.6, (0.1, 2.0), "length of the pendulum"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(F, FORCE, 4.0, (0.1, 30.0), "horizontal force on the trolley"),
        Parameter(P, FORCE, 1.5, (0.1, 30.0), "horizontal force on the bob"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-1.0, 1.0), (-2.0, 2.0), "position of the trolley"),
        Coordinate(theta, ANGLE, (-1.3, 1.3), (-3.0, 3.0),
                   "angle of the pendulum from the downward vertical"),
    )
    extra_coordinates = (
        Coordinate(X, LENGTH, (-2.0, 2.0), (-3.0, 3.0), "horizontal position of the bob"),
        Coordinate(r, LENGTH, (0.1, 2.0), (-1.0, 1.0), "distance of the bob from the pivot"),
    )
    reactions = (Reaction("T", FORCE, "rod on bob, along arm.y (towards the pivot)"),)
    extra_models = ("bob_coordinates", "multiplier")

    def coordinate_maps(self) -> dict:
        return {"bob_coordinates": {X: x + a * sp.sin(theta), theta: theta},
                "multiplier": {x: x, theta: theta, r: a}}

    def newton_euler(self) -> EquationSet:
        """Trolley along ``i``; bob along ``arm.x`` and ``arm.y``."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[x, theta], ground=sc.O,
                         description="trolley along i, bob along e_theta and the rod")
        ne.gravity(-g * sc.O.y)
        ne.force("F on trolley", sc.trolley, F * sc.O.x)
        ne.force("P on bob", sc.bob, P * sc.O.x)
        ne.reaction("T", sc.bob, sc.arm.y, against=sc.trolley)
        ne.linear_momentum(sc.trolley, sc.O.x)
        ne.linear_momentum(sc.bob, sc.arm.x)
        ne.linear_momentum(sc.bob, sc.arm.y)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``(x, theta)``: T and V by hand, generalised forces by virtual work (by hand)."""
        c = sp.cos(theta)
        lg = Lagrangian("lagrange", coordinates=[x, theta],
                        description="coordinate option 1: trolley position and angle")
        lg.kinetic("T of trolley", M * rate(x)**2 / 2)
        lg.kinetic("T of bob", m * (rate(x)**2 + 2 * a * rate(x) * rate(theta) * c
                                    + a**2 * rate(theta)**2) / 2)
        lg.potential("gravity", -m * g * a * c)
        lg.generalized_force("F on trolley", [F, 0])       # delta W = F delta x
        lg.generalized_force("P on bob", [P, P * a * c])   # delta W = P delta(x + a sin th)
        return lg.equations()

    def bob_coordinates(self) -> EquationSet:
        """``(X, theta)``: the bob's horizontal position and the angle."""
        s, c = sp.sin(theta), sp.cos(theta)
        lg = Lagrangian("bob_coordinates", coordinates=[X, theta],
                        description="coordinate option 2: bob position and angle")
        lg.kinetic("T of trolley", M * (rate(X) - a * rate(theta) * c)**2 / 2)
        lg.kinetic("T of bob", m * (rate(X)**2 + a**2 * rate(theta)**2 * s**2) / 2)
        lg.potential("gravity", -m * g * a * c)
        lg.generalized_force("F on trolley", [F, -F * a * c])  # delta W = F delta(X - a sin th)
        lg.generalized_force("P on bob", [P, 0])               # delta W = P delta X
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """``(x, theta, r)`` with the rod as the constraint ``a - r = 0`` (multiplier ``T``)."""
        bob = sp.Matrix([x + r * sp.sin(theta), -r * sp.cos(theta)])
        lg = Lagrangian("multiplier", coordinates=[x, theta, r],
                        description="the bob freed along the rod, held by a multiplier")
        lg.kinetic("T of trolley", M * rate(x)**2 / 2)
        lg.kinetic("T of bob", m * (rate(bob).T * rate(bob))[0, 0] / 2)
        lg.potential("gravity", m * g * bob[1])
        lg.generalized_force("F on trolley", [F, 0, 0])
        lg.generalized_force("P on bob", [P * bob[0].diff(q) for q in (x, theta, r)])
        lg.constraint("T", a - r)
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        T = sc.trolley.kinetic_energy(sc.O) + sc.bob.kinetic_energy(sc.O)
        V = m * g * sc.B.pos_from(sc.pivot).dot(sc.O.y)
        # generalised forces from the loads' virtual work, Q_j = sum F . dv/dq'_j
        loads = ((F * sc.O.x, sc.pivot), (P * sc.O.x, sc.B))
        Q = [sum(f.dot(pt.vel(sc.O).diff(rate(q), sc.O)) for f, pt in loads) for q in (x, theta)]
        L = T - V
        form_T, form_L, power = [], [], []
        for q, Qq in zip((x, theta), Q):
            form_T.append(T.diff(rate(q)).diff(t) - T.diff(q) + V.diff(q) - Qq)
            form_L.append(L.diff(rate(q)).diff(t) - L.diff(rate(q)) - Qq)
        power = (T + V).diff(t) - sum(Qq * rate(q) for q, Qq in zip((x, theta), Q))
        where = "section 2.2, applied to the trolley/pendulum"
        return [
            # Right (printed with '.' for '=').
            Published("Lagrange's equation, d/dt dT/dq' - dT/dq + dV/dq = Q", "motion",
                      tuple(form_T), where=where),
            # WRONG as extracted: - dL/dq'_i where - dL/dq_i belongs.
            Published("Lagrange's equation, d/dt dL/dq' - dL/dq' = Q", "equation",
                      tuple(form_L), where=where + ": WRONG as extracted, the second term "
                      "is printed -dL/dq'_i; it is -dL/dq_i"),
            # Right: the appendix's energy balance, d/dt (T + V) = sum Q_i q'_i.
            Published("energy balance d/dt (T + V) = sum Q q'", "equation", (power,),
                      where="appendix, proof of Lagrange's equation, applied"),
        ]


PROBLEMS = (TrolleyPendulum,)
