"""Rigorous interval evaluation of sympy expressions at real points (``mpmath.iv``).

Where an expression leaves the exact world (inverse trigonometric functions, logarithms of
sums, roots other than square roots, ...), :mod:`dualmech.exact.form` evaluates it at random *real*
points drawn over each symbol's whole domain, in interval arithmetic: every value is an interval
that certainly holds the true value.  An interval that excludes zero proves a nonzero value; one
that contains zero is only consistent with zero.  Branch decisions (``sign``, ``Heaviside``,
``Piecewise`` conditions, the domain of ``sqrt``/``log``/``acos``) are taken only when the
interval decides them; otherwise the point is skipped (:class:`Ambiguous`).

Example
-------
>>> import random, sympy as sp
>>> x = sp.Symbol("x")
>>> prog = IntervalProgram([sp.acos(sp.cos(x)) - sp.Abs(x)])
>>> val = prog.evaluate({x: 2})[0]          # acos(cos 2) = 2: consistent with zero
>>> sign_of(val) is None
True
>>> sign_of(prog.evaluate({x: 4})[0])       # acos(cos 4) = 2*pi - 4 != 4: certainly negative
-1
"""
from __future__ import annotations

import math
import random
from fractions import Fraction
from typing import Sequence

import mpmath
import sympy as sp
from mpmath import iv

__all__ = ["Ambiguous", "Unsupported", "IntervalProgram", "sign_of", "to_interval", "domain_of",
           "real_sample", "set_precision", "DIGITS"]

#: Decimal digits of the interval arithmetic (``mpmath.iv`` is set to this on import).
DIGITS = 60


def set_precision(digits: int = DIGITS) -> None:
    """Work at ``digits`` decimal digits in ``mpmath.iv`` (a process-wide setting)."""
    iv.dps = digits


set_precision()


class Ambiguous(ValueError):
    """A sign or domain test could not be decided at this point; the point is skipped."""


class Unsupported(ValueError):
    """A sub-expression has no rigorous interval evaluation here."""

    def __init__(self, expr, why: str):
        self.expr, self.why = expr, why
        super().__init__(f"{expr}: {why}")


def to_interval(v):
    """An ``iv.mpf`` holding the number ``v`` (int, Fraction, float, mpf or interval)."""
    if isinstance(v, iv.mpf):
        return v
    if isinstance(v, bool):
        raise TypeError("a boolean is not a number")
    if isinstance(v, int):
        return iv.mpf(v)
    if isinstance(v, Fraction):
        return iv.mpf(v.numerator) / iv.mpf(v.denominator) if v.denominator != 1 \
            else iv.mpf(v.numerator)
    if isinstance(v, (float, mpmath.mpf)):
        return iv.mpf(v)
    if isinstance(v, sp.Rational):
        return iv.mpf(int(v.p)) / iv.mpf(int(v.q))
    if isinstance(v, sp.Float):
        return iv.mpf(mpmath.mpf(v._mpf_))
    raise TypeError(f"cannot evaluate a {type(v).__name__} in interval arithmetic")


def sign_of(x) -> int | None:
    """+1 / -1 when the interval certainly has that sign, 0 for the exact zero, else None."""
    lo, hi = x.a, x.b
    if lo > 0:
        return 1
    if hi < 0:
        return -1
    if lo == 0 and hi == 0:
        return 0
    return None


def _need_sign(x, what) -> int:
    s = sign_of(x)
    if s is None:
        raise Ambiguous(f"the sign of {what} is not decided at this point")
    return s


# -- domains and sampling -------------------------------------------------------------
def domain_of(symbol: sp.Symbol, declared: dict | None = None) -> tuple[float, float]:
    """The symbol's domain: declared ``(lo, hi)``, else from its assumptions (``t``: all reals)."""
    if declared and symbol in declared:
        lo, hi = declared[symbol]
        return float(lo), float(hi)
    if symbol.is_positive or symbol.is_nonnegative:
        return 0.0, math.inf
    if symbol.is_negative or symbol.is_nonpositive:
        return -math.inf, 0.0
    return -math.inf, math.inf


def _magnitude(rng: random.Random) -> float:
    # half the time a uniform spread over several periods of an angle, half a log-uniform
    # spread from the tiny to the huge
    return rng.uniform(0.0, 10.0) if rng.random() < 0.5 else 10.0 ** rng.uniform(-6.0, 6.0)


def real_sample(rng: random.Random, lo: float, hi: float) -> Fraction:
    """A random real in ``(lo, hi)`` (either end may be infinite), as an exact Fraction."""
    if math.isfinite(lo) and math.isfinite(hi):
        return Fraction(lo + (hi - lo) * rng.random())
    if math.isfinite(lo):
        return Fraction(lo + _magnitude(rng))
    if math.isfinite(hi):
        return Fraction(hi - _magnitude(rng))
    m = _magnitude(rng)
    return Fraction(m if rng.random() < 0.5 else -m)


# -- the evaluator -----------------------------------------------------------------------
def _ipow(base, e: sp.Expr, node):
    if e.is_Integer:
        n = int(e)
        if n < 0 and sign_of(base) in (None, 0):
            raise Ambiguous(f"{node}: division by a value that may be zero")
        return base ** n
    s = _need_sign(base, node.base)
    if s < 0:
        raise Ambiguous(f"{node}: negative base outside the real domain")
    if s == 0:
        if e.is_positive:
            return iv.mpf(0)
        raise Ambiguous(f"{node}: zero to a non-positive power")
    return None  # general exponent: exp(e * log(base)), evaluated by the caller


def _acos(x):
    _in_unit(x)
    return iv.atan2(iv.sqrt(_clip0(1 - x * x)), x)


def _asin(x):
    _in_unit(x)
    return iv.atan2(x, iv.sqrt(_clip0(1 - x * x)))


def _in_unit(x):
    if x.a < -1 or x.b > 1:
        raise Ambiguous("argument of acos/asin/atanh not certainly in [-1, 1]")


def _atanh(x):
    _in_unit(x)
    return iv.log(_positive(1 + x, "atanh") / _positive(1 - x, "atanh")) / 2


def _clip0(x):
    # 1 - x^2 with x certainly in [-1, 1] is >= 0; clip the rounding below 0
    return iv.mpf([max(x.a, 0), max(x.b, 0)])


def _positive(x, what):
    if x.a <= 0:
        raise Ambiguous(f"{what}: argument not certainly positive")
    return x


def _atan2(y, x):
    if x.a <= 0 and sign_of(y) is None:
        raise Ambiguous("atan2 near its branch cut")
    return iv.atan2(y, x)


def _acot(x):
    s = _need_sign(x, "the argument of acot")
    if s == 0:
        raise Ambiguous("acot at 0")
    # acot(x) = atan(1/x), in (-pi/2, pi/2)
    return iv.atan2(iv.mpf(1), x) if s > 0 else iv.atan2(iv.mpf(-1), -x)


def _hull_max(vals):
    return iv.mpf([max(v.a for v in vals), max(v.b for v in vals)])


def _hull_min(vals):
    return iv.mpf([min(v.a for v in vals), min(v.b for v in vals)])


def _floor(x):
    lo, hi = mpmath.floor(x.a), mpmath.floor(x.b)
    if lo != hi:
        raise Ambiguous("floor/ceiling across an integer")
    return iv.mpf(lo)


_UNARY = {
    sp.sin: iv.sin, sp.cos: iv.cos, sp.exp: iv.exp,
    sp.tan: lambda x: iv.sin(x) / iv.cos(x),
    sp.cot: lambda x: iv.cos(x) / iv.sin(x),
    sp.sec: lambda x: 1 / iv.cos(x), sp.csc: lambda x: 1 / iv.sin(x),
    sp.log: lambda x: iv.log(_positive(x, "log")),
    sp.atan: lambda x: iv.atan2(x, iv.mpf(1)),
    sp.acot: lambda x: _acot(x),
    sp.asin: _asin, sp.acos: _acos,
    sp.sinh: lambda x: (iv.exp(x) - iv.exp(-x)) / 2,
    sp.cosh: lambda x: (iv.exp(x) + iv.exp(-x)) / 2,
    sp.tanh: lambda x: 1 - 2 / (iv.exp(2 * x) + 1),
    sp.asinh: lambda x: iv.log(x + iv.sqrt(x * x + 1)) if x.a >= 0
    else -iv.log(-x + iv.sqrt(x * x + 1)),
    sp.acosh: lambda x: iv.log(x + iv.sqrt(_positive(x - 1, "acosh") * (x + 1))),
    sp.atanh: lambda x: _atanh(x),
    sp.Abs: abs, sp.floor: _floor, sp.ceiling: lambda x: -_floor(-x),
    sp.erf: iv.erf,
}


class IntervalProgram:
    """Expressions ready for interval evaluation; :meth:`evaluate` gives one interval each.

    Construction checks that every sub-expression is supported (:class:`Unsupported` names the
    first that is not).
    """

    def __init__(self, exprs: Sequence[sp.Expr]):
        self.exprs = [sp.sympify(e, strict=True) for e in exprs]
        seen: set = set()
        for e in self.exprs:
            self._check(e, seen)

    def _check(self, e, seen) -> None:
        if e in seen:
            return
        seen.add(e)
        if isinstance(e, (sp.Symbol, sp.Rational, sp.Float)) or e in (sp.pi, sp.E):
            return
        if isinstance(e, sp.Piecewise):
            for value, cond in e.args:
                self._check(value, seen)
                self._check(cond, seen)
            return
        if isinstance(e, (sp.Add, sp.Mul, sp.Pow, sp.Piecewise, sp.Max, sp.Min, sp.sign,
                          sp.Heaviside, sp.atan2, sp.logic.boolalg.Boolean)) or \
                type(e) in _UNARY:
            if isinstance(e, sp.Heaviside) and len(e.args) > 1 and not e.args[1].is_Rational:
                raise Unsupported(e, "Heaviside with a symbolic value at 0")
            for a in e.args:
                self._check(a, seen)
            return
        if e.has(sp.I):
            raise Unsupported(e, "complex values are not supported; write real and imaginary "
                                 "parts as separate real expressions")
        if isinstance(e, sp.core.function.AppliedUndef):
            raise Unsupported(e, "an undefined function has no value; substitute plain symbols "
                                 "or an explicit expression")
        if isinstance(e, sp.Derivative):
            raise Unsupported(e, "a derivative left unevaluated; write the states as symbols")
        raise Unsupported(e, f"`{type(e).__name__}` has no rigorous interval evaluation here")

    def evaluate(self, point: dict) -> list:
        """Intervals of the expressions at ``point`` (``{symbol: number}``).

        Raises :class:`Ambiguous` (a ``ValueError``) when a branch or domain test cannot be
        decided at this point, ``ZeroDivisionError`` on a certain division by zero.
        """
        memo: dict = {}
        return [self._ev(e, point, memo) for e in self.exprs]

    def _ev(self, e, point, memo):
        hit = memo.get(e)
        if hit is not None:
            return hit
        out = self._node(e, point, memo)
        memo[e] = out
        return out

    def _node(self, e, point, memo):
        ev = lambda a: self._ev(a, point, memo)  # noqa: E731
        if e.is_Symbol:
            if e not in point:
                raise KeyError(f"no value for {e}")
            return to_interval(point[e])
        if e.is_Rational or e.is_Float:
            return to_interval(e)
        if e is sp.pi:
            return +iv.pi
        if e is sp.E:
            return iv.exp(iv.mpf(1))
        if e.is_Add:
            total = iv.mpf(0)
            for a in e.args:
                total = total + ev(a)
            return total
        if e.is_Mul:
            prod = iv.mpf(1)
            for a in e.args:
                prod = prod * ev(a)
            return prod
        if e.is_Pow:
            base = ev(e.base)
            if e.exp == sp.S.Half:
                if _need_sign(base, e.base) < 0:
                    raise Ambiguous(f"{e}: square root of a negative number")
                return iv.sqrt(base)
            direct = _ipow(base, e.exp, e)
            if direct is not None:
                return direct
            return iv.exp(ev(e.exp) * iv.log(base))
        if isinstance(e, sp.sign):
            return iv.mpf(_need_sign(ev(e.args[0]), e.args[0]))
        if isinstance(e, sp.Heaviside):
            s = _need_sign(ev(e.args[0]), e.args[0])
            if s == 0:
                h0 = e.args[1] if len(e.args) > 1 else sp.S.Half
                return to_interval(h0)
            return iv.mpf(1 if s > 0 else 0)
        if isinstance(e, sp.Max):
            return _hull_max([ev(a) for a in e.args])
        if isinstance(e, sp.Min):
            return _hull_min([ev(a) for a in e.args])
        if isinstance(e, sp.atan2):
            return _atan2(ev(e.args[0]), ev(e.args[1]))
        if isinstance(e, sp.Piecewise):
            for value, cond in e.args:
                if self._truth(cond, point, memo):
                    return ev(value)
            raise Ambiguous(f"{e}: no branch applies at this point (outside its domain)")
        fn = _UNARY.get(type(e))
        if fn is not None:
            return fn(ev(e.args[0]))
        raise Unsupported(e, "no interval evaluation")

    def _truth(self, cond, point, memo) -> bool:
        """Three-valued truth of a condition, as a bool; undecided raises Ambiguous."""
        if cond is sp.true:
            return True
        if cond is sp.false:
            return False
        if isinstance(cond, sp.And):
            return all(self._truth(c, point, memo) for c in cond.args)
        if isinstance(cond, sp.Or):
            return any(self._truth(c, point, memo) for c in cond.args)
        if isinstance(cond, sp.Not):
            return not self._truth(cond.args[0], point, memo)
        if isinstance(cond, sp.core.relational.Relational):
            d = self._ev(cond.lhs - cond.rhs, point, memo)
            s = sign_of(d)
            if isinstance(cond, (sp.Eq, sp.Ne)):
                if s is None:
                    raise Ambiguous(f"{cond}: equality not decided at this point")
                return (s == 0) == isinstance(cond, sp.Eq)
            if s is None:
                raise Ambiguous(f"{cond}: not decided at this point")
            if isinstance(cond, sp.StrictGreaterThan):
                return s > 0
            if isinstance(cond, sp.GreaterThan):
                return s >= 0
            if isinstance(cond, sp.StrictLessThan):
                return s < 0
            return s <= 0
        raise Unsupported(cond, "condition not supported")
