"""Values of the world's trigonometric and exponential arguments at a sampled point.

A circle atom ``a`` is sampled as a rational ``u = p/q``; ``exp(i a)`` is then the Gaussian
rational ``z = (q + i p)^2 / (p^2 + q^2)``, a point of the unit circle.  The argument
``k_1 a_1 + k_2 a_2 + ...`` has ``cos + i sin = prod z_j^(k_j)``: exact powers of Gaussian
integers by repeated squaring, so ``sin(1000 t)`` costs ten squarings, not an expansion.
A growth atom ``b`` is sampled as a positive rational ``w = exp(b)``; the argument's value is
``prod w_j^(k_j)``.

Example
-------
>>> from fractions import Fraction
>>> args = [("circle", ((0, 2),), None), ("circle", ((0, 1),), None)]
>>> (s2, c2), (s1, c1) = world_values(args, {0: Fraction(3)})
>>> s2 == 2 * s1 * c1 and c2 == c1**2 - s1**2 and s1**2 + c1**2 == 1
True
"""
from __future__ import annotations

import numbers
from fractions import Fraction

__all__ = ["world_values"]


class _Lowest:
    """A rational already in lowest terms; ``Fraction(_Lowest(n, d))`` copies it without a gcd
    (the documented conversion of a ``numbers.Rational``), which matters for the long numbers
    of large multiples."""

    __slots__ = ("numerator", "denominator")

    def __init__(self, n: int, d: int):
        self.numerator, self.denominator = n, d


numbers.Rational.register(_Lowest)


def _over(n: int, d: int, single: bool) -> Fraction:
    """``n/d`` for ``d > 0``.  For a single atom at an integer ``u`` only a power of 2 can divide
    both (an odd prime dividing ``1 + u^2`` splits in Z[i] into a prime dividing ``1 + iu`` and
    one dividing ``1 - iu``, and only one of them divides the numerator)."""
    if not single or n == 0:
        return Fraction(n, d)
    shift = min((n & -n).bit_length(), (d & -d).bit_length()) - 1
    return Fraction(_Lowest(n >> shift, d >> shift))


def _gmul(a, b):
    # three integer products (Karatsuba): the integers get long for large multiples
    ac, bd = a[0] * b[0], a[1] * b[1]
    return (ac - bd, (a[0] + a[1]) * (b[0] + b[1]) - ac - bd)


def _gsq(a):
    return ((a[0] + a[1]) * (a[0] - a[1]), 2 * a[0] * a[1])


class _Powers:
    """``g**k`` for one Gaussian integer, sharing the squarings ``g**(2**j)`` among exponents."""

    def __init__(self, g):
        self.squares = [g]

    def __call__(self, k: int):
        out = None
        j = 0
        while k:
            if j == len(self.squares):
                self.squares.append(_gsq(self.squares[-1]))
            if k & 1:
                out = self.squares[j] if out is None else _gmul(out, self.squares[j])
            k >>= 1
            j += 1
        return out if out is not None else (1, 0)


def world_values(args, us: dict) -> list[tuple]:
    """``[(sin, cos)]`` for circle arguments and ``[(exp,)]`` for growth ones, as Fractions.

    ``args`` are ``(kind, ((atom, multiple), ...), _)``; ``us`` maps an atom to its sampled
    ``u`` (circle) or ``w`` (growth).
    """
    unit: dict = {}     # atom -> (powers of g, norm of g)
    powers: dict = {}   # (atom, k) -> (g**|k| or its conjugate, norm**|k|)
    out = []
    for kind, terms, _ in args:
        if kind == "circle":
            num, den = (1, 0), 1
            single = len(terms) == 1 and Fraction(us[terms[0][0]]).denominator == 1
            for i, k in terms:
                key = (i, k)
                hit = powers.get(key)
                if hit is None:
                    pw, d = unit.get(i) or unit.setdefault(i, _unit(us[i]))
                    g = pw(abs(k))
                    if k < 0:
                        g = (g[0], -g[1])
                    hit = powers[key] = (g, d ** abs(k))
                num, den = _gmul(num, hit[0]), den * hit[1]
            out.append((_over(num[1], den, single), _over(num[0], den, single)))
        else:
            v = Fraction(1)
            for i, k in terms:
                v *= Fraction(us[i]) ** k
            out.append((v,))
    return out


def _unit(u) -> tuple:
    u = Fraction(u)
    p, q = u.numerator, u.denominator
    return _Powers((q * q - p * p, 2 * p * q)), p * p + q * q
