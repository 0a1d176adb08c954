"""What every endpoint shares: the JSON error, reading a JSON object body safely.

:func:`json_object` reads a request body up to a limit and returns the JSON object or the
response that says what is wrong with it (too large: 413; not JSON, nested too deeply, not an
object, a lone surrogate anywhere: 400) -- never a 500.

Example
-------
>>> lone_surrogate({"a": ["ok", {"b": "\\ud800"}]}), lone_surrogate({"a": "fine"})
('a', None)
>>> error(400, "no").status_code
400
"""
from __future__ import annotations

import json

from starlette.responses import JSONResponse

from dualmech.web.guard import TooLarge, read_body

__all__ = ["error", "lone_surrogate", "json_object", "server_of", "teacher_only", "safe_cell"]


def error(status: int, message: str, headers: dict | None = None) -> JSONResponse:
    """``{"error": message}`` with ``status``."""
    return JSONResponse({"error": message}, status_code=status, headers=headers)


def lone_surrogate(body: dict):
    """The top-level key under which ``body`` holds a string (a key or a value, at any depth)
    with a lone UTF-16 surrogate, which no page can show and no file can store; ``None``
    when there is none."""
    stack = [(key, part) for key, value in body.items() for part in (key, value)]
    while stack:
        key, part = stack.pop()
        if isinstance(part, str):
            try:
                part.encode("utf-8")
            except UnicodeEncodeError:
                return key.encode("utf-8", "replace").decode()[:40]
        elif isinstance(part, dict):
            stack += [(key, x) for item in part.items() for x in item]
        elif isinstance(part, list):
            stack += [(key, x) for x in part]
    return None


async def json_object(request, limit: int, shape: str):
    """``(body, None)`` with the request's JSON object, or ``(None, error response)``;
    ``shape`` shows the expected object in the messages."""
    try:
        raw = await read_body(request, limit)
    except TooLarge as exc:
        return None, error(413, str(exc))
    try:
        body = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError):
        return None, error(400, f"the request body must be a JSON object: {shape}.")
    except RecursionError:
        return None, error(400, f"the request body is nested too deeply: send a flat JSON "
                                f"object {shape}.")
    if not isinstance(body, dict):
        return None, error(400, f"the request body must be a JSON object: {shape}.")
    bad = lone_surrogate(body)
    if bad is not None:
        return None, error(400, f"`{bad}` holds a lone surrogate (an escape such as \\ud800 "
                                "that is half of a character); send the text as it is typed.")
    return body, None


def server_of(request):
    """The state every endpoint shares (``app.state.server``) for ``request``."""
    return request.app.state.server


def teacher_only(handler):
    """``handler`` for the teacher alone (the token, or the session cookie of /teacher)."""
    async def guarded(request):
        if not server_of(request).teacher(request):
            return error(401, "this needs the teacher token (Authorization: Bearer <token>, "
                              "or log in on /teacher).")
        return await handler(request)
    return guarded


def safe_cell(v) -> str:
    """``v`` as a CSV cell no spreadsheet reads as a formula (``'`` before ``= + - @``, a tab
    or a carriage return): an answer ``-g*sin(theta)`` stays text.

    >>> safe_cell("=HYPERLINK(1)"), safe_cell("-g*sin(theta)"), safe_cell("s1"), safe_cell(None)
    ("'=HYPERLINK(1)", "'-g*sin(theta)", 's1', '')
    """
    s = "" if v is None else str(v)
    return "'" + s if s[:1] in ("=", "+", "-", "@", "\t", "\r") else s
