"""The ``dualmech serve`` subcommand (wired into the ``dualmech`` command by :func:`register`).

::

    dualmech serve [--host 127.0.0.1] [--port 8000] [--problems NAME|FILE ...] [--token T]
                   [--data DIR] [--workers N]

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
import sys
from pathlib import Path

__all__ = ["register", "handle"]


def _port(text: str) -> int:
    try:
        port = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"`--port` must be a whole number, got {text!r}.")
    if not 0 < port < 65536:
        raise argparse.ArgumentTypeError(f"`--port` must be 1 to 65535, got {port}.")
    return port


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
    p.add_argument("--problems", nargs="+", metavar="NAME|FILE",
                   help="the problems to serve: catalogue names or problem files (default: "
                        "the whole catalogue); clients can only name these")
    p.add_argument("--token", help="the teacher's token (default: a random one, printed)")
    p.add_argument("--data", type=Path, default=Path("dualmech-data"), metavar="DIR",
                   help="where batches and results are kept (default: %(default)s)")
    p.add_argument("--workers", type=int, default=None, metavar="N",
                   help="grading processes (default: every core)")
    p.add_argument("--json", action="store_true",
                   help="print the address, the teacher's token and the problems as one JSON "
                        "line at start")
    p.set_defaults(func=handle)
    return p


def handle(args: argparse.Namespace) -> int:
    """Run the server; 2 with a message when it cannot start."""
    try:
        import starlette  # noqa: F401
        import uvicorn  # noqa: F401
    except ImportError:
        print("dualmech serve: error: the web extra is missing: pip install 'dualmech[web]'",
              file=sys.stderr)
        return 2
    if args.workers is not None and args.workers < 1:
        print("dualmech serve: error: `--workers` must be at least 1.", file=sys.stderr)
        return 2
    from dualmech.web.server import serve
    try:
        serve(args.host, args.port, args.problems, token=args.token, data=args.data,
              workers=args.workers, as_json=args.json)
    except ValueError as exc:
        print(f"dualmech serve: error: {exc}", file=sys.stderr)
        return 2
    return 0
