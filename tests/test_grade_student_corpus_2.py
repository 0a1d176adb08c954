"""The grader on a second corpus of students' answers (``tests/corpus/student_answers_2.toml``),
written independently of the first: 20 catalogue problems, 11 of them not in the first corpus,
and the quantities the first does not ask -- reactions, kinetic and potential energies,
Lagrangians, generalised forces, accelerations, linearisations about an equilibrium, a
constrained system with its multiplier, printed results -- typed as students type them (dots,
primes, LaTeX with implicit products such as ``ml^2`` and ``\\frac{ML^3}{6}``, Unicode with
``ẍ1``, ``θ₂``, ``½``, ``·``, ``−``).  Every verdict in the file is derived by hand from the
problem's statement (the file's header lists the right forms and the source pages).

Measured (``tests/_student_corpus.py``): right answers accepted, wrong ones rejected, each
injected mistake named with its kind of term, and no other term or kind named.
"""
from __future__ import annotations

import pytest

import _student_corpus as corpus

ANSWERS = corpus.load("student_answers_2.toml")



@pytest.fixture(scope="module")
def results():
    return [(entry, corpus.judge(entry)) for entry in ANSWERS]


def test_the_corpus_is_what_the_issue_asks_for():
    problems = {e["problem"] for e in ANSWERS}
    first = {e["problem"] for e in corpus.load("student_answers.toml")}
    wrong = [e for e in ANSWERS if e.get("mistakes")]
    assert len(ANSWERS) >= 150 and len(problems) >= 15 and len(problems - first) >= 10
    assert len(wrong) >= 75 and sum(len(e["mistakes"]) > 1 for e in wrong) >= 8
    quantities = {e.get("quantity", "eom") for e in ANSWERS}
    assert {"KE", "PE", "L", "linearised", "Q_beta", "N", "S"} <= quantities
    styles = {"latex": "\\", "unicode dots": "̈", "unicode minus": "−", "primes": "''",
              "dots": "ddot", "implicit product": "ml^2", "subscript digit": "₂"}
    for key, mark in styles.items():
        assert any(mark in e["text"] for e in ANSWERS), key


def test_right_answers_are_accepted(results):
    bad = [(e["problem"], e["text"], r["grade"]) for e, r in results if r["right"] and not r["ok"]]
    assert not bad, bad


def test_wrong_answers_are_rejected(results):
    bad = [(e["problem"], e["text"], r["grade"]) for e, r in results
           if not r["right"] and not r["ok"]]
    assert not bad, bad


def test_every_mistake_is_named(results):
    missed = {(e["problem"], e["text"]): r["grade"] for e, r in results
              if r["named"] < r["mistakes"]}
    total = sum(r["mistakes"] for _, r in results)
    named = sum(r["named"] for _, r in results)
    assert named / total >= 0.95, (named, total)
    assert not missed, missed


def test_no_wrong_kind_is_named_with_certainty(results):
    kinds = [(e["text"], r["wrong_kinds"]) for e, r in results if r["wrong_kinds"]]
    assert not kinds, kinds


def test_no_other_term_is_named(results):
    terms = [(e["problem"], e["text"], r["wrong_terms"]) for e, r in results
             if r["wrong_terms"]]
    assert not terms, terms
