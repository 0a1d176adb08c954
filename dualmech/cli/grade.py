"""The ``dualmech grade`` subcommand: one answer, a file of equations, or a class in a CSV.

::

    dualmech grade NAME --answer "R*theta'' + ... = 0"        one answer (or one equation)
    dualmech grade NAME --answer-file answer.txt              several lines: a set
    dualmech grade NAME --quantity F_r --answer "m*(...)"     a reaction, T, V, L, Q_q, q''
    dualmech grade NAME --quantity linearised --about "theta=0" --answer "..."
    dualmech grade NAME --list                                 what can be asked of NAME
    dualmech grade --batch answers.csv --out report/           a class: id, question, answer
                   [--workers N | --scheduler ADDRESS] [--no-progress]
    ... --json                                                 JSON instead of text

Every answer is graded in a child process under a 1 s and 256 MB ceiling
(:mod:`dualmech.grade.sandbox`); one that overruns it is "too costly to grade".

NAME is any form :func:`dualmech.problems.get` takes (a catalogue name, a file
``path.py[:Class]``, ``module:Class``, a registered catalogue's problem).  A problem that is
not in dualmech's catalogue is loaded and its models built here first, so an error in the
teacher's file is shown at its file and line before any answer is graded.

Exit status (:mod:`dualmech.cli.errors`): 0 the answer is right (a batch: every row was
graded), 1 it is wrong, 2 it could not be graded as typed, a usage error (the message says
what to fix), an error in the problem's file or a model that cannot be built; 130
interrupted.

Wire it into an argparse command with :func:`register`.

Example
-------
>>> import argparse
>>> parser = argparse.ArgumentParser(prog="dualmech")
>>> _ = register(parser.add_subparsers(dest="command"))
>>> args = parser.parse_args(["grade", "simple_pendulum", "--answer", "a*theta'' + g*sin(theta)"])
>>> args.func(args)  # doctest: +ELLIPSIS
RIGHT: equivalent to the equations of motion...
0
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from dualmech.cli import names as _names
from dualmech.cli.errors import DISAGREE as EXIT_WRONG
from dualmech.cli.errors import UsageError, about, columns, fit, guarded, say
from dualmech.cli.errors import OK as EXIT_RIGHT
from dualmech.cli.errors import USAGE_OR_MODEL_ERROR as EXIT_USAGE

__all__ = ["register", "handle", "EXIT_RIGHT", "EXIT_WRONG", "EXIT_USAGE"]


def register(subparsers) -> argparse.ArgumentParser:
    """Add the ``grade`` subcommand to an argparse ``subparsers`` object; return its parser."""
    p = subparsers.add_parser(
        "grade", help="grade typed answers against a problem's verified equations",
        description="Grade an answer -- equations of motion, one equation, a reaction, T, V, "
                    "L, a generalised force, an acceleration -- against the problem's verified "
                    "equations, exactly, and say what is wrong: the smallest edit, named as "
                    "terms.  A batch CSV (columns id, question, answer; question is NAME or "
                    "NAME:QUANTITY) is graded on every core or on a Dask cluster.",
        epilog="Exit status: 0 right (batch: all graded), 1 wrong, 2 not gradable, a usage "
               "error, an error in the problem's file or a model that cannot be built; 130 "
               "interrupted.")
    p.add_argument("name", nargs="?", metavar="NAME", help="the problem (not with --batch)")
    src = p.add_mutually_exclusive_group()
    src.add_argument("--answer", metavar="TEXT", help="the answer; several equations may be "
                     "separated by ';'")
    src.add_argument("--answer-file", metavar="FILE", type=Path,
                     help="a file with the answer, one equation per line")
    src.add_argument("--batch", metavar="CSV", type=Path,
                     help="grade every row of a CSV with columns id, question, answer")
    src.add_argument("--list", action="store_true", help="list the quantities NAME offers")
    p.add_argument("--quantity", metavar="Q",
                   help="what the answer is: eom (default), equation, equation:q, a reaction "
                        "name, KE/T, PE/V, L, Q_q, q'', linearised, or a printed label")
    p.add_argument("--about", metavar="EQUILIBRIUM",
                   help="for --quantity linearised: e.g. 'theta=0, phi=pi' (default: zero)")
    p.add_argument("--out", metavar="DIR", type=Path, default=Path("grades"),
                   help="with --batch: where results.json and report.md go "
                        "(default: %(default)s)")
    p.add_argument("--workers", metavar="N", type=int, default=None,
                   help="with --batch: processes (default: every core)")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="with --batch: run on the Dask cluster at ADDRESS "
                        "(needs the 'dask' extra)")
    p.add_argument("--feedback", metavar="LEVEL", default="full",
                   choices=("verdict", "locate", "hint", "full"),
                   help="how much a wrong answer is told: verdict (right or wrong only), "
                        "locate (which equation and kind of term), hint (the wrong term, not "
                        "its correction) or full (the smallest edit; the default); one answer "
                        "only: a --batch report is the teacher's and always full")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print JSON instead of text")
    p.set_defaults(func=handle)
    return p


@guarded
def handle(args: argparse.Namespace) -> int:
    """Run ``dualmech grade`` for parsed ``args``; return the exit status."""
    if args.batch is not None:
        return _batch(args)
    if not args.name:
        raise UsageError("name a problem (dualmech grade NAME --answer ...), or use --batch.")
    if args.list:
        _built_if_users(args.name)
        return _list(args)
    if args.answer_file is not None:
        from dualmech.grade.parser import LIMITS
        try:   # read no more than the parser accepts (+1 to see it is too long)
            with open(args.answer_file, encoding="utf-8") as fh:
                answer = fh.read(LIMITS.chars + 1)
        except (OSError, UnicodeDecodeError) as exc:
            raise UsageError(f"cannot read {args.answer_file}: {exc}") from None
    elif args.answer is not None:
        answer = args.answer
    else:
        raise UsageError("give the answer with --answer TEXT or --answer-file FILE.")
    from dualmech.startup import defer, load
    defer("symengine")   # used only when the problem's context must be built
    load("dualmech.grade.api")   # sympy and the grader (see dualmech.startup)
    _built_if_users(args.name)
    from dualmech.grade.sandbox import grade_bounded
    result = grade_bounded(args.name, answer, args.quantity, about=args.about)
    result = result.at_level(args.feedback)
    print(json.dumps(result.to_dict(), indent=2) if args.json
          else fit(str(result), columns(sys.stdout)))   # wrapped, as every report is
    if result.status == "invalid":   # the grade above says why; scripts read stderr
        say("grade", "the answer could not be graded as typed (see above).")
    return {"right": EXIT_RIGHT, "wrong": EXIT_WRONG}.get(result.status, EXIT_USAGE)


def _built_if_users(spec: str) -> None:
    """A problem outside dualmech's catalogue (a file, ``module:Class``, a course package's)
    loaded and its models built, so that an error in it is raised here -- shown at the
    teacher's file and line -- rather than reported by the grading child without its line.
    dualmech's own problems are left to the child (they are tested)."""
    cat = _names.catalogue()
    if cat.is_name(spec):
        try:
            cat.module_of(spec)
            return
        except KeyError:
            pass
        try:
            problem = _names.get(spec)
        except UsageError:   # an unknown name: the grader's own answer says so
            return
    else:
        problem = _names.get(spec)
    with about(problem):
        problem.models()


def _list(args) -> int:
    from dualmech.grade.api import Grader
    from dualmech.grade.parser import AnswerError
    from dualmech.grade.vocabulary import symbol_table
    try:
        grader = Grader.of(args.name)
        quantities = grader.quantities()
        names = symbol_table(grader.context)
    except AnswerError as exc:
        raise UsageError(str(exc)) from None
    if args.json:
        print(json.dumps({"quantities": quantities, "names": names}, indent=2))
    else:
        width = max(len(n) for n in quantities)
        for n, d in quantities.items():
            print(f"{n.ljust(width)}  {d}")
        print("\nnames an answer may use (also accepted; unit; meaning):")
        width = max(len(r["name"]) for r in names)
        for r in names:
            also = ", ".join(r["aliases"])
            print(f"  {r['name'].ljust(width)}  {r['kind']:10s} {also + ';' if also else ''} "
                  f"{r['unit']}; {r['description']}")
    return EXIT_RIGHT


def _batch(args) -> int:
    from dualmech.grade.batch import BatchError, grade_batch, read_csv
    from dualmech.grade.report import summarise, write_report
    if args.name:
        raise UsageError("--batch takes the problem from each row's question; drop NAME.")
    if args.workers is not None and args.workers < 1:
        raise UsageError("--workers must be at least 1.")
    try:
        rows = read_csv(args.batch)
        results = grade_batch(rows, workers=args.workers, scheduler=args.scheduler,
                              progress=not args.no_progress)
    except BatchError as exc:
        raise UsageError(str(exc)) from None
    paths = write_report(results, args.out, title=f"Grades: {args.batch.name}")
    summary = summarise(results)
    if args.json:
        print(json.dumps({"files": {k: str(v) for k, v in paths.items()},
                          "questions": {q: {k: v for k, v in s.items() if k != "mistakes"}
                                        for q, s in summary.items()}}, indent=2))
    else:
        for q, s in summary.items():
            print(f"{q}: {s['right']}/{s['answers']} right" +
                  (f", {s['invalid']} not graded" if s["invalid"] else ""))
        print(f"wrote {paths['json']} and {paths['markdown']}")
    return EXIT_RIGHT
