"""The histories of a problem's given inputs, for a simulation: callables and tables.

A problem declares its given inputs on :attr:`Problem.inputs
<dualmech.model.problem.Problem>` (:class:`~dualmech.model.inputs.Input`); a simulation needs a
history for each, ``inputs={"F": history}``, where a history is

* a Python callable ``f(t) -> number``, or
* a table ``(times, values)`` -- two sequences of the same length, times strictly increasing
  -- interpolated linearly between its rows (never extrapolated: a run that reaches past the
  table is refused before it starts).

:func:`input_functions` checks the mapping against the declaration (a missing input, an
unknown name, a malformed table are refused, saying what to give) and returns the functions
:class:`~dualmech.numeric.model.NumericModel` binds at each evaluation; each one refuses a
value that is not a finite number, naming the input and the time.

Example
-------
>>> import sympy as sp
>>> from dualmech import FORCE, Input, Problem
>>> class Pushed(Problem):
...     name, inputs = "pushed", (Input(sp.Symbol("F"), FORCE, "push"),)
>>> fns = input_functions(Pushed(), {"F": ([0, 1, 2], [0.0, 10.0, 0.0])}, (0, 2))
>>> [fns[sp.Symbol("F")](x) for x in (0.5, 1.0, 1.5)]
[5.0, 10.0, 5.0]
>>> input_functions(Pushed(), {})            # doctest: +ELLIPSIS
Traceback (most recent call last):
ValueError: problem `pushed` needs the given input F (push) to be simulated: ...
"""
from __future__ import annotations

import math
from typing import Callable, Mapping

import numpy as np

__all__ = ["input_functions", "table_function", "declared_inputs", "InputError",
           "MAX_TABLE_ROWS"]

#: the most rows a table may have
MAX_TABLE_ROWS = 1_000_000

_HOW = ("pass inputs={{{name!r}: history}}: a function of t, or a table (times, values) "
        "(on the command line --input {name}=EXPRESSION-OF-t or --input {name}=table.csv)")


class InputError(ValueError):
    """A given input's history failed at some time (not a number, outside its table)."""


def declared_inputs(problem) -> dict:
    """``{name: Input}`` of the problem's declared given inputs."""
    return {x.name: x for x in (getattr(problem, "inputs", ()) or ())}


def input_functions(problem, inputs: Mapping | None, t_span=None) -> dict:
    """``{symbol: f(t)}`` for every declared input of ``problem`` from ``inputs`` (names or
    symbols to callables or tables); ``t_span`` is the run a table must cover."""
    declared = declared_inputs(problem)
    if inputs is not None and not isinstance(inputs, Mapping):
        raise TypeError(f"`inputs` must be a mapping {{name: history}}, got {inputs!r:.60}.")
    given = {getattr(k, "name", k): v for k, v in (inputs or {}).items()}
    for name in given:
        if name not in declared:
            known = ", ".join(declared) or "none"
            raise ValueError(f"`inputs`: {str(name)[:40]!r} is not a given input of problem "
                             f"`{problem.name}` (its inputs: {known}).")
    out = {}
    for name, decl in declared.items():
        if name not in given:
            what = f" ({decl.description})" if decl.description else ""
            raise ValueError(f"problem `{problem.name}` needs the given input {name}{what} "
                             "to be simulated: " + _HOW.format(name=name) + ".")
        out[decl.symbol] = _history(name, given[name], t_span)
    return out


def _history(name: str, value, t_span) -> Callable[[float], float]:
    if callable(value):
        return _checked(name, value)
    if isinstance(value, (str, bytes)):
        raise TypeError(f"`inputs`: {name} is text; give a function of t or a table (times, "
                        "values) -- the command line reads expressions and CSV files "
                        "(--input).")
    return table_function(name, value, t_span)


def _checked(name: str, f: Callable) -> Callable[[float], float]:
    def value(t: float) -> float:
        try:
            v = float(f(t))
        except (TypeError, ValueError, OverflowError, ZeroDivisionError) as exc:
            raise InputError(f"input {name} at t = {t:.6g} did not give a number "
                             f"({type(exc).__name__}: {exc}).") from None
        if not math.isfinite(v):
            raise InputError(f"input {name} at t = {t:.6g} is {v}: give a finite value.")
        return v
    return value


def table_function(name: str, table, t_span=None) -> Callable[[float], float]:
    """``f(t)`` interpolating the table ``(times, values)`` linearly (checked: two columns of
    the same length, at least two rows, finite numbers, times strictly increasing, covering
    ``t_span``)."""
    try:
        times, values = table
        times = np.asarray(times, dtype=float)
        values = np.asarray(values, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"input {name}: a table is (times, values), two sequences of numbers "
                         f"({exc}).") from None
    if times.ndim != 1 or times.shape != values.shape:
        raise ValueError(f"input {name}: times and values must be two sequences of the same "
                         f"length, got shapes {times.shape} and {values.shape}.")
    if not 2 <= times.size <= MAX_TABLE_ROWS:
        raise ValueError(f"input {name}: a table needs 2 to {MAX_TABLE_ROWS} rows, got "
                         f"{times.size}.")
    if not (np.isfinite(times).all() and np.isfinite(values).all()):
        raise ValueError(f"input {name}: the table holds a value that is not a finite number.")
    if not (np.diff(times) > 0).all():
        raise ValueError(f"input {name}: the table's times must increase strictly.")
    lo, hi = float(times[0]), float(times[-1])
    if t_span is not None:
        a, b = sorted(float(x) for x in t_span)
        if a < lo or b > hi:
            raise ValueError(f"input {name}: the table covers t in [{lo:g}, {hi:g}], the run "
                             f"needs [{a:g}, {b:g}]; extend the table (it is never "
                             "extrapolated).")

    def value(t: float) -> float:
        if not lo - 1e-12 * max(1.0, abs(lo)) <= t <= hi + 1e-12 * max(1.0, abs(hi)):
            raise InputError(f"input {name}: t = {t:.6g} is outside its table [{lo:g}, "
                             f"{hi:g}] (a table is never extrapolated).")
        return float(np.interp(t, times, values))
    return value
