"""Peer pipeline for ball_in_sphere: sympy.physics.mechanics instead of dualmech.

A ball m on the inside of a sphere of radius a: latitude theta from the upward vertical,
longitude phi.  What a user of sympy.physics.mechanics writes: Lagrange's method with gravity
as a potential; Kane's method with an auxiliary speed along e_r to expose the normal force N;
the accelerations compared with LUsolve + simplify; N from the auxiliary equation; the first
integrals (momentum of phi, energy) differentiated along the motion.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "ball_in_sphere"


def run() -> None:
    m, a, g = sp.symbols("m a g", positive=True)
    Nf = sp.Symbol("N", real=True)
    th, ph, w1, w2, u_aux = dynamicsymbols("theta phi w1 w2 u_aux")
    thd, phd = dynamicsymbols("theta phi", 1)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (ph, N.z))
    B = A.orientnew("B", "Axis", (th, A.y))     # B.z = e_r, B.x = e_theta, B.y = e_phi
    O = Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", a * B.z)

    P.set_vel(N, a * thd * B.x + a * sp.sin(th) * phd * B.y)
    ball = Particle("ball", P, m)
    ball.potential_energy = m * g * a * sp.cos(th)
    L = Lagrangian(N, ball)
    lm = LagrangesMethod(L, [th, ph], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    P.set_vel(N, a * w1 * B.x + a * sp.sin(th) * w2 * B.y + u_aux * B.z)
    km = KanesMethod(N, q_ind=[th, ph], u_ind=[w1, w2], kd_eqs=[thd - w1, phd - w2],
                     u_auxiliary=[u_aux])
    km.kanes_equations([Particle("ball", P, m)], [(P, -m * g * N.z - Nf * B.z)])
    back = {w1: thd, w2: phd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    N_sol = sp.solve([e.subs(back) for e in km.auxiliary_eqs], Nf, dict=True)[0][Nf]
    hand = m * a * (thd**2 + sp.sin(th)**2 * phd**2) - m * g * sp.cos(th)
    assert sp.simplify(N_sol - hand) == 0, N_sol

    t = dynamicsymbols._t
    on_motion = {thd.diff(t): acc_l[0], phd.diff(t): acc_l[1]}
    p_phi = L.diff(phd)
    energy = L + 2 * ball.potential_energy   # T + V
    for first_integral in (p_phi, energy):
        assert sp.simplify(first_integral.diff(t).subs(on_motion)) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; normal force recovered; momentum and energy "
          "conserved")
