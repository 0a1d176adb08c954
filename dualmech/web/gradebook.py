"""The teacher's side of an assignment: gradebook CSV, statistics, regrade, a student's data.

* ``GET /api/assignments`` -- the assignments;
* ``GET /api/assignments/{id}/grades.csv`` -- one row per student, one column per question
  (percent), and the total, in the layout both Moodle's and Canvas's gradebook imports read
  (``Student``, ``ID``, ``SIS User ID``, ``SIS Login ID``, ``Section``, then one column per
  grade item; map ``SIS User ID`` to the student's ID number in Moodle); a cell a spreadsheet
  would read as a formula is prefixed with ``'``;
* ``GET /api/assignments/{id}/stats`` -- per question the share of students right, the
  mistakes most often named (grouped: ``gravity sign``, ``missing Coriolis term``, ...);
  per student the attempts and scores;
* ``POST /api/assignments/{id}/regrade`` -- every attempt graded again (after a problem's fix
  and a restart of the server: the data is kept), with what changed;
* ``GET`` / ``DELETE /api/students/{student}`` -- everything kept about one student (their
  assignments, numbers, attempts, rows of uploaded batches), and its removal.

Example
-------
>>> mistake({"kind": "sign", "category": "a gravity term"})
'gravity sign'
>>> mistake({"kind": "missing", "category": "a Coriolis term"})
'missing Coriolis term'
>>> safe_cell("=HYPERLINK(1)"), safe_cell("-2+3"), safe_cell("s1")
("'=HYPERLINK(1)", "'-2+3", 's1')
"""
from __future__ import annotations

import asyncio
import csv
import io
from collections import Counter, defaultdict

from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import JSONResponse, Response
from starlette.routing import Route

from dualmech.web.common import error, safe_cell, server_of as _server, teacher_only as _teacher

__all__ = ["routes", "record", "mistake", "safe_cell", "grades_csv", "statistics"]

_KINDS = {"sign": "{c} sign", "missing": "missing {c} term", "extra": "extra {c} term",
          "coefficient": "{c} coefficient", "replace": "wrong function in a {c} term"}
_PLAIN = {"sign": "a term's sign", "missing": "a missing term", "extra": "an extra term",
          "coefficient": "a term's coefficient", "replace": "a term's function",
          "swap": "two symbols swapped", "factor": "off by a constant factor"}


def record(grade, level: str) -> dict:
    """What an attempt keeps: the full grade, the grade as ``level`` shows it, the score."""
    full = grade.to_dict()
    return {"full": full, "shown": grade.at_level(level).to_dict(),
            "score": float(grade.score or 0.0)}


def mistake(edit: dict) -> str:
    """A short name for the mistake an edit corrects, by its kind and the kind of term."""
    kind, category = edit.get("kind", ""), (edit.get("category") or "").strip()
    c = category.removeprefix("a ").removeprefix("an ").removesuffix(" term")
    if c and kind in _KINDS:
        return _KINDS[kind].format(c=c)
    return _PLAIN.get(kind, kind or "another mistake")


async def _rules(request: Request):
    rules = await run_in_threadpool(_server(request).classroom.rules, request.path_params["id"])
    return (rules, None) if rules else (None, error(404, "no such assignment."))


# -- the gradebook ---------------------------------------------------------------------------------
def grades_csv(rules: dict, roster: list[str], attempts: list[dict], classroom) -> str:
    """The gradebook CSV (see the module docstring)."""
    by_student = defaultdict(list)
    for a in attempts:
        by_student[a["student"]].append(a)
    heads = [f"{rules['title']} Q{i + 1} {q['problem']}" + (f" {q['quantity']}"
                                                             if q["quantity"] else "")
             for i, q in enumerate(rules["questions"])]
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\r\n")
    w.writerow(["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]
               + [safe_cell(h) for h in heads] + [safe_cell(f"{rules['title']} total")])
    for s in roster:
        scores = classroom.scores(rules, by_student.get(s, []))
        cells = [f"{100 * x:.2f}" for x in scores]
        total = f"{100 * sum(scores) / len(scores):.2f}"
        w.writerow([safe_cell(s), "", safe_cell(s), safe_cell(s), ""] + cells + [total])
    return out.getvalue()


async def gradebook_csv(request: Request):
    srv = _server(request)
    rules, err = await _rules(request)
    if err:
        return err
    roster = list(await run_in_threadpool(srv.classroom.roster, rules["id"]))
    attempts = await run_in_threadpool(srv.classroom.attempts, rules["id"])
    text = grades_csv(rules, roster, attempts, srv.classroom)
    return Response(text, media_type="text/csv; charset=utf-8", headers={
        "Content-Disposition": 'attachment; filename="grades.csv"'})


# -- statistics ----------------------------------------------------------------------------------
def statistics(rules: dict, roster: list[str], attempts: list[dict], classroom) -> dict:
    """Per question: students right (share), attempts, mean score, the mistakes most often
    named; per student: attempts and score of each question, and the total."""
    n = len(rules["questions"])
    right = [set() for _ in range(n)]
    tried = [set() for _ in range(n)]
    count = [0] * n
    named = [Counter() for _ in range(n)]
    who = [defaultdict(set) for _ in range(n)]
    for a in attempts:
        i, full = a["question"], a["result"]["full"]
        count[i] += 1
        tried[i].add(a["student"])
        if full.get("status") == "right":
            right[i].add(a["student"])
        names = {mistake(e) for e in full.get("edits", [])}
        if full.get("dimension_issues"):
            names.add("inconsistent dimensions")
        if full.get("status") == "invalid":
            names.add("not graded (could not be read)")
        for m in names:
            named[i][m] += 1
            who[i][m].add(a["student"])
    students = {}
    for s in roster:
        mine = [a for a in attempts if a["student"] == s]
        scores = classroom.scores(rules, mine)
        students[s] = {"attempts": [sum(1 for a in mine if a["question"] == i)
                                    for i in range(n)],
                       "scores": scores, "total": round(sum(scores) / n, 4)}
    questions = []
    for i, q in enumerate(rules["questions"]):
        questions.append({"index": i, "problem": q["problem"], "quantity": q["quantity"],
                          "students": len(roster), "answered": len(tried[i]),
                          "right": len(right[i]),
                          "right_share": round(len(right[i]) / max(1, len(roster)), 4),
                          "attempts": count[i],
                          "mistakes": [{"mistake": m, "attempts": k, "students": len(who[i][m])}
                                       for m, k in named[i].most_common(10)]})
    return {"assignment": rules["id"], "title": rules["title"], "questions": questions,
            "students": students}


async def stats(request: Request):
    srv = _server(request)
    rules, err = await _rules(request)
    if err:
        return err
    roster = list(await run_in_threadpool(srv.classroom.roster, rules["id"]))
    attempts = await run_in_threadpool(srv.classroom.attempts, rules["id"])
    return JSONResponse(statistics(rules, roster, attempts, srv.classroom))


# -- regrade -------------------------------------------------------------------------------------
async def regrade(request: Request):
    from dualmech.web.classroom_routes import spec_for
    srv = _server(request)
    rules, err = await _rules(request)
    if err:
        return err
    roster = await run_in_threadpool(srv.classroom.roster, rules["id"])
    attempts = await run_in_threadpool(srv.classroom.attempts, rules["id"])
    room = asyncio.Semaphore(2 * max(1, getattr(srv.pool, "workers", 1) or 1))

    async def again(a):   # a few at a time: the students answering now keep their turn
        async with room:
            return await asyncio.wrap_future(srv.pool.submit(
                spec_for(srv, rules, roster.get(a["student"], {}), a["question"]),
                a["answer"], rules["questions"][a["question"]]["quantity"], None))
    grades = await asyncio.gather(*(again(a) for a in attempts))
    changed = []
    for a, g in zip(attempts, grades):
        new = record(g, rules["feedback"])
        before, after = a["result"]["full"]["status"], new["full"]["status"]
        if before != after or a["result"]["score"] != new["score"]:
            changed.append({"student": a["student"], "question": a["question"],
                            "answer": a["answer"], "before": before, "after": after,
                            "score_before": a["result"]["score"], "score_after": new["score"]})
        await run_in_threadpool(srv.classroom.finish, a["id"], new)
    return JSONResponse({"regraded": len(attempts), "changed": changed})


# -- the assignments and a student's data --------------------------------------------------------
async def listing(request: Request):
    return JSONResponse(await run_in_threadpool(_server(request).classroom.assignments))


async def student_data(request: Request):
    srv = _server(request)
    student = request.path_params["student"]
    if request.method == "DELETE":
        n = await run_in_threadpool(srv.classroom.delete_student, student)
        rows = await run_in_threadpool(srv.store.delete_student_rows, student)
        if not n and not rows:
            return error(404, "nothing is kept about this student.")
        return JSONResponse({"student": student, "assignments": n, "batch_rows": rows})
    assignments = await run_in_threadpool(srv.classroom.export_student, student)
    rows = await run_in_threadpool(srv.store.student_rows, student)
    if not assignments and not rows:
        return error(404, "nothing is kept about this student.")
    return JSONResponse({"student": student, "assignments": assignments, "batch_rows": rows},
                        headers={"Content-Disposition": 'attachment; filename="student.json"'})


routes = [
    Route("/api/assignments", _teacher(listing)),
    Route("/api/assignments/{id}/grades.csv", _teacher(gradebook_csv)),
    Route("/api/assignments/{id}/stats", _teacher(stats)),
    Route("/api/assignments/{id}/regrade", _teacher(regrade), methods=["POST"]),
    Route("/api/students/{student:path}", _teacher(student_data), methods=["GET", "DELETE"]),
]
