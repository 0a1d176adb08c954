"""Rigid-rod pendulum (problems/rigid_rod_pendulum.py): frequency, pivot force, printed slides."""
import random

import pytest
import sympy as sp

from dualmech import t
from dualmech.exact.form import ExactForm
from dualmech.problems.rigid_rod_pendulum import RigidRodPendulum, g, hand_reactions, l, m, theta

problem = RigidRodPendulum()
D = lambda q: q.diff(t)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("rigid_rod_pendulum")


def test_small_oscillation_frequency_is_the_sources_three_halves_g_over_l():
    # source: theta'' + (3/2)(g/l) sin(theta) = 0, so omega^2 = (3/2) g/l; derived by the library
    (w,) = problem.model("lagrange").natural_frequencies()
    assert sp.simplify(w**2 - sp.Rational(3, 2) * g / l) == 0
    M, C, K = problem.model("lagrange").linearize()
    assert M == sp.Matrix([[m * l**2 / 3]]) and C == sp.zeros(1, 1)


def test_pivot_force_is_the_hand_derived_one(comparison):
    # decided exactly: the recovered reactions minus the hand formulas vanish identically
    diffs = [comparison.reactions[k] - v for k, v in hand_reactions().items()]
    plain = [problem.model("lagrange").to_plain(d) for d in diffs]
    symbols = sorted(set().union(*(d.free_symbols for d in plain)), key=str)
    form = ExactForm.build(plain, symbols)
    rng = random.Random(3)
    assert form.method == "exact"
    for _ in range(4):
        assert form.evaluate(form.sample(rng)) == [0, 0]


def test_rod_hanging_at_rest_carries_its_weight_and_at_horizontal_a_quarter(comparison):
    R = comparison.reactions
    rest = {D(theta): 0}
    assert sp.simplify(R["R_y"].subs(rest).subs(theta, 0) - m * g) == 0
    assert sp.simplify(R["R_x"].subs(rest).subs(theta, 0)) == 0
    # released from rest with the rod horizontal: R_y = m g / 4 (classic result)
    assert sp.simplify(R["R_y"].subs(rest).subs(theta, sp.pi / 2) - m * g / 4) == 0
