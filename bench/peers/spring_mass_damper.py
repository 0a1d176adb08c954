"""Peer pipeline for spring_mass_damper: sympy.physics.mechanics instead of dualmech.

A block m on a spring k and a dashpot b, driven by f(t) = F0 cos(Omega t) (Example 11 of
source 000).  What a user of sympy.physics.mechanics writes: Lagrange's method with the
spring as a potential and the dashpot and drive in the force list; Kane's method with every
force as a load; the accelerations compared with LUsolve + simplify.  No reaction is asked for.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "spring_mass_damper"


def run() -> None:
    m, k, b, F0, W = sp.symbols("m k b F0 Omega", positive=True)
    t = dynamicsymbols._t
    x, v = dynamicsymbols("x v")
    xd = dynamicsymbols("x", 1)
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", x * N.x)
    drive = F0 * sp.cos(W * t)

    P.set_vel(N, xd * N.x)
    block = Particle("block", P, m)
    block.potential_energy = k * x**2 / 2
    lm = LagrangesMethod(Lagrangian(N, block), [x], frame=N,
                         forcelist=[(P, (drive - b * xd) * N.x)])
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    P.set_vel(N, v * N.x)
    km = KanesMethod(N, q_ind=[x], u_ind=[v], kd_eqs=[xd - v])
    km.kanes_equations([Particle("block", P, m)], [(P, (drive - k * x - b * v) * N.x)])
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(v, xd)
    assert sp.simplify(acc_l[0] - acc_k[0]) == 0, "Lagrange and Kane"
    assert sp.simplify(acc_l[0] - (drive - b * xd - k * x) / m) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree")
