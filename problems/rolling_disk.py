r"""A thin disk rolling without slipping on a horizontal plane; its upright rolling is stable
above the critical speed ``sqrt(g r / 3)``.

Source: none of the course sources treats the rolling disk (``sources/README.md`` lists a wheel
rolling about a pivot and a rolling cylinder, both with one degree of freedom).  The problem
and its critical speed are the classic ones: D. T. Greenwood, *Advanced Dynamics* (Cambridge,
2003), the rolling disk of the nonholonomic-systems chapter; also Neimark and Fufaev,
*Dynamics of Nonholonomic Systems* (AMS, 1972), chapter II.  Everything below is derived by
hand here and checked by the toolkit, not transcribed.

A uniform thin disk (mass ``m``, radius ``r``) rolls on the plane ``Z = 0`` without slipping.
Moments of inertia about its centre G: ``A = m r^2 / 4`` about a diameter, ``C = m r^2 / 2``
about its axle.

Sign convention and coordinates (Euler angles heading, lean, spin; contact point ``(x, y)``)::

             Z                                   O  = ground, Z up, gravity -g Z
             |        G                          H  = O.child(rot_z(psi))     heading
             |       /|\    B.z (P to G)         B  = H.child(rot_x(theta))   lean about H.x
             |      / | \                        D  = B.child(rot_y(phi))     spin about the axle
             |     |  o--|--> B.y (axle)         P  = x O.x + y O.y           the contact point
             |      \ | /                        G  = P + r B.z
             |       \|/                         rolling forward: H.x = B.x, the disk's own
     --------+--------P----------> H.x             direction of travel
            /  x, y     F (contact force on the disk, unknown: F_x, F_y along O, F_z up)

``theta > 0`` tips the top of the disk towards ``-H.y``; upright is ``theta = 0``.

Kinematics by hand.  ``w = psi' Z + theta' H.x + phi' B.y``; in B axes, with
``Z = sin(theta) B.y + cos(theta) B.z``: ``w = (theta', phi' + psi' sin(theta),
psi' cos(theta))``.  ``G = (x + r sin(theta) sin(psi), y - r sin(theta) cos(psi),
r cos(theta))``.  The material point of the disk at P moves at ``v_G + w x (-r B.z)``; its
horizontal components are, after the terms in ``theta'`` and ``psi' sin(theta)`` cancel::

    x' - r phi' cos(psi) = 0,      y' - r phi' sin(psi) = 0        (rolling, two rows)

and its vertical component vanishes identically (the height ``r cos(theta)`` of G is built
into the coordinates).  The rolling rows are nonholonomic: ``psi`` in the first row's
coefficient of ``phi'`` is not the derivative of anything.

Direct form (model ``newton_euler``).  Free-body diagram of the disk: weight ``-m g Z`` at G,
contact force ``F = F_x O.x + F_y O.y + F_z O.z`` at P (three unknowns).  Equations:
``sum F = m a_G`` on ``O.x, O.y, O.z``; ``sum tau_G = dH_G/dt`` on ``B.x, B.y, B.z``; and
the rolling condition *declared* (``NewtonEuler.rolling``: the disk's material point at P has
no velocity along ``O.x``, ``O.y``), which the model holds as the two rolling rows above and
their time derivatives: eight equations in five accelerations and three forces.  Because the
rolling is a declaration, the Kane referee reads it too and derives the motion and all three
contact forces a third time.

Indirect form (model ``lagrange``), written independently::

    T = m |v_G|^2 / 2 + (A theta'^2 + C (phi' + psi' sin(theta))^2 + A psi'^2 cos(theta)^2) / 2
    V = m g r cos(theta)

with the two rolling rows as velocity constraints whose multipliers are ``F_x`` and ``F_y``:
the virtual work of the horizontal contact force is ``F . dv_P/dq'_j``, and ``v_P . O.x`` is
the first row, so its multiplier is ``F_x`` (likewise ``F_y``).  ``F_z`` does no virtual work
and only the direct form gives it.

Critical speed, by hand.  Straight upright rolling at speed ``v``: ``psi = theta = 0``,
``phi' = W = v / r``, ``x' = v``.  Linearise in small ``theta``, ``psi'``, ``theta'``.
Angular momentum about the contact point's material neighbourhood is awkward; use the
Lagrange rows with ``F_x, F_y`` eliminated by the rolling rows (``x'' = r phi''``,
``y'' = r (phi'' psi + W psi')`` to first order).  To first order ``T`` gives::

    theta:  (A + m r^2) theta'' + (C + m r^2) W psi' - m g r theta = 0        ... (1)
    psi:    A psi'' - C W theta' = 0                                         ... (2)

(``(C + m r^2) W psi'``: ``C W psi'`` from the spin term of ``T``, ``m r^2 W psi'`` from the
centripetal pull ``m v psi'`` of the contact force at the height ``r`` of G.)  Integrating (2),
``A psi' = C W theta + const``; for the perturbation with ``const = 0`` put into (1)::

    (A + m r^2) theta'' + ((C + m r^2) C W^2 / A - m g r) theta = 0.

With ``A = m r^2/4``, ``C = m r^2/2``: ``(C + m r^2) C / A = 3 m r^2``, and ``A + m r^2 =
5 m r^2 / 4``, so ``theta'' = (4 / (5 r^2)) (g r - 3 v^2) theta``: the eigenvalues of the lean
are ``+-sqrt(4 (g r - 3 v^2) / (5 r^2))``.  Real (one positive: the disk falls) for
``v^2 < g r / 3``, imaginary (a lean oscillation) for ``v^2 > g r / 3``: the critical speed is
``v_c = sqrt(g r / 3)`` (1.0 m/s for ``r = 0.3 m``, ``g = 10``).  The remaining eigenvalues
are zero: the heading ``psi`` (nothing depends on it), the speed ``phi'`` (a neighbouring
steady motion), and the constant of (2).  ``tests/test_stability.py`` checks the sweep finds
``v_c`` and these eigenvalues, from both models.

Example
-------
>>> p = RollingDisk(); p.validate()
>>> p.model("lagrange").unknowns
(F_x, F_y)
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter,
                      Point, Problem, Published, Reaction, RigidBody, SteadyMotion, coordinate,
                      linearize_about, rate, rot_x, rot_y, rot_z, t, ACCELERATION, ANGLE, FORCE,
                      LENGTH, MASS)

__all__ = ["RollingDisk", "PROBLEMS", "m", "r", "g", "v", "psi", "theta", "phi", "x", "y", "h",
           "critical_speed", "lean_eigenvalue_squared"]

m, r, g = sp.symbols("m r g", positive=True)
v = sp.Symbol("v", real=True)   # forward speed of the steady motion (not a model parameter)
psi, theta, phi = coordinate("psi"), coordinate("theta"), coordinate("phi")
x, y = coordinate("x"), coordinate("y")
h = coordinate("h")   # rise of the disk off the plane, multiplier model only
COORDS = [psi, theta, phi, x, y]


def critical_speed() -> sp.Expr:
    """``sqrt(g r / 3)``, derived by hand in the module docstring."""
    return sp.sqrt(g * r / 3)


def lean_eigenvalue_squared() -> sp.Expr:
    """``lambda^2 = 4 (g r - 3 v^2) / (5 r^2)`` of the lean on straight upright rolling."""
    return 4 * (g * r - 3 * v**2) / (5 * r**2)


def scene() -> SimpleNamespace:
    """Frames ``O, H, B, D``, the contact point ``P``, the centre ``G`` and the disk."""
    O = Frame.ground("O")
    H = O.child("H", rot_z(psi))
    B = H.child("B", rot_x(theta))
    D = B.child("D", rot_y(phi))
    P = Point.origin(O).locate("P", x * O.x + y * O.y)
    G = P.locate("G", r * B.z)
    inertia = sp.diag(m * r**2 / 4, m * r**2 / 2, m * r**2 / 4)   # D axes; axle D.y
    disk = RigidBody("disk", m, G, D, inertia)
    return SimpleNamespace(O=O, H=H, B=B, D=D, P=P, G=G, disk=disk)


def _rolling_rows(s) -> list:
    """The material contact point's velocity along ``O.x``, ``O.y`` (from the frames)."""
    w = s.D.ang_vel_in(s.O)
    vP = s.G.vel(s.O) + w.cross(-r * s.B.z)
    return [vP.dot(s.O.x), vP.dot(s.O.y)]


class RollingDisk(Problem):
    """A thin disk rolling without slipping on a plane (see the module docstring)."""

    name = "rolling_disk"
    title = "Rolling disk: nonholonomic rolling, contact force, critical speed"
    source = ("classic (no course source): Greenwood, Advanced Dynamics, the rolling disk; "
              "derived by hand in the module docstring")
    summary = ("A thin disk rolling on a plane, Newton-Euler with the contact force against "
               "Lagrange with rolling multipliers; upright rolling stable for v^2 > g r / 3.")
    parameters = (
        Parameter(m, MASS, 1.0, (0.1, 10.0), "mass of the disk"),
        Parameter(r, LENGTH, 0.3, (0.05, 2.0), "radius of the disk"),
        Parameter(g, ACCELERATION, 10.0, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(psi, ANGLE, (-3.0, 3.0), (-5.0, 5.0), "heading about the vertical"),
        Coordinate(theta, ANGLE, (-1.2, 1.2), (-5.0, 5.0), "lean from the upright"),
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-20.0, 20.0), "spin about the axle"),
        Coordinate(x, LENGTH, (-2.0, 2.0), (-5.0, 5.0), "contact point, O.x"),
        Coordinate(y, LENGTH, (-2.0, 2.0), (-5.0, 5.0), "contact point, O.y"),
    )
    extra_coordinates = (
        Coordinate(h, LENGTH, (-0.1, 0.1), (-1.0, 1.0),
                   "rise off the plane (multiplier model)"),
    )
    extra_models = ("multiplier",)
    reactions = (
        Reaction("F_x", FORCE, "plane on disk at the contact point, along O.x"),
        Reaction("F_y", FORCE, "plane on disk at the contact point, along O.y"),
        Reaction("F_z", FORCE, "plane on disk at the contact point, up"),
    )
    unilateral = {"F_z": "the disk leaves the plane"}
    steady_motion = SteadyMotion({rate(phi): v / r, rate(x): v}, "v", (0.2, 2.0, 91),
                                 "upright rolling straight along O.x at speed v")

    def newton_euler(self) -> EquationSet:
        """``sum F = m a_G``, ``sum tau_G = dH_G/dt``; rolling declared at the contact point
        (the referee reads it); contact force unknown."""
        s = scene()
        ne = NewtonEuler("newton_euler", coordinates=COORDS, ground=s.O,
                         description="the disk's free-body diagram, contact force unknown")
        ne.gravity(-g * s.O.z)
        ne.reaction_vector("F", s.disk, s.O, at=s.P)
        for axis in (s.O.x, s.O.y, s.O.z):
            ne.linear_momentum(s.disk, axis)
        for axis in (s.B.x, s.B.y, s.B.z):
            ne.angular_momentum(s.disk, axis)
        ne.rolling("rolling", s.disk, s.P, [s.O.x, s.O.y])
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T`` and ``V`` by hand, the rolling rows as velocity constraints (``F_x``, ``F_y``)."""
        s, c = sp.sin, sp.cos
        G = sp.Matrix([x + r * s(theta) * s(psi), y - r * s(theta) * c(psi), r * c(theta)])
        vG = G.diff(t)
        A, C = m * r**2 / 4, m * r**2 / 2
        lg = Lagrangian("lagrange", coordinates=COORDS,
                        description="T and V by hand, rolling by two multipliers")
        lg.kinetic("T of G", m * (vG.T * vG)[0, 0] / 2)
        lg.kinetic("T about G", (A * rate(theta)**2 + C * (rate(phi) + rate(psi) * s(theta))**2
                                 + A * rate(psi)**2 * c(theta)**2) / 2)
        lg.potential("gravity", m * g * r * c(theta))
        lg.velocity_constraint("F_x", [0, 0, -r * c(psi), 1, 0])
        lg.velocity_constraint("F_y", [0, 0, -r * s(psi), 0, 1])
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The disk freed to rise by ``h`` off the plane, closed by ``h = 0`` (multiplier
        ``F_z``: the normal force does the virtual work ``F_z dh``)."""
        s, c = sp.sin, sp.cos
        G = sp.Matrix([x + r * s(theta) * s(psi), y - r * s(theta) * c(psi), h + r * c(theta)])
        vG = G.diff(t)
        A, C = m * r**2 / 4, m * r**2 / 2
        coords = COORDS + [h]
        lg = Lagrangian("multiplier", coordinates=coords,
                        description="the disk freed off the plane; contact by three multipliers")
        lg.kinetic("T of G", m * (vG.T * vG)[0, 0] / 2)
        lg.kinetic("T about G", (A * rate(theta)**2 + C * (rate(phi) + rate(psi) * s(theta))**2
                                 + A * rate(psi)**2 * c(theta)**2) / 2)
        lg.potential("gravity", m * g * (h + r * c(theta)))
        lg.velocity_constraint("F_x", [0, 0, -r * c(psi), 1, 0, 0])
        lg.velocity_constraint("F_y", [0, 0, -r * s(psi), 0, 1, 0])
        lg.constraint("F_z", h)
        return lg.equations()

    def coordinate_maps(self) -> dict:
        return {"multiplier": {**{q: q for q in COORDS}, h: 0}}

    def published(self) -> list[Published]:
        s, c = sp.sin, sp.cos
        where = "classic rolling disk (Greenwood, Advanced Dynamics); derived by hand above"
        lin = linearize_about(self.model("lagrange"), self.steady_motion.about, parameter=v)
        lam = sp.Symbol("lambda")
        coeffs = sp.Poly(lin.symbolic.charpoly(lam).as_expr(), lam).all_coeffs()
        if coeffs[3:] != [0, 0, 0] or coeffs[1] != 0:   # expected: lambda^3 (lambda^2 - k)
            raise ValueError(f"the upright disk's characteristic polynomial is {coeffs}.")
        spin = {v: r * rate(phi)}   # on the steady motion v = r phi'
        return [
            Published("rolling rows", "expression",
                      (rate(x) - r * rate(phi) * c(psi), rate(y) - r * rate(phi) * s(psi)),
                      tuple(_rolling_rows(scene())), where=where),
            Published("lean eigenvalues squared on upright rolling", "expression",
                      (lean_eigenvalue_squared().subs(spin),),
                      (-sp.cancel(coeffs[2] / coeffs[0]).subs(spin),), where=where),
            # the same two results as numbers at the defaults (r = 0.3, g = 10), judged on
            # the linearised steady motion: v_c = sqrt(g r / 3) = 1, and at v = 1/2 the lean
            # eigenvalues are +-sqrt(4 (3 - 3/4) / (5 * 0.09)) = +-sqrt(20)
            Published("critical speed (m/s)", "critical", (1.0,), tolerance=1e-9,
                      where=where + ": v_c = sqrt(g r / 3) at r = 0.3, g = 10"),
            Published("lean eigenvalues at v = 0.5 m/s", "eigenvalues",
                      (sp.sqrt(20), -sp.sqrt(20)), at=0.5, tolerance=1e-12,
                      where=where + ": +-sqrt(4 (g r - 3 v^2) / (5 r^2))"),
        ]


PROBLEMS = (RollingDisk,)
