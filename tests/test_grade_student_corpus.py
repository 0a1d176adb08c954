"""The grader on a corpus of students' answers typed as students type them
(``tests/corpus/student_answers.toml``: right forms derived by hand from each problem's
statement, wrong ones with mistakes injected by hand, across 17 catalogue problems).

Measured: right answers accepted, wrong ones rejected, every injected mistake named (the edit
of that kind on that term, with the right kind of term in physics words; or, when no small
edit exists, the closest equation and the kinds of term that differ), and no term named that
is not one of the mistakes.  A term is compared with the expected one by value at random
real points (a test's matcher, not a verdict).
"""
from __future__ import annotations

import pytest

import _student_corpus as corpus

ANSWERS = corpus.load("student_answers.toml")


@pytest.fixture(scope="module")
def results():
    return [(entry, corpus.judge(entry)) for entry in ANSWERS]


def test_the_corpus_is_what_the_issue_asks_for():
    problems = {e["problem"] for e in ANSWERS}
    wrong = [e for e in ANSWERS if e.get("mistakes")]
    assert len(ANSWERS) >= 60 and len(problems) >= 10 and len(wrong) >= 40
    styles = {"latex": "\\", "unicode": "θ", "dots": "ddot", "primes": "''"}
    for key, mark in styles.items():
        assert any(mark in e["text"] for e in ANSWERS), key


def test_right_answers_are_accepted(results):
    bad = [(e["problem"], e["text"], r["grade"]) for e, r in results if r["right"] and not r["ok"]]
    assert not bad, bad


def test_wrong_answers_are_rejected(results):
    bad = [(e["problem"], e["text"]) for e, r in results if not r["right"] and not r["ok"]]
    assert not bad, bad


def test_every_mistake_is_named(results):
    """The issue's target: every mistake named >= 95 % (here: all of them)."""
    total = sum(r["mistakes"] for _, r in results)
    named = sum(r["named"] for _, r in results)
    missed = [(e["text"], r["grade"]) for e, r in results if r["named"] < r["mistakes"]]
    assert named / total >= 0.95, (named, total, missed)
    assert named == total, missed


def test_no_wrong_term_is_named_with_certainty(results):
    terms = [(e["text"], r["wrong_terms"]) for e, r in results if r["wrong_terms"]]
    kinds = [(e["text"], r["wrong_kinds"]) for e, r in results if r["wrong_kinds"]]
    assert not terms, terms
    assert not kinds, kinds
