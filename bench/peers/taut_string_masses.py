"""Peer pipeline for taut_string_masses: sympy.physics.mechanics instead of dualmech.

Two masses m on a string of tension P between anchors 3a apart, at a and 2a, moving
transversely by x1, x2 (the source's small-vibration model).  What a user of
sympy.physics.mechanics writes: Lagrange's method with V = P Delta (the stretch expanded to
second order); Kane's method with the tension P along each segment, its length taken as a;
the accelerations compared with LUsolve + simplify; the natural frequencies from the
linearisation.  The source asks for no reaction.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "taut_string_masses"


def run() -> None:
    m, P, a = sp.symbols("m P a", positive=True)
    x1, x2, u1, u2 = dynamicsymbols("x1 x2 u1 u2")
    x1d, x2d = dynamicsymbols("x1 x2", 1)
    N = ReferenceFrame("N")
    O = Point("O")

    def masses(r1, r2):
        P1 = O.locatenew("P1", a * N.x + x1 * N.y)
        P2 = O.locatenew("P2", 2 * a * N.x + x2 * N.y)
        P1.set_vel(N, r1 * N.y)
        P2.set_vel(N, r2 * N.y)
        return P1, P2

    P1, P2 = masses(x1d, x2d)
    b1, b2 = Particle("m1", P1, m), Particle("m2", P2, m)
    b1.potential_energy = P / (2 * a) * (x1**2 + (x2 - x1)**2 + x2**2)
    lm = LagrangesMethod(Lagrangian(N, b1, b2), [x1, x2], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    P1, P2 = masses(u1, u2)
    ends = [O, P1, P2, O.locatenew("E", 3 * a * N.x)]
    loads = []
    for left, right in zip(ends, ends[1:]):
        pull = P * right.pos_from(left) / a     # on the left end, towards the right end
        loads += [(left, pull), (right, -pull)]
    loads = [(p, f) for p, f in loads if p in (P1, P2)]
    km = KanesMethod(N, q_ind=[x1, x2], u_ind=[u1, u2], kd_eqs=[x1d - u1, x2d - u2])
    km.kanes_equations([Particle("m1", P1, m), Particle("m2", P2, m)], loads)
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs({u1: x1d, u2: x2d})
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    rest = {x1d: 0, x2d: 0, x1: 0, x2: 0}
    M0 = lm.mass_matrix.subs(rest)
    K0 = -lm.forcing.jacobian([x1, x2]).subs(rest)
    w2 = sp.Symbol("w2")
    roots = set(sp.solve((K0 - w2 * M0).det(), w2))
    assert roots == {P / (a * m), 3 * P / (a * m)}, roots


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; omega^2 = P/(a m), 3P/(a m)")
