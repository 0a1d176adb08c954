"""Restrained plane pendulum of Example 12 (problems/restrained_pendulum.py): the source's
model (spring and dashpot along the arcs) and the horizontal variant of its fidelity ladder."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import EquationSet, t
from dualmech.verify.check import compare_models, reaction_pairs
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.restrained_pendulum import (RestrainedPendulum,
                                                   RestrainedPendulumHorizontal, a, b, c, g,
                                                   hand_reactions, hand_reactions_horizontal,
                                                   k, l, m, theta)

_EPS = np.finfo(float).eps
problem = RestrainedPendulum()
horizontal = RestrainedPendulumHorizontal()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731
PRINTED_EOM = (m * l**2 * DD(theta) + c * a**2 * D(theta) + m * g * l * sp.sin(theta)
               + k * b**2 * theta)


def test_both_direct_forms_have_the_pivot_force_as_unknowns():
    for name in ("newton_euler", "multiplier"):
        assert [u.name for u in problem.model(name).unknowns] == ["H", "V"]


@pytest.mark.slow
def test_reference_equation_is_the_printed_one():
    # the source's U = m g l (1 - cos th) + k (b th)^2/2 and R = c (a th')^2/2 give, by hand,
    # d/dt(m l^2 th') + c a^2 th' + m g l sin th + k b^2 th = 0 -- the printed equation
    for name in ("lagrange", "newton_euler"):
        eqs = problem.model(name)
        sol = eqs.solve()
        assert sp.simplify(sol[DD(theta)] + (PRINTED_EOM - m * l**2 * DD(theta))
                           / (m * l**2)) == 0, name


def test_horizontal_variant_equation_is_the_hand_derived_one():
    # m l^2 th'' + c a^2 th' cos^2 th + k b^2 sin th cos th + m g l sin th = 0 (module doc)
    (eq,) = horizontal.model("lagrange").equations
    s, co = sp.sin(theta), sp.cos(theta)
    hand = (m * l**2 * DD(theta) + c * a**2 * D(theta) * co**2 + k * b**2 * s * co
            + m * g * l * s)
    assert sp.simplify(eq - hand) == 0


@pytest.mark.parametrize("p", [problem, horizontal], ids=["source", "horizontal"])
def test_library_linearisation_gives_the_printed_linear_equation(p):
    # printed: m l^2 th'' + c a^2 th' + m g l th + k b^2 th = 0, for both readings
    M, C, K = p.model("lagrange").linearize()
    assert (M[0, 0], C[0, 0], K[0, 0]) == (m * l**2, c * a**2, m * g * l + k * b**2)
    (w,) = p.model("lagrange").natural_frequencies()
    assert sp.simplify(w**2 - (g / l + k * b**2 / (m * l**2))) == 0


def test_printed_nonlinear_equation_is_not_the_motion_of_horizontal_elements():
    printed = EquationSet("printed", (theta,), (PRINTED_EOM,))
    result = compare_models(horizontal.model("lagrange"), printed)
    assert not result.equivalent and result.method == "exact"


def test_printed_nonlinear_equation_is_the_source_models_motion():
    printed = EquationSet("printed", (theta,), (PRINTED_EOM,))
    assert compare_models(problem.model("newton_euler"), printed).equivalent


@pytest.mark.parametrize("p, hand", [(problem, hand_reactions),
                                     (horizontal, hand_reactions_horizontal)],
                         ids=["source", "horizontal"])
@pytest.mark.parametrize("model", ["newton_euler", "multiplier"])
def test_hand_derived_reactions_satisfy_each_derivation(model, p, hand):
    # put H, V of the module docstring (written with th'') into the direct / multiplier
    # equations: what is left must hold on the Lagrangian motion, row by row (exact test)
    eqs = p.in_reference_coordinates(p.model(model))
    assert eqs.is_square
    values = {sp.Symbol(n, real=True): e for n, e in hand(DD(theta)).items()}
    rows = [e.subs(values) for e in eqs.equations]
    # a row the hand reactions were read from vanishes identically; the rest must be the motion
    left = [e for e in rows if sp.simplify(e) != 0]
    assert 0 < len(left) < len(rows)
    closed = EquationSet("hand", eqs.coordinates, left)
    result = compare_models(p.model("lagrange"), closed, explain=False)
    assert result.equivalent and result.method == "exact"


def test_pivot_carries_the_weight_at_rest_hanging():
    # at rest at th = 0 the direct equations alone give H = 0, V = m g
    A, rhs = problem.model("newton_euler").matrix()
    rest = lambda e: e.xreplace({D(theta): 0}).xreplace({theta: 0})  # noqa: E731
    thdd, H, V = A.applyfunc(rest).LUsolve(rhs.applyfunc(rest))
    assert (sp.simplify(thdd), sp.simplify(H), sp.simplify(V - m * g)) == (0, 0, 0)


@settings(max_examples=40, deadline=None)
@given(points(problem))
def test_numeric_reactions_match_the_free_body_diagram(point):
    nm = NumericModel(problem.model("newton_euler"), point.params)
    A, rhs = nm.system(point.time, point.q, point.qd)
    thdd, H, V = np.linalg.solve(A, rhs)
    p = {str(s): val for s, val in point.params.items()}
    (th,), (thd,) = point.q, point.qd
    s, co = np.sin(th), np.cos(th)
    tangential = p["k"] * p["b"] * th + p["c"] * p["a"] * thd     # module doc, source's model
    H_hand = tangential * co + p["m"] * p["l"] * (thdd * co - thd**2 * s)
    V_hand = p["m"] * p["g"] + tangential * s + p["m"] * p["l"] * (thdd * s + thd**2 * co)
    tol = 64 * _EPS * np.linalg.cond(A) * max(1.0, float(np.max(np.abs(rhs))),
                                               abs(H_hand), abs(V_hand))
    assert abs(H - H_hand) <= tol and abs(V - V_hand) <= tol


def test_a_break_that_leaves_the_motion_alone_shows_in_the_reaction():
    # the motion comes from the moment balance about the pivot; dropping the weight from the
    # vertical force balance only changes V, which the multiplier model then contradicts
    ne = problem.model("newton_euler")
    row = ne.labels.index(next(lb for lb in ne.labels if lb.startswith("sum F . O.y")))
    eqs = list(ne.equations)
    eqs[row] = eqs[row] - ne.contributions[row]["gravity on bob"]
    broken = EquationSet("newton_euler", ne.coordinates, eqs, ne.unknowns, ne.labels)
    assert compare_models(problem.model("lagrange"), broken, explain=False).equivalent
    models = dict(problem.models(), newton_euler=broken)
    (pair,) = reaction_pairs(problem, models, explain=False)
    assert not pair.equivalent and pair.mismatches[0].equation == "reaction V"
