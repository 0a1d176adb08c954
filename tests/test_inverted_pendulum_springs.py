"""Inverted pendulum with springs (problems/inverted_pendulum_springs.py): stability, derived."""
import pytest
import sympy as sp

from dualmech import t
from dualmech.problems.inverted_pendulum_springs import InvertedPendulumSprings, a, g, k, l, m, theta

problem = InvertedPendulumSprings()
D = lambda q: q.diff(t)  # noqa: E731


def test_upright_position_is_among_the_equilibria_the_library_finds():
    found = problem.model("lagrange").equilibria()
    assert any(sp.simplify(e[theta]) == 0 for e in found)
    # hand: sin(th) (2 k a^2 cos(th) - m g l) = 0 also gives the tilted pair cos = m g l/(2 k a^2)
    tilted = [e[theta] for e in found if sp.simplify(sp.sin(e[theta])) != 0]
    assert tilted and all(sp.simplify(sp.cos(th) - m * g * l / (2 * k * a**2)) == 0
                          for th in tilted)


def test_stability_condition_derived_by_the_library_is_the_sources():
    M, C, K = problem.model("lagrange").linearize({theta: 0})
    assert C == sp.zeros(1, 1) and M == sp.Matrix([[m * l**2]])
    # stable: M > 0 and K > 0 (the eigenvalues +-sqrt(-K/M) imaginary, V at a strict minimum)
    derived = sp.solve_univariate_inequality(K[0, 0] > 0, k, relational=False)
    printed = sp.solve_univariate_inequality(k > m * g * l / (2 * a**2), k, relational=False)
    assert derived == printed
    # K is the curvature of V at the upright position (Lagrange-Dirichlet)
    V = k * a**2 * sp.sin(theta)**2 + m * g * l * sp.cos(theta)
    assert sp.simplify(V.diff(theta, 2).subs(theta, 0) - K[0, 0]) == 0


@pytest.mark.parametrize("factor, stable", [(1.05, True), (0.95, False)], ids=["above", "below"])
def test_natural_frequency_is_real_only_above_the_critical_stiffness(factor, stable):
    values = {m: 1.0, l: 1.0, a: 0.6, g: 9.81}
    values[k] = factor * 9.81 / (2 * 0.6**2)
    (w,), _ = problem.model("lagrange").natural_frequencies({theta: 0}, values)
    # stable: omega real (omega^2 > 0); unstable: omega imaginary (a real exponent).  The
    # library returns sqrt(omega^2 + 0j), so the other part is exactly zero
    assert bool(w.imag == 0 and w.real > 0) is stable
    assert bool(w.real == 0 and w.imag > 0) is (not stable)


def test_hinge_carries_the_weight_in_the_upright_position():
    R = {u.name: v for u, v in problem.model("newton_euler").reactions_solved().items()}
    up = {D(theta): 0}
    assert sp.simplify(R["R_y"].subs(up).subs(theta, 0) - m * g) == 0
    assert sp.simplify(R["R_x"].subs(up).subs(theta, 0)) == 0
