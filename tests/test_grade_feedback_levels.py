"""Feedback levels a teacher sets: ``verdict`` and ``locate`` never show a correct term, ``hint``
shows the wrong term but never its correction, ``full`` is unchanged; the verdict itself never
depends on the level.  Mistakes are the grader's own generated classic mistakes
(:func:`dualmech.grade.generate.wrong_answers`), whose full feedback names the correct terms."""
import json

import pytest

from dualmech import Grader, grade
from dualmech.grade.generate import wrong_answers
from dualmech.grade.result import FEEDBACK_LEVELS

PROBLEMS = ["simple_pendulum", "toy_car", "cart_pendulum", "spring_mass_damper",
            "satellite_polar"]


def _shown(g) -> str:
    """Everything a student is shown: the text and the JSON, without the echo of the answer."""
    d = g.to_dict()
    d.pop("answer")
    return str(g) + "\n" + json.dumps(d)


def _graded(name):
    grader = Grader(name)
    out = []
    for sample in wrong_answers(grader.context)[:8]:
        full = grader.grade(sample.text)
        if full.status == "wrong":
            out.append((sample.text, full))
    assert out, f"{name}: no generated mistake graded wrong"
    return grader, out


@pytest.mark.parametrize("name", PROBLEMS)
def test_levels_below_full_never_show_the_correct_term(name):
    grader, graded = _graded(name)
    corrections = 0
    for text, full in graded:
        correct = {e.correct for e in full.edits if e.correct}
        correct_html = {e.correct_html for e in full.edits if e.correct_html}
        corrections += len(correct)
        for level in ("verdict", "locate", "hint"):
            g = grader.grade(text, feedback=level)
            assert g.status == full.status == "wrong" and g.feedback == level
            shown = _shown(g)
            for term in correct:
                assert f"`{term}`" not in shown and json.dumps(term) not in shown, (level, term)
            for html in correct_html:
                assert html not in shown, (level, html)
            assert "the right value" not in shown.replace("not the right value", "")
        located = grader.grade(text, feedback="locate")
        for e, e_full in zip(located.edits, full.edits):
            assert e.term == "" and e.correct == "" and e.kind == e_full.kind
            assert e.category == e_full.category and e.equation == e_full.equation
            assert "`" not in e.sentence()
        hinted = grader.grade(text, feedback="hint")
        for e, e_full in zip(hinted.edits, full.edits):
            assert e.correct == "" and (e.term == e_full.term or e_full.kind == "factor")
    assert corrections, f"{name}: the full feedback named no correct term to hide"


@pytest.mark.parametrize("name", PROBLEMS[:2])
def test_verdict_level_says_right_or_wrong_and_nothing_else(name):
    grader, graded = _graded(name)
    text, full = graded[0]
    g = grader.grade(text, feedback="verdict")
    assert str(g) == "WRONG: the answer is wrong"
    assert g.edits == [] and g.details == [] and g.state == {} and g.dimension_issues == []


def test_full_is_the_default_and_unchanged():
    answer = "a*theta'' - g*sin(theta) = 0"
    default, full = grade("simple_pendulum", answer), grade("simple_pendulum", answer,
                                                              feedback="full")
    assert str(default) == str(full)
    assert any(e.correct == "g*sin(theta)" for e in full.edits)


def test_a_right_answer_is_right_at_every_level():
    for level in FEEDBACK_LEVELS:
        assert grade("simple_pendulum", "a*theta'' + g*sin(theta) = 0", feedback=level).right


def test_an_invalid_answer_keeps_its_reason_at_every_level():
    for level in FEEDBACK_LEVELS:
        g = grade("simple_pendulum", "a*theta'' + (g = 0", feedback=level)
        assert g.status == "invalid" and g.summary


@pytest.mark.parametrize("level", ["", "FULL", "everything", None])
def test_an_unknown_level_is_refused_clearly(level):
    with pytest.raises(ValueError, match="`feedback` must be one of verdict, locate, hint, full"):
        grade("simple_pendulum", "a*theta'' = 0", feedback=level)


def test_the_command_takes_the_level_and_hides_the_correction(capsys):
    from dualmech.cli.main import main
    status = main(["grade", "simple_pendulum", "--answer", "a*theta'' - g*sin(theta) = 0",
                   "--feedback", "locate"])
    out = capsys.readouterr().out
    assert status == 1
    assert "a term has the wrong sign (a gravity term)" in out and "`" not in out
    status = main(["grade", "simple_pendulum", "--answer", "a*theta'' = 0", "--feedback", "all"])
    assert status == 2 and "invalid choice: 'all'" in capsys.readouterr().err


def test_an_answer_that_cannot_be_graded_says_so_on_stderr_too(capsys):
    from dualmech.cli.main import main
    status = main(["grade", "simple_pendulum", "--answer", "simple_pendulum"])
    captured = capsys.readouterr()
    assert status == 2 and "NOT GRADED" in captured.out
    assert "could not be graded as typed" in captured.err
