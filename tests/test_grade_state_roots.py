r"""The grader on models holding square roots of state expressions (a rolling wheel's contact).

:mod:`dualmech.grade.formula` keeps ``sqrt(X)`` exact at a rational point as the formal root of
``X``'s rational value there (an element of ``Q(sqrt d)``), which is sound only where the
radicands are independent; at a point where a radicand's value is a rational square (a branch:
``sqrt(theta^2) = |theta|``), negative, or dependent on another root's, the formula is left to
the comparator.  The expected values below are computed by hand: at ``th = 3`` the radicand
``1 + th^2`` is 10 (no rational square), ``th^2`` is 9.

The Whipple bicycle (``problems/whipple_bicycle.py``, whose front contact holds ``sqrt(1 -
a_z^2)``) is graded on the exact route: its right answer is its own verified equation of the
rear wheel's spin (207 characters; the front wheel's has 3003, the other rows 20 000 to
180 000).
"""
from __future__ import annotations

from fractions import Fraction

import pytest
import sympy as sp

from dualmech.exact.surds import Surd
from dualmech.grade import Grader
from dualmech.grade.formula import Env, Formula, NotExactHere, state_root
from dualmech.grade.judge import method_for
from dualmech.grade.parser import parse
from dualmech.grade.vocabulary import Vocabulary

TH = sp.Symbol("th", real=True)
EXACT = "exact rational-point test"   # the method a Grade names (dualmech.grade.api)


def formula(text: str) -> Formula:
    return Formula.from_node(parse(text)[0].lhs, Vocabulary.build(parameters=[TH]))


def test_a_root_of_a_state_expression_is_exact():
    f = formula("sqrt(1 + th^2)")
    assert f.exact and f.state_roots
    v = f.evaluate(Env({TH: Fraction(3)}))
    assert v == Surd.root(10) and v * v == 10     # sqrt(10), not a float near 3.1623


def test_a_root_and_its_inverse_power_share_one_field():
    # (1 + th^2)^(-3/2) * sqrt(1 + th^2)^3 = 1 exactly, as in the bicycle's rows
    f = formula("(1 + th^2)^(-3/2) * sqrt(1 + th^2)^3")
    assert f.evaluate(Env({TH: Fraction(3)})) == 1


@pytest.mark.parametrize("text", ["sqrt(th^2)",                  # a square: |th|, a branch
                                  "sqrt(th) + sqrt(4*th)",       # dependent radicands
                                  "sqrt(-1 - th^2)"])            # negative
def test_roots_that_cannot_stay_exact_leave_the_exact_method(text):
    with pytest.raises(NotExactHere):
        formula(text).evaluate(Env({TH: Fraction(3)}))


def test_state_root_refuses_a_square_value():
    assert state_root(Fraction(5), 3) == 5 * Surd.root(5)
    with pytest.raises(NotExactHere):
        state_root(Fraction(9, 4), 1)


def test_an_answer_with_a_branching_root_goes_to_the_comparator():
    """``sqrt(theta^2)/theta`` is the sign of theta: exact points would call it 1 or -1
    depending on where they fall, so the comparator (with its branches) decides."""
    g = Grader("simple_pendulum")
    right = g.grade("a*theta'' + g*sin(theta)*sqrt(1 + theta^2)/sqrt(1 + theta^2)")
    assert right.right and right.method.startswith(EXACT)
    text = "a*theta'' + g*sin(theta)*sqrt(theta^2)/theta"
    f = Formula.from_node(parse(text)[0].lhs, g.context.vocabulary)
    assert method_for(g.context, [f]) == "slow"
    wrong = g.grade(text)
    assert wrong.status == "wrong" and wrong.summary == "not equivalent to the equations of motion"
    assert any("Abs(theta)" in str(e) for e in wrong.edits), str(wrong)


# -- the Whipple bicycle ------------------------------------------------------------------------
@pytest.fixture(scope="module")
def bicycle():
    from dualmech.grade.generate import _reaction_forms, write
    g = Grader("whipple_bicycle")
    ctx = g.context
    assert ctx.method == "exact"       # its front contact's root stays exact
    return g, ctx, write, _reaction_forms


@pytest.mark.slow
def test_bicycle_equation_is_graded_exactly(bicycle):
    """The rear wheel spin's equation as the model has it (207 characters): right, decided on
    the exact route (before: the comparator, about 15 s, and a dimension complaint about the
    geometry's numbers, which the problem declares unchecked)."""
    g, ctx, write, _ = bicycle
    i = [str(q.func) for q in ctx.reference.coordinates].index("thetaR")
    row = ctx.plain(ctx.reference.equations[i])
    r = g.grade(write(row, ctx), "equation:thetaR")
    assert r.right and r.method.startswith(EXACT), str(r)
    assert r.matches == "the equation of thetaR", str(r)
