"""Rational functions on FLINT for display: cancel and ``sin^2 + cos^2 = 1`` in C.

:func:`tidy_rational` gives what :func:`dualmech.verify.display.tidy` gives -- the expression
as one reduced fraction, with ``sin(a)^2 + cos(a)^2 = 1`` applied whichever way makes it
shortest -- by polynomial arithmetic on ``python-flint``'s ``fmpz_mpoly`` (exact integer
multivariate polynomials, gcd in C) instead of sympy's ``cancel`` and ``factor_terms`` on
expression trees, which cost seconds on a double pendulum's reactions.  Every symbol, function
application and non-integer power of the input is one generator of the polynomial ring; the
result is the same rational function (display only: no verdict reads it).

Example
-------
>>> import sympy as sp
>>> x, m, g = sp.symbols("x m g")
>>> tidy_rational((m*g*sp.sin(x)**2 + m*g*sp.cos(x)**2) / (m*sp.cos(x)))
g/cos(x)
"""
from __future__ import annotations

import sympy as sp

from dualmech.model import trees

__all__ = ["tidy_rational", "solve_rational", "solve_rational_held", "NotRational"]

try:   # python-flint is a dependency; without it the caller keeps sympy's route
    import flint
except ImportError:  # pragma: no cover
    flint = None


class NotRational(ValueError):
    """The expression is not a rational function of its atoms (or flint is missing)."""


class _Ring:
    def __init__(self, atoms: list):
        self.atoms = atoms
        self.index = {a: i for i, a in enumerate(atoms)}
        self.ctx = flint.fmpz_mpoly_ctx.get(tuple(f"v{i}" for i in range(len(atoms))), "lex")
        self.gens = self.ctx.gens()
        self.one = self.ctx.from_dict({(0,) * len(atoms): 1})
        self.zero = self.one - self.one

    def fraction(self, e, index: dict | None = None):
        """``(numerator, denominator)`` polynomials of ``e``, a sympy or symengine
        expression whose atoms ``index`` maps to generator indices (by default the ring's
        own sympy atoms)."""
        index = self.index if index is None else index
        k = trees.kind(e)
        if k is trees.INTEGER or k is trees.RATIONAL:
            p, q = trees.ratio(e)
            return self.one * p, self.one * q
        i = index.get(e)
        if i is not None:
            return self.gens[i], self.one
        if k is trees.ADD:
            n, d = self.zero, self.one
            for a in e.args:
                an, ad = self.fraction(a, index)
                if ad == d:
                    n = n + an
                else:
                    g = d.gcd(ad)
                    n, d = n * (ad / g) + an * (d / g), d * (ad / g)
            return n, d
        if k is trees.MUL:
            n, d = self.one, self.one
            for a in e.args:
                an, ad = self.fraction(a, index)
                n, d = n * an, d * ad
            return n, d
        if k is trees.POW and trees.kind(e.args[1]) is trees.INTEGER:
            bn, bd = self.fraction(e.args[0], index)
            k = trees.ratio(e.args[1])[0]
            if k < 0:
                bn, bd, k = bd, bn, -k
            if bn.is_zero():
                raise ZeroDivisionError("a zero denominator")
            return bn ** k, bd ** k
        raise NotRational(f"not an atom of the ring: {e}")

    def expr(self, p) -> sp.Expr:
        terms = []
        for monom, coeff in zip(p.monoms(), p.coeffs()):
            factors = [sp.Integer(int(coeff))]
            factors += [self.atoms[i] ** k for i, k in enumerate(monom) if k]
            terms.append(sp.Mul(*factors))
        return sp.Add(*terms)


#: kinds that are atoms of the ring (a power is one unless its exponent is an integer)
_ATOMS = frozenset((trees.SYMBOL, trees.FUNCTION, trees.UNDEFINED, trees.DERIVATIVE,
                    trees.CONSTANT, trees.POW))


def _atoms(e, out: dict) -> None:
    """Collect in ``out`` the atoms of ``e`` (sympy or symengine): the symbols, constants,
    function applications, derivatives and non-integer powers it is a rational function of."""
    k = trees.kind(e)
    if k in trees.NUMBERS:
        if k is not trees.INTEGER and k is not trees.RATIONAL:
            raise NotRational(f"a float: {e}")
        return
    if k is trees.ADD or k is trees.MUL:
        for a in e.args:
            _atoms(a, out)
        return
    if k is trees.POW and trees.kind(e.args[1]) is trees.INTEGER:
        _atoms(e.args[0], out)
        return
    if k in _ATOMS:
        out.setdefault(e, None)
        return
    raise NotRational(f"cannot treat {type(e).__name__} as an atom")


def _reduce(n, d):
    g = n.gcd(d)
    if not g.is_one():
        n, d = n / g, d / g
    lead = d.leading_coefficient()
    if lead < 0:
        n, d = -n, -d
    return n, d


def _pythagoras(ring: _Ring, p, s: int, c: int):
    """``p`` with every ``gen_s ** k`` (k >= 2) written through ``1 - gen_c ** 2``."""
    out = ring.zero
    base = 1 - ring.gens[c] ** 2
    for monom, coeff in zip(p.monoms(), p.coeffs()):
        k = monom[s]
        rest = list(monom)
        rest[s] = k % 2
        term = ring.ctx.from_dict({tuple(rest): int(coeff)})
        out = out + (term * base ** (k // 2) if k >= 2 else term)
    return out


def _size(n, d) -> int:
    return len(n.monoms()) + len(d.monoms())


def tidy_rational(expr) -> sp.Expr:
    """``expr`` as one reduced fraction with ``sin^2 + cos^2 = 1`` applied, per angle,
    whichever way gives fewer terms; the numerator's and denominator's integer content and
    common monomial pulled out.  Raises :class:`NotRational` when ``expr`` is not a rational
    function of its atoms (or python-flint is missing)."""
    if flint is None:
        raise NotRational("python-flint is not installed")
    found: dict = {}
    _atoms(expr, found)
    atoms = sorted(found, key=sp.default_sort_key)
    if not atoms:
        return expr
    ring = _Ring(atoms)
    n, d = _reduce(*ring.fraction(expr))
    return _tidied(ring, n, d)


def _tidied(ring: _Ring, n, d) -> sp.Expr:
    """The reduced fraction ``n/d`` shown with ``sin^2 + cos^2 = 1`` applied per angle
    whichever way gives fewer terms (the tail of :func:`tidy_rational`)."""
    atoms = ring.atoms
    if n.is_zero():
        return sp.Integer(0)
    by_arg: dict = {}
    for i, a in enumerate(atoms):
        if isinstance(a, (sp.sin, sp.cos)):
            by_arg.setdefault(a.args[0], {})[type(a)] = i
    for pair in by_arg.values():
        if len(pair) != 2:
            continue
        s, c = pair[sp.sin], pair[sp.cos]
        best = (n, d)
        for a, b in ((s, c), (c, s)):
            cand = _reduce(_pythagoras(ring, n, a, b), _pythagoras(ring, d, a, b))
            if _size(*cand) < _size(*best):
                best = cand
        n, d = best
    return _display(ring, n) / _display(ring, d)


def solve_rational(rows: list, rhs: list, pivots: list) -> list:
    """The solution of ``rows x = rhs`` (sympy expressions, rational functions of their
    atoms), each component tidied as by :func:`tidy_rational`.

    Gaussian elimination on reduced fractions of ``fmpz_mpoly`` (every intermediate entry
    cancelled by a gcd in C, so nothing grows past the size of the answer); ``pivots[k]`` is
    the row (counted from the current order) brought to position ``k`` at step ``k``, chosen
    by the caller (:func:`dualmech.verify.display.solve_display` reads them off values at a
    real point, so that an entry zero on the motion is never one).  Raises
    :class:`NotRational` for anything else, ``ZeroDivisionError`` when a pivot is zero.

    >>> import sympy as sp
    >>> a, b, s, c = sp.symbols("a b s c")
    >>> solve_rational([[a, b], [0, a]], [a * b, a * s], [0, 1])
    [b*(a - s)/a, s]
    """
    if flint is None:
        raise NotRational("python-flint is not installed")
    rows = [[sp.sympify(x, strict=True) for x in row] for row in rows]
    rhs = [sp.sympify(x, strict=True) for x in rhs]
    found: dict = {}
    for e in [x for row in rows for x in row] + rhs:
        _atoms(e, found)
    atoms = sorted(found, key=sp.default_sort_key)
    ring = _Ring(atoms)
    M = [[_reduce(*ring.fraction(e)) for e in row] + [_reduce(*ring.fraction(r))]
         for row, r in zip(rows, rhs)]
    return _eliminate(ring, M, pivots)


def solve_rational_held(rows: list, rhs: list, pivots: list, to_sympy) -> list:
    """:func:`solve_rational` of symengine ``rows`` and ``rhs``: the same solution, with only
    the atoms (symbols, function applications, non-integer powers) converted to sympy by
    ``to_sympy`` -- not every entry's tree -- and the polynomials built from the symengine
    trees.  Raises :class:`NotRational` as :func:`solve_rational` does, and also when an atom
    does not stay one in sympy (then the caller converts the entries and asks
    :func:`solve_rational`)."""
    if flint is None:
        raise NotRational("python-flint is not installed")
    found: dict = {}
    for e in [x for row in rows for x in row] + list(rhs):
        _atoms(e, found)
    mine = {a: to_sympy(a) for a in found}
    theirs: dict = {}
    for a in mine.values():
        _atoms(a, theirs)
        if a not in theirs:      # an atom that sympy writes as a sum or a product
            raise NotRational(f"not an atom once in sympy: {a}")
    atoms = sorted(theirs, key=sp.default_sort_key)
    ring = _Ring(atoms)
    held = {a: ring.index[v] for a, v in mine.items()}
    M = [[_reduce(*ring.fraction(e, held)) for e in row]
         + [_reduce(*ring.fraction(r, held))] for row, r in zip(rows, rhs)]
    return _eliminate(ring, M, pivots)


def _eliminate(ring: _Ring, M: list, pivots: list) -> list:
    """Gaussian elimination of the augmented matrix ``M`` of reduced fractions (see
    :func:`solve_rational`), each component of the solution tidied."""
    n = len(M)

    def mul(x, y):
        return _reduce(x[0] * y[0], x[1] * y[1])

    def sub(x, y):
        if y[0].is_zero():
            return x
        g = x[1].gcd(y[1])
        return _reduce(x[0] * (y[1] / g) - y[0] * (x[1] / g), x[1] * (y[1] / g))

    for k in range(n):
        p = pivots[k]
        M[k], M[p] = M[p], M[k]
        head = M[k][k]
        if head[0].is_zero():
            raise ZeroDivisionError("a zero pivot")
        for r in range(k + 1, n):
            if M[r][k][0].is_zero():
                continue
            f = _reduce(M[r][k][0] * head[1], M[r][k][1] * head[0])
            for c in range(k + 1, n + 1):
                M[r][c] = sub(M[r][c], mul(f, M[k][c]))
    x = [None] * n
    for k in reversed(range(n)):
        acc = M[k][n]
        for c in range(k + 1, n):
            acc = sub(acc, mul(M[k][c], x[c]))
        x[k] = _reduce(acc[0] * M[k][k][1], acc[1] * M[k][k][0])
    return [_tidied(ring, *v) for v in x]


def _display(ring: _Ring, p) -> sp.Expr:
    """``content * monomial * (primitive rest)`` so that common factors show."""
    content, prim = p.primitive()
    if prim.leading_coefficient() < 0 and len(prim.monoms()) > 1:
        content, prim = -content, -prim
    mono = prim.term_content()
    rest = prim / mono
    return sp.Integer(int(content)) * ring.expr(mono) * ring.expr(rest)
