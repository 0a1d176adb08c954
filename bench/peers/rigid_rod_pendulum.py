"""Peer pipeline for rigid_rod_pendulum: sympy.physics.mechanics instead of dualmech.

A uniform rod (m, l) hinged at one end, theta from the downward vertical (source 003).  What a
user of sympy.physics.mechanics writes: Lagrange's method with the rod as a RigidBody; Kane's
method with two auxiliary speeds at the hinge to expose the pivot force R_x i + R_y j; the
accelerations compared with LUsolve + simplify; R from the auxiliary equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "rigid_rod_pendulum"


def run() -> None:
    m, l, g = sp.symbols("m l g", positive=True)
    R_x, R_y = sp.symbols("R_x R_y", real=True)
    th, w, ux, uy = dynamicsymbols("theta omega u_x u_y")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (th, N.z))        # the rod along -B.y

    def rod(rate, aux_x=0, aux_y=0):
        O = Point("O")
        O.set_vel(N, aux_x * N.x + aux_y * N.y)
        B.set_ang_vel(N, rate * N.z)
        C = O.locatenew("C", -l / 2 * B.y)
        C.v2pt_theory(O, N, B)
        body = RigidBody("rod", C, B, m, (inertia(B, m * l**2 / 12, 0, m * l**2 / 12), C))
        return O, C, body

    O, C, body = rod(thd)
    body.potential_energy = m * g * C.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, body), [th], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    O, C, body = rod(w, ux, uy)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[ux, uy])
    km.kanes_equations([body], [(C, -m * g * N.y), (O, R_x * N.x + R_y * N.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"
    assert sp.simplify(acc_l + 3 * g / (2 * l) * sp.sin(th)) == 0, acc_l

    thdd = dynamicsymbols("theta", 2)
    aux = [e.subs(dynamicsymbols("omega", 1), thdd).subs(w, thd) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [R_x, R_y], dict=True)[0]
    s, c = sp.sin(th), sp.cos(th)
    hand = {R_x: -sp.Rational(3, 4) * m * g * s * c - m * l / 2 * thd**2 * s,
            R_y: m * g * (1 - sp.Rational(3, 4) * s**2) + m * l / 2 * thd**2 * c}
    assert all(sp.simplify(sol[r].subs(thdd, acc_l) - hand[r]) == 0 for r in hand), sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; pivot force R_x, R_y recovered")
