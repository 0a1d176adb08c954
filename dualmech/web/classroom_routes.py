"""The assignment endpoints: a teacher makes an assignment, each student answers it.

* ``POST /api/assignments`` (teacher): the rules (:mod:`.rules`) and the roster; each
  student gets a token and a personal link ``/assignments/{id}#token=...`` (shown once);
  with ``per_student_numbers`` each gets parameter values of their own (:mod:`.numbers`);
* ``GET /api/assignments/{id}/me`` (student): their numbers, the questions, attempts left,
  the score;
* ``POST /api/assignments/{id}/answers`` (student): one answer to one question, graded in the
  grading pool at the student's numbers, under the assignment's rules (feedback level,
  attempts, deadline);
* ``/assignments/{id}``: the student's page (its script reads the token from the fragment).

The teacher's gradebook, statistics, regrade and a student's data are in :mod:`.gradebook`.
A student authenticates with ``Authorization: Bearer <token>``; a token names one student of
one assignment.  Each request of a student sets ``scope["dualmech.rate_key"]`` to
``student:<assignment>:<student>`` and their answers are rate-limited under that key, so a
class behind one address (a school's NAT) is not limited as one client.
"""
from __future__ import annotations

import asyncio
import secrets
from datetime import datetime, timezone

from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Route

from dualmech.web import gradebook, pages
from dualmech.web.common import error, json_object, server_of as _server
from dualmech.web.numbers import Personal, draw_numbers, shared_ranges
from dualmech.web.rules import RuleError, read_assignment
from dualmech.web.student_script import SCRIPT

__all__ = ["routes", "ROSTER_BYTES", "ANSWER_CHARS"]

#: Largest body of ``POST /api/assignments`` (a roster of 2000 ids fits).
ROSTER_BYTES = 512 * 1024
#: Longest answer a student may send.
ANSWER_CHARS = 4000
_SHAPE = '{"title", "questions": [{"problem", "quantity"}], "students": [ids], ...}'


def _limited(srv, key: str, kind: str):
    ok, wait = srv.limiter.allow(key, kind)
    if ok:
        return None
    return error(429, f"too many requests; wait {wait:.1f} s and try again.",
                 {"Retry-After": str(max(1, round(wait + 0.5)))})


# -- the teacher makes an assignment ---------------------------------------------------------
async def create(request: Request):
    srv = _server(request)
    if not srv.teacher(request):
        return error(401, "this needs the teacher token (Authorization: Bearer <token>).")
    limited = _limited(srv, request.client.host if request.client else "?", "upload")
    if limited:
        return limited
    body, err = await json_object(request, ROSTER_BYTES, _SHAPE)
    if err:
        return err
    try:
        rules = await run_in_threadpool(read_assignment, body, srv.served,
                                        lambda n: list(srv.info(n).quantities))
        infos = {q["problem"]: srv.info(q["problem"]) for q in rules["questions"]}
        numbers = _numbers(rules, infos)
    except RuleError as exc:
        return error(exc.status, str(exc))
    except ValueError as exc:
        return error(400, str(exc))
    students = rules.pop("students")
    aid, tokens = await run_in_threadpool(srv.classroom.create, rules,
                                          {s: numbers(s) for s in students})
    base = str(request.base_url).rstrip("/")
    return JSONResponse({"id": aid, "title": rules["title"], "students": {
        s: {"token": tokens[s], "url": f"{base}/assignments/{aid}#token={tokens[s]}"}
        for s in students}}, status_code=201)


def _numbers(rules: dict, infos: dict):
    """A function giving one student's numbers (``{}`` without ``per_student_numbers``);
    records in ``rules`` each problem's parameters and their units."""
    problems = list(dict.fromkeys(q["problem"] for q in rules["questions"]))
    params = {n: infos[n].context.problem.parameters for n in problems}
    rules["parameters"] = {n: [str(p.symbol) for p in params[n]] for n in problems}
    rules["units"] = {p["name"]: p["unit"] for n in problems for p in infos[n].parameters}
    if not rules["per_student_numbers"]:
        return lambda student: {}
    rules["ranges"] = shared_ranges(params.values())
    return lambda student: new_numbers(rules)


def new_numbers(rules: dict) -> dict:
    """Numbers for a student joining an assignment (``{}`` without per-student numbers)."""
    if not rules["per_student_numbers"]:
        return {}
    return draw_numbers({k: tuple(v) for k, v in rules["ranges"].items()},
                        secrets.token_hex(16))


# -- the student ---------------------------------------------------------------------------------
async def _student(request: Request):
    """``((assignment rules, student), None)`` for the bearer of a student's token, or
    ``(None, error response)``."""
    srv = _server(request)
    auth = request.headers.get("authorization", "")
    token = auth[7:].strip() if auth.lower().startswith("bearer ") else ""
    if not token:
        return None, error(401, "this needs your personal token (Authorization: Bearer "
                                "<token>, from the link your teacher sent).")
    found = await run_in_threadpool(srv.classroom.student, token)
    if found is None:
        return None, error(401, "this token is not known here (a mistyped link, or a student "
                                "removed from the assignment).")
    aid, student = found
    if aid != request.path_params["id"]:
        return None, error(403, "this token is for another assignment; use the link of this "
                                "one.")
    request.scope["dualmech.rate_key"] = f"student:{aid}:{student}"
    rules = await run_in_threadpool(srv.classroom.rules, aid)
    return (rules, student), None


def _closed(srv, rules: dict) -> bool:
    return rules["deadline"] is not None and srv.clock() > rules["deadline"]


def _iso(when: float | None) -> str | None:
    return None if when is None else \
        datetime.fromtimestamp(when, timezone.utc).isoformat().replace("+00:00", "Z")


async def me(request: Request):
    srv = _server(request)
    who, err = await _student(request)
    if err:
        return err
    rules, student = who
    limited = _limited(srv, request.scope["dualmech.rate_key"], "validate")
    if limited:
        return limited
    out = await run_in_threadpool(_me, srv, rules, student)
    return JSONResponse(out)


def _me(srv, rules: dict, student: str) -> dict:
    aid, n = rules["id"], len(rules["questions"])
    numbers = srv.classroom.roster(aid).get(student, {})
    attempts = srv.classroom.attempts(aid, student)
    used = srv.classroom.used(aid, student, n)
    scores = srv.classroom.scores(rules, attempts)
    last = {a["question"]: a["result"]["shown"] for a in attempts}
    titles = {t["name"]: t["title"] for t in srv.titles}
    questions = []
    for i, q in enumerate(rules["questions"]):
        info = srv.info(q["problem"])
        asked = info.quantities.get(q["quantity"]) if q["quantity"] else None
        questions.append({"index": i, "problem": q["problem"], "quantity": q["quantity"],
                          "title": titles.get(q["problem"], q["problem"]),
                          "asked": asked or "the equations of motion",
                          "attempts_used": used[i],
                          "attempts_left": max(0, rules["attempts"] - used[i]),
                          "score": scores[i], "last": last.get(i)})
    return {"assignment": aid, "title": rules["title"], "student": student,
            "numbers": numbers, "units": {k: rules["units"].get(k, "") for k in numbers},
            "questions": questions, "attempts": rules["attempts"],
            "attempts_left": [q["attempts_left"] for q in questions],
            "score": round(sum(scores) / n, 4), "penalty": rules["penalty"],
            "feedback": rules["feedback"], "deadline": _iso(rules["deadline"]),
            "closed": _closed(srv, rules)}


async def answer(request: Request):
    srv = _server(request)
    who, err = await _student(request)
    if err:
        return err
    rules, student = who
    limited = _limited(srv, request.scope["dualmech.rate_key"], "grade")
    if limited:
        return limited
    body, err = await json_object(request, srv.limits.json_bytes,
                                  '{"question": index, "answer": text}')
    if err:
        return err
    err = _check_answer(body, rules)
    if err:
        return err
    if _closed(srv, rules):
        return error(403, f"the deadline passed at {_iso(rules['deadline'])}; answers are no "
                          "longer graded.")
    if srv.waiting >= srv.limits.queue:
        return error(503, "the server is busy grading; try again in a few seconds.",
                     {"Retry-After": "5"})
    i = body["question"]
    attempt = await run_in_threadpool(srv.classroom.reserve, rules["id"], student, i,
                                      body["answer"], rules["attempts"])
    if attempt is None:
        return error(409, f"no attempt left at question {i + 1} (all {rules['attempts']} "
                          "used).")
    return await _grade(srv, rules, student, i, body["answer"], attempt)


def _check_answer(body: dict, rules: dict):
    q, text = body.get("question"), body.get("answer")
    n = len(rules["questions"])
    if isinstance(q, bool) or not isinstance(q, int) or not 0 <= q < n:
        return error(400, f"`question` must be the index of a question, 0 to {n - 1}.")
    if not isinstance(text, str):
        return error(400, "`answer` must be a string.")
    if len(text) > ANSWER_CHARS:
        return error(413, f"`answer` is longer than {ANSWER_CHARS} characters.")
    if set(body) - {"question", "answer"}:
        return error(400, "the body has only `question` and `answer`.")
    return None


def spec_for(srv, rules: dict, numbers: dict, question: int):
    """What the pool grades question ``question`` of an assignment as: the served spec, or
    the spec at the student's numbers."""
    problem = rules["questions"][question]["problem"]
    spec = srv.served[problem]
    if not rules["per_student_numbers"]:
        return spec
    mine = {k: numbers[k] for k in rules["parameters"][problem]}
    return Personal.of(spec, mine)


async def _grade(srv, rules, student, i, text, attempt):
    numbers = (await run_in_threadpool(srv.classroom.roster, rules["id"])).get(student, {})
    q = rules["questions"][i]
    srv.waiting += 1
    try:
        future = srv.pool.submit(spec_for(srv, rules, numbers, i), text, q["quantity"], None)
        grade = await asyncio.wait_for(asyncio.wrap_future(future), srv.limits.seconds)
    except asyncio.TimeoutError:
        await run_in_threadpool(srv.classroom.give_back, attempt)
        return error(503, "grading took too long; try again (the attempt was not counted).")
    except BaseException:
        await run_in_threadpool(srv.classroom.give_back, attempt)
        raise
    finally:
        srv.waiting -= 1
    record = gradebook.record(grade, rules["feedback"])
    await run_in_threadpool(srv.classroom.finish, attempt, record)
    used = await run_in_threadpool(srv.classroom.used, rules["id"], student,
                                   len(rules["questions"]))
    attempts = await run_in_threadpool(srv.classroom.attempts, rules["id"], student)
    scores = srv.classroom.scores(rules, attempts)
    out = dict(record["shown"], question=i, attempt=used[i],
               attempts_left=max(0, rules["attempts"] - used[i]), question_score=scores[i])
    sent = await run_in_threadpool(srv.lti.send_score, rules["id"], student,
                                   round(sum(scores) / len(scores), 4))
    if sent is not None:   # launched from a learning platform: the score went back to it
        out["platform"] = sent
    return JSONResponse(out)


# -- the student's page ------------------------------------------------------------------------
async def student_page(request: Request):
    return HTMLResponse(pages.student_page(request.path_params["id"][:40]))


async def student_script(request: Request):
    return Response(SCRIPT, media_type="text/javascript")


#: The assignment routes (the app adds them to its own).
routes = [
    Route("/assignments/student.js", student_script),
    Route("/assignments/{id}", student_page),
    Route("/api/assignments", create, methods=["POST"]),
    Route("/api/assignments/{id}/me", me),
    Route("/api/assignments/{id}/answers", answer, methods=["POST"]),
    *gradebook.routes,
]
