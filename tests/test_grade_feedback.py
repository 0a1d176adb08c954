"""The grader names the real mistake, in the student's notation and names.

Reference equations here are the problems' own verified rows (printed in each test's comment
from ``ctx.reference.equations``); each wrong answer below changes exactly one thing a student
changes, and the diagnosis must be exactly that one edit.
"""
from __future__ import annotations

import json
import subprocess
import sys

import sympy as sp

from dualmech.grade import Grader, grade
from dualmech.grade.formula import Formula
from dualmech.grade.parser import parse


def read(ctx, text):
    return Formula.from_node(parse(text)[0].lhs, ctx.vocabulary).sympy()


def test_a_dropped_group_is_one_missing_term_as_written():
    # falling_container, Lagrange x1: m1 x1'' + m1 g - k (x2 - x1 - l0) - c (x2' - x1') = 0;
    # the student left out the damper's force, written as one group
    g = Grader.of("falling_container")
    r = g.grade("m1*x1'' + m1*g - k*(x2 - x1 - l0) = 0", "equation")
    assert r.status == "wrong" and len(r.edits) == 1, str(r)
    e = r.edits[0]
    ctx = g.context
    assert e.kind == "missing"
    assert sp.expand(read(ctx, e.correct) - (-read(ctx, "c*(x2' - x1')"))) == 0


def test_a_sign_inside_the_students_factor():
    # taut_string_masses, mass 1: -m x1'' - P x1/a + P (x2 - x1)/a = 0; the student wrote
    # (P/a)(x1 + x2): the x1 inside the factor has the wrong sign, and the two x1 terms
    # written cancel -- the edit is that one sign, not a missing -2 P x1/a
    g = Grader.of("taut_string_masses")
    r = g.grade("-P*x1/a - m*x1'' + (P/a)*(x1 + x2) = 0", "equation")
    assert r.status == "wrong" and len(r.edits) == 1, str(r)
    e = r.edits[0]
    ctx = g.context
    assert e.kind == "sign"
    assert sp.expand(read(ctx, e.correct) - read(ctx, e.term) - read(ctx, "-2*P*x1/a")) == 0


def test_the_flipped_term_is_named_not_the_others():
    # inverted_pendulum_springs: l^2 m theta'' - m g l sin(theta) + 2 k a^2 sin(theta) cos(theta)
    # = 0; the student flipped the spring's sign only: one edit, the spring term (not the
    # inertia and gravity terms flipped, which is the same equation times -1 with two edits)
    r = grade("inverted_pendulum_springs",
              "m*l^2*theta'' = m*g*l*sin(theta) + 2*k*a^2*sin(theta)*cos(theta)")
    assert r.status == "wrong" and len(r.edits) == 1, str(r)
    assert r.edits[0].kind == "sign" and r.edits[0].category == "a spring term"


def test_feedback_in_the_students_notation():
    # toy_car, theta: R theta'' + R phi'^2 sin(theta) cos(theta) + g sin(theta) cos(phi) = 0
    r = grade("toy_car", "R*thetaddot + R*phidot^2*sin(theta)*cos(theta) - g*sin(theta)*cos(phi)"
              " = 0")
    text = str(r)
    assert r.status == "wrong" and len(r.edits) == 1, text
    assert "**" not in text and "'" not in text.split("(decided")[0], text
    r = grade("toy_car", "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*sin(theta)*cos(phi) "
              "+ R*phi'^2 = 0")
    assert "phi'^2" in str(r) and "**" not in str(r), str(r)


def test_equations_are_named_by_coordinate_without_model_names():
    # falling_container: the damper's sign flipped in the x1 equation of a set of two
    r = grade("falling_container", "m1*x1'' + m1*g - k*(x2-x1-l0) + c*(x2'-x1') = 0\n"
              "m2*x2'' + m2*g + k*(x2-x1-l0) + c*(x2'-x1') = 0")
    text = str(r)
    assert r.status == "wrong" and "the x1 equation" in text, text
    for internal in ("lagrange [", "newton_euler", "Lagrange, x1", "sum F"):
        assert internal not in text, text
    r = grade("toy_car", "m*R*theta'' + m*R*phi'^2*sin(theta)*cos(theta) - "
              "m*g*sin(theta)*cos(phi) = 0", "equation")
    assert "newton_euler" not in str(r) and "[" not in str(r), str(r)


def test_every_edit_carries_mathml():
    r = grade("toy_car", "R*theta'' + R*phi'^2*sin(theta)*cos(theta) - g*sin(theta)*cos(phi) = 0",
              "equation")
    d = r.to_dict()
    json.dumps(d)
    (e,) = d["edits"]
    for key in ("term_html", "correct_html"):
        assert e[key].startswith("<math") and "&#952;" in e[key], e[key]   # theta as θ


def test_declared_aliases_are_names_students_use():
    # simple_pendulum writes M and a; students write m and l (declared aliases)
    assert grade("simple_pendulum", "l*theta'' + g*sin(theta) = 0").right
    r = grade("simple_pendulum", "m*l^2*theta'' - m*g*l*sin(theta) = 0")
    assert r.status == "wrong" and "`-m*l*g*sin(theta)`" in str(r), str(r)
    # an undeclared alias is still unknown
    assert grade("toy_car", "l*theta'' = 0").status == "invalid"


def test_grade_list_shows_names_units_and_hides_internal_coordinates():
    out = subprocess.run([sys.executable, "-m", "dualmech", "grade", "toy_car", "--list",
                          "--json"], capture_output=True, text=True, check=True).stdout
    names = {r["name"]: r for r in json.loads(out)["names"]}
    assert "rho" not in names                      # the multiplier model's constant radius
    assert names["g"]["unit"] == "m s^-2" and names["m"]["unit"] == "kg"
    assert "θ" in names["theta"]["aliases"]
    out = subprocess.run([sys.executable, "-m", "dualmech", "grade", "simple_pendulum",
                          "--list"], capture_output=True, text=True, check=True).stdout
    assert "names an answer may use" in out and " l;" in out


def test_an_answer_in_declared_coordinates_is_diagnosed_in_them():
    # falling_container in (y1, y2) = (x1, x2 - x1 - l0), the source's second choice:
    #   (m1 + m2) y1'' + m2 y2'' + (m1 + m2) g = 0,  m2 y1'' + m2 y2'' + c y2' + k y2 + m2 g = 0
    # the damper's sign flipped in the second: named in y2, state shown in y1, y2
    first = "m1*y1'' + m1*g + m2*g + m2*y1'' + m2*y2'' = 0\n"
    assert grade("falling_container", first + "m2*(y1''+y2'') + m2*g + k*y2 + c*y2' = 0").right
    r = grade("falling_container", first + "m2*(y1''+y2'') + m2*g + k*y2 - c*y2' = 0")
    assert r.status == "wrong" and len(r.edits) == 1, str(r)
    (e,) = r.edits
    assert e.kind == "sign" and e.correct == "c*y2'" and "the y2 equation" in e.sentence()
    assert "x1" not in str(r) and "x2" not in str(r), str(r)
    # no small edit explains this one: the state where it fails is given in y1, y2
    r = grade("falling_container", first + "m2*(y1''+y2'') + y2*y1^3 + c*y1'*y2' = 0")
    assert r.status == "wrong" and not r.edits, str(r)
    assert set(r.state) >= {"y1", "y1'", "y2", "y2'"} and "x1" not in r.state, r.state


def test_a_map_the_student_states():
    # simple_pendulum (M a^2 theta'' + M g a sin(theta) = 0) in the arc length s = a*theta
    assert grade("simple_pendulum", "a*s'' + g*a*sin(s/a) = 0; where s = a*theta").right
    assert grade("simple_pendulum", "M*s'' + M*g*sin(s/a) = 0 where s = a*theta").right
    r = grade("simple_pendulum", "a*s'' - g*a*sin(s/a) = 0; where s = a*theta")
    assert r.status == "wrong" and [e.kind for e in r.edits] == ["sign"], str(r)
    # named in the student's coordinate, as they wrote it (the map is affine: inverted exactly)
    (e,) = r.edits
    assert e.term == "-a*g*sin(s/a)" and e.correct == "a*g*sin(s/a)", str(r)
    assert "theta" not in e.sentence(), e.sentence()
    # dimensions audited in the student's coordinate (s is a length by its map)
    r = grade("simple_pendulum", "M*a*s'' + g*a*s = 0; where s = a*theta")
    assert any("M*a*s''" in d and "L^2 M T^-2" in d for d in r.dimension_issues), str(r)
    assert "theta" not in str(r), str(r)
    assert set(r.state) >= {"s", "s'"} and "theta" not in r.state, r.state
    # a map whose inverse multiplies the angles (theta = 150*s) would make the correct
    # equations cost more than the answer was allowed to: graded, and diagnosed in theta,
    # not "too costly"
    r = grade("simple_pendulum", "s'' + s = 0; where s = theta/150")
    assert r.status == "wrong" and "too costly" not in str(r), str(r)


def test_relative_coordinates_the_student_states_are_diagnosed_in_them():
    # falling_container with u = x2 - x1 (hand derivation from problems/falling_container.py's
    # Lagrangian in x1, x2): m1 x1'' - c u' - k (u - l0) + m1 g = 0 and
    # m2 (x1'' + u'') + c u' + k (u - l0) + m2 g = 0.  The damper's sign flipped in the first.
    second = "m2*(x1''+u'') + c*u' + k*(u-l0) + m2*g = 0"
    assert grade("falling_container", f"m1*x1'' - c*u' - k*(u - l0) + m1*g = 0; {second}; "
                 "where u = x2 - x1").right
    r = grade("falling_container", f"m1*x1'' + c*u' - k*(u - l0) + m1*g = 0; {second}; "
              "where u = x2 - x1")
    assert r.status == "wrong" and len(r.edits) == 1, str(r)
    (e,) = r.edits
    assert (e.kind, e.term, e.correct) == ("sign", "c*u'", "-c*u'"), str(r)
    assert "x2" not in str(r), str(r)


def test_a_map_that_is_not_invertible_is_refused_with_the_reason():
    for answer, words in [
            ("s'' = 0; where s = cos(theta)^2 + sin(theta)^2", "not invertible"),
            ("u'' + v'' = 0; where u = theta + phi, v = 2*theta + 2*phi", "not invertible"),
            ("s'' = 0; where s = theta'", "not their rates"),
            ("s'' = 0; where g = theta", "already means a parameter"),
            ("s'' = 0; where s = theta, s = phi", "defined twice"),
            ("where s = theta", "write the answer"),
            ("s'' = 0; where s", "name = expression")]:
        problem = "toy_car" if "phi" in answer else "simple_pendulum"
        r = grade(problem, answer)
        assert r.status == "invalid" and words in r.summary, (answer, r.summary)
