"""``--input NAME=HISTORY``: a given input's history for ``dualmech simulate``.

``HISTORY`` is either a CSV file (``F=push.csv``: two columns, time then value, an optional
header row; interpolated linearly, never extrapolated) or an expression of ``t`` (``F=2*sin(3
t)``) read by the grader's parser (:func:`dualmech.grade.parser.parse`, which never evaluates
text) and built into a sympy expression node by node: numbers, ``t``, ``pi``, the problem's
parameters (their values in this run), ``+ - * / ^``, and ``sin cos tan cot sec csc exp log
sqrt``.  Anything else is refused, saying what to write.  Both kinds run in the compiled
C right-hand side on the CVODE route (:mod:`dualmech.numeric.input_code`).

>>> expression_history("F", "2 sin(3 t) + t^2", {})
t**2 + 2*sin(3*t)
>>> expression_history("F", "open('x')", {})   # doctest: +ELLIPSIS
Traceback (most recent call last):
dualmech.cli.errors.UsageError: `--input F`: could not read the answer at column 6: ...
"""
from __future__ import annotations

import csv
import math
import re
from pathlib import Path
from typing import Mapping

import sympy as sp

from dualmech.cli.errors import UsageError
from dualmech.model.kinematics import t
from dualmech.numeric.inputs import MAX_TABLE_ROWS

__all__ = ["parse_inputs", "expression_history", "read_table", "MAX_INPUT", "MAX_CSV_BYTES"]

MAX_INPUT = 2000            # characters of one --input
MAX_CSV_BYTES = 50_000_000  # size of one table file
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
_FUNCS: dict = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "exp": sp.exp, "log": sp.log,
                "sqrt": sp.sqrt, "cot": lambda x: 1 / sp.tan(x), "sec": lambda x: 1 / sp.cos(x),
                "csc": lambda x: 1 / sp.sin(x)}
_EXAMPLE = "e.g. --input 'F=2*sin(3*t)' or --input F=push.csv"


def parse_inputs(texts, parameters: Mapping[str, object]) -> dict:
    """``{name: history}`` from the ``--input`` options (``parameters``: name -> symbol)."""
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
            if len(times) == MAX_TABLE_ROWS:   # stop reading: the table is refused anyway
                raise UsageError(f"`--input {name}`: {path[:200]} has more than "
                                 f"{MAX_TABLE_ROWS} rows; a table may have at most that many.")
            times.append(t)
            values.append(v)
    return times, values


def expression_history(name: str, text: str, parameters: Mapping[str, object]):
    """A sympy expression of ``t`` (:data:`dualmech.t`) from ``text`` (see the module
    docstring); ``parameters`` maps the names it may use to their symbols."""
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
    expr = _built(name, eq.lhs, dict(parameters))
    if expr.free_symbols - {t}:   # the parameters' values come later: checked in the run
        return expr
    try:   # a finite value where the run starts (10^10^10 is refused here, not mid-run)
        value = complex(expr.subs(t, 0).evalf(17))
    except (TypeError, ValueError, ZeroDivisionError, OverflowError):
        value = complex("nan")
    if not (math.isfinite(value.real) and value.imag == 0):
        raise UsageError(f"`--input {name}`: {text[:60]!r} did not give a number at t = 0; "
                         f"{_EXAMPLE}.")
    return expr


def _built(name: str, node, parameters: dict):
    """The parsed tree as a sympy expression, node by node (no text is evaluated)."""
    op, a = node.op, node.args
    if op == "num":
        return sp.Rational(a[0].numerator, a[0].denominator)
    if op == "name":
        return _leaf(name, a, parameters)
    if op == "group":
        return _built(name, a[0], parameters)
    if op == "neg":
        return -_built(name, a[0], parameters)
    if op == "inv":
        return 1 / _built(name, a[0], parameters)
    if op in ("add", "mul"):
        parts = [_built(name, c, parameters) for c in a]
        return sp.Add(*parts) if op == "add" else sp.Mul(*parts)
    if op == "pow":
        base, exp = (_built(name, c, parameters) for c in a)
        if exp.is_number and base.is_number and abs(exp) > 1000:
            raise UsageError(f"`--input {name}`: a power too large to evaluate (the input "
                             f"did not give a number); {_EXAMPLE}.")
        return sp.Pow(base, exp)
    if op == "func" and a[0] in _FUNCS:
        return _FUNCS[a[0]](_built(name, a[1], parameters))
    raise UsageError(f"`--input {name}`: {op!r} is not allowed in an input's expression "
                     f"(numbers, t, pi, parameters, + - * / ^, sin cos tan exp log sqrt); "
                     f"{_EXAMPLE}.")


def _leaf(name: str, args: tuple, parameters: dict):
    text, primes = args
    if primes:
        raise UsageError(f"`--input {name}`: {text}{chr(39) * primes} -- an input is a function "
                         f"of t alone; {_EXAMPLE}.")
    if text == "t":
        return t
    if text == "pi":
        return sp.pi
    if text in parameters:
        return parameters[text]
    known = ", ".join(["t", "pi"] + sorted(parameters))
    raise UsageError(f"`--input {name}`: {text[:40]!r} is not t, pi or a parameter ({known}).")
