"""Textbook notation for coordinates and their rates, in every output format.

A coordinate is a function of time ``theta(t)``; sympy prints its rates as ``Derivative(theta(t),
t)`` or ``d/dt(θ(t))``.  A worked solution writes them as dots or primes, and so does every
output of dualmech:

===============  ====================  ===========================  ===================
format           ``theta``             ``theta'``                   ``theta''``
===============  ====================  ===========================  ===================
pretty (dots)    ``θ``                 ``θ̇``                        ``θ̈``
pretty (primes)  ``θ``                 ``θ′``                       ``θ′′``
textbook line    ``θ``                 ``θ̇`` or ``θ′``              ``θ̈`` or ``θ′′``
LaTeX (dots)     ``\\theta``            ``\\dot{\\theta}``             ``\\ddot{\\theta}``
LaTeX (primes)   ``\\theta``            ``\\theta'``                  ``\\theta''``
plain text       ``theta``             ``theta'``                   ``theta''``
machine          ``theta``             ``theta_d``                  ``theta_dd``
MathML           a theta               a theta, dot above           two dots above
chart label      ``$\\theta$``          ``$\\dot{\\theta}$``           ``$\\ddot{\\theta}$``
===============  ====================  ===========================  ===================

The textbook line (:func:`plain`) is what a page of prose or a terminal shows in one line:
the pretty letters, powers as ``^`` and products as spaces (``m l θ̇^2 + sin(θ)``), no Python
syntax.  A *sentence* -- the explanations dualmech writes -- is a tuple of text and expressions
(:func:`sentence`), so each output typesets its expressions its own way.

The LaTeX is the one ``sympy.physics.vector.vlatex`` writes for dynamic symbols (Greek names as
``\\theta``, trailing digits as subscripts: ``\\dot{\\theta}_{1}``); the machine form is a name the
grader's parser reads (``theta_dd``), for programs that take JSON.  Functions of time that are
not rates of a coordinate (a forcing ``f(t)``) keep their ``(t)`` when the coordinates are named.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t
>>> th = coordinate("theta"); m, l = sp.symbols("m l", positive=True)
>>> e = m*l*th.diff(t)**2 + sp.sin(th)
>>> text(e), machine(e)
("l*m*theta'**2 + sin(theta)", 'l*m*theta_d**2 + sin(theta)')
>>> latex(th.diff(t, 2))
'\\\\ddot{\\\\theta}'
>>> pretty(th.diff(t, 2))
'θ̈'
>>> plain(e), plain(e, "primes")
('l m θ̇^2 + sin(θ)', 'l m θ′^2 + sin(θ)')
>>> sentence(("on the motion it equals ", e, ", not 0"))
'on the motion it equals l m θ̇^2 + sin(θ), not 0'
>>> print(mathtext("theta1", 1), mathtext("F_r"))
$\\dot{\\theta}_{1}$ $F_{r}$
"""
from __future__ import annotations

import re
from typing import Iterable

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.latex import LatexPrinter
from sympy.printing.mathml import MathMLPresentationPrinter
from sympy.printing.pretty.pretty import PrettyPrinter
from sympy.printing.pretty.pretty_symbology import greek_unicode, sub as _SUB
from sympy.printing.str import StrPrinter

from dualmech.model._expr import as_expr
from dualmech.model.kinematics import t

__all__ = ["NOTATIONS", "check_notation", "pretty", "latex", "text", "machine",
           "mathml", "plain", "sentence", "symbol_text", "mathtext",
           "equation_words"]

#: the two ways of writing rates: dots over the letter, or primes after it
NOTATIONS = ("dots", "primes")

_DOTS = {1: "\u0307", 2: "\u0308", 3: "\u20db"}
_LATEX_DOTS = {1: r"\dot", 2: r"\ddot", 3: r"\dddot"}


def check_notation(notation: str) -> str:
    """``notation`` if it is one of :data:`NOTATIONS`; a ``ValueError`` saying which are."""
    if notation not in NOTATIONS:
        raise ValueError(f"`notation` must be one of {', '.join(NOTATIONS)}; got {notation!r}.")
    return notation


def _split(name: str) -> tuple[str, str]:
    """``theta1`` -> ``("theta", "1")``; ``x_B`` -> ``("x", "B")``; ``phi`` -> ``("phi", "")``."""
    if "_" in name:
        stem, _, sub = name.partition("_")
        return stem, sub
    m = re.fullmatch(r"([A-Za-z]+?)(\d+)", name)
    return (m.group(1), m.group(2)) if m else (name, "")


_AXES = ("x", "y", "z")


def _unicode(name: str, order: int, notation: str) -> str:
    stem, sub = _split(name)
    letter = greek_unicode.get(stem, stem)
    if order and notation == "dots" and order in _DOTS:
        letter += _DOTS[order]
    if sub:
        # an axis (x, y, z) stays after "_" alike: Unicode has a subscript x but no y or z,
        # and F_x beside F_y reads better than Fₓ beside F_y
        sub = ("".join(_SUB[c] for c in sub) if sub not in _AXES and all(_SUB.get(c) for c in sub)
               else "_" + sub)
    primes = "\u2032" * order if order and (notation == "primes" or order not in _DOTS) else ""
    return letter + sub + primes


def _latex(name: str, order: int, notation: str) -> str:
    stem, sub = _split(name)
    base = LatexPrinter()._print(sp.Symbol(stem))
    if order and notation == "dots" and order in _LATEX_DOTS:
        base = f"{_LATEX_DOTS[order]}{{{base}}}"
    elif order:
        base += "'" * order
    return base + (f"_{{{sub}}}" if sub else "")


def _rate(printer, expr):
    """``(name, order)`` when ``expr`` is a coordinate or one of its rates, else ``None``."""
    order = 0
    if isinstance(expr, sp.Derivative):
        if not all(v == t for v in expr.variables):
            return None
        order, expr = len(expr.variables), expr.expr
    if not (isinstance(expr, AppliedUndef) and expr.args == (t,)):
        return None
    wanted = printer._settings.get("coordinates")
    if wanted is not None and expr not in wanted and not order:
        return None
    return expr.func.__name__, order


class _Pretty(PrettyPrinter):
    _default_settings = dict(PrettyPrinter._default_settings, coordinates=None,
                             notation="dots")

    def _print_Derivative(self, e):
        r = _rate(self, e)
        if r is None:
            return super()._print_Derivative(e)
        return super()._print_Symbol(sp.Symbol(_unicode(*r, self._settings["notation"])))

    def _print_Function(self, e, *args, **kwargs):
        r = _rate(self, e)
        if r is None:
            return super()._print_Function(e, *args, **kwargs)
        return super()._print_Symbol(sp.Symbol(_unicode(*r, self._settings["notation"])))


class _Latex(LatexPrinter):
    _default_settings = dict(LatexPrinter._default_settings, coordinates=None,
                             notation="dots")

    def _print_Derivative(self, e):
        r = _rate(self, e)
        return super()._print_Derivative(e) if r is None else \
            _latex(*r, self._settings["notation"])

    def _print_Function(self, e, exp=None):
        r = _rate(self, e)
        if r is None:
            return super()._print_Function(e, exp)
        s = _latex(*r, self._settings["notation"])
        return s if exp is None else f"{s}^{{{exp}}}"


class _Str(StrPrinter):
    _default_settings = dict(StrPrinter._default_settings, coordinates=None, machine=False)

    def _name(self, r) -> str:
        name, order = r
        if self._settings["machine"]:
            return name + ("_" + "d" * order if order else "")
        return name + "'" * order

    def _print_Derivative(self, e):
        r = _rate(self, e)
        return super()._print_Derivative(e) if r is None else self._name(r)

    def _print_Function(self, e):
        r = _rate(self, e)
        return super()._print_Function(e) if r is None else self._name(r)


class _Plain(StrPrinter):
    """One-line textbook text: :func:`_unicode` names; ``*`` and ``**`` marked so that
    :func:`plain` turns them into spaces and ``^`` (a name never holds the marks)."""
    _default_settings = dict(StrPrinter._default_settings, coordinates=None,
                             notation="dots")

    def _name(self, name: str, order: int = 0) -> str:
        return _unicode(name, order, self._settings["notation"]).replace("*", "\u2217")

    def _print_Symbol(self, e):
        return self._name(e.name)

    _print_Dummy = _print_Symbol

    def _print_Derivative(self, e):
        r = _rate(self, e)
        return super()._print_Derivative(e) if r is None else self._name(*r)

    def _print_Function(self, e):
        r = _rate(self, e)
        return super()._print_Function(e) if r is None else self._name(*r)


class _Named(StrPrinter):
    """Only for :func:`_rate`'s settings lookup."""
    _default_settings = dict(StrPrinter._default_settings, coordinates=None)


def _as_symbols(expr, notation: str, coordinates):
    """``expr`` with each coordinate and rate replaced by a symbol whose name is its unicode
    form (``θ̇_1``): sympy's MathML printer shows that as a dotted letter with a subscript
    and, unlike a function, never puts it in parentheses."""
    probe = _Named({"coordinates": coordinates})
    rules = {}
    for a in expr.atoms(sp.Derivative, AppliedUndef):
        r = _rate(probe, a)
        if r is not None:
            stem, sub = _split(r[0])
            name = greek_unicode.get(stem, stem)
            if r[1]:
                name += _DOTS[r[1]] if notation == "dots" and r[1] in _DOTS else \
                    "\u2032" * r[1]
            rules[a] = sp.Symbol(name + (f"_{sub}" if sub else ""))
    derivs = {k: v for k, v in rules.items() if isinstance(k, sp.Derivative)}
    plain = {k: v for k, v in rules.items() if not isinstance(k, sp.Derivative)}
    return expr.xreplace(derivs).xreplace(plain)


def _settings(coordinates: Iterable | None) -> dict:
    return {"coordinates": None if coordinates is None else frozenset(coordinates)}


def pretty(expr, notation: str = "dots", coordinates: Iterable | None = None,
           order: str | None = None) -> str:
    """Two-dimensional unicode text of ``expr`` (``θ̈`` for ``theta''``), no line wrapping.

    ``coordinates`` (the ``q(t)`` of the model) keeps other functions of time as ``f(t)``;
    without it every function of ``t`` is written as its bare name.  ``order="none"``
    prints the terms of an unevaluated sum in the order they were given.
    """
    check_notation(notation)
    return _Pretty(dict(_settings(coordinates), notation=notation, use_unicode=True,
                        wrap_line=False, order=order)).doprint(as_expr(expr))


def latex(expr, notation: str = "dots", coordinates: Iterable | None = None,
          order: str | None = None) -> str:
    """LaTeX of ``expr``: ``\\ddot{\\theta}`` (dots) or ``\\theta''`` (primes) for ``theta''``;
    ``order`` as :func:`pretty`."""
    check_notation(notation)
    return _Latex(dict(_settings(coordinates), notation=notation, order=order)).doprint(
        as_expr(expr))


def text(expr, coordinates: Iterable | None = None) -> str:
    """Plain one-line text of ``expr`` with primes: ``theta'``, ``theta''``, ``theta``."""
    return _Str(_settings(coordinates)).doprint(as_expr(expr))


def machine(expr, coordinates: Iterable | None = None) -> str:
    """One-line text a parser reads: ``theta_d``, ``theta_dd`` for the rates, ``**`` powers."""
    return _Str(dict(_settings(coordinates), machine=True)).doprint(as_expr(expr))


def plain(expr, notation: str = "dots", coordinates: Iterable | None = None) -> str:
    """One line of textbook text: ``m l θ̇^2 + sin(θ)`` (``θ′`` with ``"primes"``).

    Letters as :func:`pretty` writes them (Greek, subscript digits), powers as ``^``, products
    as a space; nothing of Python's syntax (``**``, ``*``, ``Derivative``, ``(t)``).
    """
    check_notation(notation)
    out = _Plain(dict(_settings(coordinates), notation=notation)).doprint(as_expr(expr))
    return out.replace("**", "^").replace("*", " ").replace("\u2217", "*")


def sentence(parts, notation: str = "dots", coordinates: Iterable | None = None) -> str:
    """A sentence -- a tuple of text and expressions -- as one line of textbook text, each
    expression written by :func:`plain`.  A plain string is returned as it is."""
    if isinstance(parts, str):
        return parts
    return "".join(x if isinstance(x, str) else plain(x, notation, coordinates)
                   for x in parts)


def mathml(expr, notation: str = "dots", coordinates: Iterable | None = None) -> str:
    """Presentation MathML (no ``<math>`` wrapper) of ``expr``, rates as dotted letters."""
    check_notation(notation)
    coords = _settings(coordinates)["coordinates"]
    expr = _as_symbols(as_expr(expr), notation, coords)
    return MathMLPresentationPrinter().doprint(expr)


def symbol_text(name: str, order: int = 0, notation: str = "dots") -> str:
    """The unicode name of a coordinate's rate: ``symbol_text("theta1", 2)`` is ``θ̈₁``."""
    return _unicode(name, order, check_notation(notation))


_BALANCE = re.compile(r"sum (F|tau_(\w+)) \. (\w+)\.(\w+) \((.+)\)$")
_CONSTRAINT = re.compile(r"constraint (\w+) \((.+)\)$")


def equation_words(label: str, model: str = "", coordinates: Iterable = ()) -> tuple:
    """A derived equation named in words a teacher reads, as a sentence (text and
    expressions, see :func:`sentence`) -- never the row's internal label.

    ``label`` is the row's label in its :class:`~dualmech.model.equations.EquationSet`, ``model``
    the derivation's name, ``coordinates`` the coordinates (a Lagrange row's coordinate is
    then an expression, typeset as the letter).  Force and moment balances are named as the
    grader names them; a label of any other form is quoted.

    Example
    -------
    >>> from dualmech import coordinate
    >>> th = coordinate("theta")
    >>> sentence(equation_words("Lagrange, theta", "lagrange", [th]))
    'the θ equation of the Lagrange derivation'
    >>> sentence(equation_words("sum F . O.y (m2)", "newton_euler"))
    'the force balance on m2 along y of the Newton–Euler derivation'
    >>> sentence(equation_words("sum tau_G . b.x (body)"))
    'the moment balance about G on body along b.x'
    """
    if label.startswith(("Lagrange, ", "linearised, ")):
        kind, _, name = label.partition(", ")
        q = next((c for c in coordinates if getattr(getattr(c, "func", None), "__name__", "")
                  == name), None)
        head = "the linearised " if kind == "linearised" else "the "
        out: tuple = (head, q if q is not None else name, " equation")
    elif _BALANCE.match(label):
        kind, point, frame, axis, bodies = _BALANCE.match(label).groups()
        along = axis if frame in ("O", "N", "E") else f"{frame}.{axis}"
        what = "the force balance" if kind == "F" else f"the moment balance about {point}"
        out = (f"{what} on {bodies} along {along}",)
    elif _CONSTRAINT.match(label):
        name, level = _CONSTRAINT.match(label).groups()
        out = (f"the constraint of the multiplier {name} ({level})",)
    else:
        out = (f"the equation \u201c{label}\u201d",)
    if model:
        out += (f" of the {_model_words(model)} derivation",)
    return out


def _model_words(model: str) -> str:
    """``newton_euler`` -> ``Newton–Euler``, ``lagrange`` -> ``Lagrange``, else its words."""
    words = {"lagrange": "Lagrange", "newton": "Newton", "euler": "Euler"}
    text = " ".join(words.get(w, w) for w in model.split("_"))
    return text.replace("Newton Euler", "Newton\u2013Euler")


#: a name :func:`mathtext` typesets: letters, optional digits, ``_`` and a subscript
_NAME = re.compile(r"[A-Za-z]+[0-9]*(_[A-Za-z0-9]+)?")


def mathtext(name: str, order: int = 0, notation: str = "dots") -> str:
    """A chart label (matplotlib mathtext) of a coordinate, its rate or a reaction's name.

    ``mathtext("theta1", 1)`` is ``$\\dot{\\theta}_{1}$`` -- the LaTeX of :func:`latex` between
    dollars, so a legend shows θ̇₁ as the page does.  A name that is not a symbol's name
    (spaces, punctuation) is returned as text with its ``$`` escaped, never as markup.

    Examples
    --------
    >>> mathtext("phi", 2), mathtext("phi", 1, "primes"), mathtext("R_x")
    ('$\\\\ddot{\\\\phi}$', "$\\\\phi'$", '$R_{x}$')
    >>> mathtext("a $5 fee")
    'a \\\\$5 fee'
    """
    check_notation(notation)
    if not isinstance(order, int) or isinstance(order, bool) or order < 0:
        raise ValueError(f"`order` must be a non-negative integer, got {order!r}.")
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        return str(name).replace("$", r"\$")
    return f"${_latex(name, order, notation)}$"
