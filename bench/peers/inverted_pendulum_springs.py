"""Peer pipeline for inverted_pendulum_springs: sympy.physics.mechanics instead of dualmech.

A tip mass m on a massless rod l above a hinge, two horizontal zero-length springs k at height
a (source 004, question 4).  What a user of sympy.physics.mechanics writes: Lagrange's method
with gravity and the springs as potentials; Kane's method with two auxiliary speeds at the
hinge to expose its force R_x i + R_y j; the accelerations compared with LUsolve + simplify;
the stiffness about the upright position from the forcing, and the stability condition from
its sign; R from the auxiliary equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "inverted_pendulum_springs"


def run() -> None:
    m, l, a, k, g = sp.symbols("m l a k g", positive=True)
    R_x, R_y = sp.symbols("R_x R_y", real=True)
    th, w, ux, uy = dynamicsymbols("theta omega u_x u_y")
    thd, thdd = dynamicsymbols("theta", 1), dynamicsymbols("theta", 2)
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (th, N.z))       # the rod along B.y, theta from the vertical

    def rod(rate, aux_x=0, aux_y=0):
        O = Point("O")
        O.set_vel(N, aux_x * N.x + aux_y * N.y)
        B.set_ang_vel(N, rate * N.z)
        S, T = O.locatenew("S", a * B.y), O.locatenew("tip", l * B.y)
        S.v2pt_theory(O, N, B)
        T.v2pt_theory(O, N, B)
        return O, S, T

    O, S, T = rod(thd)
    p = Particle("tip", T, m)
    p.potential_energy = m * g * T.pos_from(O).dot(N.y) + k * S.pos_from(O).dot(N.x)**2
    lm = LagrangesMethod(Lagrangian(N, p), [th], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    O, S, T = rod(w, ux, uy)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[ux, uy])
    springs = -2 * k * S.pos_from(O).dot(N.x) * N.x
    km.kanes_equations([Particle("tip", T, m)],
                       [(T, -m * g * N.y), (S, springs), (O, R_x * N.x + R_y * N.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    # linearised about theta = 0: M theta'' + K theta = 0 with K = -d(forcing)/d(theta)
    M0 = lm.mass_matrix[0].subs(th, 0)
    K0 = sp.simplify(-lm.forcing[0].diff(th).subs({thd: 0}).subs(th, 0))
    assert sp.simplify(K0 - (2 * k * a**2 - m * g * l)) == 0 and M0 == m * l**2
    stable = sp.solve_univariate_inequality(K0 > 0, k, relational=False)
    assert stable == sp.Interval.open(m * g * l / (2 * a**2), sp.oo), stable

    aux = [e.subs(w.diff(), thdd).subs(w, thd) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [R_x, R_y], dict=True)[0]
    s, c = sp.sin(th), sp.cos(th)
    hand = {R_x: m * l * (thd**2 * s - acc_l * c) - 2 * k * a * s,      # by hand: R + springs
            R_y: m * g - m * l * (acc_l * s + thd**2 * c)}           # + weight = m a_tip
    assert all(sp.simplify(sol[r].subs(thdd, acc_l) - hand[r]) == 0 for r in hand), sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; stable for k > m g l / (2 a^2)")
