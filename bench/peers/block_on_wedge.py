"""Peer pipeline for block_on_wedge: sympy.physics.mechanics instead of dualmech.

A block m slides without friction down the incline (angle alpha) of a wedge M that slides on
frictionless ground (source 000, Example 16); q1 down the slope relative to the wedge, q2 the
wedge's horizontal position.  What a user of sympy.physics.mechanics writes: the incline frame
S (N turned by -alpha about N.z, S.x down the slope, S.y its outward normal); Lagrange's
method with gravity as a potential; Kane's method with two auxiliary speeds -- the block off
the incline along S.y (exposes the normal force N1, N1 S.y on the block and -N1 S.y on the
wedge) and the wedge off the ground along N.y, carrying the block (exposes N2); the
accelerations compared with LUsolve + simplify; N1 and N2 from the auxiliary equations,
checked against the source's values ``N1 = m M g cos a / D``, ``N2 = M (M + m) g / D`` with
``D = M + m sin^2 a``, and the printed accelerations checked.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "block_on_wedge"


def run() -> None:
    m, M, g, alpha = sp.symbols("m M g alpha", positive=True)
    N1, N2 = sp.symbols("N1 N2", real=True)
    q1, q2, u1, u2, ua1, ua2 = dynamicsymbols("q1 q2 u1 u2 u_a1 u_a2")
    q1d, q2d = dynamicsymbols("q1 q2", 1)
    N = ReferenceFrame("N")
    S = N.orientnew("S", "Axis", (-alpha, N.z))
    O = Point("O")

    def scene(r1, r2, a1=0, a2=0):
        A = O.locatenew("A", q2 * N.x)               # top of the incline, on the wedge
        A.set_vel(N, r2 * N.x + a2 * N.y)
        P = A.locatenew("P", q1 * S.x)               # the block
        P.set_vel(N, A.vel(N) + r1 * S.x + a1 * S.y)
        return A, P

    A, P = scene(q1d, q2d)
    block, wedge = Particle("block", P, m), Particle("wedge", A, M)
    block.potential_energy = m * g * P.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, block, wedge), [q1, q2], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    A, P = scene(u1, u2, ua1, ua2)
    km = KanesMethod(N, q_ind=[q1, q2], u_ind=[u1, u2], kd_eqs=[q1d - u1, q2d - u2],
                     u_auxiliary=[ua1, ua2])
    loads = [(P, -m * g * N.y + N1 * S.y), (A, -M * g * N.y - N1 * S.y + N2 * N.y)]
    km.kanes_equations([Particle("block", P, m), Particle("wedge", A, M)], loads)
    back = {u1: q1d, u2: q2d}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert (acc_l - acc_k).applyfunc(sp.simplify) == sp.zeros(2, 1), "Lagrange and Kane"

    s, c = sp.sin(alpha), sp.cos(alpha)
    delta = M + m * s**2
    # the source's printed accelerations
    assert sp.simplify(acc_l[0] - g * s / (1 - m / (M + m) * c**2)) == 0, acc_l[0]
    assert sp.simplify(acc_l[1] + m / (M + m) * acc_l[0] * c) == 0, acc_l[1]

    on_motion = {u1.diff(): acc_l[0], u2.diff(): acc_l[1]}
    aux = [e.subs(on_motion).subs(back) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [N1, N2], dict=True)[0]
    assert sp.simplify(sol[N1] - m * M * g * c / delta) == 0, sol[N1]
    assert sp.simplify(sol[N2] - M * (M + m) * g / delta) == 0, sol[N2]


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; printed accelerations right; N1, N2 recovered")
