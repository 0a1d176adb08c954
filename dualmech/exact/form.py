"""Deciding identities fast and soundly: exact evaluation at random rational points.

The equivalence test of DESIGN.md.  :meth:`ExactForm.build` compiles a list of expressions;
:meth:`~ExactForm.sample` draws a random point, :meth:`~ExactForm.evaluate` gives the values.
A caller decides an identity by evaluating at a few points (and doing exact linear algebra on the
values, :mod:`dualmech.exact.linalg`); :func:`is_zero` is the zero test.  Three methods:

``"exact"`` (:data:`METHOD_NAMES`).  The expressions are rewritten as rational functions of
*world variables* (:mod:`dualmech.exact.sample_space`): the symbols, ``pi``, for each *circle atom*
``a`` (a Laurent monomial in the symbols over an integer: ``theta``, ``omega*t``, ``t/tau``,
``theta/2``) the point ``exp(i a)`` of the unit circle, for each *growth atom* ``b`` the value
``exp(b)``.  Why that is sound: distinct Laurent monomials are linearly independent, so no
nonzero integer combination of the atoms is constant, and by Ax's theorem (the functional
Schanuel statement; for exponentials of rational functions already the Kolchin--Ostrowski
theorem as Rosenlicht states it) the functions ``exp(i a_j)``, ``exp(b_k)`` are algebraically
independent over the rational functions of the symbols.  ``pi`` is transcendental, so a
polynomial in it vanishes only when every coefficient does; constants inside ``sin``/``exp``
(``sin(1)``, ``E``) are atoms too, by Lindemann--Weierstrass, but not beside ``pi`` (whether
``pi`` and ``e`` are independent is unknown: interval fallback).  Hence an identity holds exactly
when it holds in the ring where every world variable is an independent indeterminate: each
symbol and ``pi`` is sampled as a random integer, each circle atom as a rational point
``((1 - u^2), 2u)/(1 + u^2)`` at a random integer ``u``, each growth atom as a random positive
integer; ``sin``/``cos`` of ``k_1 a_1 + ...`` are exact powers of Gaussian rationals
(:mod:`dualmech.exact.trig_values`), so ``sin(1000 t)`` costs ten squarings.  Float constants are
taken at their exact binary value.  A nonzero rational function of total degree ``D`` in the
sampled integers vanishes at a random point (each integer uniform over ``2**SAMPLE_BITS``
values) with probability at most ``D / 2**SAMPLE_BITS`` (Schwartz--Zippel), so ``k`` zero points
leave a chance of a false "equal" at most ``(D / 2**SAMPLE_BITS)**k``
(:meth:`~ExactForm.false_equal_bound`); a nonzero value is a certain counter-example.

*Square roots* ``sqrt(X)`` of rational world expressions stay exact: at the point,
``d = X(point)`` and ``sqrt(d)`` is a formal root with ``r**2 = d``
(:mod:`dualmech.exact.surds`).  When the radicands are multiplicatively independent modulo
squares (checked at every point, which is skipped otherwise), ``Q(x)(sqrt X_1, ...)`` has degree
``2**m`` over the rational functions and the evaluation is a field homomorphism: a nonzero
value is a certain counter-example, and a zero value makes the *norm* (a rational function of
degree at most ``2**m`` times the weighted degree) vanish, which the bound covers.  Radicands
are factored where needed (:mod:`dualmech.exact.radicals`): ``sqrt(c Y^2 f_1 f_2 ...)`` is real
where ``c f_1 f_2 ... >= 0`` and there equals ``|Y| sqrt|c| sqrt|f_1| sqrt|f_2| ...``; a perfect
square becomes ``|Y|`` (``sqrt(1 - sin^2) = |cos|``), and radicands that are dependent
(``sqrt(2) sqrt(x^2 + 1)`` beside ``sqrt(2 x^2 + 2)``) are rewritten over roots of their
irreducible factors, the factors' signs being branch cases.

*Branch functions* (``Abs``, ``sign``, ``Heaviside``, ``Max``, ``Min``, ``Piecewise``, and the
``|Y|`` above) with rational conditions are split into *cases*
(:mod:`dualmech.exact.branches`): on each region of fixed condition signs the expression is one
rational piece, and two expressions agree almost everywhere exactly when their pieces agree
on every region with interior points in the *domain* -- each symbol's natural domain (from its
assumptions; ``t`` any real) or a domain a problem declares (``domains``).  Regions are
witnessed by real points in interval arithmetic or proved empty by interval bisection; each
remaining case is tested exactly.  Points cycle through the cases (:attr:`ExactForm.cases`).  A
difference in a witnessed case is certain; one in a case neither witnessed nor excluded is not
(:meth:`ExactForm.certain` says so; the caller must then refuse, not report a difference).

``"interval"``.  What leaves the exact world (inverse trigonometric functions, logarithms,
other roots, symbolic exponents, ``pi`` beside ``E``...) is evaluated at random *real* points over
each symbol's whole domain (never the working ranges) in rigorous interval arithmetic at
``MP_DIGITS`` digits (:mod:`dualmech.exact.interval`).  A value whose interval excludes 0 is a
certain difference; "equal" means every interval contained 0 -- evidence, not a proof.

``"mpmath"`` (``force_mp=True``): plain high-precision floats inside the given working ranges,
for display (values at a physical state); never for a verdict.

What none of these can decide (undefined functions, complex values, integer symbols inside
transcendental functions, contradictory assumptions) raises :class:`Undecidable`, which names
the sub-expression and why.

Example
-------
>>> import random, sympy as sp
>>> th, w = sp.symbols("theta omega")
>>> ev = ExactForm.build([sp.sin(2*th) - 2*sp.sin(th)*sp.cos(th), sp.cos(th)**2 + w], [th, w])
>>> ev.method
'exact'
>>> vals = ev.evaluate(ev.sample(random.Random(1)))
>>> vals[0] == 0, vals[1] == 0
(True, False)
>>> ev = ExactForm.build([sp.Abs(sp.cos(th)) - sp.cos(th)], [th])
>>> len(ev.cases), any(ev.evaluate(ev.sample(random.Random(1)))[0] != 0 for _ in range(2))
(2, True)
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Sequence

import mpmath
import symengine as se
import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from dualmech.model._algebra import to_sp
from dualmech.model._expr import as_expr
from dualmech.exact import interval as _iv
from dualmech.exact.branches import Case, find_cases, regions
from dualmech.exact.trig_values import world_values
from dualmech.exact.surds import Surd, independent, is_square
from dualmech.exact.mp_program import flat_program
from dualmech.exact.register_program import NotRationalProgram, compile_rational
from dualmech.exact.sample_space import (AtomKey, NotExact, Undecidable, World, analyse,
                                         analyse_se, degree_bound)

__all__ = ["ExactForm", "Undecidable", "NotRational", "METHOD_NAMES", "CASE", "AtomKey",
           "SAMPLE_BITS", "MP_DIGITS", "is_zero"]

#: Integers for each variable are drawn uniformly from a set of 2**SAMPLE_BITS values.
SAMPLE_BITS = 62
#: Working precision (decimal digits) of the interval and high-precision methods.
MP_DIGITS = _iv.DIGITS

#: What each ``ExactForm.method`` means, for reports.
METHOD_NAMES = {
    "exact": "exact rational-point test",
    "interval": "rigorous interval arithmetic at real points over the whole domain "
                "(evidence, not proof)",
    "mpmath": "high-precision floats in the working ranges (display only)",
}

NotRational = NotExact  # former name


class _CaseKey:
    """Key of the branch case in a sampled point (no symbols: shared like a parameter)."""

    free_symbols: frozenset = frozenset()

    def __repr__(self) -> str:
        return "CASE"


#: Key under which a sampled point records its branch case (an index into ``form.cases``).
CASE = _CaseKey()


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
        raise NotExact(expr, "non-integer power")

    def _print_Float(self, expr):
        raise NotExact(expr, "floating-point constant")


def _compile(args, exprs):
    """A function of ``args`` returning the values of ``exprs`` in exact arithmetic: a register
    program after symengine's common-subexpression elimination (:mod:`.verify.program`), or
    lambdify with Fraction constants for what that does not cover."""
    try:
        return compile_rational(args, exprs)
    except NotRationalProgram:
        printer = _FractionPrinter({"fully_qualified_modules": False, "inline": True})
        return sp.lambdify(args, exprs, modules=[{"Fraction": Fraction}], printer=printer,
                           cse=True, dummify=True)


@dataclass
class ExactForm:
    """A list of expressions compiled for deciding identities (see the module docstring).

    Attributes: ``method`` (a key of :data:`METHOD_NAMES`), ``degree`` (total-degree bound of
    every expression in the sampled integers, exact method), ``cases`` (branch cases the points
    cycle through; one when there are no branches), ``notes`` (what was unified or why the
    exact method did not apply).
    """

    symbols: tuple
    method: str
    degree: int = 0
    cases: list = field(default_factory=lambda: [Case((), (), "witnessed")])
    notes: list = field(default_factory=list)
    _read: dict = field(default_factory=dict, repr=False)      # canonical -> keys to read
    _world: World | None = field(default=None, repr=False)
    _fn: Callable | None = field(default=None, repr=False)
    _radicands: Callable | None = field(default=None, repr=False)
    _twins: Callable | None = field(default=None, repr=False)
    _choices: list = field(default_factory=list, repr=False)
    _program: object = field(default=None, repr=False)
    _domains: dict = field(default_factory=dict, repr=False)
    _regions: list = field(default_factory=list, repr=False)   # interval method: boxes
    _counter: int = field(default=0, repr=False)

    # -- building ----------------------------------------------------------------------------
    @classmethod
    def build(cls, exprs: Sequence, symbols: Sequence, force_mp: bool = False,
              domains: dict | None = None) -> "ExactForm":
        """Compile ``exprs`` in ``symbols``; ``domains`` maps symbols to a declared ``(lo, hi)``.

        Raises ``ValueError`` for undeclared symbols and :class:`Undecidable` for what cannot
        be decided soundly.
        """
        symbols = tuple(symbols)
        if exprs and not force_mp and all(isinstance(e, se.Basic) for e in exprs):
            world = analyse_se(exprs, symbols)
            if world is not None:   # the common case, built in symengine
                doms = {s: (float(r[0]), float(r[1])) for s, r in (domains or {}).items()}
                return cls._from_world(world, dict(symbols=symbols,
                                                   _read={s: [s] for s in symbols},
                                                   notes=[], _domains=doms))
        names = {s.name: s for s in symbols}
        exprs = [to_sp(e, names) if isinstance(e, se.Basic) else as_expr(e) for e in exprs]
        exprs, canon, read, notes = _unify(exprs, symbols)
        floats = set().union(*(e.atoms(sp.Float) for e in exprs)) if exprs else set()
        if floats:
            exact = {f: sp.Rational(f) for f in floats}
            exprs = [e.xreplace(exact) for e in exprs]
        doms = {}
        for s, rng in (domains or {}).items():
            doms[canon.get(s, s)] = (float(rng[0]), float(rng[1]))
        base = dict(symbols=symbols, _read=read, notes=notes, _domains=doms)
        if force_mp:
            return cls._build_mp(exprs, base)
        try:
            return cls._build_exact(exprs, base)
        except NotExact as exc:
            why = f"exact test not applicable: `{exc.expr}`: {exc.why}"
        except (sp.PolynomialError, sp.polys.polyerrors.CoercionFailed, RecursionError) as exc:
            why = f"exact test not applicable: {type(exc).__name__}: {exc}"
        try:
            program = _iv.IntervalProgram(exprs)
        except _iv.Unsupported as exc:
            raise Undecidable(exc.expr, exc.why) from None
        boxes = regions(_conditions(exprs), doms)
        return cls(method="interval", _program=program, _regions=boxes,
                   **{**base, "notes": notes + [why]})

    @classmethod
    def _build_exact(cls, exprs, base) -> "ExactForm":
        return cls._from_world(analyse(exprs, list(base["_read"])), base)

    @classmethod
    def _from_world(cls, world, base) -> "ExactForm":
        cases = find_cases(world, base["_domains"])
        args = _world_args(world)
        fn = _compile(args, world.exprs)
        radicands = _compile(args, [r for _, r in world.radicals]) if world.radicals else None
        # sqrt(X) written sqrt(r) sqrt(X_j): X - r X_j must vanish at every point used
        twins = _compile(args, [x - (se if isinstance(x, se.Basic) else sp).Rational(
            r.numerator, r.denominator) * xj for x, r, xj in world.twins]) \
            if world.twins else None
        choices = [[_compile(args, c) for c in b.choices] for b in world.branches]
        form = cls(method="exact", cases=cases, _world=world, _fn=fn, _radicands=radicands,
                   _twins=twins, _choices=choices, **base)
        form.degree = _degree(world)
        if world.radicals:
            form._check_radicals()
        return form

    @classmethod
    def _build_mp(cls, exprs, base) -> "ExactForm":
        syms = list(base["_read"])
        try:
            fn = sp.lambdify(syms, exprs, modules="mpmath", cse=True, dummify=True)
        except RecursionError:     # source too deep for CPython's compiler: a flat program
            fn = flat_program(syms, exprs)
        except (SyntaxError, NameError) as exc:  # pragma: no cover - lambdify's own limits
            raise Undecidable(exprs, f"cannot compile for mpmath: {exc}") from None
        return cls(method="mpmath", _fn=fn, **base)

    def _check_radicals(self) -> None:
        """Radicands dependent at every one of a few random points are dependent identically
        (the exact method would skip every point): leave them to intervals."""
        rng = random.Random(7)
        dependent = None
        for _ in range(4 * len(self.cases)):
            try:
                self._args(self._sample_exact(rng))
                break
            except ZeroDivisionError:
                continue
            except ValueError as exc:
                dependent = str(exc)
        else:
            if dependent and "proportional" in dependent:
                raise NotExact(self._world.twins[0][0], "square roots screened as multiples "
                                                       "of one another are not (write them "
                                                       "with one root)")
            if dependent:
                raise NotExact(self._world.radicals[0][1], "square roots whose product is a "
                                                          "perfect square (write them with "
                                                          "one root)")
        self._counter = 0

    # -- points ------------------------------------------------------------------------------
    def sample(self, rng: random.Random, floats: dict | None = None) -> dict:
        """A random point: ``{symbol: value}``, plus ``{AtomKey: u or w}``, ``pi`` and
        :data:`CASE` for the exact method.

        Exact: random integers (cases in turn).  Interval: random reals over each symbol's
        domain (``floats``, the working ranges, are ignored).  mpmath: inside ``floats``.
        """
        if self.method == "exact":
            return self._sample_exact(rng)
        point = {}
        box: dict = {}
        if self.method == "interval":
            # every other point inside a branch or domain region found at build time
            turn = self._counter
            self._counter += 1
            if self._regions and turn % 2:
                box = self._regions[(turn // 2) % len(self._regions)]
        for c, keys in self._read.items():
            if self.method == "interval":
                lo, hi = box.get(c) or _iv.domain_of(c, self._domains)
                v = Fraction(lo) if lo == hi else _iv.real_sample(rng, lo, hi)
            else:
                lo, hi = _range(floats, keys)
                v = mpmath.mpf(rng.uniform(lo, hi))
            for k in keys:
                point[k] = v
        return point

    def _sample_exact(self, rng) -> dict:
        half = 1 << (SAMPLE_BITS - 1)
        point: dict = {}
        for keys in self._read.values():
            v = Fraction(rng.randrange(-half, half))
            for k in keys:
                point[k] = v
        for a in self._world.atoms:
            point[a] = Fraction(rng.randrange(-half, half)) if a.kind == "circle" \
                else Fraction(rng.randrange(1, 2 * half + 1))
        if self._world.pi is not None:
            point[sp.pi] = Fraction(rng.randrange(-half, half))
        point[CASE] = self._counter % len(self.cases)
        self._counter += 1
        return point

    def evaluate(self, point: dict) -> list:
        """Values at ``point``: Fractions (or exact :class:`~dualmech.exact.surds.Surd` numbers
        with square roots), intervals (``mpmath.iv``), or mpf for the display method.

        Raises ``ZeroDivisionError`` or ``ValueError`` where the point is singular, outside a
        domain or undecided (the caller skips it).
        """
        if self.method == "interval":
            return self._program.evaluate({c: point[keys[0]] for c, keys in self._read.items()})
        if self.method == "mpmath":
            with mpmath.workdps(MP_DIGITS):
                return list(self._fn(*[point[keys[0]] for keys in self._read.values()]))
        args = self._args(point)
        return list(self._fn(*args))

    def _args(self, point, radicals: bool = True) -> list:
        """Arguments of the compiled functions: symbols, world values, roots, branch pieces.

        Branches with constant pieces (signs) come first: a root's radicand may use them.
        """
        w = self._world
        args = [point[keys[0]] for keys in self._read.values()]
        us = {i: point[a] for i, a in enumerate(w.atoms)}
        for vals in world_values(w.args, us):
            args.extend(vals)
        args.extend(us[i] for i in range(len(w.atoms)))
        if w.pi is not None:
            args.append(point[sp.pi])
        if not radicals:
            return args
        roots_at = len(args)
        branches_at = roots_at + len(w.radicals)
        args.extend([0] * (len(w.radicals) + len(w.branches)))
        case = self.cases[point.get(CASE, 0)] if w.branches else None
        for pre in (True, False):
            if not pre and w.radicals:
                args[roots_at:branches_at] = self._roots(args)
            for i, (b, fns) in enumerate(zip(w.branches, self._choices)):
                if b.pre == pre:
                    args[branches_at + i] = fns[case.choices[i]](*args)
        return args

    def _radicand_list(self, args) -> list:
        vals = list(self._radicands(*args))
        for v in vals:
            if not isinstance(v, (int, Fraction)):
                raise ValueError("a radicand is not rational at this point")
        return vals

    def _roots(self, args) -> list:
        if self._twins is not None and any(v != 0 for v in self._twins(*args)):
            raise ValueError("radicands taken as proportional are not, at this point")
        ds = self._radicand_list(args)
        irr = [d for d in ds if d != 0 and not is_square(d)]
        if not independent(irr):
            raise ValueError("square roots dependent at this point")
        return [Surd.root(d) for d in ds]

    # -- what a verdict means ----------------------------------------------------------------
    def certain(self, point: dict) -> bool:
        """Does a nonzero result at ``point`` prove a difference?  False in an ``unknown``
        branch case (and for the display method): the caller must refuse, not report."""
        if self.method == "mpmath":
            return False
        if self.method == "interval":
            return True
        return self.cases[point.get(CASE, 0)].status == "witnessed"

    def where(self, point: dict) -> str:
        """The branch case of ``point`` in words ("" without branches)."""
        if self.method != "exact":
            return ""
        return self.cases[point.get(CASE, 0)].where

    def points_needed(self, per_case: int) -> int:
        """Points to draw so that every branch case gets ``per_case`` of them."""
        return per_case * len(self.cases)

    def false_equal_bound(self, points, extra_degree: int = 0) -> float:
        """Bound on the chance that a nonzero result vanished at every point (exact method).

        ``points`` is a count (points drawn in turn from :meth:`sample`, none skipped) or the
        list of points that were used, which counts each case exactly.  NaN for the other
        methods (no probability claim); 1.0 when some case got no point.
        """
        if self.method != "exact":
            return float("nan")
        n = len(self.cases)
        if isinstance(points, int):
            counts = [points // n] * n      # sample() cycles through the cases
        else:
            counts = [0] * n
            for p in points:
                counts[p.get(CASE, 0)] += 1
        p1 = min(1.0, (self.degree + extra_degree) / 2.0**SAMPLE_BITS)
        return max(p1 ** c for c in counts)

    def describe(self, points, extra_degree: int = 0) -> str:
        """How an "equal" from ``points`` zero points was reached and how sure it is."""
        k = points if isinstance(points, int) else len(points)
        if self.method == "exact":
            text = (f"{METHOD_NAMES['exact']}: exactly 0 at {k} random points; "
                    f"P(false equal) <= {self.false_equal_bound(points, extra_degree):.1e} "
                    f"(Schwartz-Zippel, degree <= {self.degree + extra_degree})")
            if len(self.cases) > 1:
                unknown = [c.where for c in self.cases if c.status != "witnessed"]
                text += f"; in each of {len(self.cases)} branch cases"
                if unknown:
                    text += " (some not seen in the domain: " + "; ".join(unknown) + ")"
            if self._world.radicals:
                text += "; square roots as exact algebraic numbers"
            return text
        if self.method == "interval":
            return (f"{METHOD_NAMES['interval']}: every interval contained 0 at {k} random real "
                    f"points ({MP_DIGITS} digits); evidence, not a proof")
        return METHOD_NAMES["mpmath"]


def is_zero(value, scale=1) -> bool:
    """The zero test on an evaluated value.

    Exact numbers: ``== 0``.  Intervals: the interval contains 0 (a ``False`` is certain).
    mpf (display method): ``|value| <= 10**(-MP_DIGITS/2) * |scale|`` -- relative, no floor.
    """
    if isinstance(value, (Fraction, int)):
        return value == 0
    if isinstance(value, Surd):
        return value.is_zero()
    if isinstance(value, _iv.iv.mpf):
        return value.a <= 0 <= value.b
    if isinstance(value, float):
        raise TypeError("a float reached an exact zero test; exact arithmetic was lost "
                        "(int / int?)")
    with mpmath.workdps(MP_DIGITS):
        return abs(value) <= mpmath.mpf(10) ** (-(MP_DIGITS // 2)) * abs(scale)


def as_float(value) -> float:
    if isinstance(value, _iv.iv.mpf):
        return float(value.mid)
    return float(value)


# ---------------------------------------------------------------------------------------------
def _conditions(exprs) -> list:
    """Where the value of ``exprs`` changes form: branch conditions and domain boundaries."""
    out: list = []

    def add(g):
        g = sp.sympify(g, strict=True)
        if g.free_symbols and g not in out and -g not in out:
            out.append(g)

    for e in exprs:
        for node in sp.preorder_traversal(e):
            if isinstance(node, (sp.Abs, sp.sign, sp.Heaviside)):
                add(node.args[0])
            elif isinstance(node, sp.Piecewise):
                for _, cond in node.args:
                    for rel in cond.atoms(sp.core.relational.Relational):
                        add(rel.lhs - rel.rhs)
            elif isinstance(node, (sp.Max, sp.Min)):
                add(node.args[0] - node.args[1])
            elif isinstance(node, sp.Pow) and not node.exp.is_Integer:
                add(node.base)
            elif isinstance(node, sp.log):
                add(node.args[0])
            elif isinstance(node, (sp.acos, sp.asin, sp.atanh)):
                add(1 - node.args[0])
                add(1 + node.args[0])
            elif isinstance(node, sp.acosh):
                add(node.args[0] - 1)
    return out


def _range(floats, keys) -> tuple:
    for k in keys:
        if floats and k in floats:
            return floats[k]
    return (-2.0, 2.0)


def _world_args(world: World) -> list:
    args = list(world.symbols)
    for _, _, dummies in world.args:
        args.extend(dummies)
    args.extend(world.u_dummies[i] for i in range(len(world.atoms)))
    if world.pi is not None:
        args.append(world.pi)
    args.extend(d for d, _ in world.radicals)
    args.extend(b.dummy for b in world.branches)
    return args


def _degree(world: World) -> int:
    """Total-degree bound over every case, times ``2**m`` for ``m`` square roots (the norm)."""
    weights: dict = {}
    for kind, terms, dummies in world.args:
        K = sum(abs(k) for _, k in terms)
        if kind == "circle":
            weights[dummies[0]] = (1, 2) if K == 1 else (2 * K, 2 * K)
            weights[dummies[1]] = (2, 2) if K == 1 else (2 * K, 2 * K)
        else:
            weights[dummies[0]] = (sum(k for _, k in terms if k > 0),
                                   sum(-k for _, k in terms if k < 0))
    memo: dict = {}
    for d, radicand in world.radicals:
        n, m = degree_bound(radicand, weights, memo)
        weights[d] = ((n + m + 1) // 2, 0)
    for b in world.branches:
        parts = [degree_bound(c, weights, memo) for c in b.choices]
        weights[b.dummy] = (max(p[0] for p in parts), max(p[1] for p in parts))
    total = max((sum(degree_bound(e, weights, memo)) for e in world.exprs), default=0)
    for x, _, xj in world.twins:     # X - r X_j vanishing at a point by chance
        total = max(total, sum(degree_bound(x * xj, weights, memo)))
    return max(total, 1) * 2 ** len(world.radicals)


def _unify(exprs, symbols):
    """Symbols that share a name become one (the one with the narrowest assumptions)."""
    free = set().union(*(e.free_symbols for e in exprs)) if exprs else set()
    groups: dict = {}
    for s in list(symbols) + sorted(free - set(symbols), key=str):
        key = s.name if type(s) is sp.Symbol else s
        group = groups.setdefault(key, [])
        if s not in group:
            group.append(s)
    alias, read, notes = {}, {}, []
    declared = set(symbols)
    for key, group in groups.items():
        canon = _narrowest(group) if len(group) > 1 else group[0]
        if len(group) > 1:
            notes.append(f"symbols named {key!r} with different assumptions were unified as "
                         f"{_assumption_text(canon)}")
            for s in group:
                if s != canon:
                    alias[s] = canon
        keys = [s for s in group if s in declared]
        if not keys:
            continue
        read[canon] = keys
    extra = [s for s in free if alias.get(s, s) not in read]
    if extra:
        raise ValueError(f"expressions use undeclared symbols {sorted(map(str, extra))}.")
    if alias:
        exprs = [e.xreplace(alias) for e in exprs]
    return exprs, alias, read, notes


def _interval_of(s) -> tuple:
    lo, hi = _iv.domain_of(s)
    return lo, hi, bool(s.is_integer)


def _narrowest(group):
    doms = {s: _interval_of(s) for s in group}
    lo = max(d[0] for d in doms.values())
    hi = min(d[1] for d in doms.values())
    if lo >= hi:
        raise Undecidable(group[0], "symbols with this name carry contradictory assumptions "
                                    f"({', '.join(_assumption_text(s) for s in group)}); "
                                    "use one symbol")
    for s, d in doms.items():
        if d[0] == lo and d[1] == hi and (d[2] or not any(x[2] for x in doms.values())):
            return s
    raise Undecidable(group[0], "symbols with this name carry assumptions that no one of them "
                                "summarises; use one symbol")


def _assumption_text(s) -> str:
    flags = [k for k in ("positive", "negative", "nonnegative", "nonpositive", "integer", "real")
             if getattr(s, f"is_{k}")]
    return f"{s} ({', '.join(flags) or 'no assumptions'})"
