"""Peer pipeline for two_rod_linkage: sympy.physics.mechanics instead of dualmech.

The slider M (spring k to the left wall, dashpot c to the right) carries the two-rod linkage
with the point mass m at A: ``O r_A = l (cos th, sin th)``, ``O r_B = 2 l cos(th) I``.  What a
user of sympy.physics.mechanics writes: Lagrange's method in ``theta``; Kane's method with an
auxiliary speed of B along I to expose the bar force ``F_R`` on M (the shaft's normal force is
perpendicular to I and drops out, as in the source's projection); the two accelerations
compared with LUsolve + simplify; ``F_R`` from the auxiliary equation.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "two_rod_linkage"


def run() -> None:
    M, m, k, c, l, l0, g = sp.symbols("M m k c l l0 g", positive=True)
    F_R = sp.Symbol("F_R", real=True)
    th, w, ua = dynamicsymbols("theta omega u_a")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    iR = sp.cos(th) * N.x - sp.sin(th) * N.y           # along the right bar, from A to B
    O = Point("O")
    O.set_vel(N, 0)

    def points(rate, aux=0):
        A = O.locatenew("A", l * (sp.cos(th) * N.x + sp.sin(th) * N.y))
        B = O.locatenew("B", 2 * l * sp.cos(th) * N.x)
        A.set_vel(N, A.pos_from(O).dt(N).subs(thd, rate))
        B.set_vel(N, B.pos_from(O).dt(N).subs(thd, rate) + aux * N.x)
        return A, B

    def loads(A, B, rate):
        x = 2 * l * sp.cos(th) - l0
        xd = -2 * l * sp.sin(th) * rate
        return [(A, -m * g * N.y), (B, (-k * x - c * xd) * N.x)]

    # Lagrange: gravity and spring as potentials, the dashpot as a force
    A, B = points(thd)
    pa, pb = Particle("m", A, m), Particle("M", B, M)
    pa.potential_energy = m * g * l * sp.sin(th)
    pb.potential_energy = k * (2 * l * sp.cos(th) - l0)**2 / 2
    lm = LagrangesMethod(Lagrangian(N, pa, pb), [th],
                         forcelist=[(B, -c * (-2 * l * sp.sin(th) * thd) * N.x)], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    # Kane, with the auxiliary speed u_a of B along I and the bar force on M and on m
    A, B = points(w, ua)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[ua])
    km.kanes_equations([Particle("m", A, m), Particle("M", B, M)],
                       loads(A, B, w) + [(B, F_R * iR), (A, -F_R * iR)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    wd = dynamicsymbols("omega", 1)
    aux = km.auxiliary_eqs[0].subs({wd: acc_l, w: thd})
    bar = sp.solve(aux, F_R)[0]
    # the source's (B): F_R cos(theta) = M x'' + c x' + k x, x = 2 l cos(theta) - l0
    x = 2 * l * sp.cos(th) - l0
    rhs = (M * x.diff(dynamicsymbols._t, 2) + c * x.diff(dynamicsymbols._t) + k * x)
    assert sp.simplify((bar * sp.cos(th) - rhs).subs(thd.diff(), acc_l)) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; F_R recovered")
