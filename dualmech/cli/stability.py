"""The ``stability`` subcommand of ``dualmech``: eigenvalues of a steady motion over a sweep.

::

    dualmech stability NAME [--about 'q=0, q_dot=2.5'] [--sweep PARAM=START:STOP:N]
                            [--model M] [--out DIR] [--json]

NAME is anything :func:`dualmech.problems.load` takes.  Every model of the problem is
linearised about the steady motion (:func:`dualmech.numeric.stability.stability`): the
declared :attr:`Problem.steady_motion <dualmech.model.problem.Problem.steady_motion>` when no
option is given, else ``--about`` (coordinates of the reference model and their rates,
``name_dot`` or ``name'``; missing ones zero) with ``--sweep`` over a parameter of the
problem or a symbol of the declared steady motion.  Printed: the state matrix, the
eigenvalues at each swept value, the critical values and whether the derivations' eigenvalues
agree; with ``--out DIR`` also a root-locus chart ``DIR/NAME_root_locus.png``.

``--about`` is read by a strict ``name=number`` grammar: nothing in it is evaluated.  The
steady motion is checked exactly (the accelerations must vanish there, and only coordinates
nothing depends on may move), so a steady motion whose rates are not decimal numbers -- a
top's steady precession -- is declared on the problem with exact expressions
(``steady_motion = SteadyMotion(...)``) rather than typed.

Exit status (:mod:`dualmech.cli.errors`): 0 done and the derivations agree, 1 they disagree,
2 a usage error (a malformed ``--about`` or ``--sweep``) or a model that cannot be linearised
there (not a steady motion, a singular system).

Example
-------
>>> parse_about("theta=0.1, theta_dot=-2e-1")
{'theta': 0.1, 'theta_dot': -0.2}
>>> parse_about("theta=__import__('os')")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
dualmech.cli.errors.UsageError: `--about`: "__import__('os')" is not a number (theta=...); ...
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

from dualmech.cli.errors import DISAGREE, OK, UsageError, about, guarded

__all__ = ["register", "parse_about", "parse_sweep"]

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}'?")
_NUMBER = re.compile(r"[+-]?(?:\d{1,30}(?:\.\d{0,30})?|\.\d{1,30})(?:[eE][+-]?\d{1,3})?")
_EXAMPLE = "write name=number pairs separated by commas, e.g. 'theta=0.1, theta_dot=2'"
MAX_ABOUT = 2000
MAX_POINTS = 2001


def register(subparsers) -> None:
    """Add ``stability`` to ``subparsers`` (nothing heavy is imported before it runs)."""
    p = subparsers.add_parser(
        "stability", help="eigenvalues of a steady motion over a parameter sweep, every "
                          "derivation linearised and compared",
        description="Linearise every model of a problem about a steady motion (with "
                    "multipliers and rolling constraints reduced to independent coordinates "
                    "and speeds), print the eigenvalues at each swept value and the values "
                    "where stability changes.")
    p.add_argument("name", metavar="NAME",
                   help="the problem: a catalogue name, path.py[:Class] or module:Class")
    p.add_argument("--about", metavar="'q=V, q_dot=W'", default=None,
                   help="the steady motion: coordinates and rates (name_dot) of the reference "
                        "model as name=number pairs (default: the problem's declared "
                        "steady_motion, else every coordinate and rate zero)")
    p.add_argument("--sweep", metavar="PARAM=START:STOP:N", default=None, type=parse_sweep,
                   help=f"sweep PARAM over N values (2 to {MAX_POINTS}) from START to STOP")
    p.add_argument("--model", metavar="M", default=None,
                   help="the model whose eigenvalues are printed (default: the reference)")
    p.add_argument("--out", metavar="DIR", type=Path, default=None,
                   help="also write the root-locus chart DIR/NAME_root_locus.png")
    p.add_argument("--json", action="store_true",
                   help="print JSON: name, model, parameter, values, eigenvalues ([re, im] "
                        "per eigenvalue), stable, critical ({value, kind}), states, "
                        "derivations, chart")
    p.set_defaults(func=guarded(_stability))


def parse_about(text: str) -> dict:
    """``'a=1, b_dot=2'`` -> ``{'a': 1.0, 'b_dot': 2.0}`` by a strict grammar (no evaluation)."""
    if len(text) > MAX_ABOUT:
        raise UsageError(f"`--about` is {len(text)} characters long; at most {MAX_ABOUT}.")
    out: dict = {}
    items = [item.strip() for item in re.split(r"[,;]", text)]
    if not any(items):
        raise UsageError(f"`--about` is empty; {_EXAMPLE}.")
    for item in items:
        if not item:
            continue
        name, sep, value = (x.strip() for x in item.partition("="))
        if not sep:
            raise UsageError(f"`--about`: {item[:40]!r} has no '='; {_EXAMPLE}.")
        if not _NAME.fullmatch(name):
            raise UsageError(f"`--about`: {name[:40]!r} is not a coordinate name; {_EXAMPLE}.")
        if not _NUMBER.fullmatch(value):
            raise UsageError(f"`--about`: {value[:40]!r} is not a number ({name}=...); "
                             f"{_EXAMPLE}.".replace(f"{value[:40]!r}", f'"{value[:40]}"'))
        number = float(value)
        if not math.isfinite(number):
            raise UsageError(f"`--about`: {name} = {value[:40]} is not finite.")
        if name in out:
            raise UsageError(f"`--about`: {name} is given twice.")
        out[name] = number
    return out


def parse_sweep(text: str) -> tuple:
    """``'v=0:2:11'`` -> ``('v', 0.0, 2.0, 11)`` (argparse type; no evaluation)."""
    import argparse
    m = re.fullmatch(r"\s*([A-Za-z][A-Za-z0-9_]{0,63})\s*=\s*([^:]{1,40}):([^:]{1,40}):"
                     r"\s*(\d{1,6})\s*", text)
    bad = f"expected PARAM=START:STOP:N, e.g. v=0:2:21, got {text[:60]!r}"
    if not m:
        raise argparse.ArgumentTypeError(bad)
    start, stop = m.group(2).strip(), m.group(3).strip()
    if not (_NUMBER.fullmatch(start) and _NUMBER.fullmatch(stop)):
        raise argparse.ArgumentTypeError(bad)
    count = int(m.group(4))
    if not 2 <= count <= MAX_POINTS:
        raise argparse.ArgumentTypeError(f"N = {count} is outside 2..{MAX_POINTS}")
    if float(start) == float(stop):
        raise argparse.ArgumentTypeError(f"START and STOP are equal in {text[:60]!r}")
    return m.group(1), float(start), float(stop), count


def _load(name: str):
    from dualmech import problems
    try:
        return problems.load(name)
    except KeyError as exc:
        raise UsageError(exc.args[0] if exc.args else str(exc)) from None


def _stability(args) -> int:
    numbers = parse_about(args.about) if args.about is not None else None
    problem = _load(args.name)
    from dualmech.numeric.stability import root_locus_chart, stability, steady_state_from_names
    if args.model is not None and args.model not in problem.model_names:
        raise UsageError(f"`--model` {args.model!r} is not a model of `{problem.name}` "
                         f"({', '.join(problem.model_names)}).")
    with about(problem):
        try:
            steady = None if numbers is None else steady_state_from_names(problem, numbers)
            parameter, sweep = (args.sweep[0], args.sweep[1:]) if args.sweep else (None, None)
            study = stability(problem, steady, parameter, sweep, args.model)
        except ValueError as exc:
            steady_error = "not a steady motion" in str(exc) or "breaks the constraint" in str(exc)
            if numbers is not None and steady_error:   # the user's --about, not the problem
                raise UsageError(f"`--about`: {exc}") from None
            if steady_error and getattr(problem, "steady_motion", None) is None:
                raise UsageError(f"`{problem.name}` declares no steady motion, and the state "
                                 f"at rest with every coordinate zero is not one: {exc}  Give "
                                 "--about, or declare steady_motion = SteadyMotion(...) on the "
                                 "problem.") from None
            if type(exc).__name__ in ("ModelError", "ProblemError"):
                raise
            raise UsageError(str(exc)) from None
    chart = None
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        chart = root_locus_chart(study, args.out / f"{problem.name}_root_locus.png")
    status = DISAGREE if study.derivations.get("agree") is False else OK
    if args.json:
        print(json.dumps({**study.as_dict(), "chart": chart}, indent=1))
        return status
    print(study)
    if chart:
        print(f"  chart: {chart}")
    return status
