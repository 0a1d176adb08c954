"""The ``dualmech serve`` subcommand (wired into the ``dualmech`` command by :func:`register`).

::

    dualmech serve [--host 127.0.0.1] [--port 8000] [--problems NAME ...]
                   [--token-file FILE] [--data DIR] [--workers N] [--trusted-proxy ADDR ...]
                   [--header-timeout S] [--body-timeout S] [--connections-per-client N]

The teacher's token is read from ``--token-file`` (a file only its owner can read) or the
environment variable ``DUALMECH_TOKEN``, never from the command line, where every user of
the machine sees it (``ps``); without either a random one is made and printed.  A weak token
(under 16 characters, or of few distinct ones) is refused.

``--problems`` takes every NAME form (a catalogue name, a file ``path.py[:Class]``,
``module:Class``, a registered catalogue's problem, or a registered catalogue's name for
all its problems).  A problem outside dualmech's catalogue is loaded and its models built
before the server starts, so that an error in a teacher's file stops it at once, shown at
its file and line (exit status 2, :mod:`dualmech.cli.errors`); a file is passed on as an
absolute path, which the grading processes load the same way.

Example
-------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="dualmech")
>>> _ = register(parser.add_subparsers(dest="command"))
>>> args = parser.parse_args(["serve", "--port", "8123", "--problems", "toy_car"])
>>> args.host, args.port, args.problems
('127.0.0.1', 8123, ['toy_car'])
"""
from __future__ import annotations

import argparse
import os
import stat
from pathlib import Path

from dualmech.cli import names as _names
from dualmech.cli.errors import OK, UsageError, about, guarded

__all__ = ["register", "handle", "served_specs", "read_token", "TOKEN_VARIABLE"]

#: The environment variable a teacher's token may be given in.
TOKEN_VARIABLE = "DUALMECH_TOKEN"


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"`--port` must be a whole number, got {text!r}.")
    if not 0 < port < 65536:
        raise argparse.ArgumentTypeError(f"`--port` must be 1 to 65535, got {port}.")
    return port


def _seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}.")
    if not 0 < value <= 3600:
        raise argparse.ArgumentTypeError(f"expected 0 < seconds <= 3600, got {text!r}.")
    return value


def register(subparsers) -> argparse.ArgumentParser:
    """Add the ``serve`` subcommand to an argparse ``subparsers`` object; return its parser."""
    p = subparsers.add_parser(
        "serve", help="serve the answer pages, the teacher page and the JSON API",
        description="Serve a page per problem where students type answers (validated while "
                    "they type, graded on submission), a teacher page (token) that grades a "
                    "class's CSV, and a JSON API (/api/docs).  Needs the 'web' extra: pip "
                    "install 'dualmech[web]'.")
    p.add_argument("--host", default="127.0.0.1",
                   help="address to listen on (default: %(default)s, this machine only)")
    p.add_argument("--port", type=_port, default=8000, help="port (default: %(default)s)")
    p.add_argument("--problems", nargs="+", metavar="NAME",
                   help="the problems to serve: catalogue names, problem files "
                        "path.py[:Class], module:Class, a registered catalogue's problem or "
                        "its name for all of them (default: dualmech's catalogue); clients "
                        "can only name these")
    p.add_argument("--token-file", type=Path, metavar="FILE",
                   help=f"a file holding the teacher's token, readable by its owner only "
                        f"(chmod 600); or set {TOKEN_VARIABLE}; default: a random token, "
                        "printed")
    p.add_argument("--token", help=argparse.SUPPRESS)   # refused: visible in `ps`
    p.add_argument("--data", type=Path, default=None, metavar="DIR",
                   help="where batches, results and answers are kept, readable by you only "
                        "(default: your data folder, ~/.local/share/dualmech on Linux)")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="grading processes (default: every core)")
    p.add_argument("--trusted-proxy", action="append", default=[], metavar="ADDR",
                   help="a reverse proxy (IP address or network) whose X-Forwarded-For is "
                        "believed; repeat for several (default: none, every client is its "
                        "own address)")
    p.add_argument("--header-timeout", type=_seconds, default=10.0, metavar="S",
                   help="seconds a request's headers may take to arrive (default: "
                        "%(default)s)")
    p.add_argument("--body-timeout", type=_seconds, default=30.0, metavar="S",
                   help="seconds a request's body may take to arrive after its headers "
                        "(default: %(default)s)")
    p.add_argument("--connections-per-client", type=int, default=128, metavar="N",
                   help="open connections one address may hold at once (default: "
                        "%(default)s)")
    p.add_argument("--json", action="store_true",
                   help="print the address, the teacher's token and the problems as one JSON "
                        "line at start")
    p.set_defaults(func=handle)
    return p


@guarded
def handle(args: argparse.Namespace) -> int:
    """Run the server; 2 with a message when it cannot start."""
    try:
        import starlette  # noqa: F401
        import uvicorn  # noqa: F401
    except ImportError:
        raise UsageError("the web extra is missing: pip install 'dualmech[web]'") from None
    if args.workers is not None and args.workers < 1:
        raise UsageError("`--workers` must be at least 1.")
    if args.connections_per_client < 1:
        raise UsageError("`--connections-per-client` must be at least 1.")
    from dualmech.web.server import ConnectionLimits, proxy_settings, serve
    try:
        proxy_settings(args.trusted_proxy)
    except ValueError as exc:
        raise UsageError(f"`--trusted-proxy`: {exc}") from None
    token = read_token(args.token_file, os.environ, args.token)
    specs = served_specs(args.problems)
    limits = ConnectionLimits(args.header_timeout, args.body_timeout, args.connections_per_client)
    try:
        serve(args.host, args.port, specs, token=token, data=args.data,
              workers=args.workers, as_json=args.json, trusted_proxies=args.trusted_proxy,
              limits=limits)
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return OK


def read_token(path: Path | None, environ, given: str | None = None) -> str | None:
    """The teacher's token from ``path`` or ``environ[TOKEN_VARIABLE]`` (None: the server
    makes one); a token ``given`` on the command line, a file others can read or one that
    cannot be read is a usage error saying what to do.

    >>> read_token(None, {"DUALMECH_TOKEN": "  from-the-environment-1  "})
    'from-the-environment-1'
    >>> read_token(None, {}) is None
    True
    """
    if given is not None:
        raise UsageError(f"`--token` would show the token to every user of this machine "
                         f"(`ps`); put it in a file only you can read and pass "
                         f"`--token-file FILE`, or set {TOKEN_VARIABLE}.")
    if path is not None:
        try:
            mode = path.stat().st_mode
            if mode & (stat.S_IRWXG | stat.S_IRWXO):
                raise UsageError(f"{path} can be read by other users; `chmod 600 {path}` "
                                 "and start again.")
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise UsageError(f"cannot read the token file {path}: "
                             f"{getattr(exc, 'strerror', None) or exc}") from None
        if not text.strip():
            raise UsageError(f"the token file {path} is empty.")
        return text.strip()
    value = environ.get(TOKEN_VARIABLE)
    return value.strip() if value else None


def served_specs(names) -> list | None:
    """The specs the server loads for ``names`` (None: dualmech's whole catalogue): each
    registered catalogue's name expanded to its problems, each file made absolute, and every
    problem outside dualmech's catalogue loaded and its models built here, so that an error
    in it is raised now, at its file and line.

    >>> served_specs(["toy_car"]), served_specs(None)
    (['toy_car'], None)
    """
    if not names:
        return None
    cat = _names.catalogue()
    out = []
    for spec in _names.expand(names):
        if not (cat.is_name(spec) and _catalogued(spec)):
            problem = _names.get(spec)
            with about(problem):
                problem.models()
        out.append(cat.canonical(spec))
    return out


def _catalogued(name: str) -> bool:
    try:
        _names.catalogue().module_of(name)
    except KeyError:
        return False
    return True
