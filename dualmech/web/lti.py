"""LTI 1.3: a learning platform (Moodle, Canvas, ...) launches a student into an assignment,
and the assignment's score goes back through Assignment and Grade Services.

Built on ``pylti1p3`` (the ``lti`` extra), which validates each launch: the OIDC state and
nonce, the platform's signature on the ``id_token`` (RS256, its key from the platform's
JWKS), the registration and the deployment.  The platform's registration is read from
``DATA/lti.json`` in pylti1p3's format (issuer -> client_id, auth_login_url,
auth_token_url, key_set_url, deployment_ids, private_key_file, public_key_file; the key
files beside it); without that file the LTI endpoints answer 404.

* ``GET|POST /lti/login`` -- the platform's third-party login: redirects to its
  authorisation endpoint with a state (cookie) and a nonce;
* ``POST /lti/launch`` -- the platform posts the signed ``id_token``; a learner's launch of a
  resource link whose custom parameter ``assignment`` names an assignment enrols them (their
  LTI ``sub`` is their id; numbers drawn as for the roster), gives them a fresh token and
  sends them to their page; the AGS endpoint of the launch is kept;
* ``GET /lti/jwks`` -- the tool's public keys, for the platform.

After each graded answer of a launched student, :meth:`Lti.send_score` posts their
assignment score (``scoreGiven`` of ``scoreMaximum`` 100, ``FullyGraded``) to the line item
of the launch, with an access token the tool obtains by a JWT signed with its own key.

A launch is a cross-site form post from the platform, protected by the signed token, the
state and the nonce; :class:`SameOriginExceptLaunch` lets it through the app's Origin check.
"""
from __future__ import annotations

import json
import threading
import time
from datetime import datetime, timezone
from pathlib import Path
from urllib.parse import parse_qsl

from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import JSONResponse, RedirectResponse
from starlette.routing import Route

from dualmech.web.common import error
from dualmech.web.guard import SameOrigin, TooLarge, read_body

__all__ = ["Lti", "routes", "SameOriginExceptLaunch", "CONFIG"]

#: The platform registration's file in the data directory.
CONFIG = "lti.json"
_LAUNCH_PATHS = ("/lti/login", "/lti/launch")
_CUSTOM = "https://purl.imsglobal.org/spec/lti/claim/custom"
_ROLES = "https://purl.imsglobal.org/spec/lti/claim/roles"
_AGS = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
_SCHEMA = """CREATE TABLE IF NOT EXISTS lti_links (
    assignment TEXT NOT NULL, student TEXT NOT NULL, iss TEXT NOT NULL, client_id TEXT NOT NULL,
    ags TEXT NOT NULL, PRIMARY KEY (assignment, student));"""


class _Cache:
    """pylti1p3's launch data (state, nonce, launches): a bounded in-memory table with
    expiry, shared by the requests of one server."""

    def __init__(self, most: int = 20000):
        self._data: dict = {}
        self._most = most
        self._lock = threading.Lock()

    def get(self, key):
        with self._lock:
            found = self._data.get(key)
        return found[0] if found and found[1] > time.time() else None

    def set(self, key, value, exp=None):
        with self._lock:
            self._data[key] = (value, time.time() + (exp or 3600))
            while len(self._data) > self._most:
                self._data.pop(next(iter(self._data)))


class Lti:
    """The server's LTI side: its configuration (``DATA/lti.json``, or None), the launch
    cache, and each launched student's AGS endpoint (in the SQLite file)."""

    def __init__(self, data: Path, store):
        self.store = store
        self.path = Path(data) / CONFIG
        self.cache = _Cache()
        #: the ``requests.Session`` pylti1p3 uses (None: its own); tests set a simulated one
        self.requests_session = None
        self._conf = None
        with store._lock:
            store._db.executescript(_SCHEMA)

    def conf(self):
        """The tool configuration (pylti1p3's ``ToolConfJsonFile``), or None without the
        file; ``RuntimeError`` without pylti1p3."""
        if self._conf is None and self.path.exists():
            try:
                from pylti1p3.tool_config import ToolConfJsonFile
            except ImportError:
                raise RuntimeError("LTI needs pylti1p3: pip install 'dualmech[lti]'.") from None
            self._conf = ToolConfJsonFile(str(self.path))
        return self._conf

    def link(self, aid: str, student: str, iss: str, client_id: str, ags: dict) -> None:
        self.store._run("INSERT OR REPLACE INTO lti_links VALUES (?, ?, ?, ?, ?)",
                        (aid, student, iss, client_id, json.dumps(ags)))

    def link_of(self, aid: str, student: str) -> dict | None:
        rows = self.store._all("SELECT iss, client_id, ags FROM lti_links WHERE assignment = ? "
                               "AND student = ?", (aid, student))
        return dict(rows[0], ags=json.loads(rows[0]["ags"])) if rows else None

    def send_score(self, aid: str, student: str, score: float) -> str | None:
        """Post ``student``'s assignment score (0 to 1) to their launch's line item; None
        when they were not launched from a platform, else ``"sent"`` or why not."""
        link = self.link_of(aid, student)
        if link is None:
            return None
        conf = self.conf()
        try:
            from pylti1p3.assignments_grades import AssignmentsGradesService
            from pylti1p3.grade import Grade
            from pylti1p3.service_connector import ServiceConnector
            registration = conf.find_registration_by_params(link["iss"], link["client_id"])
            connector = ServiceConnector(registration, requests_session=self.requests_session)
            grade = (Grade().set_score_given(round(100 * score, 2)).set_score_maximum(100)
                     .set_activity_progress("Submitted").set_grading_progress("FullyGraded")
                     .set_user_id(student).set_timestamp(
                         datetime.now(timezone.utc).isoformat(timespec="seconds")))
            AssignmentsGradesService(connector, link["ags"]).put_grade(grade)
        except Exception as exc:   # noqa: BLE001 - the platform's failure never loses a grade
            return f"not sent to the platform ({type(exc).__name__}: {str(exc)[:200]})"
        return "sent"


def _classes():
    """pylti1p3's framework adapters for this app (built on first use)."""
    global _ADAPTERS
    if _ADAPTERS is not None:
        return _ADAPTERS
    from pylti1p3.cookie import CookieService
    from pylti1p3.launch_data_storage.cache import CacheDataStorage
    from pylti1p3.message_launch import MessageLaunch
    from pylti1p3.oidc_login import OIDCLogin
    from pylti1p3.redirect import Redirect
    from pylti1p3.request import Request as LtiRequest
    from pylti1p3.session import SessionService

    class Req(LtiRequest):
        def __init__(self, params: dict, cookies: dict, secure: bool):
            super().__init__()
            self.params, self.jar, self.secure = params, cookies, secure

        @property
        def session(self):
            return {}

        def get_param(self, key):
            return self.params.get(key)

        def get_cookie(self, key):
            return self.jar.get(key)

        def is_secure(self):
            return self.secure

    class Cookies(CookieService):
        def __init__(self, request):
            self.request, self.to_set = request, {}

        def get_cookie(self, name):
            return self.request.get_cookie(f"{self._cookie_prefix}-{name}")

        def set_cookie(self, name, value, exp=3600):
            self.to_set[f"{self._cookie_prefix}-{name}"] = (str(value), exp)

        def apply(self, response):
            secure = self.request.is_secure()
            for key, (value, exp) in self.to_set.items():
                response.set_cookie(key, value, max_age=exp, path="/", httponly=True,
                                    secure=secure, samesite="none" if secure else "lax")
            return response

    class Redirecting(Redirect):
        def __init__(self, location, cookies):
            self.location, self.cookies = location, cookies

        def do_redirect(self):
            return self.cookies.apply(RedirectResponse(self.location, status_code=302))

        do_js_redirect = do_redirect   # the page's CSP runs no inline script

        def set_redirect_url(self, location):
            self.location = location

        def get_redirect_url(self):
            return self.location

    class Storage(CacheDataStorage):
        def __init__(self, cache):
            super().__init__()
            self._cache = cache

    class Login(OIDCLogin):
        def get_redirect(self, url):
            return Redirecting(url, self._cookie_service)

    class Launch(MessageLaunch):
        def _get_request_param(self, key):
            return self._request.get_param(key)

    _ADAPTERS = {"request": Req, "cookies": Cookies, "storage": Storage, "login": Login,
                 "launch": Launch, "session": SessionService}
    return _ADAPTERS


_ADAPTERS = None


# -- the endpoints --------------------------------------------------------------------------------
async def _params(request: Request) -> dict:
    if request.method == "GET":
        return dict(request.query_params)
    raw = await read_body(request, 64 * 1024)
    return dict(parse_qsl(raw.decode("utf-8", "replace")))


def _parts(srv, request, params):
    a = _classes()
    req = a["request"](params, dict(request.cookies), request.url.scheme == "https")
    cookies, session = a["cookies"](req), a["session"](req)
    storage = a["storage"](srv.lti.cache)
    return a, req, cookies, session, storage


async def _configured(request: Request):
    srv = request.app.state.server
    try:
        conf = srv.lti.conf()
    except RuntimeError as exc:
        return None, error(501, str(exc))
    except Exception as exc:   # noqa: BLE001 - a broken file: say so
        return None, error(500, f"the LTI configuration {CONFIG} cannot be read: {exc}")
    if conf is None:
        return None, error(404, f"LTI is not set up on this server (no {CONFIG} in its data "
                                "directory).")
    return conf, None


async def login(request: Request):
    srv = request.app.state.server
    conf, err = await _configured(request)
    if err:
        return err
    try:
        params = await _params(request)
    except TooLarge as exc:
        return error(413, str(exc))
    target = params.get("target_link_uri") or ""
    if not target.startswith(str(request.base_url).rstrip("/") + "/lti/launch"):
        return error(400, "`target_link_uri` must be this server's /lti/launch.")
    a, req, cookies, session, storage = _parts(srv, request, params)
    oidc = a["login"](req, conf, session_service=session, cookie_service=cookies,
                      launch_data_storage=storage)
    try:
        return await run_in_threadpool(oidc.redirect, target)
    except Exception as exc:   # noqa: BLE001 - pylti1p3's OIDCException and the like
        return error(400, f"LTI login refused: {exc}")


async def launch(request: Request):
    from dualmech.web.classroom_routes import new_numbers
    srv = request.app.state.server
    conf, err = await _configured(request)
    if err:
        return err
    try:
        params = await _params(request)
    except TooLarge as exc:
        return error(413, str(exc))
    a, req, cookies, session, storage = _parts(srv, request, params)
    message = a["launch"](req, conf, session_service=session, cookie_service=cookies,
                          launch_data_storage=storage,
                          requests_session=srv.lti.requests_session)
    try:
        data = await run_in_threadpool(lambda: message.validate().get_launch_data())
    except Exception as exc:   # noqa: BLE001 - LtiException: a forged or stale launch
        return error(403, f"LTI launch refused: {exc}")
    aid = str((data.get(_CUSTOM) or {}).get("assignment", ""))
    rules = await run_in_threadpool(srv.classroom.rules, aid) if aid else None
    if rules is None:
        return error(404, "the launch names no assignment of this server (set the custom "
                          "parameter assignment=<id> on the link).")
    if not any(r.endswith("#Learner") for r in data.get(_ROLES, [])):
        return RedirectResponse("/teacher", status_code=303)
    student = str(data.get("sub", ""))
    if not student or len(student) > 255:
        return error(400, "the launch's `sub` (the user's id) must be 1 to 255 characters.")
    numbers = (await run_in_threadpool(srv.classroom.roster, aid)).get(student) or \
        new_numbers(rules)
    token = await run_in_threadpool(srv.classroom.enrol, aid, student, numbers)
    if data.get(_AGS):
        await run_in_threadpool(srv.lti.link, aid, student, data["iss"],
                                message.get_client_id(), data[_AGS])
    return RedirectResponse(f"/assignments/{aid}#token={token}", status_code=303)


async def jwks(request: Request):
    conf, err = await _configured(request)
    if err:
        return err
    return JSONResponse(conf.get_jwks())


class SameOriginExceptLaunch:
    """The app's :class:`~.guard.SameOrigin` check, except for the LTI login and launch: a
    platform posts them from its own site, and the signed token, state and nonce protect
    them."""

    def __init__(self, app):
        self.app, self.checked = app, SameOrigin(app)

    async def __call__(self, scope, receive, send):
        if scope["type"] == "http" and scope["path"] in _LAUNCH_PATHS:
            return await self.app(scope, receive, send)
        return await self.checked(scope, receive, send)


routes = [
    Route("/lti/login", login, methods=["GET", "POST"]),
    Route("/lti/launch", launch, methods=["POST"]),
    Route("/lti/jwks", jwks),
]
