"""Exact evaluation of expressions at random rational points.

The equivalence test of DESIGN.md: evaluate both sides at random *rational* points in exact
arithmetic, with ``sin`` and ``cos`` of each angle taken at a rational point of the unit circle
``(c, s) = ((1 - u^2)/(1 + u^2), 2u/(1 + u^2))``.

Why that is sound.  After ``expand_trig``, every trigonometric argument is a monomial ``a``
(``theta``, ``omega*t``...).  Distinct monomials are linearly independent over Q, so by Ax's
theorem the functions ``a`` and ``exp(i a)`` satisfy no algebraic relation other than
``sin^2 + cos^2 = 1``: an identity in the original functions holds exactly when it holds in the
polynomial ring where each pair ``(sin a, cos a)`` is a point of the unit circle, independent of
every other variable (including ``a`` itself where it appears outside a trig function).  The
circle is parametrised rationally by ``u``, so a nonzero rational function of degree ``D``
vanishes at a random point drawn from a set of size ``N`` with probability at most ``D/N``
(Schwartz--Zippel).  A nonzero value is a certain counter-example.

Expressions that leave this world (square roots, exponentials, floats, ``sin(theta/2)`` beside
``sin(theta)``) are evaluated in high-precision floating point (mpmath) instead, and the result
says so.

Example
-------
>>> import sympy as sp
>>> th, w = sp.symbols("theta omega")
>>> ev = ExactForm.build([sp.sin(2*th) - 2*sp.sin(th)*sp.cos(th), sp.cos(th)**2 + w], [th, w])
>>> ev.method
'exact'
>>> import random
>>> vals = ev.evaluate(ev.sample(random.Random(1)))
>>> vals[0] == 0, vals[1] == 0
(True, False)
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from fractions import Fraction
from typing import Callable, Sequence

import mpmath
import sympy as sp
from ._expr import as_expr
from sympy.printing.pycode import PythonCodePrinter

__all__ = ["ExactForm", "NotRational", "SAMPLE_BITS", "MP_DIGITS"]

#: Integers for each variable are drawn uniformly from a set of 2**SAMPLE_BITS values.
SAMPLE_BITS = 62
#: Working precision (decimal digits) of the high-precision fallback.
MP_DIGITS = 60

_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


class NotRational(Exception):
    """The expression cannot be evaluated exactly at rational points."""


class _FractionPrinter(PythonCodePrinter):
    """Python code in which every rational constant is a ``Fraction``."""

    def _print_Rational(self, expr):
        return f"Fraction({expr.p}, {expr.q})"

    def _print_Half(self, expr):
        return "Fraction(1, 2)"

    def _print_Integer(self, expr):
        return str(expr.p)

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.args
        if exp.is_Integer:
            b = self.parenthesize(base, sp.printing.precedence.PRECEDENCE["Pow"])
            if exp < 0:
                return f"(Fraction(1) / ({b})**{-int(exp)})"
            return f"({b})**{int(exp)}"
        raise NotRational(f"non-integer power {expr}")

    def _print_Float(self, expr):
        raise NotRational(f"floating-point constant {expr}")


def _monomial(arg: sp.Expr) -> bool:
    """A product of symbols with positive integer powers (coefficient 1)."""
    for f in sp.Mul.make_args(arg):
        base, e = f.as_base_exp()
        if not (base.is_Symbol and e.is_Integer and e > 0):
            return False
    return True


def _trig_atoms(expr: sp.Expr) -> tuple[sp.Expr, dict]:
    """Expand trig functions until every argument is a monomial; map each to (s, c) symbols."""
    # tan etc. -> sin/cos; then expand multiple and compound angles
    expr = expr.rewrite(sp.cos, sp.sin) if expr.has(sp.sec, sp.csc, sp.cot) else expr
    expr = expr.replace(lambda e: isinstance(e, sp.tan), lambda e: sp.sin(e.args[0]) / sp.cos(e.args[0]))
    expr = expr.replace(lambda e: isinstance(e, (sp.sin, sp.cos)) and not _monomial(sp.expand(e.args[0])),
                        lambda e: _expand_one(e))
    atoms: dict = {}
    for f in expr.atoms(sp.sin, sp.cos):
        a = f.args[0]
        if not _monomial(a):
            raise NotRational(f"trigonometric argument {a} is not an integer combination of "
                              "monomials")
        if a not in atoms:
            name = str(a).replace("*", "_")
            atoms[a] = (sp.Dummy(f"s_{name}"), sp.Dummy(f"c_{name}"))
    rules = {}
    for a, (s, c) in atoms.items():
        rules[sp.sin(a)] = s
        rules[sp.cos(a)] = c
    return expr.xreplace(rules), atoms


def _expand_one(e):
    arg = sp.expand(e.args[0])
    terms = sp.Add.make_args(arg)
    for term in terms:
        coeff, mono = term.as_coeff_Mul()
        if not (coeff.is_Integer and _monomial(mono)):
            raise NotRational(f"trigonometric argument {e.args[0]} has a non-integer multiple "
                              f"{term}")
    return sp.expand_trig(type(e)(arg))


def _degree(expr, weights: dict, memo: dict | None = None) -> tuple[int, int]:
    """Bound on (numerator degree, denominator degree) of ``expr`` as a rational function.

    Works on the tree as it stands (no ``together``, which is slow on large input); shared
    subtrees are bounded once.
    """
    memo = {} if memo is None else memo
    hit = memo.get(expr)
    if hit is not None:
        return hit
    if expr.is_Number:
        out = (0, 0)
    elif expr.is_Symbol:
        out = weights.get(expr, (1, 0))
    elif expr.is_Add:
        parts = [_degree(a, weights, memo) for a in expr.args]
        den = sum(d for _, d in parts)
        out = (max(n + den - d for n, d in parts), den)
    elif expr.is_Mul:
        parts = [_degree(a, weights, memo) for a in expr.args]
        out = (sum(n for n, _ in parts), sum(d for _, d in parts))
    elif expr.is_Pow:
        n, d = _degree(expr.base, weights, memo)
        e = int(expr.exp)
        out = (n * e, d * e) if e >= 0 else (d * -e, n * -e)
    else:
        raise NotRational(f"cannot bound the degree of {expr}")
    memo[expr] = out
    return out


@dataclass
class ExactForm:
    """A list of expressions compiled for exact (or high-precision) evaluation.

    Use :meth:`build`; then :meth:`sample` draws a point and :meth:`evaluate` gives the values.
    ``method`` is ``"exact"`` or ``"mpmath"``; ``degree`` bounds the total degree of every
    expression as a rational function of the sampled integers (exact method only).
    """

    symbols: tuple
    method: str
    degree: int
    _fn: Callable
    _sampled: tuple  # what the sampler draws: symbols and the u of each trig atom
    _trig: dict      # atom -> (s, c)

    @classmethod
    def build(cls, exprs: Sequence, symbols: Sequence, force_mp: bool = False) -> "ExactForm":
        exprs = [as_expr(e) for e in exprs]
        symbols = tuple(symbols)
        free = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
        extra = free - set(symbols)
        if extra:
            raise ValueError(f"expressions use undeclared symbols {sorted(map(str, extra))}.")
        if not force_mp:
            try:
                return cls._build_exact(exprs, symbols)
            except NotRational:
                pass
        return cls._build_mp(exprs, symbols)

    @classmethod
    def _build_exact(cls, exprs, symbols):
        rewritten, atoms = [], {}
        for e in exprs:
            r, a = _trig_atoms(e)
            for k, v in a.items():
                if k in atoms:
                    r = r.xreplace({v[0]: atoms[k][0], v[1]: atoms[k][1]})
                else:
                    atoms[k] = v
            rewritten.append(r)
        for e in rewritten:
            bad = [f for f in e.atoms(sp.Function)]
            if bad:
                raise NotRational(f"function {bad[0]} is not rational")
        weights = {}
        for s, c in atoms.values():
            weights[s] = (1, 2)
            weights[c] = (2, 2)
        memo: dict = {}
        degree = max((sum(_degree(e, weights, memo)) for e in rewritten), default=0)
        trig_syms = [x for pair in atoms.values() for x in pair]
        args = list(symbols) + trig_syms
        printer = _FractionPrinter({"fully_qualified_modules": False, "inline": True})
        fn = sp.lambdify(args, rewritten, modules=[{"Fraction": Fraction}], printer=printer,
                         cse=True)
        sampled = tuple(symbols) + tuple(atoms)
        return cls(symbols, "exact", max(degree, 1), fn, sampled, dict(atoms))

    @classmethod
    def _build_mp(cls, exprs, symbols):
        fn = sp.lambdify(symbols, exprs, modules="mpmath", cse=True)
        return cls(symbols, "mpmath", 0, fn, tuple(symbols), {})

    # -- points ------------------------------------------------------------------------
    def sample(self, rng: random.Random, floats: dict | None = None) -> dict:
        """A random point: ``{symbol: value}`` (plus ``{atom: u}`` for each trig atom).

        Exact method: random integers (and a random rational ``u`` for each angle).  mpmath
        method: ``floats`` gives a real value (or a ``(low, high)`` range) per symbol.
        """
        if self.method == "exact":
            half = 1 << (SAMPLE_BITS - 1)
            return {s: Fraction(rng.randrange(-half, half)) for s in self._sampled}
        point = {}
        for s in self.symbols:
            lo, hi = (floats or {}).get(s, (-2.0, 2.0))
            point[s] = mpmath.mpf(rng.uniform(lo, hi))
        return point

    def evaluate(self, point: dict) -> list:
        """Values of the expressions at ``point`` (Fractions, or mpf for the fallback)."""
        if self.method == "exact":
            args = [point[s] for s in self.symbols]
            for atom in self._trig:
                u = point[atom]
                d = 1 + u * u
                args.append(2 * u / d)
                args.append((1 - u * u) / d)
            return list(self._fn(*args))
        with mpmath.workdps(MP_DIGITS):
            return list(self._fn(*[point[s] for s in self.symbols]))

    def false_equal_bound(self, points: int, extra_degree: int = 0) -> float:
        """Upper bound on the chance that a nonzero result vanished at ``points`` random points."""
        if self.method != "exact":
            return float("nan")
        p = min(1.0, (self.degree + extra_degree) / 2.0**SAMPLE_BITS)
        return p**points


def is_zero(value, scale=1) -> bool:
    """Exact zero test, or the mpmath tolerance ``10**(-MP_DIGITS/2)`` relative to ``scale``."""
    if isinstance(value, (Fraction, int)):
        return value == 0
    if isinstance(value, float):
        raise TypeError("a float reached an exact zero test; exact arithmetic was lost "
                        "(int / int?)")
    with mpmath.workdps(MP_DIGITS):
        return abs(value) <= mpmath.mpf(10) ** (-(MP_DIGITS // 2)) * (1 + abs(scale))


def as_float(value) -> float:
    return float(value)
