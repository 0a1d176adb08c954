"""Peer pipeline for satellite_polar: sympy.physics.mechanics instead of dualmech.

A satellite m about a fixed centre with gravitational parameter mu, in polar coordinates.
What a user of sympy.physics.mechanics writes: Lagrange's method with the potential -m mu/r;
Kane's method with the central force as a load; the accelerations compared with LUsolve +
simplify; the angular momentum differentiated along the motion; the circular-orbit rate.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "satellite_polar"


def run() -> None:
    m, mu = sp.symbols("m mu", positive=True)
    r, th, u1, u2 = dynamicsymbols("r theta u1 u2")
    rd, thd = r.diff(), th.diff()
    N = ReferenceFrame("N")
    E = N.orientnew("E", "Axis", (th, N.z))
    O = Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", r * E.x)
    P.v2pt_theory(O, N, E)
    P.set_vel(N, P.vel(N) + rd * E.x)
    sat = Particle("satellite", P, m)
    sat.potential_energy = -m * mu / r
    L = Lagrangian(N, sat)
    lm = LagrangesMethod(L, [r, th], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    P.set_vel(N, u1 * E.x + r * u2 * E.y)
    km = KanesMethod(N, q_ind=[r, th], u_ind=[u1, u2], kd_eqs=[rd - u1, thd - u2])
    km.kanes_equations([Particle("satellite", P, m)], [(P, -m * mu / r**2 * E.x)])
    back = {u1: rd, u2: thd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    t = dynamicsymbols._t
    on_motion = {rd.diff(t): acc_l[0], thd.diff(t): acc_l[1]}
    assert sp.simplify(L.diff(thd).diff(t).subs(on_motion)) == 0     # m r^2 theta'
    w = sp.Symbol("w", positive=True)
    circle = acc_l[0].subs(rd, 0).subs(thd, w)
    rates = sp.solve(circle, w)
    assert rates and all(sp.simplify(x**2 - mu / r**3) == 0 for x in rates)


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; m r^2 theta' conserved; circular orbit "
          "theta'^2 = mu / r^3")
