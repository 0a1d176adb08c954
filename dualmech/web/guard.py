"""What keeps one client from spoiling the page for a class: rate limits, bounded bodies,
strict headers.

* :class:`RateLimiter` -- a token bucket per client and per kind of request (typing previews,
  graded answers, teacher logins), held in a bounded table;
* :func:`read_body` -- reads a request body up to a limit, refusing more (``413``) before it
  is held in memory;
* :class:`SecurityHeaders` -- ASGI middleware that adds a Content-Security-Policy allowing
  only the server's own script and style, and forbids framing and content sniffing;
* :class:`SameOrigin` -- ASGI middleware that refuses (``403``) a state-changing request a
  browser sends from another origin (a page elsewhere posting to the teacher's upload).

Example
-------
>>> rl = RateLimiter({"grade": (1.0, 2)})      # 1 per second, bursts of 2
>>> [rl.allow("10.0.0.1", "grade", now=0.0)[0] for _ in range(3)]
[True, True, False]
>>> rl.allow("10.0.0.1", "grade", now=1.0)[0], rl.allow("10.0.0.2", "grade", now=0.0)[0]
(True, True)
"""
from __future__ import annotations

import threading
import time
from collections import OrderedDict

__all__ = ["RateLimiter", "read_body", "TooLarge", "SecurityHeaders", "SameOrigin", "RATES"]

#: Default rates: kind -> (requests per second sustained, burst).
RATES = {"validate": (5.0, 20), "grade": (1.0, 30), "login": (0.1, 5), "upload": (0.2, 5)}

_CSP = ("default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
        "connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'")


class RateLimiter:
    """Token buckets per ``(client, kind)``; ``rates[kind] = (per_second, burst)``.

    At most ``clients`` buckets are kept (the least recently used go first), so a flood of
    addresses cannot fill memory.
    """

    def __init__(self, rates: dict | None = None, clients: int = 10000):
        self.rates = dict(RATES if rates is None else rates)
        self.clients = clients
        self._buckets: OrderedDict = OrderedDict()
        self._lock = threading.Lock()

    def allow(self, client: str, kind: str, now: float | None = None) -> tuple[bool, float]:
        """``(allowed, seconds to wait)`` for one request of ``kind`` from ``client``."""
        if kind not in self.rates:
            return True, 0.0
        rate, burst = self.rates[kind]
        now = time.monotonic() if now is None else now
        key = (client, kind)
        with self._lock:
            tokens, last = self._buckets.pop(key, (float(burst), now))
            tokens = min(float(burst), tokens + (now - last) * rate)
            ok = tokens >= 1.0
            if ok:
                tokens -= 1.0
            self._buckets[key] = (tokens, now)
            while len(self._buckets) > self.clients:
                self._buckets.popitem(last=False)
        return ok, 0.0 if ok else (1.0 - tokens) / rate


class TooLarge(Exception):
    """A request body over its limit; the message says the limit."""


async def read_body(request, limit: int) -> bytes:
    """The body of ``request``, refusing more than ``limit`` bytes without reading them all."""
    declared = request.headers.get("content-length")
    if declared is not None:
        try:
            if int(declared) > limit:
                raise TooLarge(f"the request is {int(declared)} bytes; at most {limit} are "
                               "accepted here.")
        except ValueError:
            raise TooLarge("the Content-Length header is not a number.") from None
    chunks, size = [], 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limit:
            raise TooLarge(f"the request is larger than {limit} bytes, the most accepted here.")
        chunks.append(chunk)
    return b"".join(chunks)


class SecurityHeaders:
    """ASGI middleware adding strict security headers to every HTTP response."""

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)

        async def wrapped(message):
            if message["type"] == "http.response.start":
                headers = list(message.get("headers", []))
                headers += [(b"content-security-policy", _CSP.encode()),
                            (b"x-content-type-options", b"nosniff"),
                            (b"x-frame-options", b"DENY"),
                            # same-origin, not no-referrer: under no-referrer a browser
                            # sends `Origin: null` on the page's own form posts, which
                            # SameOrigin must refuse; no referrer leaves for other sites
                            (b"referrer-policy", b"same-origin")]
                message = dict(message, headers=headers)
            await send(message)
        return await self.app(scope, receive, wrapped)


class SameOrigin:
    """ASGI middleware: a ``POST``, ``PUT``, ``PATCH`` or ``DELETE`` whose ``Origin`` header
    names another origin than the one the request was sent to is refused with ``403``.

    Browsers send ``Origin`` on every cross-origin request that changes state, so a page on
    another site (or another port of the same site, which ``SameSite`` cookies do not tell
    apart) cannot post to the teacher's upload with the teacher's cookie.  Clients that are not
    browsers (curl, scripts) send no ``Origin`` and are judged by their token as before.
    """

    STATE_CHANGING = frozenset({"POST", "PUT", "PATCH", "DELETE"})

    def __init__(self, app):
        self.app = app

    async def __call__(self, scope, receive, send):
        if scope["type"] == "http" and scope["method"] in self.STATE_CHANGING:
            headers = dict(scope.get("headers") or [])
            origin = headers.get(b"origin")
            if origin is not None and not _same_origin(origin, scope, headers.get(b"host")):
                body = (b'{"error": "a request that changes state must come from this '
                        b'server\'s own pages (its Origin header names another site)."}')
                await send({"type": "http.response.start", "status": 403,
                            "headers": [(b"content-type", b"application/json"),
                                        (b"content-length", str(len(body)).encode())]})
                await send({"type": "http.response.body", "body": body})
                return
        return await self.app(scope, receive, send)


def _same_origin(origin: bytes, scope, host: bytes | None) -> bool:
    """Whether ``origin`` (``scheme://host[:port]``) is where the request was sent."""
    if host is None:
        return False
    scheme = scope.get("scheme", "http")
    default = {"http": b"80", "https": b"443"}.get(scheme, b"")
    want = host if b":" in host else host + b":" + default
    got = origin.split(b"://", 1)
    if len(got) != 2 or got[0].decode("latin-1").lower() != scheme:
        return False
    have = got[1] if b":" in got[1] else got[1] + b":" + default
    return have.lower() == want.lower()
