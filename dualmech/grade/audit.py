"""Answers shown as students write them, and their dimensions audited term by term.

Example
-------
>>> import sympy as sp
>>> th, thd = sp.symbols("theta theta_dot")
>>> display(2*thd*sp.sin(th), {thd: "theta'"})
"2*theta'*sin(theta)"
"""
from __future__ import annotations

import re

from sympy.printing.str import StrPrinter

from dualmech.model.dimensions import format_dimension, reduce
from dualmech.grade.formula import Formula, tree_to_sympy
from dualmech.grade.tidy import tidy

__all__ = ["display", "dimension_issues", "expected_dimension", "reduced", "Dims",
           "notation_of", "restyle", "label_words", "NOTATIONS"]

Dims = tuple


class _PrimePrinter(StrPrinter):
    """Plain state symbols printed as the student writes them: ``theta'``, ``theta''``."""

    def __init__(self, names: dict):
        super().__init__()
        self._names = names

    def _print_Symbol(self, expr):
        return self._names.get(expr, expr.name)

    def _as_ordered_terms(self, expr, order=None):
        """A sum led by a positive term, as a person writes it (``x2' - x1'``, not
        ``-x1' + x2'``)."""
        terms = super()._as_ordered_terms(expr, order=order)
        if terms and terms[0].could_extract_minus_sign():
            i = next((j for j, a in enumerate(terms) if not a.could_extract_minus_sign()), None)
            if i is not None:
                terms = [terms[i]] + terms[:i] + terms[i + 1:]
        return terms


def display(expr, names: dict | None = None) -> str:
    """``expr`` as text, with ``names`` (symbol -> text) for the coordinates' derivatives,
    powers written ``^`` as students type them, reduced as a person would write it
    (:func:`dualmech.grade.tidy.tidy`)."""
    return _PrimePrinter(names or {}).doprint(tidy(expr)).replace("**", "^")


#: How a student may write the rates of ``theta``: first and second derivative.
NOTATIONS = {
    "primes": ("{q}'", "{q}''"),
    "dot": ("{q}dot", "{q}ddot"),
    "_dot": ("{q}_dot", "{q}_ddot"),
    "_d": ("{q}_d", "{q}_dd"),
    "d": ("d{q}", "dd{q}"),
    "latex": ("\\dot{{{q}}}", "\\ddot{{{q}}}"),
    "unicode": ("{q}\u0307", "{q}\u0308"),
}


def notation_of(text: str, coordinates) -> str:
    """The way ``text`` writes rates (a key of :data:`NOTATIONS`; ``primes`` when it writes
    none or several ways).

    >>> notation_of("m*l^2*thetaddot + m*g*l*sin(theta)", ["theta"])
    'dot'
    """
    found = []
    for q in coordinates:
        e = re.escape(q)
        checks = [("primes", e + r"'"), ("latex", r"\\d+dot\{\\?" + e),
                  ("_dot", e + r"_d+ot\b"), ("dot", e + r"d+ot\b"), ("_d", e + r"_d+\b"),
                  ("unicode", e + "[\u0307\u0308]"), ("d", r"\bd+" + e + r"\b")]
        for key, pattern in checks:
            if re.search(pattern, text):
                found.append(key)
                break
    return found[0] if found and len(set(found)) == 1 else "primes"


def restyle(text: str, coordinates, notation: str = "primes") -> str:
    """``text`` as :func:`display` writes it (``theta'``, ``theta''``) in ``notation``.

    >>> restyle("2*theta'*phi''", ["theta", "phi"], "dot")
    '2*thetadot*phiddot'
    """
    if notation == "primes" or notation not in NOTATIONS or not text:
        return text
    one, two = NOTATIONS[notation]
    for q in sorted(coordinates, key=len, reverse=True):
        text = re.sub(r"(?<![A-Za-z0-9_])" + re.escape(q) + "''", two.format(q=q).replace(
            "\\", "\\\\"), text)
        text = re.sub(r"(?<![A-Za-z0-9_])" + re.escape(q) + "'", one.format(q=q).replace(
            "\\", "\\\\"), text)
    return text


def label_words(label: str) -> str:
    """A model row's label in words a student reads: no model name, no frame's axis label.

    A balance along an axis of the ground frame keeps its axis (``along y``); along a moving
    frame's axis (``B.y``, a name of the model's, not of the student's) it is named by body.

    >>> label_words("Lagrange, theta"), label_words("sum F . O.y (m2)")
    ('the theta equation', 'the force balance on m2 along y')
    >>> label_words("sum tau_G . b.x (body)")
    'a moment balance about G on body'
    """
    if label.startswith("Lagrange, "):
        return f"the {label[10:]} equation"
    if label.startswith("linearised, "):
        return f"the linearised {label[12:]} equation"
    if label.startswith("sum "):   # a force or moment balance, named as a teacher reads it
        from dualmech.model.notation import equation_words   # (only feedback naming a balance needs it)
        words = equation_words(label)
        if len(words) == 1 and not words[0].startswith("the equation "):
            head, along, axis = words[0].rpartition(" along ")
            return words[0] if "." not in axis else "a " + head[len("the "):]
    if " minus (" in label:
        return "a combination of balances that eliminates the reactions"
    return "a correct equation of the problem"


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
    """A Dimension (ours or sympy's) as the sorted tuple this module uses."""
    return tuple(sorted(reduce(dim)))
