"""The exact world: expressions as rational functions of independently sampled variables.

:mod:`dualmech.exact.form` decides identities by evaluating at random points of a *world* of
variables that are algebraically independent as functions (see its docstring for the proof):

* every symbol;
* ``pi`` (a transcendental number, used as a variable);
* for each *circle atom* ``a`` (a monomial in the symbols divided by an integer), the point
  ``exp(i a)`` of the unit circle, sampled as ``((1 - u^2), 2u)/(1 + u^2)`` at a random ``u``;
  ``sin``/``cos`` of ``k_1 a_1 + k_2 a_2 + ...`` (integers ``k``) are the imaginary/real parts
  of ``prod z_j^(k_j)``: large multiples cost a power, not an ``expand_trig``;
* for each *growth atom* ``b``, ``w = exp(b)``, sampled as a random positive integer
  (``exp``, ``sinh``, ``cosh``, ``tanh``, and ``E``);
* square roots of rational world expressions, kept as exact algebraic numbers
  (:mod:`dualmech.exact.surds`); a root of a perfect square becomes ``|Y|`` times the root of
  the square-free rest;
* branch functions (``Abs``, ``sign``, ``Heaviside``, ``Max``, ``Min``, ``Piecewise``) whose
  conditions are rational world expressions: each becomes one of its rational pieces,
  chosen by a *case* (:mod:`dualmech.exact.branches`).

:func:`analyse` rewrites expressions into that world, or raises :class:`NotExact` naming the
first sub-expression that leaves it (the caller then falls back to interval arithmetic) or
:class:`Undecidable` for what no method here can decide.

Example
-------
>>> th, t = sp.symbols("theta t")
>>> w = analyse([sp.sin(2*th) + sp.cos(th/3 + 1000*t)], [th, t])
>>> [str(a) for a in w.atoms], [terms for _, terms, _ in w.args]
(['exp(i*t)', 'exp(i*theta/3)'], [((0, 1000), (1, 1)), ((1, 6),)])
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Sequence

import sympy as sp

from dualmech.exact.errors import NotExact, Undecidable
from dualmech.exact.radicals import (const_root, factor_signs, factored_sqrt, proportional,
                                     square_screen as _square_screen,
                                     radicals_dependent, square_sqrt)
from dualmech.model import trees

__all__ = ["Undecidable", "NotExact", "AtomKey", "World", "analyse", "analyse_se",
           "MAX_MULTIPLE", "degree_bound"]

#: Largest total multiple ``sum |k_j|`` of an exact trigonometric/exponential argument; beyond
#: it the numbers grow too long and interval arithmetic takes over.
MAX_MULTIPLE = 2048
_MAX_RADICAND_MULTIPLE = 16

_CIRCLE = frozenset(("sin", "cos", "tan", "cot", "sec", "csc"))
_GROWTH = frozenset(("exp", "sinh", "cosh", "tanh", "coth", "sech", "csch"))
_BRANCH = frozenset(("Abs", "sign", "Heaviside", "Max", "Min", "Piecewise"))


@dataclass(frozen=True)
class AtomKey:
    """Key of a sampled atom in a point: ``kind`` is ``"circle"`` (``exp(i*expr)``, value ``u``)
    or ``"growth"`` (``exp(expr)``, value ``w``)."""

    kind: str
    expr: sp.Expr

    @property
    def free_symbols(self) -> set:
        return self.expr.free_symbols

    def __str__(self) -> str:
        return f"{'exp(i*' if self.kind == 'circle' else 'exp('}{self.expr})"


@dataclass
class Cond:
    """An atomic branch condition: an irreducible factor of a condition ``g`` whose sign picks
    the pieces.  ``real`` is it in the original symbols; ``u_form`` in the world's own
    variables (symbols, each atom's ``u``/``w``, ``pi``) when it is a polynomial there."""

    world: sp.Expr
    real: sp.Expr
    u_form: sp.Expr | None = None


@dataclass
class Branch:
    """One branch function: its dummy, its pieces (world form) and how a sign vector picks one."""

    node: sp.Expr
    dummy: sp.Dummy
    choices: list
    pick: Callable  # (sign vector tuple) -> index into choices, or None (undefined there)
    labels: list    # per choice: where it applies, in words

    @property
    def pre(self) -> bool:
        """Constant pieces (a sign): evaluated before the square roots, which may use it."""
        return all(c.is_number for c in self.choices)


@dataclass
class World:
    """Expressions rewritten as rational functions of world variables (see module docstring)."""

    exprs: list                        # rewritten expressions
    symbols: list                      # canonical symbols, in order
    atoms: list                        # AtomKey per atom
    args: list                         # (kind, ((atom index, k), ...), dummies) per argument
    pi: sp.Dummy | None
    u_dummies: dict                    # atom index -> Dummy for u (circle) or w (growth)
    radicals: list                     # (Dummy, world radicand)
    conds: list                        # Cond
    branches: list                     # Branch, inner before outer
    scales: list                       # per atom: (kind, monomial, L): the atom is monomial/L
    twins: list = field(default_factory=list)   # (X, r, X_j): sqrt(X) written r^(1/2) sqrt(X_j)


# ---------------------------------------------------------------------------------------
# linear forms of arguments
def _monomial(m: sp.Expr, node) -> tuple[bool, bool]:
    """Check ``m`` is a product of symbols/pi with nonzero integer powers.

    Returns (has a real symbol, has pi).  Raises NotExact/Undecidable otherwise.
    """
    real = has_pi = False
    for f in sp.Mul.make_args(m):
        base, e = f.as_base_exp()
        if not (e.is_Integer and e != 0):
            raise NotExact(node, f"argument term {m} is not a monomial")
        if base is sp.pi:
            has_pi = True
        elif base.is_Symbol:
            if base.is_integer:
                raise Undecidable(node, f"the integer-valued symbol {base} is inside a "
                                        "transcendental function: identities over the "
                                        "integers are not decided here; declare it real")
            real = True
        elif base is not sp.S.One:
            raise NotExact(node, f"argument term {m} is not a monomial in the symbols")
    return real, has_pi


def _linear(arg, node, factor: Callable) -> dict:
    """``arg`` as ``{monomial: Fraction coefficient}`` (monomial 1 for a constant term).

    ``factor`` gives a factor of a term as a sympy monomial factor, or ``None`` for one that
    is not (see :meth:`_Scan.factor`); a term with such a factor is retried on the expanded
    argument (sympy), or leaves the fast route (symengine).
    """
    parts = _split(arg, factor)
    if parts is None:
        if trees.is_held(arg):
            raise _Leave
        parts = _split(sp.expand(arg), lambda f: f)   # _monomial names a bad factor
        if parts is None:
            raise NotExact(node, f"argument {arg} is not a rational combination of monomials")
    out = {}
    for m, c in parts.items():
        if c == 0:
            continue
        real, has_pi = _monomial(m, node)
        if has_pi and not real:
            raise NotExact(node, f"the constant {c * m} in the argument gives an algebraic "
                                 "number that is not rational")
        out[m] = c
    return out


def _split(arg, factor: Callable) -> dict | None:
    """``{sympy monomial: Fraction}`` of the terms of ``arg``, or ``None`` when a term is not
    a rational number times a product of ``factor``-accepted factors."""
    out: dict = {}
    for term in trees.terms(arg):
        k = trees.kind(term)
        c, factors = Fraction(1), (term,)
        if k is trees.INTEGER or k is trees.RATIONAL:
            c, factors = trees.fraction(term), ()
        elif k in trees.NUMBERS:
            return None
        elif k is trees.MUL:
            first = term.args[0]
            kf = trees.kind(first)
            if kf is trees.INTEGER or kf is trees.RATIONAL:
                c, factors = trees.fraction(first), term.args[1:]
            elif kf in trees.NUMBERS:
                return None
            else:
                factors = term.args
        mono = [factor(f) for f in factors]
        if None in mono:
            return None
        m = mono[0] if len(mono) == 1 else sp.Mul(*mono)
        out[m] = out.get(m, 0) + c
    return out


class _Leave(Exception):
    """Symengine input outside the fast route's common case (see :func:`analyse_se`)."""


# ---------------------------------------------------------------------------------------
# pass 1: what the expressions contain
class _Scan:
    """What the expressions contain: their trigonometric and exponential nodes with the
    linear forms of their arguments, square roots, branch functions, ``pi`` and ``E``.

    ``held`` (``{name: sympy symbol}``) scans symengine trees for the fast route: the
    symbols must be those, and what the general route alone handles (constants, floats,
    square roots, branch functions, anything it refuses) raises :class:`_Leave`.
    """

    RAD, BR = 1, 2

    def __init__(self, held: dict | None = None):
        self.held = held
        self.memo: dict = {}
        self.trig: dict = {}       # node -> (kind, linear form)
        self.radicals: dict = {}   # node -> (radicand, power p of sqrt)
        self.branches: list = []   # branch nodes, inner first
        self.pi = False
        self.e_const = False

    def visit(self, e) -> int:
        hit = self.memo.get(e)
        if hit is not None:
            return hit
        out = self._visit(e)
        self.memo[e] = out
        return out

    def core(self, e, node, what) -> None:
        if self.visit(e):
            raise NotExact(node, f"{what} contains a square root or a branch function")

    def factor(self, f):
        """A factor of an argument's term as a sympy monomial factor (a symbol, ``pi``, or
        one of them to an integer power), or ``None``; a held factor must be a declared
        symbol."""
        k = trees.kind(f)
        if self.held is not None:
            return self.held.get(f.name) if k is trees.SYMBOL else None
        if k is trees.POW:
            base, x = f.args
            if trees.kind(x) is not trees.INTEGER:
                return None
            k = trees.kind(base)
        else:
            base = f
        return f if k is trees.SYMBOL or base is sp.pi else None

    def _visit(self, e) -> int:
        k = trees.kind(e)
        if k is trees.SYMBOL:
            if self.held is not None and (self.held.get(e.name) is None or trees.is_dummy(e)):
                raise _Leave   # undeclared (the general route says so) or a dummy
            return 0
        if k is trees.INTEGER or k is trees.RATIONAL:
            return 0
        if k is trees.ADD or k is trees.MUL:
            flags, memo = 0, self.memo
            for a in e.args:
                hit = memo.get(a)     # shared subtrees are met often: looked up once
                if hit is None:
                    hit = memo[a] = self._visit(a)
                flags |= hit
            return flags
        if k is trees.POW:
            return self._pow(e)
        f = trees.name(e) if k is trees.FUNCTION else None
        if f in _CIRCLE or f in _GROWTH:
            lin = _linear(e.args[0], e, self.factor)
            if any(m is sp.S.One for m in lin):
                self.e_const = True
            self.trig[e] = ("circle" if f in _CIRCLE else "growth", lin)
            return 0
        if self.held is not None:
            raise _Leave
        if f in _BRANCH:
            return self._branch(e)
        return self._other(e, k)

    def _other(self, e, k) -> int:
        """Constants, and what the exact world refuses."""
        if k is trees.FLOAT:
            raise AssertionError("floats are made exact before the scan")
        if e is sp.pi:
            self.pi = True
            return 0
        if e is sp.E:
            self.e_const = True
            self.trig[e] = ("growth", {sp.S.One: Fraction(1)})
            return 0
        if k is trees.SPECIAL:
            raise Undecidable(e, "complex or infinite values are not supported; write real "
                                 "quantities as separate real expressions")
        if k is trees.CONSTANT:
            raise NotExact(e, "a constant that is not rational (nor pi)")
        if k is trees.UNDEFINED:
            raise Undecidable(e, "an undefined function has no value; substitute plain symbols "
                                 "for the states or an explicit expression")
        if k is trees.DERIVATIVE or isinstance(e, sp.Integral):
            raise Undecidable(e, "an unevaluated derivative or integral; write the states as "
                                 "plain symbols")
        raise NotExact(e, f"`{type(e).__name__}` is not a rational, trigonometric or "
                          "exponential function")

    def _pow(self, e) -> int:
        b, x = e.args
        kx = trees.kind(x)
        if kx is trees.INTEGER:
            return self.visit(b)
        if self.held is not None:
            if kx is trees.RATIONAL and int(x.q) == 2 and not self.visit(b):
                self.radicals[e] = (b, int(x.p))   # the root of a rational radicand
                return self.RAD
            raise _Leave   # nested roots, other orders: the general route
        if kx is trees.RATIONAL and x.q == 2:
            self.core(b, e, "a square root's radicand")
            self.radicals[e] = (b, int(x.p))
            return self.RAD
        if kx is trees.RATIONAL:
            raise NotExact(e, f"a root of order {x.q} (only square roots are exact)")
        raise NotExact(e, "a symbolic exponent")

    def _branch(self, e) -> int:
        if isinstance(e, sp.Piecewise):
            flags = self.BR
            for value, cond in e.args:
                flags |= self.visit(value)
                self._condition(cond, e)
        else:
            args = e.args[:1] if isinstance(e, (sp.Abs, sp.sign, sp.Heaviside)) else e.args
            if isinstance(e, sp.Heaviside) and len(e.args) > 1 and not e.args[1].is_Rational:
                raise NotExact(e, "Heaviside with a symbolic value at 0")
            for a in args:
                self.core(a, e, "a branch condition")
            flags = self.BR
        self.branches.append(e)
        return flags

    def _condition(self, cond, node) -> None:
        if cond in (sp.true, sp.false):
            return
        if isinstance(cond, (sp.And, sp.Or, sp.Not)):
            for c in cond.args:
                self._condition(c, node)
            return
        if isinstance(cond, sp.core.relational.Relational) and \
                not isinstance(cond, (sp.Eq, sp.Ne)):
            self.core(cond.lhs - cond.rhs, node, "a Piecewise condition")
            return
        if isinstance(cond, (sp.Eq, sp.Ne)):
            return  # holds on a set of measure zero (Eq) or almost everywhere (Ne)
        raise NotExact(node, f"the condition {cond} is not a comparison")


# ---------------------------------------------------------------------------------------
def analyse(exprs: list, symbols: list) -> World:
    """Rewrite ``exprs`` (floats already exact, symbols unified) into the exact world."""
    scan = _Scan()
    for e in exprs:
        scan.visit(e)
    if scan.pi and scan.e_const:
        raise NotExact(sp.pi, "pi beside exp/sin/cos of a constant: whether those constants "
                              "are algebraically independent is not known")
    b = _Builder(scan, symbols)
    return b.build(exprs)


def analyse_se(exprs: Sequence, symbols: Sequence) -> World | None:
    """The world of symengine ``exprs`` (a derivation's matrices, see
    :meth:`dualmech.model.equations.EquationSet.plain_matrix_se`) in the sympy ``symbols``,
    built without a sympy expression -- or ``None`` when they leave the common case.

    The common case is what rigid-body models produce: rational functions of the symbols
    and of circle and growth functions of rational combinations of them.  The scan and the
    world are those of :func:`analyse` (the same atoms, arguments and degree bound, so the
    same verdict and false-equal bound), square roots of such expressions included (those the
    general route keeps whole: one radical each, or one shared by radicands screened equal);
    anything else (nested roots, radicands screened as squares or as other multiples of one
    another, ``pi``, ``E``, branch functions, floats, undeclared symbols, an integer symbol
    inside a sine) returns ``None`` and the caller takes the general sympy route, which
    decides or refuses it.

    Example
    -------
    >>> import symengine as se
    >>> th, t = sp.symbols("theta t", real=True)
    >>> w = analyse_se([se.sin(2 * se.Symbol("theta")) + se.cos(se.Symbol("theta") / 3)],
    ...                [th, t])
    >>> [str(a) for a in w.atoms], [terms for _, terms, _ in w.args]
    (['exp(i*theta/3)'], [((0, 1),), ((0, 6),)])
    """
    by_name = {s.name: s for s in symbols}
    if len(by_name) != len(symbols) or not all(type(s) is sp.Symbol for s in symbols):
        return None
    scan = _Scan(held=by_name)
    try:
        for e in exprs:
            scan.visit(e)
        return _Builder(scan, symbols).build(exprs)
    except (_Leave, NotExact, Undecidable):
        return None


def function_arguments_se(exprs: Sequence) -> set | None:
    """The symbols inside the circle and growth functions of symengine ``exprs`` (as real
    sympy symbols), found by the fast route's scan (each shared subtree visited once), or
    ``None`` when the expressions leave that route.

    >>> import symengine as se
    >>> x, y, w = se.symbols("x y w")
    >>> sorted(map(str, function_arguments_se([se.sin(x + 2 * y) * w + se.cos(w / 3) * x])))
    ['w', 'x', 'y']
    >>> function_arguments_se([se.exp(w)]) is None      # symengine's E**w: the general route
    True
    """
    names = set()
    for e in exprs:
        names |= {str(v) for v in e.free_symbols}
    scan = _Scan(held={n: sp.Symbol(n, real=True) for n in names})
    try:
        for e in exprs:
            scan.visit(e)
    except (_Leave, NotExact, Undecidable):
        return None
    out = set()
    for _, lin in scan.trig.values():
        for m in lin:
            out |= m.free_symbols
    return out


#: a circle function of an argument from its ``(sin, cos)`` dummies
_CIRCLE_RULES = {"sin": lambda s, c: s, "cos": lambda s, c: c, "tan": lambda s, c: s / c,
                 "cot": lambda s, c: c / s, "sec": lambda s, c: 1 / c, "csc": lambda s, c: 1 / s}
#: a growth function (or ``E``) of an argument from its ``exp`` dummy
_GROWTH_RULES = {"exp": lambda w: w, "E": lambda w: w, "sinh": lambda w: (w - 1 / w) / 2,
                 "cosh": lambda w: (w + 1 / w) / 2, "tanh": lambda w: (w**2 - 1) / (w**2 + 1),
                 "coth": lambda w: (w**2 + 1) / (w**2 - 1), "sech": lambda w: 2 / (w + 1 / w),
                 "csch": lambda w: 2 / (w - 1 / w)}


class _Builder:
    """The world of what :class:`_Scan` found: atoms, argument dummies and rewriting rules
    (in symengine for a held scan, whose expressions stay there)."""

    def __init__(self, scan: _Scan, symbols):
        self.scan = scan
        self.held = scan.held is not None
        self.symbols = list(symbols)
        self.rule: dict = {}
        self.atoms: list = []
        self.atom_index: dict = {}
        self.args: list = []
        self.arg_index: dict = {}
        self.u: dict = {}
        self.pi = sp.Dummy("pi") if scan.pi else None
        self.radicals: list = []
        self.radical_index: dict = {}
        self.conds: list = []
        self.cond_index: dict = {}
        self.branches: list = []
        self.scales: list = []
        self.u_cache: dict = {}
        self.value_cache: dict = {}   # screening values at random world points
        self.twins: list = []         # (radicand, r, radicand j): checked X = r X_j

    # -- atoms and arguments -------------------------------------------------------------
    def _atoms(self) -> None:
        lcd: dict = {}
        for kind, lin in self.scan.trig.values():
            for m, c in lin.items():
                key = (kind, m)
                lcd[key] = math.lcm(lcd.get(key, 1), int(sp.Rational(c).q))
        order = sorted(lcd, key=lambda km: (km[0], sp.default_sort_key(km[1])))
        for kind, m in order:
            L = lcd[(kind, m)]
            self.atom_index[(kind, m)] = (len(self.atoms), L)
            self.atoms.append(AtomKey(kind, m / L))
            self.scales.append((kind, m, L))
            prefix = "u" if kind == "circle" else "w"
            self.u[len(self.atoms) - 1] = trees.dummy(f"{prefix}{len(self.atoms) - 1}",
                                                      self.held)

    def _arg(self, kind, lin, node):
        terms = []
        for m, c in lin.items():
            i, L = self.atom_index[(kind, m)]
            terms.append((i, int(c * L)))
        terms = tuple(sorted(terms))
        if sum(abs(k) for _, k in terms) > MAX_MULTIPLE:
            raise NotExact(node, f"a multiple larger than {MAX_MULTIPLE} of an angle or rate")
        key = (kind, terms)
        hit = self.arg_index.get(key)
        if hit is None:
            at = len(self.args)   # the dummies' names are indices: printing costs
            dummies = (trees.dummy(f"S{at}", self.held), trees.dummy(f"C{at}", self.held)) \
                if kind == "circle" else (trees.dummy(f"W{at}", self.held),)
            hit = self.arg_index[key] = at
            self.args.append((kind, terms, dummies))
        return self.args[hit][2]

    def _trig_rules(self) -> None:
        for node, (kind, lin) in self.scan.trig.items():
            d = self._arg(kind, lin, node)
            rules = _CIRCLE_RULES if kind == "circle" else _GROWTH_RULES
            self.rule[node] = rules[trees.name(node)](*d)
        if self.pi is not None:
            self.rule[sp.pi] = self.pi

    # -- the build -------------------------------------------------------------------------
    def build(self, exprs) -> World:
        self._atoms()
        self._trig_rules()
        roots = [(node, radicand.xreplace(self.rule), p)
                 for node, (radicand, p) in self.scan.radicals.items()]
        # a radicand that is a constant multiple of another shares its root (checked at
        # every point); independent radicands stay whole; dependent ones (sqrt(2)*sqrt(x^2+1)
        # beside sqrt(2*x^2+2)) are split into roots of irreducible factors, signs as cases
        same = proportional(self, [r for _, r, _ in roots]) if len(roots) > 1 \
            else [(0, 1)] * len(roots)
        heads = [i for i, (j, _) in enumerate(same) if i == j]
        split = len(heads) > 1 and radicals_dependent(self, [roots[i][1] for i in heads])
        if self.held and (split or any(j != i and r != 1 for i, (j, r) in enumerate(same))):
            raise _Leave   # factoring and constant roots are the general route's (sympy)
        made: dict = {}
        for i in heads:
            node, radicand, _ = roots[i]
            made[i] = factored_sqrt(self, node, radicand) if split \
                else self._radical(node, radicand)
        for i, (node, radicand, p) in enumerate(roots):
            j, r = same[i]
            root = made[j]
            if j != i:
                self.twins.append((radicand, r, roots[j][1]))
                if r != 1:
                    root = const_root(self, sp.Rational(r.numerator, r.denominator)) * root
            self.rule[node] = root ** p
        for node in self.scan.branches:
            self._branch(node)
        out = [e.xreplace(self.rule) for e in exprs] if self.rule else list(exprs)
        return World(out, self.symbols, self.atoms, self.args, self.pi, self.u, self.radicals,
                     self.conds, self.branches, self.scales, self.twins)

    def _radical(self, node, radicand) -> sp.Expr:
        """``sqrt(radicand)``: a radical dummy, or ``|Y| * sqrt(rest)`` for a square factor."""
        if self.held:
            if _square_screen(self, radicand):
                raise _Leave   # |Y| sqrt(rest) is factored in sympy: the general route
            return self._radical_dummy(radicand)
        return square_sqrt(self, node, radicand) or self._radical_dummy(radicand)

    def _radical_dummy(self, radicand):
        hit = self.radical_index.get(radicand)
        if hit is None:
            hit = self.radical_index[radicand] = trees.dummy(f"r{len(self.radicals)}",
                                                             self.held)
            self.radicals.append((hit, radicand))
        return hit

    def _real_form(self, expr_world) -> sp.Expr:
        """A world expression back in the original symbols (for interval evaluation)."""
        back = {}
        for i, atom in enumerate(self.atoms):
            back[self.u[i]] = sp.tan(atom.expr / 2) if atom.kind == "circle" else sp.exp(atom.expr)
        for kind, terms, dummies in self.args:
            angle = sum(k * self.atoms[i].expr for i, k in terms)
            if kind == "circle":
                back[dummies[0]], back[dummies[1]] = sp.sin(angle), sp.cos(angle)
            else:
                back[dummies[0]] = sp.exp(angle)
        if self.pi is not None:
            back[self.pi] = sp.pi
        return expr_world.xreplace(back)

    # -- branches --------------------------------------------------------------------------
    def _cond(self, g_world, g_real) -> Callable:
        """The sign of the condition ``g`` as a function of the atomic conditions' signs.

        ``g`` is factored in the world's own variables (``sin``/``cos`` as rational functions of
        ``u``): its sign is a constant times the signs of its odd-multiplicity irreducible
        factors, so ``Abs(cos(theta))`` and the ``|Y|`` of ``sqrt(1 - sin(theta)**2)`` share
        their atomic conditions.  Conditions too large to factor stay atomic.
        """
        parts = self._factors(g_world)
        if parts is None:
            j, o = self._atomic(g_world, g_real, None)
            return lambda s: o * s[j]
        const, factors = parts
        idx = [self._atomic(f, self._real_form(f), f) for f in factors]
        return lambda s: const * math.prod(o * s[j] for j, o in idx)

    def _atomic(self, key, real, u_form) -> tuple[int, int]:
        hit = self.cond_index.get(key)
        if hit is not None:
            return hit, 1
        hit = self.cond_index.get(-key)
        if hit is not None:
            return hit, -1
        self.cond_index[key] = len(self.conds)
        self.conds.append(Cond(key, real, u_form))
        return len(self.conds) - 1, 1

    def _factors(self, g_world):
        """``(sign constant, [irreducible factors with odd multiplicity])`` or ``None``."""
        return factor_signs(self, g_world)

    def _add_branch(self, node, choices, pick, labels) -> sp.Dummy:
        beta = sp.Dummy(f"b{len(self.branches)}")
        self.branches.append(Branch(node, beta, choices, pick, labels))
        self.rule[node] = beta
        return beta

    def _abs_branch(self, node, g_world, g_real) -> sp.Dummy:
        sign = self._cond(g_world, g_real)
        return self._add_branch(node, [g_world, -g_world], lambda s: 0 if sign(s) > 0 else 1,
                                [_Label(g_real, "> 0"), _Label(g_real, "< 0")])

    def _branch(self, node) -> None:
        w = lambda e: e.xreplace(self.rule)  # noqa: E731
        if isinstance(node, sp.Abs):
            self._abs_branch(node, w(node.args[0]), node.args[0])
        elif isinstance(node, (sp.sign, sp.Heaviside)):
            sign = self._cond(w(node.args[0]), node.args[0])
            vals = [sp.S.One, -sp.S.One] if isinstance(node, sp.sign) else [sp.S.One, sp.S.Zero]
            g = node.args[0]
            self._add_branch(node, vals, lambda s: 0 if sign(s) > 0 else 1,
                             [f"{g} > 0", f"{g} < 0"])
        elif isinstance(node, (sp.Max, sp.Min)):
            self._extremum(node, w)
        else:
            self._piecewise(node, w)

    def _extremum(self, node, w) -> None:
        args = list(node.args)
        sign = 1 if isinstance(node, sp.Max) else -1
        pairs = {}
        for i in range(len(args)):
            for k in range(i):
                pairs[(i, k)] = self._cond(w(args[i] - args[k]), args[i] - args[k])

        def pick(s):
            best = 0
            for i in range(1, len(args)):
                if pairs[(i, best)](s) * sign > 0:   # the sign of args[i] - args[best]
                    best = i
            return best
        self._add_branch(node, [w(a) for a in args], pick,
                         [f"{node} = {a}" for a in args])

    def _piecewise(self, node, w) -> None:
        tests = [self._truth(cond) for _, cond in node.args]

        def pick(s):
            for i, test in enumerate(tests):
                if test(s):
                    return i
            return None
        self._add_branch(node, [w(v) for v, _ in node.args], pick,
                         [f"{node.func.__name__} piece {i + 1} ({c})"
                          for i, (_, c) in enumerate(node.args)])

    def _truth(self, cond) -> Callable:
        if cond is sp.true or isinstance(cond, sp.Ne):
            return lambda s: True
        if cond is sp.false or isinstance(cond, sp.Eq):
            return lambda s: False
        if isinstance(cond, (sp.And, sp.Or)):
            parts = [self._truth(c) for c in cond.args]
            combine = all if isinstance(cond, sp.And) else any
            return lambda s: combine(p(s) for p in parts)
        if isinstance(cond, sp.Not):
            inner = self._truth(cond.args[0])
            return lambda s: not inner(s)
        g = cond.lhs - cond.rhs
        sign = self._cond(g.xreplace(self.rule), g)
        want = 1 if isinstance(cond, (sp.StrictGreaterThan, sp.GreaterThan)) else -1
        return lambda s: sign(s) == want


# ---------------------------------------------------------------------------------------
# square roots of squares
class _Label:
    """``expr`` and a relation, written out when first shown (a ``tan(a/2)`` form from a square
    root is then simplified, if small: display only, never for a decision)."""

    def __init__(self, expr, relation: str):
        self.expr, self.relation, self._text = expr, relation, None

    def __str__(self) -> str:
        if self._text is None:
            expr = self.expr
            if expr.has(sp.tan) and sp.count_ops(expr) < 40:
                try:
                    expr = sp.trigsimp(sp.simplify(expr))
                except Exception:  # display only: keep the plain form
                    pass
            relation = self.relation
            if expr.could_extract_minus_sign():
                flip = {">": "<", "<": ">", ">=": "<=", "<=": ">="}
                op, rest = relation.split(" ", 1)
                expr, relation = -expr, f"{flip[op]} {rest}"
            self._text = f"{expr} {relation}"
        return self._text

    def __eq__(self, other) -> bool:
        return str(self) == str(other)

    __hash__ = None


def degree_bound(expr, weights: dict, memo: dict | None = None) -> tuple[int, int]:
    """Bound on (numerator degree, denominator degree) of ``expr`` as a rational function.

    Works on the tree as it stands (no ``together``, which is slow on large input); shared
    subtrees are bounded once.
    """
    memo = {} if memo is None else memo
    hit = memo.get(expr)
    if hit is not None:
        return hit
    k = trees.kind(expr)
    if k in trees.NUMBERS:
        out = (0, 0)
    elif k is trees.SYMBOL:
        out = weights.get(expr, (1, 0))
    elif k is trees.ADD:
        parts = [degree_bound(a, weights, memo) for a in expr.args]
        den = sum(d for _, d in parts)
        out = (max(n + den - d for n, d in parts), den)
    elif k is trees.MUL:
        parts = [degree_bound(a, weights, memo) for a in expr.args]
        out = (sum(n for n, _ in parts), sum(d for _, d in parts))
    elif k is trees.POW and trees.kind(expr.args[1]) is trees.INTEGER:
        n, d = degree_bound(expr.args[0], weights, memo)
        e = trees.ratio(expr.args[1])[0]
        out = (n * e, d * e) if e >= 0 else (d * -e, n * -e)
    else:
        raise NotExact(expr, "cannot bound the degree")
    memo[expr] = out
    return out
