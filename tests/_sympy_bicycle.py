r"""sympy's own Whipple bicycle, the model of sympy's test suite, as a test helper.

The model-building code is copied from ``sympy/physics/mechanics/tests/test_kane3.py``
(``test_bicycle``) of sympy 1.14.0 (BSD licence; "crudely ported from Autolev" there), names
and all: Kane's method with yaw, roll, pitch and steer coordinates ``q1, q2, q4, q5`` (the
rear contact's position and the wheel angles are ignorable and left out), six speeds ``u1..u6``
(``u3``, ``u6`` the wheels' spin rates relative to frame and fork), the pitch ``q4`` dependent
through the front contact's height (configuration constraint), the speeds ``u1, u4, u6``
dependent through the front contact's velocity (three velocity constraints).  Only the
numerical values differ from that test: :func:`benchmark_values` gives the same Meijaard et
al. (2007) Table 1 bicycle through the same formulas, with the steer-axis tilt and the lengths
exact (the tilt through ``problems/whipple_bicycle.py``'s half-angle tangent), where the test
uses 15-digit floats; the test's own floats are :data:`SYMPY_TEST_VALUES`.

Conventions (read off the code): ``N.z`` up, ``x`` forward, ``y`` left -- the axes of
``problems/whipple_bicycle.py``; ``q1`` yaw about ``N.z``, ``q2`` roll about ``Y.x``, ``q4``
pitch about ``R.y`` (zero upright: the frame is turned by ``htangle`` more), ``q5`` steer
about ``Frame.x``, the steer axis pointing *down* (ours, ``delta``, turns about it pointing
up: ``q5 = -delta``); ``u1 = q1'``, ``u2 = q2'``, ``u4 = q4'``, ``u5 = q5'``, ``u3`` the rear
wheel's spin about ``Frame.y`` (= our ``B.y``: ``thetaR'``), ``u6`` the front wheel's about
``Fork.y`` (= our ``H.y`` when ``q5 = -delta``: ``thetaF'``).
"""
from __future__ import annotations

from sympy import acos, cos, pi, sin, sqrt, symbols
from sympy.physics.mechanics import (KanesMethod, Point, ReferenceFrame, RigidBody, dot,
                                     dynamicsymbols, inertia)

__all__ = ["sympy_bicycle", "benchmark_values", "SYMPY_TEST_VALUES", "SYMPY_TEST_A"]

PARAMETERS = symbols("WFrad WRrad htangle forkoffset forklength framelength forkcg1 forkcg3 "
                     "framecg1 framecg3 Iwr11 Iwr22 Iwf11 Iwf22 Iframe11 Iframe22 Iframe33 "
                     "Iframe31 Ifork11 Ifork22 Ifork33 Ifork31 g mframe mfork mwf mwr")


def sympy_bicycle(*, formed: bool = True):
    """sympy's ``KanesMethod`` of the bicycle (``kanes_equations`` called when ``formed``)
    and its namespace ``{name: object}`` (coordinates, speeds, parameters, frames)."""
    q1, q2, q4, q5 = dynamicsymbols('q1 q2 q4 q5')
    q1d, q2d, q4d, q5d = dynamicsymbols('q1 q2 q4 q5', 1)
    u1, u2, u3, u4, u5, u6 = dynamicsymbols('u1 u2 u3 u4 u5 u6')
    (WFrad, WRrad, htangle, forkoffset, forklength, framelength, forkcg1, forkcg3, framecg1,
     framecg3, Iwr11, Iwr22, Iwf11, Iwf22, Iframe11, Iframe22, Iframe33, Iframe31, Ifork11,
     Ifork22, Ifork33, Ifork31, g, mframe, mfork, mwf, mwr) = PARAMETERS

    N = ReferenceFrame('N')
    Y = N.orientnew('Y', 'Axis', [q1, N.z])
    R = Y.orientnew('R', 'Axis', [q2, Y.x])
    Frame = R.orientnew('Frame', 'Axis', [q4 + htangle, R.y])
    WR = ReferenceFrame('WR')
    TempFrame = Frame.orientnew('TempFrame', 'Axis', [-htangle, Frame.y])
    Fork = Frame.orientnew('Fork', 'Axis', [q5, Frame.x])
    TempFork = Fork.orientnew('TempFork', 'Axis', [-htangle, Fork.y])
    WF = ReferenceFrame('WF')

    WR_cont = Point('WR_cont')
    WR_mc = WR_cont.locatenew('WR_mc', WRrad * R.z)
    Steer = WR_mc.locatenew('Steer', framelength * Frame.z)
    Frame_mc = WR_mc.locatenew('Frame_mc', - framecg1 * Frame.x + framecg3 * Frame.z)
    Fork_mc = Steer.locatenew('Fork_mc', - forkcg1 * Fork.x + forkcg3 * Fork.z)
    WF_mc = Steer.locatenew('WF_mc', forklength * Fork.x + forkoffset * Fork.z)
    WF_cont = WF_mc.locatenew('WF_cont', WFrad * (dot(Fork.y, Y.z) * Fork.y -
                                                  Y.z).normalize())

    Y.set_ang_vel(N, u1 * Y.z)
    R.set_ang_vel(Y, u2 * R.x)
    WR.set_ang_vel(Frame, u3 * Frame.y)
    Frame.set_ang_vel(R, u4 * Frame.y)
    Fork.set_ang_vel(Frame, u5 * Fork.x)
    WF.set_ang_vel(Fork, u6 * Fork.y)

    WR_cont.set_vel(N, 0)
    WR_mc.v2pt_theory(WR_cont, N, WR)
    Steer.v2pt_theory(WR_mc, N, Frame)
    Frame_mc.v2pt_theory(WR_mc, N, Frame)
    Fork_mc.v2pt_theory(Steer, N, Fork)
    WF_mc.v2pt_theory(Steer, N, Fork)
    WF_cont.v2pt_theory(WF_mc, N, WF)

    Frame_I = (inertia(TempFrame, Iframe11, Iframe22, Iframe33, 0, 0, Iframe31), Frame_mc)
    Fork_I = (inertia(TempFork, Ifork11, Ifork22, Ifork33, 0, 0, Ifork31), Fork_mc)
    WR_I = (inertia(Frame, Iwr11, Iwr22, Iwr11), WR_mc)
    WF_I = (inertia(Fork, Iwf11, Iwf22, Iwf11), WF_mc)

    BodyFrame = RigidBody('BodyFrame', Frame_mc, Frame, mframe, Frame_I)
    BodyFork = RigidBody('BodyFork', Fork_mc, Fork, mfork, Fork_I)
    BodyWR = RigidBody('BodyWR', WR_mc, WR, mwr, WR_I)
    BodyWF = RigidBody('BodyWF', WF_mc, WF, mwf, WF_I)

    kd = [q1d - u1, q2d - u2, q4d - u4, q5d - u5]
    conlist_speed = [WF_cont.vel(N) & Y.x, WF_cont.vel(N) & Y.y, WF_cont.vel(N) & Y.z]
    conlist_coord = [WF_cont.pos_from(WR_cont) & Y.z]
    FL = [(Frame_mc, -mframe * g * Y.z),
          (Fork_mc, -mfork * g * Y.z),
          (WF_mc, -mwf * g * Y.z),
          (WR_mc, -mwr * g * Y.z)]
    BL = [BodyFrame, BodyFork, BodyWR, BodyWF]

    KM = KanesMethod(N, q_ind=[q1, q2, q5],
                     q_dependent=[q4], configuration_constraints=conlist_coord,
                     u_ind=[u2, u3, u5],
                     u_dependent=[u1, u4, u6], velocity_constraints=conlist_speed,
                     kd_eqs=kd,
                     constraint_solver="CRAMER")
    if formed:
        KM.kanes_equations(BL, FL)
    names = {s.name: s for s in PARAMETERS}
    names.update({f.func.__name__: f for f in (q1, q2, q4, q5, u1, u2, u3, u4, u5, u6)})
    names.update(N=N, Y=Y, R=R, Frame=Frame, Fork=Fork, WF_cont=WF_cont, WR_cont=WR_cont,
                 bodies=BL, loads=FL)
    return KM, names


def _geometry(HTA, rake_of=None):
    """The test's formulas for the lengths, from the paper's Table 1 and the head angle."""
    PaperRadRear, PaperRadFront = 0.3, 0.35
    TrailPaper, PaperWb = 0.08, 1.02
    PaperFrameCgX, PaperFrameCgZ, PaperForkCgX, PaperForkCgZ = 0.3, 0.9, 0.9, 0.7
    rake = -(TrailPaper * sin(HTA) - (PaperRadFront * cos(HTA)))
    FrameLength = PaperWb * sin(HTA) - (rake - (PaperRadFront - PaperRadRear) * cos(HTA))
    FrameCGNorm = (PaperFrameCgZ - PaperRadRear - (PaperFrameCgX / sin(HTA)) * cos(HTA)) \
        * sin(HTA)
    FrameCGPar = PaperFrameCgX / sin(HTA) + (PaperFrameCgZ - PaperRadRear - PaperFrameCgX
                                             / sin(HTA) * cos(HTA)) * cos(HTA)
    tempa = PaperForkCgZ - PaperRadFront
    tempb = PaperWb - PaperForkCgX
    tempc = sqrt(tempa**2 + tempb**2)
    PaperForkL = PaperWb * cos(HTA) - (PaperRadFront - PaperRadRear) * sin(HTA)
    ForkCGNorm = rake + (tempc * sin(pi / 2 - HTA - acos(tempa / tempc)))
    ForkCGPar = tempc * cos((pi / 2 - HTA) - acos(tempa / tempc)) - PaperForkL
    return dict(WFrad=PaperRadFront, WRrad=PaperRadRear, htangle=HTA, forkoffset=rake,
                forklength=PaperForkL, framelength=FrameLength, forkcg1=ForkCGPar,
                forkcg3=ForkCGNorm, framecg1=FrameCGNorm, framecg3=FrameCGPar)


#: The test's own numbers (15-digit floats, the head angle ``(pi/2 - pi/10).evalf()``).
SYMPY_TEST_VALUES = {**_geometry((pi / 2 - pi / 10).evalf()),
                     "Iwr11": 0.0603, "Iwr22": 0.12, "Iwf11": 0.1405, "Iwf22": 0.28,
                     "Ifork11": 0.05892, "Ifork22": 0.06, "Ifork33": 0.00708,
                     "Ifork31": 0.00756, "Iframe11": 9.2, "Iframe22": 11, "Iframe33": 2.8,
                     "Iframe31": -2.4, "mfork": 4, "mframe": 85, "mwf": 3, "mwr": 2,
                     "g": 9.81}
SYMPY_TEST_VALUES = {k: (v.evalf() if hasattr(v, "evalf") else v)
                     for k, v in SYMPY_TEST_VALUES.items()}


def SYMPY_TEST_A(v: float) -> list:
    """The test's ``Res``: its state matrix in (roll q2, steer q5, roll rate u2, steer rate u5)
    at speed ``v``, "precomputed for comparison" there (15 digits)."""
    return [[0, 0, 1.0, 0],
            [0, 0, 0, 1.0],
            [9.48977444677355, -0.891197738059089 * v**2 - 0.571523173729245,
             -0.105522449805691 * v, -0.330515398992311 * v],
            [11.7194768719633, -1.97171508499972 * v**2 + 30.9087533932407,
             3.67680523332152 * v, -3.08486552743311 * v]]


def benchmark_values(W) -> dict:
    """``{sympy's parameter name: our parameter or exact number}``: the bicycle of
    ``problems/whipple_bicycle.py`` (module ``W``) in sympy's parameters.

    The lengths are the test's formulas with ``sin(HTA) = cos(lam)``, ``cos(HTA) = sin(lam)``
    exact (``HTA = pi/2 - lam``) and its two ``acos`` terms expanded by the angle-sum
    identities (``c sin(pi/2 - HTA - acos(a/c)) = a cos(HTA) - b sin(HTA)``, ``c cos(pi/2 - HTA
    - acos(a/c)) = a sin(HTA) + b cos(HTA)``, with ``c = sqrt(a^2 + b^2)``); the products of
    inertia change sign (the test's comment: its ``Iframe31 = -2.4`` is the paper's
    ``IBxz = 2.4``, and ours is the paper's)."""
    from sympy import atan
    sH, cH = W.COS_LAM, W.SIN_LAM
    rF, rR, wb, trail = W.rF, W.rR, W.w, W.c
    xB, zB, xH, zH = W.xB, -W.zB, W.xH, -W.zH          # the test's heights are positive
    rake = -(trail * sH - rF * cH)
    fork_l = wb * cH - (rF - rR) * sH
    a, b = zH - rF, wb - xH
    return {"WFrad": rF, "WRrad": rR, "htangle": pi / 2 - 2 * atan(W.TAN_HALF_LAM),
            "forkoffset": rake, "forklength": fork_l,
            "framelength": wb * sH - (rake - (rF - rR) * cH),
            "forkcg1": a * sH + b * cH - fork_l, "forkcg3": rake + a * cH - b * sH,
            "framecg1": (zB - rR - (xB / sH) * cH) * sH,
            "framecg3": xB / sH + (zB - rR - xB / sH * cH) * cH,
            "Iwr11": W.IRxx, "Iwr22": W.IRyy, "Iwf11": W.IFxx, "Iwf22": W.IFyy,
            "Iframe11": W.IBxx, "Iframe22": W.IByy, "Iframe33": W.IBzz, "Iframe31": -W.IBxz,
            "Ifork11": W.IHxx, "Ifork22": W.IHyy, "Ifork33": W.IHzz, "Ifork31": -W.IHxz,
            "g": W.g, "mframe": W.mB, "mfork": W.mH, "mwf": W.mF, "mwr": W.mR}
