r"""Mass pendulum on an inclined plane that turns at a prescribed rate (rheonomic).

Source: ``sources/004_f75aa9bb64d0737a.txt``, elaboration exam "Dynamics and Stability",
question 1 (a)-(d).  A frictionless plane turns about the horizontal inertial axis ``Y`` by the
prescribed angle ``beta(t)`` (its inclination).  On it, a point mass ``m`` hangs on a rod of
length ``l`` from a pivot A fixed in the plane at distance ``c`` from the axis; ``theta`` is the
rod's angle in the plane.  The plane's normal force on the mass is the multiplier of the
contact constraint.

The prescribed motion is ``beta(t) = beta0 + Omega t + alpha t^2`` (so ``beta' = Omega +
2 alpha t``, ``beta'' = 2 alpha``): general enough for every term of the source, and
polynomial in ``t`` so that the comparator stays exact.

Sign convention (the source's)::

      inertial X, Y (horizontal), Z (up);  plane frame x, y, z = i, j, k turned by beta about Y:
      X = cos(beta) i + sin(beta) k,   Z = cos(beta) k - sin(beta) i,   w = beta' j

         j (in the plane, along the axis Y)
         ^
         |        mass m
         |       o   r_rel = l cos(theta) i + l sin(theta) j  (from A)
         |      /
         |     / l
         |    /theta
      ---A---+---------> i        A = -c i (the axis Y passes through the origin, c from A)
                                  normal force N k on the mass;  rod force S on the mass
                                  along -e_r (towards A);   gravity -m g Z

Frames.  ``O`` inertial; plane ``P = O.child(rot_y(beta(t)))`` (``P.x = i``, ``P.z = k``);
rod ``R = P.child(rot_z(theta))``, ``e_r = R.x``, ``e_th = R.y``.  The mass is at
``r = (l cos(theta) - c) i + l sin(theta) j`` from the origin on the axis.

Free-body diagram of the mass: ``-m g Z``, ``N k`` (plane), ``-S e_r`` (rod).

Kinematics (a): ``v = l theta' (-sin(theta) i + cos(theta) j) + beta' (c - l cos(theta)) k``.
Direct form, ``sum F = m a`` on ``e_r``, ``e_th``, ``k``; on ``k`` (with ``a . k =
beta'' (c - l cos(theta)) + 2 beta' l sin(theta) theta'``, ``Z . k = cos(beta)``)::

    k:     N = m g cos(beta) + m (beta'' (c - l cos(theta)) + 2 beta' l sin(theta) theta')
    e_th:  m (l theta'' - beta'^2 (c - l cos(theta)) sin(theta)) = -m g sin(theta) sin(beta)
    e_r:   S = m l (theta'^2 + beta'^2 cos^2(theta)) - m beta'^2 c cos(theta)
               + m g cos(theta) sin(beta)

(the in-plane part of the acceleration is ``l theta'' e_th - l theta'^2 e_r - beta'^2
(l cos(theta) - c) i``, the centripetal term of the plane's turning; ``-Z . e_r =
cos(theta) sin(beta)``, ``-Z . e_th = -sin(theta) sin(beta)``.)

Lagrangian, written independently, ``beta`` prescribed (b)-(d)::

    T = m (l^2 theta'^2 + beta'^2 (c - l cos(theta))^2)/2,   V = m g (c - l cos(theta)) sin(beta)
    l theta'' - beta'^2 (c - l cos(theta)) sin(theta) + g sin(theta) sin(beta) = 0

The normal force twice more, independently of the free-body diagram:

* ``multiplier``: the mass may leave the plane by ``z`` along ``k``; ``z = 0`` with multiplier
  ``N`` (``N k . dr = N dz``).  The same model frees the rod too: the mass at ``rho e_r``,
  held by ``l - rho = 0`` with multiplier ``S`` (gradient ``-e_r``: the rod force on the mass
  towards the pivot, ``-S e_r . dr = -S drho``), so the rod force is derived twice as well.
* ``contact_velocity`` -- the source's route (d): the mass gets its own angle ``b`` about
  ``Y`` (``T``, ``V`` as above with ``b`` for ``beta``), and the contact is the velocity
  constraint ``(c - l cos(theta)) (b' - beta'(t)) = 0`` -- the normal velocity of the mass
  minus the plane's at the contact point, the source's ``(c - l cos(theta)) B' - V_z = 0``.
  The lever ``c - l cos(theta)`` is the partial velocity of the mass along ``k`` per unit
  ``b'``, so the multiplier ``lambda_B`` is ``N``; the map is ``b = beta(t)``.

Parameter ranges keep ``c > l``, so ``c - l cos(theta) > 0``: the mass never reaches the axis
(where the source's division by ``c - l cos(theta)`` and its constraint would fail).

Errata (see :meth:`PendulumOnRotatingPlane.published`)
------------------------------------------------------
* (a): from the combined line on, the velocity is printed with ``theta''`` where ``theta'``
  belongs (``v = l theta'' (-sin(theta) i + cos(theta) j) + ...``, boxed); ``v_rel`` above it
  has ``theta'`` right.  A misread dot cannot be ruled out.
* (d), closing remark: "solved simultaneously for the 2 unknowns theta' and the normal contact
  force A_B" -- the unknowns are ``theta''`` and ``lambda_B`` (``A_B`` is the lever).  Prose,
  not transcribed.

Garbled: ``beta`` is extracted as ``B``, ``R`` or ``beta``, and the inertial unit vectors of
``V_xyz = beta' c (sin(beta) I + cos(beta) K)`` lose their distinction from ``i, k``; the
meaning follows from the next line (``= beta' c k``).  The source's ``lambda_B`` is written
``N`` here.

Example
-------
>>> p = PendulumOnRotatingPlane(); p.validate()
>>> sp.factor(p.model("newton_euler").reactions_solved()[N].subs(alpha, 0))  # steady turning
m*(2*Omega*l*sin(theta(t))*Derivative(theta(t), t) + g*cos(Omega*t + beta0))
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_y, rot_z, t,
                      ACCELERATION, ANGLE, FORCE, FREQUENCY, LENGTH, MASS)

__all__ = ["PendulumOnRotatingPlane", "PROBLEMS", "frames", "plane_angle", "hand_rod_force",
           "on_plane", "m", "l", "c", "g", "beta0", "Omega", "alpha", "theta", "N"]

m, l, c, g = sp.symbols("m l c g", positive=True)
beta0, Omega, alpha = sp.symbols("beta0 Omega alpha", real=True)
theta = coordinate("theta")
beta = coordinate("beta")    # the plane's angle, prescribed in every model
b = coordinate("b")          # the mass's own angle about Y (the source's route)
z = coordinate("z")          # the mass's height off the plane
rho = coordinate("rho")      # the mass's distance from the pivot (rod freed), multiplier only
N = sp.Symbol("N", real=True)


def plane_angle():
    """The prescribed ``beta(t) = beta0 + Omega t + alpha t^2``."""
    return beta0 + Omega * t + alpha * t**2


def hand_rod_force():
    """The rod force ``S`` by hand (the ``e_r`` balance of the module docstring)."""
    bd = plane_angle().diff(t)
    return (m * l * (rate(theta)**2 + bd**2 * sp.cos(theta)**2) - m * bd**2 * c * sp.cos(theta)
            + m * g * sp.cos(theta) * sp.sin(plane_angle()))


def on_plane(expr):
    """``expr`` with the coordinate ``beta`` and its rates replaced by the prescribed motion."""
    bt = plane_angle()
    return sp.sympify(expr).xreplace({rate(beta, 2): bt.diff(t, 2), rate(beta): bt.diff(t)}).xreplace(
        {beta: bt})


def frames() -> SimpleNamespace:
    """Frames ``O, P, R``; points ``o`` (on the axis), ``a`` (pivot), ``mass``; the particle."""
    O = Frame.ground("O")
    P = O.child("P", rot_y(plane_angle()))
    R = P.child("R", rot_z(theta))
    o = Point.origin(O, "O")
    a = o.locate("A", -c * P.x)
    mass = a.locate("mass", l * R.x)
    return SimpleNamespace(O=O, P=P, R=R, o=o, a=a, mass=mass, particle=Particle("mass", m, mass))


def _energies(angle):
    """The source's ``T`` and ``V`` with the plane (or the mass) at ``angle`` about ``Y``."""
    lever = c - l * sp.cos(theta)
    T = m * (l**2 * rate(theta)**2 + rate(angle)**2 * lever**2) / 2
    V = m * g * lever * sp.sin(angle)
    return T, V


class PendulumOnRotatingPlane(Problem):
    """Point-mass pendulum on a plane turned at a prescribed rate (see module doc)."""

    name = "pendulum_on_rotating_plane"
    title = "Mass pendulum on a rotating inclined plane"
    source = "004_f75aa9bb64d0737a.txt: question 1 (a)-(d)"
    summary = ("Rheonomic: the plane's angle beta(t) is prescribed; the normal force from the "
               "free-body diagram, a height multiplier and the source's velocity constraint.")
    parameters = (
        Parameter(m, MASS, 0.5, (0.05, 5.0), "mass of the bob"),
        Parameter(l, LENGTH, 0.5, (0.1, 0.9), "length of the rod"),
        Parameter(c, LENGTH, 1.5, (1.0, 3.0), "distance of the pivot from the axis (c > l)"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(beta0, ANGLE, 0.3, (-1.5, 1.5), "plane angle at t = 0"),
        Parameter(Omega, FREQUENCY, 0.8, (-3.0, 3.0), "plane's rate at t = 0"),
        Parameter(alpha, FREQUENCY**2, 0.1, (-1.0, 1.0), "half the plane's angular acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-3.0, 3.0), (-4.0, 4.0), "rod angle in the plane, from i"),
    )
    extra_coordinates = (
        Coordinate(b, ANGLE, (-3.0, 3.0), (-3.0, 3.0), "mass's own angle about Y"),
        Coordinate(z, LENGTH, (-0.05, 0.05), (-0.5, 0.5), "height of the mass off the plane"),
        Coordinate(rho, LENGTH, (0.1, 0.9), (0.01, 2.0), "distance of the mass from the pivot "
                   "(rod freed)"),
    )
    reactions = (
        Reaction("N", FORCE, "plane on the mass, along k (the plane's normal)"),
        Reaction("S", FORCE, "rod on the mass, along -e_r (towards the pivot)"),
    )
    extra_models = ("multiplier", "contact_velocity")

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, z: 0, rho: l},
                "contact_velocity": {theta: theta, b: plane_angle()}}

    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on ``e_r``, ``e_th`` and the plane's normal ``k``."""
        f = frames()
        ne = NewtonEuler("newton_euler", coordinates=[theta], ground=f.O,
                         description="sum F = m a on the mass, on e_r, e_th, k")
        ne.gravity(-g * f.O.z)
        ne.reaction("N", f.particle, f.P.z)
        ne.reaction("S", f.particle, -f.R.x)
        for axis in (f.R.x, f.R.y, f.P.z):
            ne.linear_momentum(f.particle, axis)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """The source's ``T`` and ``V``, ``beta`` prescribed."""
        T, V = _energies(beta)
        lg = Lagrangian("lagrange", coordinates=[theta, beta], description="(b), (c); beta(t)")
        lg.kinetic("T of mass", T)
        lg.potential("gravity", V)
        lg.prescribe(beta, plane_angle())
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """The mass off the plane by ``z`` and off the rod's length by ``rho``, held by ``N``
        and ``S``."""
        r_plane = sp.Matrix([rho * sp.cos(theta) - c, rho * sp.sin(theta), z])
        r = rot_y(beta) * r_plane               # inertial X, Y, Z components
        lg = Lagrangian("multiplier", coordinates=[theta, z, rho, beta],
                        description="mass freed from the plane and the rod, held by N and S")
        lg.kinetic("T of mass", m * (rate(r).T * rate(r))[0, 0] / 2)
        lg.potential("gravity", m * g * r[2])
        lg.constraint("N", z)
        lg.constraint("S", l - rho)             # gradient -e_r: S pulls towards the pivot
        lg.prescribe(beta, plane_angle())
        return lg.equations()

    def contact_velocity(self) -> EquationSet:
        """The source's route (d): the mass's angle ``b``, contact as a velocity constraint."""
        T, V = _energies(b)
        lever = c - l * sp.cos(theta)
        lg = Lagrangian("contact_velocity", coordinates=[theta, b],
                        description="(d): (c - l cos theta) b' - V_z = 0 with multiplier N")
        lg.kinetic("T of mass", T)
        lg.potential("gravity", V)
        lg.velocity_constraint("N", [0, lever], -lever * plane_angle().diff(t))
        return lg.equations()

    def published(self) -> list[Published]:
        f = frames()
        O, P = f.O, f.P
        s, co = sp.sin(theta), sp.cos(theta)
        sb, cb = sp.sin(beta), sp.cos(beta)
        th1, th2, b1, b2 = rate(theta), rate(theta, 2), rate(beta), rate(beta, 2)
        lever = c - l * co
        inP = lambda v: tuple(v.express(P).components)  # noqa: E731
        inO = lambda v: tuple(v.express(O).components)  # noqa: E731
        v = f.mass.vel(O)
        T, V = _energies(beta)
        L = T - V
        pub = [
            Published("(a) r_rel, v_rel, w", "expression",
                      (l * co, l * s, 0, -l * s * th1, l * co * th1, 0, 0, b1, 0),
                      inP(f.mass.pos_from(f.a)) + inP(f.mass.pos_from(f.a).dt(P))
                      + inP(P.ang_vel_in(O)), where="(a)"),
            Published("(a) V_xyz", "expression",
                      (b1 * c * sb, 0, b1 * c * cb, 0, 0, b1 * c),
                      inO(f.a.vel(O)) + inP(f.a.vel(O)),
                      where="(a): beta' c (sin(beta) X + cos(beta) Z) = beta' c k"),
            Published("(a) X and Z in x, y, z", "expression",
                      (cb, 0, sb, -sb, 0, cb), inP(O.x) + inP(O.z), where="(a)"),
            Published("(a) v", "expression",
                      (-l * th2 * s, l * th2 * co, b1 * lever), inP(v),
                      where="(a), boxed: WRONG as extracted, theta'' for theta' in "
                      "l theta' (-sin(theta) i + cos(theta) j)"),
            Published("(b) T", "expression", (m * (l**2 * th1**2 + b1**2 * lever**2) / 2,),
                      (f.particle.kinetic_energy(O),), where="(b), boxed"),
            Published("(c) V, L", "expression",
                      (m * g * lever * sb, T - m * g * lever * sb),
                      (m * g * f.mass.pos_from(f.o).dot(O.z),
                       f.particle.kinetic_energy(O) - m * g * f.mass.pos_from(f.o).dot(O.z)),
                      where="(c), boxed"),
            Published("(d) constraint v_z", "expression", (b1 * lever,), (v.dot(P.z),),
                      where="(d): v . k = beta' (c - l cos(theta))"),
            Published("(d) theta: dL/dtheta', d/dt, dL/dtheta", "expression",
                      (m * l**2 * th1, m * l**2 * th2,
                       m * b1**2 * lever * l * s - m * g * l * s * sb),
                      (L.diff(th1), L.diff(th1).diff(t), L.diff(theta)), where="(d)"),
            Published("(d) theta equation", "equation",
                      (m * l**2 * th2 - m * b1**2 * lever * l * s + m * g * l * s * sb,),
                      where="(d)"),
            Published("(d) equation of motion", "motion",
                      (l * th2 - b1**2 * lever * s + g * s * sb,), where="(d), boxed"),
            Published("(d) beta: dL/dbeta', d/dt, dL/dbeta", "expression",
                      (m * b1 * lever**2, m * b2 * lever**2 + 2 * m * b1 * lever * l * s * th1,
                       -m * g * lever * cb),
                      (L.diff(b1), L.diff(b1).diff(t), L.diff(beta)), where="(d)"),
            Published("(d) beta equation with lambda_B", "equation",
                      (m * b2 * lever**2 + 2 * m * b1 * lever * l * s * th1 + m * g * lever * cb
                       - N * lever,), where="(d), lambda_B written N"),
            Published("(d) normal force lambda_B", "expression",
                      (m * b2 * lever + 2 * m * b1 * l * s * th1 + m * g * cb,), (N,),
                      where="(d): divided by c - l cos(theta)"),
        ]
        return [Published(p.label, p.kind, tuple(on_plane(e) for e in p.printed),
                          tuple(on_plane(e) for e in p.reference), p.where)
                for p in pub]


PROBLEMS = (PendulumOnRotatingPlane,)
