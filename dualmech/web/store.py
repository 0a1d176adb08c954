"""Batches, their rows and results, and the answers typed on the page, kept in SQLite.

One file, ``grades.sqlite3``, in the server's data directory (standard-library ``sqlite3``, in
WAL mode so a reader never waits for the grader).  A row's result is written the moment it is
graded, so a server stopped half-way through a batch loses nothing: on restart
:meth:`Store.pending` gives exactly the rows still to grade and the batch goes on.

Example
-------
>>> import tempfile
>>> store = Store(tempfile.mkdtemp())
>>> b = store.add_batch("class.csv", [{"id": "s1", "question": "simple_pendulum",
...                                    "answer": "a*theta'' + g*sin(theta)", "line": 2}])
>>> [r["idx"] for r in store.pending(b)], store.progress(b)["done"]
([0], 0)
>>> store.put_result(b, 0, {"status": "right"}); store.progress(b)["status"]
'done'
"""
from __future__ import annotations

import json
import os
import secrets
import sqlite3
import threading
import time
from pathlib import Path

__all__ = ["Store", "default_data_dir"]


def default_data_dir() -> Path:
    """The user's data folder for dualmech (``~/.local/share/dualmech`` on Linux, as
    :func:`platformdirs.user_data_dir` says for each system), where the server keeps its data
    unless told otherwise."""
    import platformdirs
    return Path(platformdirs.user_data_dir("dualmech", appauthor=False))

_SCHEMA = """
CREATE TABLE IF NOT EXISTS batches (
    id TEXT PRIMARY KEY, name TEXT NOT NULL, created REAL NOT NULL, total INTEGER NOT NULL,
    status TEXT NOT NULL, finished REAL);
CREATE TABLE IF NOT EXISTS rows (
    batch TEXT NOT NULL REFERENCES batches(id), idx INTEGER NOT NULL, line INTEGER,
    student TEXT NOT NULL, question TEXT NOT NULL, answer TEXT NOT NULL, quantity TEXT,
    about TEXT, result TEXT, PRIMARY KEY (batch, idx));
CREATE TABLE IF NOT EXISTS answers (
    id INTEGER PRIMARY KEY AUTOINCREMENT, at REAL NOT NULL, problem TEXT NOT NULL,
    quantity TEXT, answer TEXT NOT NULL, status TEXT NOT NULL, result TEXT NOT NULL);
"""


class Store:
    """The server's state in ``DIR/grades.sqlite3`` (see the module docstring); thread-safe."""

    def __init__(self, directory: str | os.PathLike):
        self.directory = Path(directory)
        self.directory.mkdir(parents=True, exist_ok=True)
        self.path = self.directory / "grades.sqlite3"
        self._lock = threading.Lock()
        self._db = sqlite3.connect(self.path, check_same_thread=False, isolation_level=None)
        self._db.row_factory = sqlite3.Row
        with self._lock:
            self._db.execute("PRAGMA journal_mode=WAL")
            self._db.execute("PRAGMA synchronous=NORMAL")
            self._db.executescript(_SCHEMA)

    def _all(self, sql: str, args: tuple = ()) -> list[sqlite3.Row]:
        with self._lock:
            return self._db.execute(sql, args).fetchall()

    def _run(self, sql: str, args: tuple = ()) -> None:
        with self._lock:
            self._db.execute(sql, args)

    # -- batches ----------------------------------------------------------------------------
    def add_batch(self, name: str, rows: list[dict]) -> str:
        """Store a new batch of ``rows`` (id, question, answer[, quantity, about, line]);
        return its id (random, unguessable)."""
        bid = secrets.token_hex(8)
        with self._lock:
            self._db.execute("BEGIN")
            try:
                self._db.execute("INSERT INTO batches VALUES (?, ?, ?, ?, 'grading', NULL)",
                                 (bid, name[:200], time.time(), len(rows)))
                self._db.executemany(
                    "INSERT INTO rows VALUES (?, ?, ?, ?, ?, ?, ?, ?, NULL)",
                    [(bid, i, r.get("line"), str(r.get("id", "")), str(r.get("question", "")),
                      str(r.get("answer", "")), (r.get("quantity") or "").strip() or None,
                      (r.get("about") or "").strip() or None) for i, r in enumerate(rows)])
                self._db.execute("COMMIT")
            except BaseException:
                self._db.execute("ROLLBACK")
                raise
        return bid

    def batches(self) -> list[dict]:
        """Every batch, newest first, with its progress."""
        rows = self._all("SELECT id FROM batches ORDER BY created DESC")
        return [self.progress(r["id"]) for r in rows]

    def unfinished(self) -> list[str]:
        """Ids of the batches still grading (oldest first): the ones to resume."""
        return [r["id"] for r in self._all(
            "SELECT id FROM batches WHERE status = 'grading' ORDER BY created")]

    def progress(self, bid: str) -> dict | None:
        """``{"id", "name", "created", "total", "done", "status", "finished"}`` or None."""
        rows = self._all("SELECT *, (SELECT COUNT(*) FROM rows WHERE batch = b.id AND result "
                         "IS NOT NULL) AS done FROM batches b WHERE id = ?", (bid,))
        if not rows:
            return None
        r = rows[0]
        return {"id": r["id"], "name": r["name"], "created": r["created"], "total": r["total"],
                "done": r["done"], "status": r["status"], "finished": r["finished"]}

    def pending(self, bid: str) -> list[dict]:
        """The rows of batch ``bid`` not graded yet, in order."""
        return [dict(r) for r in self._all(
            "SELECT idx, line, student, question, answer, quantity, about FROM rows "
            "WHERE batch = ? AND result IS NULL ORDER BY idx", (bid,))]

    def put_result(self, bid: str, idx: int, result: dict) -> None:
        """Record the result of row ``idx``; the batch is done when its last row is."""
        with self._lock:
            self._db.execute("UPDATE rows SET result = ? WHERE batch = ? AND idx = ?",
                             (json.dumps(result, default=str), bid, idx))
            left = self._db.execute("SELECT COUNT(*) FROM rows WHERE batch = ? AND result IS "
                                    "NULL", (bid,)).fetchone()[0]
            if left == 0:
                self._db.execute("UPDATE batches SET status = 'done', finished = ? WHERE id = ? "
                                 "AND status = 'grading'", (time.time(), bid))

    def results(self, bid: str) -> list[dict]:
        """The graded rows of batch ``bid``, in input order (each the grade's JSON with
        ``id``, ``question`` and ``line``)."""
        return [json.loads(r["result"]) for r in self._all(
            "SELECT result FROM rows WHERE batch = ? AND result IS NOT NULL ORDER BY idx",
            (bid,))]

    def student_rows(self, student: str) -> list[dict]:
        """Every row of an uploaded batch with ``student``'s id: batch, line, question,
        answer and result."""
        return [dict(r, result=json.loads(r["result"]) if r["result"] else None)
                for r in self._all("SELECT batch, line, question, answer, quantity, about, "
                                   "result FROM rows WHERE student = ? ORDER BY batch, idx",
                                   (student,))]

    def delete_student_rows(self, student: str) -> int:
        """Remove ``student``'s rows from every batch (each batch's total follows); how many."""
        with self._lock:
            batches = [r[0] for r in self._db.execute(
                "SELECT DISTINCT batch FROM rows WHERE student = ?", (student,))]
            n = self._db.execute("DELETE FROM rows WHERE student = ?", (student,)).rowcount
            for b in batches:
                self._db.execute("UPDATE batches SET total = (SELECT COUNT(*) FROM rows WHERE "
                                 "batch = ?) WHERE id = ?", (b, b))
        return n

    # -- answers typed on the page ------------------------------------------------------------
    def add_answer(self, result: dict) -> None:
        """Keep one graded answer from the page (for the teacher's view of the class)."""
        self._run("INSERT INTO answers (at, problem, quantity, answer, status, result) "
                  "VALUES (?, ?, ?, ?, ?, ?)",
                  (time.time(), str(result.get("problem", "")), result.get("quantity"),
                   str(result.get("answer", ""))[:5000], str(result.get("status", "")),
                   json.dumps(result, default=str)))

    def answers(self, limit: int = 5000) -> list[dict]:
        """The latest answers typed on the page, oldest first."""
        rows = self._all("SELECT result FROM answers ORDER BY id DESC LIMIT ?", (limit,))
        return [json.loads(r["result"]) for r in reversed(rows)]

    def close(self) -> None:
        with self._lock:
            self._db.close()
