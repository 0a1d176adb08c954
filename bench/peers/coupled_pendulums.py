"""Peer pipeline for coupled_pendulums: sympy.physics.mechanics instead of dualmech.

Two pendulums (massless rods 3l, bobs m) from pivots O and O' = O + d I, joined at depth l by a
spring whose force is horizontal with extension ``l (sin th2 - sin th1)`` (the source's hint).
What a user of sympy.physics.mechanics writes: Lagrange's method with the spring and gravity
as potentials; Kane's method with the spring as forces at the rods' attachment points; the
accelerations compared with LUsolve + simplify; then the linearisation about the vertical and
its natural frequencies.  The source asks for no reaction.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "coupled_pendulums"


def run() -> None:
    m, k, l, d, g = sp.symbols("m k l d g", positive=True)
    q1, q2, u1, u2 = dynamicsymbols("theta1 theta2 u1 u2")
    q1d, q2d = dynamicsymbols("theta1 theta2", 1)
    N = ReferenceFrame("N")
    O1 = Point("O")
    O1.set_vel(N, 0)
    O2 = O1.locatenew("O'", d * N.x)
    O2.set_vel(N, 0)

    def place(rates):
        pts = []
        for q, rate, piv in zip((q1, q2), rates, (O1, O2)):
            P = N.orientnew("P", "Axis", (q, N.z))
            P.set_ang_vel(N, rate * N.z)
            S, B = piv.locatenew("S", -l * P.y), piv.locatenew("B", -3 * l * P.y)
            S.v2pt_theory(piv, N, P)
            B.v2pt_theory(piv, N, P)
            pts.append((S, B))
        return pts

    stretch = l * (sp.sin(q2) - sp.sin(q1))
    (S1, B1), (S2, B2) = place((q1d, q2d))
    b1, b2 = Particle("bob1", B1, m), Particle("bob2", B2, m)
    b1.potential_energy = m * g * B1.pos_from(O1).dot(N.y) + k * stretch**2 / 2
    b2.potential_energy = m * g * B2.pos_from(O2).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, b1, b2), [q1, q2], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    (S1, B1), (S2, B2) = place((u1, u2))
    km = KanesMethod(N, q_ind=[q1, q2], u_ind=[u1, u2], kd_eqs=[q1d - u1, q2d - u2])
    km.kanes_equations([Particle("bob1", B1, m), Particle("bob2", B2, m)],
                       [(B1, -m * g * N.y), (B2, -m * g * N.y),
                        (S1, k * stretch * N.x), (S2, -k * stretch * N.x)])
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs({u1: q1d, u2: q2d})
    assert all(sp.simplify(a - b) == 0 for a, b in zip(acc_l, acc_k)), "Lagrange and Kane"

    # linearise about the vertical: M q'' + K q = 0, frequencies from det(K - w^2 M) = 0
    rest = {q1d: 0, q2d: 0, q1: 0, q2: 0}
    M0 = lm.mass_matrix.subs(rest)
    K0 = -lm.forcing.jacobian([q1, q2]).subs(rest)
    w2 = sp.Symbol("w2")
    roots = set(sp.solve((K0 - w2 * M0).det(), w2))
    assert roots == {g / (3 * l), g / (3 * l) + 2 * k / (9 * m)}, roots

if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; omega^2 = g/(3l), g/(3l) + 2k/(9m)")
