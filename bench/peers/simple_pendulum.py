"""Peer pipeline for simple_pendulum: sympy.physics.mechanics instead of dualmech.

A bob M on a massless string of length a, theta from the downward vertical.  What a user of
sympy.physics.mechanics writes: Lagrange's method with gravity as a potential; Kane's method
with an auxiliary speed along the string to expose its tension T; the accelerations compared
with LUsolve + simplify; T from the auxiliary equation.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "simple_pendulum"


def run() -> None:
    M, a, g = sp.symbols("M a g", positive=True)
    T = sp.Symbol("T", real=True)
    th, w, u_aux = dynamicsymbols("theta omega u_aux")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (th, N.z))   # A.y points from the bob to the pivot
    O = Point("O")
    O.set_vel(N, 0)

    B = O.locatenew("B", -a * A.y)
    A.set_ang_vel(N, thd * N.z)
    B.v2pt_theory(O, N, A)
    bob = Particle("bob", B, M)
    bob.potential_energy = M * g * B.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, bob), [th], frame=N)
    lm.form_lagranges_equations()
    acc_l = sp.simplify(lm.mass_matrix.LUsolve(lm.forcing)[0])

    A.set_ang_vel(N, w * N.z)
    B.set_vel(N, a * w * A.x - u_aux * A.y)   # the auxiliary speed stretches the string
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[u_aux])
    km.kanes_equations([Particle("bob", B, M)], [(B, -M * g * N.y + T * A.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    T_sol = sp.solve([e.subs(w, thd) for e in km.auxiliary_eqs], T, dict=True)[0][T]
    assert sp.simplify(T_sol - M * (g * sp.cos(th) + a * thd**2)) == 0, T_sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; T = M (g cos(theta) + a theta'^2)")
