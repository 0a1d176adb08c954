"""Simple pendulum (problems/simple_pendulum.py): four derivations, the string's tension twice."""
import pytest
import sympy as sp

from dualmech import t
from dualmech.verify.check import compare_models, reaction_pairs
from dualmech.problems.simple_pendulum import M, SimplePendulum, a, g, hand_tension, theta

problem = SimplePendulum()
D = lambda q: q.diff(t)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("simple_pendulum")


def test_tension_from_both_derivations_is_the_hand_one(comparison):
    # hand (module docstring): T = M (g cos theta + a theta'^2), from the free-body diagram
    # and from the multiplier of a - r = 0
    assert sp.simplify(comparison.reactions["T"] - hand_tension()) == 0
    assert comparison.reaction_derivations == {"T": ["newton_euler", "multiplier"]}
    mult = problem.in_reference_coordinates(problem.model("multiplier"))
    (T_mult,) = mult.reactions_solved().values()
    assert sp.simplify(T_mult - hand_tension()) == 0


def test_tension_at_hand_checked_states(comparison):
    T = comparison.reactions["T"]
    # hanging at rest: the weight; passing the bottom at speed v = a theta': M g + M v^2 / a
    assert sp.simplify(T.subs(D(theta), 0).subs(theta, 0) - M * g) == 0
    w = sp.Symbol("w", positive=True)
    assert sp.simplify(T.subs(D(theta), w).subs(theta, 0) - (M * g + M * (a * w)**2 / a)) == 0
    # horizontal string at rest: gravity has no component along it
    assert sp.simplify(T.subs(D(theta), 0).subs(theta, sp.pi / 2)) == 0


def test_doubling_the_mass_in_the_free_body_diagram_only_shows_in_the_tension():
    # M scales out of the motion (theta'' = -g sin(theta)/a), so only the reaction pair sees it
    models = dict(problem.models())
    models["newton_euler"] = models["newton_euler"].substitute({M: 2 * M})
    assert compare_models(problem.model("lagrange"), models["newton_euler"],
                          explain=False).equivalent
    (pair,) = reaction_pairs(problem, models)
    assert not pair.equivalent


def test_small_oscillations_have_omega_squared_g_over_a():
    for name in ("lagrange", "angular_momentum"):
        (omega,) = problem.model(name).natural_frequencies()
        assert sp.simplify(omega - sp.sqrt(g / a)) == 0, name
