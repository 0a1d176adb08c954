"""Pendulum on a rotating plane (problems/pendulum_on_rotating_plane.py): the normal force."""
import random

import pytest
import sympy as sp

from dualmech import t
from dualmech.model.dimensions import audit
from dualmech.model.equations import to_plain
from dualmech.exact.form import ExactForm
from dualmech.problems.pendulum_on_rotating_plane import (N, Omega, PendulumOnRotatingPlane, alpha, beta0,
                                                 c, g, hand_rod_force, l, m, plane_angle, theta)

problem = PendulumOnRotatingPlane()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
S = sp.Symbol("S", real=True)


def _identically_zero(expr) -> bool:
    """Exact rational-point test (dualmech.exact.form) at 4 random points."""
    plain = to_plain(expr, (theta,))
    form = ExactForm.build([plain], sorted(plain.free_symbols, key=str))
    assert form.method == "exact"
    rng = random.Random(11)
    return all(form.evaluate(form.sample(rng)) == [0] for _ in range(4))


@pytest.fixture
def comparison(compared):
    return compared("pendulum_on_rotating_plane")


def test_theta_is_the_only_free_coordinate_of_every_model():
    # beta is prescribed: theta is the only free coordinate of every model once mapped
    for m_ in problem.models().values():
        assert problem.in_reference_coordinates(m_).coordinates == (theta,)


def test_normal_force_thrice_and_rod_force_twice(comparison):
    # the free-body diagram and both multipliers give N; the multiplier model frees the rod's
    # length too: S by a second derivation
    assert comparison.reaction_derivations == {
        "N": ["newton_euler", "multiplier", "contact_velocity"],
        "S": ["newton_euler", "multiplier"]}


def test_rod_and_normal_force_satisfy_the_free_body_equations_by_hand():
    # hand (module docstring): N = m g cos(beta) + m (beta'' lever + 2 beta' l sin th th')
    bt = plane_angle()
    lever = c - l * sp.cos(theta)
    N_hand = m * g * sp.cos(bt) + m * (bt.diff(t, 2) * lever
                                       + 2 * bt.diff(t) * l * sp.sin(theta) * D(theta))
    known = dict(problem.model("lagrange").accelerations_solved())
    known.update({N: N_hand, S: hand_rod_force()})
    for label, eq in zip(problem.model("newton_euler").labels,
                         problem.model("newton_euler").equations):
        assert _identically_zero(eq.xreplace(known)), label


def test_plane_at_rest_is_an_incline_pendulum():
    # Omega = alpha = 0: l th'' + g sin(beta0) sin(th) = 0, so omega^2 = g sin(beta0)/l
    still = problem.model("lagrange").substitute({Omega: 0, alpha: 0})
    (w,) = still.natural_frequencies()
    assert sp.simplify(w**2 - g * sp.sin(beta0) / l) == 0
    N_rest = problem.model("newton_euler").substitute({Omega: 0, alpha: 0}).reactions_solved()[N]
    assert sp.simplify(N_rest - m * g * sp.cos(beta0)) == 0


def test_printed_velocity_slips_a_dimension():
    # the slip shows in the dimensions: theta'' beside beta' (c - l cos(theta))
    v = next(p for p in problem.published() if p.label == "(a) v")
    issues = audit(v.printed[0] - v.reference[0], problem.dimensions())
    assert issues and "theta''" in str(issues[0])
