"""``--input NAME=HISTORY``: a given input's history for ``dualmech simulate``.

``HISTORY`` is either a CSV file (``F=push.csv``: two columns, time then value, an optional
header row; interpolated linearly, never extrapolated) or an expression of ``t`` (``F=2*sin(3
t)``) read by the grader's parser (:func:`dualmech.grade.parser.parse`, which never evaluates
text) and turned into a function of ``t`` node by node: numbers, ``t``, ``pi``, the problem's
parameters (their values in this run), ``+ - * / ^``, and ``sin cos tan cot sec csc exp log
sqrt``.  Anything else is refused, saying what to write.

>>> import math
>>> f = expression_history("F", "2 sin(3 t) + t^2", {})
>>> abs(f(1.0) - (2 * math.sin(3.0) + 1.0)) < 1e-15
True
>>> expression_history("F", "open('x')", {})   # doctest: +ELLIPSIS
Traceback (most recent call last):
dualmech.cli.errors.UsageError: `--input F`: could not read the answer at column 6: ...
"""
from __future__ import annotations

import csv
import math
import re
from pathlib import Path
from typing import Callable, Mapping

from dualmech.cli.errors import UsageError

__all__ = ["parse_inputs", "expression_history", "read_table", "MAX_INPUT", "MAX_CSV_BYTES"]

MAX_INPUT = 2000            # characters of one --input
MAX_CSV_BYTES = 50_000_000  # size of one table file
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
_FUNCS: dict = {"sin": math.sin, "cos": math.cos, "tan": math.tan, "exp": math.exp,
                "log": math.log, "sqrt": math.sqrt, "cot": lambda x: 1 / math.tan(x),
                "sec": lambda x: 1 / math.cos(x), "csc": lambda x: 1 / math.sin(x)}
_EXAMPLE = "e.g. --input 'F=2*sin(3*t)' or --input F=push.csv"


def parse_inputs(texts, parameters: Mapping[str, float]) -> dict:
    """``{name: history}`` from the ``--input`` options (``parameters``: name -> value)."""
    out: dict = {}
    for text in texts:
        if len(text) > MAX_INPUT:
            raise UsageError(f"`--input` is {len(text)} characters long; at most {MAX_INPUT}.")
        name, sep, value = (x.strip() for x in text.partition("="))
        if not sep or not _NAME.fullmatch(name) or not value:
            raise UsageError(f"`--input` takes NAME=HISTORY, got {text[:60]!r}; {_EXAMPLE}.")
        if name in out:
            raise UsageError(f"`--input`: {name} is given twice.")
        out[name] = (read_table(name, value) if value.lower().endswith(".csv")
                     else expression_history(name, value, parameters))
    return out


def read_table(name: str, path: str) -> tuple[list, list]:
    """``(times, values)`` from a two-column CSV file (cells read by ``float``, nothing
    evaluated; the table's own checks are :func:`dualmech.numeric.inputs.table_function`'s)."""
    p = Path(path)
    if not p.is_file():
        raise UsageError(f"`--input {name}`: no file {path[:200]!r}.")
    if p.stat().st_size > MAX_CSV_BYTES:
        raise UsageError(f"`--input {name}`: {path[:200]} is larger than {MAX_CSV_BYTES} bytes.")
    times, values = [], []
    with p.open(newline="", encoding="utf-8", errors="replace") as fh:
        for i, row in enumerate(csv.reader(fh), 1):
            if not row or not "".join(row).strip():
                continue
            if len(row) != 2:
                raise UsageError(f"`--input {name}`: {path[:200]}, line {i}: {len(row)} "
                                 "columns; a table has two (time, value).")
            try:
                t, v = (float(x) for x in row)
            except ValueError:
                if i == 1:
                    continue     # a header row
                raise UsageError(f"`--input {name}`: {path[:200]}, line {i}: {row[0][:30]!r}, "
                                 f"{row[1][:30]!r} are not two numbers.") from None
            times.append(t)
            values.append(v)
    return times, values


def expression_history(name: str, text: str, parameters: Mapping[str, float]) -> Callable:
    """A function of ``t`` from the expression ``text`` (see the module docstring)."""
    from dualmech.grade.parser import AnswerError, parse
    try:
        (eq,) = parse(text)
    except AnswerError as exc:
        raise UsageError(f"`--input {name}`: {exc}".rstrip(".") + f"; {_EXAMPLE}.") from None
    except ValueError:
        raise UsageError(f"`--input {name}`: one expression of t, not several; "
                         f"{_EXAMPLE}.") from None
    if eq.rhs is not None:
        raise UsageError(f"`--input {name}`: an expression of t, not an equation; {_EXAMPLE}.")
    return _compiled(name, eq.lhs, dict(parameters))


def _compiled(name: str, node, parameters: dict) -> Callable:
    """The parsed tree as nested closures of floats (no text is evaluated)."""
    op, a = node.op, node.args
    if op == "num":
        c = float(a[0])
        return lambda t: c
    if op == "name":
        return _leaf(name, a, parameters)
    if op == "group":
        return _compiled(name, a[0], parameters)
    if op == "neg":
        f = _compiled(name, a[0], parameters)
        return lambda t: -f(t)
    if op == "inv":
        f = _compiled(name, a[0], parameters)
        return lambda t: 1.0 / f(t)
    if op in ("add", "mul"):
        fs = [_compiled(name, c, parameters) for c in a]
        if op == "add":
            return lambda t: math.fsum(f(t) for f in fs)
        return lambda t: math.prod(f(t) for f in fs)
    if op == "pow":
        base, exp = (_compiled(name, c, parameters) for c in a)
        return lambda t: math.pow(base(t), exp(t))
    if op == "func" and a[0] in _FUNCS:
        fn, arg = _FUNCS[a[0]], _compiled(name, a[1], parameters)
        return lambda t: fn(arg(t))
    raise UsageError(f"`--input {name}`: {op!r} is not allowed in an input's expression "
                     f"(numbers, t, pi, parameters, + - * / ^, sin cos tan exp log sqrt); "
                     f"{_EXAMPLE}.")


def _leaf(name: str, args: tuple, parameters: dict) -> Callable:
    text, primes = args
    if primes:
        raise UsageError(f"`--input {name}`: {text}{chr(39) * primes} -- an input is a function "
                         f"of t alone; {_EXAMPLE}.")
    if text == "t":
        return lambda t: t
    if text == "pi":
        return lambda t: math.pi
    if text in parameters:
        c = float(parameters[text])
        return lambda t: c
    known = ", ".join(["t", "pi"] + sorted(parameters))
    raise UsageError(f"`--input {name}`: {text[:40]!r} is not t, pi or a parameter ({known}).")
