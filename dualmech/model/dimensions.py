"""Physical dimensions of symbols and a term-by-term audit of expressions.

A :class:`Dimension` is an immutable product of powers of the base dimensions (mass, length,
time, angle, current, temperature, amount of substance, luminous intensity), with rational
exponents; problems combine the named ones (:data:`MASS`, :data:`FORCE`, ...) with ``*``, ``/``
and ``**``.  :func:`reduce` turns one into base exponents; angles count as dimensionless there
(radians).  A sympy ``sympy.physics.units.Dimension`` is accepted wherever a dimension is taken
and converted (:func:`as_dimension`); sympy's units package is imported only then.

Example
-------
>>> import sympy as sp
>>> from dualmech.model.dimensions import MASS, LENGTH, TIME, ANGLE, audit
>>> from dualmech import coordinate, t
>>> m, l, g = sp.symbols("m l g"); th = coordinate("theta")
>>> dims = {m: MASS, l: LENGTH, g: LENGTH/TIME**2, th: ANGLE}
>>> audit(m*l**2*th.diff(t, 2) + m*g*l*sp.sin(th), dims)
[]
>>> eq = m*l*th.diff(t, 2) + m*g*l*sp.sin(th)
>>> [str(issue) for issue in audit(eq, dims, expected=MASS*LENGTH**2/TIME**2)]
["term `l*m*theta''` has dimension M L T^-2 where the rest has M L^2 T^-2"]
"""
from __future__ import annotations

import numbers
from collections import Counter
from fractions import Fraction
from typing import Mapping

import symengine as se
import sympy as sp

from dualmech.model import trees
from dualmech.model._algebra import to_se, to_sp
from dualmech.model._expr import as_expr, dotted
from dualmech.model.equations import state_symbols
from dualmech.model.kinematics import t

__all__ = ["BASES", "Dimension", "MASS", "LENGTH", "TIME", "ANGLE", "FORCE", "TORQUE", "ENERGY",
           "DIMENSIONLESS", "VELOCITY", "ACCELERATION", "STIFFNESS", "DAMPING",
           "TORSIONAL_STIFFNESS", "TORSIONAL_DAMPING", "INERTIA", "FREQUENCY",
           "DimensionIssue", "quoted", "as_dimension", "audit", "audit_rows", "dimension_of",
           "dimension_reader", "format_dimension", "reduce"]

#: the base dimensions, in the order :class:`Dimension` keeps them (sympy's SI names)
BASES = ("mass", "length", "time", "angle", "current", "temperature", "amount_of_substance",
         "luminous_intensity")
_SYMBOLS = ("M", "L", "T", "angle", "I", "Theta", "N", "J")


def _exponent(k, what: str) -> Fraction:
    """``k`` as an exact Fraction: an int, a Fraction, any rational number (sympy's too) or
    a float that is a simple fraction (``0.5``)."""
    if isinstance(k, bool):
        raise TypeError(f"{what} must be a rational number, got {k!r}.")
    if isinstance(k, numbers.Rational):
        return Fraction(int(k.numerator), int(k.denominator))
    if isinstance(k, float):
        f = Fraction(k)
        if f.denominator <= 1000:
            return f
        raise TypeError(f"{what} must be a rational number, got the float {k!r}: write it "
                        "as a Fraction.")
    if getattr(k, "is_Rational", False):   # symengine's Integer and Rational
        return Fraction(str(k))
    raise TypeError(f"{what} must be a rational number, got {k!r} ({type(k).__name__}).")


class Dimension:
    """A physical dimension: rational powers of the base dimensions in :data:`BASES`.

    Immutable and hashable; ``*``, ``/`` and ``**`` (rational exponents) combine dimensions,
    a plain number counts as dimensionless, and two dimensions are equal when their base
    exponents are.  Adding dimensions is an error: quantities of one dimension add, the
    dimension stays.  ``str`` gives ``M L T^-2``; :func:`reduce` the exponents angle aside.

    Example
    -------
    >>> from dualmech.model.dimensions import Dimension, MASS, LENGTH, TIME
    >>> force = MASS * LENGTH / TIME**2
    >>> force
    Dimension(mass=1, length=1, time=-2)
    >>> print(force, force**Fraction(1, 2))
    M L T^-2 M^1/2 L^1/2 T^-1
    >>> force == Dimension(mass=1, length=1, time=-2), force / force == Dimension()
    (True, True)
    """

    __slots__ = ("_exps", "_hash")

    def __init__(self, mass=0, length=0, time=0, angle=0, current=0, temperature=0,
                 amount_of_substance=0, luminous_intensity=0):
        exps = tuple(_exponent(e, f"the exponent of {name}") for name, e in zip(BASES, (
            mass, length, time, angle, current, temperature, amount_of_substance,
            luminous_intensity)))
        object.__setattr__(self, "_exps", exps)
        object.__setattr__(self, "_hash", hash(exps))

    @classmethod
    def _of(cls, exps: tuple) -> "Dimension":
        d = object.__new__(cls)
        object.__setattr__(d, "_exps", exps)
        object.__setattr__(d, "_hash", hash(exps))
        return d

    @property
    def exponents(self) -> dict:
        """The nonzero base exponents, ``{"mass": Fraction(1), ...}`` in :data:`BASES` order."""
        return {name: e for name, e in zip(BASES, self._exps) if e}

    def power(self, base: str) -> Fraction:
        """The exponent of ``base`` (a name in :data:`BASES`), 0 when absent."""
        try:
            return self._exps[BASES.index(base)]
        except ValueError:
            raise ValueError(f"`base` must be one of {', '.join(BASES)}; got {base!r}.") \
                from None

    # algebra ---------------------------------------------------------------------------
    def __mul__(self, other):
        other = _operand(other, "*")
        return Dimension._of(tuple(a + b for a, b in zip(self._exps, other._exps)))

    __rmul__ = __mul__

    def __truediv__(self, other):
        other = _operand(other, "/")
        return Dimension._of(tuple(a - b for a, b in zip(self._exps, other._exps)))

    def __rtruediv__(self, other):
        return _operand(other, "/") / self

    def __pow__(self, k):
        k = _exponent(k, "a dimension's power")
        return Dimension._of(tuple(e * k for e in self._exps))

    def _no_sum(self, other):
        raise TypeError(f"dimensions do not add: `{self} + {other}`; quantities of one "
                        "dimension add and keep it, dimensions only multiply, divide and "
                        "take powers.")

    __add__ = __radd__ = __sub__ = __rsub__ = _no_sum

    def __neg__(self):
        raise TypeError(f"a dimension has no sign: `-{self}`.")

    def __setattr__(self, name, value):
        raise AttributeError("a Dimension is immutable.")

    def __delattr__(self, name):
        raise AttributeError("a Dimension is immutable.")

    def __eq__(self, other):
        if isinstance(other, Dimension):
            return self._exps == other._exps
        return NotImplemented

    def __hash__(self):
        return self._hash

    def __reduce__(self):
        return (Dimension, self._exps)

    def __repr__(self):
        args = ", ".join(f"{name}={_number(e)}" for name, e in zip(BASES, self._exps) if e)
        return f"Dimension({args})"

    def __str__(self):
        parts = [s if e == 1 else f"{s}^{e}" for s, e in zip(_SYMBOLS, self._exps) if e]
        return " ".join(parts) or "1"


def _number(e: Fraction) -> str:
    return str(e.numerator) if e.denominator == 1 else f"Fraction({e.numerator}, {e.denominator})"


def _operand(other, op: str):
    """The other side of ``op`` as a Dimension: a Dimension, a sympy one, or a number (which
    is dimensionless); a ``TypeError`` for anything else."""
    if isinstance(other, Dimension):
        return other
    if _is_sympy_dimension(other):
        return _from_sympy(other)
    if isinstance(other, numbers.Number) and not isinstance(other, bool):
        return DIMENSIONLESS
    raise TypeError(f"a dimension {op} a dimension or a number makes sense, not {other!r} "
                    f"({type(other).__name__}).")


def _is_sympy_dimension(d) -> bool:
    """Whether ``d`` is a ``sympy.physics.units.Dimension`` (without importing that package)."""
    return type(d).__module__.startswith("sympy.physics.units") and type(d).__name__ == \
        "Dimension"


_FROM_SYMPY: dict = {}   # sympy Dimension -> ours (both immutable)


def _from_sympy(d) -> Dimension:
    hit = _FROM_SYMPY.get(d)
    if hit is None:
        from sympy.physics.units.systems.si import dimsys_SI
        exps = dict.fromkeys(BASES, Fraction(0))
        for base, e in dimsys_SI.get_dimensional_dependencies(d).items():
            name = str(getattr(base, "name", base))
            if name not in exps:
                raise ValueError(f"the sympy dimension {d} has the base {name!r}, which is "
                                 f"not one of {', '.join(BASES)}.")
            exps[name] = Fraction(str(e))
        hit = _FROM_SYMPY[d] = Dimension._of(tuple(exps.values()))
    return hit


def as_dimension(d) -> Dimension:
    """``d`` as a :class:`Dimension`: a Dimension as it is, a sympy
    ``sympy.physics.units.Dimension`` converted; a ``TypeError`` for anything else.

    Example
    -------
    >>> from sympy.physics.units.definitions import dimension_definitions as dd
    >>> as_dimension(dd.force)
    Dimension(mass=1, length=1, time=-2)
    """
    if isinstance(d, Dimension):
        return d
    if _is_sympy_dimension(d):
        return _from_sympy(d)
    raise TypeError(f"a dimension must be a dualmech.model.dimensions.Dimension (or a sympy "
                    f"Dimension), got {d!r} ({type(d).__name__}).")


MASS = Dimension(mass=1)
LENGTH = Dimension(length=1)
TIME = Dimension(time=1)
ANGLE = Dimension(angle=1)
DIMENSIONLESS = Dimension()
FORCE = MASS * LENGTH / TIME**2
TORQUE = FORCE * LENGTH
ENERGY = FORCE * LENGTH
VELOCITY = LENGTH / TIME
ACCELERATION = LENGTH / TIME**2
STIFFNESS = FORCE / LENGTH
DAMPING = FORCE / VELOCITY
TORSIONAL_STIFFNESS = TORQUE / ANGLE
TORSIONAL_DAMPING = TORQUE * TIME / ANGLE
INERTIA = MASS * LENGTH**2
FREQUENCY = 1 / TIME

_ORDER = ("mass", "length", "time", "current", "temperature", "amount_of_substance",
          "luminous_intensity")
_SHORT = {"mass": "M", "length": "L", "time": "T"}
_ANGLE = BASES.index("angle")

Dims = tuple  # ((base, Fraction exponent), ...) in _ORDER, angle dropped


def reduce(dim) -> Dims:
    """Base exponents of ``dim`` as a hashable tuple; angle is dropped (radians).

    ``dim`` is a :class:`Dimension`, a sympy Dimension, or a tuple this function returned.

    >>> reduce(FORCE / ANGLE)
    (('mass', Fraction(1, 1)), ('length', Fraction(1, 1)), ('time', Fraction(-2, 1)))
    """
    if isinstance(dim, tuple):
        return dim
    dim = as_dimension(dim)
    return tuple((name, e) for i, (name, e) in enumerate(zip(BASES, dim._exps))
                 if e and i != _ANGLE)


def format_dimension(d) -> str:
    """``M L^2 T^-2`` style text; ``1`` for dimensionless."""
    d = reduce(d)
    if not d:
        return "1"
    parts = []
    for name, e in d:
        s = _SHORT.get(name, name)
        parts.append(s if e == 1 else f"{s}^{e}")
    return " ".join(parts)


# Inside the audit a dimension is one integer: the base exponents in ``_ORDER``, each times
# ``_SCALE`` (so halves and thirds of roots stay integral), packed as balanced digits in base
# ``_BASE``.  A product of dimensions is then the sum of the integers, an integer power a
# product: no dictionaries or Fractions per node.
_SCALE = 60
_BASE = 1 << 24
_ZERO = 0


def _vec(d: Dims) -> int:
    out = 0
    for name, e in d:
        if name not in _ORDER:
            raise ValueError(f"unknown base dimension {name!r}")
        scaled = Fraction(e) * _SCALE
        if scaled.denominator != 1 or abs(scaled) >= _BASE // 2:
            raise ValueError(f"dimension exponent {e} of {name} is not supported")
        out += int(scaled) * _BASE ** _ORDER.index(name)
    return out


def _exponents(v: int) -> list:
    out = []
    for _ in _ORDER:
        digit = v % _BASE
        if digit >= _BASE // 2:
            digit -= _BASE
        out.append(digit)
        v = (v - digit) // _BASE
    return out


def _pairs(v: int) -> Dims:
    return tuple((name, Fraction(e, _SCALE)) for name, e in zip(_ORDER, _exponents(v))
                 if e != 0)


def _vadd(a: int, b: int, k: int = 1) -> int:
    return a + k * b


def _vscale(a: int, k) -> int:
    k = Fraction(k)
    if k.denominator == 1:
        return a * int(k)
    return _vec(tuple((name, e * k) for name, e in _pairs(a)))


def _vformat(v: int) -> str:
    return format_dimension(_pairs(v))


class DimensionIssue:
    """One inconsistency: ``term`` has ``found`` where ``expected`` was required.

    ``parts`` is the sentence that says so, text and sympy expressions (a page typesets the
    expressions, :func:`dualmech.model.notation.sentence` writes them in textbook text); ``str()``
    writes each expression as plain text between backticks.  ``term`` may be given as a
    function that writes it: it is then written when first read (most readers only read the
    sentence).
    """

    __slots__ = ("_term", "found", "expected", "parts")

    def __init__(self, term, found: str, expected: str, parts: tuple = ()):
        object.__setattr__(self, "_term", term)
        object.__setattr__(self, "found", found)
        object.__setattr__(self, "expected", expected)
        object.__setattr__(self, "parts", tuple(parts))

    def __setattr__(self, name, value):
        raise AttributeError(f"a DimensionIssue is read-only (cannot set `{name}`)")

    @property
    def term(self) -> str:
        """The offending term as plain text (primes for rates)."""
        if callable(self._term):
            object.__setattr__(self, "_term", self._term())
        return self._term

    def _key(self) -> tuple:
        return (self.term, self.found, self.expected, self.parts)

    def __eq__(self, other) -> bool:
        if not isinstance(other, DimensionIssue):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        return (f"DimensionIssue(term={self.term!r}, found={self.found!r}, "
                f"expected={self.expected!r}, parts={self.parts!r})")

    def sentence(self) -> tuple:
        """The sentence as text and expressions."""
        return self.parts or (f"term `{self.term}` has dimension {self.found} where the "
                              f"rest has {self.expected}",)

    def __str__(self) -> str:
        return quoted(self.sentence())


def quoted(sentence) -> str:
    """A sentence (text and expressions) as plain text, each expression between backticks:
    the form of :meth:`DimensionIssue.__str__` and :meth:`Problem.dimension_issues`."""
    return "".join(x if isinstance(x, str) else f"`{dotted(x)}`" for x in sentence)


class _Walker:
    """The audit of one expression tree: each distinct subexpression is visited once (its
    dimension memoised), so the cost is linear in the size of the shared tree."""

    def __init__(self, dims: Mapping):
        self.dims = {}
        for k, v in dims.items():
            self.dims[k] = _vec(reduce(v))
        self.dims.setdefault(t, _vec(reduce(TIME)))
        self.issues: list[DimensionIssue] = []
        self._memo: dict = dict(self.dims)   # declared symbols are their own memo entries
        self._seeded: set = set(self.dims)

    def forget(self) -> None:
        """Drop the memo of visited subexpressions (declared symbols stay)."""
        self._memo = {k: v for k, v in self._memo.items() if k in self._seeded}

    def __call__(self, e) -> tuple:
        d = self._memo.get(e)
        if d is None:
            d = self._memo[e] = self._visit(e)
        return d

    def _visit(self, e) -> tuple:
        k = trees.kind(e)
        if k in trees.NUMBERS or k is trees.CONSTANT:
            return _ZERO
        if k is trees.SYMBOL or k is trees.UNDEFINED:
            return self._undeclared(e)     # declared ones are in the memo from the start
        if k is trees.DERIVATIVE:
            expr, counts = trees.derivative_parts(e)
            d = self(expr)
            for var, n in counts:
                d = _vadd(d, self(var), -n)
            return d
        if k is trees.ADD:
            return self._add(e, None)
        if k is trees.MUL:
            d = _ZERO
            for a in e.args:
                d = _vadd(d, self(a))
            return d
        if k is trees.POW:
            b, x = e.args
            base = self(b)
            if trees.kind(x) in (trees.INTEGER, trees.RATIONAL, trees.FLOAT):
                return _vscale(base, trees.fraction(x))
            if base != _ZERO or self(x) != _ZERO:
                self._symbolic_power(e)
            return _ZERO
        if k is trees.FUNCTION:
            for a in e.args:
                self._dimensionless_argument(a, trees.name(e))
            return _ZERO
        raise TypeError(f"cannot find the dimension of {e!r}")

    def _issue(self, e, found: str, expected: str, *parts) -> None:
        # the term's text is written when someone reads it (the sentence holds the term)
        self.issues.append(DimensionIssue(lambda: self._show(e), found, expected, parts))

    def _symbolic_power(self, e) -> None:
        self._issue(e, "?", "1", self._sympy(e), ": a symbolic power needs a dimensionless "
                    "base and exponent")

    def _dimensionless_argument(self, a, function: str) -> None:
        d = self(a)
        if d != _ZERO:
            self._issue(a, _vformat(d), "1", "argument ", self._sympy(a),
                        f" of {function} has dimension {_vformat(d)}; it must be "
                        "dimensionless")

    def _undeclared(self, e) -> tuple:
        self._issue(e, "?", "?", self._sympy(e), " has no declared dimension")
        return _ZERO

    def _sympy(self, e):
        """``e`` as a sympy expression (what an issue's sentence holds)."""
        return e

    def _show(self, e) -> str:
        return dotted(self._sympy(e))

    def _add(self, e, expected) -> tuple:
        # zero has every dimension: it never conflicts (a reaction that vanishes, say)
        terms = [(a, self(a)) for a in trees.terms(e) if a != 0]
        if not terms:
            return expected if expected is not None else _ZERO
        counts = Counter(d for _, d in terms)
        if expected is None:
            if len(counts) == 1:
                return terms[0][1]
            ranked = counts.most_common()
            if ranked[0][1] == ranked[1][1]:
                listing: list = ["terms disagree: "]
                for i, (a, d) in enumerate(terms):
                    listing += (["; "] if i else []) + [self._sympy(a), f" has {_vformat(d)}"]
                self._issue(e, "mixed", "one dimension", *listing)
                return ranked[0][0]
            expected = ranked[0][0]
        for a, d in terms:
            if d != expected:
                self._issue(a, _vformat(d), _vformat(expected), "term ", self._sympy(a),
                            f" has dimension {_vformat(d)} where the rest has "
                            f"{_vformat(expected)}")
        return expected


class _SeWalker(_Walker):
    """:class:`_Walker` on symengine expressions (equations a derivation holds there).

    ``names`` maps symbol names back to sympy (see :func:`dualmech.model._algebra.to_sp`): a
    symbol's dimension is its sympy twin's; a plain state symbol (``theta_dot``) has its
    coordinate's dimension over time to the order of the derivative."""

    def __init__(self, dims: Mapping, names: Mapping):
        super().__init__(dims)
        self.names = names
        # plain state symbol -> (coordinate, order): the rate it stands for, built in sympy
        # only when an issue is shown (a derivative costs more than the audit itself)
        self._rate_of: dict = {}
        self._rates_sp: dict | None = None
        se_dims: dict = {}
        for name, obj in names.items():
            if not name.endswith("()") and obj in self.dims:
                se_dims[se.Symbol(name)] = self.dims[obj]
        for q, d in list(self.dims.items()):
            if not isinstance(q, sp.core.function.AppliedUndef):
                continue
            se_dims[to_se(q)] = d
            if q.args != (t,):
                continue
            st = state_symbols(q)
            for order, sym in enumerate((st.q, st.qd, st.qdd)):
                if names.get(sym.name) is sym:   # plain rows: q, q_dot, q_ddot
                    se_dims[se.Symbol(sym.name)] = _vadd(d, self.dims[t], -order)
                    self._rate_of[sym] = (q, order)
        se_dims[se.Symbol(t.name)] = self.dims[t]
        self._memo = se_dims   # declared symbols are their own memo entries
        self._seeded = set(se_dims)

    @property
    def _rates(self) -> dict:
        """``{plain state symbol: the rate it stands for}`` (``theta_dot -> theta'``)."""
        if self._rates_sp is None:
            self._rates_sp = {sym: q.diff(t, order) if order else q
                              for sym, (q, order) in self._rate_of.items()}
        return self._rates_sp

    def _sympy(self, e):
        return to_sp(e, self.names).xreplace(self._rates)


def audit(expr, dims: Mapping, expected=None, names: Mapping | None = None
          ) -> list[DimensionIssue]:
    """Every dimensional inconsistency in ``expr`` (an empty list when it is consistent).

    ``expected`` (a Dimension), when given, is the dimension every top-level term must have;
    otherwise the majority of the terms decides, and a tie is reported as such.  ``expr``
    may be a symengine expression held by a derivation, with its ``names`` (see
    :class:`dualmech.model.equations.Rows`).
    """
    held = trees.is_held(expr)
    w = _walker(dims, names, held)
    w._add(expr if held else as_expr(expr), None if expected is None else _vec(reduce(expected)))
    return w.issues


def _walker(dims: Mapping, names: Mapping | None, held: bool) -> _Walker:
    """The walker for symengine expressions (``held``, with their ``names``) or sympy ones."""
    return _SeWalker(dims, names or {}) if held else _Walker(dims)


def audit_rows(rows, dims: Mapping, expected=None, names: Mapping | None = None
               ) -> list[list[DimensionIssue]]:
    """:func:`audit` of each of ``rows`` (one derivation's equations), sharing one walk.

    ``expected`` is ``None`` or one Dimension (or ``None``) per row.  A subexpression the rows
    share is audited once, and an issue inside it is reported on the first row that has it.

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech.model.dimensions import MASS, LENGTH, TIME, audit_rows
    >>> m, l, x = sp.symbols("m l x")
    >>> issues = audit_rows([m*l + m*x, m*l + m*x + l], {m: MASS, l: LENGTH, x: LENGTH})
    >>> [[str(i) for i in row] for row in issues]
    [[], ['term `l` has dimension L where the rest has M L']]
    """
    rows = list(rows)
    if expected is None:
        expected = [None] * len(rows)
    held = bool(rows) and trees.is_held(rows[0])
    w = _walker(dims, names, held)
    out = []
    for e, x in zip(rows, expected):
        w.issues = []
        w._add(e if held else as_expr(e), None if x is None else _vec(reduce(x)))
        out.append(w.issues)
    return out


def dimension_reader(dims: Mapping, names: Mapping | None = None, held: bool = True):
    """A function ``expr -> dimension`` like :func:`dimension_of` that shares one walk (and
    its memo) between calls: for many expressions of one derivation.  ``held`` says whether
    the expressions are symengine ones (with ``names``) or sympy ones.

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech.model.dimensions import MASS, LENGTH, dimension_reader
    >>> m, l = sp.symbols("m l")
    >>> read = dimension_reader({m: MASS, l: LENGTH}, held=False)
    >>> read(m*l**2), read(l)
    ((('mass', Fraction(1, 1)), ('length', Fraction(2, 1))), (('length', Fraction(1, 1)),))
    """
    w = _walker(dims, names, held)

    def read(expr) -> Dims:
        w.issues = []
        d = w(expr if held else as_expr(expr))
        if w.issues:
            issues, w.issues = w.issues, []
            w.forget()   # so that the same expression raises again
            raise ValueError("; ".join(map(str, issues)))
        return _pairs(d)
    return read


def dimension_of(expr, dims: Mapping, names: Mapping | None = None) -> Dims:
    """Dimension of ``expr``; raises ``ValueError`` listing the issues when inconsistent."""
    held = trees.is_held(expr)
    w = _walker(dims, names, held)
    d = w(expr if held else as_expr(expr))
    if w.issues:
        raise ValueError("; ".join(map(str, w.issues)))
    return _pairs(d)
