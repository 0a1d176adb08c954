"""Peer pipeline for trolley_pendulum: sympy.physics.mechanics instead of dualmech.

A trolley M at x on a horizontal track carries a pendulum (massless rod a, bob m, theta from
the downward vertical); horizontal forces F on the trolley and P on the bob.  What a user of
sympy.physics.mechanics writes: Lagrange's method with F and P in the force list (the
generalised forces come from their virtual work inside LagrangesMethod); Kane's method with an
auxiliary speed along the rod to expose its pull T; the accelerations compared with LUsolve +
simplify; T from the auxiliary equation.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "trolley_pendulum"


def run() -> None:
    M, m, a, g, F, P = sp.symbols("M m a g F P", positive=True)
    T = sp.Symbol("T", real=True)
    x, th, ux, w, u_aux = dynamicsymbols("x theta u_x omega u_aux")
    xd, thd = dynamicsymbols("x theta", 1)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (th, N.z))   # A.y points from the bob to the pivot
    O = Point("O")

    def scene(xrate, thrate, aux=0):
        C = O.locatenew("C", x * N.x)
        C.set_vel(N, xrate * N.x)
        A.set_ang_vel(N, thrate * N.z)
        B = C.locatenew("B", -a * A.y)
        B.set_vel(N, xrate * N.x + a * thrate * A.x - aux * A.y)
        return C, B

    C, B = scene(xd, thd)
    trolley, bob = Particle("trolley", C, M), Particle("bob", B, m)
    bob.potential_energy = m * g * B.pos_from(C).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, trolley, bob), [x, th],
                         forcelist=[(C, F * N.x), (B, P * N.x)], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    C, B = scene(ux, w, u_aux)
    km = KanesMethod(N, q_ind=[x, th], u_ind=[ux, w], kd_eqs=[xd - ux, thd - w],
                     u_auxiliary=[u_aux])
    km.kanes_equations([Particle("trolley", C, M), Particle("bob", B, m)],
                       [(C, F * N.x - T * A.y), (B, P * N.x - m * g * N.y + T * A.y)])
    back = {ux: xd, w: thd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    xdd = dynamicsymbols("x", 2)
    aux = [e.subs({dynamicsymbols("u_x", 1): xdd}).subs(back) for e in km.auxiliary_eqs]
    T_sol = sp.solve(aux, T, dict=True)[0][T].subs(xdd, acc_l[0])
    # by hand (the bob along the rod): T = m (a th'^2 - x'' sin th) + m g cos th + P sin th
    hand = (m * (a * thd**2 - acc_l[0] * sp.sin(th)) + m * g * sp.cos(th)
            + P * sp.sin(th))
    assert sp.simplify(T_sol - hand) == 0, T_sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; rod pull T recovered")
