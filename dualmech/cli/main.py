"""The ``dualmech`` command: list, check, show and report the problems of the catalogue.

::

    dualmech list                                  the catalogue (and registered ones)
    dualmech check NAME [NAME...] | --all          Newton-Euler vs Lagrange, exactly
    dualmech show NAME [--latex] [--model M]       equations of motion and reactions
                   [--at 'q=V, q_dot=W']         (and their values at a state)
    dualmech report [NAME...] [--all] [--out DIR]  checked and written to DIR (report.html)
    dualmech grade NAME --answer TEXT              a typed answer, checked exactly
    dualmech chart | atlas | fidelity NAME         work-precision, where methods fail, model ladder
    dualmech mutate NAME [NAME...] | --all         break each model: does the check notice?
    dualmech new NAME [--out DIR]                  a new problem's skeleton and its test

NAME is a catalogue name, a file ``path.py`` or ``path.py:Class``, ``module:Class``, or a
problem of a catalogue a course package registers (entry-point group ``dualmech.problems``),
``catalogue:problem`` or its bare name; every command takes every form.  ``check``,
``report``, ``mutate``, ``chart`` and ``serve --problems`` also take a registered catalogue's
name for all its problems, and ``--all`` is every problem ``dualmech list`` lists (the course
packages' too).  Every command takes ``--json``.  Progress goes to stderr (a bar on a
terminal, plain lines otherwise).

Exit status (:mod:`dualmech.cli.errors`): 0 when every checked pair agrees, 1 when one
disagrees (a wrong model), 2 for a usage error such as an unknown problem name, an error in
a problem file (shown at its file and line, with what to fix), a declaration error or a
model that cannot be built, and an internal error (which says so); 130 when interrupted.
Several problems: the worst of their statuses.  A closed standard output (``| head``) does
not change it: the command finishes its work and discards the rest of its output.

Example
-------
>>> from dualmech.cli.main import main
>>> main(["--version"])  # doctest: +ELLIPSIS
dualmech ...
0
"""
from __future__ import annotations

import argparse
import contextlib
import json
import sys
import time
from pathlib import Path
from typing import Sequence

from dualmech import __version__
from dualmech.cli import names as _names
from dualmech.cli.at_state import (add_at_option, check_at, report_data, state_values,
                                   values_wanted, with_values)
from dualmech.cli.options import positive_number
from dualmech.cli.errors import (DISAGREE, EXIT_STATUS, OK, USAGE_OR_MODEL_ERROR, Failure,
                                 UsageError, about, describe, guarded, say, worst)

__all__ = ["main", "command", "build_parser"]


# -- the parser ------------------------------------------------------------------------
def _positive_int(text: str, most: int | None = None) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a positive integer, got {value}")
    if most is not None and value > most:
        raise argparse.ArgumentTypeError(f"expected at most {most}, got {value}")
    return value


def _points(text: str) -> int:
    """Random points per verdict: 1 to 1000 (8 already bound a false 'equal' below 1e-100)."""
    return _positive_int(text, 1000)


#: longest simulated span a report chart takes, in seconds
MAX_DURATION = 600.0


def _duration(text: str) -> float:
    value = positive_number(text)
    if value > MAX_DURATION:
        raise argparse.ArgumentTypeError(f"expected at most {MAX_DURATION:g} s of simulated "
                                         f"time, got {text!r}")
    return value


class _Parser(argparse.ArgumentParser):
    """argparse's parser, its usage errors wrapped to the terminal as every message is
    (:func:`dualmech.cli.errors.fit`); sub-parsers are of this class too."""

    def error(self, message: str):
        from dualmech.cli.errors import columns, fit
        self.print_usage(sys.stderr)
        self.exit(USAGE_OR_MODEL_ERROR,
                  fit(f"{self.prog}: error: {message}", columns(sys.stderr)) + "\n")


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``dualmech`` (one sub-parser per command)."""
    parser = _Parser(
        prog="dualmech",
        description="Every mechanics problem written twice -- Newton-Euler and Lagrange -- "
                    "proved equivalent exactly, with the reaction forces recovered.",
        epilog="NAME is a catalogue name (dualmech list), a file path.py or path.py:Class, "
               "module:Class, or a problem of a catalogue registered under the entry-point "
               "group dualmech.problems (catalogue:problem, or its name alone); check, report, "
               "mutate and chart also take a registered catalogue's name for all its "
               "problems.  " + EXIT_STATUS)
    parser.add_argument("--version", action="version", version=f"dualmech {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    p = sub.add_parser("list", help="list the problems of the catalogue",
                       description="List every problem: name, degrees of freedom "
                                   "(coordinates of the reference model), reactions and title "
                                   "(--json adds the source and summary), then those of the "
                                   "catalogues course packages register.")
    p.add_argument("files", nargs="*", metavar="FILE",
                   help="a problem file of your own: list the problems it defines, by the "
                        "names the other commands take (FILE:Class)")
    _json_flag(p, "a list of objects: name, title, source (named by course), source_file, "
                  "summary, dof, coordinates, reactions, status, catalogue")
    p.set_defaults(func=_cmd_list)

    p = sub.add_parser("check", help="prove each problem's models equivalent",
                       description="Compare every model of each problem with its reference "
                                   "model, exactly, and check the source's printed answers.")
    p.add_argument("names", nargs="*", metavar="NAME",
                   help="problems to check: catalogue names, path.py[:Class] or module:Class")
    p.add_argument("--all", action="store_true",
                   help="check every problem: the catalogue's and the registered catalogues'")
    p.add_argument("--json", action="store_true",
                   help="print JSON: one object for one problem, a list for several")
    p.add_argument("--n", metavar="N", type=_positive_int, default=None,
                   help="size of a parametric problem (one that declares `parametric`), "
                        "e.g. --n 10")
    p.add_argument("--jobs", "-j", metavar="J", type=_positive_int, default=None,
                   help="problems checked at once, in worker processes (default: one per "
                        "CPU when several problems are checked)")
    _points_seed(p)
    _notation_option(p)
    add_at_option(p)
    p.set_defaults(func=_cmd_check)

    p = sub.add_parser("show", help="print a problem's equations of motion and reactions",
                       description="Print the equations of motion of each model of a "
                                   "problem, then the recovered reaction forces.")
    p.add_argument("name", metavar="NAME",
                   help="the problem to show: a catalogue name, path.py[:Class] or module:Class")
    p.add_argument("--latex", action="store_true", help="LaTeX instead of pretty text")
    p.add_argument("--model", metavar="M", help="show only model M (e.g. lagrange)")
    _notation_option(p)
    add_at_option(p)
    _json_flag(p, "models (coordinates, unknowns, labelled equations), reactions and "
                  "reaction values at a state (with --at, or when a formula is too long)")
    p.set_defaults(func=_cmd_show)

    p = sub.add_parser("report", help="check problems and write report.html with charts",
                       description="Check the problems named (every problem without a name, "
                                   "or with --all), print the summary table and write "
                                   "DIR/report.html (open it in a browser: one page, charts "
                                   "included), DIR/report.md, DIR/<name>.json and "
                                   "DIR/<name>_reactions.png and DIR/<name>_motion.gif.")
    p.add_argument("names", nargs="*", metavar="NAME",
                   help="problems to report: catalogue names, path.py[:Class], module:Class, "
                        "a registered catalogue's problem or the catalogue's name for all of "
                        "them (default: every problem)")
    p.add_argument("--all", action="store_true",
                   help="every problem: the catalogue's and the registered catalogues'")
    p.add_argument("--out", metavar="DIR", default="out", type=Path,
                   help="output directory (default: %(default)s)")
    p.add_argument("--duration", metavar="T", default=5.0, type=_duration,
                   help="simulated time for the charts, in seconds (default: %(default)s)")
    p.add_argument("--no-animations", dest="animations", action="store_false",
                   help="leave out the animation of each motion (about 3 s a problem)")
    p.add_argument("--for", dest="audience", choices=("teachers", "students"),
                   default="teachers",
                   help="teachers: why each wrong printed answer is wrong; students: a page "
                        "to hand out, printed answers judged and corrections hidden "
                        "(default: %(default)s)")
    _points_seed(p)
    _notation_option(p)
    _json_flag(p, "the summary: one object per problem, and the files written")
    p.set_defaults(func=_cmd_report)

    p = sub.add_parser("mutate", help="break each model on purpose: does the check notice?",
                       description="Make every mutant of each problem's models -- one force, "
                                   "torque, energy term or inertia dropped, flipped or "
                                   "doubled; one unknown reaction's sign flipped; one mass "
                                   "doubled; two parameters swapped -- and check that the "
                                   "comparison, judging the mutant among all the problem's "
                                   "derivations and the Kane referee (as `check` does), "
                                   "names the mutant's derivation (or the reaction it "
                                   "changes).  A survivor is a mistake the checks would "
                                   "not catch; the report says why.  A mutant that changes "
                                   "only reactions no second derivation gives is reported "
                                   "as uncatchable, with the model that would catch it.  "
                                   "Exit status 1 when a mutant survives.")
    p.add_argument("names", nargs="*", metavar="NAME",
                   help="problems to mutate: catalogue names, path.py[:Class] or module:Class")
    p.add_argument("--all", action="store_true",
                   help="every problem: the catalogue's and the registered catalogues'")
    p.add_argument("--n", metavar="N", type=_positive_int, default=None,
                   help="size of a parametric problem (one that declares `parametric`), "
                        "e.g. --n 3")
    p.add_argument("--points", metavar="K", type=_points, default=3,
                   help="random exact points per verdict (default: %(default)s)")
    p.add_argument("--seed", metavar="S", type=int, default=0,
                   help="seed of the random points (default: %(default)s)")
    _json_flag(p, "one object per problem: caught, judged, kill_rate, and every mutant by "
                  "outcome (killed, survived with why, identical, equivalent, errored, "
                  "undetermined)")
    p.set_defaults(func=_cmd_mutate)

    p = sub.add_parser("new", help="write a new problem's skeleton (both models, a test)",
                       description="Write DIR/NAME.py -- a working problem with both models "
                                   "(a pendulum to replace by your system), a sign sketch in "
                                   "its docstring and TODO comments -- and DIR/test_NAME.py. "
                                   "`dualmech check DIR/NAME.py` passes as written.")
    p.add_argument("name", metavar="NAME", help="the problem's name (lower_case_with_underscores)")
    p.add_argument("--out", metavar="DIR", default=Path("."), type=Path,
                   help="where to write the two files (default: the current directory)")
    p.add_argument("--force", action="store_true", help="overwrite existing files")
    _json_flag(p, "the files written")
    p.set_defaults(func=_cmd_new)

    from dualmech.cli.grade import register as _register_grade
    from dualmech.cli.handout import register as _register_handout
    from dualmech.cli.studies import register as _register_numeric
    from dualmech.cli.serve import register as _register_web
    from dualmech.cli.simulate import register as _register_simulate
    from dualmech.cli.stability import register as _register_stability
    _register_grade(sub)
    _register_handout(sub)
    _register_numeric(sub)
    _register_web(sub)
    _register_simulate(sub)
    _register_stability(sub)
    for p in sub.choices.values():   # every command's --help ends with the exit statuses
        if "Exit status" not in (p.epilog or ""):
            p.epilog = f"{p.epilog}  {EXIT_STATUS}" if p.epilog else EXIT_STATUS
    return parser


def _json_flag(p: argparse.ArgumentParser, what: str) -> None:
    p.add_argument("--json", action="store_true", help=f"print JSON: {what}")


def _points_seed(p: argparse.ArgumentParser) -> None:
    p.add_argument("--points", metavar="N", type=_points, default=8,
                   help="random exact points per comparison, 1 to 1000 "
                        "(default: %(default)s)")
    p.add_argument("--seed", metavar="S", type=int, default=0,
                   help="seed of the random points (default: %(default)s)")


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``dualmech`` with ``argv`` (default ``sys.argv[1:]``); return the exit status."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version, or argparse's own usage errors
        return int(exc.code or 0) if not isinstance(exc.code, str) else USAGE_OR_MODEL_ERROR
    with _guarded_stdout():
        return guarded(args.func)(args)


def command() -> int:
    """The ``dualmech`` program (and ``python -m dualmech``): :func:`main` on ``sys.argv``,
    with the start-up and the exit of a process that ends with the command
    (:mod:`dualmech.startup`: big modules load with the garbage collector paused, and
    shutdown leaves the objects to the operating system instead of freeing them one by one).
    :func:`main` called inside a longer-lived process keeps the default collector.
    """
    from dualmech import startup
    startup.as_program()
    status = main()
    startup.leave()
    return status


@contextlib.contextmanager
def _guarded_stdout():
    """``sys.stdout`` that survives a closed pipe (``dualmech check X | head -1``): the command
    finishes, keeps its exit status, and the output nobody reads goes to /dev/null."""
    from dualmech.progress import GuardedStdout
    try:
        sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):  # not a file (a test's capture): as it is
        yield
        return
    real = sys.stdout
    sys.stdout = guarded = GuardedStdout(real)
    try:
        yield
    finally:
        guarded.flush()
        sys.stdout = real


# -- helpers ---------------------------------------------------------------------------
def _catalogue():
    return _names.catalogue()


def _get(spec: str, n: int | None = None):
    return _names.get(spec, n)


def _selected(args) -> list:
    return _names.selected(args.names, args.all, getattr(args, "n", None))


def _dof(problem) -> int | str:
    try:
        return len(problem.model(problem.reference).coordinates)
    except Exception:  # a broken model still gets listed; `check` reports the error
        return len(problem.coordinates) or "?"


def _table(headers: Sequence[str], rows: Sequence[Sequence], markdown: bool = False) -> str:
    cells = [[str(h) for h in headers]] + [[str(c) for c in r] for r in rows]
    widths = [max(len(row[i]) for row in cells) for i in range(len(headers))]
    if markdown:
        fmt = lambda row: "| " + " | ".join(c.ljust(w) for c, w in zip(row, widths)) + " |"  # noqa: E731
        rule = "|" + "|".join("-" * (w + 2) for w in widths) + "|"
    else:
        fmt = lambda row: "  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip()  # noqa: E731
        rule = "  ".join("-" * w for w in widths)
    return "\n".join([fmt(cells[0]), rule] + [fmt(r) for r in cells[1:]])


def _json(obj) -> str:
    return json.dumps(obj, indent=2, default=_jsonable)


def _jsonable(x):
    import sympy as sp
    if isinstance(x, sp.Basic):
        return str(x)
    if hasattr(x, "tolist"):
        return x.tolist()
    if isinstance(x, (set, frozenset, tuple)):
        return list(x)
    return str(x)


class _Failed:
    """Stands in for a Comparison when a problem could not be compared at all: its models
    cannot be built, or its file has an error (:attr:`failure` says where and what to fix)."""

    def __init__(self, problem, error: BaseException, seconds: float):
        self.problem, self.seconds = problem, seconds
        self.failure: Failure = describe(error, problem)
        self.equivalent = False
        self.method = "error"
        self.reactions = {}

    def __str__(self) -> str:
        return f"{self.problem.name}: could not be compared -- {self.failure.message}"

    def to_dict(self) -> dict:
        p = self.problem
        from dualmech.sources import source_fields
        return {"name": p.name, "title": p.title, **source_fields(p.source),
                "equivalent": False, "method": "error", "seconds": self.seconds,
                "error": self.failure.message}


def _compare(problem, points: int, seed: int):
    from dualmech.verify.check import compare
    start = time.perf_counter()
    try:
        return compare(problem, points=points, seed=seed)
    except Exception as exc:  # a broken model is a failed check, reported, not a crash
        return _Failed(problem, exc, time.perf_counter() - start)


def _status(c) -> int:
    """The exit status of one comparison: 2 when it could not be made, 1 disagree, 0 agree."""
    failure = getattr(c, "failure", None)
    if failure is not None:
        return failure.status
    return OK if c.equivalent else DISAGREE


def _say_failed(command: str, c) -> None:
    """A comparison that could not be made, as the command's error on stderr."""
    failure = getattr(c, "failure", None)
    if failure is not None:
        say(command, failure.message)


def _progress(items, what: str):
    """``items`` with progress on stderr: a bar on a terminal, one line per problem otherwise."""
    from dualmech.progress import progress
    return progress(items, what, unit="problem")


# -- commands --------------------------------------------------------------------------
#: width the text of ``dualmech list`` fits in
LIST_WIDTH = 100


def _list_rows() -> list[dict]:
    """One dict per problem: dualmech's catalogue, its out-of-scope systems, then every
    registered catalogue's problems."""
    from dualmech.sources import source_fields
    cat = _catalogue()
    rows = [{"name": d.name, "title": d.title, **source_fields(d.source), "summary": d.summary,
             "dof": d.dof, "coordinates": list(d.coordinates), "reactions": list(d.reactions),
             "status": "modelled", "catalogue": "dualmech"} for d in cat.declarations()]
    rows += [{"name": name, "title": "(not modelled)", **source_fields(source), "summary": reason,
              "dof": None, "coordinates": [], "reactions": [], "status": "out of scope",
              "catalogue": "dualmech"} for name, source, reason in cat.OUT_OF_SCOPE]
    for cname, ep in sorted(getattr(cat, "registered", dict)().items()):
        try:
            classes = cat.catalogue_classes(ep)
        except KeyError as exc:   # a broken course package is named, the rest still listed
            say("list", exc.args[0] if exc.args else str(exc), "")
            continue
        for c in classes:
            coords = [getattr(x, "name", str(x)) for x in getattr(c, "coordinates", ())]
            rows.append({"name": f"{cname}:{c.name or c.__name__}", "title": c.title,
                         **source_fields(c.source or ""),
                         "summary": getattr(c, "summary", ""),
                         "dof": getattr(c, "parametric", "") or len(coords),
                         "coordinates": coords,
                         "reactions": [r.name for r in getattr(c, "reactions", ())],
                         "status": "modelled", "catalogue": cname})
    return rows


def _clip(text: str, width: int) -> str:
    return text if len(text) <= width else text[:max(width - 3, 0)].rstrip() + "..."


def _file_rows(files) -> list[dict]:
    """One dict per problem class each file defines, named ``FILE:Class`` (what ``check``
    and the other commands take); a file's own error is shown at its line."""
    from pathlib import Path
    from dualmech.problems import SpecError
    from dualmech.problems._loader import _import_file, problem_classes
    from dualmech.sources import source_fields
    rows = []
    for f in files:
        path = Path(f).expanduser()
        if not path.is_file() or path.suffix != ".py":
            raise SpecError(f"no problem file {f} (a file path.py of your own; the catalogue "
                            "is `dualmech list` without a file)")
        for c in problem_classes(_import_file(path.resolve())):
            coords = [getattr(x, "name", str(x)) for x in getattr(c, "coordinates", ())]
            rows.append({"name": f"{f}:{c.__name__}", "title": c.title,
                         **source_fields(c.source or ""), "summary": getattr(c, "summary", ""),
                         "dof": getattr(c, "parametric", "") or _file_dof(c, len(coords)),
                         "coordinates": coords,
                         "reactions": [r.name for r in getattr(c, "reactions", ())],
                         "status": "modelled", "catalogue": str(f)})
    return rows


def _file_dof(cls, declared: int) -> int | str:
    """Degrees of freedom of a file's problem class: its reference model's coordinates (a
    coordinate given a known motion, ``lg.prescribe``, is declared but no degree of
    freedom); the declared count when the class or its model cannot be built (``check``
    reports why)."""
    try:
        return len(cls().model(cls.reference).coordinates)
    except Exception:  # noqa: BLE001 - listed all the same; the other commands say what is wrong
        return declared


def _cmd_list(args) -> int:
    rows = _file_rows(args.files) if getattr(args, "files", None) else _list_rows()
    if args.json:
        print(_json(rows))
        return OK
    modelled = [r for r in rows if r["status"] == "modelled"]
    table = [(r["name"], r["dof"], _clip(", ".join(r["reactions"]) or "-", 18), r["title"])
             for r in modelled]
    # every column but the title at its natural width; the title gets what is left
    fixed = [max(len(str(x)) for x in col) for col in zip(("name", "dof", "reactions"),
                                                          *[row[:3] for row in table])]
    room = max(LIST_WIDTH - sum(fixed) - 2 * len(fixed), 20)
    print(_table(("name", "dof", "reactions", "title"),
                 [row[:3] + (_clip(row[3], room),) for row in table]))
    skipped = [r for r in rows if r["status"] != "modelled"]
    if skipped:
        print("\nnot modelled (dualmech models finitely many coordinates):")
        for r in skipped:
            print(_clip(f"  {r['name']}: {r['summary']}", LIST_WIDTH))
    print("\nsources and summaries: dualmech list --json; one problem: dualmech show NAME")
    return OK


class _Checked:
    """A comparison done in a worker process, as the parent prints it."""

    def __init__(self, text: str, data: dict, equivalent: bool, failure: Failure | None = None):
        self.text, self.data, self.equivalent = text, data, equivalent
        self.failure = failure

    def __str__(self) -> str:
        return self.text

    def to_dict(self) -> dict:
        return self.data


_CHOSEN: list = []   # the problems of a parallel check, inherited by forked workers


def _text(c, notation: str = "dots") -> str:
    """The readable report of a comparison in ``notation`` (a stand-in's ``str()``)."""
    text = getattr(c, "text", None)
    return text(notation) if callable(text) else str(c)


def _check_in_worker(i: int, points: int, seed: int, notation: str,
                     at: str | None = None) -> _Checked:
    problem = _CHOSEN[i]
    c = _compare(problem, points, seed)
    try:   # the report is written here, where the error's traceback (its user line) is
        with about(problem):
            text, data = with_values(problem, c, _text(c, notation), c.to_dict(), at)
            text, data = _one_sided(problem, c, text, data)
            text = _fit(text)
            return _Checked(text, data, bool(c.equivalent), getattr(c, "failure", None))
    except Exception as exc:  # noqa: BLE001 - the parent reports it
        failed = _Failed(problem, exc, getattr(c, "seconds", 0.0))
        return _Checked(str(failed), failed.to_dict(), False, failed.failure)


def _compared(chosen: list, points: int, seed: int, jobs: int | None,
              notation: str = "dots", at: str | None = None):
    """``compare`` of each problem, in order; several at once in forked worker processes
    (each problem's check is independent) when there are several problems and CPUs."""
    import os
    jobs = jobs or min(len(chosen), os.cpu_count() or 1)
    fork = None
    if jobs > 1 and len(chosen) > 1:
        import multiprocessing
        if "fork" in multiprocessing.get_all_start_methods():
            fork = multiprocessing.get_context("fork")
    if fork is None:
        for problem in _progress(chosen, "checking"):
            yield problem, _compare(problem, points, seed)
        return
    from concurrent.futures import ProcessPoolExecutor
    _CHOSEN[:] = chosen
    try:
        with ProcessPoolExecutor(max_workers=jobs, mp_context=fork) as pool:
            futures = [pool.submit(_check_in_worker, i, points, seed, notation, at)
                       for i in range(len(chosen))]
            for problem, future in zip(_progress(chosen, "checking"), futures):
                yield problem, future.result()
    finally:
        _CHOSEN.clear()


def _printed(problem, c, notation: str, at: str | None = None):
    """``(text, c)``: the report of ``c`` (with reaction values at a state, see
    :mod:`dualmech.cli.at_state`), or of the failure writing it raised."""
    try:
        with about(problem):
            text = with_values(problem, c, _text(c, notation), None, at)[0]
            return _fit(_one_sided(problem, c, text, None)[0]), c
    except Exception as exc:  # noqa: BLE001 - e.g. a model the display cannot solve
        failed = _Failed(problem, exc, getattr(c, "seconds", 0.0))
        return str(failed), failed


def _one_sided(problem, c, text: str | None, data: dict | None):
    """``(text, data)`` with a warning for each one-sided reaction (``Problem.unilateral``)
    that is negative at the problem's default state: it must be >= 0 along its declared
    direction, so the direction is probably reversed (the models agree all the same: the
    direct form and its referee share that declaration), or the scene starts where the
    contact has already let go.  Nothing is added when the models disagree."""
    one_sided = getattr(problem, "unilateral", None) or {}
    if not one_sided or not getattr(c, "equivalent", False) or isinstance(c, _Checked) or \
            getattr(c, "failure", None) is not None:   # a worker's report has it already
        return text, data
    from dualmech.numeric.reactions_state import reactions_at_state
    try:
        values = reactions_at_state(problem, None, comparison=c)
    except (ValueError, ArithmeticError):   # no state to judge at: nothing to say
        return text, data
    info = problem.reaction_info()
    warnings = [f"one-sided reaction {name} = {values.direct[name]:.6g} < 0 at t = "
                f"{values.time:g} s, {values.where()}: it must be >= 0 along its declared "
                f"direction ({info[name].direction or 'see reactions'}) -- the direction "
                "is probably reversed (both the direct form and its referee take it from "
                "the declaration, so they agree), or the scene starts where the contact has "
                "let go"
                for name in one_sided if values.direct.get(name, 0.0) < 0]
    if not warnings:
        return text, data
    if text is not None:
        text += "\n" + "\n".join(f"  warning: {w}" for w in warnings)
    if data is not None:
        data = {**data, "one_sided_warnings": warnings}
    return text, data


class _JsonValues:
    """A comparison whose ``to_dict`` also holds the reaction values at a state."""

    def __init__(self, problem, c, at: str | None):
        self._problem, self._c, self._at = problem, c, at

    def __getattr__(self, name):
        return getattr(self._c, name)

    def to_dict(self) -> dict:
        data = with_values(self._problem, self._c, None, self._c.to_dict(), self._at)[1]
        return _one_sided(self._problem, self._c, None, data)[1]


def _cmd_check(args) -> int:
    from dualmech.startup import load
    load("dualmech.verify.check")   # sympy, symengine and the comparator (see dualmech.startup)
    chosen = _selected(args)
    if args.at is not None:
        if len(chosen) != 1:
            raise UsageError("`--at` names one problem's coordinates: check one problem with it.")
        check_at(chosen[0], args.at)
    results = []
    for problem, c in _compared(chosen, args.points, args.seed, args.jobs, args.notation,
                                args.at):
        text, c = (_printed(problem, c, args.notation, args.at) if not args.json
                   else (None, _JsonValues(problem, c, args.at)))
        results.append((problem, c))
        _say_failed("check", c)
        if not args.json and getattr(c, "failure", None) is None:
            print(text)
            print()
    if args.json:
        dicts = [c.to_dict() for _, c in results]
        print(_json(dicts[0] if len(args.names) == 1 and not args.all and len(dicts) == 1
                    else dicts))
    elif len(results) > 1:
        print(_summary(results))
    return worst(_status(c) for _, c in results)


def _cmd_show(args) -> int:
    from dualmech.startup import load
    load("dualmech.verify.check", "dualmech.model.notation")   # see dualmech.startup
    problem = _get(args.name)
    with about(problem):   # an error in the problem's own code: at its file and line
        return _show(problem, args)


def _show(problem, args) -> int:
    if args.at is not None:
        check_at(problem, args.at)   # a bad --at is refused before any derivation
    models = problem.models()
    if args.model is not None:
        if args.model not in models:
            raise UsageError(f"problem `{problem.name}` has no model {args.model!r}; it has "
                             f"{', '.join(models)}.")
        models = {args.model: models[args.model]}
    if args.json:
        return _show_json(problem, models, args)
    from dualmech.sources import source_name
    from dualmech.verify.display import CONVENTION, rows_text
    print(_fit(f"{problem.name}: {problem.title}  ({source_name(problem.source)})"))
    print(_fit(f"({CONVENTION})"))
    for name, eqs in models.items():
        coords = ", ".join(q.func.__name__ for q in eqs.coordinates)
        unknowns = ", ".join(str(u) for u in eqs.unknowns) or "none"
        print()
        print(_heading(f"{name}  (coordinates: {coords}; unknowns: {unknowns})"))
        print(rows_text(eqs, latex=args.latex, notation=args.notation))
    if not problem.reactions:
        return OK
    c = _compare(problem, 8, 0)
    print()
    print(_heading("reactions (from the direct form, with the verified accelerations)"))
    if isinstance(c, _Failed):
        _say_failed("show", c)
        return _status(c)
    info = problem.reaction_info()
    import sympy as sp
    from dualmech.model import notation
    coords = problem.coordinate_functions + tuple(problem.model(problem.reference).coordinates)
    for rname, expr in c.reactions.items():
        where = info.get(str(rname))
        note = f"   [{where.direction}]" if where is not None and where.direction else ""
        if args.latex:
            print(f"{notation.latex(sp.Symbol(str(rname)))} = "
                  f"{notation.latex(expr, args.notation, coords)}{note}")
        else:
            print(f"{rname}{note} =")
            print(notation.pretty(expr, args.notation, coords))
        print()
    for note in c.display_notes:
        print(_fit(f"({note})"))
    if values_wanted(problem, c, args.at):
        print()
        print(_heading("reaction values at a state (direct form; Kane referee beside it)"))
        print(_fit("\n".join(state_values(problem, c, args.at).lines())))
    return _status(c)


#: :data:`dualmech.model.notation.NOTATIONS`, written out so that building the parser (``--help``,
#: ``list``) does not import sympy; tests/test_cli.py checks that the two agree
_NOTATIONS = ("dots", "primes")


def _notation_option(p) -> None:
    p.add_argument("--notation", choices=_NOTATIONS, default="dots",
                   help="rates as dots over the letter (θ̇, \\dot{\\theta}) or primes "
                        "(θ′); default: %(default)s")


def _show_json(problem, models: dict, args) -> int:
    """``show --json``: each model's labelled equations, then the recovered reactions (the
    expressions as ``check --json`` writes them)."""
    from dualmech.model.notation import machine
    from dualmech.verify.display import CONVENTION, dotted
    from dualmech.sources import source_fields
    doc = {"name": problem.name, "title": problem.title, **source_fields(problem.source),
           "models": {name: {"coordinates": [q.func.__name__ for q in eqs.coordinates],
                             "unknowns": [str(u) for u in eqs.unknowns],
                             "equations": [{"label": label, "expression": dotted(e),
                                            "machine": machine(e, eqs.coordinates),
                                            **_grouped_json(eqs, e)}
                                           for label, e in zip(eqs.labels, eqs.equations)]}
                      for name, eqs in models.items()},
           "grouped_as": CONVENTION, "reactions": {}}
    status = OK
    if problem.reactions:
        c = _compare(problem, 8, 0)
        doc["equivalent"] = c.equivalent
        if isinstance(c, _Failed):
            _say_failed("show", c)
            doc["error"] = c.to_dict()["error"]
        info = problem.reaction_info()
        for rname, expr in c.reactions.items():
            where = info.get(str(rname))
            doc["reactions"][str(rname)] = {
                "expression": dotted(expr),
                "machine": machine(expr, problem.coordinate_functions
                                   + tuple(problem.model(problem.reference).coordinates)),
                "direction": where.direction if where is not None else ""}
        doc["display_notes"] = list(getattr(c, "display_notes", ()))
        if values_wanted(problem, c, args.at):
            doc["values_at_state"] = state_values(problem, c, args.at).to_dict()
        status = _status(c)
    print(_json(doc))
    return status


def _grouped_json(eqs, row) -> dict:
    """``{"grouped": {"left", "right"}}``: the row as :func:`~dualmech.verify.display.grouped`
    writes it (machine text), or nothing past the display budget."""
    from dualmech.model.notation import machine
    from dualmech.verify.display import grouped, row_sign
    sides = grouped(row, eqs.coordinates, row_sign(eqs))
    if sides is None:
        return {}
    return {"grouped": {"left": machine(sides[0], eqs.coordinates),
                        "right": machine(sides[1], eqs.coordinates)}}


def _heading(text: str) -> str:
    return f"== {text} =="


def _summary_row(problem, c) -> dict:
    """The summary of one ``(problem, comparison)``: what a row of the table shows."""
    d = c.to_dict()
    published = d.get("published") or []
    verdicts = [p.get("verdict") for p in published if isinstance(p, dict)]
    return {"problem": problem.name, "dof": _dof(problem), "equivalent": bool(c.equivalent),
            "method": d.get("method", "?"), "seconds": float(d.get("seconds", 0.0)),
            "reactions": len(getattr(problem, "reactions", ()) or d.get("reactions") or {}),
            "reactions_not_cross_checked": list(d.get("reactions_not_cross_checked") or []),
            "published": {v: verdicts.count(v) for v in dict.fromkeys(verdicts)}}


def _summary(results, markdown: bool = False) -> str:
    """One row per ``(problem, comparison)``."""
    rows, lonely_total = [], 0
    for problem, c in results:
        r = _summary_row(problem, c)
        lonely = len(r["reactions_not_cross_checked"])
        lonely_total += lonely
        cell = f"{r['reactions']}" + (f" ({lonely} not cross-checked)" if lonely else "")
        rows.append((r["problem"], r["dof"], "yes" if r["equivalent"] else "NO", r["method"],
                     f"{r['seconds']:.2f}", cell,
                     _verdict_counts([v for v, n in r["published"].items() for _ in range(n)])))
    table = _table(("problem", "dof", "equivalent", "method", "seconds", "reactions",
                    "published answers"), rows, markdown=markdown)
    if lonely_total:
        table += (f"\n{lonely_total} reaction(s) not cross-checked (given by one derivation only; "
                  "`dualmech check NAME` names them)")
    return table


def _verdict_counts(verdicts) -> str:
    """``"14 correct, 4 wrong"``, or ``-`` for none."""
    if not verdicts:
        return "-"
    order = dict.fromkeys(["correct", "wrong", "unchecked", *verdicts])
    counts = {v: verdicts.count(v) for v in order if v in verdicts}
    return ", ".join(f"{n} {v}" for v, n in counts.items())


def _cmd_report(args) -> int:
    from dualmech.report import write_report
    out: Path = args.out
    if "\x00" in str(out):
        raise UsageError("`--out` contains a NUL byte; give a directory path.")
    chosen = _names.selected(args.names, args.all, default_all=True)
    out.mkdir(parents=True, exist_ok=True)
    results = []
    for problem in _progress(chosen, "checking"):
        c = _compare(problem, args.points, args.seed)
        if not args.json:
            _, c = _printed(problem, c, args.notation)   # what the page shows, or its error
        _say_failed("report", c)
        results.append((problem, c))
        (out / f"{problem.name}.json").write_text(_json(report_data(problem, c)) + "\n")
    if not args.json:
        print(_summary(results), flush=True)
    if not sys.stderr.isatty():
        print(f"report: writing the charts and {out / 'report.html'}", file=sys.stderr,
              flush=True)
    w = write_report([c for _, c in results], out, args.duration,
                     audience=args.audience, notation=args.notation,
                     animations=args.animations)
    if args.json:
        print(_json({"problems": [_summary_row(p, c) for p, c in results],
                     "files": {"html": str(w.html), "markdown": str(w.markdown),
                               "json": [str(out / f"{p.name}.json") for p, _ in results],
                               "charts": [str(x) for ch in w.charts.values()
                                          for x in getattr(ch, "paths", [])]},
                     "no_chart": dict(w.failed)}))
    else:
        from dualmech.verify.display import wrap
        files, charts = len(results), len(w.charts) - len(w.failed)
        print("\n" + wrap(f"wrote {w.html} (open it in a browser), {w.markdown}, {files} JSON "
                          f"file{'s' * (files != 1)} and {charts} chart{'s' * (charts != 1)} "
                          f"to {out}/"))
        for name, why in w.failed.items():
            print(f"no chart for {name}: {why}")
    return worst(_status(c) for _, c in results)


def _cmd_mutate(args) -> int:
    from dualmech.startup import load
    load("dualmech.verify.mutation")   # sympy, symengine and the comparator (see dualmech.startup)
    from dualmech.verify.mutation import mutation_report
    chosen = _selected(args)
    reports, failed, statuses = [], [], []
    for problem in _progress(chosen, "mutating"):
        try:
            with about(problem):
                problem.models()   # a model that cannot be built: the user's error, status 2
            report = mutation_report(problem, points=args.points, seed=args.seed)
        except Exception as exc:  # a problem whose models cannot be mutated: reported, not a crash
            failure = describe(exc, problem)
            # mutation refuses derivations that already disagree (or a single one): status
            # 1; a model that cannot be built, an error in the user's file, a bug: 2
            statuses.append(DISAGREE if failure.kind == "refused" else failure.status)
            failed.append({"problem": getattr(problem, "name", "?"), "error": failure.message})
            if statuses[-1] == DISAGREE and not args.json:
                print(_fit(f"{getattr(problem, 'name', '?')}: not mutated: {failure.message}")
                      + "\n")
            elif statuses[-1] != DISAGREE:
                say("mutate", failure.message)
            continue
        reports.append(report)
        if not args.json:
            print(_fit(str(report)))
            print()
    if args.json:
        data = [r.to_dict() for r in reports] + failed
        print(_json(data[0] if len(args.names) == 1 and not args.all else data))
    elif len(chosen) > 1:
        rows = [(r.problem, f"{len(r.killed)}/{r.total}", len(r.survived), len(r.identical),
                 len(r.equivalent), len(r.errored) + len(r.undetermined)) for r in reports]
        caught = sum(len(r.killed) for r in reports)
        judged = sum(r.total for r in reports)
        print(_table(("problem", "caught", "survived", "identical", "equivalent",
                      "no verdict"), rows))
        print(f"\n{caught}/{judged} mutants caught over {len(reports)} problems"
              + (f"; {len(failed)} not mutated" if failed else ""))
    statuses += [DISAGREE if r.survived else OK for r in reports]
    return worst(statuses)


def _cmd_new(args) -> int:
    from dualmech.cli.skeleton import SkeletonError, write_skeleton
    try:
        problem, test = write_skeleton(args.name, args.out, force=args.force)
    except SkeletonError as exc:
        raise UsageError(str(exc)) from None
    if args.json:
        print(_json({"problem": str(problem), "test": str(test)}))
        return OK
    print(f"wrote {problem} and {test}\n\n"
          f"It is a working pendulum; make it your system:\n"
          f"  1. draw your sign sketch in the docstring of {problem.name}: positive directions "
          f"of every coordinate and force;\n"
          f"  2. declare your parameters, coordinates and reactions (dimensions, defaults, "
          f"ranges);\n"
          f"  3. write newton_euler() from the free-body diagram and lagrange() from T and V, "
          f"independently;\n"
          f"  4. replace the hand result in {test.name} by yours.\n"
          f"Every TODO comment marks a place to fill in.  Then:\n"
          f"  dualmech check {problem}\n"
          f"  dualmech show {problem}\n"
          f"  python -m pytest {test}")
    return OK


def _fit(text: str | None) -> str | None:
    """A report's lines wrapped to the terminal (the verdict line whole):
    :func:`dualmech.verify.display.fit`."""
    if text is None:
        return None
    from dualmech.verify.display import fit
    return fit(text)
