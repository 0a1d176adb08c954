"""The teacher's token and sessions: a strong token, sessions that expire, logout, no caching.

* :func:`check_token` refuses a weak teacher token (short, or of few distinct characters),
  saying how to make a strong one;
* :class:`Sessions` keeps the teacher's login sessions in the server's SQLite file: a random
  id per login (the cookie; only its SHA-256 is stored), valid for :data:`SESSION_SECONDS`,
  ended by logout;
* :class:`NoStore` -- ASGI middleware adding ``Cache-Control: no-store`` to every response
  that may carry a teacher's or a student's data (teacher pages, assignment pages, the
  authenticated API), so no browser or proxy keeps a copy.

Example
-------
>>> import tempfile
>>> from dualmech.web.store import Store
>>> s = Sessions(Store(tempfile.mkdtemp()), seconds=60)
>>> sid = s.open(now=0.0)
>>> s.valid(sid, now=30.0), s.valid(sid, now=61.0), s.valid("forged", now=1.0)
(True, False, False)
>>> check_token("s3cret")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: the teacher token is too weak (6 characters); use at least 16 characters of ...
"""
from __future__ import annotations

import hashlib
import secrets
import time

__all__ = ["check_token", "Sessions", "NoStore", "SESSION_SECONDS", "MIN_TOKEN"]

#: How long a teacher's login lasts.
SESSION_SECONDS = 8 * 3600.0
#: Fewest characters (and distinct characters: half as many) of a teacher token.
MIN_TOKEN = 16

_SCHEMA = "CREATE TABLE IF NOT EXISTS sessions (hash TEXT PRIMARY KEY, expires REAL NOT NULL);"


def check_token(token) -> str:
    """``token`` when it is a strong teacher token; ``ValueError`` saying what to use else."""
    if not isinstance(token, str) or not token:
        raise ValueError("`token` must be a non-empty string.")
    if len(token) < MIN_TOKEN or len(set(token)) < MIN_TOKEN // 2 or token != token.strip():
        raise ValueError(
            f"the teacher token is too weak ({len(token)} characters); use at least "
            f"{MIN_TOKEN} characters of several kinds, e.g. the output of `python -c \"import "
            "secrets; print(secrets.token_urlsafe(24))\"`.")
    return token


def digest(secret: str) -> str:
    """The SHA-256 (hex) a secret is stored as."""
    return hashlib.sha256(secret.encode("utf-8", "surrogatepass")).hexdigest()


class Sessions:
    """Teacher sessions in ``store``'s SQLite file (see the module docstring)."""

    def __init__(self, store, seconds: float = SESSION_SECONDS):
        self.store = store
        self.seconds = float(seconds)
        with store._lock:
            store._db.executescript(_SCHEMA)

    def open(self, now: float | None = None) -> str:
        """A new session's id (what the cookie holds); expired sessions are dropped."""
        now = time.time() if now is None else now
        sid = secrets.token_urlsafe(32)
        with self.store._lock:
            self.store._db.execute("DELETE FROM sessions WHERE expires <= ?", (now,))
            self.store._db.execute("INSERT INTO sessions VALUES (?, ?)",
                                   (digest(sid), now + self.seconds))
        return sid

    def valid(self, sid: str, now: float | None = None) -> bool:
        """Whether ``sid`` is an open session that has not expired."""
        if not sid or len(sid) > 200:
            return False
        now = time.time() if now is None else now
        rows = self.store._all("SELECT expires FROM sessions WHERE hash = ?", (digest(sid),))
        return bool(rows) and rows[0]["expires"] > now

    def close(self, sid: str) -> None:
        """End session ``sid`` (logout)."""
        if sid:
            self.store._run("DELETE FROM sessions WHERE hash = ?", (digest(sid),))


_PRIVATE = ("/teacher", "/assignments", "/api/batches", "/api/assignments", "/api/students",
            "/lti")


class NoStore:
    """ASGI middleware: ``Cache-Control: no-store`` on the pages and API answers that may
    hold a teacher's or a student's data (paths under :data:`_PRIVATE`)."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http" or not scope["path"].startswith(_PRIVATE):
            return await self.app(scope, receive, send)

        async def wrapped(message):
            if message["type"] == "http.response.start":
                headers = [h for h in message.get("headers", [])
                           if h[0].lower() != b"cache-control"]
                headers += [(b"cache-control", b"no-store"), (b"pragma", b"no-cache")]
                message = dict(message, headers=headers)
            await send(message)
        return await self.app(scope, receive, wrapped)
