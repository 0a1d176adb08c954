r"""Parsed answers made into formulas: resolved names, exact evaluation, degree and dimensions.

A :class:`Formula` is a small tree over the problem's own symbols, compiled into closures that
evaluate it at a sampled point -- exactly, in ``Fraction`` arithmetic, or in high-precision
floating point (mpmath) where the answer leaves the rational world (``sqrt``, ``exp``,
``sin(theta/2)``).  The exact method is the one of :mod:`dualmech.exact.form`: after expanding
multiple and compound angles, ``sin`` and ``cos`` of each angle monomial ``a`` are taken at a
rational point of the unit circle, ``(cos a, sin a) = ((1 - u^2), 2u) / (1 + u^2)``, with ``u``
drawn independently of every other variable -- including ``a`` itself where it also appears
outside a trigonometric function (a torsional spring's ``k_t theta``): by Ax's theorem the
functions ``a`` and ``exp(i a)`` satisfy no algebraic relation, so the independent draw is sound.

Square roots of rational constants (``sqrt(3)/2`` of a push at 30 degrees, in an answer or in
a model) stay exact too: their values are elements of ``Q(sqrt p_1, ..., sqrt p_k)`` over prime
radicands (:class:`~dualmech.exact.surds.Surd`, :mod:`.roots`), where ``== 0`` is still
an exact test; so are ``sin``/``cos`` of multiples of ``pi/12`` (``cos(pi/6) = sqrt(3)/2``).
A root of more than :data:`MAX_ROOTS` primes in one formula is left to mpmath.

Square roots of expressions in the symbols (a rolling wheel's ``sqrt(1 - a_z^2)``) stay exact
the same way: at a rational point the radicand has a rational value ``d``, and ``sqrt(X)`` is
taken as the formal root of ``d`` (a :class:`~dualmech.exact.surds.Surd`, read as the positive
root).  This is sound only when the radicands are independent as functions (no radicand, nor
any product of them, a square: ``sqrt(theta^2) = |theta|`` has branches), so at a point where
a radicand's value is a rational square or the radicands' values are dependent -- which they
then are at every rational point -- or a radicand is negative, the evaluation raises
:class:`NotExactHere` and the caller leaves the formula to the comparator.  Where the values
are independent the functions are too, the field of the roots has degree ``2**k`` over the
rational functions, and a nonzero answer vanishes at a random point only where its norm (a
rational function of ``2**k`` times the degree, :attr:`Formula.degree`) does.

Building a formula never evaluates text and never calls ``sympify``: each node is made from
the parser's tree with the operations listed here, under the :class:`~.parser.Limits`
(exponents, degree, size of constants).

Example
-------
>>> import sympy as sp
>>> from fractions import Fraction
>>> from dualmech.grade.parser import parse
>>> from dualmech.grade.vocabulary import Vocabulary
>>> m, g = sp.symbols("m g", positive=True); th = sp.Symbol("th", real=True)
>>> v = Vocabulary.build(parameters=[m, g, th])
>>> f = Formula.from_node(parse("m*g*sin(2*th)")[0].lhs, v)
>>> env = Env({m: Fraction(2), g: Fraction(3), th: Fraction(5)}, atoms={((th, 1),): Fraction(1, 2)})
>>> f.evaluate(env)   # cos = 3/5, sin = 4/5 at u = 1/2: 2*3*2*(4/5)*(3/5)
Fraction(144, 25)
>>> f.exact, f.sympy()
(True, g*m*sin(2*th))
"""
from __future__ import annotations

import random
from fractions import Fraction
from typing import Callable

import mpmath
import sympy as sp

from dualmech.exact.form import MP_DIGITS
from dualmech.exact.surds import Surd, is_square
from dualmech.grade.roots import MAX_ROOTS, TURN_ROOTS, TURNS, surd_constant
from dualmech.grade.parser import LIMITS, AnswerError, AnswerTooLarge, Limits, Node, to_text
from dualmech.grade.cost import check
from dualmech.grade.resolve import resolve
from dualmech.grade.vocabulary import Vocabulary

__all__ = ["Formula", "Env", "NotExactHere", "difference", "seeded_draw", "tree_to_sympy",
           "sympy_to_tree"]

_PI = "pi"
_MAX_MULTIPLE = 10 ** 4  # largest multiple of an angle evaluated exactly; answers are bounded
                        # by the cost model (.cost: degree 4 per unit of a multiple angle)
_MP_FUNCS = {"sin": mpmath.sin, "cos": mpmath.cos, "tan": mpmath.tan, "cot": mpmath.cot,
             "sec": mpmath.sec, "csc": mpmath.csc, "sqrt": mpmath.sqrt, "exp": mpmath.exp,
             "log": mpmath.log}
_SP_FUNCS = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec,
             "csc": sp.csc, "sqrt": sp.sqrt, "exp": sp.exp, "log": sp.log}
_TRIG = ("sin", "cos", "tan", "cot", "sec", "csc")


class NotExactHere(ValueError):
    """A square root of an expression cannot be kept exact at this point: its radicand is
    negative, a rational square, or dependent on another root's (see the module docstring);
    the formula is then decided by the comparator."""


def state_root(d, k: int):
    """``sqrt(d)**k`` for the rational value ``d`` of a radicand that depends on the state,
    exactly (a :class:`~dualmech.exact.surds.Surd`), else :class:`NotExactHere`.

    >>> state_root(Fraction(5), -1)
    Surd(1/5*sqrt(5))
    >>> state_root(Fraction(4), 1)
    Traceback (most recent call last):
    ...
    dualmech.grade.formula.NotExactHere: a square root's radicand is a rational square at this point (a branch, as sqrt(x^2) = |x|)
    """
    if isinstance(d, Surd) or not isinstance(d, (Fraction, int)):
        raise NotExactHere("a square root of an expression with square roots")
    if d < 0:
        raise NotExactHere("a square root of a negative number at this point")
    if d == 0:
        if k < 0:
            raise ZeroDivisionError("a negative power of a square root of zero")
        return Fraction(0)
    if is_square(d):
        raise NotExactHere("a square root's radicand is a rational square at this point (a "
                           "branch, as sqrt(x^2) = |x|)")
    try:
        return Surd.root(d) ** k
    except ValueError as exc:   # dependent on the other roots met (Surd's own check)
        raise NotExactHere(str(exc)) from None


# -- evaluation environments ----------------------------------------------------------------
class Env:
    """Values at one point: ``values[symbol]``; ``atoms[monomial] = u`` for each angle.

    ``exact`` selects Fractions (``True``) or mpmath numbers.  An angle monomial not in
    ``atoms`` gets its ``u`` from ``draw(monomial)`` (deterministic per point), so every
    formula evaluated at this point sees the same ``sin`` and ``cos`` of every angle.
    """

    __slots__ = ("values", "exact", "atoms", "draw", "_z")

    def __init__(self, values: dict, exact: bool = True, atoms: dict | None = None,
                 draw: Callable | None = None, cache: dict | None = None):
        self.values = values
        self.exact = exact
        self.atoms = atoms if atoms is not None else {}
        self.draw = draw
        self._z = cache if cache is not None else {}   # angle -> (cos, sin): fixed per point

    def with_values(self, changes: dict) -> "Env":
        """The same point with some values replaced (shares the angles)."""
        return Env({**self.values, **changes}, self.exact, self.atoms, self.draw, self._z)

    def angle(self, parts: tuple, turn: int) -> tuple:
        """``(cos, sin)`` of ``sum(k * monomial) + turn * pi/12``, exactly (cached)."""
        key = (parts, turn)
        z = self._z.get(key)
        if z is None:
            z = TURNS[turn]
            for mono, k in parts:
                z = _cmul(z, _cpow(self.unit(mono), k))
            self._z[key] = z
        return z

    def unit(self, mono) -> tuple:
        """``(cos a, sin a)`` of the angle monomial ``mono``, exactly."""
        z = self._z.get(mono)
        if z is None:
            u = self.atoms.get(mono)
            if u is None:
                if self.draw is None:
                    raise KeyError(f"no angle value for {mono}")
                u = self.atoms[mono] = self.draw(mono)
            d = 1 + u * u
            z = self._z[mono] = ((1 - u * u) / d, 2 * u / d)
        return z


def seeded_draw(seed: str) -> Callable:
    """A ``draw`` for :class:`Env`: the same ``u`` for the same monomial and seed, always."""
    return _SeededDraw(seed)


class _SeededDraw:
    """The ``draw`` of :func:`seeded_draw` (a plain object, so a context pickles)."""

    __slots__ = ("seed",)

    def __init__(self, seed: str):
        self.seed = seed

    def __call__(self, mono) -> Fraction:
        key = self.seed + "|" + ",".join(f"{s}^{p}" for s, p in mono)
        rng = random.Random(key)
        return Fraction(rng.randrange(-(1 << 61), 1 << 61))

    def __getstate__(self):
        return self.seed

    def __setstate__(self, seed):
        if not isinstance(seed, str):
            raise TypeError("a draw's seed is text")
        self.seed = seed


def _cmul(a, b):
    return (a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0])


def _cpow(z, k):
    out = (Fraction(1), Fraction(0))
    if k < 0:
        z, k = (z[0], -z[1]), -k
    while k:
        if k & 1:
            out = _cmul(out, z)
        z = _cmul(z, z)
        k >>= 1
    return out


# -- polynomial view of an angle ------------------------------------------------------------
def _poly(tree, limit=40):
    """``{monomial: coefficient}`` of a polynomial tree (``pi`` as the monomial "pi"), or None."""
    op = tree[0]
    if op == "c":
        return {(): tree[1]}
    if op == "s":
        return {((tree[1], 1),): Fraction(1)}
    if op == "pi":
        return {_PI: Fraction(1)}
    if op == "add":
        out: dict = {}
        for c in tree[1]:
            p = _poly(c, limit)
            if p is None:
                return None
            for k, v in p.items():
                out[k] = out.get(k, 0) + v
        out = {k: v for k, v in out.items() if v != 0}
        return out if len(out) <= limit else None
    if op == "mul":
        out = {(): Fraction(1)}
        for c in tree[1]:
            p = _poly(c, limit)
            if p is None:
                return None
            out = _pmul(out, p)
            if out is None or len(out) > limit:
                return None
        return out
    if op == "pow" and tree[2] >= 0:
        p = _poly(tree[1], limit)
        out = {(): Fraction(1)}
        for _ in range(tree[2]):
            if p is None:
                return None
            out = _pmul(out, p)
            if out is None or len(out) > limit:
                return None
        return out
    return None


def _pmul(a, b):
    out: dict = {}
    for ka, va in a.items():
        for kb, vb in b.items():
            if ka == _PI or kb == _PI:
                if ka != () and kb != ():
                    return None  # pi times a symbol: not an angle we evaluate exactly
                k = _PI
            else:
                powers = dict(ka)
                for s, p in kb:
                    powers[s] = powers.get(s, 0) + p
                k = tuple(sorted(powers.items(), key=lambda sp_: str(sp_[0])))
            out[k] = out.get(k, 0) + va * vb
    return {k: v for k, v in out.items() if v != 0}


def _angle(tree):
    """``(((monomial, k), ...), twelfths)`` when ``tree`` is an integer combination of
    monomials plus a multiple of pi/12 (``cos(pi/6)`` of a 30-degree push: exact, in
    ``Q(sqrt 2, sqrt 3)``); else ``None`` (then only mpmath evaluates it)."""
    p = _poly(tree)
    if p is None:
        return None
    turn = 0
    parts = []
    for k, v in p.items():
        if k == _PI:
            if (12 * v).denominator != 1:
                return None
            turn = int(12 * v) % 24
        elif k == ():
            return None  # sin(1): a transcendental constant
        else:
            if v.denominator != 1 or abs(v) > _MAX_MULTIPLE:
                return None
            parts.append((k, int(v)))
    return tuple(sorted(parts, key=str)), turn


# -- formulas ---------------------------------------------------------------------------------
class Formula:
    """A resolved answer expression (see the module docstring).

    Attributes: ``tree`` (nested tuples), ``exact`` (evaluable in Fractions), ``degree``
    (bound on numerator + denominator degree in the sampled variables), ``symbols`` (the
    symbols it uses).  :meth:`evaluate` gives its value at an :class:`Env`.
    """

    __slots__ = ("tree", "exact", "degree", "symbols", "_fn", "_sympy", "text", "_parts",
                 "student", "roots", "state_roots")

    def __init__(self, tree, text: str = ""):
        self.tree = tree
        self.text = text
        self.symbols: set = set()
        self.roots: set = set()   # primes under the square roots of constants
        #: radicands (trees) of the square roots of expressions in the symbols
        self.state_roots: set = set()
        self.exact = True
        self._sympy = None
        self._parts = None
        #: ``(formula as written, StudentMap)`` when this formula is the student's answer
        #: rewritten from their own coordinates (:mod:`.maps`), else None
        self.student = None
        self.degree = sum(self._scan(tree)) << len(self.state_roots)   # the norm's degree
        self._few_roots()
        self._fn = self._compile(tree)

    def __getstate__(self):
        """What a stored context keeps of a formula: everything but the compiled closures
        (rebuilt from ``tree`` when read back)."""
        return {"tree": self.tree, "text": self.text, "sympy": self._sympy}

    def __setstate__(self, state):
        self.tree, self.text, self._sympy = state["tree"], state["text"], state["sympy"]
        self.symbols, self.exact, self._parts, self.student = set(), True, None, None
        self.roots, self.state_roots = set(), set()
        self.degree = sum(self._scan(self.tree)) << len(self.state_roots)
        self._few_roots()
        self._fn = None   # compiled when first evaluated

    # -- construction -----------------------------------------------------------------
    @classmethod
    def from_node(cls, node: Node, vocabulary: Vocabulary, limits: Limits = LIMITS,
                  text: str = "") -> "Formula":
        """Resolve the parser's tree against ``vocabulary`` (raises ``UnknownName``)."""
        check(node, limits)     # the cost model, before anything is computed
        _vectors_only_outside(node)
        tree = resolve(node, vocabulary, limits)
        f = cls(tree, text or to_text(node))
        size = _term_degree(tree)
        if size > limits.degree:
            raise AnswerTooLarge(f"a term of the answer has degree about {size}, above "
                                 f"{limits.degree}; write it with smaller powers.")
        return f

    @classmethod
    def from_sympy(cls, expr) -> "Formula":
        """A formula of a sympy expression built by the library (never of text)."""
        return cls(sympy_to_tree(expr), "")

    # -- facts ------------------------------------------------------------------------
    def _scan(self, tree):
        """Collect symbols and exactness; return the (numerator, denominator) degree bound."""
        op = tree[0]
        if op == "c":
            return (0, 0)
        if op == "s":
            self.symbols.add(tree[1])
            return (1, 0)
        if op == "pi":
            self.exact = False
            return (0, 0)
        if op == "add":
            parts = [self._scan(c) for c in tree[1]]
            den = sum(d for _, d in parts)
            return (max(n + den - d for n, d in parts), den)
        if op == "mul":
            parts = [self._scan(c) for c in tree[1]]
            return (sum(n for n, _ in parts), sum(d for _, d in parts))
        if op == "pow":
            n, d = self._scan(tree[1])
            k = tree[2]
            return (n * k, d * k) if k >= 0 else (d * -k, n * -k)
        if op == "rpow":
            root = surd_constant(tree)
            if root is None and tree[2].denominator == 2 and _has_symbol(tree[1]):
                # sqrt(X)**k of an expression: exact where the radicands are independent;
                # bounded as X**|k| (the norm's doubling is in the degree, see __init__)
                self.state_roots.add(tree[1])
                n, d = self._scan(tree[1])
                k = tree[2].numerator
                return (n * k, d * k) if k > 0 else (d * -k, n * -k)
            self.exact = self.exact and root is not None
            if isinstance(root, Surd):
                self.roots |= root.radicands
            self._scan(tree[1])
            return (0, 0)
        if op == "f":
            name, arg = tree[1], tree[2]
            inner = Formula.__new__(Formula)
            inner.symbols, inner.exact, inner.roots = set(), True, set()
            inner.state_roots = set()
            inner._scan(arg)
            if inner.state_roots:   # sin(sqrt(x)): not an angle evaluated exactly
                self.exact = False
            self.symbols |= inner.symbols
            self.roots |= inner.roots
            ang = _angle(arg) if name in _TRIG else None
            if ang is None:
                self.exact = False
                return (0, 0)
            if ang[1] % 6:      # cos(pi/6), sin(pi/4): in Q(sqrt 2, sqrt 3)
                self.roots |= TURN_ROOTS
            k = sum(abs(m) for _, m in ang[0])
            return (2 * k, 2 * k) if name in ("sin", "cos") else (4 * k, 4 * k)
        if op == "vec":
            parts = [self._scan(c) for c in tree[1]]
            return max(parts, key=sum, default=(0, 0))
        raise AssertionError(op)

    def _few_roots(self) -> None:
        """A formula with roots of more than :data:`MAX_ROOTS` primes is left to mpmath: the
        field's degree doubles with each (``sqrt 2 + sqrt 3 + sqrt 5 + ...`` to a power would
        have ``2**k`` coordinates), so a hostile answer cannot make exact arithmetic slow."""
        if len(self.roots) > MAX_ROOTS:
            self.exact = False

    def unknown_degree(self, unknowns: set) -> int | None:
        """Polynomial degree in ``unknowns`` (None if they appear non-polynomially)."""
        return _udeg(self.tree, unknowns)

    # -- evaluation -----------------------------------------------------------------------
    def evaluate(self, env: Env):
        """The value at ``env`` (a Fraction, an mpmath number, or a list for a vector)."""
        fn = self._fn
        if fn is None:
            fn = self._fn = self._compile(self.tree)
        if not self.state_roots or not env.exact:
            return fn(env)
        try:
            return fn(env)
        except NotExactHere:
            raise
        except ValueError as exc:   # roots of dependent radicands met (Surd's own check)
            raise NotExactHere(str(exc)) from None

    def _compile(self, tree):
        op = tree[0]
        if op == "c":
            v = tree[1]
            with mpmath.workdps(MP_DIGITS):
                mv = mpmath.mpf(v.numerator) / v.denominator
            return lambda env: v if env.exact else mv
        if op == "s":
            s = tree[1]
            return lambda env: env.values[s]
        if op == "pi":
            return lambda env: mpmath.pi if not env.exact else _not_exact()
        if op == "add":
            fs = [self._compile(c) for c in tree[1]]
            first, rest = fs[0], fs[1:]

            def add(env):
                v = first(env)
                for f in rest:
                    v = v + f(env)
                return v
            return add
        if op == "mul":
            fs = [self._compile(c) for c in tree[1]]
            first, rest = fs[0], fs[1:]

            def mul(env):
                v = first(env)
                for f in rest:
                    v = v * f(env)
                return v
            return mul
        if op == "pow":
            b, k = self._compile(tree[1]), tree[2]
            return lambda env: b(env) ** k
        if op == "rpow":
            b, e = self._compile(tree[1]), tree[2]
            with mpmath.workdps(MP_DIGITS):
                me = mpmath.mpf(e.numerator) / e.denominator
            exact = surd_constant(tree)
            if exact is not None:   # sqrt(3)/2 of a 30-degree push: exact in Q(sqrt 3)
                return lambda env: exact if env.exact else b(env) ** me
            if e.denominator == 2 and _has_symbol(tree[1]):   # sqrt(1 - a_z^2): see Env
                k = e.numerator
                return lambda env: state_root(b(env), k) if env.exact else b(env) ** me
            return lambda env: b(env) ** me if not env.exact else _not_exact()
        if op == "f":
            return self._compile_function(tree[1], tree[2])
        if op == "vec":
            fs = [self._compile(c) for c in tree[1]]
            return lambda env: [f(env) for f in fs]
        raise AssertionError(op)

    def _compile_function(self, name, arg):
        argf = self._compile(arg)
        mpf = _MP_FUNCS[name]
        ang = _angle(arg) if name in _TRIG else None
        if ang is None:
            return lambda env: mpf(argf(env)) if not env.exact else _not_exact()
        parts, turn = ang
        pick = {"sin": lambda z: z[1], "cos": lambda z: z[0], "tan": lambda z: z[1] / z[0],
                "cot": lambda z: z[0] / z[1], "sec": lambda z: 1 / z[0],
                "csc": lambda z: 1 / z[1]}[name]
        return lambda env: pick(env.angle(parts, turn)) if env.exact else mpf(argf(env))

    def term_values(self, env: Env) -> list:
        """Values of the top-level terms (the scale of a high-precision zero test)."""
        if self._parts is None:
            kids = self.tree[1] if self.tree[0] == "add" else (self.tree,)
            self._parts = [Formula(k) for k in kids]
        return [p.evaluate(env) for p in self._parts]

    def written_terms(self) -> list:
        """The top-level terms as written (sympy), for feedback that keeps them apart."""
        kids = self.tree[1] if self.tree[0] == "add" else (self.tree,)
        return [tree_to_sympy(k) for k in kids]

    def expanded_size(self) -> int:
        """Number of terms after expanding products (an upper estimate, capped)."""
        return _expanded_size(self.tree)

    # -- sympy, for display and symbolic feedback -------------------------------------
    def sympy(self):
        """The formula as a sympy expression (built from its tree, never from text)."""
        if self._sympy is None:
            self._sympy = tree_to_sympy(self.tree)
        return self._sympy

    def __repr__(self) -> str:
        return f"Formula({self.text or self.sympy()})"


def _vectors_only_outside(node: Node) -> None:
    """A vector ``[a, b, c]`` may be a whole answer, never a part of a formula."""
    root = node
    while root.op == "group":
        root = root.args[0]
    stack = list(root.args) if root.op == "vec" else [root]
    while stack:
        n = stack.pop()
        if n.op == "vec":
            raise AnswerError(f"`{to_text(n)}` is a vector inside a formula; a vector can only "
                              "be a whole answer, [a, b, c] with scalar components (no "
                              "vectors in functions, powers, products, sums or other "
                              "vectors).")
        stack.extend(n.children)


def _term_degree(tree) -> int:
    """Largest degree of one product in the formula (what sizes the exact numbers)."""
    op = tree[0]
    if op in ("c", "pi"):
        return 0
    if op == "s":
        return 1
    if op in ("add", "vec"):
        return max((_term_degree(c) for c in tree[1]), default=0)
    if op == "mul":
        return sum(_term_degree(c) for c in tree[1])
    if op in ("pow", "rpow"):
        return _term_degree(tree[1]) * max(1, abs(int(tree[2])))
    if op == "f":
        ang = _angle(tree[2]) if tree[1] in _TRIG else None
        if ang is None:
            return _term_degree(tree[2])
        return 4 * sum(abs(k) for _, k in ang[0])
    raise AssertionError(op)


def _expanded_size(tree, cap=10 ** 6) -> int:
    op = tree[0]
    if op in ("c", "s", "pi", "f", "rpow"):
        return 1
    if op in ("add", "vec"):
        return min(cap, sum(_expanded_size(c) for c in tree[1]))
    if op == "mul":
        out = 1
        for c in tree[1]:
            out = min(cap, out * _expanded_size(c))
        return out
    if op == "pow":
        return min(cap, _expanded_size(tree[1]) ** abs(tree[2])) if tree[2] else 1
    return 1


def difference(lhs: Formula, rhs: Formula | None) -> Formula:
    """``lhs - rhs`` as one flat sum (``lhs`` itself when there is no right side)."""
    if rhs is None:
        return lhs
    left = lhs.tree[1] if lhs.tree[0] == "add" else (lhs.tree,)
    right = rhs.tree[1] if rhs.tree[0] == "add" else (rhs.tree,)
    neg = tuple(("mul", (("c", Fraction(-1)), r)) for r in right)
    return Formula(("add", left + neg), f"{lhs.text} = {rhs.text}")


def _has_symbol(tree) -> bool:
    op = tree[0]
    if op == "s":
        return True
    if op in ("c", "pi"):
        return False
    if op in ("add", "mul", "vec"):
        return any(_has_symbol(c) for c in tree[1])
    return _has_symbol(tree[2] if op == "f" else tree[1])


def _not_exact():
    raise TypeError("this formula needs the high-precision method")


def _udeg(tree, unknowns):
    op = tree[0]
    if op in ("c", "pi"):
        return 0
    if op == "s":
        return 1 if tree[1] in unknowns else 0
    if op in ("add", "vec"):
        ds = [_udeg(c, unknowns) for c in tree[1]]
        return None if None in ds else max(ds)
    if op == "mul":
        ds = [_udeg(c, unknowns) for c in tree[1]]
        return None if None in ds else sum(ds)
    if op == "pow":
        d = _udeg(tree[1], unknowns)
        if d is None:
            return None
        if d and tree[2] < 0:
            return None
        return d * max(tree[2], 0)
    if op == "rpow":
        return 0 if _udeg(tree[1], unknowns) == 0 else None
    if op == "f":
        return 0 if _udeg(tree[2], unknowns) == 0 else None
    raise AssertionError(op)


# -- sympy conversions ----------------------------------------------------------------------
def tree_to_sympy(tree):
    """The sympy expression of a formula tree (built from symbols, never from text)."""
    op = tree[0]
    if op == "c":
        return sp.Rational(tree[1].numerator, tree[1].denominator)
    if op == "s":
        return tree[1]
    if op == "pi":
        return sp.pi
    if op == "add":
        return sp.Add(*[tree_to_sympy(c) for c in tree[1]])
    if op == "mul":
        return sp.Mul(*[tree_to_sympy(c) for c in tree[1]])
    if op == "pow":
        return sp.Pow(tree_to_sympy(tree[1]), sp.Integer(tree[2]))
    if op == "rpow":
        return sp.Pow(tree_to_sympy(tree[1]), sp.Rational(tree[2].numerator, tree[2].denominator))
    if op == "f":
        return _SP_FUNCS[tree[1]](tree_to_sympy(tree[2]))
    if op == "vec":
        return sp.Matrix([tree_to_sympy(c) for c in tree[1]])
    raise AssertionError(op)


_FROM_SP = {sp.sin: "sin", sp.cos: "cos", sp.tan: "tan", sp.cot: "cot", sp.sec: "sec",
            sp.csc: "csc", sp.exp: "exp", sp.log: "log"}


def sympy_to_tree(e):
    """The formula tree of a sympy expression built by the library."""
    if e.is_Integer or e.is_Rational:
        return ("c", Fraction(int(e.p), int(e.q)))
    if e is sp.pi:
        return ("pi",)
    if e.is_Symbol:
        return ("s", e)
    if e.is_Add:
        return ("add", tuple(sympy_to_tree(a) for a in e.args))
    if e.is_Mul:
        return ("mul", tuple(sympy_to_tree(a) for a in e.args))
    if e.is_Pow:
        base, ex = e.args
        if ex.is_Integer:
            return ("pow", sympy_to_tree(base), int(ex))
        if ex.is_Rational:
            return ("rpow", sympy_to_tree(base), Fraction(int(ex.p), int(ex.q)))
    if isinstance(e, sp.Function) and type(e) in _FROM_SP:
        return ("f", _FROM_SP[type(e)], sympy_to_tree(e.args[0]))
    if e.is_Float:
        return ("rpow", ("c", Fraction(str(e))), Fraction(1))
    raise TypeError(f"cannot evaluate {e} ({type(e).__name__}) in a grading formula")
