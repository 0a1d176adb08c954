"""Peer pipeline for pendulum_on_rotating_plane: sympy.physics.mechanics instead of dualmech.

A mass m on a rod l in a plane turned about the horizontal Y axis by the prescribed
beta(t) = beta0 + Omega t + alpha t^2, pivot c from the axis (source 004, question 1).  What a
user of sympy.physics.mechanics writes: Lagrange's method in theta with the plane's motion as
a known function of time; Kane's method with auxiliary speeds along the plane's normal and the
rod to expose the normal force N and the rod force S; the accelerations compared with LUsolve
+ simplify; N from the auxiliary equations against the source's lambda_B.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "pendulum_on_rotating_plane"


def run() -> None:
    m, l, c, g = sp.symbols("m l c g", positive=True)
    beta0, Omega, alpha = sp.symbols("beta0 Omega alpha", real=True)
    N_, S = sp.symbols("N S", real=True)
    t = dynamicsymbols._t
    beta = beta0 + Omega * t + alpha * t**2
    th, w, un, ur = dynamicsymbols("theta omega u_n u_r")
    thd = dynamicsymbols("theta", 1)
    O = ReferenceFrame("O")                               # O.z up, gravity -g O.z
    P = O.orientnew("P", "Axis", (beta, O.y))             # the plane; P.z its normal
    R = P.orientnew("R", "Axis", (th, P.z))               # R.x along the rod, pivot -> mass
    o = Point("o")
    o.set_vel(O, 0)

    def mass(rate, aux_n=0, aux_r=0):
        R.set_ang_vel(P, rate * P.z)
        q = o.locatenew("q", -c * P.x + l * R.x)
        q.set_vel(O, q.pos_from(o).dt(O) + aux_n * P.z + aux_r * R.x)
        return q

    q = mass(thd)
    p = Particle("mass", q, m)
    p.potential_energy = m * g * q.pos_from(o).dot(O.z)
    lm = LagrangesMethod(Lagrangian(O, p), [th], frame=O)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    q = mass(w, un, ur)
    km = KanesMethod(O, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[un, ur])
    km.kanes_equations([Particle("mass", q, m)],
                       [(q, -m * g * O.z + N_ * P.z - S * R.x)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    thdd = dynamicsymbols("theta", 2)
    aux = [e.subs(w.diff(), thdd).subs(w, thd) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [N_, S], dict=True)[0]
    lever = c - l * sp.cos(th)
    lam_B = (m * beta.diff(t, 2) * lever + 2 * m * beta.diff(t) * l * sp.sin(th) * thd
             + m * g * sp.cos(beta))
    assert sp.simplify(sol[N_].subs(thdd, acc_l) - lam_B) == 0, sol[N_]


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; N is the source's lambda_B")
