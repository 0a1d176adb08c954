"""Peer pipeline for pendulum_on_mass: sympy.physics.mechanics instead of dualmech.

A mass M slides in a vertical shaft on a spring k (y: its drop from the unstretched spring,
A = -(l0 + y) N.y) and carries at A a pendulum (theta from the downward vertical): a thin rod
m of length 4r and a thin disk 2m of radius r centred 5r from A (MIT 2.003J quiz 2, problem 1).
What a user of sympy.physics.mechanics writes: the pendulum frame P (theta about N.z, hanging
along -P.y), the rod and the disk as two RigidBody objects (rod: m (4r)^2/12 across, disk:
2m r^2/2 about its axis, 2m r^2/4 across); Lagrange's method with the spring and gravity as
potentials; Kane's method with three auxiliary speeds -- M sideways along N.x carrying the
pendulum (exposes the shaft force F_N, along -N.x on M) and the pendulum's pivot moving apart
from M along N.x and N.y (the pivot force F_Rx N.x + F_Ry N.y on M, its opposite on the
pendulum); the accelerations compared with LUsolve + simplify; the reactions from the
auxiliary equations against the direct form's rows (F_Rx = F_N = -12 m r (th'' cos th -
th'^2 sin th), F_Ry = M g - k y - M y''); the mass matrix's theta entry against the source's
``169/3 m r^2``.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "pendulum_on_mass"


def run() -> None:
    M, m, r, k, g, l0 = sp.symbols("M m r k g l0", positive=True)
    F_N, F_Rx, F_Ry = sp.symbols("F_N F_Rx F_Ry", real=True)
    y, th, v, w, u_s, u_x, u_y = dynamicsymbols("y theta v omega u_s u_x u_y")
    yd, thd = dynamicsymbols("y theta", 1)
    N = ReferenceFrame("N")
    P = N.orientnew("P", "Axis", (th, N.z))
    O = Point("O")

    def scene(yrate, thrate, a_s=0, a_x=0, a_y=0):
        A = O.locatenew("A", -(l0 + y) * N.y)                 # M, in the shaft
        A.set_vel(N, -yrate * N.y + a_s * N.x)
        pivot = O.locatenew("pivot", -(l0 + y) * N.y)          # the pendulum's pin
        pivot.set_vel(N, A.vel(N) + a_x * N.x + a_y * N.y)
        P.set_ang_vel(N, thrate * N.z)
        Cr = pivot.locatenew("Cr", -2 * r * P.y)
        Cr.v2pt_theory(pivot, N, P)
        Cd = pivot.locatenew("Cd", -5 * r * P.y)
        Cd.v2pt_theory(pivot, N, P)
        rod = RigidBody("rod", Cr, P, m, (inertia(P, m * (4 * r)**2 / 12, 0,
                                                    m * (4 * r)**2 / 12), Cr))
        disk = RigidBody("disk", Cd, P, 2 * m, (inertia(P, 2 * m * r**2 / 4, 2 * m * r**2 / 4,
                                                        2 * m * r**2 / 2), Cd))
        return A, pivot, Cr, Cd, rod, disk

    A, pivot, Cr, Cd, rod, disk = scene(yd, thd)
    mass = Particle("M", A, M)
    mass.potential_energy = M * g * A.pos_from(O).dot(N.y) + k * y**2 / 2
    rod.potential_energy = m * g * Cr.pos_from(O).dot(N.y)
    disk.potential_energy = 2 * m * g * Cd.pos_from(O).dot(N.y)
    lm = LagrangesMethod(Lagrangian(N, mass, rod, disk), [y, th], frame=N)
    lm.form_lagranges_equations()
    assert sp.simplify(lm.mass_matrix[1, 1] - sp.Rational(169, 3) * m * r**2) == 0
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    A, pivot, Cr, Cd, rod, disk = scene(v, w, u_s, u_x, u_y)
    pin = F_Rx * N.x + F_Ry * N.y                              # the pendulum on M
    km = KanesMethod(N, q_ind=[y, th], u_ind=[v, w], kd_eqs=[yd - v, thd - w],
                     u_auxiliary=[u_s, u_x, u_y])
    loads = [(A, (-M * g + k * y) * N.y - F_N * N.x + pin), (pivot, -pin),
             (Cr, -m * g * N.y), (Cd, -2 * m * g * N.y)]
    km.kanes_equations([Particle("M", A, M), rod, disk], loads)
    back = {v: yd, w: thd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert (acc_l - acc_k).applyfunc(sp.simplify) == sp.zeros(2, 1), "Lagrange and Kane"

    on_motion = {v.diff(): acc_l[0], w.diff(): acc_l[1]}
    aux = [e.subs(on_motion).subs(back) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [F_N, F_Rx, F_Ry], dict=True)[0]
    s, c = sp.sin(th), sp.cos(th)
    Rx = -12 * m * r * (acc_l[1] * c - thd**2 * s)
    hand = {F_Rx: Rx, F_N: Rx, F_Ry: M * g - k * y - M * acc_l[0]}
    assert all(sp.simplify(sol[f] - hand[f]) == 0 for f in hand), sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; shaft and pivot forces recovered")
