"""The matcher shared by the student-answer corpus tests (``tests/corpus/student_answers*.toml``).

An answer is graded as its ``quantity`` (default: the equations of motion, or one equation),
linearised ``about`` an equilibrium when it says so.  Measured per answer: accepted or
rejected as expected, every injected mistake named (the edit of that kind on that term, with
the right kind of term in physics words; when no small edit exists, the closest equation and
the kinds of term that differ; for an incomplete set, what is missing), and no term named that
is not one of the mistakes.  A term is compared with the expected one by value at random real
points (a test's matcher, not a verdict).
"""
from __future__ import annotations

import random
import tomllib
from dataclasses import replace
from pathlib import Path

import sympy as sp

from dualmech.grade import Grader
from dualmech.grade.formula import Formula
from dualmech.grade.parser import LIMITS, parse

CORPUS_DIR = Path(__file__).resolve().parent / "corpus"

_graders: dict = {}


def load(name: str) -> list[dict]:
    """The answers of ``tests/corpus/<name>``."""
    return tomllib.loads((CORPUS_DIR / name).read_text(encoding="utf-8"))["answer"]


def grader(problem: str) -> Grader:
    """The grader of ``problem``: a catalogue name, or a teacher's file given by its path
    under ``tests/corpus/`` (graded as the ``dualmech grade path/to/file.py`` command does)."""
    if problem not in _graders:
        spec = str(CORPUS_DIR / problem) if problem.endswith(".py") else problem
        # the corpus asks for verdicts, not speed: a generous wall-clock ceiling, so that a
        # stall of a loaded machine is not read as "too costly" (the ceiling's own behaviour
        # is tested with hostile answers, tests/test_grade_safety.py and the fuzz tests)
        _graders[problem] = Grader(spec, limits=replace(LIMITS, seconds=60.0))
    return _graders[problem]


def _read(g: Grader, text: str):
    return Formula.from_node(parse(text)[0].lhs, g.context.vocabulary).sympy()


def _same(a, b) -> bool:
    """``a == b`` at three random real points (both plain sympy expressions)."""
    syms = sorted(a.free_symbols | b.free_symbols, key=str)
    rng = random.Random(7)
    for _ in range(3):
        point = {s: sp.Float(rng.uniform(0.3, 1.7)) for s in syms}
        x, y = complex(a.evalf(subs=point)), complex(b.evalf(subs=point))
        if abs(x - y) > 1e-9 * (1 + abs(x) + abs(y)):
            return False
    return True


def _names(g, edit, mistake) -> bool:
    """Whether ``edit`` is the injected ``mistake`` (its kind, on its term)."""
    if edit.kind not in mistake["kind"]:
        return False
    text = edit.correct if edit.kind == "missing" else edit.term
    try:
        got = _read(g, text)
    except Exception:
        return False
    return any(_same(got, _read(g, t)) for t in mistake["term"])


def judge(entry) -> dict:
    """Counts for one answer: accepted/rejected, mistakes named, terms named wrongly."""
    gr = grader(entry["problem"])
    g = gr.grade(entry["text"], entry.get("quantity"), entry.get("about"))
    mistakes = entry.get("mistakes", [])
    out = {"right": not mistakes, "ok": g.right == (not mistakes), "mistakes": len(mistakes),
           "named": 0, "wrong_terms": [], "wrong_kinds": [], "grade": str(g),
           "status": g.status}
    if not mistakes or g.right:
        return out
    first = mistakes[0]
    if first["kind"] == ["value"]:   # one wrong number (a printed result): nothing to name
        out["mistakes"] = 0
        return out
    if first["kind"] == ["words"]:   # a slip no term edit shows, said in words
        text = " ".join([g.summary] + list(g.details))
        out["named"] = int(all(w in text for w in first["words"]))
        return out
    if first["kind"] == ["none"]:
        text = " ".join(g.details)
        if not g.edits and first["equation"] in text and all(k in text for k in first["kinds"]):
            out["named"] = 1
        out["wrong_terms"] = [e.sentence() for e in g.edits]
        return out
    if first["kind"] == ["incomplete"]:
        out["named"] = int(all(w in g.summary for w in first["words"]))
        return out
    left, edits = list(mistakes), list(g.edits)
    for m in [m for m in mistakes if "right" in m]:   # a replaced term as extra + missing
        pair = _pair(gr, edits, m)
        if pair:
            for e in pair:
                edits.remove(e)
            left.remove(m)
            _kind(out, pair[0], m)
    for e in edits:
        hit = next((m for m in left if _names(gr, e, m)), None)
        if hit is None:
            out["wrong_terms"].append(e.sentence())
            continue
        left.remove(hit)
        _kind(out, e, hit)
    return out


def _pair(g, edits, m):
    """``(extra, missing)`` edits that together replace ``m``'s term by its ``right`` one."""
    extra = [e for e in edits if _names(g, e, dict(m, kind=["extra"]))]
    missing = [e for e in edits if _names(g, e, dict(m, kind=["missing"], term=m["right"]))]
    return (extra[0], missing[0]) if extra and missing else None


def _kind(out, e, m) -> None:
    """A named mistake counts when its kind of term is right; a wrong kind named with
    certainty (no "or") is recorded."""
    wanted = m["category"] if isinstance(m["category"], list) else [m["category"]]
    if e.category in wanted:
        out["named"] += 1
    elif " or " not in e.category:
        out["wrong_kinds"].append(f"{e.sentence()} (expected {' or '.join(wanted)})")


def figures(results) -> dict:
    """The corpus's figures: right accepted, wrong rejected, mistakes named."""
    right = [r for _, r in results if r["right"]]
    wrong = [r for _, r in results if not r["right"]]
    return {"right accepted": (sum(r["ok"] for r in right), len(right)),
            "wrong rejected": (sum(r["ok"] for r in wrong), len(wrong)),
            "mistakes named": (sum(r["named"] for r in wrong), sum(r["mistakes"] for r in wrong)),
            "answers with a wrong term named": sum(bool(r["wrong_terms"]) for r in wrong),
            "answers with a wrong kind named": sum(bool(r["wrong_kinds"]) for r in wrong)}
