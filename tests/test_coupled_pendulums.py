"""Two pendulums coupled by a spring (problems/coupled_pendulums.py): linear model, modes."""
import numpy as np
import pytest
import sympy as sp

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.problems.coupled_pendulums import (CoupledPendulums, d, g, geometric_spring_model, k, l, m,
                                        theta1, theta2)

_EPS = np.finfo(float).eps
problem = CoupledPendulums()


@pytest.fixture(scope="module")
def geometric():
    return geometric_spring_model()


def test_linear_equations_are_the_sources_times_l():
    # source (a): 9 m l theta1'' + (k l + 3 m g) theta1 - k l theta2 = 0 (and 1 <-> 2)
    for name in ("newton_euler", "lagrange"):
        M0, C0, K0 = problem.model(name).linearize()
        scale = 1 if name == "lagrange" else -1   # the direct form is sum tau - dH/dt = 0
        assert C0 == sp.zeros(2, 2)
        assert (scale * M0 / l).applyfunc(sp.expand) == 9 * m * l * sp.eye(2), name
        assert (scale * K0 / l).applyfunc(sp.expand) == sp.Matrix(
            [[k * l + 3 * m * g, -k * l], [-k * l, k * l + 3 * m * g]]), name


def test_hinted_horizontal_spring_is_exact_to_first_order(geometric):
    # the true spring (length |S2 - S1|, free length d) has the same linearisation, whatever d
    M_hint, _, K_hint = problem.model("newton_euler").linearize()
    M_true, _, K_true = geometric.linearize()
    assert (M_true - M_hint).applyfunc(sp.simplify) == sp.zeros(2, 2)
    assert (K_true - K_hint).applyfunc(sp.simplify) == sp.zeros(2, 2)
    assert not K_true.has(d)


def test_hint_differs_from_the_true_spring_at_large_angles(geometric):
    # an approximation, not an identity: at theta1 = 1, theta2 = -0.5 the accelerations differ
    values = problem.defaults()
    state = (0.0, (1.0, -0.5), (0.0, 0.0))
    hint = NumericModel(problem.model("newton_euler"), values).accelerations(*state)
    true = NumericModel(geometric, values).accelerations(*state)
    assert np.max(np.abs(hint - true)) > 1e-3 * np.max(np.abs(hint))


def test_natural_frequencies_and_modes_from_the_library():
    # hand: in phase (1, 1), omega^2 = g/(3 l); antiphase (1, -1), omega^2 = g/(3 l) + 2k/(9m)
    lag = problem.model("lagrange")
    found = {sp.simplify(w**2) for w in lag.natural_frequencies()}
    assert found == {g / (3 * l), sp.simplify(g / (3 * l) + 2 * k / (9 * m))}
    values = problem.defaults()
    omegas, modes = lag.natural_frequencies(values=values)
    expected = np.sqrt([values[g] / (3 * values[l]),
                        values[g] / (3 * values[l]) + 2 * values[k] / (9 * values[m])])
    # symmetric 2x2 generalised eigenproblem: errors of a few ulps of the largest eigenvalue
    tol = 16 * _EPS * expected[-1]
    assert np.max(np.abs(omegas.real - expected)) <= tol
    ratios = modes[0] / modes[1]
    assert np.max(np.abs(ratios - np.array([1.0, -1.0]))) <= 1e3 * _EPS


def test_in_phase_mode_leaves_the_spring_unstretched():
    # theta1 = theta2: the spring's extension l (sin(theta2) - sin(theta1)) vanishes, so each
    # pendulum swings as if alone: 9 m l^2 theta'' + 3 m g l sin(theta) = 0
    sol = problem.model("lagrange").accelerations_solved()
    th = sp.Symbol("th")
    a1 = sol[theta1.diff(t, 2)]
    same = a1.subs({theta2: theta1}).subs(theta1, th)
    assert sp.simplify(same + g * sp.sin(th) / (3 * l)) == 0
