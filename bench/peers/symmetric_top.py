"""Peer pipeline for symmetric_top: sympy.physics.mechanics instead of dualmech.

A symmetric top (A across the axis and C about it, both about the fixed tip O; mass M, mass
centre at h on the axis) in z-y-z Euler angles.  What a user of sympy.physics.mechanics
writes: Lagrange's method with gravity as a potential; Kane's method with the angle rates as
generalised speeds; the accelerations compared with LUsolve + simplify; the steady precession
rates from the theta equation with theta'' = theta' = 0, checked against the fast-top limit
M g h / (C psi').
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "symmetric_top"


def run() -> None:
    A, C, M, g, h = sp.symbols("A C M g h", positive=True)
    q = dynamicsymbols("phi theta psi")
    phi, theta, psi = q
    qd = [x.diff() for x in q]
    u = dynamicsymbols("u1:4")
    N = ReferenceFrame("N")
    b = N.orientnew("b", "Body", q, "ZYZ")
    O = Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", h * b.z)
    G.v2pt_theory(O, N, b)
    top = RigidBody("top", G, b, M, (inertia(b, A, A, C), O))
    top.potential_energy = M * g * h * sp.cos(theta)

    lm = LagrangesMethod(Lagrangian(N, top), q, frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    km = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[a - v for a, v in zip(qd, u)])
    km.kanes_equations([top], [(G, -M * g * N.z)])
    back = dict(zip(u, qd))
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert all(sp.simplify(p - r) == 0 for p, r in zip(acc_l, acc_k)), "Lagrange and Kane"

    # steady precession: theta'' = 0 with theta' = 0 and constant phi', psi'
    p, s = sp.symbols("p s", positive=True)
    t = dynamicsymbols._t
    still = {qd[1]: 0, qd[0]: p, qd[2]: s}
    theta_dd = sp.simplify(acc_l[1].subs({x.diff(t): 0 for x in qd}).subs(still))
    rates = sp.solve(sp.numer(sp.together(theta_dd)), p)
    slow = [r for r in rates if sp.limit(r, s, sp.oo) == 0]
    assert len(slow) == 1
    assert sp.simplify(sp.limit(slow[0] * C * s / (M * g * h), s, sp.oo) - 1) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; slow precession -> M g h / (C psi')")
