"""Spring-mass-damper of Example 11 (problems/spring_mass_damper.py)."""
import pytest
import sympy as sp

from dualmech import t
from dualmech.verify.check import compare_models
from dualmech.problems.spring_mass_damper import (F0, Omega, SpringMassDamper, b, forcing, k, m,
                                         steady_state, x)

problem = SpringMassDamper()


def test_linearisation_is_the_printed_coefficients():
    # m x'' + b x' + k x = f(t): M = m, C = b, K = k, read off by the library about the
    # unforced equilibrium x = 0 (with the drive on, x = 0 is no equilibrium)
    free = problem.model("lagrange").substitute({F0: 0})
    M, C, K = free.linearize()
    assert (M, C, K) == (sp.Matrix([[m]]), sp.Matrix([[b]]), sp.Matrix([[k]]))
    (w,) = free.natural_frequencies()
    assert sp.simplify(w - sp.sqrt(k / m)) == 0


@pytest.mark.parametrize("model", ["newton_euler", "lagrange"])
def test_hand_derived_steady_state_solves_each_model(model):
    # x_p = F0 ((k - m W^2) cos Wt + b W sin Wt) / ((k - m W^2)^2 + (b W)^2), by hand
    (eq,) = problem.model(model).equations
    residual = eq.subs(x, steady_state()).doit()
    assert sp.simplify(residual) == 0


def test_steady_state_amplitude_at_resonance_is_F0_over_b_Omega():
    # at Omega^2 = k/m the response is in quadrature with the force: amplitude F0/(b Omega)
    xp = steady_state().subs(k, m * Omega**2)
    assert sp.simplify(xp - F0 / (b * Omega) * sp.sin(Omega * t)) == 0


def test_comparator_catches_a_dashpot_of_the_wrong_sign():
    broken = problem.model("newton_euler").flipped("dashpot")
    result = compare_models(problem.model("lagrange"), broken, explain=False)
    assert not result.equivalent and result.method == "exact"


def test_forcing_is_a_function_of_time_only():
    assert forcing().free_symbols == {F0, Omega, t}
