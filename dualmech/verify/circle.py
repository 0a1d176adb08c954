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

from fractions import Fraction

__all__ = ["world_values"]


def _gmul(a, b):
    return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])


def _gpow(g, k: int):
    out, base = (1, 0), g
    while k:
        if k & 1:
            out = _gmul(out, base)
        k >>= 1
        if k:
            base = _gmul(base, base)
    return out


def world_values(args, us: dict) -> list[tuple]:
    """``[(sin, cos)]`` for circle arguments and ``[(exp,)]`` for growth ones, as Fractions.

    ``args`` are ``(kind, ((atom, multiple), ...), _)``; ``us`` maps an atom to its sampled
    ``u`` (circle) or ``w`` (growth).
    """
    unit: dict = {}
    powers: dict = {}
    out = []
    for kind, terms, _ in args:
        if kind == "circle":
            num, den = (1, 0), 1
            for i, k in terms:
                key = (i, k)
                hit = powers.get(key)
                if hit is None:
                    g, d = unit.get(i) or unit.setdefault(i, _unit(us[i]))
                    if k < 0:
                        g = (g[0], -g[1])
                    hit = powers[key] = (_gpow(g, abs(k)), d ** abs(k))
                num, den = _gmul(num, hit[0]), den * hit[1]
            out.append((Fraction(num[1], den), Fraction(num[0], den)))
        else:
            v = Fraction(1)
            for i, k in terms:
                v *= Fraction(us[i]) ** k
            out.append((v,))
    return out


def _unit(u) -> tuple:
    u = Fraction(u)
    p, q = u.numerator, u.denominator
    return (q * q - p * p, 2 * p * q), p * p + q * q
