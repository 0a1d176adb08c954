"""``dualmech serve``: the app under uvicorn, loopback by default, the teacher token printed.

Example
-------
>>> is_loopback("127.0.0.1"), is_loopback("localhost"), is_loopback("0.0.0.0")
(True, True, False)
"""
from __future__ import annotations

import ipaddress
import secrets
import socket
import sys
from pathlib import Path
from typing import Sequence

__all__ = ["serve", "is_loopback"]


def is_loopback(host: str) -> bool:
    """Whether ``host`` is reachable from this machine only."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def serve(host: str = "127.0.0.1", port: int = 8000, problems: Sequence[str] | None = None,
          *, token: str | None = None, data: str | Path = "dualmech-data",
          workers: int | None = None, out=sys.stdout, as_json: bool = False) -> None:
    """Serve the pages and the API until interrupted (see :func:`.app.create_app`).

    ``token`` is the teacher's; a random one is made and printed when none is given.
    """
    import uvicorn

    from dualmech.web.app import create_app
    try:
        Path(data).mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"cannot use {data} for the data: {exc.strerror or exc}") from None
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as probe:   # a clear error, before starting
        probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            probe.bind((host, port))
        except OSError as exc:
            raise ValueError(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None
    token = token or secrets.token_urlsafe(18)
    app = create_app(problems, data=data, token=token, workers=workers)
    shown = f"[{host}]" if ":" in host else host
    n = len(app.state.server.served)
    if as_json:
        import json
        print(json.dumps({"url": f"http://{shown}:{port}/", "teacher":
                          f"http://{shown}:{port}/teacher", "token": token,
                          "problems": list(app.state.server.served),
                          "data": str(Path(data).resolve()),
                          "loopback": is_loopback(host)}), file=out)
        out.flush()
        uvicorn.run(app, host=host, port=port, log_level="warning", timeout_keep_alive=5,
                    limit_concurrency=1000, h11_max_incomplete_event_size=16 * 1024)
        return
    print(f"dualmech: serving {n} problem{'s' if n != 1 else ''} on "
          f"http://{shown}:{port}/  (data in {Path(data).resolve()})", file=out)
    print(f"dualmech: teacher page http://{shown}:{port}/teacher  token: {token}", file=out)
    if not is_loopback(host):
        print(f"dualmech: warning: {host} is reachable from other machines; anyone who can "
              "reach it can use the student pages (the teacher page needs the token).",
              file=out)
    out.flush()
    uvicorn.run(app, host=host, port=port, log_level="warning", timeout_keep_alive=5,
                limit_concurrency=1000, h11_max_incomplete_event_size=16 * 1024)
