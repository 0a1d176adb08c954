"""The answer parser, the vocabulary and formulas: every accepted notation means what it says.

Notations are checked by value: each spelling is resolved against a small vocabulary and
evaluated at one exact point, and must give the value of the same expression built by hand
with sympy (an independent construction).  Refusals are checked by error type and by the
words of the message a student reads.
"""
from __future__ import annotations

from fractions import Fraction

import pytest
import sympy as sp

from dualmech import coordinate
from dualmech.model.equations import state_symbols
from dualmech.grade.audit import dimension_issues
from dualmech.grade.formula import Env, Formula, difference
from dualmech.grade.parser import AnswerError, AnswerTooLarge, Limits, parse
from dualmech.grade.vocabulary import UnknownName, Vocabulary

theta, x1 = coordinate("theta"), coordinate("x1")
TH, X1 = state_symbols(theta), state_symbols(x1)
m, m0, k_t, g, omega, F_r = sp.symbols("m m0 k_t g omega F_r", positive=True)
VOC = Vocabulary.build([theta, x1], [m, m0, k_t, g, omega], [F_r])

#: one exact point; the angle theta has u = 1/2 (cos = 3/5, sin = 4/5), independent of
#: the value 7 of the symbol theta itself
VALUES = {TH.q: Fraction(7), TH.qd: Fraction(2), TH.qdd: Fraction(-3), X1.q: Fraction(5),
          X1.qd: Fraction(11), X1.qdd: Fraction(13), m: Fraction(3), m0: Fraction(17),
          k_t: Fraction(19), g: Fraction(23), omega: Fraction(29), F_r: Fraction(31),
          sp.Symbol("t", real=True): Fraction(37)}
ATOMS = {((TH.q, 1),): Fraction(1, 2)}
COS, SIN = Fraction(3, 5), Fraction(4, 5)


def value(text: str):
    (eq,) = parse(text)
    f = Formula.from_node(eq.lhs, VOC)
    if eq.rhs is not None:
        f = difference(f, Formula.from_node(eq.rhs, VOC))
    return f.evaluate(Env(dict(VALUES), atoms=dict(ATOMS), draw=lambda mono: Fraction(1, 3)))


@pytest.mark.parametrize("text", [
    "theta''", "thetaddot", "theta_ddot", "theta_dd", "ddtheta", "ddth", r"\ddot{\theta}",
    r"\ddot\theta", "θ''", "θ̈", "th''", "theta''(t)",
], ids=repr)
def test_second_derivative_notations(text):
    assert value(text) == VALUES[TH.qdd]


@pytest.mark.parametrize("text", [
    "theta'", "thetadot", "theta_dot", "theta_d", "dtheta", r"\dot{\theta}", "θ̇", "θ′",
], ids=repr)
def test_first_derivative_notations(text):
    assert value(text) == VALUES[TH.qd]


@pytest.mark.parametrize("text", [
    "x1''", "x_1''", "x_{1}''", r"\ddot{x}_1", r"\ddot{x_1}", "x1ddot", "ddx1",
    "ẍ1", "ẍ₁", "ẍ_1", "x₁''",      # a dot typed on the letter before the index, not x''*1
], ids=repr)
def test_subscripted_coordinate(text):
    assert value(text) == VALUES[X1.qdd]


@pytest.mark.parametrize("text, expected", [
    ("m*g*sin(theta)", 3 * 23 * SIN),
    ("m g sin(theta)", 3 * 23 * SIN),                       # implicit multiplication
    ("mg sin θ", 3 * 23 * SIN),                              # split into known names
    (r"m g \sin\theta", 3 * 23 * SIN),
    ("sin^2(theta) + cos(theta)**2", Fraction(1)),
    (r"\sin^{2}\theta + \cos^2\theta", Fraction(1)),
    ("sin(2*theta)", 2 * SIN * COS),                         # multiple angle, exactly
    (r"\sin 2\theta", 2 * SIN * COS),
    ("cos(pi/2 - theta)", SIN),                              # quarter turn
    ("tan(theta)", SIN / COS),
    (r"\frac{1}{2} m \dot{x}_1^2", Fraction(1, 2) * 3 * 11 ** 2),
    ("1/2*m*x1'^2", Fraction(1, 2) * 3 * 11 ** 2),
    ("m(theta'' + 2)", 3 * (-3 + 2)),
    ("m_0 + m0 + m_{0}", 3 * 17),
    ("k_t*theta + kt*theta", 2 * 19 * 7),                   # theta itself: 7, not its angle
    ("2^3^2", Fraction(2) ** 9),                             # right associative
    ("-x1^2", -Fraction(25)),
    ("1.5e1 + .5", Fraction(31, 2)),
    (r"m \cdot g \times 2", 3 * 23 * 2),
    (r"\left( m + g \right)", 26),
    ("F_r = m*g", 31 - 3 * 23),                              # lhs - rhs
    ("ω t", 29 * 37),
    # a power on a word read as an implicit product binds to its last letter, as with spaces
    ("mg^2", 3 * 23 ** 2),
    (r"\frac{mg^2}{2}", Fraction(3 * 23 ** 2, 2)),
    ("mg^2 - m g^2", 0),
    ("½ m x1'^2 + ¼ m + ¾ g", Fraction(3 * 11 ** 2, 2) + Fraction(3, 4) + Fraction(69, 4)),
    ("m₀ + θ̇²", 17 + 2 ** 2),
], ids=lambda v: repr(v) if isinstance(v, str) else "")
def test_values(text, expected):
    assert value(text) == expected


def test_equations_split_by_lines_and_semicolons():
    eqs = parse("m*theta'' = -g;\n x1'' + x1 = 0 \n\n k_t")
    assert [e.rhs is not None for e in eqs] == [True, True, False]
    assert [e.text for e in eqs] == ["m*theta'' = -g", "x1'' + x1 = 0", "k_t"]


def test_sympy_form_is_built_from_symbols():
    (eq,) = parse("m*g*sin(theta) + x1'^2/2")
    f = Formula.from_node(eq.lhs, VOC)
    assert f.sympy() == m * g * sp.sin(TH.q) + X1.qd ** 2 / 2
    assert f.exact


def test_non_rational_answers_are_marked():
    for text in ("exp(theta)", "sin(theta/2)", "log(m)", "sin(sqrt(m))", "m^(1/3)"):
        (eq,) = parse(text)
        assert not Formula.from_node(eq.lhs, VOC).exact, text
    # square roots of symbols are exact where their radicands stay independent at the point
    # (else NotExactHere sends them to the comparator: tests/test_grade_state_roots.py)
    for text in ("sqrt(m)", "m^(1/2)"):
        (eq,) = parse(text)
        f = Formula.from_node(eq.lhs, VOC)
        assert f.exact and f.state_roots, text


@pytest.mark.parametrize("text, words", [
    ("thta''", "unknown name `thta`. Did you mean `theta`"),
    ("theta'''", "at most second derivatives"),
    ("m'", "only coordinates have derivatives"),
    ("a = b = c", "one `=`"),
    ("sin x^2", "ambiguous"),
    ("sin^-1(x1)", "unexpected '-'"),
    ("m^g", "exponents must be numbers"),
    ("m*(g", "ends too early"),
    ("m g)", "unexpected ')'"),
    ("", "empty"),
], ids=repr)
def test_refusals_say_what_to_fix(text, words):
    with pytest.raises((AnswerError, UnknownName)) as exc:
        (eq,) = parse(text)
        Formula.from_node(eq.lhs, VOC)
    assert words in str(exc.value)


def test_unknown_name_lists_the_problems_names():
    with pytest.raises(UnknownName) as exc:
        Formula.from_node(parse("zeta")[0].lhs, VOC)
    msg = str(exc.value)
    for name in ("theta (θ, th)", "x1", "k_t", "F_r", "theta''", "thetadot"):
        assert name in msg


def test_ambiguous_alias_is_dropped():
    # `th` would be both theta's alias and the parameter th: the alias goes, the name stays
    th = sp.Symbol("th", positive=True)
    voc = Vocabulary.build([theta], [th])
    assert voc.lookup("th", 0).symbol == th


@pytest.mark.parametrize("text, error", [
    ("x" * 5000, AnswerTooLarge),
    ("(" * 50 + "x" + ")" * 50, AnswerTooLarge),
    ("-" * 60 + "x", AnswerTooLarge),
    ("x" + "^x" * 60, AnswerTooLarge),
    ("9^9^9^9", AnswerTooLarge),
    ("x1^99", AnswerTooLarge),
    ("((x1^20)^20)^20", AnswerTooLarge),
    ("1" * 40, AnswerTooLarge),
    ("1e99999", AnswerTooLarge),
    (";".join(["x1"] * 30), AnswerTooLarge),
], ids=lambda v: v[:20] if isinstance(v, str) else "")
def test_limits(text, error):
    with pytest.raises(error):
        for eq in parse(text):
            Formula.from_node(eq.lhs, VOC)


def test_limits_are_configurable():
    small = Limits(chars=10)
    with pytest.raises(AnswerTooLarge, match="at most 10"):
        parse("m*g*sin(theta)", small)


def test_dimension_audit_names_the_odd_term():
    from dualmech.model.dimensions import ANGLE, FORCE, LENGTH, MASS, ACCELERATION, reduce
    dims = {TH.q: (), TH.qd: (("time", -1),), TH.qdd: (("time", -2),),
            m: tuple(sorted(reduce(MASS))), g: tuple(sorted(reduce(ACCELERATION))),
            X1.q: tuple(sorted(reduce(LENGTH)))}
    del ANGLE, FORCE
    (eq,) = parse("m*x1*theta'' + m*g*sin(theta) + m*g*x1")
    issues = dimension_issues(Formula.from_node(eq.lhs, VOC).tree, dims,
                              {TH.qdd: "theta''"})
    assert issues == ["the term `g*m*x1` has dimension L^2 M T^-2 where the other terms have "
                      "L M T^-2"]


def test_a_dot_before_an_index_is_never_a_product_with_the_index():
    # with both x and x1 names (pulley_bent_track has them), ``ẍ1`` once read as x''*1
    x = coordinate("x")
    voc = Vocabulary.build([x, x1], [m], [])
    (eq,) = parse("ẍ1 + ẋ₁")
    got = Formula.from_node(eq.lhs, voc).sympy()
    assert got == X1.qdd + X1.qd, got
