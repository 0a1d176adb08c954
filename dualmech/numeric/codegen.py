"""Generated numeric code: straight-line programs printed as Python/NumPy source.

A list of expressions in the state ``(t, q, q')`` and the parameters becomes one
:class:`Program`:

1. every input is renamed by position (``t_``, ``q_0``, ``u_0`` for ``q_0'``, ``p_0`` ...), so
   symbol names, assumptions or clashes never reach the printed code;
2. each expression is expanded (symengine) and written as a sum of *static* coefficients (the
   parameter-only factors) times *dynamic* monomials (products of powers of the state and of
   functions of it); every distinct coefficient becomes one static value ``k_i``, computed once
   per parameter set instead of once per call; ``c X cos^2 + c X sin^2`` becomes ``c X``.
   An expression whose expansion would run past :data:`EXPAND_LIMIT` terms (a bicycle's mass
   matrix: products of long sums) is not expanded: its tree is kept, its parameter-only sums
   and products hoisted as static values all the same;
3. each sum is factored by its most frequent factor, recursively (a multivariate Horner
   scheme), then common subexpressions of the dynamic part (and, separately, of the static
   part) are eliminated (``symengine.cse``);
4. the program is printed twice: scalar Python (``math``) for one state and NumPy for arrays of
   states (the same operations elementwise); :mod:`~dualmech.numeric.cbackend` prints it as C.

Expressions are never passed through text: symengine receives sympy objects, and the printer
walks symengine's trees.  Node types the printer does not know (``Piecewise``,
``Heaviside`` ...) are printed by sympy's own code printers.

Example
-------
>>> import sympy as sp
>>> x, v, k = sp.symbols("x v k")
>>> prog = program([k * sp.sin(x) * v**2], t=sp.Symbol("t"), q=[x], qd=[v], params=[k])
>>> src = python_source(prog, key="example", params=[k])
>>> "def vector" in src and "def scalar" in src
True
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import symengine as se
import sympy as sp

__all__ = ["GENERATOR_VERSION", "EXPAND_LIMIT", "Program", "Printer", "program", "python_source",
           "expanded_terms"]

#: Bumped whenever the generated code changes meaning or form (invalidates every cache entry).
GENERATOR_VERSION = "10"


@dataclass(frozen=True)
class Program:
    """Straight-line code computing ``outputs`` from ``(t_, q_i, u_i)``, ``p_i`` and ``k_i``.

    ``static`` assigns ``k_i`` (and temporaries) from the parameters ``p_i`` only; ``body``
    assigns temporaries from the state; ``outputs`` are expressions in all of these.
    """

    n: int
    n_params: int
    static: tuple
    static_names: tuple
    body: tuple
    outputs: tuple
    n_inputs: int = 0


class _Statics:
    """Distinct parameter-only coefficients, each given one symbol ``k_i``."""

    def __init__(self):
        self.defs: dict = {}

    def symbol(self, expr):
        if expr.is_Number:
            return expr
        hit = self.defs.get(expr)
        if hit is not None:
            return hit
        hit = self.defs.get(-expr)
        if hit is not None:
            return -hit
        s = se.Symbol(f"k_{len(self.defs)}")
        self.defs[expr] = s
        return s


_TRIG = ("sin", "cos")
_ELEMENTARY = {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
               "log", "Abs", "sign"}


class _Splitter:
    """Rewrites expressions as sums of static symbols times dynamic monomials."""

    def __init__(self, dynamic: set):
        self.dynamic = dynamic
        self.statics = _Statics()
        self._inner: dict = {}
        self._tree: dict = {}
        self._terms: dict = {}

    def is_static(self, e) -> bool:
        return not (e.free_symbols & self.dynamic)

    def groups(self, expr) -> dict:
        """``{dynamic monomial: static coefficient}`` of the expanded ``expr``."""
        out: dict = {}
        for term in _args(se.expand(expr), "Add"):
            st, dy = [], []
            for f in _args(term, "Mul"):
                (dy.append(self.inner(f)) if f.free_symbols & self.dynamic else st.append(f))
            d = se.Mul(*dy)
            out[d] = out.get(d, 0) + se.Mul(*st)
        return _pythagoras({d: c for d, c in out.items() if c != 0})

    def split(self, expr):
        """``expr`` as static coefficients times dynamic monomials, with the most frequent
        factors taken out of the sums (``s1 (k1 c2 + k2 c3)``, not ``k1 s1 c2 + k2 s1 c3``).

        An expression whose expansion would exceed :data:`EXPAND_LIMIT` terms keeps its tree
        (:meth:`tree`): expanding a bicycle's mass matrix multiplies out products of long
        sums."""
        if self.is_static(expr):
            return self.statics.symbol(expr)
        if expanded_terms(expr, self._terms) > EXPAND_LIMIT:
            return self.tree(expr)
        terms = []
        for d, c in self.groups(expr).items():
            k = self.statics.symbol(c)
            terms.append([f for f in _args(k, "Mul") + _args(d, "Mul") if f != 1])
        return _horner(terms)

    def tree(self, e):
        """``e`` as it is written, its parameter-only sums and products hoisted as statics."""
        if self.is_static(e):
            return self.statics.symbol(e)
        hit = self._tree.get(e)
        if hit is not None:
            return hit
        name = type(e).__name__
        if name in ("Add", "Mul"):
            op = se.Add if name == "Add" else se.Mul
            fixed = [a for a in e.args if self.is_static(a)]
            moving = [self.tree(a) for a in e.args if not self.is_static(a)]
            hit = op(*([self.statics.symbol(op(*fixed))] if fixed else []), *moving)
        else:
            hit = self.inner(e)
        self._tree[e] = hit
        return hit

    def bound(self, e):
        """An upper bound of ``|e|`` without expanding (sin, cos taken as 1): the magnitude of
        an expression too large to expand."""
        if self.is_static(e):
            return self.statics.symbol(se.Abs(e))
        name = type(e).__name__
        if name in ("Add", "Mul"):
            return (se.Add if name == "Add" else se.Mul)(*[self.bound(a) for a in e.args])
        if name in _TRIG:
            return se.Integer(1)
        if name == "Pow" and e.args[1].is_Integer and e.args[1] > 0:
            return self.bound(e.args[0]) ** e.args[1]
        return se.Abs(self.inner(e))

    def inner(self, f):
        """A dynamic factor with the static parts of its arguments hoisted as well."""
        if f.is_Symbol:
            return f
        hit = self._inner.get(f)
        if hit is None:
            name = type(f).__name__
            if name == "Pow":
                base, ex = f.args
                new_base = base if base.is_Symbol else self.split(base)
                hit = se.Pow(new_base, ex if self.is_static(ex) else self.split(ex))
            elif name in _ELEMENTARY:
                hit = f.func(*[self.split(a) for a in f.args])
            else:  # Piecewise, Heaviside, ...: printed as they are
                hit = f
            self._inner[f] = hit
        return hit

    def magnitude(self, exprs) -> object:
        """Sum over ``exprs`` of the terms' absolute values with every sin/cos taken as 1.

        A pivot far below this size is a cancellation to zero: the matrix is singular there
        even when its condition number (which ignores scale) looks harmless.
        """
        by_mono: dict = {}
        bounds = []
        for e in exprs:
            if not self.is_static(e) and expanded_terms(e, self._terms) > EXPAND_LIMIT:
                bounds.append(self.bound(e))
                continue
            if self.is_static(e):
                by_mono[se.Integer(1)] = by_mono.get(se.Integer(1), 0) + se.Abs(e)
                continue
            for d, c in self.groups(e).items():
                mono = se.Mul(*[_untrig(f) for f in _args(d, "Mul")])
                by_mono[mono] = by_mono.get(mono, 0) + se.Abs(c)
        return se.Add(*[self.statics.symbol(c) * m for m, c in by_mono.items()], *bounds)


#: Estimated terms of an expanded expression beyond which :meth:`_Splitter.split` keeps the
#: tree (the estimate multiplies the terms of a product's factors: an upper bound).
EXPAND_LIMIT = 400


def expanded_terms(e, memo: dict) -> int:
    """Upper bound on the terms of ``se.expand(e)`` (capped just above the limit); a factor
    with a negative or fractional power counts one (it is split on its own).

    >>> import symengine as se
    >>> a, b, c = se.symbols("a b c")
    >>> expanded_terms((a + b) * (a + c + 1) ** 2 + 1 / (a + b), {})   # 2 * 3**2 + 1
    19
    """
    hit = memo.get(e)
    if hit is not None:
        return hit
    name = type(e).__name__
    if name == "Add":
        n = sum(expanded_terms(a, memo) for a in e.args)
    elif name == "Mul":
        n = 1
        for a in e.args:
            n = min(n * expanded_terms(a, memo), EXPAND_LIMIT + 1)
    elif name == "Pow" and e.args[1].is_Integer and e.args[1] > 0:
        n = expanded_terms(e.args[0], memo) ** min(int(e.args[1]), 64)
    else:
        n = 1
    memo[e] = n = min(n, EXPAND_LIMIT + 1)
    return n


def _pythagoras(groups: dict) -> dict:
    """Merge ``c X cos(a)^2 + c X sin(a)^2`` into ``c X`` (same coefficient ``c`` only, so no
    cancellation is introduced: ``1 - sin^2`` would lose digits where ``cos`` is small)."""
    changed = True
    while changed:
        changed = False
        for d in list(groups):
            for f in _args(d, "Mul"):
                if not (type(f).__name__ == "Pow" and f.args[1] == 2
                        and type(f.args[0]).__name__ == "cos"):
                    continue
                rest = d / f
                partner = rest * se.sin(f.args[0].args[0]) ** 2
                if partner in groups and se.expand(groups[partner] - groups[d]) == 0:
                    c = groups.pop(d)
                    groups.pop(partner)
                    groups[rest] = groups.get(rest, 0) + c
                    if groups[rest] == 0:
                        del groups[rest]
                    changed = True
                    break
            if changed:
                break
    return groups


def _horner(terms: list) -> object:
    """The sum of the products ``terms`` (lists of factors), the most frequent factor taken
    out first, recursively (a multivariate Horner scheme: fewer multiplications)."""
    if len(terms) < 2:
        return se.Add(*[se.Mul(*t) for t in terms])
    counts: dict = {}
    for t in terms:
        for f in set(t):
            if not f.is_Number:
                counts[f] = counts.get(f, 0) + 1
    best = max(counts.items(), key=lambda kv: kv[1], default=(None, 0))
    if best[1] < 2:
        return se.Add(*[se.Mul(*t) for t in terms])
    f = best[0]
    inside, outside = [], []
    for t in terms:
        if f in t:
            rest = list(t)
            rest.remove(f)
            inside.append(rest)
        else:
            outside.append(t)
    return se.Add(se.Mul(f, _horner(inside)), _horner(outside))


def _untrig(f):
    """``|f|`` with sin/cos (and their powers) replaced by 1."""
    name = type(f).__name__
    if name in _TRIG:
        return se.Integer(1)
    if name == "Pow" and type(f.args[0]).__name__ in _TRIG:
        return se.Integer(1) if f.args[1].is_Number and f.args[1] > 0 else se.Abs(f)
    return se.Abs(f)


def _args(e, kind: str) -> tuple:
    return e.args if type(e).__name__ == kind else (e,)


def _positional(t, q, qd, params, inputs=()):
    """Renaming of the inputs to positional symbols."""
    rename = {t: sp.Symbol("t_")}
    rename.update({s: sp.Symbol(f"q_{i}") for i, s in enumerate(q)})
    rename.update({s: sp.Symbol(f"u_{i}") for i, s in enumerate(qd)})
    rename.update({s: sp.Symbol(f"p_{i}") for i, s in enumerate(params)})
    rename.update({s: sp.Symbol(f"w_{i}") for i, s in enumerate(inputs)})
    return rename


def program(outputs: Sequence, *, t, q: Sequence, qd: Sequence, params: Sequence,
            scale_of: int = 0, inputs: Sequence = ()) -> Program:
    """Compile sympy ``outputs`` in ``t``, ``q``, ``qd`` (plain symbols) and ``params``.

    With ``scale_of = k > 0`` one output is appended: the magnitude (see
    :meth:`_Splitter.magnitude`) of the first ``k`` outputs.  ``inputs`` are symbols whose
    values change with time (given inputs ``F(t)``): named ``w_i`` and dynamic like the state,
    never part of a static coefficient; the printer that uses such a program defines each
    ``w_i`` (:func:`dualmech.numeric.cbackend.c_source`'s ``input_code``).
    """
    rename = {se.Symbol(k.name): se.Symbol(v.name)
              for k, v in _positional(t, q, qd, params, inputs).items()}
    if len(rename) != 1 + len(q) + len(qd) + len(params) + len(inputs):
        raise ValueError("two inputs share a name; give every state symbol and parameter "
                         "its own name.")
    # symengine receives sympy objects (converted node by node, never through text)
    exprs = [se.sympify(o).xreplace(rename) for o in outputs]
    extra = set().union(*[e.free_symbols for e in exprs]) - set(rename.values())
    if extra:
        raise ValueError(f"the expressions use {sorted(map(str, extra))}, which are neither "
                         "state symbols nor parameters.")
    dynamic = {se.Symbol("t_")} | {se.Symbol(f"q_{i}") for i in range(len(q))} \
        | {se.Symbol(f"u_{i}") for i in range(len(qd))} \
        | {se.Symbol(f"w_{i}") for i in range(len(inputs))}
    splitter = _Splitter(dynamic)
    split = [splitter.split(e) for e in exprs]
    if scale_of:
        split.append(splitter.magnitude(exprs[:scale_of]))
    names = tuple(splitter.statics.defs.values())
    static_repl, static_out = se.cse(list(splitter.statics.defs.keys())) if names else ([], [])
    body, outs = se.cse(split)
    # temporaries are x0, x1, ... in each of two scopes (static, and per state): no clash
    # with the positional inputs t_, q_i, u_i, p_i, k_i
    return Program(len(q), len(params), tuple(static_repl) + tuple(zip(names, static_out)),
                   names, tuple(body), tuple(outs), len(inputs))


# -- printing ----------------------------------------------------------------------------

_PY_FUNCS = {"sin": "_sin", "cos": "_cos", "tan": "_tan", "asin": "_asin", "acos": "_acos",
             "atan": "_atan", "atan2": "_atan2", "sinh": "_sinh", "cosh": "_cosh",
             "tanh": "_tanh", "log": "_log", "Abs": "abs"}
_NP_FUNCS = {"sin": "_np.sin", "cos": "_np.cos", "tan": "_np.tan", "asin": "_np.arcsin",
             "acos": "_np.arccos", "atan": "_np.arctan", "atan2": "_np.arctan2",
             "sinh": "_np.sinh", "cosh": "_np.cosh", "tanh": "_np.tanh", "log": "_np.log",
             "Abs": "_np.abs", "sign": "_np.sign"}


class Printer:
    """Python source of symengine expressions; ``numpy`` selects elementwise functions."""

    language = "python"

    def __init__(self, numpy: bool = False):
        self.numpy = numpy
        self.funcs = _NP_FUNCS if numpy else _PY_FUNCS
        self.exp = "_np.exp" if numpy else "_exp"
        self.sqrt = "_np.sqrt" if numpy else "_sqrt"

    def power(self, base: str, ex: str) -> str:
        if self.numpy:
            return f"{base}**{ex}"
        return f"_pow({base}, {ex})"  # math.pow: an error, never a complex number

    def __call__(self, e) -> str:
        name = type(e).__name__
        method = getattr(self, f"_{name}", None)
        if method is not None:
            return method(e)
        if e.is_Number:
            return repr(float(e))
        if name in self.funcs:
            return f"{self.funcs[name]}({', '.join(self(a) for a in e.args)})"
        return self._sympy(e)

    def _Symbol(self, e):
        return e.name

    def _Integer(self, e):
        return f"{int(e)}.0" if abs(int(e)) < 2**53 else repr(float(e))

    def _Pi(self, e):
        return repr(float(e))

    _Exp1 = _Pi

    def _Add(self, e):
        return _sum_text([self(a) for a in e.args])

    def _Mul(self, e):
        num, den, sign = [], [], ""
        for a in e.args:
            if a.is_Number and a == -1:
                sign = "-"
            elif type(a).__name__ == "Pow" and a.args[1].is_Number and a.args[1] < 0:
                den.append(self(se.Pow(a.args[0], -a.args[1])))
            else:
                num.append(self(a))
        text = _product_text(num) if num else "1.0"
        if den:
            text += f"/({_product_text(den)})"
        return f"{sign}{text}"

    def _Pow(self, e):
        base, ex = e.args
        if type(base).__name__ == "Exp1":
            return f"{self.exp}({self(ex)})"
        b = self(base)
        atom = base.is_Symbol or type(base).__name__ in self.funcs
        b = b if atom or b.startswith("(") else f"({b})"
        if ex.is_Integer:
            k = int(ex)
            if 0 < k <= 3:
                return "*".join([b] * k)
            if -3 <= k < 0:
                return f"(1.0/({'*'.join([b] * -k)}))"
            return self.power(b, str(k))
        if ex.is_Number and ex == se.Rational(1, 2):
            return f"{self.sqrt}({self(base)})"
        if ex.is_Number and ex == se.Rational(-1, 2):
            return f"(1.0/{self.sqrt}({self(base)}))"
        return self.power(b, f"({self(ex)})")

    def _sign(self, e):
        if self.numpy:
            return f"_np.sign({self(e.args[0])})"
        return f"_sign({self(e.args[0])})"

    def sympy_printer(self):
        from sympy.printing.numpy import NumPyPrinter
        from sympy.printing.pycode import PythonCodePrinter
        return NumPyPrinter({"fully_qualified_modules": True}) if self.numpy \
            else PythonCodePrinter({"fully_qualified_modules": True})

    def _sympy(self, e) -> str:
        """Node types we do not print ourselves: sympy's code printers."""
        expr = sp.sympify(e, strict=True)  # a symengine object, converted through its own _sympy_
        text = self.sympy_printer().doprint(expr)
        if "Not supported" in text:
            raise NotImplementedError(f"cannot generate code for {expr}")
        return f"({text})"


#: Terms or factors printed in one run; longer sums and products are printed in parenthesised
#: runs of runs, so the parsed tree stays shallow (CPython's compiler refuses a chain of a few
#: thousand ``+``: "maximum recursion depth exceeded during compilation").
RUN = 64


def _sum_text(parts: list) -> str:
    """``(a + b - c ...)`` in parenthesised runs of at most :data:`RUN` terms."""
    if len(parts) > RUN:
        return _sum_text([_sum_text(parts[i:i + RUN]) for i in range(0, len(parts), RUN)])
    text = parts[0]
    for p in parts[1:]:
        text += f" - {p[1:]}" if p.startswith("-") and not p.startswith("-(") else f" + {p}"
    return f"({text})"


def _product_text(parts: list) -> str:
    """``a*b*c ...`` in parenthesised runs of at most :data:`RUN` factors."""
    if len(parts) > RUN:
        return _product_text([f"({_product_text(parts[i:i + RUN])})"
                              for i in range(0, len(parts), RUN)])
    return "*".join(parts)


def _block(assignments, printer, indent: str) -> list[str]:
    return [f"{indent}{s.name} = {printer(e)}" for s, e in assignments]


def _unpack(names: Sequence[str], source: str, indent: str) -> list[str]:
    if not names:
        return []
    return [f"{indent}{', '.join(names)}, = {source}"]


def python_source(prog: Program, key: str, params: Sequence = ()) -> str:
    """A module with ``static(p)``, ``scalar(p, k)`` and ``vector(p, k)``.

    ``params`` (the parameter symbols, in order) are recorded as ``PARAMS``: names and
    assumptions, from which a cache hit rebuilds the symbols without reading the equations.

    ``static(p)`` returns the tuple ``k`` of static values; ``scalar(p, k)`` and
    ``vector(p, k)`` return ``evaluate(t_, y)`` for one state (a list ``[q..., q'...]``) or for
    states in the columns of an array ``(2n, K)``, giving the tuple of outputs.
    """
    if prog.n_inputs:
        raise ValueError("a program with time-varying inputs w_i is printed as C only "
                         "(cbackend.c_source defines them); Python binds inputs as parameters.")
    n = prog.n
    p_names = [f"p_{i}" for i in range(prog.n_params)]
    states = [f"q_{i}" for i in range(n)] + [f"u_{i}" for i in range(n)]
    k_names = [s.name for s in prog.static_names]
    lines = [f'"""Generated by dualmech.numeric.codegen {GENERATOR_VERSION}; do not edit."""',
             "import math as _m", "import numpy as _np", "",
             "from math import (sin as _sin, cos as _cos, tan as _tan, asin as _asin, "
             "acos as _acos, atan as _atan,", "                  atan2 as _atan2, sinh as _sinh, "
             "cosh as _cosh, tanh as _tanh, log as _log, exp as _exp, sqrt as _sqrt,",
             "                  pow as _pow)",
             "math = _m", "numpy = _np", "",
             f"KEY = {key!r}", f"VERSION = {GENERATOR_VERSION!r}",
             f"N_OUTPUTS = {len(prog.outputs)}",
             "PARAMS = " + repr(tuple((s.name, dict(sorted(s.assumptions0.items())))
                                      for s in params)), "", "",
             "def _sign(x):", "    return (x > 0) - (x < 0)", "", "",
             "def static(p):"]
    lines += _unpack(p_names, "p", "    ")
    scalar = Printer(numpy=False)
    lines += _block(prog.static, scalar, "    ")
    lines += [f"    return ({''.join(k + ', ' for k in k_names)})", ""]
    for kind, printer in (("scalar", scalar), ("vector", Printer(numpy=True))):
        lines += ["", f"def {kind}(p, k):"]
        lines += _unpack(p_names, "p", "    ") + _unpack(k_names, "k", "    ")
        lines += ["", "    def evaluate(t_, y):"]
        lines += _unpack(states, "y", "        ")
        lines += _block(prog.body, printer, "        ")
        outs = ", ".join(printer(o) for o in prog.outputs)
        lines += [f"        return ({outs},)", "", "    return evaluate", ""]
    return "\n".join(lines) + "\n"
