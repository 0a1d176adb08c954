"""Grading a class: a CSV of answers, on every core or on a Dask cluster, with a progress bar.

The CSV has a header with the columns ``id`` (the student), ``question`` and ``answer``, and
optionally ``quantity`` and ``about``; ``question`` is a problem name, or ``name:quantity``
(``toy_car:F_r``).  An answer may span several lines (quoted, as CSV allows) to give a set of
equations.

Every answer is graded under a wall-clock and memory ceiling (1 s and 256 MB above the
worker's size): locally by a :class:`~.sandbox.GradingPool` of ``workers`` processes, which
stay warm (each loads a problem's points once), or on ``dask.distributed`` (``scheduler``, the
address of a running scheduler), which maps the pure function :func:`grade_rows` over chunks of
rows grouped by question.  A bad row -- an unknown problem, a hostile answer, one that overruns
the ceiling -- gets its own "not graded" result and the batch goes on.

Example
-------
>>> rows = [{"id": "s1", "question": "simple_pendulum", "answer": "a*theta'' + g*sin(theta)"},
...         {"id": "s2", "question": "simple_pendulum", "answer": "a*theta'' - g*sin(theta)"}]
>>> [r["status"] for r in grade_batch(rows, workers=1, progress=False)]
['right', 'wrong']
"""
from __future__ import annotations

import csv
import os
from pathlib import Path
from typing import Iterable, Sequence

from dualmech.grade.api import Grader
from dualmech.grade.parser import LIMITS, Limits

__all__ = ["read_csv", "grade_rows", "grade_batch", "BatchError", "warm", "warm_targets"]

_CHUNK = 20
_REQUIRED = ("id", "question", "answer")


class BatchError(ValueError):
    """A batch file that cannot be read; the message says what to fix."""


def read_csv(path: str | os.PathLike) -> list[dict]:
    """Rows of a batch CSV, each with ``line`` (its line number) added."""
    path = Path(path)
    try:
        with path.open(newline="", encoding="utf-8") as fh:
            reader = csv.DictReader(fh)
            header = [h.strip() for h in (reader.fieldnames or [])]
            missing = [c for c in _REQUIRED if c not in header]
            if missing:
                raise BatchError(f"{path}: the header must have the columns id, question, "
                                 f"answer (optional: quantity, about); missing "
                                 f"{', '.join(missing)}; found {', '.join(header) or 'none'}.")
            rows = []
            for row in reader:
                row = {(k or "").strip(): (v or "") for k, v in row.items()}
                row["line"] = reader.line_num
                rows.append(row)
    except FileNotFoundError:
        raise BatchError(f"{path}: no such file.") from None
    except UnicodeDecodeError as exc:
        raise BatchError(f"{path}: not UTF-8 text ({exc.reason}).") from None
    except csv.Error as exc:
        raise BatchError(f"{path}: not a valid CSV file ({exc}).") from None
    if not rows:
        raise BatchError(f"{path}: no answers (only a header, or empty).")
    return rows


def _question(row: dict) -> tuple[str, str | None]:
    q = (row.get("question") or "").strip()
    name, _, quantity = q.partition(":")
    quantity = (row.get("quantity") or "").strip() or quantity.strip() or None
    return name.strip(), quantity


def grade_rows(rows: Sequence[dict], seconds: float = 1.0, memory_mb: int = 256) -> list[dict]:
    """Grade ``rows`` (dicts with id, question, answer[, quantity, about]); one result dict
    per row: the :class:`~.result.Grade` as JSON plus ``id``, ``question`` and ``line``.

    Each answer is graded under a ``seconds`` wall-clock and ``memory_mb`` memory ceiling
    (:func:`~.sandbox.grade_bounded`).  A pure function of its input (graders are cached per
    process), so any executor may map it.
    """
    from dualmech.grade.sandbox import grade_bounded
    out = []
    for row in rows:
        name, quantity = _question(row)
        about = (row.get("about") or "").strip() or None
        result = _untrusted_name(name, row) or grade_bounded(
            name, row.get("answer", ""), quantity, about=about, seconds=seconds,
            memory_mb=memory_mb).to_dict()
        out.append(_tag(row, result))
    return out


def _untrusted_name(name: str, row: dict) -> dict | None:
    """The ``invalid`` result of a row whose question is not a plain problem name (a CSV row
    never makes us import a file or module), else ``None``."""
    from dualmech.problems import is_name, named
    if is_name(name):
        return None
    try:
        named(name)
        summary = f"{name!r} is not a problem name."
    except Exception as exc:
        summary = str(exc.args[0]) if exc.args else str(exc)
    return {"problem": name, "quantity": "auto", "kind": "", "answer": row.get("answer", ""),
            "status": "invalid", "right": False, "summary": summary, "details": [],
            "edits": [], "dimension_issues": [], "matches": "", "state": {}, "method": "none",
            "false_right_bound": None, "seconds": 0.0}


def warm(names: Iterable[str] | str, limits: Limits = LIMITS) -> None:
    """Build each problem's grader (the one :meth:`Grader.of` gives for ``limits``), its
    quantities, points, feedback targets and the correct forms of its reactions and
    accelerations now (so forked workers share them)."""
    from dualmech.grade.answers import catalogue
    from dualmech.grade.targets import expression_targets
    if isinstance(names, str):
        names = [names]
    for name in sorted(set(names)):
        try:
            g = Grader.of(name, limits=limits)
            g.quantities()
            ctx = g.context
            warm_targets(ctx)
            # the correct forms of each reaction and acceleration read off single rows
            # (the whole system's symbolic solution, stage 1, is left to first use: it can
            # take seconds and is needed only when no single row explains a wrong answer)
            for q in catalogue(ctx).values():
                if len(q.reference) == 1 and (q.reference[0] in set(ctx.reactions) or
                                              q.reference[0] in set(ctx.qdd)):
                    expression_targets(ctx, q, 0)
        except Exception:  # reported row by row when graded
            continue


def warm_targets(ctx) -> None:
    """Build the exact points of ``ctx`` and its equations' feedback targets in every mode,
    with their written groups (what explaining a wrong equation reads), now."""
    from dualmech.grade.kinds import sources
    from dualmech.grade.terms import MODES, equation_targets
    sources(ctx)    # what each term of a correct equation is made of (names kinds of terms)
    if ctx.method == "exact":
        ctx.points("exact")
        for mode in MODES:
            for table in equation_targets(ctx, mode):
                table.groups(ctx)   # the written groups an edit may add or flip


def _chunks(rows: Sequence[dict], size: int) -> list[list[dict]]:
    def key(i):
        name, quantity = _question(rows[i])
        return name, quantity or "", i
    order = sorted(range(len(rows)), key=key)
    out, current, key = [], [], None
    for i in order:
        k = _question(rows[i])[0]
        if current and (len(current) >= size or k != key):
            out.append(current)
            current = []
        current.append(dict(rows[i], _index=i))
        key = k
    if current:
        out.append(current)
    return out


def grade_batch(rows: Sequence[dict], workers: int | None = None,
                scheduler: str | None = None, progress: bool = True,
                chunk: int = _CHUNK, connect_timeout: float = 10.0) -> list[dict]:
    """Grade every row, in input order.

    ``workers``: processes (default: every core; 1 grades here).  ``scheduler``: the address
    of a Dask scheduler (``tcp://host:8786``); the chunks then run on its workers.
    ``progress`` shows a tqdm bar on stderr; ``connect_timeout`` (seconds) bounds the wait
    for the scheduler.
    """
    if not rows:
        return []
    chunks = _chunks(rows, chunk)
    results: list = [None] * len(rows)
    from tqdm.auto import tqdm
    bar = tqdm(total=len(rows), unit="answer", disable=not progress, desc="grading")
    try:
        for done in _run(chunks, workers, scheduler, connect_timeout):
            for r in done:
                results[r.pop("_index")] = r
            bar.update(len(done))
    finally:
        bar.close()
    return results


def _run(chunks, workers, scheduler, connect_timeout):
    """Yield each chunk's results as they complete."""
    tagged = [[dict(r) for r in c] for c in chunks]
    if scheduler:
        yield from _run_dask(tagged, scheduler, connect_timeout)
        return
    from concurrent.futures import as_completed

    from dualmech.grade.sandbox import GradingPool
    workers = workers or os.cpu_count() or 1
    with GradingPool(min(workers, len(tagged))) as pool:
        futures = {}
        done: list = []
        for c in tagged:
            for row in c:
                name, quantity = _question(row)
                about = (row.get("about") or "").strip() or None
                refused = _untrusted_name(name, row)
                if refused is not None:
                    done.append(_tag(row, refused))
                    continue
                futures[pool.submit(name, row.get("answer", ""), quantity, about)] = row
        for f in as_completed(futures):
            done.append(_tag(futures[f], f.result().to_dict()))
            if len(done) >= _CHUNK:
                yield done
                done = []
        if done:
            yield done


def _tag(row: dict, result: dict) -> dict:
    result.update(id=row.get("id", ""), question=row.get("question", ""), line=row.get("line"))
    if "_index" in row:
        result["_index"] = row["_index"]
    return result


def _run_dask(chunks, scheduler: str, connect_timeout: float):
    try:
        from distributed import Client, as_completed as dask_completed
    except ImportError as exc:  # the optional extra is missing
        raise BatchError("`--scheduler` needs dask.distributed: pip install "
                         "'dualmech[dask]'.") from exc
    try:
        client = Client(scheduler, timeout=f"{connect_timeout}s")
    except (OSError, TimeoutError) as exc:
        raise BatchError(f"cannot reach the Dask scheduler at {scheduler}: {exc}") from None
    try:
        futures = client.map(grade_rows, chunks, pure=False)
        for f in dask_completed(futures):
            yield f.result()
    finally:
        client.close()
