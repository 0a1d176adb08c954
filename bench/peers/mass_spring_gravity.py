"""Peer pipeline for mass_spring_gravity: sympy.physics.mechanics instead of dualmech.

A mass M at height x on a spring k (unstretched at x = 0), gravity -g j, a steady force F j.
What a user of sympy.physics.mechanics writes: Lagrange's method with the spring and gravity
as potentials and F in the force list; Kane's method with all three as forces; the
accelerations compared with LUsolve + simplify; the static equilibrium from the forcing.  The
source asks for no reaction.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "mass_spring_gravity"


def run() -> None:
    M, k, g, F = sp.symbols("M k g F", positive=True)
    x, u = dynamicsymbols("x u")
    xd = dynamicsymbols("x", 1)
    N = ReferenceFrame("N")
    O = Point("O")

    P = O.locatenew("P", x * N.y)
    P.set_vel(N, xd * N.y)
    mass = Particle("mass", P, M)
    mass.potential_energy = k * x**2 / 2 + M * g * x
    lm = LagrangesMethod(Lagrangian(N, mass), [x], forcelist=[(P, F * N.y)], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    P.set_vel(N, u * N.y)
    km = KanesMethod(N, q_ind=[x], u_ind=[u], kd_eqs=[xd - u])
    km.kanes_equations([Particle("mass", P, M)], [(P, (F - k * x - M * g) * N.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(u, xd)
    assert sp.simplify(acc_l[0] - acc_k[0]) == 0, "Lagrange and Kane disagree"

    (x_eq,) = sp.solve(lm.forcing[0].subs(xd, 0), x)
    assert sp.simplify(x_eq - (F - M * g) / k) == 0, x_eq


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; equilibrium x* = (F - M g)/k")
