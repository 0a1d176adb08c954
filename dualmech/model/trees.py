"""One reading of expression trees for sympy and symengine alike.

Derivations hold their equations in symengine; problems, answers and displays are in sympy.
The walkers that read a tree (the dimension audit, the exact world's scan, the rational
functions of the display) are written once against the few questions asked here: a node's
:func:`kind`, its arguments, its :func:`name` and its exact :func:`ratio`, whichever library
built it.  A node's kind is looked up by its type (one dictionary read after the first node of
that type), so a walker pays no more than the ``is_Add``/``is_Mul`` tests it replaces.

Kinds: :data:`ADD`, :data:`MUL`, :data:`POW` (``exp(x)`` in symengine is ``E**x``),
:data:`SYMBOL` (dummies too), :data:`INTEGER`, :data:`RATIONAL` (not an integer),
:data:`FLOAT`, :data:`SPECIAL` (``I``, complex numbers, infinities, ``nan``), :data:`CONSTANT`
(``pi``, ``E``, ``GoldenRatio``, ...), :data:`UNDEFINED` (an undefined function applied, such
as ``theta(t)``), :data:`DERIVATIVE`, :data:`FUNCTION` (any other function applied: ``sin``,
``Abs``, ``Piecewise``, ``Max``, ...) and :data:`OTHER` (relations, logic, integrals, ...).

Example
-------
>>> import symengine as se, sympy as sp
>>> x = sp.Symbol("x")
>>> [kind(e) for e in (x + 1, sp.sin(x), sp.Rational(1, 3), se.sin(se.Symbol("x")), se.pi)]
['add', 'function', 'rational', 'function', 'constant']
>>> name(se.cos(se.Symbol("x"))), name(sp.pi), ratio(se.Rational(-2, 6))
('cos', 'pi', (-1, 3))
>>> derivative_parts(sp.Function("f")(x).diff(x, 2))
(f(x), ((x, 2),))
"""
from __future__ import annotations

from fractions import Fraction
from functools import cache

import symengine as se
import sympy as sp
from sympy.core.function import AppliedUndef

__all__ = ["ADD", "MUL", "POW", "SYMBOL", "INTEGER", "RATIONAL", "FLOAT", "SPECIAL",
           "CONSTANT", "UNDEFINED", "DERIVATIVE", "FUNCTION", "OTHER", "NUMBERS", "kind",
           "name", "ratio", "fraction", "terms", "derivative_parts", "is_held", "is_dummy",
           "dummy"]

ADD, MUL, POW = "add", "mul", "pow"
SYMBOL, INTEGER, RATIONAL, FLOAT, SPECIAL = "symbol", "integer", "rational", "float", "special"
CONSTANT, UNDEFINED, DERIVATIVE = "constant", "undefined", "derivative"
FUNCTION, OTHER = "function", "other"
#: the kinds of numbers (a plain number, finite or not, real or not)
NUMBERS = frozenset((INTEGER, RATIONAL, FLOAT, SPECIAL))

# (class, kind), most specific first: the first class a node's type derives from gives its kind
_SYMPY = ((sp.Add, ADD), (sp.Mul, MUL), (sp.Pow, POW), (sp.Symbol, SYMBOL),
          (sp.Integer, INTEGER), (sp.Rational, RATIONAL), (sp.Float, FLOAT),
          (sp.Number, SPECIAL), (sp.core.numbers.ImaginaryUnit, SPECIAL),
          (sp.core.numbers.ComplexInfinity, SPECIAL),
          (sp.NumberSymbol, CONSTANT), (AppliedUndef, UNDEFINED),
          (sp.Derivative, DERIVATIVE), (sp.Function, FUNCTION),
          (sp.functions.elementary.miscellaneous.MinMaxBase, FUNCTION))


@cache
def _symengine() -> tuple:
    """The symengine table, made when the first symengine node is read (a one-answer
    ``dualmech grade`` from a stored context never loads symengine: see
    :func:`dualmech.startup.defer`)."""
    from symengine.lib.symengine_wrapper import Constant
    return ((se.Add, ADD), (se.Mul, MUL), (se.Pow, POW), (se.Symbol, SYMBOL),
            (se.Integer, INTEGER), (se.Rational, RATIONAL), (se.Float, FLOAT),
            (se.Number, SPECIAL), (Constant, CONSTANT), (se.FunctionSymbol, UNDEFINED),
            (se.Derivative, DERIVATIVE), (se.Function, FUNCTION))


_KINDS: dict = {}   # type -> kind, filled as types are met


def _classify(t: type) -> str:
    table = _symengine() if _from_symengine(t) else _SYMPY
    found = next((k for cls, k in table if issubclass(t, cls)), OTHER)
    _KINDS[t] = found
    return found


def _from_symengine(t: type) -> bool:
    return (t.__module__ or "").startswith("symengine")   # sympy's undefined functions: None


def kind(e) -> str:
    """The kind of the node ``e`` (a sympy or symengine expression): one of the module's
    constants."""
    k = _KINDS.get(type(e))
    return k if k is not None else _classify(type(e))


def is_held(e) -> bool:
    """Whether ``e`` is a symengine expression (one a derivation holds)."""
    return _from_symengine(type(e))


def name(e) -> str:
    """The name of a function applied (``"sin"``, ``"Abs"``, an undefined function's own), of
    a constant (``"pi"``, ``"E"``) or of a symbol."""
    k = kind(e)
    if k is SYMBOL:
        return e.name
    if k is UNDEFINED:
        return e.get_name() if is_held(e) else type(e).__name__
    if k is CONSTANT:
        return str(e)
    return type(e).__name__


def ratio(e) -> tuple[int, int]:
    """``(p, q)``, the value ``p/q`` in lowest terms (``q > 0``) of an :data:`INTEGER` or
    :data:`RATIONAL` node."""
    if is_held(e):
        if kind(e) is INTEGER:
            return int(e), 1
        p, q = e.get_num_den()
        return int(p), int(q)
    return int(e.p), int(e.q)


def fraction(e) -> Fraction:
    """The exact value of a rational node (:data:`INTEGER`, :data:`RATIONAL`) or of a
    :data:`FLOAT` (its binary value, as ``sympy.Rational(float)`` gives it)."""
    if kind(e) is FLOAT:
        return Fraction(float(e)) if is_held(e) else Fraction(*ratio(sp.Rational(e)))
    return Fraction(*ratio(e))


def terms(e) -> tuple:
    """The terms of a sum, or ``(e,)`` for any other node."""
    return e.args if kind(e) is ADD else (e,)


def derivative_parts(e) -> tuple:
    """``(expression, ((variable, count), ...))`` of a :data:`DERIVATIVE` node."""
    if is_held(e):
        out: dict = {}
        for v in e.args[1:]:   # symengine repeats a variable once per differentiation
            out[v] = out.get(v, 0) + 1
        return e.args[0], tuple(out.items())
    return e.expr, tuple(e.variable_count)


def is_dummy(e) -> bool:
    """Whether the :data:`SYMBOL` ``e`` is a dummy (never equal to a symbol of a problem)."""
    return isinstance(e, se.Dummy) if is_held(e) else isinstance(e, sp.Dummy)


def dummy(label: str, held: bool):
    """A fresh dummy symbol named ``label``, in symengine when ``held``, else in sympy."""
    return se.Dummy(label) if held else sp.Dummy(label)
