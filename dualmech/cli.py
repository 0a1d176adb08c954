"""The ``dualmech`` command: list, check, show and report the problems of the catalogue.

::

    dualmech list                                  the catalogue
    dualmech check NAME [NAME...] | --all          Newton-Euler vs Lagrange, exactly
    dualmech show NAME [--latex] [--model M]       equations of motion and reactions
    dualmech report [--out DIR]                    everything, written to DIR
    dualmech grade NAME --answer TEXT              a typed answer, checked exactly
    dualmech chart | atlas | fidelity NAME         work-precision, where methods fail, model ladder

Exit status: 0 when every checked pair agrees, 1 when one disagrees (or cannot be built),
2 for a usage error such as an unknown problem name.

Example
-------
>>> from dualmech.cli import main
>>> main(["--version"])  # doctest: +ELLIPSIS
dualmech ...
0
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path
from typing import Sequence

from . import __version__

__all__ = ["main", "build_parser"]

EXIT_OK, EXIT_DISAGREE, EXIT_USAGE = 0, 1, 2


class UsageError(Exception):
    """A command-line mistake; the message says what to do instead."""


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


def _positive_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}") from None
    if not (value > 0 and value < float("inf")):
        raise argparse.ArgumentTypeError(f"expected a positive finite number, got {text!r}")
    return value


def _duration(text: str) -> float:
    value = _positive_float(text)
    if value > MAX_DURATION:
        raise argparse.ArgumentTypeError(f"expected at most {MAX_DURATION:g} s of simulated "
                                         f"time, got {text!r}")
    return value


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``dualmech`` (one sub-parser per command)."""
    parser = argparse.ArgumentParser(
        prog="dualmech",
        description="Every mechanics problem written twice -- Newton-Euler and Lagrange -- "
                    "proved equivalent exactly, with the reaction forces recovered.",
        epilog="Exit status: 0 all pairs agree, 1 a pair disagrees, 2 usage error.")
    parser.add_argument("--version", action="version", version=f"dualmech {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    p = sub.add_parser("list", help="list the problems of the catalogue",
                       description="List every problem: name, title, source and number of "
                                   "degrees of freedom (coordinates of the reference model).")
    p.set_defaults(func=_cmd_list)

    p = sub.add_parser("check", help="prove each problem's models equivalent",
                       description="Compare every model of each problem with its reference "
                                   "model, exactly, and check the source's printed answers.")
    p.add_argument("names", nargs="*", metavar="NAME", help="problems to check")
    p.add_argument("--all", action="store_true", help="check every problem")
    p.add_argument("--json", action="store_true",
                   help="print JSON: one object for one problem, a list for several")
    p.add_argument("--n", metavar="N", type=_positive_int, default=None,
                   help="size of a parametric problem (e.g. n_link_pendulum --n 10)")
    _points_seed(p)
    p.set_defaults(func=_cmd_check)

    p = sub.add_parser("show", help="print a problem's equations of motion and reactions",
                       description="Print the equations of motion of each model of a "
                                   "problem, then the recovered reaction forces.")
    p.add_argument("name", metavar="NAME", help="the problem to show")
    p.add_argument("--latex", action="store_true", help="LaTeX instead of pretty text")
    p.add_argument("--model", metavar="M", help="show only model M (e.g. lagrange)")
    p.set_defaults(func=_cmd_show)

    p = sub.add_parser("report", help="check everything and write a report with charts",
                       description="Check every problem, print the summary table and write "
                                   "DIR/report.md, DIR/<name>.json and "
                                   "DIR/<name>_reactions.png.")
    p.add_argument("--out", metavar="DIR", default="out", type=Path,
                   help="output directory (default: %(default)s)")
    p.add_argument("--duration", metavar="T", default=5.0, type=_duration,
                   help="simulated time for the charts, in seconds (default: %(default)s)")
    _points_seed(p)
    p.set_defaults(func=_cmd_report)

    from .grade.cli import register as _register_grade
    from .numeric.commands import register as _register_numeric
    from .web.cli import register as _register_web
    _register_grade(sub)
    _register_numeric(sub)
    _register_web(sub)
    return parser


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
        return int(exc.code or 0) if not isinstance(exc.code, str) else EXIT_USAGE
    try:
        return args.func(args)
    except UsageError as exc:
        print(f"dualmech {args.command}: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except BrokenPipeError:  # e.g. `dualmech report | head`: stop quietly
        import os
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_OK
    except OSError as exc:   # e.g. an unwritable --out, an unreadable input: one line
        where = f"{exc.filename}: " if getattr(exc, "filename", None) else ""
        print(f"dualmech {args.command}: error: {where}{exc.strerror or exc}",
              file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print(f"dualmech {args.command}: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - no traceback reaches a CLI user
        print(f"dualmech {args.command}: error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return EXIT_USAGE


# -- helpers ---------------------------------------------------------------------------
def _catalogue():
    from dualmech import problems
    return problems


def _get(name: str, n: int | None = None):
    cat = _catalogue()
    try:
        decl = cat.module_of(name)
    except KeyError as exc:
        raise UsageError(exc.args[0] if exc.args else str(exc)) from None
    if n is not None and not decl.parametric:
        raise UsageError(f"`--n` sizes a parametric problem; `{name}` has a fixed size.")
    try:
        return cat.get(name, **({"n": n} if n is not None else {}))
    except ValueError as exc:
        raise UsageError(str(exc)) from None


def _selected(args) -> list:
    if args.all and args.names:
        raise UsageError("give problem names or --all, not both.")
    if args.all:
        return list(_catalogue().all_problems())
    if not args.names:
        known = ", ".join(d.name for d in _catalogue().declarations())
        raise UsageError(f"name at least one problem, or use --all; known problems: {known}.")
    return [_get(n, getattr(args, "n", None)) for n in args.names]


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
    """Stands in for a Comparison when a problem could not be compared at all."""

    def __init__(self, problem, error: Exception, seconds: float):
        self.problem, self.error, self.seconds = problem, error, seconds
        self.equivalent = False
        self.method = "error"
        self.reactions = {}

    def __str__(self) -> str:
        return (f"{self.problem.name}: could not be compared -- "
                f"{type(self.error).__name__}: {self.error}")

    def to_dict(self) -> dict:
        p = self.problem
        return {"name": p.name, "title": p.title, "source": p.source, "equivalent": False,
                "method": "error", "seconds": self.seconds,
                "error": f"{type(self.error).__name__}: {self.error}"}


def _compare(problem, points: int, seed: int):
    from .compare import compare
    start = time.perf_counter()
    try:
        return compare(problem, points=points, seed=seed)
    except Exception as exc:  # a broken model is a failed check, reported, not a crash
        return _Failed(problem, exc, time.perf_counter() - start)


def _progress(items, what: str):
    """``items`` with a progress bar on stderr (tqdm) when there are several and it is a tty."""
    items = list(items)
    if len(items) < 2:
        return items
    from tqdm import tqdm
    return tqdm(items, desc=what, unit="problem", file=sys.stderr, leave=False,
                disable=None)


# -- commands --------------------------------------------------------------------------
def _cmd_list(args) -> int:
    cat = _catalogue()
    rows = [(d.name, d.title, d.source, d.dof, ", ".join(d.reactions) or "-", "modelled")
            for d in cat.declarations()]
    rows += [(name, "(not modelled)", source, "-", "-", "out of scope: " + reason)
             for name, source, reason in cat.OUT_OF_SCOPE]
    print(_table(("name", "title", "source", "dof", "reactions", "status"), rows))
    return EXIT_OK


def _cmd_check(args) -> int:
    chosen = _selected(args)
    results = []
    for problem in _progress(chosen, "checking"):
        c = _compare(problem, args.points, args.seed)
        results.append((problem, c))
        if not args.json:
            print(c)
            print()
    if args.json:
        dicts = [c.to_dict() for _, c in results]
        print(_json(dicts[0] if len(args.names) == 1 and not args.all else dicts))
    elif len(results) > 1:
        print(_summary(results))
    return EXIT_OK if all(c.equivalent for _, c in results) else EXIT_DISAGREE


def _cmd_show(args) -> int:
    problem = _get(args.name)
    models = problem.models()
    if args.model is not None:
        if args.model not in models:
            raise UsageError(f"problem `{problem.name}` has no model {args.model!r}; it has "
                             f"{', '.join(models)}.")
        models = {args.model: models[args.model]}
    print(f"{problem.name}: {problem.title}  ({problem.source})")
    for name, eqs in models.items():
        coords = ", ".join(q.func.__name__ for q in eqs.coordinates)
        unknowns = ", ".join(str(u) for u in eqs.unknowns) or "none"
        print()
        print(_heading(f"{name}  (coordinates: {coords}; unknowns: {unknowns})"))
        print(eqs.pretty(latex=args.latex))
    if not problem.reactions:
        return EXIT_OK
    c = _compare(problem, 8, 0)
    print()
    print(_heading("reactions (from the direct form, with the verified accelerations)"))
    if isinstance(c, _Failed):
        print(c)
        return EXIT_DISAGREE
    info = problem.reaction_info()
    coords = problem.coordinate_functions + tuple(problem.model(problem.reference).coordinates)
    for rname, expr in c.reactions.items():
        where = info.get(str(rname))
        note = f"   [{where.direction}]" if where is not None and where.direction else ""
        expr = _dotted(expr, coords)
        if args.latex:
            import sympy as sp
            print(f"{sp.latex(sp.Symbol(str(rname)))} = {sp.latex(expr)}{note}")
        else:
            print(f"{rname}{note} =")
            import sympy as sp
            print(sp.pretty(expr, use_unicode=True))
        print()
    return EXIT_OK if c.equivalent else EXIT_DISAGREE


def _dotted(expr, coordinates):
    """``expr`` with ``q(t), q', q''`` as symbols ``q``, ``qdot``, ``qddot``, which sympy prints
    with dots (``\\dot{q}`` in LaTeX)."""
    import sympy as sp
    from .equations import state_symbols, to_plain
    rules = {}
    for q in dict.fromkeys(coordinates):
        s = state_symbols(q)
        rules[s.qd] = sp.Symbol(f"{s.name}dot", real=True)
        rules[s.qdd] = sp.Symbol(f"{s.name}ddot", real=True)
    return to_plain(expr, tuple(dict.fromkeys(coordinates))).xreplace(rules)


def _heading(text: str) -> str:
    return f"== {text} =="


def _summary(results, markdown: bool = False) -> str:
    """One row per ``(problem, comparison)``."""
    rows = []
    for problem, c in results:
        d = c.to_dict()
        published = d.get("published") or []
        verdicts = [p.get("verdict") for p in published if isinstance(p, dict)]
        rows.append((problem.name, _dof(problem), "yes" if c.equivalent else "NO",
                     d.get("method", "?"), f"{float(d.get('seconds', 0.0)):.2f}",
                     len(d.get("reactions") or {}),
                     _verdict_counts(verdicts)))
    return _table(("problem", "dof", "equivalent", "method", "seconds", "reactions",
                   "published answers"), rows, markdown=markdown)


def _verdict_counts(verdicts) -> str:
    """``"14 correct, 4 wrong"``, or ``-`` for none."""
    if not verdicts:
        return "-"
    order = dict.fromkeys(["correct", "wrong", "unchecked", *verdicts])
    counts = {v: verdicts.count(v) for v in order if v in verdicts}
    return ", ".join(f"{n} {v}" for v, n in counts.items())


def _cmd_report(args) -> int:
    from .report import write_report
    out: Path = args.out
    if "\x00" in str(out):
        raise UsageError("`--out` contains a NUL byte; give a directory path.")
    out.mkdir(parents=True, exist_ok=True)
    results = []
    for problem in _progress(_catalogue().all_problems(), "checking"):
        c = _compare(problem, args.points, args.seed)
        results.append((problem, c))
        (out / f"{problem.name}.json").write_text(_json(c.to_dict()) + "\n")
    print(_summary(results))
    w = write_report([c for _, c in results], out, args.duration)
    print(f"\nwrote {w.markdown}, {w.html}, {len(results)} JSON files and "
          f"{len(w.charts) - len(w.failed)} charts to {out}/")
    for name, why in w.failed.items():
        print(f"no chart for {name}: {why}")
    return EXIT_OK if all(c.equivalent for _, c in results) else EXIT_DISAGREE


