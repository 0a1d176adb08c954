"""A class's CSV graded in the background, row by row, through the bounded grading pool.

An upload is read by the batch grader's own reader (:func:`dualmech.grade.batch.read_csv`,
from a file the server names in its data directory -- never a path from the client), checked
against :data:`MAX_ROWS`, stored, and graded by :class:`BatchRunner`: one thread that keeps a
bounded number of answers in the :class:`~dualmech.grade.sandbox.GradingPool` and writes each
result to the :class:`~.store.Store` as it arrives.  A batch left half-graded by a stopped
server is picked up where it stopped when the next runner starts.

A question names a problem *served by this server* (``name`` or ``name:quantity``); any other
name is refused row by row, so a CSV can never make the server load a problem of its choice.

Example
-------
>>> split_question({"question": "toy_car:F_r"}), split_question({"question": "toy_car",
...                                                               "quantity": "eom"})
(('toy_car', 'F_r'), ('toy_car', 'eom'))
"""
from __future__ import annotations

import os
import re
import tempfile
import threading
from concurrent.futures import Future

from dualmech.grade.batch import BatchError, read_csv

__all__ = ["BatchRunner", "read_upload", "split_question", "MAX_ROWS", "BatchError"]

#: Most answers in one uploaded batch.
MAX_ROWS = 5000


def split_question(row: dict) -> tuple[str, str | None]:
    """``(problem name, quantity or None)`` of a batch row (``question`` is ``name`` or
    ``name:quantity``; a ``quantity`` column wins)."""
    name, _, quantity = (row.get("question") or "").strip().partition(":")
    quantity = (row.get("quantity") or "").strip() or quantity.strip() or None
    return name.strip(), quantity


def read_upload(data: bytes, filename: str, directory: str | os.PathLike) -> list[dict]:
    """Rows of an uploaded CSV (``data``), read by the batch grader's reader; ``BatchError``
    says what is wrong with the file, naming it as the client did (``filename``)."""
    shown = re.sub(r"[^\w.\- ]", "_", os.path.basename(filename or "upload.csv"))[:80] or \
        "upload.csv"
    os.makedirs(directory, exist_ok=True)
    fd, path = tempfile.mkstemp(suffix=".csv", dir=directory)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        try:
            rows = read_csv(path)
        except BatchError as exc:
            raise BatchError(str(exc).replace(path, shown)) from None
    finally:
        os.unlink(path)
    if len(rows) > MAX_ROWS:
        raise BatchError(f"{shown}: {len(rows)} answers; at most {MAX_ROWS} are graded in one "
                         "batch (split the file).")
    return rows


class BatchRunner:
    """Grades stored batches in the background (see the module docstring).

    ``served`` maps the problem names clients may use to the specs the pool loads;
    ``inflight`` bounds the answers waiting in the pool at once, so a large batch never
    crowds out the students typing on the page.
    """

    def __init__(self, store, pool, served: dict[str, str], inflight: int = 4):
        self.store = store
        self.pool = pool
        self.served = served
        self.inflight = max(1, inflight)
        self._busy = 0
        self._cond = threading.Condition()
        self._wake = threading.Event()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, name="dualmech-batches",
                                        daemon=True)

    def start(self) -> "BatchRunner":
        """Start grading; batches left unfinished by an earlier run are resumed first."""
        self._thread.start()
        return self

    def notify(self) -> None:
        """A new batch was stored."""
        self._wake.set()

    def close(self, timeout: float = 10.0) -> None:
        """Stop after the answers in flight (their results are kept)."""
        self._stop.set()
        self._wake.set()
        with self._cond:
            self._cond.notify_all()
        if self._thread.is_alive():
            self._thread.join(timeout)

    def _loop(self) -> None:
        while not self._stop.is_set():
            worked = False
            for bid in self.store.unfinished():
                if self._stop.is_set():
                    break
                self._grade(bid)
                worked = True
            if not worked:
                self._wake.wait(1.0)
                self._wake.clear()

    def _grade(self, bid: str) -> None:
        for row in self.store.pending(bid):
            with self._cond:
                self._cond.wait_for(lambda: self._busy < self.inflight)
                if self._stop.is_set():
                    break
                self._busy += 1
            try:
                future = self._submit(row)
            except Exception:   # the pool refused (it is closing): the row stays pending
                self._release()
                break
            future.add_done_callback(lambda f, b=bid, r=row: self._done(b, r, f))
        with self._cond:    # this batch's answers are in before the next look
            self._cond.wait_for(lambda: self._busy == 0)

    def _release(self) -> None:
        with self._cond:
            self._busy -= 1
            self._cond.notify_all()

    def _submit(self, row: dict) -> Future:
        name, quantity = split_question({"question": row["question"],
                                         "quantity": row.get("quantity")})
        spec = self.served.get(name)
        if spec is None:
            f: Future = Future()
            f.set_result(_not_served(name, quantity, row["answer"], self.served))
            return f
        return self.pool.submit(spec, row["answer"], quantity, row.get("about"))

    def _done(self, bid: str, row: dict, future: Future) -> None:
        try:
            grade = future.result()
            result = grade if isinstance(grade, dict) else grade.to_dict()
        except Exception as exc:   # the contract says never; recorded, never lost
            result = _invalid(row, f"could not grade this answer ({type(exc).__name__}).")
        result = dict(result, id=row["student"], question=row["question"], line=row["line"])
        try:
            self.store.put_result(bid, row["idx"], result)
        finally:
            self._release()


def _not_served(name: str, quantity, answer: str, served: dict) -> dict:
    return _invalid({"question": name, "quantity": quantity, "answer": answer},
                    f"no problem `{name}` is served here; served: {', '.join(sorted(served))}.")


def _invalid(row: dict, summary: str) -> dict:
    name, quantity = split_question(row)
    return {"problem": name, "quantity": quantity or "auto", "kind": "",
            "answer": row.get("answer", ""), "status": "invalid", "right": False,
            "summary": summary, "details": [], "edits": [], "dimension_issues": [],
            "matches": "", "state": {}, "method": "none", "false_right_bound": None,
            "seconds": 0.0}
