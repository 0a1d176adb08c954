"""An assignment as a teacher posts it, checked field by field: :func:`read_assignment`.

Every field is checked before anything is stored, and a refusal names the field and what to
send instead (:class:`RuleError`, with the HTTP status: 400 for a wrong value, 413 for one
over its bound, 404 for a problem this server does not serve).

Example
-------
>>> served = {"my_pendulum": ["eom", "T"]}
>>> r = read_assignment({"title": "HW 1", "questions": [{"problem": "my_pendulum"}],
...                      "students": ["s1", "s2"], "deadline": "2030-01-01T09:00:00Z"},
...                     served, served.get)
>>> r["attempts"], r["feedback"], r["deadline"], r["questions"][0]["quantity"]
(3, 'full', 1893488400.0, None)
>>> read_assignment({"title": "x", "questions": [], "students": ["s"]}, served, served.get)
Traceback (most recent call last):
...
dualmech.web.rules.RuleError: `questions` must be a list of 1 to 50 objects {"problem", "quantity"}.
"""
from __future__ import annotations

import math
import unicodedata
from datetime import datetime

from dualmech.grade.result import FEEDBACK_LEVELS

__all__ = ["read_assignment", "RuleError", "MAX_STUDENTS", "MAX_QUESTIONS", "MAX_TITLE",
           "MAX_ID", "MAX_ATTEMPTS"]

MAX_STUDENTS = 2000
MAX_QUESTIONS = 50
MAX_TITLE = 200
MAX_ID = 100
MAX_ATTEMPTS = 100
_FIELDS = ("title", "questions", "students", "per_student_numbers", "feedback", "attempts",
           "penalty", "deadline")


class RuleError(ValueError):
    """A field of the assignment that cannot be used; ``status`` is the HTTP status."""

    def __init__(self, message: str, status: int = 400):
        super().__init__(message)
        self.status = status


def read_assignment(body: dict, served, quantities) -> dict:
    """The assignment's rules from a teacher's JSON ``body``; ``served`` holds the served
    problems' names, ``quantities(name)`` gives the quantities a served problem can be asked
    for (called last, after every other field is checked: it may load the problem)."""
    unknown = sorted(k for k in body if k not in _FIELDS)
    if unknown:
        raise RuleError(f"unknown field `{str(unknown[0])[:40]}`; the fields are "
                        f"{', '.join(_FIELDS)}.")
    rules = {"title": _title(body.get("title")),
             "students": _students(body.get("students")),
             "per_student_numbers": _flag(body.get("per_student_numbers", False)),
             "feedback": _feedback(body.get("feedback", "full")),
             "attempts": _whole(body.get("attempts", 3), "attempts", 1, MAX_ATTEMPTS),
             "penalty": _fraction(body.get("penalty", 0.0)),
             "deadline": _deadline(body.get("deadline"))}
    return {**rules, "questions": _questions(body.get("questions"), served, quantities)}


def _text(v, name: str, most: int) -> str:
    if not isinstance(v, str) or not v.strip():
        raise RuleError(f"`{name}` must be a non-empty string.")
    if len(v) > most:
        raise RuleError(f"`{name}` is longer than {most} characters.", 413)
    if any(unicodedata.category(c) in ("Cc", "Cf", "Cs") for c in v):
        raise RuleError(f"`{name}` holds a control or format character; send plain text.")
    return v.strip()


def _title(v) -> str:
    return _text(v, "title", MAX_TITLE)


def _questions(v, served, quantities) -> list[dict]:
    if not isinstance(v, list) or not 1 <= len(v) <= MAX_QUESTIONS:
        status = 413 if isinstance(v, list) and len(v) > MAX_QUESTIONS else 400
        raise RuleError(f"`questions` must be a list of 1 to {MAX_QUESTIONS} objects "
                        "{\"problem\", \"quantity\"}.", status)
    for i, q in enumerate(v):
        if not isinstance(q, dict) or not isinstance(q.get("problem"), str) or \
                set(q) - {"problem", "quantity"}:
            raise RuleError(f"question {i + 1} must be an object {{\"problem\": name, "
                            "\"quantity\": name or null}.")
        if q["problem"] not in served:
            shown = q["problem"] if len(q["problem"]) <= 60 else q["problem"][:60] + "..."
            raise RuleError(f"question {i + 1}: no problem {shown!r} is served here; served: "
                            f"{', '.join(served)}.", 404)
        if q.get("quantity") is not None and not isinstance(q["quantity"], str):
            raise RuleError(f"question {i + 1}: `quantity` must be null (the equations of "
                            "motion) or the name of one of the problem's quantities.")
    out = []
    for i, q in enumerate(v):
        name, quantity = q["problem"], q.get("quantity")
        if quantity is not None and quantity not in quantities(name):
            raise RuleError(f"question {i + 1}: `quantity` must be null (the equations of "
                            f"motion) or one of {name}'s: {', '.join(quantities(name))}.")
        out.append({"problem": name, "quantity": quantity})
    return out


def _students(v) -> list[str]:
    if not isinstance(v, list) or not v:
        raise RuleError("`students` must be a non-empty list of student ids (strings).")
    if len(v) > MAX_STUDENTS:
        raise RuleError(f"`students` lists {len(v)} students; at most {MAX_STUDENTS} in one "
                        "assignment.", 413)
    ids = [_text(s, "students[]", MAX_ID) for s in v]
    seen: set = set()
    for s in ids:
        if s in seen:
            raise RuleError(f"student {s!r} is listed twice; each id once.")
        seen.add(s)
    return ids


def _flag(v) -> bool:
    if not isinstance(v, bool):
        raise RuleError("`per_student_numbers` must be true or false.")
    return v


def _feedback(v) -> str:
    if v not in FEEDBACK_LEVELS:
        raise RuleError(f"`feedback` must be one of {', '.join(FEEDBACK_LEVELS)}.")
    return v


def _whole(v, name: str, lo: int, hi: int) -> int:
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        raise RuleError(f"`{name}` must be a whole number from {lo} to {hi}.")
    return v


def _fraction(v) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or \
            not 0 <= v <= 1:
        raise RuleError("`penalty` must be a number from 0 to 1: the share of a question's "
                        "score lost per attempt after the first.")
    return float(v)


def _deadline(v) -> float | None:
    if v is None:
        return None
    if not isinstance(v, str) or len(v) > 40:
        raise RuleError("`deadline` must be an ISO 8601 time with its zone, e.g. "
                        "\"2030-01-31T23:59:00+01:00\", or null.")
    try:
        when = datetime.fromisoformat(v.replace("Z", "+00:00").replace("z", "+00:00"))
    except ValueError:
        raise RuleError(f"`deadline` {v!r} is not an ISO 8601 time; e.g. "
                        "\"2030-01-31T23:59:00+01:00\".") from None
    if when.tzinfo is None:
        raise RuleError("`deadline` needs its time zone (e.g. \"Z\" or \"+01:00\"), so that "
                        "it means the same moment for every student.")
    return when.timestamp()
