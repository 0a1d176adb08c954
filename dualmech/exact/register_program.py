"""Rational expressions compiled to a straight-line register program, for exact evaluation.

The exact verdict evaluates the same list of rational expressions (sums, products and integer
powers of symbols and rational constants) at a handful of points in exact arithmetic.
Compiling with ``sympy.lambdify(cse=True)`` cost most of a verdict on large models (an 8-link
chain: 20 of 25 s).  Here the symengine trees become a flat list of instructions, one per
distinct subtree (equal subtrees share a register), run by a small loop -- no source text is
generated or executed.  (symengine's ``cse`` found little more to share in derivations'
matrices and cost a second on a 20-link chain; exact values with rational inputs are
computed with FLINT's ``fmpq`` when python-flint is installed.)  Values may be ``Fraction``, ``int`` or any number type with ``+ * / **`` (the
exact square-root numbers of :mod:`dualmech.exact.surds`, intervals).

Example
-------
>>> import sympy as sp
>>> from fractions import Fraction
>>> x, y = sp.symbols("x y")
>>> run = compile_rational([x, y], [x**2 + x*y/3, 1/(x + y)])
>>> run(Fraction(1), Fraction(2))
[Fraction(5, 3), Fraction(1, 3)]
"""
from __future__ import annotations

from fractions import Fraction
from typing import Callable, Sequence

import symengine as se

from dualmech.exact.surds import Quadratic, one_radicand

try:   # FLINT's exact rationals, when installed (a dependency; Fraction is the fallback)
    import flint
except ImportError:  # pragma: no cover - platforms without python-flint wheels
    flint = None

__all__ = ["compile_rational", "NotRationalProgram"]

_ADD, _MUL, _POW, _INV_POW = range(4)


class NotRationalProgram(ValueError):
    """An expression that is not a rational function of the arguments."""


def compile_rational(args: Sequence, exprs: Sequence) -> Callable:
    """A function ``f(*values) -> list`` evaluating ``exprs`` (sympy or symengine) at
    ``args = values``.

    Raises :class:`NotRationalProgram` for anything but sums, products, integer powers,
    rational constants and the argument symbols.
    """
    try:
        se_args = [se.sympify(a) for a in args]
        converted = [se.sympify(e) for e in exprs]   # symengine input passes through as is
    except Exception as exc:  # noqa: BLE001 - conversion refusals are reported as such
        raise NotRationalProgram(f"cannot convert for compilation: {exc}") from None
    if len(set(se_args)) != len(se_args):   # two arguments symengine cannot tell apart
        raise NotRationalProgram("arguments that symengine does not distinguish")
    builder = _Builder(len(args))
    for i, s in enumerate(se_args):
        builder.regs[s] = i
    outputs = [builder.node(e) for e in converted]
    code, consts, nregs = builder.code, builder.consts, builder.count
    nargs = len(args)

    flint_consts = [(at, _fmpq(v)) for at, v in consts] if flint is not None else None

    def run(*values):
        if len(values) != nargs:
            raise TypeError(f"expected {nargs} values, got {len(values)}")
        rational = flint is not None and all(type(v) is Fraction or type(v) is int
                                             for v in values)
        root = None if rational or flint is None else one_radicand(values)
        if rational:   # FLINT's rationals: the same exact arithmetic, in C
            r = [_fmpq(v) for v in values] + [None] * (nregs - nargs)
            one, cs = flint.fmpq(1), flint_consts
        elif root is not None:   # one square root: FLINT rationals and surds.Quadratic
            d = _fmpq(root)
            r = [Quadratic.lift(v, root, d) for v in values] + [None] * (nregs - nargs)
            one, cs = flint.fmpq(1), flint_consts
        else:
            r = list(values) + [None] * (nregs - nargs)
            one, cs = Fraction(1), consts
        for at, v in cs:
            r[at] = v
        for op, at, a, b in code:
            if op == _ADD:
                acc = r[a[0]]
                for j in a[1:]:
                    acc = acc + r[j]
                r[at] = acc
            elif op == _MUL:
                acc = r[a[0]]
                for j in a[1:]:
                    acc = acc * r[j]
                r[at] = acc
            elif op == _POW:
                r[at] = r[a] ** b
            else:
                r[at] = one / (r[a] ** b)
        if rational:
            return [Fraction(int(r[i].p), int(r[i].q)) for i in outputs]
        if root is not None:
            return [Quadratic.back(r[i], root) for i in outputs]
        return [r[i] for i in outputs]

    return run


def _fmpq(v):
    if type(v) is int:
        return flint.fmpq(v)
    return flint.fmpq(v.numerator, v.denominator)


class _Builder:
    """Turns symengine trees into register instructions, sharing equal subtrees."""

    def __init__(self, nargs: int):
        self.count = nargs
        self.regs: dict = {}
        self.code: list = []
        self.consts: list = []

    def _new(self) -> int:
        self.count += 1
        return self.count - 1

    def node(self, e) -> int:
        hit = self.regs.get(e)
        if hit is not None:
            return hit
        if isinstance(e, se.Integer):
            at = self._new()
            self.consts.append((at, int(e)))
        elif isinstance(e, se.Rational):
            at = self._new()
            p, q = e.get_num_den()
            self.consts.append((at, Fraction(int(p), int(q))))
        elif isinstance(e, se.Add):
            parts = [self.node(x) for x in e.args]
            at = self._new()
            self.code.append((_ADD, at, parts, None))
        elif isinstance(e, se.Mul):
            parts = [self.node(x) for x in e.args]
            at = self._new()
            self.code.append((_MUL, at, parts, None))
        elif isinstance(e, se.Pow):
            base, exp = e.args
            if not isinstance(exp, se.Integer):
                raise NotRationalProgram(f"non-integer power {e}")
            k = int(exp)
            b = self.node(base)
            at = self._new()
            self.code.append((_POW, at, b, k) if k >= 0 else (_INV_POW, at, b, -k))
        else:
            raise NotRationalProgram(f"{type(e).__name__} {e} is not rational")
        self.regs[e] = at
        return at
