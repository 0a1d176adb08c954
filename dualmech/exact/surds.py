"""Exact numbers with square roots: elements of a field ``Q(sqrt d_1, ..., sqrt d_k)``.

The exact evaluator (:mod:`dualmech.exact.form`) keeps a square root ``sqrt(X)`` of a rational
expression exact by evaluating ``X`` at the sampled rational point, ``d = X(point)``, and
computing with ``r = sqrt(d)`` as a formal symbol with ``r**2 = d``.  When no product of a
nonempty subset of the ``d_i`` is the square of a rational (checked by :func:`independent`),
the field has degree ``2**k`` and the products of distinct roots form a basis: a number is zero
exactly when every coordinate is zero, so ``== 0`` is an exact test.

Example
-------
>>> from fractions import Fraction
>>> r2, r3 = Surd.root(2), Surd.root(3)
>>> (r2 * r3) ** 2 == 6, (r2 + r3) * (r2 - r3) == -1
(True, True)
>>> 1 / (1 + r2) == r2 - 1
True
"""
from __future__ import annotations

from fractions import Fraction
from itertools import combinations
from math import isqrt

__all__ = ["Surd", "Quadratic", "independent", "is_square", "one_radicand"]

try:   # FLINT's exact rationals (a dependency): the fast field of one square root
    import flint
except ImportError:  # pragma: no cover - platforms without python-flint wheels
    flint = None

_Rational = (int, Fraction)


def is_square(q) -> bool:
    """Is the rational ``q`` the square of a rational?"""
    q = Fraction(q)
    if q < 0:
        return False
    n, d = q.numerator, q.denominator
    return isqrt(n) ** 2 == n and isqrt(d) ** 2 == d


def independent(radicands) -> bool:
    """True when no product of a nonempty subset of ``radicands`` is a rational square.

    Then ``sqrt`` of the radicands span a field of degree ``2**k`` and :class:`Surd` arithmetic
    over them is exact.  Costs ``2**k`` square tests (``k`` is small: a few roots).
    """
    ds = [Fraction(d) for d in radicands]
    if any(d == 0 for d in ds):
        return False
    for size in range(1, len(ds) + 1):
        for subset in combinations(ds, size):
            prod = Fraction(1)
            for d in subset:
                prod *= d
            if is_square(prod):
                return False
    return True


_CHECKED: dict = {}


def _check_union(radicands: frozenset) -> None:
    ok = _CHECKED.get(radicands)
    if ok is None:
        ok = _CHECKED[radicands] = independent(sorted(radicands))
        if len(_CHECKED) > 4096:
            _CHECKED.clear()
    if not ok:
        raise ValueError(f"square roots of {sorted(map(str, radicands))} are not independent "
                         "at this point (a product of them is a rational square)")


class Surd:
    """An element ``sum_S c_S prod_{d in S} sqrt(d)`` of a multi-quadratic field.

    ``terms`` maps a frozenset of radicands (Fractions) to a nonzero Fraction coefficient.
    Arithmetic with ints and Fractions is supported; elements over different radicands combine
    in the field they generate, provided those radicands are independent (else ``ValueError``).
    """

    __slots__ = ("terms",)

    def __init__(self, terms: dict):
        self.terms = {k: v for k, v in terms.items() if v != 0}

    @classmethod
    def root(cls, d) -> "Surd | Fraction":
        """``sqrt(d)`` for a rational ``d``: a Fraction when ``d`` is a square, else a Surd."""
        d = Fraction(d)
        if d == 0:
            return Fraction(0)
        if is_square(d):
            return Fraction(isqrt(d.numerator), isqrt(d.denominator))
        return cls({frozenset([d]): Fraction(1)})

    # -- structure ---------------------------------------------------------------------
    @property
    def radicands(self) -> frozenset:
        out: set = set()
        for key in self.terms:
            out |= key
        return frozenset(out)

    def rational(self):
        """The value as a Fraction when it has no irrational part, else ``None``."""
        if all(not k for k in self.terms):
            return self.terms.get(frozenset(), Fraction(0))
        return None

    def is_zero(self) -> bool:
        return not self.terms

    @staticmethod
    def _lift(x) -> "Surd":
        if isinstance(x, Surd):
            return x
        if isinstance(x, _Rational):
            return Surd({frozenset(): Fraction(x)})
        raise TypeError(f"cannot combine a {type(x).__name__} with an exact square root")

    @staticmethod
    def _down(s: "Surd"):
        r = s.rational()
        return s if r is None else r

    def _joined(self, other: "Surd") -> None:
        # every Surd's radicands were checked when it was made; a union is new only when
        # neither set holds the other
        a, b = self.radicands, other.radicands
        if not (a <= b or b <= a):
            _check_union(a | b)

    # -- arithmetic --------------------------------------------------------------------
    def __add__(self, other):
        try:
            o = self._lift(other)
        except TypeError:
            return NotImplemented
        self._joined(o)
        terms = dict(self.terms)
        for k, v in o.terms.items():
            terms[k] = terms.get(k, 0) + v
        return self._down(Surd(terms))

    __radd__ = __add__

    def __neg__(self):
        return Surd({k: -v for k, v in self.terms.items()})

    def __pos__(self):
        return self

    def __sub__(self, other):
        try:
            return self + (-self._lift(other))
        except TypeError:
            return NotImplemented

    def __rsub__(self, other):
        return (-self) + other

    def __mul__(self, other):
        try:
            o = self._lift(other)
        except TypeError:
            return NotImplemented
        self._joined(o)
        terms: dict = {}
        for ka, va in self.terms.items():
            for kb, vb in o.terms.items():
                coeff = va * vb
                for d in ka & kb:
                    coeff *= d
                key = ka ^ kb
                terms[key] = terms.get(key, 0) + coeff
        return self._down(Surd(terms))

    __rmul__ = __mul__

    def _conjugate(self, d) -> "Surd":
        return Surd({k: (-v if d in k else v) for k, v in self.terms.items()})

    def inverse(self):
        """``1/self`` by multiplying with conjugates until the denominator is rational."""
        if not self.terms:
            raise ZeroDivisionError("division by an exact zero (square-root field)")
        num: Surd | Fraction = Fraction(1)
        den: Surd | Fraction = self
        for d in sorted(self.radicands):
            if not isinstance(den, Surd):
                break
            c = den._conjugate(d)
            num = num * c
            den = den * c
        den = den.rational() if isinstance(den, Surd) else den
        if den == 0:
            raise ZeroDivisionError("division by an exact zero (square-root field)")
        return num * (1 / Fraction(den))

    def __truediv__(self, other):
        if isinstance(other, _Rational):
            if other == 0:
                raise ZeroDivisionError("division by zero")
            return self * (1 / Fraction(other))
        if isinstance(other, Surd):
            return self * other.inverse()
        return NotImplemented

    def __rtruediv__(self, other):
        if not isinstance(other, _Rational):
            return NotImplemented
        return self.inverse() * other

    def __pow__(self, n):
        if not isinstance(n, int):
            return NotImplemented
        base = self if n >= 0 else self.inverse()
        out: Surd | Fraction = Fraction(1)
        for _ in range(abs(n)):
            out = out * base
        return out

    # -- comparisons -------------------------------------------------------------------
    def __eq__(self, other):
        try:
            o = self._lift(other)
        except TypeError:
            return NotImplemented
        d = self - o
        return d.is_zero() if isinstance(d, Surd) else d == 0

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __bool__(self):
        return bool(self.terms)

    __hash__ = None  # mutable-looking numbers; never used as keys

    def __abs__(self) -> Fraction:
        """A size (sum of |coefficient| * sqrt|d| bounds), used only as a scale, not a value."""
        total = Fraction(0)
        for k, v in self.terms.items():
            bound = Fraction(1)
            for d in k:
                bound *= abs(d) + 1
            total += abs(v) * bound
        return total

    def __float__(self) -> float:
        total = 0.0
        for k, v in self.terms.items():
            term = float(v)
            for d in k:
                term *= float(abs(d)) ** 0.5 * (1 if d > 0 else float("nan"))
            total += term
        return total

    def __repr__(self) -> str:
        parts = []
        for k, v in sorted(self.terms.items(), key=lambda kv: sorted(kv[0])):
            roots = "*".join(f"sqrt({d})" for d in sorted(k))
            parts.append(f"{v}" + (f"*{roots}" if roots else ""))
        return "Surd(" + (" + ".join(parts) or "0") + ")"


def one_radicand(values):
    """The radicand ``d`` when ``values`` are rationals and :class:`Surd` s over ``sqrt(d)``
    alone, at least one of them a Surd, and FLINT is installed; else ``None``.

    >>> one_radicand([Fraction(1, 2), 3 + Surd.root(5)])
    Fraction(5, 1)
    >>> one_radicand([Surd.root(2), Surd.root(3)]) is None
    True
    """
    if flint is None:
        return None
    found = None
    for v in values:
        if type(v) is Fraction or type(v) is int:
            continue
        if type(v) is not Surd or len(v.terms) > 2:
            return None
        rad = v.radicands
        if len(rad) != 1:
            return None
        d, = rad
        if found is None:
            found = d
        elif d != found:
            return None
    return found


def _fmpq(v):
    if type(v) is int:
        return flint.fmpq(v)
    return flint.fmpq(v.numerator, v.denominator)


class Quadratic:
    """``a + b sqrt(d)`` with FLINT rationals ``a``, ``b``: the field ``Q(sqrt d)`` of one
    square root (the common case: a model with one root), in C-backed rationals instead of
    :class:`Surd`'s dictionaries of Fractions.  The same exact arithmetic: ``d`` is not a
    rational square (a Surd's radicand never is), so ``a + b sqrt(d)`` is zero exactly when
    ``a`` and ``b`` are.  Rational values stay plain ``fmpq`` beside it (their arithmetic is
    FLINT's own, in C); a Quadratic combines with them and with ints.  Used by the register
    programs and the exact row reduction on values :func:`one_radicand` accepts:
    :meth:`lift` brings a value in, :meth:`back` returns a Fraction or a Surd.

    >>> r = Surd.root(Fraction(5))
    >>> x = Quadratic.lift(1 + r, Fraction(5))
    >>> Quadratic.back(x * x, Fraction(5)) == (1 + r) * (1 + r)
    True
    >>> Quadratic.back(x / x, Fraction(5)), Quadratic.back(2 / x - x * 0, Fraction(5))
    (Fraction(1, 1), Surd(-1/2 + 1/2*sqrt(5)))
    """

    __slots__ = ("a", "b", "d")

    def __init__(self, a, b, d):
        self.a, self.b, self.d = a, b, d

    @staticmethod
    def lift(v, root, d=None):
        """``v`` (a rational or a Surd over ``sqrt(root)``): an ``fmpq``, or a Quadratic."""
        if type(v) is Fraction or type(v) is int:
            return _fmpq(v)
        d = _fmpq(root) if d is None else d
        return Quadratic(_fmpq(v.terms.get(frozenset(), 0)),
                         _fmpq(v.terms.get(frozenset([root]), 0)), d)

    @staticmethod
    def back(v, root):
        """A value of the field (an ``fmpq`` or a Quadratic) as a Fraction or a :class:`Surd`
        over ``sqrt(root)``."""
        if type(v) is not Quadratic:
            return Fraction(int(v.p), int(v.q))
        a = Fraction(int(v.a.p), int(v.a.q))
        if not v.b:
            return a
        return Surd({frozenset(): a, frozenset([root]): Fraction(int(v.b.p), int(v.b.q))})

    @staticmethod
    def size(v) -> int | None:
        """Bits of ``v`` when it is rational (an ``fmpq``, or a Quadratic with ``b = 0``), else
        ``None``."""
        if type(v) is Quadratic:
            if v.b:
                return None
            v = v.a
        return int(v.p).bit_length() + int(v.q).bit_length()

    def __add__(self, o):
        if type(o) is Quadratic:
            return Quadratic(self.a + o.a, self.b + o.b, self.d)
        return Quadratic(self.a + o, self.b, self.d)

    __radd__ = __add__

    def __sub__(self, o):
        if type(o) is Quadratic:
            return Quadratic(self.a - o.a, self.b - o.b, self.d)
        return Quadratic(self.a - o, self.b, self.d)

    def __rsub__(self, o):
        return Quadratic(o - self.a, -self.b, self.d)

    def __neg__(self):
        return Quadratic(-self.a, -self.b, self.d)

    def __mul__(self, o):
        if type(o) is not Quadratic:
            return Quadratic(self.a * o, self.b * o, self.d)
        a, b, c, e = self.a, self.b, o.a, o.b
        return Quadratic(a * c + self.d * b * e, a * e + b * c, self.d)

    __rmul__ = __mul__

    def inverse(self) -> "Quadratic":
        a, b = self.a, self.b
        n = a * a - self.d * b * b
        if not n:
            raise ZeroDivisionError("division by an exact zero (square-root field)")
        return Quadratic(a / n, -b / n, self.d)

    def __truediv__(self, o):
        if type(o) is Quadratic:
            return self * o.inverse()
        if not o:
            raise ZeroDivisionError("division by an exact zero (square-root field)")
        return Quadratic(self.a / o, self.b / o, self.d)

    def __rtruediv__(self, o):
        return self.inverse() * o

    def __pow__(self, n: int) -> "Quadratic":
        base = self if n >= 0 else self.inverse()
        out = None
        n = abs(n)
        while n:
            if n & 1:
                out = base if out is None else out * base
            n >>= 1
            if n:
                base = base * base
        return Quadratic(flint.fmpq(1), flint.fmpq(0), self.d) if out is None else out

    def __bool__(self) -> bool:
        return bool(self.a) or bool(self.b)

    def __eq__(self, o) -> bool:
        if type(o) is Quadratic:
            return self.a == o.a and self.b == o.b
        return not self.b and self.a == o

    __hash__ = None
