"""Peer pipeline for inertia_wheel_pendulum: sympy.physics.mechanics instead of dualmech.

A rod (m1, I1 about its centre at l_c1) hinged at O with a motor-driven disc (m2, I2) at l1,
x pointing down (source 003).  What a user of sympy.physics.mechanics writes: Lagrange's method
with the motor torque pair in the force list; Kane's method with two auxiliary speeds at the
hinge to expose the pivot force R_x i1 + R_y i2; the accelerations compared with LUsolve +
simplify; R from the auxiliary equations against the whole system's momentum balance.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "inertia_wheel_pendulum"


def run() -> None:
    m1, m2, l1, lc, I1, I2, g, tau = sp.symbols("m1 m2 l1 l_c1 I1 I2 g tau", positive=True)
    R_x, R_y = sp.symbols("R_x R_y", real=True)
    q1, q2, u1, u2, ux, uy = dynamicsymbols("q1 q2 u1 u2 u_x u_y")
    q1d, q2d = dynamicsymbols("q1 q2", 1)
    N = ReferenceFrame("N")                       # N.x down, gravity +g N.x
    B = N.orientnew("B", "Axis", (q1, N.z))
    C = B.orientnew("C", "Axis", (q2, B.z))

    def scene(r1, r2, aux_x=0, aux_y=0):
        O = Point("O")
        O.set_vel(N, aux_x * N.x + aux_y * N.y)
        B.set_ang_vel(N, r1 * N.z)
        C.set_ang_vel(B, r2 * B.z)
        P1, P2 = O.locatenew("C1", lc * B.x), O.locatenew("C2", l1 * B.x)
        P1.v2pt_theory(O, N, B)
        P2.v2pt_theory(O, N, B)
        rod = RigidBody("rod", P1, B, m1, (inertia(B, 0, I1, I1), P1))
        disc = RigidBody("disc", P2, C, m2, (inertia(C, I2 / 2, I2 / 2, I2), P2))
        loads = [(P1, m1 * g * N.x), (P2, m2 * g * N.x), (C, tau * N.z), (B, -tau * N.z)]
        return O, P1, P2, rod, disc, loads

    O, P1, P2, rod, disc, loads = scene(q1d, q2d)
    rod.potential_energy = -m1 * g * P1.pos_from(O).dot(N.x)
    disc.potential_energy = -m2 * g * P2.pos_from(O).dot(N.x)
    lm = LagrangesMethod(Lagrangian(N, rod, disc), [q1, q2], forcelist=loads[2:], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    O, P1, P2, rod, disc, loads = scene(u1, u2, ux, uy)
    km = KanesMethod(N, q_ind=[q1, q2], u_ind=[u1, u2], kd_eqs=[q1d - u1, q2d - u2],
                     u_auxiliary=[ux, uy])
    km.kanes_equations([rod, disc], loads + [(O, R_x * N.x + R_y * N.y)])
    rules = {u1: q1d, u2: q2d}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(rules)
    assert (acc_l - acc_k).applyfunc(sp.simplify) == sp.zeros(2, 1), "Lagrange and Kane"

    q1dd, q2dd = dynamicsymbols("q1 q2", 2)
    aux = [e.subs({u1.diff(): q1dd, u2.diff(): q2dd}).subs(rules) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [R_x, R_y], dict=True)[0]
    # by hand: R = m1 a_C1 + m2 a_C2 - (m1 + m2) g i1 with M = m1 l_c1 + m2 l1
    M, s, c = m1 * lc + m2 * l1, sp.sin(q1), sp.cos(q1)
    a1 = acc_l[0]
    hand = {R_x: -M * (a1 * s + q1d**2 * c) - (m1 + m2) * g, R_y: M * (a1 * c - q1d**2 * s)}
    sub = {q1dd: acc_l[0], q2dd: acc_l[1]}
    assert all(sp.simplify(sol[r].subs(sub) - hand[r]) == 0 for r in hand), sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; pivot force R_x, R_y recovered")
