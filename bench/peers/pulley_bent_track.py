"""Peer pipeline for pulley_bent_track: sympy.physics.mechanics instead of dualmech.

M1 on the horizontal track (spring k, dashpot c to the wall), the string over a uniform pulley
(m, r) to M2 on the incline ``e = cos(th0) I - sin(th0) J``, ``F(t) = F0 cos(omega t)`` on M2.
What a user of sympy.physics.mechanics writes: Lagrange's method in x with the string's
kinematics built in; Kane's method with auxiliary speeds to expose the string tensions T1, T2
(M1 alone along I; M2 alone along e); the accelerations compared with LUsolve + simplify; the
tensions from the auxiliary equations.  (The source asks for no reaction; the tensions are the
ones the free bodies carry.)
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "pulley_bent_track"


def run() -> None:
    M1, M2, m, k, c, r, g, F0, w, th0 = sp.symbols("M1 M2 m k c r g F0 omega theta0",
                                                   positive=True)
    T1, T2 = sp.symbols("T1 T2", real=True)
    x, u, a1, a2 = dynamicsymbols("x u a1 a2")
    xd = dynamicsymbols("x", 1)
    F = F0 * sp.cos(w * dynamicsymbols._t)
    N = ReferenceFrame("N")
    e = sp.cos(th0) * N.x - sp.sin(th0) * N.y
    n = sp.sin(th0) * N.x + sp.cos(th0) * N.y
    O = Point("O")

    def bodies(rate, aux1=0, aux2=0):
        P = N.orientnew("P", "Axis", (-x / r, N.z))
        P.set_ang_vel(N, -rate / r * N.z)
        C = O.locatenew("C", 0 * N.x)
        C.set_vel(N, 0)
        A1 = C.locatenew("A1", r * N.y)          # where the string leaves towards M1
        A2 = C.locatenew("A2", r * n)            # where it leaves along e towards M2
        for A in (A1, A2):
            A.v2pt_theory(C, N, P)
        p1, p2 = O.locatenew("M1", x * N.x), O.locatenew("M2", x * e)
        p1.set_vel(N, rate * N.x + aux1 * N.x)
        p2.set_vel(N, rate * e + aux2 * e)
        pulley = RigidBody("pulley", C, P, m, (inertia(P, 0, 0, m * r**2 / 2), C))
        return Particle("M1", p1, M1), Particle("M2", p2, M2), pulley, p1, p2, A1, A2

    # Lagrange: spring and gravity as potentials, dashpot and F(t) as forces
    b1, b2, pul, p1, p2, A1, A2 = bodies(xd)
    b1.potential_energy = k * x**2 / 2
    b2.potential_energy = M2 * g * p2.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, b1, b2, pul), [x], frame=N,
                         forcelist=[(p1, -c * xd * N.x), (p2, F * N.x)])
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    # Kane: the string as two unknown tensions on the masses and the pulley's rim
    b1, b2, pul, p1, p2, A1, A2 = bodies(u, a1, a2)
    km = KanesMethod(N, q_ind=[x], u_ind=[u], kd_eqs=[xd - u], u_auxiliary=[a1, a2])
    km.kanes_equations([b1, b2, pul],
                       [(p1, (-k * x - c * u + T1) * N.x - M1 * g * N.y),
                        (p2, F * N.x - M2 * g * N.y - T2 * e),
                        (A1, -T1 * N.x), (A2, T2 * e)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(u, xd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    ud = dynamicsymbols("u", 1)
    aux = [eq.subs({ud: acc_l, u: xd}) for eq in km.auxiliary_eqs]
    sol = sp.solve(aux, [T1, T2], dict=True)[0]
    # by hand: T1 = M1 x'' + c x' + k x, T2 = T1 + m x''/2
    hand_T1 = M1 * acc_l + c * xd + k * x
    assert sp.simplify(sol[T1] - hand_T1) == 0
    assert sp.simplify(sol[T2] - hand_T1 - m * acc_l / 2) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; string tensions recovered")
