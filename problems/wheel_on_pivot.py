r"""Wheel rolling round a pivot: a steady motion, and the contact force it needs.

Source: ``sources/004_f75aa9bb64d0737a.txt``, elaboration exam "Dynamics and Stability",
question 2 (a), (b).  A thin wheel (mass ``m``, radius ``a``) turns freely on a massless axle
of length ``l``; the axle is pivoted at O, level with the wheel's centre G, and turns about the
vertical at the rate ``Omega`` while the wheel rolls without slipping on the horizontal plane.

Sign convention (the source's)::

        k = K (up)                 i: along the axle, O -> G      j = k x i
        ^                          Omega: rate of the axle about K;  psi: wheel's spin about i
        |   O          G           rolling at the contact point C = G - a k:
        +---o==========(|)--> i        v_C = (l Omega + a psi) j = 0,  psi = -(l/a) Omega
            :  axle l   |a
        ====:===========C========   plane (the source's figure is not in the text)
            contact force F = F_x i + F_y j + F_z k on the wheel;  weight -m g k at G

Frames.  ``O`` inertial (``I, J, K``); axle ``A = O.child(rot_z(phi))`` (``i = A.x``,
``j = A.y``, ``k = K``); wheel ``W = A.child(rot_x(psi))`` with ``psi = -(l/a) phi``.

Modelling the steady motion.  A steady motion has no free coordinate if every rate is
prescribed; here the precession angle ``phi`` is kept as the one free coordinate (rolling ties
the spin to it) and its steady solution is *checked*.  A drive torque ``tau K`` on the axle
(a motor at O; not in the source) is added: the equations of motion give ``J phi'' = tau``
with ``J = 3/2 m l^2 + m a^2/4``, so the source's motion -- every constant rate ``phi' =
Omega`` -- is exactly the case ``tau = 0`` (nothing else does work: gravity keeps its height,
the contact point is at rest).  Without ``tau`` the equation would be ``J phi'' = 0`` whatever
``J``, and no check could see a wrong inertia about the vertical.  The source's ``Omega``
(extracted also as ``U`` and ``v``) is ``phi'``; its steady claims are judged on ``tau = 0``.

Body: the wheel, mass ``m`` at G, inertia about G in ``W`` axes ``diag(m a^2/2, m a^2/4,
m a^2/4)`` (thin disk, normal ``i``).  The axle is massless and carries the pivot force.

Free-body diagram (wheel with its axle): weight ``-m g k`` at G; contact force ``F`` at C;
pivot force ``R = R_x i + R_y j + R_z k`` at O; drive torque ``tau k``. Rigid-body mechanics
fixes only ``a F_x + l F_z`` and ``R_x + F_x`` (the radial friction and the axle's axial force
share the centripetal force in any proportion: statically indeterminate). The models close it
with the classic assumption that the contact transmits no radial friction, ``F_x = 0`` (a
closure equation in the direct forms); the source's printed relation does not depend on it (the
tests check it with the other extreme, ``R_x = 0``, too).

Angular momentum about O (the source's route; ``R`` has no moment about O)::

    H_O = phi' (-(1/2) m a l i + (m a^2/4 + m l^2) k)
    dH_O/dt = phi'' (-(1/2) m a l i + (m a^2/4 + m l^2) k) - (1/2) m a l phi'^2 j
    sum M_O = a F_y i + (-a F_x - l F_z + m g l) j + (l F_y + tau) k

so ``a F_y = -(1/2) m a l phi''`` and ``l F_y + tau = (m a^2/4 + m l^2) phi''`` give
``J phi'' = tau`` and ``F_y = -(1/2) m l phi''`` (zero on the steady motion); on ``j``:
``a F_x + (F_z - m g) l = (1/2) m a l phi'^2``.  With ``F_x = 0``::

    F_z = m g + (1/2) m a phi'^2,     R = (-m l phi'^2, (3/2) m l phi'', -(1/2) m a phi'^2)

Direct form (``newton_euler``): ``sum F = m a_G`` (``a_G = -l phi'^2 i + l phi'' j``) and
Euler's equation about G, all on ``i, j, k``, with ``R`` and ``F`` unknown, plus the closure.

Lagrangian, written independently::

    T = m (l phi')^2/2 + (m a^2/2) (l phi'/a)^2/2 + (m a^2/4) phi'^2/2,   V = const,  Q = tau
    (3/2 m l^2 + m a^2/4) phi'' = tau

The contact force once more (``multiplier``), independently: free the axle to tilt by
``eps`` (raising G) and the spin ``psi`` from the rolling.  With ``n = (cos eps, 0, sin eps)``
along the axle, the wheel's rate ``w = phi' K - eps' j + psi' n``::

    T = m l^2 (eps'^2 + phi'^2 cos^2 eps)/2 + (m a^2/2)(psi' + phi' sin eps)^2/2
        + (m a^2/4)(eps'^2 + phi'^2 cos^2 eps)/2,          V = m g l sin eps,    Q = (tau, 0, 0)
    rolling:  (l cos eps + a sin eps) phi' + a psi' = 0      (slip velocity of C along j; F_y)
    contact:  a + l sin eps - a cos eps = 0                  (height of the rim's lowest point)

The slip rate and the height are the contact point's displacement along ``j`` and ``k``, so
the multipliers are ``F_y`` and ``F_z`` (radial friction, zero by the closure, does no work
here either).  The map back is ``psi = -(l/a) phi``, ``eps = 0``.

The pivot force once more (``pivot_multiplier``), independently: free the pivot O as well,
to move by ``u_x i + u_y j + u_z k`` (so the pivot is a ball joint that lets go; the axle
keeps the azimuth ``phi`` and tilt ``eps``, the wheel its spin ``psi``).  Positions in inertial
components (``i = (cos phi, sin phi, 0)``, ``j = (-sin phi, cos phi, 0)``), differentiated
as they stand; the wheel's rate ``w`` on its axis ``n`` and across it::

    r_O = u_x i + u_y j + u_z k,   n = cos eps i + sin eps k,   b = -sin eps i + cos eps k
    r_G = r_O + l n,   r_C = r_G - a b (the rim's lowest point),   w = phi' k - eps' j + psi' n
    T = m |r_G'|^2/2 + (m a^2/2)(w . n)^2/2 + (m a^2/4)(|w|^2 - (w . n)^2)/2
    V = m g (u_z + l sin eps),   Q = (tau, 0, 0, 0, 0, 0)   (drive about K on the axle)
    pivot:    u_x = 0 (R_x),   u_y = 0 (R_y),   u_z = 0 (R_z)
    contact:  r_C . k + a = u_z + l sin eps - a cos eps + a = 0                       (F_z)
    rolling:  v_C . j = u_y' + (u_x + l cos eps + a sin eps) phi' + a psi' = 0       (F_y)

with ``v_C = r_G' + w x (-a b)`` the wheel's material point at C.  ``R . dr_O = R_x du_x +
R_y du_y + R_z du_z`` on ``u = 0``, so the pivot's multipliers are ``R``'s components on
``i, j, k``.  On the motion (``u = 0``, ``eps = 0``, ``r_G' = l phi' j``)::

    u_x:  -m l phi'^2 = R_x           (the centripetal force, all through the axle)
    u_y:   m l phi'' = R_y + F_y      (F_y: the rolling constraint has u_y' in it)
    u_z:   m g       = R_z + F_z

which with ``F_y``, ``F_z`` from the ``phi``, ``psi``, ``eps`` rows is ``R`` above: the pivot
force is derived twice (and the contact force three times).  The radial friction is no
constraint here (the contact may slip along ``i``), which is the closure ``F_x = 0`` of the
direct forms.  The map back adds ``u_x = u_y = u_z = 0``.

Errata (see :meth:`WheelOnPivot.published`)
-------------------------------------------
* (a), first line of ``L_O``: ``L_G`` is copied as ``(1/4) m a^2 Omega (-(l/a) i + k)``; it is
  ``-(2 l/a) i`` (as ``L_G`` two lines up, and as the final line uses).

Garbled: the rate is extracted as ``Omega``, ``U`` and ``v`` (in ``(1/2) m a l v^2``); all are
the precession rate.

Example
-------
>>> p = WheelOnPivot(); p.validate()
>>> p.model("lagrange").accelerations_solved()
{Derivative(phi(t), (t, 2)): 4*tau/(m*(a**2 + 6*l**2))}
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, Reaction, RigidBody, coordinate, rate, rot_x, rot_z, t,
                      thin_disk, ACCELERATION, ANGLE, FORCE, LENGTH, MASS, TORQUE)

__all__ = ["WheelOnPivot", "PROBLEMS", "frames", "direct_form", "m", "a", "l", "g", "tau",
           "phi"]

m, a, l, g = sp.symbols("m a l g", positive=True)
tau = sp.Symbol("tau", real=True)
phi = coordinate("phi")
psi, eps = coordinate("psi"), coordinate("eps")
u_x, u_y, u_z = coordinate("u_x"), coordinate("u_y"), coordinate("u_z")
F_x, F_y, F_z = sp.symbols("F_x F_y F_z", real=True)


def frames() -> SimpleNamespace:
    """Frames ``O, A, W``; points ``o`` (pivot), ``G`` (centre), ``C`` (contact); the wheel."""
    O = Frame.ground("O")
    A = O.child("A", rot_z(phi))
    W = A.child("W", rot_x(-l / a * phi))
    o = Point.origin(O, "O")
    G = o.locate("G", l * A.x)
    C = G.locate("C", -a * A.z)
    wheel = RigidBody("wheel", m, G, W, thin_disk(m, a, normal="x"))
    return SimpleNamespace(O=O, A=A, W=W, o=o, G=G, C=C, wheel=wheel)


def direct_form(name: str, closure: str = "F_x") -> tuple[NewtonEuler, SimpleNamespace]:
    """Free-body diagram with gravity, ``F`` at C and (for ``newton_euler``) ``R`` at O.

    ``closure`` names the reaction held at zero to settle the indeterminate radial split:
    ``"F_x"`` (no radial friction, the problem's choice) or ``"R_x"`` (no axial force in the
    axle).
    """
    f = frames()
    ne = NewtonEuler(name, coordinates=[phi], ground=f.O,
                     description=f"wheel and axle; closure {closure} = 0")
    ne.gravity(-g * f.O.z)
    ne.torque("drive", f.wheel, tau * f.O.z)
    F = ne.reaction_vector("F", f.wheel, f.A, at=f.C)
    unknowns = {"F_x": F.dot(f.A.x)}
    if name != "angular_momentum":
        R = ne.reaction_vector("R", f.wheel, f.A, at=f.o)
        unknowns["R_x"] = R.dot(f.A.x)
    ne.equation(f"closure: {closure} = 0", {f"closure {closure}": unknowns[closure]})
    return ne, f


class WheelOnPivot(Problem):
    """Wheel rolling round a pivot at a steady rate (see module doc)."""

    name = "wheel_on_pivot"
    title = "Wheel rolling round a pivot (driven precession; contact and pivot forces)"
    source = "004_f75aa9bb64d0737a.txt: question 2 (a), (b)"
    summary = ("Precession angle as the free coordinate (J phi'' = tau: steady iff tau = 0); "
               "contact force from H_O, from Newton-Euler and from multipliers; pivot force "
               "from Newton-Euler and from the pivot freed.")
    parameters = (
        Parameter(m, MASS, 2.0, (0.1, 10.0), "mass of the wheel"),
        Parameter(a, LENGTH, 0.3, (0.05, 1.0), "radius of the wheel"),
        Parameter(l, LENGTH, 0.8, (0.1, 3.0), "axle length, O to G"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(tau, TORQUE, 0.0, (-2.0, 2.0), "drive torque on the axle about K (0: steady)"),
    )
    coordinates = (
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-6.0, 6.0), "azimuth of the axle (rate Omega)"),
    )
    extra_coordinates = (
        Coordinate(psi, ANGLE, (-3.0, 3.0), (-30.0, 30.0), "spin of the wheel about its axle"),
        Coordinate(eps, ANGLE, (-0.2, 0.2), (-1.0, 1.0), "tilt of the axle (G raised)"),
        Coordinate(u_x, LENGTH, (-0.1, 0.1), (-1.0, 1.0), "pivot O freed: displacement along i"),
        Coordinate(u_y, LENGTH, (-0.1, 0.1), (-1.0, 1.0), "pivot O freed: displacement along j"),
        Coordinate(u_z, LENGTH, (-0.1, 0.1), (-1.0, 1.0), "pivot O freed: displacement along k"),
    )
    reactions = (
        Reaction("F_x", FORCE, "plane on the wheel at C, along i (radial; 0 by the closure)"),
        Reaction("F_y", FORCE, "plane on the wheel at C, along j (rolling friction)"),
        Reaction("F_z", FORCE, "plane on the wheel at C, along k (normal force)"),
        Reaction("R_x", FORCE, "pivot on the axle at O, along i"),
        Reaction("R_y", FORCE, "pivot on the axle at O, along j"),
        Reaction("R_z", FORCE, "pivot on the axle at O, along k"),
    )
    extra_models = ("angular_momentum", "multiplier", "pivot_multiplier")
    unilateral = {"F_z": "the wheel lifts off the plane"}

    def coordinate_maps(self) -> dict:
        return {"multiplier": {phi: phi, psi: -l / a * phi, eps: 0},
                "pivot_multiplier": {phi: phi, psi: -l / a * phi, eps: 0,
                                     u_x: 0, u_y: 0, u_z: 0}}

    def newton_euler(self) -> EquationSet:
        """``sum F = m a_G`` and Euler about G on ``i, j, k``; closure ``F_x = 0``."""
        ne, f = direct_form("newton_euler")
        for axis in (f.A.x, f.A.y, f.A.z):
            ne.linear_momentum(f.wheel, axis)
        for axis in (f.A.x, f.A.y, f.A.z):
            ne.angular_momentum(f.wheel, axis)
        return ne.equations()

    def angular_momentum(self) -> EquationSet:
        """The source's route: ``dH_O/dt = sum M_O`` on ``i, j, k``; closure ``F_x = 0``."""
        ne, f = direct_form("angular_momentum")
        for axis in (f.A.x, f.A.y, f.A.z):
            ne.angular_momentum(f.wheel, axis, about=f.o)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T`` by hand; the height of G is constant (``V`` drops out)."""
        lg = Lagrangian("lagrange", coordinates=[phi], description="rolling built in: psi' = "
                        "-(l/a) phi'")
        lg.kinetic("T of wheel, translation", m * (l * rate(phi))**2 / 2)
        lg.kinetic("T of wheel, spin", m * a**2 / 2 * (l / a * rate(phi))**2 / 2)
        lg.kinetic("T of wheel, precession", m * a**2 / 4 * rate(phi)**2 / 2)
        lg.generalized_force("drive", [tau])
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Tilt ``eps`` and spin ``psi`` freed; rolling (``F_y``) and contact (``F_z``) restored."""
        se, ce = sp.sin(eps), sp.cos(eps)
        lg = Lagrangian("multiplier", coordinates=[phi, psi, eps],
                        description="axle free to tilt, spin free; multipliers F_y, F_z")
        lg.kinetic("T of wheel, translation", m * l**2 * (rate(eps)**2 + rate(phi)**2 * ce**2) / 2)
        lg.kinetic("T of wheel, rotation", m * a**2 / 2 * (rate(psi) + rate(phi) * se)**2 / 2
                   + m * a**2 / 4 * (rate(eps)**2 + rate(phi)**2 * ce**2) / 2)
        lg.potential("gravity", m * g * l * se)
        lg.generalized_force("drive", [tau, 0, 0])
        lg.velocity_constraint("F_y", [l * ce + a * se, a, 0])
        lg.constraint("F_z", a + l * se - a * ce)
        return lg.equations()

    def pivot_multiplier(self) -> EquationSet:
        """The pivot freed by ``(u_x, u_y, u_z)`` too; ``R`` and ``F_y``, ``F_z`` restored by
        multipliers.  Vectors in inertial components, differentiated as they stand."""
        cp, sp_ = sp.cos(phi), sp.sin(phi)
        se, ce = sp.sin(eps), sp.cos(eps)
        i, j, k = sp.Matrix([cp, sp_, 0]), sp.Matrix([-sp_, cp, 0]), sp.Matrix([0, 0, 1])
        n = ce * i + se * k                   # along the axle, O -> G
        b = -se * i + ce * k                  # up in the wheel's plane
        r_G = u_x * i + u_y * j + u_z * k + l * n
        v_G = r_G.diff(t)
        w = rate(phi) * k - rate(eps) * j + rate(psi) * n
        v_C = v_G + w.cross(-a * b)           # the wheel's material point at C
        # |r_G'|^2, w . n and |w|^2 from their components on i, j, k, each with
        # sin^2 + cos^2 = 1 used (the azimuth phi drops out of them, as it must)
        unit = {sp.sin(x)**2: 1 - sp.cos(x)**2 for x in (phi, eps)}
        tidy = lambda e: sp.expand(sp.expand(e).xreplace(unit))  # noqa: E731
        on_ijk = lambda v: [tidy(v.dot(e)) for e in (i, j, k)]  # noqa: E731
        speed2 = sum(c**2 for c in on_ijk(v_G))
        spin = tidy(w.dot(n))
        turn2 = sum(c**2 for c in on_ijk(w))
        coords = [phi, psi, eps, u_x, u_y, u_z]
        lg = Lagrangian("pivot_multiplier", coordinates=coords,
                        description="pivot and contact freed; multipliers R_x, R_y, R_z, "
                        "F_y, F_z")
        lg.kinetic("T of wheel, translation", m * speed2 / 2)
        lg.kinetic("T of wheel, rotation", m * a**2 / 2 * spin**2 / 2
                   + m * a**2 / 4 * (turn2 - spin**2) / 2)
        lg.potential("gravity", m * g * r_G.dot(k))
        lg.generalized_force("drive", [tau, 0, 0, 0, 0, 0])
        lg.constraint("R_x", u_x)
        lg.constraint("R_y", u_y)
        lg.constraint("R_z", u_z)
        lg.constraint("F_z", (r_G - a * b).dot(k) + a)
        slip = v_C.dot(j)                     # linear in the rates: its gradient is exact
        lg.velocity_constraint("F_y", [tidy(slip.diff(rate(q))) for q in coords])
        return lg.equations()

    def published(self) -> list[Published]:
        f = frames()
        A, O = f.A, f.O
        i, j, k = A.x, A.y, A.z
        W1, W2 = rate(phi), rate(phi, 2)
        inA = lambda v: tuple(v.express(A).components)  # noqa: E731
        I_G = f.wheel.inertia
        H_G = f.wheel.angular_momentum(f.G, O)
        H_O = f.wheel.angular_momentum(f.o, O)
        p = f.wheel.linear_momentum(O)
        F = F_x * i + F_y * j + F_z * k
        M_O = f.C.pos_from(f.o).cross(F) + f.G.pos_from(f.o).cross(-m * g * O.z)
        H_O_vec = (-m * a * l / 2) * i + (m * a**2 / 4 + m * l**2) * k
        steady_F_y = self.model("angular_momentum").substitute({tau: 0}).reactions_solved()[F_y]
        return [
            Published("(a) inertia about G", "expression",
                      (m * a**2 / 2, m * a**2 / 4, m * a**2 / 4), (I_G[0, 0], I_G[1, 1], I_G[2, 2]),
                      where="(a): I_s = m a^2/2, I = m a^2/4"),
            Published("(a) spin rate", "expression", (-l / a * W1,),
                      (f.W.ang_vel_in(A).dot(i),), where="(a): psi = -(l/a) Omega"),
            Published("(a) L_G", "expression",
                      inA(-m * a**2 / 2 * l / a * W1 * i + m * a**2 / 4 * W1 * k)
                      + inA(m * a**2 / 4 * W1 * (-2 * l / a * i + k)), inA(H_G) + inA(H_G),
                      where="(a): I_s psi i + I Omega k, and factored"),
            Published("(a) p, r_OG, r_OC", "expression",
                      inA(m * W1 * l * j) + inA(l * i) + inA(l * i - a * k),
                      inA(p) + inA(f.G.pos_from(f.o)) + inA(f.C.pos_from(f.o)), where="(a), (b)"),
            Published("(a) L_O, first line", "expression",
                      inA(l * i.cross(m * l * W1 * j) + m * a**2 / 4 * W1 * (-l / a * i + k)),
                      inA(H_O), where="(a): WRONG, L_G copied with -(l/a) i; it is -(2l/a) i"),
            Published("(a) L_O", "expression", inA(W1 * H_O_vec), inA(H_O), where="(a), final"),
            Published("(b) rate of L_O", "expression",
                      inA(W2 * H_O_vec + (W1 * k).cross(W1 * H_O_vec))
                      + inA(W2 * H_O_vec - W1**2 * m * a * l / 2 * j),
                      inA(H_O.dt(O)) + inA(H_O.dt(O)),
                      where="(b): Omega' (...) + w x L_O, and with k x i = j"),
            Published("(b) rate of L_O, steady", "expression",
                      inA(-W1**2 * m * a * l / 2 * j), inA(H_O.dt(O).subs(W2, 0)),
                      where="(b): Omega constant (reference: dH_O/dt at phi'' = 0)"),
            Published("(b) sum of moments about O", "expression",
                      (F_y * a, -a * F_x - l * F_z + m * g * l, F_y * l), inA(M_O),
                      where="(b): contact force and weight (the drive is not in the source)"),
            Published("(b) F_y", "expression", (0,), (steady_F_y,),
                      where="(b): on the steady motion (reference: the angular-momentum "
                      "model's F_y at tau = 0)"),
            Published("(b) contact force relation", "equation",
                      (m * a * l * W1**2 / 2 - a * F_x - (F_z - m * g) * l,),
                      where="(b): (1/2) m a l v^2 = a F_x + (F_z - m g) l, v read as Omega"),
        ]


PROBLEMS = (WheelOnPivot,)
