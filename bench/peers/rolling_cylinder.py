"""Peer pipeline for rolling_cylinder: sympy.physics.mechanics instead of dualmech.

A uniform cylinder (M, R) rolls without slip along I with a point mass m fixed at r from its
axis: ``O r_C = -R theta I + R J``, ``O r_P = O r_C + r (sin th I - cos th J)``.  What a user of
sympy.physics.mechanics writes: Lagrange's method with the rolling built into the velocities;
Kane's method with two auxiliary speeds of the whole body (along I and J) to expose the
friction F and normal force N at the contact; the accelerations compared with LUsolve +
simplify; F and N from the auxiliary equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "rolling_cylinder"


def run() -> None:
    M, m, R, r, g = sp.symbols("M m R r g", positive=True)
    F, Nn = sp.symbols("F N", real=True)
    th, w, u1, u2 = dynamicsymbols("theta omega u1 u2")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (th, N.z))
    O = Point("O")

    def bodies(rate, aux=0 * N.x):
        B.set_ang_vel(N, rate * N.z)
        C = O.locatenew("C", -R * th * N.x + R * N.y)
        C.set_vel(N, -R * rate * N.x + aux)
        P = C.locatenew("P", -r * B.y)
        P.v2pt_theory(C, N, B)
        Q = C.locatenew("Q", -R * N.y)
        Q.v2pt_theory(C, N, B)
        cyl = RigidBody("cylinder", C, B, M, (inertia(B, 0, 0, M * R**2 / 2), C))
        return cyl, Particle("m", P, m), C, P, Q

    # Lagrange: the mass's height is the only potential (the cylinder's is constant)
    cyl, pm, C, P, Q = bodies(thd)
    pm.potential_energy = m * g * P.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, cyl, pm), [th], frame=N)
    lm.form_lagranges_equations()
    acc_l = sp.simplify(lm.mass_matrix.LUsolve(lm.forcing)[0])

    # Kane, with auxiliary speeds u1 I + u2 J of the whole body and the contact forces at Q
    cyl, pm, C, P, Q = bodies(w, u1 * N.x + u2 * N.y)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[u1, u2])
    km.kanes_equations([cyl, pm], [(C, -M * g * N.y), (P, -m * g * N.y),
                                   (Q, F * N.x + Nn * N.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(w, thd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    wd = dynamicsymbols("omega", 1)
    aux = [e.subs({wd: acc_l, w: thd}) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [F, Nn], dict=True)[0]
    # by hand: F = -(M + m) R th'' + m r (th'' cos - th'^2 sin),
    #          N = (M + m) g + m r (th'' sin + th'^2 cos)
    hand_F = -(M + m) * R * acc_l + m * r * (acc_l * sp.cos(th) - thd**2 * sp.sin(th))
    hand_N = (M + m) * g + m * r * (acc_l * sp.sin(th) + thd**2 * sp.cos(th))
    assert sp.simplify(sol[F] - hand_F) == 0 and sp.simplify(sol[Nn] - hand_N) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; friction and normal force recovered")
