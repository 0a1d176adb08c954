"""Pendulum on a cart (problems/cart_pendulum.py): the massless rod, the reactions, the errata."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.model.dimensions import audit
from dualmech.model.equations import state_symbols, to_plain
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.cart_pendulum import (CartPendulum, F0, c, c_t, direct_form, g, hand_reactions, k,
                                    k_t, l, m, m0, omega, theta, x)

_EPS = np.finfo(float).eps
problem = CartPendulum()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
REACTIONS = ["N", "T", "S"]


@pytest.fixture
def comparison(compared):
    return compared("cart_pendulum")


def test_both_direct_forms_have_the_three_reactions_as_unknowns():
    for name in ("newton_euler", "lagrange_multipliers"):
        assert [u.name for u in problem.model(name).unknowns] == REACTIONS


def test_massless_rod_moment_balance_gives_the_transverse_force():
    # moments about P on the rod: l e_r x (-S e_th) - (k_t th + c_t th') k = 0
    ne = problem.model("newton_euler")
    i = ne.labels.index("sum tau_P . O.z (rod)")
    S = sp.Symbol("S", real=True)
    (sol,) = sp.solve(ne.equations[i], S)
    assert sp.simplify(sol + (k_t * theta + c_t * D(theta)) / l) == 0


def test_massless_rod_force_balance_holds_identically():
    # the pivot force was drawn as the opposite of the bob's pull: sum F = 0 on the rod
    ne, sc = direct_form()
    ne.linear_momentum(sc.rod, sc.O.x)
    ne.linear_momentum(sc.rod, sc.O.y)
    assert [sp.simplify(e) for e in ne.equations().equations] == [0, 0]


_MAPPED = {n: problem.in_reference_coordinates(m) for n, m in problem.models().items()}


def _numeric(name, point):
    """``[x'', theta'', reactions...]`` of model ``name`` (reference coordinates), cond(A)."""
    A, b = NumericModel(_MAPPED[name], point.params).system(point.time, point.q, point.qd)
    return np.linalg.solve(A, b), np.linalg.cond(A)


_plain = [state_symbols(x), state_symbols(theta)]
_args = ([t] + [s.q for s in _plain] + [s.qd for s in _plain] + [s.qdd for s in _plain]
         + [m, m0, l, k, c, k_t, c_t, g, F0, omega])
_hand = sp.lambdify(_args, [to_plain(hand_reactions(DD(x), DD(theta))[r], (x, theta))
                            for r in REACTIONS], "numpy")


@settings(max_examples=60)
@given(points(problem))
def test_all_models_give_the_same_motion(point):
    # tolerance: the error bound of the linear solves, 64 eps (cond(A) + cond(A_ref)) |x|
    ref, c_ref = _numeric("lagrange", point)
    for name in ("newton_euler", "lagrange_multipliers"):
        x_, cond = _numeric(name, point)
        scale = max(1.0, float(np.max(np.abs(x_))))
        assert np.max(np.abs(x_[:2] - ref)) <= 64 * _EPS * (cond + c_ref) * scale, name


@settings(max_examples=60)
@given(points(problem))
def test_recovered_reactions_are_the_hand_derived_ones(point):
    # hand formulas (module docstring) with the accelerations of the *Lagrange* model put in;
    # both the free-body diagrams and the multipliers must give them
    lg, c_lg = _numeric("lagrange", point)
    p = point.params
    hand = np.array(_hand(point.time, *point.q, *point.qd, *lg[:2],
                          *[p[s] for s in (m, m0, l, k, c, k_t, c_t, g, F0, omega)]))
    for name in ("newton_euler", "lagrange_multipliers"):
        sol, cond = _numeric(name, point)
        tol = 64 * _EPS * (c_lg + cond) * max(1.0, float(np.max(np.abs(sol))))
        assert np.max(np.abs(sol[2:] - hand)) <= tol, name


def _power_balance_terms():
    """The terms of ``d/dt (T + V) - P`` with ``P = -c x'^2 - c_t th'^2 + F . v_B``.

    Written here from scratch (bob velocity by hand), independent of both models.
    """
    th, thd, xd = theta, D(theta), D(x)
    E = (m * xd**2 / 2 + m0 * ((xd + l * thd * sp.cos(th))**2 + (l * thd * sp.sin(th))**2) / 2
         + k * x**2 / 2 + k_t * th**2 / 2 + m0 * g * l * (1 - sp.cos(th)))
    power = -c * xd**2 - c_t * thd**2 + F0 * sp.sin(omega * t) * (xd + l * thd * sp.cos(th))
    terms = sp.Add.make_args(sp.expand(to_plain(E.diff(t) - power, (x, theta))))
    return sp.lambdify(_args, list(terms), "numpy")


_power = _power_balance_terms()


@settings(max_examples=40)
@given(points(problem))
def test_power_balance_of_the_lagrange_model(point):
    # d/dt (T + V) = -c x'^2 - c_t th'^2 + F0 sin(wt) (x' + l th' cos th) on the motion;
    # tolerance: the solve's error bound on the sum of the terms' magnitudes
    acc, cond = _numeric("lagrange", point)
    p = point.params
    terms = np.array(_power(point.time, *point.q, *point.qd, *acc[:2],
                            *[p[s] for s in (m, m0, l, k, c, k_t, c_t, g, F0, omega)]))
    assert abs(terms.sum()) <= 64 * _EPS * cond * np.abs(terms).sum()


def _printed(label):
    (e,) = next(p for p in problem.published() if p.label == label).printed
    return e


def test_printed_theta_equation_fails_the_dimension_audit():
    issues = audit(_printed("equation of motion, theta"), problem.dimensions())
    assert len(issues) == 1
    assert issues[0].term == "l*m0*theta''"   # in the notation people read
    assert issues[0].found == "M L T^-2" and issues[0].expected == "M L^2 T^-2"
    # every other printed equation is consistent
    assert audit(_printed("equation of motion, x"), problem.dimensions()) == []


def test_printed_theta_equation_is_right_with_l_squared():
    # hand: m0 l^2 th'' + c_t th' + k_t th + m0 g l sin th + m0 l x'' cos th = F l cos th
    fixed = _printed("equation of motion, theta") - m0 * l * DD(theta) + m0 * l**2 * DD(theta)
    assert audit(fixed, problem.dimensions()) == []
    sol = problem.model("lagrange").accelerations_solved()
    assert sp.simplify(fixed.xreplace(sol)) == 0
    assert sp.simplify(_printed("equation of motion, x").xreplace(sol)) == 0


def test_comparator_says_why_the_theta_equation_is_wrong_and_finds_the_hand_S(comparison):
    detail = next(v.detail for v in comparison.published
                  if v.label == "equation of motion, theta")
    assert "dimensionally inconsistent" in detail
    assert sp.simplify(comparison.reactions["S"] + (k_t * theta + c_t * D(theta)) / l) == 0
