"""Square roots of rational constants and angles in twelfths of pi, as exact numbers.

A model with a push at 30 degrees holds ``sqrt(3)/2``; a student writes ``√3/2``, ``sqrt(12)/4``
or ``cos(pi/6)``.  Each is an element of the field ``Q(sqrt p_1, ..., sqrt p_k)`` over prime
radicands (:class:`~dualmech.exact.surds.Surd`): ``sqrt(12) = 2 sqrt(3)``, ``sqrt(6) = sqrt(2)
sqrt(3)``, so roots written differently combine in one field, where a number is zero exactly
when every coordinate is -- the grader's zero test stays exact (:mod:`.formula` evaluates
these values at its rational points).  Bounded: a constant over :data:`_ROOT_BITS` bits, a
cofactor not shown prime by trial division below 1000, or more than :data:`MAX_ROOTS`
primes in one formula is left to mpmath.

Example
-------
>>> from fractions import Fraction
>>> surd_constant(("rpow", ("c", Fraction(12)), Fraction(1, 2)))
Surd(2*sqrt(3))
>>> TURNS[2]      # (cos, sin) of pi/6
(Surd(1/2*sqrt(3)), Fraction(1, 2))
"""
from __future__ import annotations

import functools
from fractions import Fraction
from math import isqrt

from dualmech.exact.surds import Surd

__all__ = ["surd_constant", "MAX_ROOTS", "TURNS", "TURN_ROOTS"]


_SMALL_PRIMES = tuple(p for p in range(2, 1000) if all(p % q for q in range(2, int(p ** 0.5) + 1)))
_PRIME_BOUND = 1009 ** 2   # a cofactor below this with no prime factor under 1000 is prime


def _constant(tree) -> Fraction | None:
    """The value of a tree of numbers (``("c", ...)``, sums, products, integer powers), else
    None: what a square root of a constant is taken of (``sqrt(3)``, ``sqrt(1 + 1/3)``)."""
    op = tree[0]
    if op == "c":
        return tree[1]
    if op in ("add", "mul"):
        vals = [_constant(c) for c in tree[1]]
        if any(v is None for v in vals):
            return None
        out = Fraction(0) if op == "add" else Fraction(1)
        for v in vals:
            out = out + v if op == "add" else out * v
        return out
    if op == "pow":
        v = _constant(tree[1])
        return None if v is None or (v == 0 and tree[2] < 0) else v ** tree[2]
    return None


@functools.lru_cache(maxsize=256)
def _root(c: Fraction):
    """``sqrt(c)`` for a rational ``c > 0`` as a :class:`~dualmech.exact.surds.Surd` over
    prime radicands (``sqrt(12) = 2 sqrt(3)``, ``sqrt(6) = sqrt(2) sqrt(3)``), or a Fraction;
    None when ``c`` has a factor too large to tell squarefree by trial division (then only
    mpmath evaluates it).  Prime radicands are independent, so roots written differently by
    a student and a model combine in one field and ``== 0`` stays an exact test."""
    n = c.numerator * c.denominator          # sqrt(p/q) = sqrt(p q)/q
    square, primes = 1, []
    for p in _SMALL_PRIMES:
        if p * p > n:
            break
        k = 0
        while n % p == 0:
            n //= p
            k += 1
        square *= p ** (k // 2)
        if k % 2:
            primes.append(p)
    if n > 1:
        r = isqrt(n)
        if r * r == n:
            square *= r
        elif n < _PRIME_BOUND:
            primes.append(n)
        else:
            return None
    coeff = Fraction(square, c.denominator)
    return Surd({frozenset(Fraction(p) for p in primes): coeff}) if primes else coeff


def surd_constant(tree):
    """The exact value of ``("rpow", constant, k/2)`` -- a square root of a positive rational
    constant to an odd power, as ``sqrt(3)/2`` of a push at 30 degrees -- in the field
    ``Q(sqrt p_1, ..., sqrt p_k)`` (:class:`~dualmech.exact.surds.Surd`); None for any other
    fractional power (left to mpmath).

    >>> surd_constant(("rpow", ("c", Fraction(3, 4)), Fraction(1, 2)))
    Surd(1/2*sqrt(3))
    >>> surd_constant(("rpow", ("c", Fraction(12)), Fraction(-1, 2))) * 6
    Surd(1*sqrt(3))
    >>> surd_constant(("rpow", ("s", "x"), Fraction(1, 2))) is None
    True
    """
    if tree[0] != "rpow" or tree[2].denominator != 2:
        return None
    c = _constant(tree[1])
    if c is None or c <= 0 or max(c.numerator, c.denominator).bit_length() > _ROOT_BITS:
        return None
    root = _root(c)
    return None if root is None else root ** int(tree[2].numerator)


_ROOT_BITS = 200   # larger constants under a root are left to mpmath (trial division is cheap)
MAX_ROOTS = 4      # distinct primes under the roots of one formula evaluated exactly


def _twelfths() -> tuple:
    """``(cos, sin)`` of ``k pi/12``, ``k = 0..23``, exactly: ``cos(pi/12) = (sqrt 6 + sqrt 2)/4``
    over the prime radicands 2 and 3 (as :func:`surd_constant` writes every root)."""
    r2, r3 = Surd.root(2), Surd.root(3)
    step = ((r2 * r3 + r2) / 4, (r2 * r3 - r2) / 4)
    out = [(Fraction(1), Fraction(0))]
    for _ in range(23):
        c, s_ = out[-1]
        out.append((c * step[0] - s_ * step[1], c * step[1] + s_ * step[0]))
    return tuple(out)


TURNS = _twelfths()         #: (cos, sin) of k pi/12, k = 0..23
TURN_ROOTS = frozenset({Fraction(2), Fraction(3)})   #: the primes under them
