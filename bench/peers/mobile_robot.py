"""Peer pipeline for mobile_robot: sympy.physics.mechanics instead of dualmech.

A base M at x driven by f, an arm (point masses m1 at D1 and m2 at D2 + r2 from the pivot P,
phi from the upward vertical) turned by a torque T (case study of source 000, detailed model).
What a user of sympy.physics.mechanics writes: Lagrange's method with gravity as a potential
and f, T in the force list; Kane's method with an auxiliary speed of the pivot along i to
expose its horizontal force H; the accelerations compared with LUsolve + simplify; H from the
auxiliary equation and checked against H = f - M x'' (2.6-11).
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "mobile_robot"


def run() -> None:
    M, m1, m2, D1, D2, r2, g = sp.symbols("M m1 m2 D1 D2 r2 g", positive=True)
    f, T, H = sp.symbols("f T H", real=True)
    x, ph, ux, w, u_aux = dynamicsymbols("x phi u_x w u_aux")
    xd, phd = dynamicsymbols("x phi", 1)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (ph, N.z))      # A.y along the arm
    O = Point("O")
    O.set_vel(N, 0)

    def scene(xrate, phrate, aux=0):
        base = O.locatenew("B", x * N.x)
        base.set_vel(N, xrate * N.x)
        pivot = base.locatenew("P", 0)
        pivot.set_vel(N, (xrate + aux) * N.x)
        A.set_ang_vel(N, phrate * N.z)
        arm = [pivot.locatenew(f"p{i}", d * A.y) for i, d in ((1, D1), (2, D2 + r2))]
        for p in arm:
            p.v2pt_theory(pivot, N, A)
        return base, pivot, arm

    base, pivot, arm = scene(xd, phd)
    parts = [Particle("base", base, M)] + [Particle(f"arm{i}", p, mi)
                                           for i, (p, mi) in enumerate(zip(arm, (m1, m2)))]
    for p in parts[1:]:
        p.potential_energy = p.mass * g * p.point.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, *parts), [x, ph], frame=N,
                         forcelist=[(base, f * N.x), (A, T * N.z)])
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    base, pivot, arm = scene(ux, w, u_aux)
    parts = [Particle("base", base, M)] + [Particle(f"arm{i}", p, mi)
                                           for i, (p, mi) in enumerate(zip(arm, (m1, m2)))]
    km = KanesMethod(N, q_ind=[x, ph], u_ind=[ux, w], kd_eqs=[xd - ux, phd - w],
                     u_auxiliary=[u_aux])
    loads = [(base, (f - H) * N.x), (pivot, H * N.x), (A, T * N.z)]
    loads += [(p, -mi * g * N.y) for p, mi in zip(arm, (m1, m2))]
    km.kanes_equations(parts, loads)
    back = {ux: xd, w: phd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    xdd, phdd = dynamicsymbols("x phi", 2)
    aux = km.auxiliary_eqs[0].subs({dynamicsymbols("u_x", 1): xdd,
                                    dynamicsymbols("w", 1): phdd}).subs(back)
    (H_sol,) = sp.solve(aux, H)
    on = {xdd: acc_l[0], phdd: acc_l[1]}
    assert sp.simplify(H_sol.subs(on) - (f - M * acc_l[0])) == 0, "(2.6-11)"


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; pivot reaction H recovered")
