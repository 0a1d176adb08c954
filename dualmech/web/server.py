"""``dualmech serve``: the app under uvicorn, loopback by default, the teacher token printed.

What reaches the application is bounded before it gets there (:mod:`.transport`): a request
must arrive within its deadlines, one address holds a bounded number of connections, and
``X-Forwarded-For`` is believed only from the proxies named in ``trusted_proxies`` (none by
default: a client on this machine cannot claim to be another).  The data -- batches, results,
students' answers -- lives in the user's data folder unless ``data`` says otherwise, in a
directory only its owner can open, and every file the server writes is private to its owner.

Example
-------
>>> is_loopback("127.0.0.1"), is_loopback("localhost"), is_loopback("0.0.0.0")
(True, True, False)
>>> default_data_dir().name
'dualmech'
"""
from __future__ import annotations

import ipaddress
import os
import secrets
import socket
import sys
from pathlib import Path
from typing import Sequence

from dualmech.web.store import default_data_dir
from dualmech.web.transport import ConnectionLimits, protocol, raise_open_files

__all__ = ["serve", "is_loopback", "default_data_dir", "prepare_data_dir", "proxy_settings",
           "ConnectionLimits"]

#: Connections the server accepts at once, from all clients together.
CONNECTIONS = 2048


def is_loopback(host: str) -> bool:
    """Whether ``host`` is reachable from this machine only."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def prepare_data_dir(data: str | Path | None) -> Path:
    """Create the data directory (the default one when ``data`` is None) readable by its owner
    only, and make every file this process creates from now on private (``umask 077``).

    A directory that exists already is made private too; one owned by somebody else is
    refused, since its owner could read every answer.
    """
    path = Path(data) if data is not None else default_data_dir()
    try:
        path.mkdir(parents=True, exist_ok=True, mode=0o700)
        if hasattr(os, "getuid") and path.stat().st_uid != os.getuid():
            raise ValueError(f"cannot use {path} for the data: it belongs to another user, "
                             "who could read every answer; choose a directory of your own "
                             "with --data.")
        path.chmod(0o700)
        for existing in path.iterdir():
            if existing.is_file():
                existing.chmod(0o600)
    except OSError as exc:
        raise ValueError(f"cannot use {path} for the data: {exc.strerror or exc}") from None
    os.umask(0o077)
    return path


def proxy_settings(trusted_proxies: Sequence[str] = ()) -> dict:
    """uvicorn's settings for ``X-Forwarded-For``: believed from ``trusted_proxies`` only.

    >>> proxy_settings()
    {'proxy_headers': False}
    >>> proxy_settings(["10.0.0.5"])
    {'proxy_headers': True, 'forwarded_allow_ips': '10.0.0.5'}
    >>> proxy_settings(["nonsense"])
    Traceback (most recent call last):
    ...
    ValueError: a trusted proxy must be an IP address or network (10.0.0.5, 10.0.0.0/8), got 'nonsense'.
    """
    checked = []
    for p in trusted_proxies:
        try:
            checked.append(str(ipaddress.ip_network(p, strict=False)) if "/" in p
                           else str(ipaddress.ip_address(p)))
        except ValueError:
            raise ValueError(f"a trusted proxy must be an IP address or network (10.0.0.5, "
                             f"10.0.0.0/8), got {p!r}.") from None
    if not checked:
        return {"proxy_headers": False}
    return {"proxy_headers": True, "forwarded_allow_ips": ",".join(checked)}


def _check_port(host: str, port: int) -> None:
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as probe:   # a clear error, before starting
        probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            probe.bind((host, port))
        except OSError as exc:
            raise ValueError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None


def serve(host: str = "127.0.0.1", port: int = 8000, problems: Sequence[str] | None = None,
          *, token: str | None = None, data: str | Path | None = None,
          workers: int | None = None, out=sys.stdout, as_json: bool = False,
          trusted_proxies: Sequence[str] = (), limits: ConnectionLimits | None = None) -> None:
    """Serve the pages and the API until interrupted (see :func:`.app.create_app`).

    ``token`` is the teacher's; a random one is made and printed when none is given.
    ``data`` is the data directory (default :func:`default_data_dir`); ``trusted_proxies``
    the addresses whose ``X-Forwarded-For`` is believed (see :func:`proxy_settings`);
    ``limits`` the deadlines and per-address connections of :class:`.transport.ConnectionLimits`.
    """
    import uvicorn

    from dualmech.web.app import create_app
    proxies = proxy_settings(trusted_proxies)
    limits = limits or ConnectionLimits()
    path = prepare_data_dir(data)
    _check_port(host, port)
    raise_open_files(CONNECTIONS + 256)
    token = token or secrets.token_urlsafe(18)
    app = create_app(problems, data=path, token=token, workers=workers)
    shown = f"[{host}]" if ":" in host else host
    n = len(app.state.server.served)
    if as_json:
        import json
        print(json.dumps({"url": f"http://{shown}:{port}/", "teacher":
                          f"http://{shown}:{port}/teacher", "token": token,
                          "problems": list(app.state.server.served),
                          "data": str(path.resolve()),
                          "loopback": is_loopback(host)}), file=out)
    else:
        print(f"dualmech: serving {n} problem{'s' if n != 1 else ''} on "
              f"http://{shown}:{port}/  (data in {path.resolve()})", file=out)
        print(f"dualmech: teacher page http://{shown}:{port}/teacher  token: {token}", file=out)
        if not is_loopback(host):
            print(f"dualmech: warning: {host} is reachable from other machines; anyone who can "
                  "reach it can use the student pages (the teacher page needs the token).",
                  file=out)
    out.flush()
    uvicorn.run(app, host=host, port=port, log_level="warning", timeout_keep_alive=5,
                limit_concurrency=CONNECTIONS, h11_max_incomplete_event_size=16 * 1024,
                http=protocol(limits), **proxies)
