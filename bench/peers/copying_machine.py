"""Peer pipeline for copying_machine: sympy.physics.mechanics instead of dualmech.

A mass m2 (displacement y) driven by F, a dashpot b to the ground, a spring k2 to the end (at
L) of a massless bar pivoted at O and held by a spring k1 at a; small rotation theta of the
bar, so its points at s move s theta along j (Example 14 of source 000).  The bar has no mass:
theta has no inertia and both mass matrices are singular -- the theta row is static.  What a
user of sympy.physics.mechanics then does by hand: solve the static row for theta, put it into
the y row and compare the accelerations; Kane's method with an auxiliary speed at the pivot
(along j) exposes the pivot's force R_O, solved from the auxiliary equation with theta on its
static solution.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "copying_machine"


def run() -> None:
    m2, k1, k2, a, L, b, F = sp.symbols("m2 k1 k2 a L b F", positive=True)
    R_O = sp.Symbol("R_O", real=True)
    y, th, v, w, u_aux = dynamicsymbols("y theta v w u_aux")
    yd, thd = dynamicsymbols("y theta", 1)
    N = ReferenceFrame("N")

    def scene(yrate, thrate, aux=0):
        O = Point("O")
        O.set_vel(N, aux * N.y)
        A, E = O.locatenew("A", a * N.x), O.locatenew("E", L * N.x)
        A.set_vel(N, (aux + a * thrate) * N.y)          # small rotation: s theta along j
        E.set_vel(N, (aux + L * thrate) * N.y)
        P = O.locatenew("P", L * N.x + y * N.y)
        P.set_vel(N, yrate * N.y)
        return O, A, E, P

    O, A, E, P = scene(yd, thd)
    mass = Particle("m2", P, m2)
    mass.potential_energy = k2 * (L * th - y)**2 / 2 + k1 * (a * th)**2 / 2
    lm = LagrangesMethod(Lagrangian(N, mass), [y, th], frame=N,
                         forcelist=[(P, (F - b * yd) * N.y)])
    lm.form_lagranges_equations()
    assert lm.mass_matrix.det() == 0            # theta has no inertia: a static row
    assert list(lm.mass_matrix[1, :]) == [0, 0]
    (th_static,) = sp.solve(lm.forcing[1], th)    # the static row: forcing = 0
    on = {th: th_static}
    acc_l = sp.solve((lm.mass_matrix[0, 0] * sp.Symbol("ydd") - lm.forcing[0]).subs(on),
                     sp.Symbol("ydd"))[0]

    O, A, E, P = scene(v, w, u_aux)
    km = KanesMethod(N, q_ind=[y, th], u_ind=[v, w], kd_eqs=[yd - v, thd - w],
                     u_auxiliary=[u_aux])
    s2 = k2 * (y - L * th)
    km.kanes_equations([Particle("m2", P, m2)],
                       [(P, (F - b * v - s2) * N.y), (E, s2 * N.y), (A, -k1 * a * th * N.y),
                        (O, R_O * N.y)])
    assert km.mass_matrix.det() == 0
    (th_kane,) = sp.solve(km.forcing[1], th)
    assert sp.simplify(th_kane - th_static) == 0, "the static rows agree"
    acc_k = (km.forcing[0] / km.mass_matrix[0, 0]).subs(th, th_kane).subs(v, yd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane"
    k_e = k1 * k2 * a**2 / (k2 * L**2 + k1 * a**2)
    assert sp.simplify(acc_l - (F - b * yd - k_e * y) / m2) == 0

    (R,) = sp.solve(km.auxiliary_eqs[0].subs(th, th_kane), R_O)
    assert sp.simplify(R - k1 * k2 * a * (L - a) * y / (k2 * L**2 + k1 * a**2)) == 0, R


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: singular mass matrices (static theta row) handled by hand; "
          "Lagrange and Kane agree; pivot force R_O recovered")
