"""Peer pipeline for block_in_pipe: sympy.physics.mechanics instead of dualmech.

A block m in a massless pipe swinging about O, spring k (free length y0) and damper d along
the pipe (source 003).  What a user of sympy.physics.mechanics writes: Lagrange's method in
(theta, y) with the damper in the force list; Kane's method with an auxiliary speed across the
pipe to expose its normal force N (N on the block, -N on the massless pipe at the block); the
accelerations compared with LUsolve + simplify; N from the auxiliary equation (it vanishes:
the massless pipe only guides the block).
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "block_in_pipe"


def run() -> None:
    m, k, d, y0, g = sp.symbols("m k d y0 g", positive=True)
    Nf = sp.Symbol("N", real=True)
    th, y, w, v, ua = dynamicsymbols("theta y omega v u_a")
    thd, yd = dynamicsymbols("theta y", 1)
    F = ReferenceFrame("F")
    P = F.orientnew("P", "Axis", (th, F.z))      # e_r = -P.y (outward), e_th = P.x
    O = Point("O")
    O.set_vel(F, 0)

    def block(rate, speed, aux=0):
        P.set_ang_vel(F, rate * F.z)
        b = O.locatenew("b", -y * P.y)
        b.set_vel(F, -speed * P.y + y * rate * P.x + aux * P.x)
        return b

    b = block(thd, yd)
    p = Particle("block", b, m)
    p.potential_energy = m * g * b.pos_from(O).dot(F.y) + k * (y - y0)**2 / 2
    lm = LagrangesMethod(Lagrangian(F, p), [th, y], forcelist=[(b, d * yd * P.y)], frame=F)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    b = block(w, v, ua)
    c = O.locatenew("c", -y * P.y)               # the pipe's point at the block
    c.set_vel(F, y * w * P.x)
    km = KanesMethod(F, q_ind=[th, y], u_ind=[w, v], kd_eqs=[thd - w, yd - v],
                     u_auxiliary=[ua])
    loads = [(b, -m * g * F.y + (k * (y - y0) + d * v) * P.y + Nf * P.x), (c, -Nf * P.x)]
    km.kanes_equations([Particle("block", b, m)], loads)
    rules = {w: thd, v: yd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(rules)
    assert (acc_l - acc_k).applyfunc(sp.simplify) == sp.zeros(2, 1), "Lagrange and Kane"

    thdd, ydd = dynamicsymbols("theta y", 2)
    aux = [e.subs({w.diff(): thdd, v.diff(): ydd}).subs(rules) for e in km.auxiliary_eqs]
    N_sol = sp.solve(aux, Nf, dict=True)[0][Nf].subs({thdd: acc_l[0], ydd: acc_l[1]})
    assert sp.simplify(N_sol) == 0, N_sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; the pipe's normal force N = 0")
