r"""Example 14: the copying machine -- a massless bar, so one equation of motion is static.

Source: ``sources/000_203248afac9714e6.txt``, "Example 14: Pair-Share: Copying machine"
(Lagrange's equation, gravity neglected).  Coordinates ``q1 = y`` (the mass ``m2``) and
``q2 = theta`` (the bar).  The bar has no mass, so ``theta`` has no inertia: its equation is
*algebraic* (static), ``(k2 L^2 + k1 a^2) theta = k2 L y``, and the equation set is
differential-algebraic (index 1: differentiating the static row once gives ``theta'``, twice
``theta''``).  Both models keep that static row; nothing is eliminated by hand in them.

Geometry (the source's figure is missing; this is the one its energies describe)
------------------------------------------------------------------------------
::

                          F (on m2)
                          ^
                        +----+
                        | m2 |  y: displacement of m2 (k2 unstretched at y = 0, theta = 0)
                        +----+
                         |  |
                     k2  /  [ b   (dashpot to the ground)
                         \  |
          k1            |  ///
          /\/\          |
    O=====+=============+   massless bar, pivot O, turned by theta (small):
    ^     a             L   the point at distance s from O moves s*theta along j
   /// (pivot, reaction R_O along j)

     j (up)
     ^
     +--> i      no gravity (the source neglects it)

The source's energies, ``U = k2 (L theta - y)^2/2 + k1 (a theta)^2/2``, are those of a small
rotation: the bar's points at ``a`` and ``L`` move ``a theta`` and ``L theta`` along ``j``
and the springs stay along ``j``.  The models keep exactly that (linear) theory: the
free-body diagrams are drawn in the reference configuration (moment arms ``a`` and ``L``).

Frames and bodies.  One inertial frame ``O`` (``i`` along the bar at rest, ``j`` up).  ``m2``
is a particle at ``y j`` (plus its rest position).  The bar is massless: a rigid body of zero
mass and inertia, kept in the reference configuration, loaded at ``a i`` and ``L i``.

Free-body diagrams::

    m2:   -k2 (y - L theta) j  (spring k2),   -b y' j  (dashpot),   F j
    bar:  +k2 (y - L theta) j  at L i,   -k1 a theta j  at a i,   R_O j  at O (pivot)

    m2 . j:          m2 y'' = -k2 (y - L theta) - b y' + F
    bar . j:         0 = R_O + k2 (y - L theta) - k1 a theta            (static)
    bar, tau_O . k:  0 = L k2 (y - L theta) - a k1 a theta               (static)

so ``(k2 L^2 + k1 a^2) theta = k2 L y`` and ``R_O = k1 a theta - k2 (y - L theta)
= k1 k2 a (L - a) y / (k2 L^2 + k1 a^2)`` on the constraint manifold.

Lagrangian (written independently, the source's)::

    T = m2 y'^2 / 2,   U = k2 (L theta - y)^2/2 + k1 (a theta)^2/2,   R = b y'^2/2
    Q1 = F, Q2 = 0
    y:      m2 y'' + b y' - k2 (L theta - y) = F
    theta:  k2 L (L theta - y) + k1 a^2 theta = 0                         (static)

The pivot reaction a second time (multiplier model): free the pivot by ``w`` (its travel
along ``j``), so the points at ``a`` and ``L`` move ``w + a theta`` and ``w + L theta``, and
close it with ``w = 0``, multiplier ``R_O`` (virtual work ``R_O dw``).  Its ``theta`` and
``w`` rows are both static.

A further derivation (``reduced``): ``theta`` eliminated by hand through the static row,
``U_e = k_e y^2/2`` with ``k_e = k1 k2 a^2 / (k2 L^2 + k1 a^2)``: ``m2 y'' + b y' + k_e y =
F``, a one-coordinate model mapped onto ``(y, theta)`` by ``y -> y``.

Errata
------
* The slide states Lagrange's equation for ``theta`` as ``d/dt(dT/dtheta') - dU/dtheta = 0``:
  the sign of ``dU/dtheta`` is wrong (Lagrange's equation has ``+ dU/dtheta``).  Harmless
  here -- the right side is 0 and ``dT/dtheta' = 0`` -- and the next line,
  ``k2 L^2 theta - k2 L y + k1 a^2 theta = 0``, is right.
* Every other printed line is right, the final one-coordinate equation included.

Garbled in the extraction: the table of derivatives is scrambled into two columns; it
prints ``dU/dtheta' = 0`` (true, ``U`` has no rates; presumably meant ``dT/dtheta = 0``) and
``But dT/dtheta' = 0 giving`` beside the static equation.  Transcribed as printed.

Example
-------
>>> p = CopyingMachine(); p.validate()
>>> p.model("lagrange").mass_matrix()
Matrix([
[m2, 0],
[ 0, 0]])
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, RigidBody, coordinate, rate, t, ANGLE,
                      DAMPING, FORCE, LENGTH, MASS, STIFFNESS)

__all__ = ["CopyingMachine", "PROBLEMS", "effective_stiffness", "m2", "k1", "k2", "a", "L",
           "b", "F", "y", "theta", "w"]

m2, k1, k2, a, L, b, F = sp.symbols("m2 k1 k2 a L b F", positive=True)
y, theta = coordinate("y"), coordinate("theta")
w = coordinate("w")  # pivot travel along j, multiplier model only


def effective_stiffness() -> sp.Expr:
    """``k_e = k1 k2 a^2 / (k2 L^2 + k1 a^2)``: the two springs seen from ``m2`` (by hand)."""
    return k1 * k2 * a**2 / (k2 * L**2 + k1 * a**2)


def _scene() -> SimpleNamespace:
    O = Frame.ground("O")
    o = Point.origin(O, "O")
    mass = Particle("m2", m2, o.locate("P", L * O.x + y * O.y))
    bar = RigidBody("bar", sp.Integer(0), o.locate("G", L / 2 * O.x), O, sp.zeros(3, 3))
    return SimpleNamespace(O=O, o=o, mass=mass, bar=bar, A=o.locate("A", a * O.x),
                           E=o.locate("E", L * O.x))


def _extensions() -> dict:
    """Spring extensions of the small-rotation theory: k2 between bar end and m2, k1 at a."""
    return {"spring k2": y - L * theta, "spring k1": a * theta}


class CopyingMachine(Problem):
    """Mass ``m2`` driven by ``F`` through springs on a massless pivoted bar (module doc)."""

    name = "copying_machine"
    title = "Copying machine: mass on springs and a massless bar"
    source = "000_203248afac9714e6.txt: Example 14"
    summary = ("Differential-algebraic: the massless bar's angle has no inertia, so its "
               "equation is static, (k2 L^2 + k1 a^2) theta = k2 L y; both models keep it. "
               "The slide's Lagrange equation for theta has the sign of dU/dtheta wrong.")
    parameters = (
        Parameter(m2, MASS, 2.0, (0.1, 10.0), "mass driven by F"),
        Parameter(k1, STIFFNESS, 400.0, (10.0, 2000.0), "spring at distance a on the bar"),
        Parameter(k2, STIFFNESS, 200.0, (10.0, 2000.0), "spring between bar end and m2"),
        Parameter(a, LENGTH, 0.1, (0.02, 0.5), "distance of spring k1 from the pivot"),
        Parameter(L, LENGTH, 0.3, (0.05, 1.0), "length of the bar"),
        Parameter(b, DAMPING, 5.0, (0.1, 50.0), "dashpot on m2"),
        Parameter(F, FORCE, 10.0, (0.1, 100.0), "force on m2"),
    )
    coordinates = (
        Coordinate(y, LENGTH, (-0.05, 0.05), (-0.5, 0.5), "displacement of m2"),
        Coordinate(theta, ANGLE, (-0.2, 0.2), (-2.0, 2.0), "rotation of the bar (small)"),
    )
    extra_coordinates = (
        Coordinate(w, LENGTH, (-0.01, 0.01), (-0.1, 0.1), "travel of the pivot along j"),
    )
    reactions = (Reaction("R_O", FORCE, "pivot on bar, along j"),)
    extra_models = ("multiplier", "reduced")

    def coordinate_maps(self) -> dict:
        return {"multiplier": {y: y, theta: theta, w: 0}, "reduced": {y: y}}

    # -- direct form ----------------------------------------------------------------------
    def newton_euler(self) -> EquationSet:
        """``m2`` along ``j``; the massless bar's force and moment balances (static rows)."""
        sc = _scene()
        O = sc.O
        ne = NewtonEuler("newton_euler", coordinates=[y, theta], ground=O,
                         description="free-body diagrams of m2 and of the massless bar")
        ext = _extensions()
        ne.linear_spring("spring k2", sc.mass, k2, ext["spring k2"], O.y,
                         against=sc.bar, against_at=sc.E)
        ne.linear_spring("spring k1", sc.bar, k1, ext["spring k1"], O.y, at=sc.A)
        ne.linear_damper("dashpot", sc.mass, b, rate(y), O.y)
        ne.force("drive", sc.mass, F * O.y)
        ne.reaction("R_O", sc.bar, O.y, at=sc.o)
        ne.linear_momentum(sc.mass, O.y)
        ne.linear_momentum(sc.bar, O.y)
        ne.angular_momentum(sc.bar, O.z, about=sc.o)
        return ne.equations()

    # -- indirect form --------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """The source's ``T``, ``U``, ``R`` and ``Q``; the ``theta`` row comes out static."""
        lg = Lagrangian("lagrange", coordinates=[y, theta],
                        description="T, U, R, Q of Example 14 (bar massless)")
        lg.kinetic("T of m2", m2 * rate(y)**2 / 2)
        lg.spring("spring k2", k2, L * theta - y)
        lg.spring("spring k1", k1, a * theta)
        lg.damper("dashpot", b, rate(y))
        lg.generalized_force("drive", [F, 0])
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The pivot freed by ``w`` and held by the multiplier ``R_O``."""
        lg = Lagrangian("multiplier", coordinates=[y, theta, w],
                        description="pivot freed along j, closed by a multiplier")
        lg.kinetic("T of m2", m2 * rate(y)**2 / 2)
        lg.spring("spring k2", k2, y - (w + L * theta))
        lg.spring("spring k1", k1, w + a * theta)
        lg.damper("dashpot", b, rate(y))
        lg.generalized_force("drive", [F, 0, 0])
        lg.constraint("R_O", w)
        return lg.equations()

    def reduced(self) -> EquationSet:
        """``theta`` eliminated by hand: ``m2`` on the effective spring ``k_e``."""
        lg = Lagrangian("reduced", coordinates=[y],
                        description="one coordinate, theta eliminated by the static row")
        lg.kinetic("T of m2", m2 * rate(y)**2 / 2)
        lg.spring("effective spring", effective_stiffness(), y)
        lg.damper("dashpot", b, rate(y))
        lg.generalized_force("drive", [F])
        return lg.equations()

    # -- the source's answers -------------------------------------------------------------
    def published(self) -> list[Published]:
        sc = _scene()
        O = sc.O
        ext = _extensions()
        T = sc.mass.kinetic_energy(O)
        U = k2 * ext["spring k2"]**2 / 2 + k1 * ext["spring k1"]**2 / 2
        Rd = b * sc.mass.point.vel(O).dot(O.y)**2 / 2
        v = sc.mass.point.vel(O)
        Q = tuple((F * O.y).dot(v.diff(rate(q), O)) for q in (y, theta))
        lagrange_theta = (T.diff(rate(theta)).diff(t) - T.diff(theta) + Rd.diff(rate(theta))
                          + U.diff(theta) - Q[1])
        D_ = k2 * L**2 + k1 * a**2
        y_eq = m2 * rate(y, 2) + b * rate(y) - k2 * (L * theta - y) - F
        th_eq = (k2 * L**2 + k1 * a**2) * theta - k2 * L * y
        where = "Example 14"
        return [
            Published("T", "expression", (m2 * rate(y)**2 / 2,), (T,), where=where),
            Published("U", "expression",
                      (k2 * (L * theta - y)**2 / 2 + k1 * (a * theta)**2 / 2,), (U,),
                      where=where),
            Published("R", "expression", (b * rate(y)**2 / 2,), (Rd,), where=where),
            Published("Q1, Q2", "expression", (F, 0), Q, where=where),
            Published("derivatives", "expression",
                      (m2 * rate(y), m2 * rate(y, 2), -k2 * (L * theta - y), 0, b * rate(y), 0),
                      (T.diff(rate(y)), T.diff(rate(y)).diff(t), U.diff(y), U.diff(rate(theta)),
                       Rd.diff(rate(y)), T.diff(rate(theta))),
                      where=where + ", table of derivatives (scrambled by the extraction): "
                      "dT/dy', d/dt dT/dy', dU/dy, dU/dtheta', dR/dy', dT/dtheta'"),
            Published("Lagrange's equation for theta", "expression",
                      (T.diff(rate(theta)).diff(t) - U.diff(theta),), (lagrange_theta,),
                      where=where + ": WRONG, d/dt(dT/dtheta') - dU/dtheta; Lagrange's "
                      "equation has + dU/dtheta (harmless: the right side is 0)"),
            Published("static equation", "equation",
                      (k2 * L**2 * theta - k2 * L * y + k1 * a**2 * theta, th_eq),
                      where=where + ": k2 L^2 th - k2 L y + k1 a^2 th = 0, i.e. "
                      "(k2 L^2 + k1 a^2) th = k2 L y"),
            Published("theta from y", "equation", (theta - k2 * L * y / D_,),
                      where=where + ": th = k2 L y / (k2 L^2 + k1 a^2)"),
            Published("equations of motion", "motion", (y_eq, th_eq),
                      where=where + ": the y equation with the static theta equation"),
            Published("one-coordinate equation", "equation",
                      (m2 * rate(y, 2) + b * rate(y) + k2 * y - k2 * L * k2 * L / D_ * y - F,),
                      where=where + ": after substituting theta"),
        ]


PROBLEMS = (CopyingMachine,)
