"""Answers with two or three mistakes in one equation: the grader names every one, and no other.

Each answer is a problem's verified equation (the reference rows, printed in each case's
comment from ``ctx.reference.equations``) typed as a student types it, with two or three
classic mistakes injected: terms dropped, a sign flipped, a function linearised or replaced,
a coefficient changed, a combination of two rows with a slip inside.  The expected edits are
exactly the injected mistakes, the correct terms at the student's own scale.
"""
from __future__ import annotations

import pytest
import sympy as sp

from dualmech.grade import Grader
from dualmech.grade.formula import Formula
from dualmech.grade.parser import parse

#: (problem, answer, [(kind, written term, correct term)]) -- "" where an edit has none
CORPUS = [
    # toy_car, phi: R cos(theta) phi'' - 2 R phi' theta' sin(theta) + g sin(phi) = 0
    ("toy_car", "R*cos(theta)*phi'' = 0",
     [("missing", "", "g*sin(phi)"), ("missing", "", "-2*R*phi'*theta'*sin(theta)")]),
    ("toy_car", "R*phi''*cos(theta) - 2*R*phi'*theta'*cos(theta) = 0",
     [("replace", "-2*R*phi'*theta'*cos(theta)", "-2*R*phi'*theta'*sin(theta)"),
      ("missing", "", "g*sin(phi)")]),
    # toy_car, theta: R theta'' + R phi'^2 sin(theta) cos(theta) + g cos(phi) sin(theta) = 0,
    # two terms linearised
    ("toy_car", "R*theta'' + R*phi'^2*theta*cos(theta) + g*cos(phi)*theta = 0",
     [("replace", "R*phi'^2*theta*cos(theta)", "R*phi'^2*sin(theta)*cos(theta)"),
      ("replace", "g*theta*cos(phi)", "g*sin(theta)*cos(phi)")]),
    # symmetric_top, psi: C phi'' cos(theta) - C phi' theta' sin(theta) + C psi'' = 0
    ("symmetric_top", "C*psi'' = 0",
     [("missing", "", "C*phi''*cos(theta)"), ("missing", "", "-C*phi'*theta'*sin(theta)")]),
    # symmetric_top, theta: A theta'' - A phi'^2 sin cos + C phi' (phi' cos + psi') sin
    # - M g h sin(theta) = 0; C phi'^2 sin cos dropped, gravity's sign flipped
    ("symmetric_top", "A*theta'' - A*phi'^2*sin(theta)*cos(theta) + C*phi'*psi'*sin(theta) "
     "+ M*g*h*sin(theta) = 0",
     [("missing", "", "C*phi'^2*sin(theta)*cos(theta)"),
      ("sign", "M*g*h*sin(theta)", "-M*g*h*sin(theta)")]),
    # spring_mass_damper: m x'' + b x' + k x - F0 cos(Omega t) = 0
    ("spring_mass_damper", "m*x'' + k*x = F0*sin(Omega*t)",
     [("replace", "-F0*sin(Omega*t)", "-F0*cos(Omega*t)"), ("missing", "", "b*x'")]),
    ("spring_mass_damper", "m*x'' - b*x' + k*x^2 = F0*cos(Omega*t)",
     [("sign", "-b*x'", "b*x'"), ("replace", "k*x^2", "k*x")]),
    # trolley_pendulum, x: (M + m) x'' + a m theta'' cos - a m theta'^2 sin - F - P = 0
    ("trolley_pendulum", "(M+m)*x'' + m*a*theta''*sin(theta) = F",
     [("missing", "", "-P"), ("replace", "a*m*theta''*sin(theta)", "a*m*theta''*cos(theta)"),
      ("missing", "", "-a*m*theta'^2*sin(theta)")]),
    # trolley_pendulum, theta: a^2 m theta'' + a m x'' cos + a g m sin - P a cos = 0
    ("trolley_pendulum", "m*a^2*theta'' + m*a*x''*cos(theta) - m*g*a*sin(theta) = 0",
     [("sign", "-a*g*m*sin(theta)", "a*g*m*sin(theta)"), ("missing", "", "-P*a*cos(theta)")]),
    # compound_double_pendulum, theta1: a^2 m theta1'' + a b m theta2'' cos(theta1 - theta2)
    # + a b m theta2'^2 sin(theta1 - theta2) + a g m sin(theta1) = 0
    ("compound_double_pendulum", "a^2*m*theta1'' + a*b*m*theta2'' + a*g*m*sin(theta1) = 0",
     [("replace", "a*b*m*theta2''", "a*b*m*theta2''*cos(theta1 - theta2)"),
      ("missing", "", "a*b*m*theta2'^2*sin(theta1 - theta2)")]),
    # inertia_wheel_pendulum, q1: (I1 + l_c1^2 m1 + I2 + l1^2 m2) q1'' + I2 q2''
    # + g (l1 m2 + l_c1 m1) sin(q1) = 0: the wheel's inertia left out twice
    ("inertia_wheel_pendulum",
     "(I1 + m1*l_c1^2 + m2*l1^2)*q1'' + (m1*l_c1 + m2*l1)*g*sin(q1) = 0",
     [("missing", "", "I2*q1''"), ("missing", "", "I2*q2''")]),
    # bead_on_hoop: R^2 m theta'' - R^2 m omega^2 sin cos + R g m sin(theta) = 0
    ("bead_on_hoop", "m*R^2*theta'' - m*R^2*omega^2*sin(theta) + m*g*R*theta = 0",
     [("replace", "-R^2*m*omega^2*sin(theta)", "-R^2*m*omega^2*sin(theta)*cos(theta)"),
      ("replace", "R*g*m*theta", "R*g*m*sin(theta)")]),
    # cart_pendulum, x (MIT 2.003J Example 17): the damper dropped, the centripetal sign
    # flipped inside the student's factor
    ("cart_pendulum", "(m + m0)*x'' + k*x + m0*l*(theta''*cos(theta) + theta'^2*sin(theta)) "
     "= F0*sin(omega*t)",
     [("sign", "l*m0*theta'^2*sin(theta)", "-l*m0*theta'^2*sin(theta)"),
      ("missing", "", "c*x'")]),
    # a slip inside a combination the student made: the x row plus the theta row over a
    # (trolley_pendulum), the reaction P's sign flipped in the second
    ("trolley_pendulum", "(M+m)*x'' + m*a*theta''*cos(theta) - m*a*theta'^2*sin(theta) - F - P"
     " + m*a*theta'' + m*x''*cos(theta) + m*g*sin(theta) + P*cos(theta) = 0",
     [("sign", "P*cos(theta)", "-P*cos(theta)")]),
    # the inertia of a rod about its end written m l^2 (for m l^2/3), the answer divided by
    # m: the student's scale (1/m), not a rescaled one (3/m) with a changed gravity term
    ("rigid_rod_pendulum", "l^2*theta'' + g*l/2*sin(theta) = 0",
     [("coefficient", "l^2*theta''", "l^2*theta''/3")]),
]


def _expr(problem: str, text: str):
    voc = Grader.of(problem).context.vocabulary
    return Formula.from_node(parse(text)[0].lhs, voc).sympy()


def _same(problem: str, a: str, b: str) -> bool:
    if not a or not b:
        return a == b
    return sp.expand(_expr(problem, a) - _expr(problem, b)) == 0


def _named(problem: str, edit, expected) -> bool:
    kind, term, correct = expected
    return edit.kind == kind and _same(problem, edit.term, term) and \
        _same(problem, edit.correct, correct)


def _grade(problem, answer):
    return Grader.of(problem).grade(answer, "equation")


@pytest.mark.parametrize("problem, answer, expected", CORPUS,
                         ids=[f"{p}-{i}" for i, (p, _, _) in enumerate(CORPUS)])
def test_every_mistake_is_named_and_no_other(problem, answer, expected):
    r = _grade(problem, answer)
    assert r.status == "wrong", str(r)
    assert len(r.edits) == len(expected), str(r)
    for want in expected:
        assert any(_named(problem, e, want) for e in r.edits), (want, str(r))


def test_share_named_over_the_corpus():
    """Every injected mistake named (the share is 1 over this corpus), no wrong term."""
    named = total = wrong = 0
    for problem, answer, expected in CORPUS:
        r = _grade(problem, answer)
        total += len(expected)
        named += sum(any(_named(problem, e, w) for e in r.edits) for w in expected)
        wrong += sum(not any(_named(problem, e, w) for w in expected) for e in r.edits)
    assert len({p for p, _, _ in CORPUS}) >= 6
    assert (named, wrong) == (total, 0)


def test_a_set_with_two_terms_dropped_from_one_equation():
    # the brief's example: toy_car's phi equation with its Coriolis and gravity terms dropped
    r = Grader.of("toy_car").grade("R*theta'' + R*phi'^2*sin(theta)*cos(theta) "
                                   "+ g*cos(phi)*sin(theta) = 0; R*cos(theta)*phi'' = 0")
    assert r.status == "wrong" and {e.equation for e in r.edits} == {1}, str(r)
    assert sorted(e.category for e in r.edits) == ["a Coriolis term", "a gravity term"]
    assert r.score == pytest.approx((1 + 0.25) / 2)    # one right, one with two edits


def test_a_slip_inside_a_combined_equation_of_a_set():
    # toy_car: (theta row) + (phi row) with the Coriolis sign flipped, and the phi row
    r = Grader.of("toy_car").grade(
        "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) + R*phi''*cos(theta)"
        " + 2*R*phi'*theta'*sin(theta) + g*sin(phi) = 0\n"
        "R*phi''*cos(theta) - 2*R*phi'*theta'*sin(theta) + g*sin(phi) = 0")
    (e,) = r.edits
    assert e.kind == "sign" and e.equation == 0 and e.category == "a Coriolis term"
    assert _same("toy_car", e.correct, "-2*R*phi'*theta'*sin(theta)")
    assert "a combination of" in str(r) and r.score == pytest.approx((0.5 + 1) / 2)


def test_scores_count_edits_per_equation():
    one = _grade("rigid_rod_pendulum", "l^2*theta'' + g*l/2*sin(theta) = 0")
    three = _grade("trolley_pendulum", "(M+m)*x'' + m*a*theta''*sin(theta) = F")
    assert (one.score, three.score) == (0.5, 0.25)


@pytest.mark.parametrize("problem, answer, kinds", [
    # toy_car, theta: the centripetal and gravity terms rewritten beyond a small edit
    ("toy_car", "R*theta'' + 3*R*phi'^2*theta + 5*g*cos(phi)*theta^2 = 0",
     "the theta equation, its centripetal and gravity terms differ"),
    # spring_mass_damper: damping, spring and drive all wrong
    ("spring_mass_damper", "m*x'' + 3*b*x'^2 + k*sin(x) = 0",
     "the x equation, its driving force, spring and damping terms differ"),
])
def test_the_kind_of_term_is_named_when_no_edit_is(problem, answer, kinds):
    r = _grade(problem, answer)
    assert r.status == "wrong" and not r.edits, str(r)
    assert kinds in r.details[0] and "at the state below" in r.details[0], str(r)
    ctx = Grader.of(problem).context
    ranges = ctx.ranges()
    for s in ctx.states:           # the state shown lies in the declared ranges
        lo, hi = ranges.get(s.q, (-float("inf"), float("inf")))
        assert lo <= r.state[s.name] <= hi
