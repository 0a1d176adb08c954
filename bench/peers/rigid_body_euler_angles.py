"""Peer pipeline for rigid_body_euler_angles: sympy.physics.mechanics instead of dualmech.

A rigid body with principal inertias A, B, C about its mass centre, constant body-axis torques
Q1, Q2, Q3, attitude in z-y-z Euler angles.  What a user of sympy.physics.mechanics writes: the
body frame by a 'Body' ZYZ orientation; Lagrange's method with the torque as a load; Kane's
method with the Euler-angle rates as generalised speeds; the two compared through their mass
matrices and forcing terms (simplify entry by entry: with the same speeds, equal ``M`` and
``f`` mean equal accelerations -- simplifying the difference of the two ``LUsolve``
solutions of this 3x3 trigonometric system did not finish in 20 minutes); the psi equation
checked against Euler's third equation.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "rigid_body_euler_angles"


def run() -> None:
    A, B, C, m = sp.symbols("A B C m", positive=True)
    Q1, Q2, Q3 = sp.symbols("Q1 Q2 Q3", real=True)
    q = dynamicsymbols("phi theta psi")
    qd = [x.diff() for x in q]
    u = dynamicsymbols("u1:4")
    N = ReferenceFrame("N")
    b = N.orientnew("b", "Body", q, "ZYZ")
    G = Point("G")
    G.set_vel(N, 0)
    body = RigidBody("body", G, b, m, (inertia(b, A, B, C), G))
    loads = [(b, Q1 * b.x + Q2 * b.y + Q3 * b.z)]

    lm = LagrangesMethod(Lagrangian(N, body), q, forcelist=loads, frame=N)
    lm.form_lagranges_equations()

    km = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[a - v for a, v in zip(qd, u)])
    km.kanes_equations([body], loads)
    back = dict(zip(u, qd))
    dM = lm.mass_matrix - km.mass_matrix.subs(back)
    df = lm.forcing - km.forcing.subs(back)
    assert all(sp.simplify(e) == 0 for e in list(dM) + list(df)), "Lagrange and Kane"

    # the psi equation is Euler's third: C w3' - (A - B) w1 w2 = Q3
    w = [b.ang_vel_in(N).dot(e) for e in (b.x, b.y, b.z)]
    t = dynamicsymbols._t
    psi_eq = lm.mass_matrix[2, :] * sp.Matrix([x.diff() for x in qd]) - lm.forcing[2, :]
    euler3 = C * w[2].diff(t) - (A - B) * w[0] * w[1] - Q3
    assert sp.simplify(psi_eq[0] - euler3) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; the psi equation is Euler's third")
