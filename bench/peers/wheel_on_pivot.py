"""Peer pipeline for wheel_on_pivot: sympy.physics.mechanics instead of dualmech.

A thin wheel (m, a) on a massless axle l pivoted at O, rolling round O on a horizontal plane
(source 004, question 2), with a drive torque tau K on the axle (tau = 0: the source's steady
motion).  What a user of sympy.physics.mechanics writes: Lagrange's method in the precession
angle phi (rolling built in: spin psi = -(l/a) phi); Kane's method with two
auxiliary speeds -- a spin of the wheel about its axle (moves the contact point along j) and a
tilt of the axle (raises G) -- to expose the contact force F_y j + F_z k (no radial friction,
as in the problem); the accelerations compared with LUsolve + simplify; F from the auxiliary
equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "wheel_on_pivot"


def run() -> None:
    m, a, l, g = sp.symbols("m a l g", positive=True)
    tau = sp.Symbol("tau", real=True)
    F_y, F_z = sp.symbols("F_y F_z", real=True)
    ph, w, us, ue = dynamicsymbols("phi omega u_s u_e")
    phd, phdd = dynamicsymbols("phi", 1), dynamicsymbols("phi", 2)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (ph, N.z))
    W = A.orientnew("W", "Axis", (-l / a * ph, A.x))
    o = Point("o")
    o.set_vel(N, 0)

    def wheel(rate, spin=0, tilt=0):
        A.set_ang_vel(N, rate * N.z)
        W.set_ang_vel(N, rate * A.z + (-l / a * rate + spin) * A.x - tilt * A.y)
        G = o.locatenew("G", l * A.x)
        G.set_vel(N, l * rate * A.y + l * tilt * A.z)
        C = G.locatenew("C", -a * A.z)
        C.v2pt_theory(G, N, W)
        body = RigidBody("wheel", G, W, m, (inertia(W, m * a**2 / 2, m * a**2 / 4,
                                                     m * a**2 / 4), G))
        return G, C, body

    G, C, body = wheel(phd)
    body.potential_energy = 0                      # G keeps its height
    lm = LagrangesMethod(Lagrangian(N, body), [ph], forcelist=[(W, tau * N.z)], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]
    J = 3 * m * l**2 / 2 + m * a**2 / 4
    assert sp.simplify(acc_l - tau / J) == 0, acc_l   # steady (phi'' = 0) iff tau = 0

    G, C, body = wheel(w, us, ue)
    km = KanesMethod(N, q_ind=[ph], u_ind=[w], kd_eqs=[phd - w], u_auxiliary=[us, ue])
    km.kanes_equations([body], [(G, -m * g * N.z), (C, F_y * A.y + F_z * A.z),
                                (W, tau * N.z)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, phd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    aux = [e.subs(w.diff(), phdd).subs(w, phd).subs(phdd, acc_l) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [F_y, F_z], dict=True)[0]
    assert sp.simplify(sol[F_y] + m * l * acc_l / 2) == 0, sol
    assert sp.simplify(sol[F_z] - m * g - m * a * phd**2 / 2) == 0, sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; phi'' = tau/J, F_y = -m l phi''/2, "
          "F_z = m g + m a phi'^2/2")
