"""Peer pipeline for helicopter_blade: sympy.physics.mechanics instead of dualmech.

A uniform blade (length L, mass M per unit length) hinged on the rotor axis, turning at the
prescribed rate Omega and flapping by beta; lift per unit length A (alpha0 Omega^2 x^2 - Omega
x^2 beta') across the blade.  What a user of sympy.physics.mechanics writes: the hub frame
turned by Omega t, the blade frame by -beta about the hinge axis; the lift as its resultant at
the centre of pressure; Lagrange's method with weight and lift as loads; Kane's method with
beta' as the generalised speed; the accelerations compared with simplify; the flapping
frequency of the linearised weightless, unpitched blade.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Point,
                                     ReferenceFrame, RigidBody, dynamicsymbols, inertia)

PROBLEM = "helicopter_blade"


def run() -> None:
    M, L, Om, A, g = sp.symbols("M L Omega A g", positive=True)
    a0 = sp.Symbol("alpha0", real=True)
    x = sp.Symbol("x", positive=True)
    t = dynamicsymbols._t
    beta, u = dynamicsymbols("beta u")
    bd = beta.diff()
    N = ReferenceFrame("N")
    H = N.orientnew("H", "Axis", (Om * t, N.z))
    b = H.orientnew("b", "Axis", (-beta, H.y))
    O = Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", L / 2 * b.x)
    G.v2pt_theory(O, N, b)
    w = A * (a0 * Om**2 * x**2 - Om * x**2 * bd)
    F = sp.integrate(w, (x, 0, L))
    cp = O.locatenew("cp", sp.cancel(sp.integrate(x * w, (x, 0, L)) / F) * b.x)
    cp.v2pt_theory(O, N, b)
    blade = RigidBody("blade", G, b, M * L, (inertia(b, 0, M * L**3 / 12, M * L**3 / 12), G))
    loads = [(G, -M * L * g * N.z), (cp, F * b.z)]
    lm = LagrangesMethod(Lagrangian(N, blade), [beta], forcelist=loads, frame=N)
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)[0]

    km = KanesMethod(N, q_ind=[beta], u_ind=[u], kd_eqs=[bd - u])
    km.kanes_equations([blade], [(G, -M * L * g * N.z), (cp, F.subs(bd, u) * b.z)])
    acc_k = km.mass_matrix.LUsolve(km.forcing)[0].subs(u, bd)
    assert sp.simplify(acc_l - acc_k) == 0, "Lagrange and Kane"

    # small flapping, no pitch, weight neglected: beta'' + c beta' + Omega^2 beta = 0
    lin = acc_l.subs({g: 0, a0: 0})
    b0, b1 = sp.symbols("b0 b1")
    lin = lin.subs(bd, b1).subs(beta, b0)
    stiffness = -sp.diff(lin, b0).subs({b0: 0, b1: 0})
    assert sp.simplify(stiffness - Om**2) == 0


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; flapping frequency = rotor speed")
