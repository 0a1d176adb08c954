r"""Validation while typing: how an answer reads, before it is graded.

:func:`preview` parses the text with the grader's whitelisting parser (never evaluating it),
looks every name up in the problem's vocabulary and typesets the answer in MathML *as the
student wrote it* -- their order of terms, their brackets, ``theta''`` shown as a theta with
two dots.  Names the problem does not define are marked and listed with the closest accepted
ones; terms whose dimensions disagree are listed as the grader's audit words them (and as
HTML with each dimension typeset, exponents as superscripts).  Nothing
is graded here; it is cheap and bounded by the parser's :class:`~dualmech.grade.Limits`.

:func:`term_mathml` typesets one term of the feedback (``-g*sin(theta)``) the same way.

Example
-------
>>> from dualmech.web.catalog import ProblemInfo
>>> info = ProblemInfo.build("simple_pendulum")
>>> p = preview(info, "a*theta'' + g*sin(thetaa) = 0")
>>> p["ok"], [u["name"] for u in p["unknown"]], p["unknown"][0]["suggestions"][:1]
(False, ['thetaa'], ['theta'])
>>> p = preview(info, "a*theta'' + g*a = 0")
>>> p["ok"], p["dimensions"]
(True, ["the terms do not share one dimension: `a*theta''` has L T^-2; `a*g` has L^2 T^-2"])
>>> "<mi>&#952;&#776;</mi>" in preview(info, "theta''")["mathml"]   # theta, two dots above
True
"""
from __future__ import annotations

import difflib
import html
from fractions import Fraction

import sympy as sp

from dualmech.grade.audit import dimension_issues
from dualmech.grade.formula import Formula, difference
from dualmech.grade.parser import LIMITS, AnswerError, Limits, Node, parse
from dualmech.grade.vocabulary import UnknownName
from dualmech.model.kinematics import t
from dualmech.model import notation
from dualmech.report.mathml import text_html

__all__ = ["preview", "term_mathml", "PREVIEW_CHARS"]

#: Longest text previewed (the grader's own limit; the page refuses longer before sending).
PREVIEW_CHARS = LIMITS.chars
_INVISIBLE_TIMES = "<mo>&#x2062;</mo>"
_APPLY = "<mo>&#x2061;</mo>"


def preview(info, text: str, quantity: str | None = None, limits: Limits = LIMITS) -> dict:
    """How ``text`` reads as an answer to problem ``info`` (a
    :class:`~dualmech.web.catalog.ProblemInfo`).

    Returns ``{"ok", "error", "mathml", "unknown", "dimensions", "dimensions_html",
    "equations"}``: ``ok`` is true when the text parses and every name is known; ``error``
    the parser's message otherwise; ``unknown`` the unknown names, each with
    ``suggestions``; ``dimensions`` the dimension warnings (sentences), ``dimensions_html``
    the same escaped, each dimension in MathML.  Never raises for any text.
    """
    out = {"ok": False, "error": None, "mathml": "", "unknown": [], "dimensions": [],
           "dimensions_html": [], "equations": 0}
    try:
        eqs = parse(text, limits)
    except AnswerError as exc:
        out["error"] = str(exc)
        return out
    except RecursionError:
        out["error"] = "the answer nests too deeply."
        return out
    writer = _Writer(info, quantity)
    out["mathml"] = "".join(writer.equation(e.lhs, e.rhs) for e in eqs)
    out["equations"] = len(eqs)
    out["unknown"] = [{"name": n, "suggestions": s} for n, s in writer.unknown.items()]
    out["ok"] = not writer.unknown
    if out["ok"] and not writer.basis_used:
        out["dimensions"] = _dimensions(info, eqs, limits, out)
        out["dimensions_html"] = [text_html(d) for d in out["dimensions"]]
    return out


def term_mathml(info, text: str) -> str:
    """One term of the feedback (text the grader wrote in the student's notation) as MathML;
    escaped plain text in ``<code>`` when it does not parse."""
    try:
        eqs = parse(text)
    except AnswerError:
        return f"<code>{html.escape(text)}</code>"
    writer = _Writer(info, None, display="inline")
    return "".join(writer.equation(e.lhs, e.rhs) for e in eqs)


def _dimensions(info, eqs, limits, out) -> list[str]:
    ctx = info.context
    issues: list[str] = []
    for e in eqs:
        try:
            lhs = Formula.from_node(e.lhs, ctx.vocabulary, limits)
            rhs = Formula.from_node(e.rhs, ctx.vocabulary, limits) if e.rhs is not None \
                else None
            f = difference(lhs, rhs)
        except (AnswerError, UnknownName) as exc:
            out["ok"], out["error"] = False, str(exc)
            return issues
        issues += [i for i in dimension_issues(f.tree, ctx.dims, ctx.names) if i not in issues]
    return issues


class _Writer:
    """Presentation MathML of the parser's tree, names resolved in the problem's vocabulary."""

    def __init__(self, info, quantity: str | None, display: str = "block"):
        self.voc = info.context.vocabulary
        self.basis = set(_basis(info, quantity))
        self.display = display
        self.unknown: dict[str, list[str]] = {}
        self.basis_used = False
        self._symbols: dict = {}

    def equation(self, lhs: Node, rhs: Node | None) -> str:
        body = self.node(lhs)
        if rhs is not None:
            body += "<mo>=</mo>" + self.node(rhs)
        return (f'<math xmlns="http://www.w3.org/1998/Math/MathML" display="{self.display}">'
                f"<mrow>{body}</mrow></math>")

    def node(self, n: Node) -> str:
        op, a = n.op, n.args
        if op == "num":
            return _number(a[0])
        if op == "name":
            return self.name(a[0], a[1])
        if op == "group":
            return _fenced(self.node(a[0]))
        if op == "neg" or (op == "mul" and a[0].op == "neg"):
            return "<mrow><mo>&#x2212;</mo>" + self._operand(_negated(n), ("add", "neg")) + \
                "</mrow>"
        if op == "add":
            parts = [self.node(a[0])]
            for c in a[1:]:
                if c.op == "neg" or (c.op == "mul" and c.args[0].op == "neg"):
                    parts.append("<mo>&#x2212;</mo>" + self._operand(_negated(c), ("add", "neg")))
                else:
                    parts.append("<mo>+</mo>" + self.node(c))
            return "<mrow>" + "".join(parts) + "</mrow>"
        if op == "mul":
            return self._product(a)
        if op == "inv":
            return f"<mfrac><mn>1</mn><mrow>{self.node(a[0])}</mrow></mfrac>"
        if op == "pow":
            base, exp = a
            if base.op == "func" and base.args[0] != "sqrt":
                return (f"<msup><mi>{base.args[0]}</mi><mrow>{self.node(exp)}</mrow></msup>"
                        + _APPLY + self._argument(base.args[1]))
            inner = self.node(base) if base.op in ("num", "name", "group", "func") else \
                _fenced(self.node(base))
            return f"<msup><mrow>{inner}</mrow><mrow>{self.node(exp)}</mrow></msup>"
        if op == "func":
            name, arg = a
            if name == "sqrt":
                return f"<msqrt>{self.node(arg)}</msqrt>"
            return f"<mrow><mi>{name}</mi>{_APPLY}{self._argument(arg)}</mrow>"
        if op == "vec":
            inner = "<mo>,</mo>".join(self.node(c) for c in a)
            return f"<mrow><mo>[</mo>{inner}<mo>]</mo></mrow>"
        raise AssertionError(op)

    def _argument(self, arg: Node) -> str:
        return self.node(arg) if arg.op == "group" else _fenced(self.node(arg))

    def _operand(self, n: Node, wrap: tuple) -> str:
        return _fenced(self.node(n)) if n.op in wrap else self.node(n)

    def _product(self, factors) -> str:
        top = [f for f in factors if f.op != "inv"]
        bottom = [f.args[0] for f in factors if f.op == "inv"]

        def joined(items):
            out, prev = "", None
            for f in items:
                if prev is not None:
                    out += "<mo>&#x22C5;</mo>" if f.op == "num" else _INVISIBLE_TIMES
                out += self._operand(f, ("add", "neg"))
                prev = f
            return out
        if not bottom:
            return f"<mrow>{joined(top)}</mrow>"
        num = joined(top) if top else "<mn>1</mn>"
        den = joined([b.args[0] if b.op == "group" else b for b in bottom])
        return f"<mfrac><mrow>{num}</mrow><mrow>{den}</mrow></mfrac>"

    def name(self, text: str, primes: int) -> str:
        if text in self.basis and primes == 0:
            self.basis_used = True
            return f'<mi mathvariant="bold">{html.escape(text)}</mi>'
        try:
            refs = self.voc.resolve(text, primes)
        except UnknownName:
            typed = (text if len(text) <= 40 else text[:40] + "...") + "'" * primes
            if typed not in self.unknown:
                self.unknown[typed] = difflib.get_close_matches(
                    text, [k for k, v in self.voc.table.items() if v is not None], n=3,
                    cutoff=0.6)
            return f'<mi class="unknown" mathcolor="#b3261e">{html.escape(typed)}</mi>'
        return _INVISIBLE_TIMES.join(self._symbol(r) for r in refs)

    def _symbol(self, ref) -> str:
        key = (ref.kind, ref.base, ref.order, str(ref.symbol))
        if key not in self._symbols:
            if ref.kind == "coordinate":
                expr = sp.Function(ref.base)(t).diff(t, ref.order) if ref.order else \
                    sp.Function(ref.base)(t)
            else:
                expr = ref.symbol
            self._symbols[key] = notation.mathml(expr)
        return self._symbols[key]


def _negated(n: Node) -> Node:
    """``-x`` -> ``x``; ``(-x)*y`` -> ``x*y`` (the sign is written in front of the term)."""
    if n.op == "neg":
        return n.args[0]
    first = n.args[0].args[0]
    return Node("mul", (first,) + n.args[1:], (first,) + n.args[1:])


def _basis(info, quantity: str | None) -> tuple:
    if not quantity:
        return ()
    from dualmech.grade.answers import find_quantity
    try:
        return find_quantity(info.context, quantity).basis
    except AnswerError:
        return ()


def _number(v: Fraction) -> str:
    if v.denominator == 1:
        return f"<mn>{v.numerator}</mn>"
    d = v.denominator
    while d % 2 == 0:
        d //= 2
    while d % 5 == 0:
        d //= 5
    if d == 1 and v.denominator <= 10 ** 12:   # a decimal as typed (0.25)
        digits = len(str(v.denominator)) - 1 if str(v.denominator).strip("0") == "1" else 12
        text = f"{float(v):.{digits}f}".rstrip("0") if digits < 12 else repr(float(v))
        return f"<mn>{text}</mn>"
    return f"<mfrac><mn>{v.numerator}</mn><mn>{v.denominator}</mn></mfrac>"


def _fenced(inner: str) -> str:
    return f"<mrow><mo>(</mo>{inner}<mo>)</mo></mrow>"
