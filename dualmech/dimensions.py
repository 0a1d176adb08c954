"""Physical dimensions of symbols and a term-by-term audit of expressions.

Dimensions are :class:`sympy.physics.units.Dimension` objects, reduced to base exponents with
sympy's SI dimension system; angles count as dimensionless (radians).

Example
-------
>>> import sympy as sp
>>> from dualmech.dimensions import MASS, LENGTH, TIME, ANGLE, audit
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

from collections import Counter
from dataclasses import dataclass
from fractions import Fraction
from typing import Mapping

import symengine as se
import sympy as sp
from sympy.physics.units import Dimension
from sympy.physics.units.definitions import dimension_definitions as _dd
from sympy.physics.units.systems.si import dimsys_SI

from ._algebra import to_se, to_sp
from ._expr import as_expr, dotted
from .equations import state_symbols
from .kinematics import t

__all__ = ["Dimension", "MASS", "LENGTH", "TIME", "ANGLE", "FORCE", "TORQUE", "ENERGY",
           "DIMENSIONLESS", "VELOCITY", "ACCELERATION", "STIFFNESS", "DAMPING",
           "TORSIONAL_STIFFNESS", "TORSIONAL_DAMPING", "INERTIA", "FREQUENCY",
           "DimensionIssue", "audit", "dimension_of", "format_dimension"]

MASS = _dd.mass
LENGTH = _dd.length
TIME = _dd.time
ANGLE = _dd.angle
DIMENSIONLESS = Dimension(1)
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

Dims = tuple  # sorted ((base, Fraction exponent), ...)


def reduce(dim) -> Dims:
    """Base exponents of ``dim`` as a hashable tuple; angle is dropped (radians)."""
    if isinstance(dim, tuple):
        return dim
    if not isinstance(dim, Dimension):
        raise TypeError(f"a dimension must be a sympy Dimension, got {dim!r}.")
    hit = _REDUCED.get(dim)
    if hit is None:
        hit = _REDUCED[dim] = _reduce(dim)
    return hit


_REDUCED: dict = {}   # Dimension -> its base exponents (Dimensions are immutable)


def _reduce(dim) -> Dims:
    deps = dimsys_SI.get_dimensional_dependencies(dim)
    out = {}
    for base, e in deps.items():
        name = str(base.name) if hasattr(base, "name") else str(base)
        if name == "angle":
            continue
        out[name] = Fraction(int(sp.Rational(e).p), int(sp.Rational(e).q))
    return tuple(sorted(((k, v) for k, v in out.items() if v != 0),
                        key=lambda kv: _ORDER.index(kv[0]) if kv[0] in _ORDER else 99))


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


def _mul(a: Dims, b: Dims, k=1) -> Dims:
    out = dict(a)
    for name, e in b:
        out[name] = out.get(name, 0) + k * e
    return tuple(sorted(((n, e) for n, e in out.items() if e != 0),
                        key=lambda kv: _ORDER.index(kv[0]) if kv[0] in _ORDER else 99))


def _pow(a: Dims, k) -> Dims:
    return tuple((n, e * k) for n, e in a) if k != 0 else ()


@dataclass(frozen=True)
class DimensionIssue:
    """One inconsistency: ``term`` has ``found`` where ``expected`` was required."""

    term: str
    found: str
    expected: str
    context: str = ""

    def __str__(self) -> str:
        if self.context:
            return self.context
        return (f"term `{self.term}` has dimension {self.found} where the rest has "
                f"{self.expected}")


class _Walker:
    def __init__(self, dims: Mapping):
        self.dims = {}
        for k, v in dims.items():
            self.dims[k] = reduce(v)
        self.dims.setdefault(t, reduce(TIME))
        self.issues: list[DimensionIssue] = []

    def __call__(self, e) -> Dims:
        if e.is_Number or e in (sp.pi, sp.E):
            return ()
        if e in self.dims:
            return self.dims[e]
        if e.is_Symbol or isinstance(e, sp.core.function.AppliedUndef):
            return self._undeclared(e)
        if isinstance(e, sp.Derivative):
            d = self(e.expr)
            for var, n in e.variable_count:
                d = _mul(d, self(var), -n)
            return d
        if e.is_Add:
            return self._add(e, None)
        if e.is_Mul:
            d: Dims = ()
            for a in e.args:
                d = _mul(d, self(a))
            return d
        if e.is_Pow:
            base = self(e.base)
            if e.exp.is_Number:
                return _pow(base, Fraction(str(sp.Rational(e.exp))))
            if base or self(e.exp):
                self.issues.append(DimensionIssue(dotted(e), "?", "1", f"`{dotted(e)}`: a symbolic power "
                                                  "needs a dimensionless base and exponent"))
            return ()
        if isinstance(e, sp.Function):
            for a in e.args:
                d = self(a)
                if d:
                    self.issues.append(DimensionIssue(
                        dotted(a), format_dimension(d), "1",
                        f"argument `{dotted(a)}` of {e.func.__name__} has dimension "
                        f"{format_dimension(d)}; it must be dimensionless"))
            return ()
        raise TypeError(f"cannot find the dimension of {e!r}")

    def _undeclared(self, e) -> Dims:
        self.issues.append(DimensionIssue(self._show(e), "?", "?",
                                          f"`{self._show(e)}` has no declared dimension"))
        return ()

    def _show(self, e) -> str:
        return dotted(e)

    def _terms(self, e):
        return sp.Add.make_args(e)

    def _add(self, e, expected) -> Dims:
        # zero has every dimension: it never conflicts (a reaction that vanishes, say)
        terms = [(a, self(a)) for a in self._terms(e) if a != 0]
        if not terms:
            return expected if expected is not None else ()
        counts = Counter(d for _, d in terms)
        if expected is None:
            ranked = counts.most_common()
            if len(ranked) > 1 and ranked[0][1] == ranked[1][1]:
                listing = "; ".join(f"`{self._show(a)}` has {format_dimension(d)}"
                                    for a, d in terms)
                self.issues.append(DimensionIssue(self._show(e), "mixed", "one dimension",
                                                  f"terms disagree: {listing}"))
                return ranked[0][0]
            expected = ranked[0][0]
        for a, d in terms:
            if d != expected:
                self.issues.append(DimensionIssue(self._show(a), format_dimension(d),
                                                  format_dimension(expected)))
        return expected


class _SeWalker(_Walker):
    """:class:`_Walker` on symengine expressions (equations a derivation holds there).

    ``names`` maps symbol names back to sympy (see :func:`dualmech._algebra.to_sp`): a
    symbol's dimension is its sympy twin's; a plain state symbol (``theta_dot``) has its
    coordinate's dimension over time to the order of the derivative."""

    def __init__(self, dims: Mapping, names: Mapping):
        super().__init__(dims)
        self.names = names
        self.se_dims: dict = {}
        for name, obj in names.items():
            if not name.endswith("()") and obj in self.dims:
                self.se_dims[se.Symbol(name)] = self.dims[obj]
        for q, d in list(self.dims.items()):
            if not isinstance(q, sp.core.function.AppliedUndef):
                continue
            self.se_dims[to_se(q)] = d
            if q.args != (t,):
                continue
            st = state_symbols(q)
            for order, sym in enumerate((st.q, st.qd, st.qdd)):
                if names.get(sym.name) is sym:   # plain rows: q, q_dot, q_ddot
                    self.se_dims[se.Symbol(sym.name)] = _mul(d, self.dims[t], -order)
        self.se_dims[se.Symbol(t.name)] = self.dims[t]

    def _show(self, e) -> str:
        return dotted(to_sp(e, self.names))

    def _terms(self, e):
        return e.args if e.is_Add else (e,)

    def __call__(self, e) -> Dims:
        if e.is_Number or e == se.pi or e == se.E:
            return ()
        d = self.se_dims.get(e)
        if d is not None:
            return d
        if e.is_Symbol or isinstance(e, se.FunctionSymbol):
            return self._undeclared(e)
        if e.is_Derivative:
            d = self(e.args[0])
            for var in e.args[1:]:
                d = _mul(d, self(var), -1)
            return d
        if e.is_Add:
            return self._add(e, None)
        if e.is_Mul:
            d = ()
            for a in e.args:
                d = _mul(d, self(a))
            return d
        if e.is_Pow:
            base = self(e.base)
            if isinstance(e.exp, (se.Integer, se.Rational)):
                p, q = e.exp.get_num_den()
                return _pow(base, Fraction(int(p), int(q)))
            if base or self(e.exp):
                self.issues.append(DimensionIssue(self._show(e), "?", "1", f"`{self._show(e)}`: "
                                                  "a symbolic power needs a dimensionless base "
                                                  "and exponent"))
            return ()
        for a in e.args:   # a function: every argument dimensionless
            d = self(a)
            if d:
                self.issues.append(DimensionIssue(
                    self._show(a), format_dimension(d), "1",
                    f"argument `{self._show(a)}` of {type(e).__name__} has dimension "
                    f"{format_dimension(d)}; it must be dimensionless"))
        return ()


def audit(expr, dims: Mapping, expected=None, names: Mapping | None = None
          ) -> list[DimensionIssue]:
    """Every dimensional inconsistency in ``expr`` (an empty list when it is consistent).

    ``expected`` (a Dimension), when given, is the dimension every top-level term must have;
    otherwise the majority of the terms decides, and a tie is reported as such.  ``expr``
    may be a symengine expression held by a derivation, with its ``names`` (see
    :class:`dualmech.equations.Rows`).
    """
    w = _SeWalker(dims, names or {}) if isinstance(expr, se.Basic) else _Walker(dims)
    w._add(expr if isinstance(expr, se.Basic) else as_expr(expr),
           None if expected is None else reduce(expected))
    return w.issues


def dimension_of(expr, dims: Mapping, names: Mapping | None = None) -> Dims:
    """Dimension of ``expr``; raises ``ValueError`` listing the issues when inconsistent."""
    if isinstance(expr, se.Basic):
        w = _SeWalker(dims, names or {})
        d = w(expr)
        if w.issues:
            raise ValueError("; ".join(map(str, w.issues)))
        return d
    w = _Walker(dims)
    d = w(as_expr(expr))
    if w.issues:
        raise ValueError("; ".join(map(str, w.issues)))
    return d
