"""Block on a free wedge (problems/block_on_wedge.py): both forms, normal forces, the answers."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.block_on_wedge import (BlockOnWedge, M, alpha, g, hand_accelerations,
                                     hand_reactions, m, q1, q2)

_EPS = np.finfo(float).eps
problem = BlockOnWedge()
DD = lambda q: q.diff(t, 2)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("block_on_wedge")


def test_both_direct_forms_have_the_two_normal_forces_as_unknowns():
    for name in ("newton_euler", "lagrange_multipliers"):
        assert [u.name for u in problem.model(name).unknowns] == ["N1", "N2"]


def test_both_forms_give_the_hand_derived_accelerations():
    hand = hand_accelerations()
    for name in ("lagrange", "newton_euler"):
        sol = problem.model(name).solve()
        assert all(sp.simplify(sol[a] - v) == 0 for a, v in hand.items()), name


@pytest.mark.parametrize("model", ["newton_euler", "lagrange_multipliers"])
def test_recovered_normal_forces_are_the_hand_derived_ones(model):
    # N1 = m M g cos(a)/(M + m sin^2 a), N2 = M (M + m) g/(M + m sin^2 a)  (module docstring);
    # the multipliers of d1 = 0, d2 = 0 must be the same forces
    eqs = problem.in_reference_coordinates(problem.model(model))
    got = {u.name: v for u, v in eqs.reactions_solved().items()}
    for name, v in hand_reactions().items():
        assert sp.simplify(got[name] - v) == 0, name


def test_hand_reactions_pass_independent_checks():
    N1, N2 = hand_reactions()["N1"], hand_reactions()["N2"]
    a = hand_accelerations()
    # whole system along j: N2 - (M + m) g = m * (block's vertical acceleration) = -m q1'' sin a
    assert sp.simplify(N2 - (M + m) * g + m * a[DD(q1)] * sp.sin(alpha)) == 0
    # wedge along i: M q2'' = -N1 sin a
    assert sp.simplify(M * a[DD(q2)] + N1 * sp.sin(alpha)) == 0
    # a fixed wedge (M -> oo) gives the incline values g sin a and m g cos a
    assert sp.limit(a[DD(q1)], M, sp.oo) == g * sp.sin(alpha)
    assert sp.limit(N1, M, sp.oo) == m * g * sp.cos(alpha)


@settings(max_examples=60)
@given(points(problem))
def test_numeric_reactions_and_conserved_horizontal_momentum(point):
    nm = NumericModel(problem.model("newton_euler"), point.params)
    A, b = nm.system(point.time, point.q, point.qd)
    sol = np.linalg.solve(A, b)
    p = {str(s): v for s, v in point.params.items()}
    s, c = np.sin(p["alpha"]), np.cos(p["alpha"])
    delta = p["M"] + p["m"] * s**2
    # [q1'', q2'', N1, N2] by hand (module docstring)
    hand = np.array([(p["M"] + p["m"]) * p["g"] * s, -p["m"] * p["g"] * s * c,
                     p["m"] * p["M"] * p["g"] * c, p["M"] * (p["M"] + p["m"]) * p["g"]]) / delta
    tol = 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.max(np.abs(hand))))
    assert np.max(np.abs(sol - hand)) <= tol
    # no horizontal external force: d/dt [(M + m) q2' + m q1' cos a] = 0
    assert abs((p["M"] + p["m"]) * sol[1] + p["m"] * sol[0] * c) <= tol * (p["M"] + p["m"])


def test_printed_accelerations_equal_the_derived_ones():
    pubs = {p.label: p for p in problem.published()}
    a = hand_accelerations()
    (q1dd,) = pubs["q1''"].printed
    (q2dd,) = pubs["q2''"].printed
    assert sp.simplify(q1dd - a[DD(q1)]) == 0
    # the printed q2'' is written with q1'': put the true one in
    assert sp.simplify(q2dd.xreplace({DD(q1): a[DD(q1)]}) - a[DD(q2)]) == 0


def test_comparators_reactions_are_the_hand_derived_ones(comparison):
    for name, v in hand_reactions().items():
        assert sp.simplify(comparison.reactions[name] - v) == 0, name
