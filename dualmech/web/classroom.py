"""Assignments, their students and every attempt, kept in the server's SQLite file.

An assignment holds its rules (questions, feedback level, attempts, penalty, deadline, whether
each student has numbers of their own); each enrolled student a token (only its SHA-256 is
stored: the link is shown once, when the assignment is made) and their numbers; each attempt
the answer and the full grade (the feedback level is applied when it is shown, so a teacher's
statistics and a regrade see everything).

A question's score is the best over its attempts of ``score * (1 - penalty * (k - 1))`` for
the ``k``-th attempt (never below 0); the assignment's score is the mean over its questions.

An attempt is *reserved* (a row without a grade) before it is graded, under the store's lock,
so two answers sent at once cannot both take a student's last attempt; a reservation whose
grading failed is given back.

Example
-------
>>> import tempfile
>>> from dualmech.web.store import Store
>>> c = Classroom(Store(tempfile.mkdtemp()))
>>> rules = {"title": "HW1", "questions": [{"problem": "simple_pendulum", "quantity": None}],
...          "feedback": "full", "attempts": 2, "penalty": 0.25, "deadline": None,
...          "per_student_numbers": False}
>>> aid, tokens = c.create(rules, {"s1": {}})
>>> c.student(tokens["s1"]) == (aid, "s1")
True
>>> k = c.reserve(aid, "s1", 0, "x", limit=2); c.finish(k, {"status": "wrong", "score": 0.5})
>>> k = c.reserve(aid, "s1", 0, "y", limit=2); c.finish(k, {"status": "right", "score": 1.0})
>>> c.reserve(aid, "s1", 0, "z", limit=2) is None          # no attempt left
True
>>> question_score([0.5, 1.0], 0.25)                        # max(0.5, 1.0 * 0.75)
0.75
"""
from __future__ import annotations

import json
import secrets
import time

from dualmech.web.sessions import digest

__all__ = ["Classroom", "question_score"]

_SCHEMA = """
CREATE TABLE IF NOT EXISTS assignments (
    id TEXT PRIMARY KEY, created REAL NOT NULL, rules TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS enrolled (
    assignment TEXT NOT NULL REFERENCES assignments(id), student TEXT NOT NULL,
    token TEXT NOT NULL UNIQUE, numbers TEXT NOT NULL, PRIMARY KEY (assignment, student));
CREATE TABLE IF NOT EXISTS attempts (
    id INTEGER PRIMARY KEY AUTOINCREMENT, assignment TEXT NOT NULL, student TEXT NOT NULL,
    question INTEGER NOT NULL, at REAL NOT NULL, answer TEXT NOT NULL, result TEXT);
CREATE INDEX IF NOT EXISTS attempts_by_student ON attempts (assignment, student, question);
"""


def question_score(scores: list[float], penalty: float) -> float:
    """The score of a question from its attempts' scores, in order (see the module doc)."""
    return max((max(0.0, s * (1.0 - penalty * k)) for k, s in enumerate(scores)),
               default=0.0)


class Classroom:
    """Assignments in ``store``'s SQLite file (see the module docstring); thread-safe."""

    def __init__(self, store):
        self.store = store
        with store._lock:
            store._db.executescript(_SCHEMA)

    # -- assignments ----------------------------------------------------------------------------
    def create(self, rules: dict, numbers: dict[str, dict]) -> tuple[str, dict[str, str]]:
        """Store an assignment with ``rules`` and its students (``{student: numbers}``);
        ``(id, {student: token})`` -- the tokens are not kept and cannot be shown again."""
        aid = secrets.token_hex(8)
        tokens = {s: secrets.token_urlsafe(24) for s in numbers}
        db = self.store._db
        with self.store._lock:
            db.execute("BEGIN")
            try:
                db.execute("INSERT INTO assignments VALUES (?, ?, ?)",
                           (aid, time.time(), json.dumps(rules)))
                db.executemany("INSERT INTO enrolled VALUES (?, ?, ?, ?)",
                               [(aid, s, digest(tokens[s]), json.dumps(n))
                                for s, n in numbers.items()])
                db.execute("COMMIT")
            except BaseException:
                db.execute("ROLLBACK")
                raise
        return aid, tokens

    def enrol(self, aid: str, student: str, numbers: dict) -> str:
        """Enrol ``student`` in ``aid`` (kept numbers if enrolled already) with a new token,
        which is returned: a launch from a learning platform (:mod:`.lti`) rotates it."""
        token = secrets.token_urlsafe(24)
        self.store._run("INSERT INTO enrolled VALUES (?, ?, ?, ?) ON CONFLICT (assignment, "
                        "student) DO UPDATE SET token = excluded.token",
                        (aid, student, digest(token), json.dumps(numbers)))
        return token

    def rules(self, aid: str) -> dict | None:
        """The rules of assignment ``aid`` (with its ``id``), or None."""
        rows = self.store._all("SELECT rules FROM assignments WHERE id = ?", (aid,))
        return dict(json.loads(rows[0]["rules"]), id=aid) if rows else None

    def assignments(self) -> list[dict]:
        """Every assignment's rules with its number of students, newest first."""
        rows = self.store._all("SELECT id, rules, (SELECT COUNT(*) FROM enrolled WHERE "
                               "assignment = a.id) AS n FROM assignments a ORDER BY created DESC")
        return [dict(json.loads(r["rules"]), id=r["id"], students=r["n"]) for r in rows]

    def student(self, token: str) -> tuple[str, str] | None:
        """``(assignment, student)`` whose token is ``token``, or None."""
        if not token or len(token) > 200:
            return None
        rows = self.store._all("SELECT assignment, student FROM enrolled WHERE token = ?",
                               (digest(token),))
        return (rows[0]["assignment"], rows[0]["student"]) if rows else None

    def roster(self, aid: str) -> dict[str, dict]:
        """``{student: numbers}`` of assignment ``aid``, in the order they were enrolled."""
        return {r["student"]: json.loads(r["numbers"]) for r in self.store._all(
            "SELECT student, numbers FROM enrolled WHERE assignment = ? ORDER BY rowid",
            (aid,))}

    # -- attempts ---------------------------------------------------------------------------
    def reserve(self, aid: str, student: str, question: int, answer: str,
                limit: int) -> int | None:
        """Take one of ``limit`` attempts at ``question``: the attempt's id, or None when
        none is left."""
        with self.store._lock:
            used = self.store._db.execute(
                "SELECT COUNT(*) FROM attempts WHERE assignment = ? AND student = ? AND "
                "question = ?", (aid, student, question)).fetchone()[0]
            if used >= limit:
                return None
            cur = self.store._db.execute(
                "INSERT INTO attempts (assignment, student, question, at, answer, result) "
                "VALUES (?, ?, ?, ?, ?, NULL)", (aid, student, question, time.time(), answer))
            return cur.lastrowid

    def finish(self, attempt: int, result: dict) -> None:
        """Record the grade of a reserved attempt."""
        self.store._run("UPDATE attempts SET result = ? WHERE id = ?",
                        (json.dumps(result, default=str), attempt))

    def give_back(self, attempt: int) -> None:
        """Drop a reserved attempt that could not be graded."""
        self.store._run("DELETE FROM attempts WHERE id = ? AND result IS NULL", (attempt,))

    def attempts(self, aid: str, student: str | None = None) -> list[dict]:
        """The graded attempts of an assignment (of one ``student``), oldest first: dicts
        with id, student, question, at, answer, result."""
        sql = ("SELECT id, student, question, at, answer, result FROM attempts WHERE "
               "assignment = ? AND result IS NOT NULL")
        args: tuple = (aid,)
        if student is not None:
            sql, args = sql + " AND student = ?", (aid, student)
        return [dict(r, result=json.loads(r["result"]))
                for r in self.store._all(sql + " ORDER BY id", args)]

    def used(self, aid: str, student: str, count: int) -> list[int]:
        """Attempts used at each of ``count`` questions (reserved ones included)."""
        out = [0] * count
        for r in self.store._all("SELECT question, COUNT(*) AS n FROM attempts WHERE "
                                 "assignment = ? AND student = ? GROUP BY question",
                                 (aid, student)):
            if 0 <= r["question"] < count:
                out[r["question"]] = r["n"]
        return out

    def scores(self, rules: dict, attempts: list[dict]) -> list[float]:
        """Each question's score from one student's ``attempts``."""
        per: list[list[float]] = [[] for _ in rules["questions"]]
        for a in attempts:
            if 0 <= a["question"] < len(per):
                per[a["question"]].append(float(a["result"].get("score") or 0.0))
        return [round(question_score(s, rules["penalty"]), 4) for s in per]

    # -- a student's data -------------------------------------------------------------------------
    def export_student(self, student: str) -> list[dict]:
        """Everything kept about ``student``: per assignment, its title, their numbers and
        every attempt with its grade."""
        out = []
        for r in self.store._all("SELECT assignment, numbers FROM enrolled WHERE student = ? "
                                 "ORDER BY rowid", (student,)):
            rules = self.rules(r["assignment"]) or {}
            out.append({"assignment": r["assignment"], "title": rules.get("title"),
                        "numbers": json.loads(r["numbers"]),
                        "attempts": [{k: a[k] for k in ("question", "at", "answer", "result")}
                                     for a in self.attempts(r["assignment"], student)]})
        return out

    def delete_student(self, student: str) -> int:
        """Remove ``student`` from every assignment with their attempts (their links stop
        working); the number of assignments they were in."""
        with self.store._lock:
            db = self.store._db
            n = db.execute("SELECT COUNT(*) FROM enrolled WHERE student = ?",
                           (student,)).fetchone()[0]
            db.execute("DELETE FROM attempts WHERE student = ?", (student,))
            db.execute("DELETE FROM enrolled WHERE student = ?", (student,))
        return n
