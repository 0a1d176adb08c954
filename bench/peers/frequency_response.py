"""Peer pipeline for frequency_response: sympy.physics.mechanics instead of dualmech.

The block of ``m x'' + c x' + k x = F0 cos(omega t)``.  What a user of
sympy.physics.mechanics writes: Lagrange's method (spring as a potential, dashpot and drive
as forces) and Kane's method (all as forces); the accelerations compared with LUsolve +
simplify; then the steady-state amplitude from the linear coefficients.  No reaction is asked.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "frequency_response"


def run() -> None:
    m, c, k, F0, w = sp.symbols("m c k F0 omega", positive=True)
    x, u = dynamicsymbols("x u")
    xd = dynamicsymbols("x", 1)
    F = F0 * sp.cos(w * dynamicsymbols._t)
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)

    def block(rate):
        P = O.locatenew("P", x * N.x)
        P.set_vel(N, rate * N.x)
        return Particle("block", P, m), P

    b, P = block(xd)
    b.potential_energy = k * x**2 / 2
    lm = LagrangesMethod(Lagrangian(N, b), [x], forcelist=[(P, (-c * xd + F) * N.x)], frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    b, P = block(u)
    km = KanesMethod(N, q_ind=[x], u_ind=[u], kd_eqs=[xd - u])
    km.kanes_equations([b], [(P, (-k * x - c * u + F) * N.x)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(u, xd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane disagree"

    # amplitude |X| = F0/|k - m w^2 + i c w|: the source's readings X(0) = 3, X(4) = 4
    K0 = -sp.diff(lm.forcing[0], x)
    C0 = -sp.diff(lm.forcing[0], xd)
    M0 = lm.mass_matrix[0]
    amp = F0 / sp.sqrt((K0 - M0 * w**2)**2 + (C0 * w)**2)
    values = {k: 3, m: sp.Rational(3, 16), c: sp.Rational(9, 16), F0: 9}
    assert amp.subs(values).subs(w, 0) == 3 and amp.subs(values).subs(w, 4) == 4


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; amplitudes 3 m at 0 and 4 m at 4 rad/s")
