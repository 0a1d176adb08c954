r"""Toy car on a rotating track (MIT 2.003J, spring 2011, quiz 1).

A point-mass car (mass ``m``) rolls without slipping on a massless circular track of radius
``R`` centred at O.  The track pivots about the horizontal ground axis ``I``; the car runs
round the track.  Two coordinates: ``phi``, the track's tilt from the vertical, and ``theta``,
the car's angle from the bottom of the track.

Sign convention::

    side view, I out of the page           track plane, i_A to the right, k_A up

      k_A       K                                   k_A
         \  phi |                                    |
          \     |                                    |
           \    |                                    O ------> i_A = I
            \   |                                   /:
             \  |                          -R k_B  / :
              \ |                                 /  : theta
               \|                               car  :
                O ------> J                          -R k_A (bottom of the track)

    K x k_A = sin(phi) I (phi > 0 tips k_A towards -J);  k_A x k_B = sin(theta) j_A

Frames (rotation matrices, columns = the child's unit vectors in the parent)::

    O = (O, I, J, K)             ground, gravity -g K
    A = O.child(rot_x(phi))      track:  i_A = I,   j_A, k_A
    B = A.child(rot_y(theta))    car:    i_B, j_B = j_A, k_B
    r_car = -R k_B

Body and free-body diagram: one particle ``m`` at ``-R k_B``; weight ``-m g K``; the track's
force ``F_r k_B`` (along ``k_B`` only -- the wheels are frictionless so there is no ``i_B``
component, and the massless track transmits no ``j_B`` component, question (6)).

Direct form (questions 8-10), ``sum F = m a`` projected on B::

    i_B:  m g sin(theta) cos(phi)  = m R (-theta'' - phi'^2 sin(theta) cos(theta))
    j_B: -m g sin(phi)             = m R (phi'' cos(theta) - 2 phi' theta' sin(theta))
    k_B:  F_r - m g cos(theta) cos(phi) = m R (phi'^2 cos^2(theta) + theta'^2)

Angular momentum about the fixed point O (question B) -- the reaction passes through O::

    h_O = m R^2 (phi' cos(theta) i_B + theta' j_B)
    tau_O = -m g R (sin(phi) i_B + cos(phi) sin(theta) j_B) = d/dt h_O

Lagrangian, written independently::

    T = m R^2 (theta'^2 + phi'^2 cos^2(theta)) / 2,     V = -m g R cos(theta) cos(phi)

The track's force once more, independently: free the car from the track with a third
coordinate ``rho`` (distance from O, ``r_car = -rho k_B``) and the constraint ``R - rho = 0``
with multiplier ``F_r``::

    T = m (rho'^2 + rho^2 (theta'^2 + phi'^2 cos^2(theta))) / 2,  V = -m g rho cos(theta) cos(phi)
    rho:  m rho'' - m rho (theta'^2 + phi'^2 cos^2(theta)) - m g cos(theta) cos(phi) + F_r = 0

(``F_r k_B`` does virtual work ``-F_r d(rho)``; the constraint contributes
``F_r d(R - rho)/d(rho) = -F_r``), so on the track ``F_r = m (g cos(theta) cos(phi)
+ R phi'^2 cos^2(theta) + R theta'^2)``, as the free-body diagram gives.

The mass matrix ``diag(m R^2, m R^2 cos^2 theta)`` is singular at ``cos(theta) = 0`` (car at
the track's pivot axis: ``phi`` no longer moves it).

Errata found in the printed solution (see :meth:`ToyCar.published`):

* (9) restates the vector equation of (8) with ``+ 2 phi' theta' sin(theta) j_B``; the
  Coriolis term is ``-2 R phi' theta' sin(theta) j_B`` (as (8) prints it).  The boxed
  scalar equations of (9) are right.
* (B) torque of gravity about O is printed ``-m g (sin(theta) i_B + cos(theta) sin(phi) j_B)``;
  it is ``-m g R (sin(phi) i_B + cos(phi) sin(theta) j_B)`` -- the factor ``R`` is missing and
  the angles are swapped.  From its third line on, the rate of ``h_O`` is printed with ``m R``
  instead of ``m R^2``, so the printed vector equation of (B) is wrong too; two errors cancel
  in the boxed equations, which are right.
* The question statement of (2) prints ``v_0 = v_N j_B v_T i_B`` (operator lost); the solution
  uses ``v_N j_B - v_T i_B``, which is what the initial rates assume.
"""
from __future__ import annotations

from types import SimpleNamespace

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Probe, Problem, Published, Reaction, RelativeMotion, Vector,
                      coordinate, rate, rot_x, rot_y, ACCELERATION, ANGLE, FORCE, LENGTH, MASS)

__all__ = ["ToyCar", "PROBLEMS", "frames", "coriolis_term", "m", "R", "g", "theta", "phi", "rho"]

m, R, g = sp.symbols("m R g", positive=True)
theta, phi = coordinate("theta"), coordinate("phi")
rho = coordinate("rho")  # distance of the car from O, only in the multiplier model
F_r = sp.Symbol("F_r", real=True)





def frames() -> SimpleNamespace:
    """Frames and points of the direct form: ``O, A, B`` and the points ``o`` (centre), ``car``."""
    O = Frame.ground("O")
    A = O.child("A", rot_x(phi))
    B = A.child("B", rot_y(theta))
    o = Point.origin(O, "O")
    car = o.locate("car", -R * B.z)
    return SimpleNamespace(O=O, A=A, B=B, o=o, car=car)


def coriolis_term(f: SimpleNamespace | None = None) -> Vector:
    """The Coriolis term of question (5): ``2 w_A x v_rel`` of the car moving in the track frame A.

    Hand derivation: in A the car moves on a circle, ``v_rel = d/dt|_A (-R k_B) = -R theta' i_B``,
    and ``w_A = phi' I``, so ``2 w_A x v_rel = -2 R phi' theta' (I x i_B)
    = -2 R phi' theta' sin(theta) j_B``.

    ``f`` are the frames to express it in (default: fresh :func:`frames`); the result has
    components in ``f.B``.

    >>> coriolis_term().simplify().components.T
    Matrix([[0, -2*R*sin(theta(t))*Derivative(phi(t), t)*Derivative(theta(t), t), 0]])
    """
    f = f or frames()
    return RelativeMotion.of(f.car, f.o, f.A, f.O).coriolis.express(f.B)


class ToyCar(Problem):
    """Point-mass car on a circular track that pivots about a horizontal axis (see module doc)."""

    name = "toy_car"
    title = "Toy car on rotating track"
    source = "001_9d08622cf8d659c2.txt: 2.003J spring 2011, quiz 1"
    summary = ("Point mass on a circular track tilting about a horizontal axis: two angles, "
               "the track's normal force recovered from the direct form.")
    parameters = (
        Parameter(m, MASS, 0.2, (0.01, 5.0), "mass of the car"),
        Parameter(R, LENGTH, 0.5, (0.05, 5.0), "radius of the track"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (-1.2, 1.2), (-3.0, 3.0), "car angle from the track's bottom"),
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-3.0, 3.0), "track tilt from the vertical"),
    )
    extra_coordinates = (
        Coordinate(rho, LENGTH, (0.05, 5.0), (-1.0, 1.0), "distance of the car from O"),
    )
    reactions = (Reaction("F_r", FORCE, "along k_B, track on car"),)
    singular = (sp.cos(theta),)
    extra_models = ("angular_momentum", "multiplier")
    unilateral = {"F_r": "the car leaves the track (the track cannot pull it towards O)"}
    probes = (Probe((1.3, 1e-3, 3.5, 0.0), "lagrange", 1.0,
                    "the car runs over the track's pivot axis (cos(theta) = 0), the track "
                    "tilted by 1 mrad"),)

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, phi: phi, rho: R}}

    # -- direct form: sum F = m a (questions 7-10) --------------------------------------
    def newton_euler(self) -> EquationSet:
        f = frames()
        car = Particle("car", m, f.car)
        ne = NewtonEuler(coordinates=[theta, phi], ground=f.O,
                         description="sum F = m a on the car, projected on i_B, j_B, k_B")
        ne.gravity(-g * f.O.z)
        ne.reaction("F_r", car, f.B.z)
        for axis in (f.B.x, f.B.y, f.B.z):
            ne.linear_momentum(car, axis)
        return ne.equations()

    # -- direct form, question (B): angular momentum about the fixed point O ------------
    def angular_momentum(self) -> EquationSet:
        """``sum tau_O = d/dt h_O`` on i_B and j_B.

        The track's force ``F_r k_B`` acts at ``-R k_B``: its moment about O is zero, so it is
        left out of this free-body diagram and the model has no reaction unknowns.
        """
        f = frames()
        car = Particle("car", m, f.car)
        ne = NewtonEuler("angular_momentum", coordinates=[theta, phi], ground=f.O,
                         description="sum tau_O = dh_O/dt on the car, projected on i_B, j_B")
        ne.gravity(-g * f.O.z)
        for axis in (f.B.x, f.B.y):
            ne.angular_momentum(car, axis, about=f.o)
        return ne.equations()

    # -- indirect form -------------------------------------------------------------------
    def lagrange(self) -> EquationSet:
        """By hand: ``v^2 = R^2 (theta'^2 + phi'^2 cos^2 theta)``; height ``-R cos theta cos phi``.

        Nothing of the direct form (frames, points) is reused.
        """
        lg = Lagrangian(coordinates=[theta, phi],
                        description="T and V of the car written by hand")
        lg.kinetic("T of car", m * R**2 * (rate(theta)**2 + rate(phi)**2 * sp.cos(theta)**2) / 2)
        lg.potential("gravity", -m * g * R * sp.cos(theta) * sp.cos(phi))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """Lagrange in ``(theta, phi, rho)`` with the track as the constraint ``R - rho = 0``.

        The multiplier is the track's force ``F_r`` (unit gradient along ``-k_B``, the
        direction in which ``rho`` grows), recovered independently of the free-body diagram.
        """
        lg = Lagrangian("multiplier", coordinates=[theta, phi, rho],
                        description="the car off the track, held on it by a multiplier")
        lg.kinetic("T of car", m * (rate(rho)**2
                                    + rho**2 * (rate(theta)**2 + rate(phi)**2 * sp.cos(theta)**2)) / 2)
        lg.potential("gravity", -m * g * rho * sp.cos(theta) * sp.cos(phi))
        lg.constraint("F_r", R - rho)
        return lg.equations()

    # -- quantities a student may be asked for (dualmech grade) -----------------------------
    def quantities(self) -> dict:
        """Momenta of question (3)/(4) in the car frame B, for answers typed in ``i_B, j_B, k_B``."""
        f = frames()
        car = Particle("car", m, f.car)
        inB = lambda vec: tuple(vec.express(f.B).components)  # noqa: E731
        basis = ("i_B", "j_B", "k_B")
        return {
            "p": {"value": inB(car.linear_momentum(f.O)), "basis": basis,
                  "description": "linear momentum of the car, in the car frame B"},
            "h_O": {"value": inB(car.angular_momentum(f.o, f.O)), "basis": basis,
                    "description": "angular momentum of the car about O, in the car frame B"},
        }

    # -- the source's answers -------------------------------------------------------------
    def published(self) -> list[Published]:
        f = frames()
        O, A, B = f.O, f.A, f.B
        I, K = O.x, O.z
        iB, jB, kB, kA = B.x, B.y, B.z, A.z
        st, ct, sp_, cp = sp.sin(theta), sp.cos(theta), sp.sin(phi), sp.cos(phi)
        th1, ph1, th2, ph2 = rate(theta), rate(phi), rate(theta, 2), rate(phi, 2)
        car = Particle("car", m, f.car)
        v = f.car.vel(O)
        a = f.car.acc(O)
        inB = lambda vec: tuple(vec.express(B).components)  # noqa: E731
        inO = lambda vec: tuple(vec.express(O).components)  # noqa: E731
        h_O = car.angular_momentum(f.o, O)
        tau_O = f.car.pos_from(f.o).cross(-m * g * K)
        a_printed = R * (ph2 * ct * jB - th2 * iB - 2 * ph1 * th1 * st * jB
                         + ph1**2 * ct * kA + th1**2 * kB)
        law_8 = F_r * kB - m * g * K - m * a_printed
        # printed (9): the vector equation again, with + 2 phi' theta' sin(theta) j_B
        a_9 = R * (ph2 * ct * jB - th2 * iB + 2 * ph1 * th1 * st * jB
                   + ph1**2 * ct * kA + th1**2 * kB)
        law_9 = F_r * kB - m * g * K - m * a_9
        dh_printed = m * R * ((ph2 * ct - 2 * ph1 * th1 * st) * iB
                              + (ph1**2 * ct * st + th2) * jB)
        tau_printed = -m * g * (st * iB + ct * sp_ * jB)
        boxed = (R * th2 + R * ph1**2 * ct * st + g * cp * st,
                 R * ph2 * ct - 2 * R * ph1 * th1 * st + g * sp_)
        # (2): v_0 = v_N j_B - v_T i_B defines v_N, v_T; the printed rates must then be theta', phi'
        v_T, v_N = -v.dot(iB), v.dot(jB)
        Ry_T = sp.Matrix([[ct, 0, -st], [0, 1, 0], [st, 0, ct]])
        Rx_T = sp.Matrix([[1, 0, 0], [0, cp, sp_], [0, -sp_, cp]])
        return [
            Published("(1) i_B, j_B, k_B", "expression",
                      (ct, st * sp_, -st * cp, 0, cp, sp_, st, -ct * sp_, ct * cp),
                      inO(iB) + inO(jB) + inO(kB), where="quiz 1 (1), boxed"),
            Published("(1) rotation matrix", "expression", tuple(Ry_T * Rx_T),
                      tuple(O.dcm(B)), where="quiz 1 (1): rows are i_B, j_B, k_B in I, J, K"),
            Published("(2) angular velocities", "expression", (ph1, 0, 0, 0, th1, 0),
                      inO(A.ang_vel_in(O)) + tuple(B.ang_vel_in(A).express(A).components),
                      where="quiz 1 (2): O w_A = phi' I (in O), A w_B = theta' j_A (in A)"),
            Published("(2) initial rates", "expression", (v_T / R, v_N / (R * ct)),
                      (th1, ph1), where="quiz 1 (2): theta0' = v_T/R, phi0' = v_N/(R cos theta),"
                      " with v_0 = v_N j_B - v_T i_B"),
            Published("(3) linear momentum", "expression", (-m * R * th1, m * R * ph1 * ct, 0),
                      inB(car.linear_momentum(O)), where="quiz 1 (3), boxed, in B"),
            Published("(4) angular momentum h_O", "expression",
                      (m * R**2 * ph1 * ct, m * R**2 * th1, 0), inB(h_O),
                      where="quiz 1 (4), boxed, in B"),
            Published("(5) hints", "expression", inB(st * jB) + inB(-ct * jB) + inB(st * jB),
                      inB(I.cross(iB)) + inB(I.cross(kB)) + inB(kA.cross(kB)),
                      where="quiz 1 (5): I x i_B, I x k_B, k_A x k_B"),
            Published("(5) Coriolis term", "expression", (0, -2 * R * ph1 * th1 * st, 0),
                      inB(coriolis_term(f)), where="quiz 1 (5)/(8): the term -2 R phi' theta' "
                      "sin(theta) j_B (the final line of (5) is unreadable in the source text)"),
            Published("(8) acceleration", "expression", inB(a_printed), inB(a),
                      where="quiz 1 (8): right side / m, k_A term converted to B"),
            Published("(8) Newton's second law", "equation", inB(law_8),
                      where="quiz 1 (8): F_r k_B - m g K = m a, on i_B, j_B, k_B"),
            Published("(9) hints", "expression", inB(ct * kB - st * iB) + inB(
                cp * ct * kB - cp * st * iB + sp_ * jB), inB(kA) + inB(K),
                where="quiz 1 (9): k_A and K in B"),
            Published("(9) restated vector equation, j_B", "equation", (law_9.dot(jB),),
                      where="quiz 1 (9): WRONG, prints + 2 phi' theta' sin(theta) j_B; the "
                      "Coriolis term is - 2 R phi' theta' sin(theta) j_B as in (8)"),
            Published("(9) equations of motion", "equation", boxed,
                      where="quiz 1 (9), boxed i_B and j_B equations"),
            Published("(10) reaction F_r", "expression",
                      (m * (g * cp * ct + R * ph1**2 * ct**2 + R * th1**2),), (F_r,),
                      where="quiz 1 (10), boxed"),
            Published("(B) torque of gravity about O", "expression", inB(tau_printed),
                      inB(tau_O), where="quiz 1 (B): WRONG, prints -m g (sin(theta) i_B + "
                      "cos(theta) sin(phi) j_B); correct -m g R (sin(phi) i_B + cos(phi) "
                      "sin(theta) j_B): R missing, angles swapped"),
            Published("(B) rate of h_O", "expression", inB(dh_printed), inB(h_O.dt(O)),
                      where="quiz 1 (B), last line of the derivation: WRONG, m R instead of "
                      "m R^2 (from the third line on)"),
            Published("(B) vector equation", "equation", inB(tau_printed - dh_printed)[:2],
                      where="quiz 1 (B), the unboxed i_B, j_B equation: WRONG (both sides "
                      "above are wrong)"),
            Published("(B) equations of motion", "equation", (boxed[1], boxed[0]),
                      where="quiz 1 (B), boxed i_B and j_B equations (right: the errors "
                      "above cancel)"),
        ]


PROBLEMS = (ToyCar,)
