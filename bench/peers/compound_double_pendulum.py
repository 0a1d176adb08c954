"""Peer pipeline for compound_double_pendulum: sympy.physics.mechanics instead of dualmech.

A rigid body (mass m, I0 about its centre G, G a distance b from the hinge A) hangs from a
light link of length a; both angles from the downward vertical.  What a user of
sympy.physics.mechanics writes: Lagrange's method with gravity as a potential; Kane's method
with two auxiliary speeds of the body at the hinge to expose the hinge force R (its opposite
acts on the light link); the accelerations compared with LUsolve + simplify; R from the
auxiliary equations, checked to lie along the link and, hanging, to be
``m (g + a w1^2 + b w2^2)``.  The source asks for no reaction; the hinge force is the one the
direct form recovers.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "compound_double_pendulum"


def run() -> None:
    m, a, b, I0, g = sp.symbols("m a b I0 g", positive=True)
    Rx, Ry = sp.symbols("R_x R_y", real=True)
    q1, q2, w1, w2, u3, u4 = dynamicsymbols("theta1 theta2 w1 w2 u3 u4")
    q1d, q2d = dynamicsymbols("theta1 theta2", 1)
    N = ReferenceFrame("N")
    L1 = N.orientnew("L1", "Axis", (q1, N.z))
    L2 = N.orientnew("L2", "Axis", (q2, N.z))
    O = Point("O")
    O.set_vel(N, 0)

    def scene(r1, r2, aux=0 * N.x):
        L1.set_ang_vel(N, r1 * N.z)
        L2.set_ang_vel(N, r2 * N.z)
        A_link = O.locatenew("A_link", -a * L1.y)
        A_link.v2pt_theory(O, N, L1)
        A = O.locatenew("A", -a * L1.y)
        A.set_vel(N, A_link.vel(N) + aux)
        G = A.locatenew("G", -b * L2.y)
        G.v2pt_theory(A, N, L2)
        body = RigidBody("body", G, L2, m, (inertia(L2, 0, 0, I0), G))
        return body, A_link, A, G

    body, _, _, G = scene(q1d, q2d)
    body.potential_energy = m * g * G.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, body), [q1, q2], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    body, A_link, A, G = scene(w1, w2, u3 * N.x + u4 * N.y)
    R = Rx * N.x + Ry * N.y
    km = KanesMethod(N, q_ind=[q1, q2], u_ind=[w1, w2], kd_eqs=[q1d - w1, q2d - w2],
                     u_auxiliary=[u3, u4])
    km.kanes_equations([body], [(G, -m * g * N.y), (A, R), (A_link, -R)])
    back = {w1: q1d, w2: q2d}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    t = dynamicsymbols._t
    on_motion = {w1.diff(t): acc_l[0], w2.diff(t): acc_l[1]}
    aux = [e.subs(on_motion).subs(back) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [Rx, Ry], dict=True)[0]
    # the light link is a two-force member: R lies along it
    assert sp.simplify(sol[Rx] * sp.cos(q1) + sol[Ry] * sp.sin(q1)) == 0
    W1, W2 = sp.symbols("W1 W2", real=True)
    hanging = {q1d: W1, q2d: W2, q1: 0, q2: 0}
    assert sp.simplify(sol[Rx].subs(hanging)) == 0
    assert sp.simplify(sol[Ry].subs(hanging) - m * (g + a * W1**2 + b * W2**2)) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; hinge force along the link recovered")
