"""The ASGI application: pages for students and the teacher, and the JSON API.

:func:`create_app` wires the pieces: problem pages (:mod:`.catalog`, :mod:`dualmech.web.pages`),
validation while typing (:mod:`.preview`), grading in the bounded process pool
(:class:`dualmech.grade.sandbox.GradingPool`), batches kept in SQLite (:mod:`.store`) and
graded in the background (:mod:`.batches`), limits per client (:mod:`.guard`).  The
endpoints are module-level functions listed in :data:`routes`, as in starlette's own
examples; each reads what the app shares (store, pool, limits, token: a ``_Server``) from
``request.app.state.server``.

A client only ever names a problem; the name is looked up among the problems the server was
started with, so nothing a client sends is opened as a path or imported.

Example
-------
>>> import tempfile
>>> from starlette.testclient import TestClient
>>> app = create_app(["simple_pendulum"], data=tempfile.mkdtemp(),
...                  token="a-strong-teacher-token-1")
>>> with TestClient(app) as client:
...     r = client.post("/api/validate", json={"problem": "simple_pendulum",
...                                            "answer": "a*theta'' + g*sin(theta) = 0"})
>>> r.status_code, r.json()["ok"]
(200, True)
"""
from __future__ import annotations

import asyncio
import contextlib
import csv
import hmac
import html
import io
import threading
import time
from collections import OrderedDict
from pathlib import Path
from typing import Sequence
from urllib.parse import parse_qs, unquote

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from starlette.routing import Route

from dualmech.web import classroom_routes, lti, pages
from dualmech.web.assets import SCRIPT, STYLE
from dualmech.web.batches import BatchError, BatchRunner, read_upload
from dualmech.web.catalog import ProblemInfo
from dualmech.web.classroom import Classroom
from dualmech.web.common import error as _error, json_object, safe_cell, teacher_only
from dualmech.web.guard import RateLimiter, SecurityHeaders, TooLarge, read_body
from dualmech.web.openapi import SPEC
from dualmech.web.preview import preview
from dualmech.web.sessions import NoStore, Sessions, check_token
from dualmech.web.store import Store, default_data_dir

__all__ = ["create_app", "served_problems", "WebLimits", "routes"]

_COOKIE = "dualmech_teacher"
#: Grades kept in memory, so the same answer typed by many students is graded once.
_REMEMBERED = 4096


class WebLimits:
    """Bounds of the web layer: ``json_bytes`` (a JSON request), ``csv_bytes`` (an upload),
    ``field_chars`` (quantity/about), ``queue`` (answers from the page waiting for the pool
    before the server answers 503), ``seconds`` (the longest a page waits for one grade)."""

    def __init__(self, json_bytes: int = 64 * 1024, csv_bytes: int = 2 * 1024 * 1024,
                 field_chars: int = 200, queue: int = 400, seconds: float = 60.0):
        self.json_bytes, self.csv_bytes, self.field_chars = json_bytes, csv_bytes, field_chars
        self.queue, self.seconds = queue, seconds


def served_problems(specs: Sequence[str] | None = None) -> dict[str, str]:
    """``{name clients use: spec the pool loads}``; every catalogue problem by default.

    A spec that is not a catalogue name is loaded here, once, to learn its name; one that
    cannot be loaded raises ``ValueError`` with the reason.
    """
    from dualmech.problems import declarations, get
    names = [d.name for d in declarations()]
    if not specs:
        return {n: n for n in names}
    out = {}
    for spec in specs:
        if spec in names:
            out[spec] = spec
            continue
        try:
            problem = get(spec)
        except Exception as exc:
            reason = exc.args[0] if isinstance(exc, KeyError) and exc.args else exc
            raise ValueError(f"cannot serve problem {spec!r}: {reason}") from None
        out[problem.name] = spec
    return out


class _Server:
    """The state behind the routes."""

    def __init__(self, served: dict, data: Path, token: str, pool, workers, rates, limits,
                 grade_seconds: float, memory_mb: int):
        self.served = served
        self.data = data
        self.token = token
        self.sessions: Sessions | None = None
        self.classroom: Classroom | None = None
        self.lti: lti.Lti | None = None
        self.clock = time.time     # what deadlines are compared with (tests set their own)
        self.pool = pool
        self.own_pool = pool is None
        self.workers = workers
        self.grade_seconds = grade_seconds
        self.memory_mb = memory_mb
        self.limits = limits
        self.limiter = RateLimiter(rates)
        self.store: Store | None = None
        self.runner: BatchRunner | None = None
        self._infos: dict = {}
        self._lock = threading.Lock()
        self.waiting = 0
        self.titles = _titles(served)
        self.graded: OrderedDict = OrderedDict()    # (problem, answer, quantity, about) -> dict

    def remember(self, key: tuple, result: dict | None = None) -> dict | None:
        """The grade of an answer already graded (grading is deterministic), or store one;
        at most :data:`_REMEMBERED` are kept, the least recently used go first."""
        with self._lock:
            if result is None:
                found = self.graded.get(key)
                if found is not None:
                    self.graded.move_to_end(key)
                return found
            self.graded[key] = result
            while len(self.graded) > _REMEMBERED:
                self.graded.popitem(last=False)
            return result

    # -- lifecycle ---------------------------------------------------------------------------
    def start(self) -> None:
        self.store = Store(self.data)
        self.sessions, self.classroom = Sessions(self.store), Classroom(self.store)
        self.lti = lti.Lti(self.data, self.store)
        if self.pool is None:
            from dualmech.grade.sandbox import GradingPool
            self.pool = GradingPool(self.workers, seconds=self.grade_seconds,
                                    memory_mb=self.memory_mb)
        self.runner = BatchRunner(self.store, self.pool, self.served,
                                  inflight=max(2, getattr(self.pool, "workers", 2) or 2)).start()

    def stop(self) -> None:
        if self.runner is not None:
            self.runner.close()
        if self.own_pool and self.pool is not None:
            self.pool.close()
        if self.store is not None:
            self.store.close()

    # -- problems ----------------------------------------------------------------------------
    def info(self, name: str) -> ProblemInfo:
        """The problem's page data, built once (only for served names)."""
        with self._lock:
            info = self._infos.get(name)
            if info is None:
                info = self._infos[name] = ProblemInfo.build(self.served[name])
        return info

    def teacher(self, request: Request) -> bool:
        auth = request.headers.get("authorization", "")
        if auth.lower().startswith("bearer "):
            return hmac.compare_digest(auth[7:].strip().encode(), self.token.encode())
        return self.sessions.valid(request.cookies.get(_COOKIE, ""))


def _titles(served: dict) -> list[dict]:
    from dualmech.problems import declarations
    from dualmech.sources import source_fields
    decl = {d.name: d for d in declarations()}
    out = []
    for name, spec in served.items():
        d = decl.get(name) or _declared_by(spec)   # a teacher's file: its own declarations
        out.append({"name": name, "title": getattr(d, "title", "") or name,
                    **source_fields(getattr(d, "source", "") or ""),
                    "summary": getattr(d, "summary", "") or ""})
    return out


def _declared_by(spec: str):
    """The problem ``spec`` names outside the catalogue (a file, ``module:Class``; loaded
    once already by :func:`served_problems`), or None when it cannot be loaded."""
    from dualmech.problems import get
    try:
        return get(spec)
    except Exception:  # noqa: BLE001 - the title falls back to the name
        return None


def _client(request: Request) -> str:
    return request.client.host if request.client else "unknown"


async def _limited(srv: _Server, request: Request, kind: str) -> JSONResponse | None:
    ok, wait = srv.limiter.allow(_client(request), kind)
    if ok:
        return None
    return _error(429, f"too many requests; wait {wait:.1f} s and try again.",
                  {"Retry-After": str(max(1, round(wait + 0.5)))})


async def _answer_request(srv: _Server, request: Request) -> tuple[dict | None, Response | None]:
    """The validated JSON body of /api/validate and /api/grade, or the error response."""
    body, err = await json_object(request, srv.limits.json_bytes,
                                  '{"problem": ..., "answer": ...}')
    if err:
        return None, err
    for key in ("problem", "answer"):
        if not isinstance(body.get(key), str):
            return None, _error(400, f"`{key}` must be a string.")
    for key in ("quantity", "about"):
        v = body.get(key)
        if v is not None and not isinstance(v, str):
            return None, _error(400, f"`{key}` must be a string or null.")
        if isinstance(v, str) and len(v) > srv.limits.field_chars:
            return None, _error(413, f"`{key}` is longer than {srv.limits.field_chars} "
                                     "characters.")
    if body["problem"] not in srv.served:
        return None, _not_found(srv, body["problem"])
    return body, None


def _not_found(srv: _Server, name: str) -> JSONResponse:
    shown = name if len(name) <= 60 else name[:60] + "..."
    return _error(404, f"no problem {shown!r} is served here; served: "
                       f"{', '.join(srv.served)}.")


def create_app(problems: Sequence[str] | None = None, *, data: str | Path | None = None,
               token: str, pool=None, workers: int | None = None, rates: dict | None = None,
               limits: WebLimits | None = None, grade_seconds: float = 1.0,
               memory_mb: int = 256) -> Starlette:
    """The application serving ``problems`` (catalogue names; all by default).

    ``data``: directory of the SQLite store (default: :func:`.store.default_data_dir`);
    ``token``: the teacher's token (at least 16
    characters of several kinds, :func:`.sessions.check_token`); ``pool``: a
    grading pool to use (default: a :class:`~dualmech.grade.sandbox.GradingPool` of
    ``workers`` processes, ``grade_seconds`` and ``memory_mb`` per answer, started with the
    app and closed with it); ``rates``: see :data:`.guard.RATES`.  The endpoints are the
    module's own functions (:data:`routes`); what they share is ``app.state.server``.
    """
    check_token(token)
    data = Path(data) if data is not None else default_data_dir()
    srv = _Server(served_problems(problems), data, token, pool, workers, rates,
                  limits or WebLimits(), grade_seconds, memory_mb)
    app = Starlette(routes=routes, lifespan=_lifespan,
                    exception_handlers={404: _not_found_page, 500: _failed,
                                        Exception: _failed})
    app.add_middleware(lti.SameOriginExceptLaunch)
    app.add_middleware(NoStore)
    app.add_middleware(SecurityHeaders)
    app.state.server = srv
    return app


@contextlib.asynccontextmanager
async def _lifespan(app: Starlette):
    srv = app.state.server
    await run_in_threadpool(srv.start)
    try:
        yield
    finally:
        await run_in_threadpool(srv.stop)


def _server(request: Request) -> _Server:
    """The state of the app serving ``request``."""
    return request.app.state.server


def _files(handler):
    async def only_known(request: Request):
        if request.path_params["file"] not in ("results.json", "report.md", "results.csv"):
            return _error(404, "no such file; results.json, report.md or results.csv.")
        return await handler(request)
    return only_known


# -- pages ---------------------------------------------------------------------------------------
async def index(request: Request):
    return HTMLResponse(pages.index_page(_server(request).titles))


async def problem_page(request: Request):
    srv = _server(request)
    name = request.path_params["name"]
    if name not in srv.served:
        return HTMLResponse(pages.layout("Not found", "<h1>No such problem</h1><p>"
                                         "<a href='/'>The problems served here</a></p>"),
                            status_code=404)
    info = await run_in_threadpool(srv.info, name)
    return HTMLResponse(pages.problem_page(info))


async def static(request: Request):
    which = request.path_params["file"]
    if which == "style.css":
        return Response(STYLE, media_type="text/css")
    if which == "app.js":
        return Response(SCRIPT, media_type="text/javascript")
    return _error(404, "no such file.")


async def favicon(request: Request):
    return Response(status_code=204)


async def teacher(request: Request):
    srv = _server(request)
    if not srv.teacher(request):
        return HTMLResponse(pages.login_page())
    batches = await run_in_threadpool(srv.store.batches)
    answers = await run_in_threadpool(srv.store.answers)
    assignments = await run_in_threadpool(srv.classroom.assignments)
    return HTMLResponse(pages.teacher_page(batches, answers, assignments))


async def login(request: Request):
    srv = _server(request)
    limited = await _limited(srv, request, "login")
    if limited:
        return HTMLResponse(pages.login_page("Too many tries; wait a minute."),
                            status_code=429)
    try:
        raw = await read_body(request, 4096)
    except TooLarge as exc:
        return HTMLResponse(pages.login_page(str(exc)), status_code=413)
    given = parse_qs(raw.decode("utf-8", "replace")).get("token", [""])[0].strip()
    if not hmac.compare_digest(given.encode(), srv.token.encode()):
        return HTMLResponse(pages.login_page("That is not the token."), status_code=401)
    sid = await run_in_threadpool(srv.sessions.open)
    r = RedirectResponse("/teacher", status_code=303)
    r.set_cookie(_COOKIE, sid, max_age=int(srv.sessions.seconds), httponly=True,
                 samesite="strict", path="/", secure=request.url.scheme == "https")
    return r


async def logout(request: Request):
    srv = _server(request)
    await run_in_threadpool(srv.sessions.close, request.cookies.get(_COOKIE, ""))
    r = RedirectResponse("/teacher", status_code=303)
    r.delete_cookie(_COOKIE, path="/", httponly=True, samesite="strict",
                    secure=request.url.scheme == "https")
    return r


async def batch_page(request: Request):
    srv = _server(request)
    if not srv.teacher(request):
        return RedirectResponse("/teacher", status_code=303)
    progress = await run_in_threadpool(srv.store.progress, request.path_params["id"])
    if progress is None:
        return HTMLResponse(pages.layout("Not found", "<h1>No such batch</h1>"),
                            status_code=404)
    results = await run_in_threadpool(srv.store.results, progress["id"]) \
        if progress["status"] == "done" else []
    return HTMLResponse(pages.batch_page(progress, results))


async def api_docs(request: Request):
    return HTMLResponse(pages.api_page(SPEC))


# -- API -----------------------------------------------------------------------------------------
async def api_openapi(request: Request):
    return JSONResponse(SPEC)


async def api_problems(request: Request):
    return JSONResponse([dict(t, url=f"/problems/{t['name']}")
                         for t in _server(request).titles])


async def api_problem(request: Request):
    srv = _server(request)
    name = request.path_params["name"]
    if name not in srv.served:
        return _not_found(srv, name)
    info = await run_in_threadpool(srv.info, name)
    return JSONResponse(info.to_dict())


async def api_validate(request: Request):
    srv = _server(request)
    limited = await _limited(srv, request, "validate")
    if limited:
        return limited
    body, err = await _answer_request(srv, request)
    if err:
        return err
    info = await run_in_threadpool(srv.info, body["problem"])
    out = await run_in_threadpool(preview, info, body["answer"], body.get("quantity"))
    return JSONResponse(out)


async def api_grade(request: Request):
    srv = _server(request)
    limited = await _limited(srv, request, "grade")
    if limited:
        return limited
    body, err = await _answer_request(srv, request)
    if err:
        return err
    if srv.waiting >= srv.limits.queue:
        return _error(503, "the server is busy grading; try again in a few seconds.",
                      {"Retry-After": "5"})
    info = await run_in_threadpool(srv.info, body["problem"])
    key = (body["problem"], body["answer"], body.get("quantity") or None,
           body.get("about") or None)
    result = srv.remember(key)
    if result is None:
        srv.waiting += 1
        try:
            future = srv.pool.submit(srv.served[key[0]], *key[1:])
            grade = await asyncio.wait_for(asyncio.wrap_future(future), srv.limits.seconds)
        except asyncio.TimeoutError:
            return _error(503, "grading took too long; try again.")
        finally:
            srv.waiting -= 1
        result = srv.remember(key, grade.to_dict())
    result = dict(result)
    result["feedback_html"] = await run_in_threadpool(pages.feedback_html, info, result)
    kept = {k: v for k, v in result.items() if k != "feedback_html"}
    kept["question"] = f"{key[0]}:{key[2]}" if key[2] else key[0]
    await run_in_threadpool(srv.store.add_answer, kept)
    return JSONResponse(result)


async def api_batches(request: Request):
    srv = _server(request)
    if request.method == "GET":
        return JSONResponse(await run_in_threadpool(srv.store.batches))
    limited = await _limited(srv, request, "upload")
    if limited:
        return limited
    try:
        raw = await read_body(request, srv.limits.csv_bytes)
    except TooLarge as exc:
        return _error(413, str(exc))
    name = unquote(request.headers.get("x-filename", "upload.csv"))[:200]
    try:
        rows = await run_in_threadpool(read_upload, raw, name, srv.data / "uploads")
    except BatchError as exc:
        return _error(400, str(exc))
    bid = await run_in_threadpool(srv.store.add_batch, name, rows)
    srv.runner.notify()
    return JSONResponse({"id": bid, "total": len(rows), "url": f"/teacher/batches/{bid}"},
                        status_code=201)


async def _done_batch(request: Request):
    srv = _server(request)
    progress = await run_in_threadpool(srv.store.progress, request.path_params["id"])
    if progress is None:
        return None, _error(404, "no such batch.")
    if progress["status"] != "done":
        return None, _error(409, f"the batch is still grading ({progress['done']} of "
                                 f"{progress['total']}).")
    return progress, None


async def api_batch(request: Request):
    progress = await run_in_threadpool(_server(request).store.progress,
                                       request.path_params["id"])
    return JSONResponse(progress) if progress else _error(404, "no such batch.")


async def api_batch_file(request: Request):
    srv = _server(request)
    progress, err = await _done_batch(request)
    if err:
        return err
    results = await run_in_threadpool(srv.store.results, progress["id"])
    which = request.path_params["file"]
    if which == "results.csv":
        return Response(_csv(results), media_type="text/csv; charset=utf-8",
                        headers=_attachment(which))
    from dualmech.grade.report import write_report
    if which == "report.md":   # ids and questions from the uploaded file: text, not HTML
        results = [dict(r, id=html.escape(str(r.get("id", ""))),
                        question=html.escape(str(r.get("question", "")))) for r in results]
    paths = await run_in_threadpool(write_report, results,
                                    srv.data / "reports" / progress["id"],
                                    f"Grades: {progress['name']}")
    key, media = {"results.json": ("json", "application/json"),
                  "report.md": ("markdown", "text/markdown; charset=utf-8")}[which]
    return Response(paths[key].read_bytes(), media_type=media, headers=_attachment(which))


# -- errors --------------------------------------------------------------------------------------
async def _not_found_page(request: Request, exc):
    if request.url.path.startswith("/api/"):
        return _error(404, "no such endpoint; see /api/docs.")
    return HTMLResponse(pages.layout("Not found", "<h1>Not found</h1><p><a href='/'>The "
                                     "problems served here</a></p>"), status_code=404)


async def _failed(request: Request, exc):
    return _error(500, "the server could not answer this request; the answer was not "
                       "graded. Try again, and tell the teacher if it persists.")


#: Every page and endpoint of the app (the API's are described in :mod:`.openapi`).
routes = [
    Route("/", index),
    Route("/problems/{name}", problem_page),
    Route("/static/{file}", static),
    Route("/favicon.ico", favicon),
    Route("/teacher", teacher),
    Route("/teacher/login", login, methods=["POST"]),
    Route("/teacher/logout", logout, methods=["POST"]),
    Route("/teacher/batches/{id}", batch_page),
    Route("/api/docs", api_docs),
    Route("/api/openapi.json", api_openapi),
    Route("/api/problems", api_problems),
    Route("/api/problems/{name}", api_problem),
    Route("/api/validate", api_validate, methods=["POST"]),
    Route("/api/grade", api_grade, methods=["POST"]),
    Route("/api/batches", teacher_only(api_batches), methods=["GET", "POST"]),
    Route("/api/batches/{id}", teacher_only(api_batch)),
    Route("/api/batches/{id}/{file:str}", teacher_only(_files(api_batch_file))),
    *classroom_routes.routes,
    *lti.routes,
]


def _attachment(name: str) -> dict:
    return {"Content-Disposition": f'attachment; filename="{name}"'}


def _csv(results: list[dict]) -> str:
    """One row per answer; a cell a spreadsheet would read as a formula is quoted with '."""
    out = io.StringIO()
    w = csv.writer(out)
    w.writerow(["id", "question", "line", "status", "summary", "feedback", "answer"])
    for r in results:
        feedback = "; ".join([e.get("sentence", "") for e in r.get("edits", [])]
                             + [f"dimensions: {d}" for d in r.get("dimension_issues", [])])
        w.writerow([safe_cell(r.get("id")), safe_cell(r.get("question")), r.get("line"),
                    r.get("status"), safe_cell(r.get("summary")), safe_cell(feedback),
                    safe_cell(r.get("answer"))])
    return out.getvalue()


