"""Peer pipeline for restrained_pendulum: sympy.physics.mechanics instead of dualmech.

A bob m on a massless link l (theta from the downward vertical), a horizontal spring k at
distance b and a horizontal dashpot c at distance a (Example 12 of source 000).  What a user of
sympy.physics.mechanics writes: Lagrange's method with gravity and the spring as potentials and
the dashpot in the force list; Kane's method with two auxiliary speeds at the pivot to expose
its reaction H i + V j; the accelerations compared with LUsolve + simplify; H, V from the
auxiliary equations.
"""
import sympy as sp
from sympy.physics.mechanics import (KanesMethod, LagrangesMethod, Lagrangian, Particle, Point,
                                     ReferenceFrame, dynamicsymbols)

PROBLEM = "restrained_pendulum"


def run() -> None:
    m, l, k, c, a, b, g = sp.symbols("m l k c a b g", positive=True)
    H, V = sp.symbols("H V", real=True)
    th, w, uh, uv = dynamicsymbols("theta omega u_h u_v")
    thd = dynamicsymbols("theta", 1)
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (th, N.z))   # A.y points from the bob to the pivot

    def scene(rate, aux_h=0, aux_v=0):
        O = Point("O")
        O.set_vel(N, aux_h * N.x + aux_v * N.y)
        A.set_ang_vel(N, rate * N.z)
        pts = [O.locatenew(n, -d * A.y) for n, d in (("S", b), ("D", a), ("B", l))]
        for p in pts:
            p.v2pt_theory(O, N, A)
        return (O, *pts)

    O, S, D, B = scene(thd)
    bob = Particle("bob", B, m)
    bob.potential_energy = m * g * l * (1 - sp.cos(th)) + k * (b * sp.sin(th))**2 / 2
    lm = LagrangesMethod(Lagrangian(N, bob), [th], frame=N,
                         forcelist=[(D, -c * D.vel(N).dot(N.x) * N.x)])
    lm.form_lagranges_equations()
    acc_l = lm.mass_matrix.LUsolve(lm.forcing)

    O, S, D, B = scene(w, uh, uv)
    km = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[thd - w], u_auxiliary=[uh, uv])
    spring = -k * S.pos_from(O).dot(N.x) * N.x
    dashpot = -c * (a * sp.cos(th) * w) * N.x        # the link's own rate, no pivot speed
    km.kanes_equations([Particle("bob", B, m)],
                       [(B, -m * g * N.y), (S, spring), (D, dashpot), (O, H * N.x + V * N.y)])
    acc_k = km.mass_matrix.LUsolve(km.forcing).subs(w, thd)
    assert sp.simplify(acc_l[0] - acc_k[0]) == 0, "Lagrange and Kane"

    thdd = dynamicsymbols("theta", 2)
    aux = [e.subs(dynamicsymbols("omega", 1), thdd).subs(w, thd) for e in km.auxiliary_eqs]
    sol = sp.solve(aux, [H, V], dict=True)[0]
    sol = {r: e.subs(thdd, acc_l[0]) for r, e in sol.items()}
    # by hand (link + bob): H = k b sin + c a th' cos + m l (th'' cos - th'^2 sin),
    # V = m g + m l (th'' sin + th'^2 cos)
    s, co = sp.sin(th), sp.cos(th)
    hand = {H: k * b * s + c * a * thd * co + m * l * (acc_l[0] * co - thd**2 * s),
            V: m * g + m * l * (acc_l[0] * s + thd**2 * co)}
    assert all(sp.simplify(sol[r] - hand[r]) == 0 for r in hand), sol


if __name__ == "__main__":
    run()
    print(f"{PROBLEM}: Lagrange and Kane agree; pivot reaction H, V recovered")
