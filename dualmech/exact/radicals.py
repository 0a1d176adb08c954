"""Algebra on world expressions: the ``u`` forms, factoring, and square roots.

The world (:mod:`dualmech.exact.sample_space`) writes ``sin``/``cos`` of an argument as dummies; here
they become rational functions of each circle atom's ``u`` (``sin a = 2u/(1 + u^2)``...), where
sympy can factor.  Factoring serves two ends:

* a branch condition's sign is a constant times the signs of its odd-multiplicity irreducible
  factors (:func:`factor_signs`), so equal conditions written differently share their cases;
* a square root ``sqrt(c * Y^2 * f_1 * f_2 ...)`` (``f_i`` distinct irreducible) is real
  exactly where ``c * prod f_i >= 0``, and there equals ``|Y| sqrt|c| prod sqrt(|f_i|)``: a
  perfect square becomes ``|Y|`` (:func:`square_sqrt`), and roots whose radicands are
  multiplicatively dependent (``sqrt(2) sqrt(x^2 + 1)`` beside ``sqrt(2 x^2 + 2)``) are rewritten
  over independent ones with the signs ``|f_i| = +-f_i`` as branch cases
  (:func:`factored_sqrt`).

Before any factoring, radicands that are constant multiples of one another (the same root
written twice, expanded once and factored once, as two derivations of one model do) are
recognised from their values at random points -- the numbers, not the polynomials -- and
written over one root: ``sqrt(X_i) = sqrt(r) sqrt(X_j)`` for a rational ``r > 0`` is an
identity of principal roots wherever ``X_i = r X_j`` (:func:`proportional`).  That equality is
checked again, exactly, at every point the verdict uses (:attr:`World.twins`), so a value
there is the exact value of the expression as written, whatever the screening concluded.

Example
-------
>>> import sympy as sp
>>> from dualmech.exact.sample_space import analyse
>>> th = sp.Symbol("theta")
>>> w = analyse([sp.sqrt(1 - sp.sin(th)**2)], [th])        # |cos(theta)|: a branch, no root
>>> len(w.radicals), [str(label) for label in w.branches[0].labels]
(0, ['cos(theta) < 0', 'cos(theta) > 0'])
"""
from __future__ import annotations

import math
import random
from fractions import Fraction

import sympy as sp

from dualmech.exact.trig_values import world_values
from dualmech.exact.errors import NotExact, Undecidable
from dualmech.exact.surds import independent, is_square

__all__ = ["u_rule", "factor_signs", "square_screen", "square_sqrt", "factored_sqrt", "radicals_dependent",
           "const_root", "proportional"]

_MAX_MULTIPLE = 16   # larger multiples are not expanded into polynomials in u
_MAX_OPS = 400       # larger expressions are not factored


def u_rule(b, expr) -> dict | None:
    """World dummies of ``expr`` as rational functions of the atoms' ``u``/``w``, or ``None``
    when an angle's multiple is too large to expand."""
    rule = {}
    free = expr.free_symbols
    for n, (kind, terms, dummies) in enumerate(b.args):
        if not any(d in free for d in dummies):
            continue
        hit = b.u_cache.get(n)
        if hit is None:
            if kind == "circle" and sum(abs(k) for _, k in terms) > _MAX_MULTIPLE:
                return None
            hit = b.u_cache[n] = _u_form_of(b, kind, terms)
        rule.update(zip(dummies, hit))
    return rule


def _u_form_of(b, kind, terms) -> tuple:
    if kind != "circle":
        return (sp.Mul(*[b.u[i] ** k for i, k in terms]),)
    num, den = sp.S.One, sp.S.One
    for i, k in terms:
        u = b.u[i]
        num *= (1 + sp.I * u * (1 if k > 0 else -1)) ** (2 * abs(k))
        den *= (1 + u**2) ** abs(k)
    num = sp.expand(num)
    conj = num.subs(sp.I, -sp.I)
    return sp.expand((num - conj) / (2 * sp.I)) / den, sp.expand((num + conj) / 2) / den


def _u_fraction(b, expr):
    rule = u_rule(b, expr)
    if rule is None:
        return None
    X = sp.cancel(sp.together(expr.xreplace(rule)))
    return None if sp.count_ops(X) > _MAX_OPS else sp.fraction(X)


def _leading_negative(f) -> bool:
    """Is the leading coefficient of ``f`` negative (in a fixed order of its symbols)?"""
    gens = sorted(f.free_symbols, key=sp.default_sort_key)
    return sp.Poly(f, *gens).LC() < 0


def _factored(b, expr):
    """``(c, Y, odd_num, odd_den)``: ``expr = c * Y**2 * prod(odd_num) / prod(odd_den)`` with
    distinct irreducible factors of positive leading coefficient, or ``None``."""
    parts = _u_fraction(b, expr)
    if parts is None:
        return None
    c, Y, odd = sp.S.One, sp.S.One, ([], [])
    for side, (poly, power) in enumerate(zip(parts, (1, -1))):
        coeff, factors = sp.factor_list(poly)
        c *= coeff ** power
        for f, mult in factors:
            Y *= f ** ((mult // 2) * power)
            if mult % 2:
                if _leading_negative(f):
                    f, c = -f, -c
                odd[side].append(f)
    return c, Y, odd[0], odd[1]


def factor_signs(b, g):
    """``(sign constant, [odd-multiplicity irreducible factors])`` of a condition ``g``."""
    if g.is_number:
        return (1 if g > 0 else -1), []
    parts = _factored(b, g)
    if parts is None:
        return None
    c, _, num, den = parts
    return (1 if c > 0 else -1), num + den


# -- square roots ---------------------------------------------------------------------------
def _world_point(b, rng) -> dict:
    us = {i: Fraction(rng.randrange(-2**40, 2**40)) if a.kind == "circle"
          else Fraction(rng.randrange(1, 2**40)) for i, a in enumerate(b.atoms)}
    out = {}
    for (_, _, dummies), v in zip(b.args, world_values(b.args, us)):
        for d, x in zip(dummies, v):
            out[d] = sp.Rational(x.numerator, x.denominator)
    for i, x in us.items():
        out[b.u[i]] = sp.Rational(x.numerator, x.denominator)
    if b.pi is not None:
        out[b.pi] = sp.Integer(rng.randrange(-2**40, 2**40))
    for s in b.symbols:
        out[s] = sp.Integer(rng.randrange(-2**40, 2**40))
    return out


def _values(b, exprs, seed: int) -> list:
    """Values of world expressions at the random world point of ``seed`` (cached per builder:
    radicands are screened more than once)."""
    cache = b.value_cache
    point = cache.get(seed)
    if point is None:
        point = cache[seed] = _world_point(b, random.Random(seed))
    out = []
    for e in exprs:
        hit = cache.get((seed, e))
        if hit is None:
            v = e.xreplace(point)    # a sympy or (a held world's) symengine expression
            hit = cache[(seed, e)] = (Fraction(int(v.p), int(v.q))
                                      if getattr(v, "is_Rational", False) else False)
        out.append(hit if hit is not False else None)
    return out


_SCREEN_SEEDS = (3, 4, 5)


def proportional(b, radicands) -> list:
    """For each radicand, ``(j, r)``: it equals ``r`` times radicand ``j`` (``j`` its own index
    and ``r = 1`` when no earlier radicand is a positive constant multiple of it).

    Screened at three random world points: the ratio of the values must be one positive
    rational at each.  Only a screen -- the caller checks ``X_i = r X_j`` exactly at every point
    it evaluates (a false screen then leaves every point skipped, and the verdict refuses).

    >>> import sympy as sp
    >>> from dualmech.exact.sample_space import analyse
    >>> a, b = sp.symbols("a b")
    >>> w = analyse([sp.sqrt(a**2 + b**2) - 2 * sp.sqrt((a**2 + b**2) / 4)], [a, b])
    >>> len(w.radicals), len(w.twins)
    (1, 1)
    """
    columns = [_values(b, radicands, seed) for seed in _SCREEN_SEEDS]
    seen: dict = {}
    out = []
    for i in range(len(radicands)):
        vals = [col[i] for col in columns]
        if any(v is None or v == 0 for v in vals):
            out.append((i, Fraction(1)))
            continue
        shape = tuple(v / vals[0] for v in vals[1:])   # equal for proportional radicands
        for j in seen.get(shape, ()):
            r = vals[0] / columns[0][j]
            if r > 0:
                out.append((j, r))
                break
        else:
            seen.setdefault(shape, []).append(i)
            out.append((i, Fraction(1)))
    return out


def radicals_dependent(b, radicands) -> bool:
    """Is some product of the radicands a square at two random world points (so, almost
    surely, identically)?"""
    for seed in (3, 4):
        vals = _values(b, radicands, seed)
        if any(v is None for v in vals):
            return False
        if independent([v for v in vals if v != 0 and not is_square(v)]):
            return False
    return True


def square_screen(b, radicand) -> bool:
    """Is ``radicand`` a perfect square at two random world points (so, almost surely, a square
    up to a square-free rest)?"""
    if not radicand.free_symbols:
        return False
    for seed in (1, 2):
        (v,) = _values(b, [radicand], seed)
        if v is None or not is_square(v):
            return False
    return True


def square_sqrt(b, node, radicand):
    """``sqrt`` of a radicand that is a perfect square up to a square-free rest (screened at two
    random points): ``|Y| * sqrt(c * rest)``; ``None`` when it is not."""
    if not square_screen(b, radicand):
        return None
    parts = _factored(b, radicand)
    if parts is None:
        raise NotExact(node, "a square root too large to factor")
    c, Y, num, den = parts
    rest = sp.Mul(*num) / sp.Mul(*den)
    if rest == 1 and c < 0:
        raise Undecidable(node, "the square root of a negative square is imaginary wherever "
                                "it is defined")
    abs_y = b._abs_branch(sp.Abs(Y), Y, b._real_form(Y)) if Y.free_symbols else abs(Y)
    if rest == 1:
        return const_root(b, c) * abs_y
    return abs_y * b._radical_dummy(c * rest)


def const_root(b, c):
    """``sqrt(c)`` for a rational ``c > 0``: rational, or a rational times a radical dummy."""
    root = sp.sqrt(sp.Rational(c))
    coeff, rest = root.as_coeff_Mul()
    if rest == 1:
        return coeff
    return coeff * b._radical_dummy(rest**2)


def factored_sqrt(b, node, radicand):
    """``sqrt(radicand)`` over roots of irreducible factors, the sign of each factor a case.

    Where ``radicand = c Y^2 prod f_i / prod g_j < 0`` the root is not real: those cases are
    outside the domain (the pick gives ``None``).
    """
    parts = _factored(b, radicand)
    if parts is None:
        raise NotExact(node, "square roots whose product is a perfect square, too large to "
                             "factor (write them with one root)")
    c, Y, num, den = parts
    out = const_root(b, abs(c))
    if Y.free_symbols:
        out *= b._abs_branch(sp.Abs(Y), Y, b._real_form(Y))
    else:
        out *= abs(Y)
    signs = []
    for f, power in [(f, 1) for f in num] + [(g, -1) for g in den]:
        j, o = b._atomic(f, b._real_form(f), f)
        signs.append((j, o))
        label = b._real_form(f)
        # |f| = sign(f) * f: the sign is a case (one per factor), the root's radicand uses it
        sign = b.rule.get(_SignOf(f))
        if sign is None:
            sign = b._add_branch(_SignOf(f), [sp.S.One, -sp.S.One],
                                 lambda s, j=j, o=o: 0 if s[j] * o > 0 else 1,
                                 [_label(label, "> 0"), _label(label, "< 0")])
        out *= b._radical_dummy(sign * f) ** power
    sign_c = 1 if c > 0 else -1
    if signs:
        b._add_branch(sp.Function("real_domain")(radicand), [sp.S.One],
                      lambda s: 0 if sign_c * math.prod(s[j] * o for j, o in signs) > 0
                      else None, [_label(radicand, ">= 0")])
    elif c < 0:
        raise Undecidable(node, "the square root of a negative constant")
    return out


class _SignOf(sp.Function):
    """Marker node: the sign of an irreducible factor under a square root."""


def _label(expr, relation):
    from dualmech.exact.sample_space import _Label
    return _Label(expr, relation)
