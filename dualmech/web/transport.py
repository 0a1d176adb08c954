"""What keeps slow or greedy connections from stalling the server for everybody else.

uvicorn cuts a connection that sits idle *between* requests (``timeout_keep_alive``), but
not one that is still sending a request: a client that trickles its headers or its body one
byte at a time holds a connection for ever, and about a thousand of them fill the server's
``limit_concurrency`` so that every other request gets ``503``.  :class:`GuardedH11` is the
HTTP/1.1 protocol uvicorn runs, with two more rules:

* **deadlines**: a request's headers must be complete within ``header_seconds`` of its first
  byte, and its body within ``body_seconds`` of its headers; past either the server answers
  ``408 Request Timeout`` (when nothing has been sent yet) and closes the connection;
* **connections per client**: one address holds at most ``per_client`` open connections at
  once; the next one is answered ``503`` and closed at once, so one client can never use up
  the connections the rest of the class needs.

:func:`protocol` makes the class with these limits bound in; :func:`raise_open_files` lifts
the process's open-file limit so the connection limits, not the operating system, decide.

Example
-------
>>> limits = ConnectionLimits(header_seconds=5, body_seconds=20, per_client=64)
>>> cls = protocol(limits)
>>> cls.limits.per_client, issubclass(cls, GuardedH11)
(64, True)
>>> ConnectionLimits(header_seconds=0)
Traceback (most recent call last):
...
ValueError: header_seconds must be a positive number of seconds, got 0.
"""
from __future__ import annotations

import asyncio
import math
from collections import Counter
from dataclasses import dataclass

from uvicorn.protocols.http.h11_impl import H11Protocol

__all__ = ["ConnectionLimits", "GuardedH11", "protocol", "raise_open_files"]



def _response(status: str, text: str, *extra: str) -> bytes:
    body = text.encode()
    head = [f"HTTP/1.1 {status}", "content-type: text/plain; charset=utf-8",
            "connection: close", *extra, f"content-length: {len(body)}", "", ""]
    return "\r\n".join(head).encode() + body


_408 = _response("408 Request Timeout", "the request took too long to arrive.\n")
_503 = _response("503 Service Unavailable", "too many open connections from this address.\n",
                 "retry-after: 5")


@dataclass(frozen=True)
class ConnectionLimits:
    """Deadlines (seconds) for a request still arriving, and open connections per address."""

    header_seconds: float = 10.0
    body_seconds: float = 30.0
    per_client: int = 128

    def __post_init__(self):
        for name in ("header_seconds", "body_seconds"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ValueError(f"{name} must be a positive number of seconds, got {value!r}.")
        if not (isinstance(self.per_client, int) and self.per_client >= 1):
            raise ValueError(f"per_client must be a whole number of at least 1, got "
                             f"{self.per_client!r}.")


class GuardedH11(H11Protocol):
    """uvicorn's h11 protocol with request deadlines and a cap on connections per address.

    Made by :func:`protocol`, which binds ``limits`` and a fresh count of connections per
    address (``open``) to the class; one server uses one such class.
    """

    limits: ConnectionLimits = ConnectionLimits()
    open: Counter = Counter()

    _timer: asyncio.TimerHandle | None = None
    _counted: str | None = None
    _phase: str = "idle"              # idle -> headers -> body -> app (-> idle on keep-alive)

    def connection_made(self, transport) -> None:  # type: ignore[override]
        super().connection_made(transport)
        host = self.client[0] if self.client else "unknown"
        if self.open[host] >= self.limits.per_client:
            transport.write(_503)
            transport.close()
            return
        self.open[host] += 1
        self._counted = host
        self._arm("headers", self.limits.header_seconds)

    def connection_lost(self, exc) -> None:
        self._disarm()
        if self._counted is not None:
            self.open[self._counted] -= 1
            if self.open[self._counted] <= 0:
                del self.open[self._counted]
            self._counted = None
        super().connection_lost(exc)

    def data_received(self, data: bytes) -> None:
        if self._counted is None:             # refused in connection_made: read nothing
            return
        if self._phase == "idle":              # the first byte of a keep-alive request
            self._arm("headers", self.limits.header_seconds)
        super().data_received(data)
        self._advance()

    def _advance(self) -> None:
        """Move the deadline on as the request arrives: headers done -> body; body done ->
        none (the application's own time is not the client's)."""
        cycle = self.cycle
        if cycle is None or cycle.response_complete:
            return
        if self._phase == "headers":
            self._arm("body", self.limits.body_seconds)
        if self._phase == "body" and not cycle.more_body:
            self._disarm()
            self._phase = "app"

    def on_response_complete(self) -> None:
        self._disarm()
        self._phase = "idle"
        super().on_response_complete()        # may start a pipelined request at once
        if self.cycle is not None and not self.cycle.response_complete:
            self._phase = "headers"
            self._advance()

    def _arm(self, phase: str, seconds: float) -> None:
        self._disarm()
        self._phase = phase
        self._timer = self.loop.call_later(seconds, self._expired)

    def _disarm(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None

    def _expired(self) -> None:
        self._timer = None
        if self.transport.is_closing():
            return
        cycle = self.cycle
        if cycle is None or cycle.response_complete or not cycle.response_started:
            self.transport.write(_408)
        self.transport.close()


def protocol(limits: ConnectionLimits) -> type[GuardedH11]:
    """A :class:`GuardedH11` subclass with ``limits`` and its own count of connections."""
    return type("GuardedH11", (GuardedH11,), {"limits": limits, "open": Counter()})


def raise_open_files(wanted: int) -> int:
    """Raise this process's soft limit of open files towards ``wanted`` (never above the hard
    limit); return the limit now in force."""
    try:
        import resource
    except ImportError:                       # not a POSIX system: nothing to raise
        return wanted
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    target = wanted if hard == resource.RLIM_INFINITY else min(wanted, hard)
    if soft != resource.RLIM_INFINITY and soft < target:
        try:
            resource.setrlimit(resource.RLIMIT_NOFILE, (target, hard))
            soft = target
        except (ValueError, OSError):
            pass
    return soft
