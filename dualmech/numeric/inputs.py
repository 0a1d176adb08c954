"""The histories of a problem's given inputs, for a simulation: closed forms, tables, callables.

A problem declares its given inputs on :attr:`Problem.inputs
<dualmech.model.problem.Problem>` (:class:`~dualmech.model.inputs.Input`); a simulation needs a
history for each, ``inputs={"F": history}``, where a history is

* a **closed form**: a sympy expression of ``t`` (:data:`dualmech.t`) and the problem's
  parameters, e.g. ``2 * sp.sin(3 * t)`` -- compiled into the C right-hand side on the
  CVODE route;
* a **table** ``(times, values)`` -- two sequences of the same length, times strictly
  increasing -- interpolated linearly between its rows (never extrapolated: a run that reaches
  past the table is refused before it starts), in C on the CVODE route; or
* a Python **callable** ``f(t) -> number``, called at every evaluation (the scipy route).

An input the caller gives no history for takes the problem's own default, the
:class:`~dualmech.model.inputs.Input`'s ``history`` (:func:`default_histories` says which
ones did); with neither, the run is refused.  :func:`input_functions` checks the mapping
against the declaration (a missing input, an unknown name, a malformed table are refused,
saying what to give) and returns a :class:`History` for each, which
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

import copy
import math
from dataclasses import dataclass
from typing import Callable, Mapping

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from dualmech.model.kinematics import t as _t

__all__ = ["History", "input_functions", "table_function", "declared_inputs",
           "default_histories", "default_values", "describe", "driven_problem", "expression_history", "InputError", "MAX_TABLE_ROWS"]

#: the most rows a table may have
MAX_TABLE_ROWS = 1_000_000

_HOW = ("pass inputs={{{name!r}: history}}: an expression of t, a table (times, values) or a "
        "function of t (on the command line --input {name}=EXPRESSION-OF-t or --input "
        "{name}=table.csv), or declare the problem's default, Input(..., history=...)")


class InputError(ValueError):
    """A given input's history failed at some time (not a number, outside its table)."""


@dataclass(frozen=True, eq=False)
class History:
    """One given input's history, callable as ``f(t)``: ``kind`` is ``"expression"`` (then
    ``expr``, in ``t`` and parameters, with the parameters' values ``params``), ``"table"``
    (then ``times`` and ``values``) or ``"callable"`` (a Python function: no compiled route
    can call it).

    Example
    -------
    >>> h = History("F", "table", lambda t: 2.0 * t, times=np.array([0.0, 1.0]),
    ...             values=np.array([0.0, 2.0]))
    >>> h(0.25), h.kind
    (0.5, 'table')
    """

    name: str
    kind: str
    function: Callable[[float], float]
    expr: object = None
    params: Mapping | None = None
    times: np.ndarray | None = None
    values: np.ndarray | None = None

    def __call__(self, time: float) -> float:
        return self.function(time)


def declared_inputs(problem) -> dict:
    """``{name: Input}`` of the problem's declared given inputs."""
    return {x.name: x for x in (getattr(problem, "inputs", ()) or ())}


def default_histories(problem, inputs: Mapping | None = None) -> list[str]:
    """Names of the inputs a run with ``inputs`` takes from the problem's own declaration
    (:class:`~dualmech.model.inputs.Input`'s ``history``), in declaration order.

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import FORCE, Input, Problem, t
    >>> class Pushed(Problem):
    ...     name, inputs = "pushed", (Input(sp.Symbol("F"), FORCE, "push", sp.sin(t)),)
    >>> default_histories(Pushed()), default_histories(Pushed(), {"F": 0 * t})
    (['F'], [])
    """
    given = {getattr(k, "name", k) for k in (inputs or {})}
    return [name for name, decl in declared_inputs(problem).items()
            if name not in given and getattr(decl, "history", None) is not None]


def describe(problem, inputs: Mapping | None = None) -> dict:
    """``{name: text}``: each input's history in words, for a run's stated conditions
    (``"default: 3*sin(2*t)"``, ``"table of 301 rows"``, ``"Python function"``)."""
    out = dict(getattr(problem, "driven_by", None) or {})
    given = {getattr(k, "name", k): v for k, v in (inputs or {}).items()}
    for name, decl in declared_inputs(problem).items():
        value, prefix = given.get(name), ""
        if value is None and getattr(decl, "history", None) is not None:
            value, prefix = decl.history, "default: "
        if value is None:
            continue
        if isinstance(value, History):
            value = value.expr if value.kind == "expression" else \
                (value.times, value.values) if value.kind == "table" else value.function
        if isinstance(value, sp.Basic):
            text = str(value)
        elif callable(value):
            text = "Python function"
        else:
            text = f"table of {len(value[0])} rows"
        out[name] = prefix + text
    return out


def default_values(problem, time: float = 0.0, params: Mapping | None = None) -> dict:
    """``{name: value}`` at ``time`` of each input that declares a default history (the
    parameters' values ``params``, default the problem's defaults).

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import FORCE, Input, Problem, t
    >>> class Pushed(Problem):
    ...     name, inputs = "pushed", (Input(sp.Symbol("F"), FORCE, "push", 3 * t),)
    >>> default_values(Pushed(), 0.5)
    {'F': 1.5}
    """
    values = {**problem.defaults(), **{_as_symbol(problem, k): v
                                       for k, v in (params or {}).items()}}
    return {name: _history(name, decl.history, None, values)(float(time))
            for name, decl in declared_inputs(problem).items()
            if getattr(decl, "history", None) is not None}


def driven_problem(problem):
    """``problem`` with each given input replaced in its models by its declared default
    history (a closed form of ``t``): an input-free problem with explicit time dependence,
    for the studies that build their own models (work-precision charts, DAE forms); a problem
    without inputs is returned as it is.  Its :func:`describe` still states the inputs.

    Raises
    ------
    ValueError
        An input has no default history, or a table as its default (a study needs a closed
        form; ``simulate`` takes tables).

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import FORCE, Input, Problem, t
    >>> class Pushed(Problem):
    ...     name, inputs = "pushed", (Input(sp.Symbol("F"), FORCE, "push", 3 * t),)
    >>> d = driven_problem(Pushed())
    >>> d.inputs, d.driven_by
    ((), {'F': 'default: 3*t'})
    """
    declared = declared_inputs(problem)
    if not declared:
        return problem
    mapping = {}
    for name, decl in declared.items():
        h = getattr(decl, "history", None)
        if not isinstance(h, sp.Expr):
            what = "no default history" if h is None else "a table as its default history"
            raise ValueError(f"problem `{problem.name}`: input {name} has {what}; a study "
                             "drives it with a closed form of t: declare Input(..., "
                             "history=expression of t).")
        mapping[decl.symbol] = h.xreplace({s: _t for s in h.free_symbols if s.name == "t"})
    stated = describe(problem)
    models = {n: eqs.substitute(mapping) for n, eqs in problem.models().items()}
    out = copy.copy(problem)
    out.__dict__.update({"_models": models, "inputs": (), "driven_by": stated})
    return out


def input_functions(problem, inputs: Mapping | None, t_span=None,
                    params: Mapping | None = None) -> dict:
    """``{symbol: History}`` for every declared input of ``problem`` from ``inputs`` (names or
    symbols to closed forms, tables or callables), else from the input's declared default
    history; ``t_span`` is the run a table must cover, ``params`` the parameters' values a
    closed form is evaluated with (default: the problem's defaults)."""
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
    values = {**problem.defaults(), **{_as_symbol(problem, k): v
                                       for k, v in (params or {}).items()}}
    for name, decl in declared.items():
        value = given.get(name, getattr(decl, "history", None))
        if value is None:
            what = f" ({decl.description})" if decl.description else ""
            raise ValueError(f"problem `{problem.name}` needs the given input {name}{what} "
                             "to be simulated: " + _HOW.format(name=name) + ".")
        out[decl.symbol] = _history(name, value, t_span, values)
    return out


def _as_symbol(problem, key):
    if not isinstance(key, str):
        return key
    return next((p.symbol for p in problem.parameters if p.symbol.name == key), key)


def _history(name: str, value, t_span, params: Mapping) -> History:
    if isinstance(value, History):
        return value
    if isinstance(value, sp.Basic):
        return expression_history(name, value, params)
    if callable(value):
        return History(name, "callable", _checked(name, value))
    if isinstance(value, (str, bytes)):
        raise TypeError(f"`inputs`: {name} is text; give a function of t or a table (times, "
                        "values) -- the command line reads expressions and CSV files "
                        "(--input).")
    return table_function(name, value, t_span)


def expression_history(name: str, expr, params: Mapping) -> History:
    """The closed-form history ``expr`` (a sympy expression of ``t`` and parameters, with
    their values ``params``: symbol -> number).

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import t
    >>> a = sp.Symbol("a")
    >>> expression_history("F", a * t**2, {a: 3.0})(2.0)
    12.0
    """
    if not isinstance(expr, sp.Expr) or isinstance(expr, sp.Tuple):
        raise TypeError(f"`inputs`: {name} = {expr!r:.60} is not an expression of t.")
    by_name = {getattr(s, "name", str(s)): s for s in params}
    rename, missing = {}, []
    for s in expr.free_symbols - {_t}:
        known = s if s in params else by_name.get(s.name) if s.name != "t" else None
        if s.name == "t" and s != _t:
            rename[s] = _t              # a plain t written by hand
        elif known is None:
            missing.append(s.name)
        else:
            rename[s] = known
    if missing:
        raise ValueError(f"`inputs`: {name} = {expr} names {', '.join(sorted(missing))}, "
                         "which are neither t nor the problem's parameters.")
    expr = expr.xreplace(rename)
    if expr.has(sp.Derivative, sp.Integral) or expr.atoms(AppliedUndef):
        raise ValueError(f"`inputs`: {name} = {expr}: a closed form of t uses numbers, t, "
                         "parameters and elementary functions only.")
    used = {s: float(params[s]) for s in expr.free_symbols - {_t}}
    fn = sp.lambdify(_t, expr.xreplace(used), "math")   # a tree built by the caller, no text
    return History(name, "expression", _checked(name, fn), expr=expr, params=used)


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


def table_function(name: str, table, t_span=None) -> History:
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
    back = np.flatnonzero(np.diff(times) <= 0)
    if back.size:
        i = int(back[0])
        raise ValueError(f"input {name}: the table's times must increase strictly (row "
                         f"{i + 2}: t = {times[i + 1]:g} after t = {times[i]:g}).")
    lo, hi = float(times[0]), float(times[-1])
    times, values = np.ascontiguousarray(times), np.ascontiguousarray(values)
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
    return History(name, "table", value, times=times, values=values)
