"""Pendulum as a particle (problems/pendulum_particle.py): DAE index, rod force, errata."""
import numpy as np
import pytest
import sympy as sp

from dualmech import t
from dualmech.numeric import reactions_at
from dualmech.problems.pendulum_particle import PendulumParticle, S, g, hand_rod_force, l, m, theta, x, y

problem = PendulumParticle()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("pendulum_particle")


def test_cartesian_model_is_an_index_three_dae():
    # hand: the constraint holds no S; nor does its 1st derivative; its 2nd derivative with
    # x'', y'' of the two Lagrange equations put in is linear in S with a nonzero factor, so
    # S follows algebraically after 2 differentiations and S' after 3: index 3
    dae = problem.model("cartesian")
    assert len(dae.equations) == 3 and dae.unknowns == (S,)
    g_pos = (l**2 - x**2 - y**2) / (2 * l)
    assert not g_pos.has(S) and not g_pos.diff(t).has(S)
    acc = sp.solve(dae.equations[:2], [DD(x), DD(y)], dict=True)[0]
    level2 = sp.expand(dae.equations[2].xreplace(acc))
    factor = level2.coeff(S)
    # -(x x'' + y y'' + ...)/l with x'' = -S x/(m l), y'' = g - S y/(m l)
    assert sp.simplify(factor - (x**2 + y**2) / (m * l**2)) == 0
    (S_alg,) = sp.solve(level2, S)
    # the source's result of "Differential index II"
    assert sp.simplify(S_alg - m * l * (D(x)**2 + D(y)**2 + g * y) / (x**2 + y**2)) == 0


def test_map_satisfies_the_rod_length_and_drops_the_constraint_row():
    mapped = problem.in_reference_coordinates(problem.model("cartesian"))
    assert mapped.coordinates == (theta,) and len(mapped.equations) == 2
    assert mapped.is_square
    assert "constraint S (acceleration level)" not in mapped.labels


def test_all_three_direct_and_multiplier_forms_give_the_hand_rod_force(comparison):
    # S = m (g cos(theta) + l theta'^2): b2 balance of the body form, by hand
    assert sp.simplify(comparison.reactions["S"] - hand_rod_force()) == 0
    assert comparison.reaction_derivations == {
        "S": ["newton_euler", "newton_euler_inertial", "cartesian"]}


def test_rod_force_at_a_state():
    # theta = 0.7, theta' = -1.3 with the defaults m = 1, l = 1, g = 9.81:
    # S = 9.81 cos(0.7) + 1.69 = 9.19328... (hand, module docstring)
    got = reactions_at(problem, [0.7], [-1.3])["S"]
    hand = 9.81 * np.cos(0.7) + 1.69
    assert abs(got - hand) <= 64 * np.finfo(float).eps * hand


def test_printed_x_acceleration_has_the_cos_term_with_the_wrong_sign():
    pub = next(p for p in problem.published() if p.label == "x''")
    true = DD(l * sp.sin(theta))
    assert sp.simplify(pub.printed[0] - true + 2 * l * sp.cos(theta) * DD(theta)) == 0


def test_comparator_says_the_body_acceleration_and_dL_dtheta_slip_a_dimension(comparison):
    detail = {v.label: v.detail for v in comparison.published}
    assert "dimensionally inconsistent" in detail["acceleration, body"]
    assert "dimensionally inconsistent" in detail["dL/dtheta'"]
