"""Peer pipeline for falling_container: sympy.physics.mechanics instead of dualmech.

A container m1 (floor at height x1) with a mass m2 inside (height x2) on a spring k (free
length l0) and a dashpot c in parallel, falling under gravity (source 000, Example 15).  What
a user of sympy.physics.mechanics writes: Lagrange's method in the heights (x1, x2) with the
spring and gravity as potentials and the dashpot's pair of forces in the force list; again in
the source's second choice (y1 = x1, y2 = x2 - x1 - l0); Kane's method in (x1, x2) with two
auxiliary speeds -- the container sideways along N.x, carrying m2 (exposes the guide force H1),
and m2 sideways relative to the container (exposes the wall force H2, -H2 on the container);
the accelerations compared with LUsolve + simplify, the (y1, y2) ones mapped back
(x1'' = y1'', x2'' = y1'' + y2''); H1 = H2 = 0 from the auxiliary equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "falling_container"


def run() -> None:
    m1, m2, k, c, l0, g = sp.symbols("m1 m2 k c l0 g", positive=True)
    H1, H2 = sp.symbols("H1 H2", real=True)
    x1, x2, y1, y2, u1, u2, ua1, ua2 = dynamicsymbols("x1 x2 y1 y2 u1 u2 u_a1 u_a2")
    x1d, x2d, y1d, y2d = dynamicsymbols("x1 x2 y1 y2", 1)
    t = dynamicsymbols._t
    N = ReferenceFrame("N")
    O = Point("O")

    def lagrange(floor, inner, coords):
        """Lagrange's method with the floor at height ``floor`` and m2 at ``inner``."""
        C = O.locatenew("C", floor * N.y)
        C.set_vel(N, floor.diff(t) * N.y)
        B = O.locatenew("B", inner * N.y)
        B.set_vel(N, inner.diff(t) * N.y)
        box, mass2 = Particle("container", C, m1), Particle("m2", B, m2)
        box.potential_energy = m1 * g * floor + k * (inner - floor - l0)**2 / 2
        mass2.potential_energy = m2 * g * inner
        rate = (inner - floor).diff(t)
        lm = LagrangesMethod(Lagrangian(N, box, mass2), coords,
                             forcelist=[(B, -c * rate * N.y), (C, c * rate * N.y)], frame=N)
        lm.form_lagranges_equations()
        return lm.mass_matrix.LUsolve(lm.forcing)

    acc_x = lagrange(x1, x2, [x1, x2])
    acc_y = lagrange(y1, y1 + y2 + l0, [y1, y2])
    to_x = {y1d: x1d, y2d: x2d - x1d, y1: x1, y2: x2 - x1 - l0}
    mapped = sp.Matrix([acc_y[0], acc_y[0] + acc_y[1]]).subs(to_x)
    assert (mapped - acc_x).applyfunc(sp.simplify) == sp.zeros(2, 1), "x and y choices"

    C = O.locatenew("C", x1 * N.y)
    C.set_vel(N, u1 * N.y + ua1 * N.x)
    B = O.locatenew("B", x2 * N.y)
    B.set_vel(N, u2 * N.y + (ua1 + ua2) * N.x)
    spring = k * (x2 - x1 - l0) + c * (u2 - u1)      # tension: pulls m2 down, m1 up
    km = KanesMethod(N, q_ind=[x1, x2], u_ind=[u1, u2], kd_eqs=[x1d - u1, x2d - u2],
                     u_auxiliary=[ua1, ua2])
    loads = [(C, (-m1 * g + spring) * N.y + (H1 - H2) * N.x),
             (B, (-m2 * g - spring) * N.y + H2 * N.x)]
    km.kanes_equations([Particle("container", C, m1), Particle("m2", B, m2)], loads)
    back = {u1: x1d, u2: x2d}
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(back)
    assert (acc_x - acc_k).applyfunc(sp.simplify) == sp.zeros(2, 1), "Lagrange and Kane"

    on_motion = {u1.diff(): acc_x[0], u2.diff(): acc_x[1]}
    aux = [e.subs(on_motion).subs(back) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [H1, H2], dict=True)[0]
    assert sp.simplify(sol[H1]) == 0 and sp.simplify(sol[H2]) == 0, sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange (x and y) and Kane agree; guide forces H1 = H2 = 0")
