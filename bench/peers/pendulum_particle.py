"""Peer pipeline for pendulum_particle: sympy.physics.mechanics instead of dualmech.

The bob m on a rod l (theta from the downward vertical, source 003).  What a user of
sympy.physics.mechanics writes: Lagrange's method in theta; Lagrange's method in Cartesian
(x, y) with the rod as a holonomic constraint (its multiplier gives the rod force); Kane's
method with an auxiliary speed along the rod to expose the rod force S; accelerations compared
with LUsolve + simplify, S from the auxiliary equation and from the multiplier.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "pendulum_particle"


def run() -> None:
    m, l, g = sp.symbols("m l g", positive=True)
    S = sp.Symbol("S", real=True)
    th, w, ua = dynamicsymbols("theta omega u_a")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (th, N.z))      # B.y points from the bob to the pivot
    O = Point("O")
    O.set_vel(N, 0)
    bob = O.locatenew("bob", -l * B.y)
    bob.v2pt_theory(O, N, B)
    p = Particle("bob", bob, m)
    p.potential_energy = m * g * bob.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, p), [th], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    B.set_ang_vel(N, w * N.z)
    bob.set_vel(N, -l * w * B.z.cross(B.y) + ua * B.y)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[ua])
    km.kanes_equations([Particle("bob", bob, m)], [(bob, -m * g * N.y + S * B.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"
    S_kane = sp.solve([e.subs(w, thd) for e in km.auxiliary_eqs], S, dict=True)[0][S]
    assert sp.simplify(S_kane - m * (g * sp.cos(th) + l * thd**2)) == 0, S_kane

    # the index-3 DAE: (x, y) with x^2 + y^2 = l^2; y measured down from O as in the source
    x, y = dynamicsymbols("x y")
    P = O.locatenew("P", x * N.x - y * N.y)
    P.set_vel(N, P.pos_from(O).dt(N))
    q = Particle("bob", P, m)
    q.potential_energy = -m * g * y
    dae = LagrangesMethod(Lagrangian(N, q), [x, y], hol_coneqs=[x**2 + y**2 - l**2], frame=N)
    dae.form_lagranges_equations()
    sol = dae.mass_matrix_full.LUsolve(dae.forcing_full)
    on_rod = {x: l * sp.sin(th), y: l * sp.cos(th),
              x.diff(): l * sp.cos(th) * thd, y.diff(): -l * sp.sin(th) * thd}
    xdd, lam = sol[2].subs(on_rod), sol[4].subs(on_rod)      # unknowns x', y', x'', y'', lambda
    assert sp.simplify(xdd - (l * sp.cos(th) * acc_l - l * sp.sin(th) * thd**2)) == 0, \
        "the DAE and the theta form disagree"
    # sympy's multiplier multiplies grad(x^2 + y^2 - l^2) = 2 r: the rod force is -2 l lambda
    assert sp.simplify(-2 * l * lam - S_kane) == 0, lam


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange (theta), Kane and the Cartesian DAE agree; "
          "S = m (g cos(theta) + l theta'^2)")
