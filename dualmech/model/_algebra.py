"""The heavy algebra of the derivation path, on symengine, with sympy at the edges.

Measured (planar 8-link chain): differentiating with sympy with respect to ``Derivative``
objects took 9 s for the linearity check alone, and Lagrange's ``d/dt dT/dq'`` 5 s; the same
work on plain symbols in symengine takes a few hundredths of a second.  Everything here works
on *plain* symbols (``q``, ``q_dot``, ``q_ddot``; see :func:`dualmech.model.equations.state_symbols`)
and returns sympy expressions whose symbols are the caller's own (symengine forgets sympy's
assumptions, so they are mapped back by name).
"""
from __future__ import annotations

import random
from functools import cache
from typing import Sequence

import symengine as se
import sympy as sp

__all__ = ["Bridge", "is_zero_held", "linear_coefficients", "total_derivative"]


class Bridge:
    """Converts sympy expressions to symengine and back, keeping each symbol's identity."""

    def __init__(self, exprs: Sequence = (), symbols: Sequence = ()):
        self.by_name: dict = {}
        self._symbols: dict = {}
        for s in symbols:
            self._add(s)
        for e in exprs:
            for s in sp.sympify(e, strict=True).free_symbols:
                self._add(s)

    def _add(self, s) -> None:
        old = self.by_name.get(s.name)
        if old is not None and old != s:
            raise ValueError(
                f"two different symbols are both called `{s.name}` ({old!r} with assumptions "
                f"{_assumptions(old)}, and one with {_assumptions(s)}); give them different "
                "names or the same assumptions.")
        self.by_name[s.name] = s

    def se(self, expr):
        if isinstance(expr, sp.Symbol) and self.by_name.get(expr.name) is expr:
            hit = self._symbols.get(expr)
            if hit is None:
                hit = self._symbols[expr] = se.Symbol(expr.name)
            return hit
        for s in sp.sympify(expr, strict=True).free_symbols:
            self._add(s)
        return se.sympify(expr)

    def sp(self, expr) -> sp.Expr:
        out = sp.sympify(expr, strict=True)
        rules = {}
        for s in out.free_symbols:
            mine = self.by_name.get(s.name)
            if mine is not None and mine is not s:
                rules[s] = mine
        return out.xreplace(rules) if rules else out


def _assumptions(s) -> str:
    kept = {k: v for k, v in s.assumptions0.items() if k in ("real", "positive", "integer",
                                                             "nonnegative", "complex")}
    return str(kept or "none")


def linear_coefficients(exprs: Sequence, unknowns: Sequence, bridge: Bridge | None = None):
    """``(A, b, bad)`` with ``exprs = A u - b`` for the plain symbols ``u = unknowns``.

    ``bad`` lists the unknowns in which some expression is not linear (then ``A`` and ``b``
    are meaningless).  ``A`` and ``b`` are sympy matrices.
    """
    bridge = bridge or Bridge(exprs, unknowns)
    us = [bridge.se(u) for u in unknowns]
    zero = {u: 0 for u in us}
    rows, rhs, bad = [], [], []
    for e in exprs:
        e = bridge.se(e)
        row = []
        for u in us:
            a = e.diff(u)
            if a != 0 and any(v in a.free_symbols for v in us):
                bad.append(u)
            row.append(a)
        rows.append(row)
        rhs.append(-e.subs(zero))
    bad_sp = [bridge.sp(u) for u in dict.fromkeys(bad)]
    A = sp.Matrix(len(rows), len(us), [bridge.sp(a) for row in rows for a in row])
    b = sp.Matrix(len(rhs), 1, [bridge.sp(x) for x in rhs])
    return A, b, bad_sp


def total_derivative(expr, states: Sequence, time, bridge: Bridge):
    """``d/dt`` of a symengine expression in plain state symbols ``(q, q', q'')`` and ``time``.

    ``states`` are :class:`dualmech.model.equations.StateSymbols`; ``q''`` must not appear in
    ``expr`` (the result is linear in the ``q''``).
    """
    out = expr.diff(bridge.se(time))
    present = expr.free_symbols
    for s in states:
        q, qd, qdd = bridge.se(s.q), bridge.se(s.qd), bridge.se(s.qdd)
        if q in present:
            out = out + expr.diff(q) * qd
        if qd in present:
            out = out + expr.diff(qd) * qdd
    return out


# -- expressions kept in symengine between the edges ------------------------------------------
@cache
def time_se():
    """symengine's time symbol (sympy's ``t`` converts to it); made on first use, so that
    importing the library does not load symengine (and numpy) before it is needed."""
    return se.Symbol("t")


def names_of(expr) -> dict:
    """``{name: symbol}`` and ``{name + "()": undefined function}`` of ``expr``'s atoms, to
    convert back (see :func:`to_sp`)."""
    expr = sp.sympify(expr, strict=True)
    if expr.is_Number:
        return {}
    out = {s.name: s for s in expr.free_symbols}
    for f in expr.atoms(sp.core.function.AppliedUndef):
        out[f.func.__name__ + "()"] = f.func
    return out


def merge_names(a: dict, b: dict) -> dict:
    """Union of two name tables; the same name for two different atoms is refused."""
    if not b or a is b:
        return a
    if not a:
        return b
    for k, v in b.items():
        old = a.get(k)
        if old is not None and old != v:
            raise ValueError(_clash(k, old, v))
    return {**a, **b}


def _clash(name, a, b) -> str:
    what = lambda s: _assumptions(s) if isinstance(s, sp.Symbol) else str(s)  # noqa: E731
    return (f"two different symbols are both called `{name}` (one with assumptions {what(a)}, "
            f"one with {what(b)}); give them different names or the same assumptions.")


def to_se(expr):
    """symengine form of a sympy expression (functions of ``t`` stay functions); text is
    refused (symengine would parse it)."""
    if isinstance(expr, (str, bytes, bytearray)):
        raise TypeError(f"expected a sympy expression, got the text {expr!r:.60}; text is "
                        "never parsed.")
    return se.sympify(expr)


def to_sp(expr, names: dict, memo: dict | None = None):
    """sympy form of a symengine expression, every atom mapped back to the caller's own.

    ``names`` maps a symbol's name to the caller's symbol and ``name + "()"`` to the caller's
    undefined function (see :func:`names_of`).  The tree is rebuilt node by node with the
    caller's atoms in place (shared subtrees once, through ``memo``), instead of converting
    and then substituting, which walks the result a second time.
    """
    return _Back(names, memo if memo is not None else {}).node(expr)


class _Back:
    def __init__(self, names: dict, memo: dict):
        self.names, self.memo = names, memo

    def node(self, e):
        hit = self.memo.get(e)
        if hit is not None:
            return hit
        if e.is_Symbol:
            out = self.names.get(e.name) or sp.Symbol(e.name)
        elif e.is_Integer:
            out = sp.Integer(int(e))
        elif e.is_Rational:
            p, q = e.get_num_den()
            out = sp.Rational(int(p), int(q))
        elif e.is_Add:
            out = sp.Add(*[self.node(a) for a in e.args])
        elif e.is_Mul:
            out = sp.Mul(*[self.node(a) for a in e.args])
        elif e.is_Pow:
            b, x = e.args
            out = sp.Pow(self.node(b), self.node(x))
        elif isinstance(e, se.FunctionSymbol):
            name = e.get_name()
            f = self.names.get(name + "()") or sp.Function(name)
            out = f(*[self.node(a) for a in e.args])
        elif e.is_Derivative:
            out = sp.Derivative(*[self.node(a) for a in e.args])
        else:
            f = _FUNCTIONS.get(type(e).__name__)
            if f is not None:
                out = f(*[self.node(a) for a in e.args])
            else:   # constants and anything rarer: symengine's own conversion, then fixed up
                out = _fix(sp.sympify(e), self.names)
        self.memo[e] = out
        return out


#: symengine's class name -> sympy's function, for the common ones (the rest convert by
#: symengine's own route)
_FUNCTIONS = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec,
              "csc": sp.csc, "asin": sp.asin, "acos": sp.acos, "atan": sp.atan,
              "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh, "log": sp.log,
              "Abs": sp.Abs, "sign": sp.sign}


def _fix(out, names: dict):
    if not names or out.is_Number:
        return out
    rules = {}
    for s in out.free_symbols:
        mine = names.get(s.name)
        if mine is not None and mine is not s:
            rules[s] = mine
    for f in out.atoms(sp.core.function.AppliedUndef):
        mine = names.get(f.func.__name__ + "()")
        if mine is not None and mine is not f.func:
            rules[f] = mine(*[a.xreplace(rules) for a in f.args])
    return out.xreplace(rules) if rules else out


def _product_of_atoms(x) -> bool:
    """Whether ``x`` is a product of powers of nonzero numbers, symbols, functions of ``t``
    and their derivatives: a form that multiplying out leaves as it is, so it is not zero."""
    if x.is_Number:
        return x != 0
    if x.is_Symbol or x.is_Derivative or isinstance(x, se.FunctionSymbol):
        return True
    if x.is_Mul:
        return all(_product_of_atoms(f) for f in x.args)
    if x.is_Pow:
        return _product_of_atoms(x.args[0])
    return False


def is_zero_held(x, seed: str = "zero test") -> bool:
    """Whether the symengine expression ``x`` is zero once multiplied out (``se.expand(x) ==
    0``), without expanding one that is clearly nonzero at a random rational point in
    100-bit arithmetic (expanding a large model's entries -- products of sums -- takes
    seconds).

    >>> x, y = se.symbols("x y")
    >>> is_zero_held((x + 1) * (x - 1) - x**2 + 1), is_zero_held((x + y)**2 - x**2)
    (True, False)
    """
    if x == 0:
        return True
    if _product_of_atoms(x):
        return False
    free = sorted(x.free_symbols, key=str)
    rnd = random.Random(seed)
    values = [rnd.randint(1, 997) / 1009 for _ in free]
    # every symbol a float: symengine evaluates as it builds; doubles first (clearly nonzero
    # there is nonzero), 100 bits where the doubles come close to zero
    for point, tiny in (({s: se.RealDouble(v) for s, v in zip(free, values)}, 1e-6),
                        ({s: se.RealMPFR(str(v), 100) for s, v in zip(free, values)}, 1e-15)):
        try:
            v = complex(x.xreplace(point) if free else x.n(100))
        except (RuntimeError, TypeError, ValueError, ZeroDivisionError):
            break
        if v == v and abs(v) != float("inf") and abs(v) > tiny:
            return False
    return se.expand(x) == 0


def is_zero_trig(expr, draws: int = 3) -> bool:
    """Is ``expr`` (symengine, plain symbols) identically zero?  A structural question (which
    bodies move together, where a body is pinned), decided the way the comparator decides:
    each ``sin(a)``, ``cos(a)`` becomes a rational point of the circle (``2u/(1+u^2)``,
    ``(1-u^2)/(1+u^2)``), then the rational function is evaluated exactly at random integers;
    a nonzero value is certain, zero at every draw leaves a chance below ``1e-50`` of a false
    "zero".  Whatever stays irrational counts as nonzero (the conservative answer).

    >>> a, b = se.symbols("a b")
    >>> is_zero_trig(se.sin(a)**2 * b + se.cos(a)**2 * b - b), is_zero_trig(se.sin(a) - a)
    (True, False)"""
    if expr == 0:
        return True
    if clearly_nonzero(expr):
        return False
    expr = se.expand(expr)
    if expr == 0:
        return True
    rules = {}
    for f in expr.atoms(se.sin, se.cos):
        u = se.Symbol("_u_" + str(f.args[0]))
        c, s = (1 - u**2) / (1 + u**2), 2 * u / (1 + u**2)
        rules[se.sin(f.args[0])], rules[se.cos(f.args[0])] = s, c
    expr = expr.xreplace(rules) if rules else expr
    rng = random.Random(0)
    for _ in range(draws):
        point = {x: se.Integer(rng.randrange(-2**60, 2**60)) for x in expr.free_symbols}
        try:
            value = se.expand(expr.xreplace(point))
        except (ZeroDivisionError, RuntimeError):
            return False
        if value != 0 or not value.is_Number:
            return False
    return True


def clearly_nonzero(expr) -> bool:
    """Whether ``expr`` is far from zero at a random point, in doubles and again in 100-bit
    arithmetic (1e-15 there cannot come from rounding an expression that is zero everywhere):
    the common answer of the structural questions, decided before anything is multiplied
    out.

    >>> a = se.Symbol("a")
    >>> clearly_nonzero(se.sin(a) + 2), clearly_nonzero(se.sin(a)**2 + se.cos(a)**2 - 1)
    (True, False)
    """
    rng = random.Random(1)
    free = list(expr.free_symbols)
    values = [rng.randint(300, 1700) / 1000 for _ in free]
    for make, tiny in ((se.RealDouble, 1e-6), (lambda v: se.RealMPFR(str(v), 100), 1e-15)):
        point = {x: make(v) for x, v in zip(free, values)}
        try:
            value = complex(expr.xreplace(point))
        except (RuntimeError, TypeError, ValueError, ZeroDivisionError):
            return False
        if not (value == value and abs(value) != float("inf") and abs(value) > tiny):
            return False
    return True
