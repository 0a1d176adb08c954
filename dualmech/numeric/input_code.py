"""Given inputs on the compiled route: closed forms and tables evaluated in the generated C.

A model driven by given inputs (:mod:`dualmech.numeric.inputs`) is generated a second time for
C with each input ``w_i`` a *dynamic* value, like the state, never folded into a static
coefficient (:func:`dualmech.numeric.codegen.program`'s ``inputs``), and defined at the top of
every evaluation (:func:`dualmech.numeric.cbackend.c_source`'s ``input_code``):

* a closed form (a sympy expression of ``t`` and parameters) is printed into the C source --
  the library's key holds the expression, so each one is compiled once and cached;
* a table is interpolated in C by ``dm_table`` (the same formula and row search as
  :func:`numpy.interp`, which the Python route calls), its rows stored after the parameters
  in the ``p`` array the library reads: the key does not depend on the data.

A Python callable cannot be called from C without Python per step: :func:`compiled_inputs`
raises :class:`NotCompiled` saying so, and the caller keeps the scipy route.

Example
-------
>>> import numpy as np, sympy as sp
>>> from dualmech import EquationSet, coordinate, t
>>> from dualmech.numeric.inputs import expression_history
>>> x = coordinate("x"); F = sp.Symbol("F")
>>> eqs = EquationSet("pushed", (x,), (x.diff(t, 2) + x - F,))
>>> c = compiled_inputs(eqs, (F,), (1, 1), {}, {F: expression_history("F", sp.sin(2 * t), {})})
>>> [line.strip() for line in c.c_source().splitlines() if "w_0" in line]
['const double w_0 = sin(2.0*t_);', 'b[0] = (-q_0 + w_0);']
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache
from typing import Callable, Mapping, Sequence

import numpy as np
import sympy as sp
import symengine as se

from dualmech.model.equations import state_symbols
from dualmech.model.kinematics import t
from dualmech.numeric import cbackend, codegen
from dualmech.numeric._cache import digest, load_module

__all__ = ["CompiledInputs", "NotCompiled", "compiled_inputs", "python_inputs"]


class NotCompiled(ValueError):
    """The inputs cannot run in C (a Python callable); the message says why."""


@dataclass(frozen=True)
class CompiledInputs:
    """The C library of a model with its inputs in C: ``key`` and ``c_source`` (for
    :func:`dualmech.numeric.cbackend.load`), the ``p`` array it reads (parameters, then the
    tables) and its static coefficients ``k``."""

    key: str
    c_source: Callable[[], str]
    p: np.ndarray
    k: np.ndarray
    n_inputs: int


def compiled_inputs(eqs, code_params: Sequence, shape: tuple, values: Mapping,
                    histories: Mapping, trip: float = 1e-8) -> CompiledInputs:
    """The C route of ``eqs`` (its system of ``shape``) driven by ``histories`` (symbol ->
    History) with the parameter ``values`` (symbol -> number; ``code_params`` are the
    equations' parameter symbols, the inputs among them).

    Raises
    ------
    NotCompiled
        A history is a Python callable.
    """
    why = python_inputs(histories)
    if why:
        raise NotCompiled(why)
    inputs = [s for s in code_params if s in histories]
    params = [s for s in code_params if s not in histories]
    for s in inputs:   # parameters a closed form names that the equations do not
        params += [p for p in _sorted(histories[s].params or {}) if p not in params]
    kinds = [histories[s].expr if histories[s].kind == "expression" else "table"
             for s in inputs]
    key = digest("equations with inputs", codegen.GENERATOR_VERSION, eqs.coordinates,
                 eqs.unknowns, eqs.equations, tuple(inputs), tuple(params), tuple(kinds))
    prog = _program_builder(eqs, tuple(params), tuple(inputs))
    module = load_module(key, lambda: codegen.python_source(_statics_only(prog()), key))
    pv = [float({**values, **_all_params(histories)}[s]) for s in params]
    tables, code = [], []
    at = len(pv) + 2 * len(inputs)       # the tables' rows follow the descriptors
    rename = {se.Symbol(s.name): se.Symbol(f"p_{i}") for i, s in enumerate(params)}
    rename[se.Symbol(t.name)] = se.Symbol("t_")
    printer = cbackend.CPrinter()
    for i, s in enumerate(inputs):
        h = histories[s]
        if h.kind == "table":
            tables.append((at, h.times.size))
            at += 2 * h.times.size
            code.append(f"dm_table(t_, p, {len(pv) + 2 * i})")
        else:
            tables.append((0, 0))
            code.append(printer(se.sympify(h.expr).xreplace(rename)))
    p = np.concatenate([np.array(pv, float), np.array(tables, float).ravel()]
                       + [np.concatenate([h.times, h.values]) for h in
                          (histories[s] for s in inputs) if h.kind == "table"])
    k = np.array(module.static(tuple(pv)), dtype=float)
    source = lambda: cbackend.c_source(prog(), key, shape, trip, tuple(code))  # noqa: E731
    return CompiledInputs(key, source, p, k, len(inputs))


def python_inputs(histories: Mapping) -> str | None:
    """Why ``histories`` cannot run in C (a Python callable among them), or ``None``."""
    slow = sorted(getattr(h, "name", str(s)) for s, h in histories.items()
                  if getattr(h, "kind", None) not in ("expression", "table"))
    if slow:
        return (f"input {', '.join(slow)} is a Python function, called at every step: give "
                "a closed form of t or a table to run it in C")
    return None


def _sorted(symbols) -> list:
    return sorted(symbols, key=lambda s: s.name)


def _all_params(histories: Mapping) -> dict:
    out = {}
    for h in histories.values():
        out.update(h.params or {})
    return out


def _program_builder(eqs, params: tuple, inputs: tuple):
    @lru_cache(maxsize=1)
    def prog() -> codegen.Program:
        A, b = eqs.plain_matrix()
        states = [state_symbols(q) for q in eqs.coordinates]
        return codegen.program(list(A) + list(b), t=t, q=[s.q for s in states],
                               qd=[s.qd for s in states], params=params,
                               scale_of=A.rows * A.cols, inputs=inputs)
    return prog


def _statics_only(prog: codegen.Program) -> codegen.Program:
    """The program's static part alone (its ``static(p)`` in Python; the C library has the
    rest)."""
    return replace(prog, body=(), outputs=(se.Integer(0),), n_inputs=0)
