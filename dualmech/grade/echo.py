"""Terms echoed the way the student typed the answer: LaTeX as LaTeX, letters as letters.

A student who typed ``a\\ddot{\\theta} - g\\sin\\theta = 0`` reads the feedback's terms in the
same spelling -- ``\\ddot{\\theta}``, ``g \\sin\\theta``, ``\\frac{1}{2}`` if they wrote
fractions so -- and one who typed ``θ̈`` reads ``θ``.  :func:`spelling` learns from the answer's
text how it writes each name, a rate, a function, a product and a fraction;
:func:`to_latex` writes a (plain-symbol) sympy expression in that spelling.

Example
-------
>>> import sympy as sp
>>> th, thdd = sp.symbols("theta theta_ddot")
>>> sp_ = spelling(r"a\\ddot{\\theta} - g\\sin\\theta = 0", {thdd: ("theta", 2)})
>>> to_latex(-sp.Symbol("g") * sp.sin(th) + sp.Symbol("a") * thdd, sp_)
'a \\\\ddot{\\\\theta} - g \\\\sin\\\\theta'
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import sympy as sp

from dualmech.grade.parser import GREEK

__all__ = ["spelling", "to_latex", "is_latex", "Spelling", "letters"]

_COMMAND = re.compile(r"\\[A-Za-z]+")
_LETTER = {name: letter for name, letter in GREEK.items() if not name.startswith("var")}


def is_latex(text: str) -> bool:
    """Whether the answer is typed in LaTeX (it uses a backslash command)."""
    return bool(_COMMAND.search(text or ""))


@dataclass
class Spelling:
    """How one answer writes things (see :func:`spelling`)."""

    text: str
    #: rate symbols -> (coordinate name, order)
    rates: dict
    times: str = " "
    frac: bool = False
    bare_args: bool = False
    braced_dots: bool = True
    names: dict = field(default_factory=dict)

    def name(self, name: str) -> str:
        """``name`` (``theta1``, ``l_c1``, ``omega``) as the answer spells it."""
        if name in self.names:
            return self.names[name]
        base, sub = _split(name)
        greek = base in _LETTER
        heads = ([f"\\{base}", _LETTER[base], base] if greek else [base])
        subs = ([f"_{{{sub}}}", f"_{sub}", sub] if sub else [""])
        found = None
        for head in heads:
            for s in subs:
                cand = head + s
                if re.search(re.escape(cand) + r"(?![A-Za-z0-9])", self.text):
                    found = cand
                    break
            if found:
                break
        if found is None:   # not typed: spelled as the answer spells its other names
            uses = "\\" if re.search(r"\\(" + "|".join(_LETTER) + r")(?![A-Za-z])",
                                     self.text) else ""
            head = f"{uses}{base}" if greek else base
            found = head + (f"_{{{sub}}}" if sub and len(sub) > 1 else f"_{sub}" if sub else "")
        self.names[name] = found
        return found


def _split(name: str) -> tuple[str, str]:
    """``theta1`` -> (``theta``, ``1``); ``l_c1`` -> (``l``, ``c1``); ``m`` -> (``m``, "")."""
    if "_" in name:
        base, _, sub = name.partition("_")
        return base, sub
    m = re.fullmatch(r"([A-Za-z]+?)(\d+)", name)
    return (m.group(1), m.group(2)) if m else (name, "")


def spelling(text: str, rates: dict) -> Spelling:
    """How ``text`` writes products (``*``, ``\\cdot`` or nothing), fractions (``\\frac``),
    a function's argument (``\\sin\\theta`` or ``\\sin(\\theta)``) and rates (``\\dot{x}`` or
    ``\\dot x``); ``rates`` maps each rate symbol to ``(coordinate name, order)``."""
    times = "*" if "*" in text else " \\cdot " if "\\cdot" in text else " "
    bare = bool(re.search(r"\\(sin|cos|tan)(\^\{?\d+\}?)?\s*\\?[A-Za-z]", text))
    braced = not re.search(r"\\d?dot\s*\\?[A-Za-z]", text)
    return Spelling(text, rates, times, "\\frac" in text or "\\dfrac" in text, bare, braced)


def letters(text: str, s: Spelling) -> str:
    """Plain feedback text (``theta'``) with Greek names as the answer typed them (``θ'``)
    when it typed the letters."""
    for name, letter in _LETTER.items():
        if letter in s.text and not re.search(r"(?<![A-Za-z\\])" + name, s.text):
            text = re.sub(r"(?<![A-Za-z\\])" + name + r"(?![A-Za-z])", letter, text)
    return text


def to_latex(expr, s: Spelling) -> str:
    """``expr`` written in the answer's LaTeX spelling."""
    return _LatexEcho(s).doprint(sp.sympify(expr))


class _LatexEcho:
    def __init__(self, s: Spelling):
        self.s = s

    def doprint(self, e) -> str:
        if e.is_Add:
            return self._add(e)
        return self._mul(e)

    def _add(self, e) -> str:
        from sympy.printing.str import StrPrinter
        out = ""
        for i, term in enumerate(StrPrinter()._as_ordered_terms(e)):
            text = self._mul(term)
            if text.startswith("-"):
                out += (" - " if i else "-") + text[1:]
            else:
                out += (" + " if i else "") + text
        return out

    def _mul(self, e) -> str:
        coeff, rest = e.as_coeff_Mul()
        sign = "-" if coeff < 0 else ""
        coeff = abs(coeff)
        num, den = [], []
        for f in rest.as_ordered_factors() if rest.is_Mul else [rest]:
            base, exp = f.as_base_exp()
            if exp.is_Number and exp < 0:
                den.append(base if exp == -1 else sp.Pow(base, -exp))
            else:
                num.append(f)
        if coeff.is_Rational and coeff.q != 1:
            den.insert(0, sp.Integer(coeff.q))
            coeff = sp.Integer(coeff.p)
        head = [] if coeff == 1 else [self._number(coeff)]
        top = self.s.times.join(head + [self._factor(f) for f in num]) or "1"
        if not den:
            return sign + top
        bottom = self.s.times.join(self._factor(f) for f in den)
        if self.s.frac:
            return f"{sign}\\frac{{{top}}}{{{bottom}}}"
        return f"{sign}{top}/{bottom if len(den) == 1 and not den[0].is_Add else '(' + bottom + ')'}"

    def _number(self, n) -> str:
        if n.is_Rational:
            return str(n)
        return str(sp.Float(n, 6))

    def _factor(self, f) -> str:
        if f.is_Add:
            return f"({self._add(f)})"
        if f.is_Number:
            return self._number(f)
        if f is sp.pi:
            return "\\pi"
        if f.is_Symbol:
            return self._symbol(f)
        if f.is_Pow:
            base, exp = f.args
            if exp == sp.Rational(1, 2):
                return f"\\sqrt{{{self.doprint(base)}}}"
            e = str(exp) if exp.is_Integer and 0 <= exp < 10 else f"{{{self.doprint(exp)}}}"
            if isinstance(base, sp.Function) and exp.is_Integer and exp > 0:
                return self._function(base, f"^{e}")
            inner = self._factor(base)
            if base.is_Pow or "/" in inner:
                inner = f"({inner})"
            return f"{inner}^{e}"
        if isinstance(f, sp.Function):
            return self._function(f, "")
        return self.doprint(f)

    def _function(self, f, power: str) -> str:
        name = f.func.__name__
        command = f"\\{name}" if f"\\{name}" in self.s.text or not re.search(
            r"(?<![A-Za-z\\])" + name + r"\s*\(", self.s.text) else name
        arg = f.args[0]
        if arg.is_Symbol and self.s.bare_args and command.startswith("\\"):
            text = self._symbol(arg)
            return f"{command}{power}{text if text.startswith(chr(92)) else ' ' + text}"
        return f"{command}{power}({self.doprint(arg)})"

    def _symbol(self, sym) -> str:
        if sym in self.s.rates:
            q, order = self.s.rates[sym]
            dot = "\\dot" if order == 1 else "\\ddot"
            inner = self.s.name(q)
            head, sub = re.fullmatch(r"(.*?)(_\{?[A-Za-z0-9]+\}?)?", inner).groups()
            if sub and re.search(r"\\d?dot\{[^{}]*\}_", self.s.text):   # \ddot{\theta}_1
                return f"{dot}{{{head}}}{sub}"
            if self.s.braced_dots:
                return f"{dot}{{{inner}}}"
            return f"{dot}{inner}" if inner.startswith("\\") else f"{dot} {inner}"
        return self.s.name(sym.name)
