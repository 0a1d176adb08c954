r"""The benchmark bicycle (Whipple's model): four rigid bodies, two knife-edge wheels rolling
without slipping, hands-free; its upright straight running is self-stable between the weave
and capsize speeds.

Source: J. P. Meijaard, J. M. Papadopoulos, A. Ruina and A. L. Schwab, "Linearized dynamics
equations for the balance and steer of a bicycle: a benchmark and review", *Proc. R. Soc. A*
463 (2007) 1955--1982, doi:10.1098/rspa.2007.1857.  Parameters from its Table 1; the
eigenvalues of its Table 2 and the weave and capsize speeds of its section 5 are the printed
answers.  (Table 2 transcribed from the paper; the same digits are in D. L. Peterson's
``whippleeig.cpp`` of the BicycleDynamics code.)  The nonlinear model below is written here;
only its linearisation is printed in the paper.

Bodies and parameters (the paper's axes: x forward, y to the right, z down, origin at the
rear contact point, in the upright reference configuration): rear wheel R (radius ``rR``,
mass ``mR``, ``IRxx = IRzz``, ``IRyy``); rear body and frame B (mass centre ``(xB, 0, zB)``,
mass ``mB``, inertia ``IBxx, IByy, IBzz, IBxz``); front frame H, handlebar and fork
(``(xH, 0, zH)``, ``mH``, ``IHxx, IHyy, IHzz, IHxz``); front wheel F (``rF``, ``mF``,
``IFxx = IFzz``, ``IFyy``).  Wheelbase ``w``, trail ``c``, steer-axis tilt ``lam`` (from the
vertical, top leaning back), gravity ``g``.  Masses, inertias and ``g`` are parameters (the
exact verdict samples them); the geometry is fixed at Table 1's values as exact numbers
(module constants): with it symbolic, the expanded equations grow past what the derivation
finishes in minutes (the nonlinear bicycle's trigonometric products of nine lengths).

The models use z *up* and y to the *left* (a half turn about x from the paper's axes), so the
heights of the mass centres are ``-zB``, ``-zH`` and the products of inertia change sign:
``I_xz(ours) = -IBxz``, ``-IHxz``.

Sign convention and coordinates (eight)::

      O  ground, O.z up, gravity -g O.z          P  rear contact point, x O.x + y O.y
      Y  = O.child(rot_z(psi))      yaw          C_R = P + rR L.z       rear wheel centre
      L  = Y.child(rot_x(phi))      roll         A  = C_R + (w + c) B.x - rR B.z
      B  = L.child(rot_y(theta))    pitch             (the steer axis's ground point, upright)
      S  = B.child(rot_y(-lam))     steer axis S.z (fixed in B)
      H  = S.child(rot_z(delta))    steer        C_F = A + f1 H.x + f3 H.z  front wheel centre
      wheels: spin thetaR about B.y, thetaF about H.y

with ``f1 = rF sin(lam) - c cos(lam)`` (the fork offset) and ``f3 = rF cos(lam) + c sin(lam)``:
upright, ``C_F = (w, 0, rF)`` and the steer axis meets the ground the trail ``c`` ahead of
the front contact.  The front frame's mass centre is ``A + h1 H.x + h3 H.z`` with
``(h1, h3)`` the components of ``(xH - w - c, -zH)`` on ``S.x = (cos lam, 0, sin lam)`` and
``S.z = (-sin lam, 0, cos lam)``.

Contacts.  The rear wheel's lowest point is ``C_R - rR L.z`` (``L.z`` is the unit vector of the
wheel plane normal to the horizontal ``L.x``).  The front wheel (axle ``a = H.y``, centre
height ``h = C_F . O.z``) has its lowest point at ``C_F - rF (O.z - a_z a) / s`` with ``s =
sqrt(1 - a_z^2)``; the holonomic constraint is its height, ``h - rF s = 0``.  Rolling: the
material point of each wheel at its lowest point has no horizontal velocity; for the front
wheel that velocity is ``v_CF - rF (w_F x (O.z - a_z a)) / s``, and its vertical component is
the time derivative of ``h - rF s`` (``(w_F x a) . O.z = a_z'``).  So every multiplier is a
contact force: ``F_R_x, F_R_y`` (rear rows), ``F_F_x, F_F_y`` (front rows), ``F_F_z`` (the
front contact); only the direct form gives the rear normal force ``F_R_z``.  The two models
are the same system at every state, on the constraints or off them (the rows and the
contact force's point are the same functions of the state).

Direct form (model ``newton_euler``), written with the toolkit's frames: a free-body
diagram per body, ``sum F = m a_G`` on ``O.x, O.y, O.z`` and ``sum tau_G = dH_G/dt`` on the
body's axes; unknown: the contact forces ``F_R``, ``F_F`` (ground axes) at the contact points,
the rear and front hubs' forces ``R_R``, ``R_F`` and couples about the two axes normal to each
axle (``M_Rx, M_Rz``, ``M_Fx, M_Fz``), the steering joint's force ``R_S`` and couples normal
to the steer axis (``M_Sx, M_Sy``): 21 reactions.  The contacts are *declared*, not written
as rows: rolling of each wheel's material point at its contact point along ``O.x, O.y``
(``NewtonEuler.rolling``) and the height of the front contact point (``NewtonEuler.
constraint``; the rear's is built into the coordinates).  The model holds them at their
level and their acceleration-level rows: 24 + 5 = 29 rows for 8 accelerations and 21
reactions.  Because they are declarations, the Kane referee reads them too: it derives the
motion and all 21 reactions a second time from the bodies, loads, reactions and constraints
declared (not from the balances), so every hub and steering-joint reaction and the rear
normal force, which no other model carries, are cross-checked.

Steady motion: upright straight running at speed ``v``: every angle zero, ``x' = v``,
``thetaR' = v / rR``, ``thetaF' = v / rF``.  Linearised, the state reduces to roll, steer and
their rates (and the yaw and a speed, whose eigenvalues vanish at every ``v``); the four
remaining eigenvalues are the paper's Table 2.

Example
-------
>>> p = WhippleBicycle()
>>> [c.name for c in p.coordinates]
['x', 'y', 'psi', 'phi', 'theta', 'delta', 'thetaR', 'thetaF']
"""
from __future__ import annotations

import sympy as sp

from types import SimpleNamespace

from dualmech import (Coordinate, EquationSet, Frame, Lagrangian, NewtonEuler, Parameter, Point,
                      Problem, Published, Reaction, RigidBody, SteadyMotion, coordinate, rate,
                      rot_x, rot_y, rot_z, t, ACCELERATION, ANGLE, FORCE, INERTIA, LENGTH, MASS,
                      TORQUE)

__all__ = ["WhippleBicycle", "PROBLEMS", "TABLE_2", "WEAVE_SPEED", "CAPSIZE_SPEED", "v",
           "COORDS"]

g = sp.Symbol("g", positive=True)
mR, IRxx, IRyy = sp.symbols("mR IRxx IRyy", positive=True)
mB, IBxx, IByy, IBzz = sp.symbols("mB IBxx IByy IBzz", positive=True)
IBxz = sp.Symbol("IBxz", real=True)
mH, IHxx, IHyy, IHzz = sp.symbols("mH IHxx IHyy IHzz", positive=True)
IHxz = sp.Symbol("IHxz", real=True)
mF, IFxx, IFyy = sp.symbols("mF IFxx IFyy", positive=True)

# The geometry of Table 1, exact (the paper's decimals are exact rationals).  The steer axis
# tilt lam = pi/10 enters through its half-angle tangent TAN_HALF_LAM, a rational within
# 3e-16 of tan(pi/20): cos(lam) and sin(lam) are then exact rationals, and lam is pi/10 to
# 6e-16 rad (far below the printed 14 digits).
w, c = sp.Rational("1.02"), sp.Rational("0.08")
rR, rF = sp.Rational("0.3"), sp.Rational("0.35")
xB, zB = sp.Rational("0.3"), sp.Rational("-0.9")
xH, zH = sp.Rational("0.9"), sp.Rational("-0.7")
TAN_HALF_LAM = sp.Rational(2276891, 14375724)
COS_LAM = (1 - TAN_HALF_LAM**2) / (1 + TAN_HALF_LAM**2)
SIN_LAM = 2 * TAN_HALF_LAM / (1 + TAN_HALF_LAM**2)
v = sp.Symbol("v", real=True)    # forward speed of the steady motion (not a model parameter)

x, y, psi, phi = (coordinate(n) for n in ("x", "y", "psi", "phi"))
theta, delta, thetaR, thetaF = (coordinate(n) for n in ("theta", "delta", "thetaR", "thetaF"))
COORDS = [x, y, psi, phi, theta, delta, thetaR, thetaF]

#: Meijaard et al. (2007), Table 2: the eigenvalues of the linearised benchmark bicycle at
#: v = 0, 1, ..., 10 m/s (complex pairs as one entry with its conjugate implied).
TABLE_2 = {
    0: (5.53094371765393, 3.13164324790656, -3.13164324790656, -5.53094371765393),
    1: (3.52696170990070 + 0.807740275199300j, -3.13423125066578, -7.11008014637442),
    2: (2.68234517512745 + 1.68066296590675j, -3.07158645641514, -8.67387984831735),
    3: (1.70675605663975 + 2.31582447384325j, -2.63366137253667, -10.3510146724592),
    4: (0.413253315211250 + 3.07910818603206j, -1.42944427361326, -12.1586142657645),
    5: (-0.775341882195850 + 4.46486771378823j, -0.322866429004090, -14.0783896927982),
    6: (-1.52644486584142 + 5.87673060598709j, -0.00406690076970000, -16.0853712309803),
    7: (-2.13875644258362 + 7.19525913329805j, 0.102681705747660, -18.1578846612526),
    8: (-2.69348683581097 + 8.46037971396931j, 0.143278797657130, -20.2794089439457),
    9: (-3.21675402252485 + 9.69377351531791j, 0.157901840309170, -22.4378855904086),
    10: (-3.72016840437287 + 10.9068113947629j, 0.161053386531720, -24.6245963501740),
}
#: section 5 of the paper: the weave and capsize speeds (m/s)
WEAVE_SPEED = 4.29238253634111
CAPSIZE_SPEED = 6.02426201538837


def _rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def _ry(a):
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])


def _rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def _tilt():
    """``rot_y(-lam)``: the steer axis ``S.z = (-sin lam, 0, cos lam)`` leans back."""
    return sp.Matrix([[COS_LAM, 0, -SIN_LAM], [0, 1, 0], [SIN_LAM, 0, COS_LAM]])


def _offsets():
    """``(f1, f3)``, the front wheel centre, and ``(h1, h3)``, the front frame's mass centre,
    from the steer axis's ground point ``A`` along ``H.x``, ``H.z`` (upright: ``S.x``, ``S.z``)."""
    cl, sl = COS_LAM, SIN_LAM
    f1, f3 = rF * sl - c * cl, rF * cl + c * sl
    dx, dz = xH - w - c, -zH
    return (f1, f3), (dx * cl + dz * sl, -dx * sl + dz * cl)


def _cross(a, b):
    return a.cross(b)


class _Hand:
    """The bicycle's geometry by hand, as component matrices in the ground axes O (the
    Lagrange model's own; the Newton-Euler model builds its frames separately)."""

    def __init__(self):
        (f1, f3), (h1, h3) = _offsets()
        RL = _rz(psi) * _rx(phi)
        RB = RL * _ry(theta)
        RH = RB * _tilt() * _rz(delta)
        self.RL, self.RB, self.RH = RL, RB, RH
        P = sp.Matrix([x, y, 0])
        self.CR = P + rR * RL[:, 2]
        A = self.CR + RB * sp.Matrix([w + c, 0, -rR])
        self.CF = A + RH * sp.Matrix([f1, 0, f3])
        self.GB = self.CR + RB * sp.Matrix([xB, 0, -zB - rR])
        self.GH = A + RH * sp.Matrix([h1, 0, h3])
        # angular velocities, body components, from the rates about the successive axes
        wY = sp.Matrix([0, 0, rate(psi)])
        wL = _rx(phi).T * wY + sp.Matrix([rate(phi), 0, 0])
        self.wB = _ry(theta).T * wL + sp.Matrix([0, rate(theta), 0])        # B axes
        self.wH = (_tilt() * _rz(delta)).T * self.wB + sp.Matrix([0, 0, rate(delta)])
        self.wR = self.wB + sp.Matrix([0, rate(thetaR), 0])                 # B axes
        self.wF = self.wH + sp.Matrix([0, rate(thetaF), 0])                 # H axes


def _inertia_B():
    """The rear body's inertia in B axes (z up, y left: the paper's IBxz changes sign)."""
    return sp.Matrix([[IBxx, 0, -IBxz], [0, IByy, 0], [-IBxz, 0, IBzz]])


def _inertia_H():
    """The front frame's inertia in H axes: given in upright axes (rotated back by ``lam``)."""
    Iup = sp.Matrix([[IHxx, 0, -IHxz], [0, IHyy, 0], [-IHxz, 0, IHzz]])
    Q = _tilt()            # H components -> upright (B-aligned) components, at zero steer
    return Q.T * Iup * Q


def _rolling_rows(hand: _Hand) -> list:
    """The four rolling rows (rear: O.x, O.y; front: O.x, O.y), linear in the rates."""
    Z = sp.Matrix([0, 0, 1])
    vR = hand.CR.diff(t) + _cross(hand.RB * hand.wR, -rR * hand.RL[:, 2])
    a = hand.RH[:, 1]
    down = Z - a[2] * a
    vF = hand.CF.diff(t) - rF * _cross(hand.RH * hand.wF, down) / sp.sqrt(1 - a[2]**2)
    return [vR[0], vR[1], vF[0], vF[1]]


def front_contact(hand: _Hand | None = None) -> sp.Expr:
    """``h - rF sqrt(1 - a_z^2)``, the height of the front wheel's lowest point: zero when it
    touches the ground (its multiplier is the normal force)."""
    hand = hand or _Hand()
    h, az = hand.CF[2], hand.RH[2, 1]
    return h - rF * sp.sqrt(1 - az**2)


def scene() -> SimpleNamespace:
    """The Newton-Euler model's frames, points and four bodies (built with the toolkit's
    frames, separately from the Lagrange model's matrices)."""
    (f1, f3), (h1, h3) = _offsets()
    O = Frame.ground("O")
    Y = O.child("Y", rot_z(psi))
    L = Y.child("L", rot_x(phi))
    B = L.child("B", rot_y(theta))
    S = B.child("S", _tilt())
    H = S.child("H", rot_z(delta))
    H0 = H.child("H0", _tilt().T)            # fixed in H, upright axes at zero steer
    WR = B.child("WR", rot_y(thetaR))
    WF = H.child("WF", rot_y(thetaF))
    origin = Point.origin(O)
    P = origin.locate("P", x * O.x + y * O.y)
    CR = P.locate("C_R", rR * L.z)
    A = CR.locate("A", (w + c) * B.x - rR * B.z)
    CF = A.locate("C_F", f1 * H.x + f3 * H.z)
    GB = CR.locate("G_B", xB * B.x + (-zB - rR) * B.z)
    GH = A.locate("G_H", h1 * H.x + h3 * H.z)
    az = H.y.dot(O.z)
    arm_R = -rR * L.z
    arm_F = -(rF / sp.sqrt(1 - az**2)) * (O.z - az * H.y)   # C_F to the wheel's lowest point
    PR = CR.locate("P_R", arm_R)
    PF = CF.locate("P_F", arm_F)
    bodies = SimpleNamespace(
        R=RigidBody("rear wheel", mR, CR, WR, sp.diag(IRxx, IRyy, IRxx)),
        B=RigidBody("rear frame", mB, GB, B, _inertia_B()),
        H=RigidBody("front frame", mH, GH, H0,
                    sp.Matrix([[IHxx, 0, -IHxz], [0, IHyy, 0], [-IHxz, 0, IHzz]])),
        F=RigidBody("front wheel", mF, CF, WF, sp.diag(IFxx, IFyy, IFxx)))
    return SimpleNamespace(O=O, L=L, B=B, H=H, WR=WR, WF=WF, A=A, CR=CR, CF=CF, PR=PR, PF=PF,
                           origin=origin,
                           arm_R=arm_R, arm_F=arm_F, bodies=bodies)


class WhippleBicycle(Problem):
    """The Meijaard et al. (2007) benchmark bicycle (see the module docstring)."""

    name = "whipple_bicycle"
    title = "Whipple bicycle: the benchmark of Meijaard, Papadopoulos, Ruina & Schwab (2007)"
    source = ("Meijaard, Papadopoulos, Ruina & Schwab, Proc. R. Soc. A 463 (2007) 1955-1982: "
              "Table 1 (parameters), Table 2 (eigenvalues), section 5 (weave, capsize speeds)")
    summary = ("Four rigid bodies, two wheels rolling without slipping, the front contact's "
               "holonomic constraint; self-stable between the weave and capsize speeds.")
    dimensions_unchecked = ("the geometry is fixed at the numbers of Table 1 (metres), so the "
                            "equations hold no dimension for lengths")
    # masses, inertias and gravity are parameters (the exact test samples them); the geometry
    # is the benchmark's, fixed (see the module constants w, c, rR, ..., TAN_HALF_LAM)
    parameters = (
        Parameter(g, ACCELERATION, 9.81, (1.0, 20.0), "gravitational acceleration"),
        Parameter(mR, MASS, 2.0, (0.5, 10.0), "rear wheel mass"),
        Parameter(IRxx, INERTIA, 0.0603, (0.01, 1.0), "rear wheel, about a diameter"),
        Parameter(IRyy, INERTIA, 0.12, (0.01, 1.0), "rear wheel, about its axle"),
        Parameter(mB, MASS, 85.0, (10.0, 150.0), "rear body mass"),
        Parameter(IBxx, INERTIA, 9.2, (1.0, 20.0), "rear body, x"),
        Parameter(IByy, INERTIA, 11.0, (1.0, 20.0), "rear body, y"),
        Parameter(IBzz, INERTIA, 2.8, (0.5, 10.0), "rear body, z"),
        Parameter(IBxz, INERTIA, 2.4, (-1.0, 4.0), "rear body, xz product (paper's axes)"),
        Parameter(mH, MASS, 4.0, (0.5, 10.0), "front frame mass"),
        Parameter(IHxx, INERTIA, 0.05892, (0.01, 0.5), "front frame, x"),
        Parameter(IHyy, INERTIA, 0.06, (0.01, 0.5), "front frame, y"),
        Parameter(IHzz, INERTIA, 0.00708, (0.001, 0.1), "front frame, z"),
        Parameter(IHxz, INERTIA, -0.00756, (-0.02, 0.0), "front frame, xz product (paper's axes)"),
        Parameter(mF, MASS, 3.0, (0.5, 10.0), "front wheel mass"),
        Parameter(IFxx, INERTIA, 0.1405, (0.01, 1.0), "front wheel, about a diameter"),
        Parameter(IFyy, INERTIA, 0.28, (0.01, 1.0), "front wheel, about its axle"),
    )
    coordinates = (
        Coordinate(x, LENGTH, (-100.0, 100.0), (-10.0, 10.0), "rear contact point, O.x"),
        Coordinate(y, LENGTH, (-100.0, 100.0), (-10.0, 10.0), "rear contact point, O.y"),
        Coordinate(psi, ANGLE, (-3.0, 3.0), (-2.0, 2.0), "yaw of the rear frame"),
        Coordinate(phi, ANGLE, (-0.6, 0.6), (-2.0, 2.0), "roll (lean) of the rear frame"),
        Coordinate(theta, ANGLE, (-0.2, 0.2), (-1.0, 1.0), "pitch of the rear frame"),
        Coordinate(delta, ANGLE, (-0.8, 0.8), (-2.0, 2.0), "steer angle"),
        Coordinate(thetaR, ANGLE, (-3.0, 3.0), (-20.0, 20.0), "rear wheel spin"),
        Coordinate(thetaF, ANGLE, (-3.0, 3.0), (-20.0, 20.0), "front wheel spin"),
    )
    reactions = (
        Reaction("F_R_x", FORCE, "ground on rear wheel at its contact, along O.x"),
        Reaction("F_R_y", FORCE, "ground on rear wheel at its contact, along O.y"),
        Reaction("F_R_z", FORCE, "ground on rear wheel at its contact, up"),
        Reaction("F_F_x", FORCE, "ground on front wheel at its contact, along O.x"),
        Reaction("F_F_y", FORCE, "ground on front wheel at its contact, along O.y"),
        Reaction("F_F_z", FORCE, "ground on front wheel at its contact, up"),
        Reaction("R_R_x", FORCE, "rear frame on rear wheel at the hub, along B.x"),
        Reaction("R_R_y", FORCE, "rear frame on rear wheel at the hub, along B.y"),
        Reaction("R_R_z", FORCE, "rear frame on rear wheel at the hub, along B.z"),
        Reaction("M_Rx", TORQUE, "rear frame on rear wheel, couple about B.x"),
        Reaction("M_Rz", TORQUE, "rear frame on rear wheel, couple about B.z"),
        Reaction("R_F_x", FORCE, "front frame on front wheel at the hub, along H.x"),
        Reaction("R_F_y", FORCE, "front frame on front wheel at the hub, along H.y"),
        Reaction("R_F_z", FORCE, "front frame on front wheel at the hub, along H.z"),
        Reaction("M_Fx", TORQUE, "front frame on front wheel, couple about H.x"),
        Reaction("M_Fz", TORQUE, "front frame on front wheel, couple about H.z"),
        Reaction("R_S_x", FORCE, "rear frame on front frame at the steering joint, along H.x"),
        Reaction("R_S_y", FORCE, "rear frame on front frame at the steering joint, along H.y"),
        Reaction("R_S_z", FORCE, "rear frame on front frame at the steering joint, along H.z"),
        Reaction("M_Sx", TORQUE, "rear frame on front frame, couple about H.x"),
        Reaction("M_Sy", TORQUE, "rear frame on front frame, couple about H.y"),
    )
    unilateral = {"F_R_z": "the rear wheel lifts off", "F_F_z": "the front wheel lifts off"}
    # riding upright and straight at 5 m/s (inside the self-stable range) and pushed into a
    # lean at 0.5 rad/s: every rate on the rolling constraints, the upright pose on the front
    # contact's; charts show the weave dying out
    initial_state = {x: 0, y: 0, psi: 0, phi: 0, theta: 0, delta: 0, thetaR: 0, thetaF: 0,
                     rate(x): 5, rate(y): 0, rate(psi): 0, rate(phi): sp.Rational(1, 2),
                     rate(theta): 0, rate(delta): 0, rate(thetaR): 5 / rR,
                     rate(thetaF): 5 / rF}
    steady_motion = SteadyMotion({rate(x): v, rate(thetaR): v / rR, rate(thetaF): v / rF},
                                 "v", (0.0, 10.0, 101), "upright straight running at speed v")

    def lagrange(self) -> EquationSet:
        """``T``, ``V`` by hand; rolling by four velocity constraints, the front contact by a
        holonomic one."""
        hand = _Hand()
        lg = Lagrangian("lagrange", coordinates=COORDS,
                        description="T and V by hand, rolling and the front contact by "
                                    "multipliers")

        def dot(u):
            return (u.T * u)[0, 0]

        lg.kinetic("T of R", (mR * dot(hand.CR.diff(t)) + IRxx * (hand.wR[0]**2 + hand.wR[2]**2)
                              + IRyy * hand.wR[1]**2) / 2)
        lg.kinetic("T of B", (mB * dot(hand.GB.diff(t))
                              + (hand.wB.T * _inertia_B() * hand.wB)[0, 0]) / 2)
        lg.kinetic("T of H", (mH * dot(hand.GH.diff(t))
                              + (hand.wH.T * _inertia_H() * hand.wH)[0, 0]) / 2)
        lg.kinetic("T of F", (mF * dot(hand.CF.diff(t)) + IFxx * (hand.wF[0]**2 + hand.wF[2]**2)
                              + IFyy * hand.wF[1]**2) / 2)
        lg.potential("gravity", g * (mR * hand.CR[2] + mB * hand.GB[2] + mH * hand.GH[2]
                                     + mF * hand.CF[2]))
        for name, row in zip(("F_R_x", "F_R_y", "F_F_x", "F_F_y"), _rolling_rows(hand)):
            lg.velocity_constraint(name, row)   # linear in the rates: its coefficients read off
        lg.constraint("F_F_z", front_contact(hand))
        return lg.equations()

    def newton_euler(self) -> EquationSet:
        """Four free-body diagrams: contact forces at both wheels, the hubs' and the steering
        joint's reactions (forces and the couples about the axes the joints do not turn
        about); the rolling and contact conditions at acceleration level."""
        s = scene()
        b = s.bodies
        ne = NewtonEuler("newton_euler", coordinates=COORDS, ground=s.O,
                         description="four bodies, contact forces and joint reactions unknown")
        ne.gravity(-g * s.O.z)
        ne.reaction_vector("F_R", b.R, s.O, at=s.PR)
        ne.reaction_vector("F_F", b.F, s.O, at=s.PF)
        ne.reaction_vector("R_R", b.R, s.B, at=s.CR, against=b.B, against_at=s.CR)
        ne.reaction_torque("M_Rx", b.R, s.B.x, against=b.B)
        ne.reaction_torque("M_Rz", b.R, s.B.z, against=b.B)
        ne.reaction_vector("R_F", b.F, s.H, at=s.CF, against=b.H, against_at=s.CF)
        ne.reaction_torque("M_Fx", b.F, s.H.x, against=b.H)
        ne.reaction_torque("M_Fz", b.F, s.H.z, against=b.H)
        ne.reaction_vector("R_S", b.H, s.H, at=s.A, against=b.B, against_at=s.A)
        ne.reaction_torque("M_Sx", b.H, s.H.x, against=b.B)
        ne.reaction_torque("M_Sy", b.H, s.H.y, against=b.B)
        for body, frame in ((b.R, s.B), (b.B, s.B), (b.H, s.H), (b.F, s.H)):
            for axis in (s.O.x, s.O.y, s.O.z):
                ne.linear_momentum(body, axis)
            for axis in (frame.x, frame.y, frame.z):
                ne.angular_momentum(body, axis)
        # rolling and the front contact declared (the referee reads them): no slip of each
        # wheel's material point at its contact, along the ground; the front contact point's
        # height zero (the rear's is built into the coordinates)
        ne.rolling("rear rolling", b.R, s.PR, [s.O.x, s.O.y])
        ne.rolling("front rolling", b.F, s.PF, [s.O.x, s.O.y])
        ne.constraint("front contact", s.PF.pos_from(s.origin).dot(s.O.z))
        return ne.equations()

    def published(self) -> list[Published]:
        where = "Meijaard et al. (2007)"
        out = []
        for speed, eig in TABLE_2.items():
            values = []
            for e in eig:
                values += [e, e.conjugate()] if isinstance(e, complex) else [e]
            out.append(Published(f"Table 2, eigenvalues at v = {speed} m/s", "eigenvalues",
                                 tuple(_number(z) for z in values), at=speed, tolerance=1e-9,
                                 where=f"{where}, Table 2"))
        out.append(Published("weave speed (m/s)", "critical", (WEAVE_SPEED,), tolerance=5e-7,
                             where=f"{where}, section 5"))
        out.append(Published("capsize speed (m/s)", "critical", (CAPSIZE_SPEED,),
                             tolerance=5e-7, where=f"{where}, section 5"))
        return out


def _number(z) -> sp.Expr:
    """A printed decimal as the exact number it prints (``Float`` parts read from text)."""
    z = complex(z)
    return sp.Float(repr(z.real), 20) + sp.I * sp.Float(repr(z.imag), 20)


PROBLEMS = (WhippleBicycle,)
