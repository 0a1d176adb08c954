"""Two masses on a taut string (problems/taut_string_masses.py): the small-vibration model."""
import numpy as np
import sympy as sp

from dualmech import t
from dualmech.problems.taut_string_masses import (P, TautStringMasses, a, exact_geometry, m,
                                         string_pulls, x1, x2)

problem = TautStringMasses()
_EPS = np.finfo(float).eps
D = lambda q: q.diff(t)  # noqa: E731


def test_pulls_along_the_string_cancel_on_each_mass():
    # with every segment's length taken as a, the i components are -P + P on each mass: the
    # masses need no guide to stay on their transverse lines (to this order)
    totals: dict = {}
    for _, mass, force in string_pulls():
        totals[mass.name] = totals.get(mass.name, 0) + force.dot(force.frame.x)
    assert {k: sp.simplify(v) for k, v in totals.items()} == {"mass 1": 0, "mass 2": 0}


def test_exact_geometry_linearises_to_the_printed_matrices():
    # V = P (L - 3a) with the exact lengths: the library's linearisation about x = 0 is the
    # source's M and K, so the small-slope expansion is exact to that order
    M, C, K = exact_geometry().linearize()
    assert M == m * sp.eye(2) and C == sp.zeros(2, 2)
    assert K == sp.Matrix([[2 * P / a, -P / a], [-P / a, 2 * P / a]])


def test_small_slope_expansion_errs_at_third_order_in_the_forces():
    # sqrt(a^2 + d^2) = a + d^2/(2a) - d^4/(8a^3) + O(d^6), so
    # V_exact - V_source = -P (x1^4 + (x2 - x1)^4 + x2^4) / (8 a^3) + O(x^6), and the x1
    # force terms differ by d/dx1 of that: -P (x1^3 - (x2 - x1)^3) / (2 a^3)
    eps = sp.Symbol("epsilon")
    small = {x1: eps * x1, x2: eps * x2}
    dV_exact = exact_geometry().contributions[0]["string"]   # dV/dx1, exact lengths
    dV_quad = problem.model("lagrange").contributions[0]["string"]
    gap = sp.series((dV_exact - dV_quad).xreplace(small), eps, 0, 5).removeO()
    hand = -P / (2 * a**3) * (x1**3 - (x2 - x1)**3) * eps**3
    assert sp.simplify(gap - hand) == 0


def test_library_frequencies_are_the_printed_ones():
    # printed: w^2 = P/(a m) (x1 = x2) and 3P/(a m) (x1 = -x2)
    got = problem.model("lagrange").natural_frequencies()
    assert {sp.simplify(w**2) for w in got} == {P / (a * m), 3 * P / (a * m)}
    values = problem.defaults()
    omegas, modes = problem.model("newton_euler").natural_frequencies(values=values)
    base = values[P] / (values[a] * values[m])
    hand = np.sqrt([base, 3 * base])
    tol = 64 * _EPS * 3 * hand[-1]   # cond(M^-1 K) = 3
    assert np.allclose(np.real(omegas), hand, rtol=0, atol=tol)
    ratios = modes[1] / modes[0]
    assert np.allclose(ratios, [1.0, -1.0], rtol=0, atol=64 * _EPS * 3)
