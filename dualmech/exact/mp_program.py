"""Expressions evaluated in mpmath at any size: lambdify, or a flat program when that fails.

``sympy.lambdify`` prints the expressions as Python source and compiles it; a sum of a few
thousand terms (a wrong model's residual, expanded) is a chain of a few thousand ``+`` that
CPython's compiler refuses with ``RecursionError: maximum recursion depth exceeded during
compilation``.  :func:`mp_function` then builds a flat list of instructions instead, one per
distinct subtree, walked without recursion: no source text, no depth limit.

Example
-------
>>> import mpmath, sympy as sp
>>> x = sp.Symbol("x")
>>> fn = flat_program([x], [sp.sin(x) ** 2 + sp.cos(x) ** 2, sp.sqrt(x) * sp.pi])
>>> [mpmath.nstr(v, 12) for v in fn(mpmath.mpf("0.5"))]
['1.0', '2.22144146908']
"""
from __future__ import annotations

from typing import Callable, Sequence

import mpmath
import sympy as sp

__all__ = ["mp_function", "flat_program"]

_FUNCS = {sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan, sp.cot: mpmath.cot,
          sp.sec: mpmath.sec, sp.csc: mpmath.csc, sp.exp: mpmath.exp, sp.log: mpmath.log,
          sp.asin: mpmath.asin, sp.acos: mpmath.acos, sp.atan: mpmath.atan,
          sp.sinh: mpmath.sinh, sp.cosh: mpmath.cosh, sp.tanh: mpmath.tanh,
          sp.Abs: mpmath.fabs, sp.sign: mpmath.sign, sp.atan2: mpmath.atan2}


def mp_function(args: Sequence, exprs: Sequence) -> Callable:
    """``f(*values) -> list`` of the values of ``exprs`` (mpmath numbers) at ``args = values``:
    ``sympy.lambdify`` where it compiles, else :func:`flat_program`."""
    try:
        return _lambdified(args, exprs)
    except RecursionError:
        return flat_program(args, exprs)


def _lambdified(args, exprs) -> Callable:
    return sp.lambdify(list(args), list(exprs), modules="mpmath")


def flat_program(args: Sequence, exprs: Sequence) -> Callable:
    """The same function as a flat instruction list (no recursion, no compiled source).

    Supports sums, products, powers, numbers, ``pi``, ``E`` and the elementary functions of
    ``_FUNCS``; anything else raises ``ValueError`` naming it.
    """
    index: dict = {s: i for i, s in enumerate(args)}
    code: list = []           # (slot, op, operand slots or constant)
    stack = [(e, False) for e in exprs]
    while stack:
        e, ready = stack.pop()
        if e in index:
            continue
        if not ready and e.args and not e.is_Number:
            stack.append((e, True))
            stack.extend((a, False) for a in e.args if a not in index)
            continue
        index[e] = len(index)
        code.append(_instruction(e, index))
    n_args = len(args)
    outputs = [index[e] for e in exprs]

    def run(*values):
        if len(values) != n_args:
            raise TypeError(f"expected {n_args} values, got {len(values)}")
        r = list(values) + [None] * len(code)
        for at, op, data in code:
            r[at] = op(r, data)
        return [r[i] for i in outputs]

    return run


def _instruction(e, index) -> tuple:
    at = index[e]
    if e.is_Number or e in (sp.pi, sp.E):
        value = mpmath.mpmathify(sp.Float(e, 40)) if not e.is_Rational else None
        if e.is_Rational:
            p, q = int(e.p), int(e.q)
            return at, lambda r, d: mpmath.mpf(d[0]) / d[1], (p, q)
        if e is sp.pi:
            return at, lambda r, d: +mpmath.pi, None
        if e is sp.E:
            return at, lambda r, d: +mpmath.e, None
        return at, lambda r, d: d, value
    slots = [index[a] for a in e.args]
    if e.is_Add:
        return at, lambda r, d: mpmath.fsum(r[i] for i in d), slots
    if e.is_Mul:
        return at, lambda r, d: mpmath.fprod(r[i] for i in d), slots
    if e.is_Pow:
        return at, lambda r, d: mpmath.power(r[d[0]], r[d[1]]), slots
    fn = _FUNCS.get(e.func)
    if fn is None:
        raise ValueError(f"`{type(e).__name__}` has no mpmath evaluation here: {e}")
    return at, lambda r, d, fn=fn: fn(*[r[i] for i in d]), slots
