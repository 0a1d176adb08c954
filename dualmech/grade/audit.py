"""Answers shown as students write them, and their dimensions audited term by term.

Example
-------
>>> import sympy as sp
>>> th, thd = sp.symbols("theta theta_dot")
>>> display(2*thd*sp.sin(th), {thd: "theta'"})
"2*theta'*sin(theta)"
"""
from __future__ import annotations

from sympy.printing.str import StrPrinter

from ..dimensions import format_dimension, reduce
from .formula import Formula, tree_to_sympy

__all__ = ["display", "dimension_issues", "expected_dimension", "reduced", "Dims"]

Dims = tuple


class _PrimePrinter(StrPrinter):
    """Plain state symbols printed as the student writes them: ``theta'``, ``theta''``."""

    def __init__(self, names: dict):
        super().__init__()
        self._names = names

    def _print_Symbol(self, expr):
        return self._names.get(expr, expr.name)


def display(expr, names: dict | None = None) -> str:
    """``expr`` as text, with ``names`` (symbol -> text) for the coordinates' derivatives."""
    s = _PrimePrinter(names or {}).doprint(expr)
    return s


def dimension_issues(tree, dims: dict, names: dict, expected: Dims | None = None) -> list[str]:
    """Terms of the formula whose dimensions disagree, as sentences (empty when consistent).

    ``dims`` maps every symbol to its reduced dimension (``dimensions.reduce``); angles are
    dimensionless.  ``expected``, when given, is the dimension the whole answer must have.
    """
    issues: list[str] = []
    top = _dim(tree, dims, names, issues)
    if not issues and expected is not None and top is not None and top != expected:
        issues.append(f"the answer has dimension {_fmt(top)}, but the quantity asked for has "
                      f"{_fmt(expected)}")
    return issues


def expected_dimension(formula: "Formula", dims: dict) -> Dims | None:
    """Dimension of a (library-built) formula, None when it is zero or inconsistent."""
    issues: list = []
    d = _dim(formula.tree, dims, {}, issues)
    return None if issues else d


def _fmt(d: Dims) -> str:
    return format_dimension(d) if d else "1 (dimensionless)"


def _dmul(a: Dims, b: Dims, k=1) -> Dims:
    out = dict(a)
    for name, e in b:
        out[name] = out.get(name, 0) + k * e
    return tuple(sorted((n, e) for n, e in out.items() if e != 0))


def _dim(tree, dims, names, issues) -> Dims | None:
    """Dimension of ``tree`` (None for zero, which has every dimension)."""
    op = tree[0]
    if op == "c":
        return None if tree[1] == 0 else ()
    if op == "pi":
        return ()
    if op == "s":
        return dims.get(tree[1], ())
    if op in ("add", "vec"):
        terms = [(c, _dim(c, dims, names, issues)) for c in tree[1]]
        known = [(c, d) for c, d in terms if d is not None]
        if not known:
            return None
        counts: dict = {}
        for _, d in known:
            counts[d] = counts.get(d, 0) + 1
        ranked = sorted(counts.items(), key=lambda kv: -kv[1])
        main = ranked[0][0]
        if len(ranked) > 1 and op == "add":
            if ranked[0][1] == ranked[1][1]:
                listing = "; ".join(f"`{display(tree_to_sympy(c), names)}` has {_fmt(d)}"
                                    for c, d in known)
                issues.append(f"the terms do not share one dimension: {listing}")
            else:
                for c, d in known:
                    if d != main:
                        issues.append(f"the term `{display(tree_to_sympy(c), names)}` has dimension "
                                      f"{_fmt(d)} where the other terms have {_fmt(main)}")
        return main
    if op == "mul":
        out: Dims = ()
        for c in tree[1]:
            d = _dim(c, dims, names, issues)
            if d is None:
                return None
            out = _dmul(out, d)
        return out
    if op in ("pow", "rpow"):
        d = _dim(tree[1], dims, names, issues)
        if d is None:
            return None
        k = tree[2]
        return tuple((n, e * k) for n, e in d) if k else ()
    if op == "f":
        d = _dim(tree[2], dims, names, issues)
        if tree[1] == "sqrt":
            return tuple((n, e / 2) for n, e in d) if d else d
        if d:
            issues.append(f"the argument `{display(tree_to_sympy(tree[2]), names)}` of {tree[1]} has "
                          f"dimension {_fmt(d)}; it must be dimensionless")
        return ()
    raise AssertionError(op)


def reduced(dim) -> Dims:
    """A sympy Dimension as the sorted tuple this module uses."""
    return tuple(sorted(reduce(dim)))
