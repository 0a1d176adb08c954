"""Peer pipeline for cart_pendulum: sympy.physics.mechanics instead of dualmech.

A cart m at x on a spring k and dashpot c carries a pendulum (massless rod l, bob m0, theta
from the downward vertical) with a torsional spring k_t and dashpot c_t at the pivot; a
horizontal force F0 sin(omega t) on the bob (source 000, Example 17).  What a user of
sympy.physics.mechanics writes: the rod frame R (theta about N.z, R.y from the bob to the
pivot); Lagrange's method with the springs and gravity as potentials and the dashpots (a force
on the cart, a torque on R) and the drive in the force list; Kane's method with three
auxiliary speeds -- the cart off the bed along N.y (exposes the normal force N), the bob along
the rod, R.y (the tension T), and the bob across the rod, R.x (the transverse force S), each
rod force acting on the bob and, opposite, on the rod's end point; the accelerations compared
with LUsolve + simplify; N, T, S from the auxiliary equations against the hand solution
(S = -(k_t th + c_t th')/l, T = m0 g cos th + F sin th + m0 l th'^2 - m0 x'' sin th,
N = (m + m0) g + m0 l (th'' sin th + th'^2 cos th)); the printed theta equation (``m0 l th''``
where ``m0 l^2 th''`` belongs) checked against Lagrange's and found wrong.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "cart_pendulum"


def run() -> None:
    m, m0, l, k, c, k_t, c_t, g, F0, omega = sp.symbols("m m0 l k c k_t c_t g F0 omega",
                                                         positive=True)
    Nf, T, S = sp.symbols("N T S", real=True)
    x, th, ux, w, u_n, u_t, u_s = dynamicsymbols("x theta u_x omega u_n u_t u_s")
    xd, thd = dynamicsymbols("x theta", 1)
    t = dynamicsymbols._t
    drive = F0 * sp.sin(omega * t)
    N = ReferenceFrame("N")
    R = N.orientnew("R", "Axis", (th, N.z))
    O = Point("O")

    def scene(xrate, thrate, a_n=0, a_t=0, a_s=0):
        P = O.locatenew("P", x * N.x)                 # the pivot, on the cart
        P.set_vel(N, xrate * N.x + a_n * N.y)
        R.set_ang_vel(N, thrate * N.z)
        E = P.locatenew("E", -l * R.y)                # the rod's end
        E.v2pt_theory(P, N, R)
        B = P.locatenew("B", -l * R.y)                # the bob
        B.set_vel(N, E.vel(N) + a_t * R.y + a_s * R.x)
        return P, E, B

    P, E, B = scene(xd, thd)
    cart, bob = Particle("cart", P, m), Particle("bob", B, m0)
    cart.potential_energy = k * x**2 / 2 + k_t * th**2 / 2
    bob.potential_energy = m0 * g * B.pos_from(P).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, cart, bob), [x, th],
                         forcelist=[(P, -c * xd * N.x), (R, -c_t * thd * N.z),
                                    (B, drive * N.x)], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    P, E, B = scene(ux, w, u_n, u_t, u_s)
    pull = T * R.y + S * R.x                          # the rod on the bob
    km = KanesMethod(N, q_ind=[x, th], u_ind=[ux, w], kd_eqs=[xd - ux, thd - w],
                     u_auxiliary=[u_n, u_t, u_s])
    loads = [(P, (-k * x - c * ux) * N.x + (Nf - m * g) * N.y),
             (B, drive * N.x - m0 * g * N.y + pull), (E, -pull),
             (R, -(k_t * th + c_t * w) * N.z)]
    km.kanes_equations([Particle("cart", P, m), Particle("bob", B, m0)], loads)
    back = {ux: xd, w: thd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert (acc_l - acc_k).applyfunc(sp.simplify) == sp.zeros(2, 1), "Lagrange and Kane"

    on_motion = {ux.diff(): acc_l[0], w.diff(): acc_l[1]}
    aux = [e.subs(on_motion).subs(back) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [Nf, T, S], dict=True)[0]
    s, co = sp.sin(th), sp.cos(th)
    hand = {S: -(k_t * th + c_t * thd) / l,
            T: m0 * g * co + drive * s + m0 * l * thd**2 - m0 * acc_l[0] * s,
            Nf: (m + m0) * g + m0 * l * (acc_l[1] * s + thd**2 * co)}
    assert all(sp.simplify(sol[r] - hand[r]) == 0 for r in hand), sol

    # the printed theta equation, against Lagrange's theta row on the motion
    xdd, thdd = dynamicsymbols("x theta", 2)
    printed = (m0 * l * thdd + c_t * thd + k_t * th + m0 * g * l * s + m0 * xdd * l * co
               - drive * l * co)
    residual = printed.subs({xdd: acc_l[0], thdd: acc_l[1]})
    point = {x: sp.Rational(1, 10), th: sp.Rational(3, 10), xd: sp.Rational(-1, 5),
             thd: sp.Rational(2, 5), t: sp.Rational(1, 2), m: 2, m0: sp.Rational(1, 2),
             l: sp.Rational(4, 5), k: 100, c: 2, k_t: 5, c_t: sp.Rational(3, 10),
             g: sp.Rational(981, 100), F0: 3, omega: 4}
    assert abs(residual.xreplace(point).evalf(30)) > 1e-3, "the printed theta equation holds"


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; N, T, S recovered; printed theta equation "
          "wrong (m0 l th'' for m0 l^2 th'')")
