"""Peer pipeline for bead_on_hoop: sympy.physics.mechanics instead of dualmech.

A bead m on a hoop of radius R turned about its vertical diameter at the prescribed rate
omega (hoop angle omega t), theta from the bottom (Example 13 of source 000).  What a user of
sympy.physics.mechanics writes: Lagrange's method with the hoop frame oriented by omega t
(explicit time); Kane's method with two auxiliary speeds, across the wire in the hoop plane
and normal to it, to expose the hoop's force N k_B + N_b j_H; the accelerations compared with
LUsolve + simplify; N, N_b from the auxiliary equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "bead_on_hoop"


def run() -> None:
    m, R, g, omega = sp.symbols("m R g omega", positive=True)
    Nn, Nb = sp.symbols("N N_b", real=True)
    t = dynamicsymbols._t
    th, w, un, ub = dynamicsymbols("theta w u_n u_b")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    H = N.orientnew("H", "Axis", (omega * t, N.z))
    B = H.orientnew("B", "Axis", (-th, H.y))      # B.x along the wire, B.z towards the centre
    O = Point("O")
    O.set_vel(N, 0)

    def bead(rate, aux_n=0, aux_b=0):
        B.set_ang_vel(H, -rate * H.y)
        P = O.locatenew("P", -R * B.z)
        P.set_vel(N, P.pos_from(O).dt(N).subs(thd, rate) + aux_n * B.z + aux_b * H.y)
        return P

    P = bead(thd)
    p = Particle("bead", P, m)
    p.potential_energy = m * g * P.pos_from(O).dot(N.z)
    lm = LagrangesMethod(Lagrangian(N, p), [th], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)
    printed = (omega**2 * sp.cos(th) - g / R) * sp.sin(th)      # the source's th''
    assert sp.simplify(acc_l[0] - printed) == 0

    P = bead(w, un, ub)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[un, ub])
    km.kanes_equations([Particle("bead", P, m)],
                       [(P, -m * g * N.z + Nn * B.z + Nb * H.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(w, thd)
    assert sp.simplify(acc_l[0] - acc_k[0]) == 0, "Lagrange and Kane"

    thdd = dynamicsymbols("theta", 2)
    aux = [e.subs(dynamicsymbols("w", 1), thdd).subs(w, thd) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [Nn, Nb], dict=True)[0]
    sol = {r: e.subs(thdd, acc_l[0]) for r, e in sol.items()}
    s, co = sp.sin(th), sp.cos(th)
    hand = {Nn: m * g * co + m * R * (thd**2 + omega**2 * s**2),
            Nb: 2 * m * R * omega * thd * co}
    assert all(sp.simplify(sol[r] - hand[r]) == 0 for r in hand), sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; the hoop's force N, N_b recovered")
