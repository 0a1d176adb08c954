"""Peer pipeline for three_mass_chain: sympy.physics.mechanics instead of dualmech.

Masses m1, m2, m3 hang on springs k1 (from the ceiling), k2, k3; x_i is the displacement of
m_i below its static position.  What a user of sympy.physics.mechanics writes: Lagrange's
method with the springs' energy about the static equilibrium (gravity neglected, as the source
does); Kane's method with gravity and the springs' forces including their static extension;
the accelerations compared with LUsolve + simplify; the mass and stiffness matrices from the
linearisation, compared with the source's, and the characteristic polynomial of an equal
chain.  The source asks for no reaction.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "three_mass_chain"


def run() -> None:
    m1, m2, m3, k1, k2, k3, g = sp.symbols("m1 m2 m3 k1 k2 k3 g", positive=True)
    ms, ks = (m1, m2, m3), (k1, k2, k3)
    xs = dynamicsymbols("x1 x2 x3")
    us = dynamicsymbols("u1 u2 u3")
    xds = [x.diff(dynamicsymbols._t) for x in xs]
    N = ReferenceFrame("N")
    O = Point("O")

    def masses(rates):
        pts = [O.locatenew(f"P{i}", -x * N.y) for i, x in enumerate(xs)]
        for p, r in zip(pts, rates):
            p.set_vel(N, -r * N.y)
        return pts, [Particle(f"m{i}", p, mi) for i, (p, mi) in enumerate(zip(pts, ms))]

    stretch = [xs[0], xs[1] - xs[0], xs[2] - xs[1]]
    pts, parts = masses(xds)
    parts[0].potential_energy = sum(k * e**2 / 2 for k, e in zip(ks, stretch))
    lm = LagrangesMethod(Lagrangian(N, *parts), xs, frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    pts, parts = masses(us)
    static = [(m1 + m2 + m3) * g / k1, (m2 + m3) * g / k2, m3 * g / k3]
    tension = [k * (d + e) for k, d, e in zip(ks, static, stretch)]
    loads = [(p, -mi * g * N.y) for p, mi in zip(pts, ms)]
    loads += [(pts[0], tension[0] * N.y), (pts[0], -tension[1] * N.y),
              (pts[1], tension[1] * N.y), (pts[1], -tension[2] * N.y), (pts[2], tension[2] * N.y)]
    km = KanesMethod(N, q_ind=xs, u_ind=us, kd_eqs=[xd - u for xd, u in zip(xds, us)])
    km.kanes_equations(parts, loads)
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(dict(zip(us, xds)))
    assert all(sp.simplify(p - q) == 0 for p, q in zip(acc_l, acc_k)), "Lagrange and Kane"

    rest = {**{xd: 0 for xd in xds}, **{x: 0 for x in xs}}
    M0 = lm.mass_matrix.subs(rest)
    K0 = -lm.forcing.jacobian(xs).subs(rest)
    assert M0 == sp.diag(m1, m2, m3)
    assert K0 == sp.Matrix([[k1 + k2, -k2, 0], [-k2, k2 + k3, -k3], [0, -k3, k3]])
    w2 = sp.Symbol("w2")
    ones = {s: 1 for s in (*ms, *ks)}
    poly = sp.expand((K0 - w2 * M0).subs(ones).det())
    assert poly == -w2**3 + 5 * w2**2 - 6 * w2 + 1, poly   # roots 4 sin^2((2j-1) pi/14)


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; M and K are the source's")
