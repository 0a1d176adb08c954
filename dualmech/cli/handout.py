"""The ``dualmech handout`` subcommand: a problem sheet for a student, a solution sheet for
the teacher (:mod:`dualmech.report.handouts`).

::

    dualmech handout NAME [--numbers 'm=1.2, l=0.5'] [--solution] [-o DIR] [--json]

Writes ``DIR/NAME_problem.tex`` (``_solution.tex`` with ``--solution``) and its PDF when
``pdflatex`` is installed; says why when there is no PDF.  ``--numbers`` are the student's
values of the problem's parameters (names and decimal numbers, read without evaluating
anything; each inside its declared range); the others keep their defaults.

Exit status: 0 written, 2 a usage error (an unknown problem or parameter, a value that is not
a number or is outside its range, an unwritable directory).

Example
-------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="dualmech")
>>> _ = register(parser.add_subparsers(dest="command"))
>>> args = parser.parse_args(["handout", "simple_pendulum", "--numbers", "a=0.5"])
>>> (args.numbers, args.solution, str(args.out))
('a=0.5', False, '.')
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from dualmech.cli import names as _names
from dualmech.cli.errors import OK, UsageError, about

__all__ = ["register", "handle"]


def register(subparsers) -> argparse.ArgumentParser:
    """Add the ``handout`` subcommand to an argparse ``subparsers`` object; return its parser."""
    p = subparsers.add_parser(
        "handout", help="write a problem sheet (or, --solution, the teacher's solution sheet)",
        description="Write a problem's sheet for a student -- statement, figure, coordinates, "
                    "the student's numbers, no solution -- or, with --solution, the teacher's "
                    "sheet: both derivations, the reactions, the equations with the numbers "
                    "and the printed answers' errata.  LaTeX, and PDF when pdflatex is "
                    "installed.",
        epilog="Exit status: 0 written, 2 a usage error (unknown problem or parameter, a "
               "value that is not a number or outside its range, an unwritable directory).")
    p.add_argument("name", metavar="NAME", help="the problem")
    p.add_argument("--numbers", metavar="'P=V, ...'", default="",
                   help="the student's parameter values, e.g. 'm=1.2, l=0.5' (default: the "
                        "problem's defaults)")
    p.add_argument("--solution", action="store_true", help="the teacher's solution sheet")
    p.add_argument("-o", "--out", metavar="DIR", type=Path, default=Path("."),
                   help="where to write (default: the current directory)")
    p.add_argument("--json", action="store_true", help="print JSON: the files written")
    p.set_defaults(func=handle)
    return p


def handle(args: argparse.Namespace) -> int:
    """Write the sheet ``args`` asks for; print what was written."""
    from dualmech.report.handouts import numbers_of, parse_numbers, write_handout
    problem = _names.get(args.name)
    try:
        numbers = parse_numbers(args.numbers)
        numbers_of(problem, numbers)
    except ValueError as exc:
        raise UsageError(f"--numbers: {exc}") from None
    with about(problem):
        try:
            h = write_handout(problem, numbers, args.out, solution=args.solution)
        except OSError as exc:
            raise UsageError(f"cannot write to {args.out}: {exc.strerror or exc}") from None
    if args.json:
        print(json.dumps({"tex": str(h.tex), "pdf": str(h.pdf) if h.pdf else None,
                          "note": h.note}))
    else:
        print(f"wrote {h.tex}" + (f" and {h.pdf}" if h.pdf else f" (no PDF: {h.note})"))
    return OK
