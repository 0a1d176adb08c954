"""Peer pipeline for toy_car: sympy.physics.mechanics instead of dualmech.

What a user of sympy.physics.mechanics writes for the toy car on the rotating track: frames A
(track, phi about I) and B (car, theta about j_A), the car at -R k_B; Lagrange's method with
gravity as a potential; Kane's method with an auxiliary speed along k_B to expose the track
force F_r; the accelerations compared with LUsolve + simplify; F_r from the auxiliary equation.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "toy_car"


def run() -> None:
    m, R, g = sp.symbols("m R g", positive=True)
    F_r = sp.Symbol("F_r", real=True)
    th, ph = dynamicsymbols("theta phi")
    thd, phd = dynamicsymbols("theta phi", 1)
    u1, u2, ua = dynamicsymbols("u1 u2 u_aux")
    O = ReferenceFrame("O")
    A = O.orientnew("A", "Axis", (ph, O.x))
    B = A.orientnew("B", "Axis", (th, A.y))
    o = Point("o")
    o.set_vel(O, 0)
    car = o.locatenew("car", -R * B.z)
    car.v2pt_theory(o, O, B)
    p = Particle("car", car, m)
    p.potential_energy = m * g * car.pos_from(o).dot(O.z)
    lm = LagrangesMethod(Lagrangian(O, p), [th, ph], frame=O)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    A.set_ang_vel(O, u2 * O.x)
    B.set_ang_vel(A, u1 * A.y)
    car.set_vel(O, car.pos_from(o).dt(B) + B.ang_vel_in(O).cross(car.pos_from(o))
                - ua * B.z)
    km = KanesMethod(O, q_ind=[th, ph], u_ind=[u1, u2], kd_eqs=[thd - u1, phd - u2],
                     u_auxiliary=[ua])
    km.kanes_equations([Particle("car", car, m)], [(car, -m * g * O.z + F_r * B.z)])
    rules = {u1: thd, u2: phd}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(rules)
    diff = (acc_l - acc_k).applyfunc(sp.simplify)
    assert diff == sp.zeros(2, 1), "Lagrange and Kane disagree"
    aux = [e.subs(rules) for e in km.auxiliary_eqs]
    F = sp.solve(aux, F_r, dict=True)[0][F_r]
    expected = m * (g * sp.cos(ph) * sp.cos(th) + R * phd**2 * sp.cos(th)**2 + R * thd**2)
    assert sp.simplify(F - expected) == 0, F


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; F_r = m (g cos(phi) cos(theta) "
          "+ R phi'^2 cos^2(theta) + R theta'^2)")
