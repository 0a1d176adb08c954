r"""Ball in a sphere: a spherical pendulum and its first integrals (Cambridge 3C5).

Source: ``sources/002_df41972c66c4514e.txt``, section 3 ("Conservation of Momentum and
Energy"), "Lagrange example: Ball in a Sphere".

A small ball (a particle ``m``) slides without friction on the inside of a sphere of radius
``a``; it starts at latitude ``theta0`` with velocity ``v`` horizontal.  The source uses the
momentum of the cyclic longitude and the energy instead of the equations of motion.

Sign convention (the figure is missing from the extraction; ``V = m g a cos theta`` fixes
``theta`` as measured from the *upward* vertical, so the ball is below the equator when
``theta > pi/2``)::

                 Z (up, the N-S axis)
                 |
                 |  theta            r_ball = a e_r,
                 | /                 e_r = (sin th cos ph, sin th sin ph, cos th)
                 |/                  e_theta = d e_r / d theta  (towards the south pole)
          -------O------- Y          e_phi   = Z x e_r / sin th (eastwards)
                / \
               /   o ball m          gravity -g Z;  the sphere pushes -N e_r (inwards)
              X  phi (about Z, from X)

Frames.  ``O`` inertial; ``A = O`` rotated by ``phi`` about ``Z`` (``rot_z``); ``B = A``
rotated by ``theta`` about ``A.y`` (``rot_y``).  Then ``B.z = e_r``, ``B.x = e_theta``,
``B.y = e_phi``.  The ball is the particle ``m`` at ``a B.z``, with
``v = a theta' e_theta + a sin(theta) phi' e_phi`` ("longitudinal velocity ``a theta'``,
circumferential velocity ``a sin(theta) phi'``", as the source says).

Free-body diagram (Newton--Euler): weight ``-m g Z``, the sphere's normal force ``-N e_r``::

        e_theta:  m a (theta'' - sin th cos th phi'^2)        =  m g sin th
        e_phi:    m a (sin th phi'' + 2 cos th theta' phi')   =  0
        e_r:     -m a (theta'^2 + sin^2 th phi'^2)            = -N - m g cos th
        =>  N = m a (theta'^2 + sin^2 th phi'^2) - m g cos th

Moments about the centre O (the normal force passes through O): along ``Z``,
``d/dt (m a^2 sin^2 th phi') = 0`` -- the conserved angular momentum about the N-S axis; along
``e_phi``, the ``theta`` equation again.

Lagrangian (written independently)::

        T = m a^2 (theta'^2 + sin^2 th phi'^2) / 2,       V = m g a cos th
        phi is cyclic:  dT/dphi' = m a^2 sin^2 th phi' = const
        no forces work: T + V = const

The normal force once more, independently: free the radius ``r`` and close it with the
constraint ``a - r = 0`` (multiplier ``N``; ``-N e_r`` does virtual work ``-N delta r``).

First integrals, as the source prints them (initial state ``theta = theta0``,
``theta' = 0``, ``phi' = v / (a sin theta0)``)::

        m a^2 sin^2 th phi' = const   =>   sin^2 th phi' = (v/a) sin theta0
        m (a^2 theta'^2 + a^2 sin^2 th phi'^2)/2 + m g a cos th
              = m a^2 sin^2 theta0 (v / (a sin theta0))^2 / 2 + m g a cos theta0

How they are judged.  "``E = const``" is a claim about the motion, not an identity in the
state, so it is judged as the equation ``dE/dt = 0``: its left side (with the accelerations)
must vanish on the equations of motion, which the checker decides exactly.  The value of the
constant is judged separately: the printed right side must equal the printed left side
evaluated at the initial state, an identity in the parameters.  Together the two say that
the printed equation holds along the source's motion.  A simulated trajectory checks the same
numerically (tests).

Reading the extraction.  The energy line is printed ``2m [a^2 theta'^2 + a^2 sin^2 theta
theta'^2]``: the ``1/2`` lost its bar, and the second ``theta'`` is a misread ``phi'`` (its right
side puts ``phi'0 = v/(a sin theta0)`` into that very term).  The line after it (the energy
equation divided by ``m a^2 / 2``) is garbled beyond reading except for its last term
``2 (g/a) cos theta``; it is not transcribed.  ``phi`` appears as ``Ø``/``∅`` throughout.  No
errata among the lines that could be read.

Example
-------
>>> p = BallInSphere(); p.validate()
>>> sp.factor(p.model("lagrange").mass_matrix().det())
a**4*m**2*sin(theta(t))**2
"""
from __future__ import annotations

import sympy as sp

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Particle,
                      Point, Problem, Published, Reaction, coordinate, rate, rot_y, rot_z, t,
                      ACCELERATION, ANGLE, FORCE, LENGTH, MASS, VELOCITY)

__all__ = ["BallInSphere", "PROBLEMS", "m", "a", "g", "v", "theta0", "theta", "phi", "r",
           "hand_normal_force", "printed_momentum", "printed_energy", "initial_state"]

m, a, g, v, theta0 = sp.symbols("m a g v theta0", positive=True)
theta, phi = coordinate("theta"), coordinate("phi")
r = coordinate("r")  # distance of the ball from the centre, only in the multiplier model


def hand_normal_force() -> sp.Expr:
    """The sphere's push on the ball (inwards), by hand: ``m a (th'^2 + sin^2 th ph'^2) - m g cos th``."""
    return m * a * (rate(theta)**2 + sp.sin(theta)**2 * rate(phi)**2) - m * g * sp.cos(theta)


def printed_momentum() -> sp.Expr:
    """The source's conserved momentum, ``dT/dphi' = m a^2 sin^2(theta) phi'``."""
    return m * a**2 * sp.sin(theta)**2 * rate(phi)


def printed_energy() -> sp.Expr:
    """The left side of the source's energy equation, ``T + V``."""
    return (m * (a**2 * rate(theta)**2 + a**2 * sp.sin(theta)**2 * rate(phi)**2) / 2
            + m * g * a * sp.cos(theta))


def initial_state(phi_rate=None) -> dict:
    """The source's start: ``theta = theta0``, ``theta' = 0``, ``phi = 0``, ``phi' = phi_rate``.

    ``phi_rate`` defaults to the printed ``v / (a sin theta0)``.
    """
    phi_dot = v / (a * sp.sin(theta0)) if phi_rate is None else phi_rate
    return {rate(theta): 0, rate(phi): phi_dot, theta: theta0, phi: 0}


def _at(expr, state: dict):
    """``expr`` at a state: rates first, then coordinates."""
    rates = {k: w for k, w in state.items() if k.has(sp.Derivative)}
    places = {k: w for k, w in state.items() if not k.has(sp.Derivative)}
    return expr.xreplace(rates).xreplace(places)


class _Scene:
    """Frames, points and the ball of the direct form (also used for published references)."""

    def __init__(self):
        self.O = Frame.ground("O")
        self.A = self.O.child("A", rot_z(phi))
        self.B = self.A.child("B", rot_y(theta))
        self.o = Point.origin(self.O, "centre")
        self.P = self.o.locate("ball", a * self.B.z)
        self.ball = Particle("ball", m, self.P)


class BallInSphere(Problem):
    """Particle ``m`` on the inside of a sphere of radius ``a`` (see module doc)."""

    name = "ball_in_sphere"
    title = "Ball in a sphere (spherical pendulum)"
    source = "002_df41972c66c4514e.txt: section 3, Lagrange example: ball in a sphere"
    summary = ("Latitude and longitude; the momentum of the cyclic longitude and the energy "
               "as first integrals, the sphere's normal force twice.")
    parameters = (
        Parameter(m, MASS, 0.3, (0.01, 5.0), "mass of the ball"),
        Parameter(a, LENGTH, 0.5, (0.05, 3.0), "radius of the sphere"),
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(v, VELOCITY, 1.2, (0.1, 5.0), "initial speed, horizontal"),
        Parameter(theta0, ANGLE, 2.4, (0.3, 2.8), "initial latitude, from the upward vertical"),
    )
    coordinates = (
        Coordinate(theta, ANGLE, (0.3, 2.85), (-4.0, 4.0), "latitude, from the upward vertical"),
        Coordinate(phi, ANGLE, (-3.0, 3.0), (-6.0, 6.0), "longitude, about the vertical"),
    )
    extra_coordinates = (
        Coordinate(r, LENGTH, (0.05, 3.0), (-1.0, 1.0), "distance of the ball from the centre"),
    )
    reactions = (Reaction("N", FORCE, "sphere on ball, along -e_r (towards the centre)"),)
    singular = (sp.sin(theta),)
    extra_models = ("angular_momentum", "multiplier")
    unilateral = {"N": "the ball leaves the sphere's wall"}

    def coordinate_maps(self) -> dict:
        return {"multiplier": {theta: theta, phi: phi, r: a}}

    def newton_euler(self) -> EquationSet:
        """``sum F = m a`` on the ball along ``e_theta``, ``e_phi``, ``e_r``."""
        sc = _Scene()
        ne = NewtonEuler("newton_euler", coordinates=[theta, phi], ground=sc.O,
                         description="sum F = m a on the ball, along e_theta, e_phi, e_r")
        ne.gravity(-g * sc.O.z)
        ne.reaction("N", sc.ball, -sc.B.z)
        for axis in (sc.B.x, sc.B.y, sc.B.z):
            ne.linear_momentum(sc.ball, axis)
        return ne.equations()

    def angular_momentum(self) -> EquationSet:
        """Moments about the centre along ``Z`` and ``e_phi``; ``N`` passes through the centre."""
        sc = _Scene()
        ne = NewtonEuler("angular_momentum", coordinates=[theta, phi], ground=sc.O,
                         description="sum tau_O = dh_O/dt along the N-S axis and e_phi")
        ne.gravity(-g * sc.O.z)
        ne.angular_momentum(sc.ball, sc.O.z, about=sc.o)
        ne.angular_momentum(sc.ball, sc.B.y, about=sc.o)
        return ne.equations()

    def lagrange(self) -> EquationSet:
        """``T = m a^2 (theta'^2 + sin^2 theta phi'^2)/2``, ``V = m g a cos theta`` by hand."""
        lg = Lagrangian("lagrange", coordinates=[theta, phi], description="T and V by hand")
        lg.kinetic("T of ball", m * a**2 * (rate(theta)**2 + sp.sin(theta)**2 * rate(phi)**2) / 2)
        lg.potential("gravity", m * g * a * sp.cos(theta))
        return lg.equations()

    def multiplier(self) -> EquationSet:
        """``(theta, phi, r)`` with the sphere as the constraint ``a - r = 0`` (multiplier ``N``)."""
        lg = Lagrangian("multiplier", coordinates=[theta, phi, r],
                        description="the ball freed from the sphere, held by a multiplier")
        lg.kinetic("T of ball", m * (rate(r)**2 + r**2 * rate(theta)**2
                                     + r**2 * sp.sin(theta)**2 * rate(phi)**2) / 2)
        lg.potential("gravity", m * g * r * sp.cos(theta))
        lg.constraint("N", a - r)
        return lg.equations()

    def published(self) -> list[Published]:
        sc = _Scene()
        vel = sc.P.vel(sc.O)
        v_theta, v_phi = vel.dot(sc.B.x), vel.dot(sc.B.y)
        T_ref = sc.ball.kinetic_energy(sc.O)
        V_ref = m * g * sc.P.pos_from(sc.o).dot(sc.O.z)
        energy = T_ref + V_ref
        # the start: horizontal speed v at latitude theta0 fixes phi'0 (from the frames)
        rate0 = v / v_phi.diff(rate(phi)).subs(theta, theta0)
        start = initial_state(rate0)
        T_printed = printed_energy() - m * g * a * sp.cos(theta)
        qs = (theta, phi)
        lagrange_sum = sum(rate(q) * (T_ref.diff(rate(q)).diff(t) - T_ref.diff(q) + V_ref.diff(q))
                           for q in qs)
        where = "section 3, ball in a sphere"
        return [
            Published("longitudinal and circumferential velocity", "expression",
                      (a * rate(theta), a * sp.sin(theta) * rate(phi)), (v_theta, v_phi), where=where),
            # Right: dT/dphi' is the angular momentum about the N-S axis.
            Published("momentum dT/dphi'", "expression", (printed_momentum(),),
                      (sc.ball.angular_momentum(sc.o, sc.O).dot(sc.O.z),),
                      where=where + ": m a^2 sin^2 theta phi' = const"),
            # Right: judged as d/dt (momentum) = 0 on the motion.
            Published("momentum is conserved", "equation", (printed_momentum().diff(t),),
                      where=where + ": d/dt of m a^2 sin^2 theta phi' vanishes on the motion"),
            Published("initial longitude rate", "expression", (v / (a * sp.sin(theta0)),),
                      (rate0,), where=where + ": at t = 0 phi' = v / (a sin theta0)"),
            # Right: the printed left side at the start is sin^2 theta0 * v/(a sin theta0).
            Published("value of the momentum", "expression", (v / a * sp.sin(theta0),),
                      (_at(sp.sin(theta)**2 * rate(phi), start),),
                      where=where + ": sin^2 theta phi' = (v/a) sin theta0"),
            Published("energy T + V", "expression", (printed_energy(),), (energy,),
                      where=where + " (printed '2m [...]' for m/2 [...], theta' for phi')"),
            # Right: judged as dE/dt = 0 on the motion.
            Published("energy is conserved", "equation", (printed_energy().diff(t),),
                      where=where + ": d/dt (T + V) vanishes on the motion"),
            Published("value of the energy", "expression",
                      (m * a**2 * sp.sin(theta0)**2 * (v / (a * sp.sin(theta0)))**2 / 2
                       + m * g * a * sp.cos(theta0),), (_at(energy, start),),
                      where=where + ": right side of the energy equation"),
            # Section 3.2, applied to the ball: T is quadratic in the rates, so the sum is 2T.
            Published("sum q' dT/dq' = 2T", "expression",
                      (sum(rate(q) * T_printed.diff(rate(q)) for q in qs),),
                      (2 * T_ref,), where="section 3.2, applied"),
            # Section 3.2: the sum of q'_i times Lagrange's equations vanishes on the motion.
            Published("sum q' (Lagrange's equation)", "equation", (lagrange_sum,),
                      where="section 3.2, applied: sum q'_i [d/dt dT/dq'_i - dT/dq_i + "
                      "dV/dq_i] = 0"),
        ]


PROBLEMS = (BallInSphere,)
