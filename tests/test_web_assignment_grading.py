"""Assignments graded for real: the grading pool, each student's own numbers, the rules.

The reference is the simple pendulum's equation of motion ``a*theta'' + g*sin(theta) = 0``
(Cambridge 3C5, Lagrangian mechanics, section 2.2; the problem module's own doctest): at a
student's numbers it is right written with their numbers, with the names, or with the
exact quotient ``g/a``, and wrong with another student's numbers or a rounded quotient.
"""
from __future__ import annotations

from fractions import Fraction

import pytest

pytest.importorskip("starlette")
from starlette.testclient import TestClient  # noqa: E402

from dualmech.web import create_app  # noqa: E402

TOKEN = "assignment-grading-token"
AUTH = {"Authorization": f"Bearer {TOKEN}"}


@pytest.fixture(scope="module")
def class_(tmp_path_factory):
    app = create_app(["simple_pendulum"], data=tmp_path_factory.mktemp("graded"),
                     token=TOKEN, workers=1, rates={}, grade_seconds=5.0)
    with TestClient(app) as c:
        made = c.post("/api/assignments", json={
            "title": "Pendulum", "questions": [{"problem": "simple_pendulum"}],
            "students": ["ada", "bob", "cy"], "per_student_numbers": True,
            "feedback": "locate", "attempts": 3, "penalty": 0.5}, headers=AUTH).json()
        yield c, made


def _as(made, student):
    return {"Authorization": f"Bearer {made['students'][student]['token']}"}


def _numbers(c, made, student):
    return c.get(f"/api/assignments/{made['id']}/me", headers=_as(made, student)).json()[
        "numbers"]


def _send(c, made, student, answer):
    r = c.post(f"/api/assignments/{made['id']}/answers", json={"question": 0,
                                                              "answer": answer},
               headers=_as(made, student))
    assert r.status_code == 200, r.text
    return r.json()


@pytest.mark.slow
def test_each_student_is_graded_exactly_at_their_own_numbers(class_):
    c, made = class_
    ada, bob = _numbers(c, made, "ada"), _numbers(c, made, "bob")
    # only g/a matters to the pendulum: bob's ratio differs from ada's (drawn independently)
    assert Fraction(ada["g"]) / Fraction(ada["a"]) != Fraction(bob["g"]) / Fraction(bob["a"])

    g = first = _send(c, made, "ada", f"{bob['a']}*theta'' + {bob['g']}*sin(theta) = 0")
    assert g["status"] == "wrong" and g["attempt"] == 1 and g["attempts_left"] == 2
    # the feedback level is `locate`: which kind of term, never the term itself
    assert g["feedback"] == "locate" and all(e["term"] == "" and e["correct"] == ""
                                              for e in g["edits"])
    # the quotient rounded to 6 decimals: wrong, the test is exact (unless it terminates)
    ratio = Fraction(ada["g"]) / Fraction(ada["a"])
    rounded = Fraction(round(ratio * 10 ** 6), 10 ** 6)
    assert rounded != ratio
    g = second = _send(c, made, "ada", f"theta'' = -{float(rounded):.6f}*sin(theta)")
    assert g["status"] == "wrong" and second["score"] < 1
    g = _send(c, made, "ada", f"{ada['a']}*theta'' + {ada['g']}*sin(theta) = 0")
    assert g["status"] == "right" and g["attempt"] == 3 and g["attempts_left"] == 0
    # the wrong attempts have the grader's partial credit (a wrong coefficient); the third,
    # right, is worth 1 * (1 - 0.5 * 2) = 0: the best of the three counts
    assert g["question_score"] == max(first["score"], second["score"] * 0.5, 0.0) < 1
    r = c.post(f"/api/assignments/{made['id']}/answers", json={"question": 0, "answer": "x"},
               headers=_as(made, "ada"))
    assert r.status_code == 409

    # bob: the names, and the exact quotient of his numbers, are right at the first try
    g = _send(c, made, "bob", "a*theta'' + g*sin(theta) = 0")
    assert g["status"] == "right" and g["question_score"] == 1.0
    g = _send(c, made, "bob", f"theta'' = -({bob['g']}/{bob['a']})*sin(theta)")
    assert g["status"] == "right"
    me = c.get(f"/api/assignments/{made['id']}/me", headers=_as(made, "bob")).json()
    assert me["score"] == 1.0 and me["attempts_left"] == [1]
    assert me["questions"][0]["last"]["status"] == "right"


@pytest.mark.slow
def test_regrade_reports_what_changed(class_):
    c, made = class_
    _send(c, made, "cy", "a*theta'' - g*sin(theta) = 0")
    srv = c.app.state.server
    # a grade recorded by a faulty grader (as before a problem's fix): cy's wrong answer
    # kept as right
    row = [a for a in srv.classroom.attempts(made["id"], "cy")][0]
    srv.classroom.finish(row["id"], {"full": {"status": "right", "edits": []},
                                     "shown": {"status": "right"}, "score": 1.0})
    r = c.post(f"/api/assignments/{made['id']}/regrade", headers=AUTH)
    assert r.status_code == 200
    out = r.json()
    assert out["regraded"] == len(srv.classroom.attempts(made["id"]))
    assert out["changed"] == [{"student": "cy", "question": 0,
                               "answer": "a*theta'' - g*sin(theta) = 0", "before": "right",
                               "after": "wrong", "score_before": 1.0, "score_after": 0.5}]
    assert c.post(f"/api/assignments/{made['id']}/regrade", headers=AUTH).json()[
        "changed"] == []
    stats = c.get(f"/api/assignments/{made['id']}/stats", headers=AUTH).json()
    assert stats["students"]["cy"] == {"attempts": [1], "scores": [0.5], "total": 0.5}
    assert {"mistake": "gravity sign", "attempts": 1, "students": 1} in \
        stats["questions"][0]["mistakes"]


def test_a_personal_grader_in_process_names_the_kind_of_term_and_checks_its_numbers():
    from dualmech.grade.context import GradingUnavailable
    from dualmech.grade.parser import LIMITS
    from dualmech.web.numbers import Personal
    grader = Personal.of("simple_pendulum", {"M": "1.5", "a": "0.75", "g": "9.81"}).grader(
        LIMITS)
    assert grader.grade("0.75*theta'' + 9.81*sin(theta) = 0").status == "right"
    assert grader.grade("theta'' = -13.08*sin(theta)").status == "right"   # 9.81/0.75
    assert grader.grade("theta'' = -13.1*sin(theta)").status == "wrong"
    g = grader.grade("0.75*theta'' - 9.81*sin(theta) = 0", feedback="locate")
    assert [e.sentence() for e in g.edits] == ["a term has the wrong sign (a gravity term)"]
    with pytest.raises(GradingUnavailable, match="simple_pendulum` has the parameters M, a, g"):
        Personal.of("simple_pendulum", {"a": "0.75", "g": "9.81", "k": "2"}).grader(LIMITS)
