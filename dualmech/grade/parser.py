r"""A whitelisting parser for typed answers: text in, a small tree of known operations out.

Nothing here evaluates text.  The answer is checked character by character against a
whitelist, bounded in length and bracket depth, then parsed by a fixed LALR grammar (lark)
whose reductions build :class:`Node` trees of a handful of operations -- numbers, names,
``+ - * / ^``, a whitelisted set of functions, vectors.  Trees are bounded in depth and size
while they are built.  Names are kept as written; :mod:`dualmech.grade.vocabulary` gives them
meaning.

Accepted syntax: ``*``, ``/``, ``^`` or ``**``, implicit multiplication (``2 m g``,
``m(a + b)``), ``=``, several equations separated by ``;`` or new lines; names with primes
(``theta'``, ``theta''``), subscripts (``k_t``, ``m_{0}``), Greek letters (``θ``,
``\theta``), combining dots (``θ̇``, also before an index: ``ẍ1``, ``θ̈₂``), subscript digits
(``θ₁``), ``½`` and like fractions; LaTeX ``\frac{a}{b}``, ``\sqrt{x}``, ``\sin``,
``\dot{x}``, ``\ddot{\theta}``, ``\cdot``, ``\left(``; functions ``sin cos tan cot sec csc
sqrt exp log ln`` with ``sin^2(x)`` and bare arguments ``sin x``, ``\sin 2\theta``; the root
sign (``√3``, ``√(k/m)``); Leibniz's rates (``dx/dt``, ``d2x/dt2``, ``d^2x/dt^2``,
``\frac{d^2\theta}{dt^2}``); equations separated by commas (``a = b, c = d``, every part an
equation); vectors ``[a, b, c]``.

Example
-------
>>> eqs = parse("R*theta'' + g*sin(theta) = 0; x^2")
>>> len(eqs), eqs[0].rhs is not None
(2, True)
>>> str(eqs[0].lhs)
"R*theta'' + g*sin(theta)"
>>> parse("__import__('os')")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
dualmech.grade.parser.AnswerSyntaxError: could not read the answer at column 1: unexpected character "_"...
"""
from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass
from fractions import Fraction

from lark import Lark, Transformer
from lark.exceptions import LarkError, UnexpectedCharacters, UnexpectedEOF, UnexpectedToken

from dualmech.grade.lalr import lalr_parser

__all__ = ["split_where",
           "Limits", "LIMITS", "Node", "Equation", "AnswerError", "AnswerSyntaxError",
           "AnswerTooLarge", "parse", "FUNCTIONS", "GREEK"]


@dataclass(frozen=True)
class Limits:
    """Bounds on one answer; anything past them is refused with a clear error.

    ``chars``: length of the text; ``depth``: nesting of the tree (brackets, powers,
    functions); ``nodes``: size of the tree; ``exponent``: largest integer exponent;
    ``degree``: largest total degree of the answer as a polynomial (so ``9^9^9^9`` and
    ``((x^9)^9)^9`` are refused before anything is computed); ``digits``: longest number;
    ``equations``: how many equations; ``seconds``: time per answer.
    """

    chars: int = 4000
    depth: int = 40
    nodes: int = 2000
    exponent: int = 24
    degree: int = 200
    digits: int = 30
    equations: int = 24
    seconds: float = 2.0


LIMITS = Limits()


class AnswerError(ValueError):
    """An answer that cannot be graded as typed; the message says what to change."""


class AnswerSyntaxError(AnswerError):
    """The text is not a formula this parser reads."""


class AnswerTooLarge(AnswerError):
    """The answer exceeds one of the :class:`Limits`."""


#: Whitelisted functions (plain or as LaTeX commands) and the name they get in the tree.
FUNCTIONS = {"sin": "sin", "cos": "cos", "tan": "tan", "cot": "cot", "sec": "sec",
             "csc": "csc", "sqrt": "sqrt", "exp": "exp", "log": "log", "ln": "log"}

#: Greek letters: LaTeX command name -> the letter; the letter is also accepted as typed.
GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε",
         "varepsilon": "ε", "zeta": "ζ", "eta": "η", "theta": "θ", "vartheta": "θ",
         "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ",
         "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "upsilon": "υ", "phi": "φ",
         "varphi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ",
         "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ", "Phi": "Φ",
         "Psi": "Ψ", "Omega": "Ω"}

# Characters that may appear at all (checked before parsing); everything else is refused.
_ALLOWED = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
               " \t\r\n+-*/^=()[]{}.,;_'\\&") | set("αβγδεζηθικλμνξοπρστυφχψωϕϑΓΔΘΛΞΠΣΦΨΩ")
_DISALLOWED = re.compile("[^" + re.escape("".join(sorted(_ALLOWED))) + "\u0307\u0308]")
_REPLACE = {"′": "'", "’": "'", "″": "''", "·": "*", "⋅": "*", "×": "*", "−": "-",
            "²": "^2", "³": "^3", "⁴": "^4", "\u0307": "\u0307", "\u0308": "\u0308",
            "\u00a0": " ", "½": "(1/2)", "⅓": "(1/3)", "⅔": "(2/3)", "¼": "(1/4)",
            "¾": "(3/4)", "⅙": "(1/6)", "⅛": "(1/8)"} | {
    chr(0x2080 + d): str(d) for d in range(10)}   # subscript digits: θ₁ is θ1
_COMBINING = {"\u0307", "\u0308"}  # combining dot above / diaeresis: theta-dot, theta-ddot
_LATEX_NOISE = re.compile(r"\\(left|right|big|Big|bigg|Bigg)(?![A-Za-z])|\\[,;:! ]|\\quad|"
                          r"\\qquad|&")
_LATEX_TIMES = re.compile(r"\\(cdot|times)(?![A-Za-z])")
_LATEX_OPERATORNAME = re.compile(r"\\operatorname\{([A-Za-z]+)\}")
_LATEX_DECOR = re.compile(r"\\(hat|vec|mathbf|boldsymbol|bm|mathrm)\{([A-Za-z]+)\}")
_BRACKETS = re.compile(r"[()\[\]{}]")
_LATEX_COMMAND = re.compile(r"\\[A-Za-z]{0,20}")
# a square-root sign before a number or a name (√3, √g) or a bracket (√(k/m))
_ROOT_SIGN = re.compile(r"√\s*(\d+(?:\.\d+)?|[A-Za-zα-ωΑ-Ωϕϑ][A-Za-z0-9α-ωΑ-Ωϕϑ]*)")
# Leibniz's notation for rates: d2x/dt2, d^2x/dt^2, dx/dt, \frac{d^2\theta}{dt^2}, \frac{dx}{dt}
_LEIBNIZ_NAME = r"(\\?[A-Za-zα-ωΑ-Ωϕϑ][A-Za-z0-9α-ωΑ-Ωϕϑ]*(?:_\{[A-Za-z0-9]+\}|_[A-Za-z0-9]+)?)"
_LEIBNIZ = (
    (re.compile(r"\\[dt]?frac\{\s*d\s*\^\s*\{?\s*2\s*\}?\s*" + _LEIBNIZ_NAME
                + r"\s*\}\{\s*dt\s*\^\s*\{?\s*2\s*\}?\s*\}"), r" \1'' "),
    (re.compile(r"\\[dt]?frac\{\s*d\s*" + _LEIBNIZ_NAME + r"\s*\}\{\s*dt\s*\}"), r" \1' "),
    (re.compile(r"(?<![A-Za-z0-9_'])d\^?2" + _LEIBNIZ_NAME + r"\s*/\s*dt\^?2(?![A-Za-z0-9_])"),
     r"\1''"),
    (re.compile(r"(?<![A-Za-z0-9_'])d" + _LEIBNIZ_NAME + r"\s*/\s*dt(?![A-Za-z0-9_^])"),
     r"\1'"))

_GREEK_CHARS = "α-ωΑ-Ωϕϑ"
_NAME_RE = (rf"[A-Za-z{_GREEK_CHARS}][A-Za-z0-9{_GREEK_CHARS}]*"
            r"(?:_(?:\{[A-Za-z0-9]+\}|[A-Za-z0-9]+))*"
            r"(?:[\u0307\u0308](?:[0-9]+|_(?:\{[A-Za-z0-9]+\}|[A-Za-z0-9]+))?)?")
# (a dot may sit on the letter before a name's index: ẍ1 and θ̈_2 are x1'' and θ_2'')
_GRAMMAR = r"""
start: _sep* equation (_sep+ equation)* _sep*
_sep: ";" | _NL | _DBLBS
equation: sum ("=" sum)*
?sum: term | sum "+" term -> add | sum "-" term -> sub
?term: unary | term "*" unary -> mul | term "/" unary -> div | term power -> imul
?unary: power | "-" unary -> neg | "+" unary -> pos
?power: postfix | postfix _POW unary -> pow
?postfix: NUMBER -> number
     | name
     | "(" sum ")" -> group
     | "{" sum "}" -> group
     | "[" sum "]" -> group
     | "[" sum ("," sum)+ "]" -> vector
     | "(" sum ("," sum)+ ")" -> vector
     | FUNC paren -> call
     | FUNC fexp paren -> callpow
     | FUNC bare -> callbare
     | FUNC fexp bare -> callpowbare
     | FRAC "{" sum "}" "{" sum "}" -> frac
paren: "(" sum ")" | "{" sum "}"
fexp: _POW NUMBER | _POW "{" NUMBER "}"
bare: simple | NUMBER simple
?simple: name
name: NAME PRIMES? -> plain
    | GREEKCMD PRIMES? -> greek
    | DOT "{" simple_name "}" SUBSCRIPT? -> dotted
    | DOT simple_name SUBSCRIPT? -> dotted
simple_name: NAME | GREEKCMD
_POW: "^" | "**"
_DBLBS: "\\\\"
PRIMES: /'+/
SUBSCRIPT: /_(\{[A-Za-z0-9]+\}|[A-Za-z0-9]+)/
FUNC.3: /\\?(sin|cos|tan|cot|sec|csc|sqrt|exp|log|ln)(?![A-Za-z0-9_\u0307\u0308])/
FRAC.3: /\\[dt]?frac(?![A-Za-z])/
DOT.3: /\\d?dot(?![A-Za-z])/
GREEKCMD.2: /\\(GREEKNAMES)(?![A-Za-z])(_(\{[A-Za-z0-9]+\}|[A-Za-z0-9]+))?/
NAME: /NAMERE/
NUMBER: /\d+(\.\d+)?([eE][-+]?\d+)?|\.\d+([eE][-+]?\d+)?/
_NL: /\r?\n/
%ignore /[ \t]+/
""".replace("GREEKNAMES", "|".join(sorted(GREEK, key=len, reverse=True))).replace(
    "NAMERE", _NAME_RE)


# -- the tree -------------------------------------------------------------------------------
class Node:
    r"""One operation of a parsed answer.

    ``op`` is one of ``num`` (``args = (Fraction,)``), ``name`` (``(text, primes)``),
    ``dot`` (``(text, dots)``, from ``\dot``/``\ddot``), ``add``, ``mul`` (n-ary),
    ``pow`` (``(base, exponent)``), ``neg``, ``inv`` (``1/x``), ``func`` (``(name, arg)``),
    ``vec`` (components) and ``group`` (brackets, kept so ``theta(t)`` can be recognised).
    ``depth`` and ``size`` are those of the subtree.
    """

    __slots__ = ("op", "args", "depth", "size", "bare")

    def __init__(self, op: str, args: tuple, children: tuple = (), bare: bool = False):
        self.op = op
        self.args = args
        self.depth = 1 + max((c.depth for c in children), default=0)
        self.size = 1 + sum(c.size for c in children)
        self.bare = bare

    @property
    def children(self) -> tuple:
        if self.op in ("add", "mul", "vec"):
            return self.args
        if self.op in ("pow",):
            return self.args
        if self.op in ("neg", "inv", "group"):
            return self.args
        if self.op == "func":
            return (self.args[1],)
        return ()

    def __repr__(self) -> str:
        return f"Node({self.op}, {self.args!r})"

    def __str__(self) -> str:
        return to_text(self)


def to_text(node: Node, inner: bool = False) -> str:
    """The tree written back as plain text for messages, as a person types it: ``^`` for
    powers, parentheses only where needed (``inner``: the node is an operand, so a sum or a
    group keeps its parentheses); the tree's depth is bounded by the parser's limits."""
    op, a = node.op, node.args
    if op == "num":
        v = a[0]
        return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
    if op in ("name", "dot"):
        return a[0] + "'" * a[1]
    if op == "group":
        return f"({to_text(a[0])})" if inner else to_text(a[0])
    if op == "neg":
        return f"-{to_text(a[0], True)}"
    if op == "add":
        out = to_text(a[0])
        for c in a[1:]:
            t = to_text(c)
            out += f" - {t[1:]}" if t.startswith("-") else f" + {t}"
        return f"({out})" if inner else out
    if op == "mul":
        out = ""
        for c in a:
            if c.op == "inv":
                out += ("1" if not out else "") + "/" + to_text(c.args[0], True)
            else:
                out += ("*" if out else "") + to_text(c, True)
        return out
    if op == "inv":
        return "1/" + to_text(a[0], True)
    if op == "pow":
        return f"{to_text(a[0], True)}^{to_text(a[1], True)}"
    if op == "func":
        return f"{a[0]}({to_text(a[1])})"
    if op == "vec":
        return "[" + ", ".join(to_text(c) for c in a) + "]"
    raise AssertionError(op)


@dataclass(frozen=True)
class Equation:
    """``lhs = rhs`` as typed (``rhs`` is ``None`` for a bare expression); ``text`` is its source."""

    lhs: Node
    rhs: Node | None
    text: str


# -- building the tree during parsing (no recursion, bounds checked at every node) ----------
class _Build(Transformer):
    def __init__(self, limits: Limits):
        super().__init__()
        self.limits = limits

    def _node(self, op, args, children=(), bare=False) -> Node:
        n = Node(op, tuple(args), tuple(children), bare)
        if n.depth > self.limits.depth:
            raise AnswerTooLarge(f"the answer nests more than {self.limits.depth} levels deep; "
                                 "write it with fewer brackets or powers of powers.")
        if n.size > self.limits.nodes:
            raise AnswerTooLarge(f"the answer has more than {self.limits.nodes} operations; "
                                 "it is too long to grade.")
        return n

    # numbers and names
    def number(self, c):
        text = str(c[0])
        mantissa, _, exp = text.lower().partition("e")
        if len(mantissa.replace(".", "")) > self.limits.digits:
            raise AnswerTooLarge(f"the number {text[:20]}... has more than "
                                 f"{self.limits.digits} digits.")
        value = Fraction(mantissa if mantissa != "." else "0")
        if exp:
            e = int(exp)
            if abs(e) > self.limits.digits:
                raise AnswerTooLarge(f"the number {text} is out of range (exponent {e}).")
            value *= Fraction(10) ** e
        return self._node("num", (value,))

    def plain(self, c):
        text = str(c[0])
        primes = len(c[1]) if len(c) > 1 else 0
        dots = 0
        mark = next((ch for ch in text if ch in _COMBINING), None)
        if mark is not None:   # on the last letter, or on the letter before the index
            dots = 1 if mark == "\u0307" else 2
            text = text.replace(mark, "")
        if primes and dots:
            raise AnswerSyntaxError(f"`{text}` has both dots and primes; use one notation.")
        return self._node("name", (_clean_name(text), primes + dots))

    def greek(self, c):
        text = str(c[0])[1:]
        base, _, sub = text.partition("_")
        name = GREEK[base] + (("_" + sub) if sub else "")
        return self._node("name", (_clean_name(name), len(c[1]) if len(c) > 1 else 0))

    def simple_name(self, c):
        text = str(c[0])
        if text.startswith("\\"):
            base, _, sub = text[1:].partition("_")
            return GREEK[base] + (("_" + sub) if sub else "")
        return text

    def dotted(self, c):
        dots = 2 if str(c[0]) == "\\ddot" else 1
        name = c[1]
        if len(c) > 2 and c[2] is not None:
            name = name + str(c[2])
        return self._node("name", (_clean_name(name), dots))

    # arithmetic
    def add(self, c):
        return self._flat("add", c[0], c[1])

    def sub(self, c):
        return self._flat("add", c[0], self.neg([c[1]]))

    def mul(self, c):
        return self._flat("mul", c[0], c[1])

    imul = mul

    def div(self, c):
        return self._flat("mul", c[0], self._node("inv", (c[1],), (c[1],)))

    def _flat(self, op, a, b):
        left = a.args if a.op == op else (a,)
        right = b.args if b.op == op else (b,)
        args = left + right
        n = self._node(op, args, ())
        n.depth = 1 + max(x.depth for x in args)
        n.size = 1 + sum(x.size for x in args)
        if n.depth > self.limits.depth or n.size > self.limits.nodes:
            self._node(op, args, args)  # raises with the right message
        return n

    def neg(self, c):
        return self._node("neg", (c[0],), (c[0],))

    def pos(self, c):
        return c[0]

    def pow(self, c):
        base, exp = c
        if base.op == "func" and base.bare:
            raise AnswerSyntaxError(f"`{to_text(base)}^{to_text(exp)}` is ambiguous: write "
                                    f"{base.args[0]}(x^{to_text(exp)}) or {base.args[0]}(x)^"
                                    f"{to_text(exp)} with brackets.")
        return self._node("pow", (base, exp), (base, exp))

    def group(self, c):
        return self._node("group", (c[0],), (c[0],))

    def vector(self, c):
        return self._node("vec", tuple(c), tuple(c))

    def frac(self, c):
        return self._flat("mul", self.group([c[1]]), self._node("inv", (c[2],), (c[2],)))

    # functions
    def paren(self, c):
        return c[0]

    def bare(self, c):
        return c[0] if len(c) == 1 else self._flat("mul", self.number([c[0]]), c[1])

    def fexp(self, c):
        return self.number([c[0]])

    def _func(self, fname, arg, exp=None, bare=False):
        name = FUNCTIONS[str(fname).lstrip("\\")]
        f = self._node("func", (name, arg), (arg,), bare=bare)
        if exp is None:
            return f
        if exp.args[0].denominator != 1 or exp.args[0] < 1:
            raise AnswerSyntaxError(f"`{name}^{to_text(exp)}`: only positive whole powers may "
                                    f"follow a function name (`{name}^2(x)`); write "
                                    f"1/{name}(x) or {name}(x)^{to_text(exp)} instead.")
        return self._node("pow", (f, exp), (f, exp))

    def call(self, c):
        return self._func(c[0], c[1])

    def callpow(self, c):
        return self._func(c[0], c[2], c[1])

    def callbare(self, c):
        return self._func(c[0], c[1], bare=True)

    def callpowbare(self, c):
        return self._func(c[0], c[2], c[1], bare=True)

    def equation(self, c):
        if len(c) > 2:
            raise AnswerSyntaxError("an equation has one `=`; put several equations on "
                                    "separate lines or separate them with `;`.")
        return (c[0], c[1] if len(c) == 2 else None)

    def start(self, c):
        return list(c)


def _clean_name(text: str) -> str:
    """``m_{0}`` -> ``m_0``; Greek variants folded (``ϕ`` -> ``φ``)."""
    text = text.replace("{", "").replace("}", "")
    return text.replace("ϕ", "φ").replace("ϑ", "θ")


_PARSERS: dict = {}


def _parser(limits: Limits) -> Lark:
    """One LALR parser per set of limits; its reductions build the tree (no second pass).
    The tables are shared by all of them and kept between runs (:mod:`.lalr`)."""
    if limits not in _PARSERS:
        _PARSERS[limits] = lalr_parser(_GRAMMAR, _Build(limits), lexer="contextual",
                                       maybe_placeholders=False)
    return _PARSERS[limits]


# -- the public entry point --------------------------------------------------------------
def parse(text: str, limits: Limits = LIMITS) -> list[Equation]:
    """Parse an answer into equations (``lhs = rhs``, or a bare expression).

    Raises :class:`AnswerSyntaxError` for text this grammar does not read (the message says
    where) and :class:`AnswerTooLarge` past the :class:`Limits`.  Never evaluates the text.
    """
    text = _prepare(text, limits)
    try:
        built = _parser(limits).parse(text)
    except AnswerError:
        raise
    except UnexpectedCharacters as exc:
        ch = text[exc.pos_in_stream] if exc.pos_in_stream < len(text) else "?"
        if ch == "\\":   # name the LaTeX command, not just its backslash
            command = _LATEX_COMMAND.match(text, exc.pos_in_stream).group()
            raise AnswerSyntaxError(f"could not read the answer at column {exc.column}: the "
                                    f"LaTeX command {command} is not supported"
                                    + _context(text, exc)) from None
        raise AnswerSyntaxError(f"could not read the answer at column {exc.column}: "
                                f"unexpected character {ch!r}{_hint(ch)}"
                                .replace("'" + ch + "'", f'"{ch}"') + _context(text, exc)) \
            from None
    except UnexpectedEOF:
        raise AnswerSyntaxError("the answer ends too early: a bracket or an operand is "
                                "missing at the end.") from None
    except UnexpectedToken as exc:
        if exc.token.type == "$END":
            raise AnswerSyntaxError("the answer ends too early: a bracket or an operand is "
                                    "missing at the end.") from None
        tok = str(exc.token)
        raise AnswerSyntaxError(f"could not read the answer at column {exc.column}: unexpected "
                                f"{tok!r}{_hint(tok)}" + _context(text, exc)) from None
    except LarkError as exc:  # any other grammar failure, reported without internals
        raise AnswerSyntaxError(f"could not read the answer ({type(exc).__name__}).") from None
    except RecursionError:
        raise AnswerTooLarge("the answer nests too deeply.") from None
    if len(built) > limits.equations:
        raise AnswerTooLarge(f"the answer has {len(built)} equations; at most "
                             f"{limits.equations} are graded.")
    sources = [s for s in re.split(r";|\r?\n|\\\\", text) if s.strip()]
    if len(sources) != len(built):
        sources = [""] * len(built)
    return [Equation(lhs, rhs, src.strip()) for (lhs, rhs), src in zip(built, sources)]


def _prepare(text, limits: Limits) -> str:
    if not isinstance(text, str):
        raise AnswerSyntaxError(f"an answer is text, got {type(text).__name__}.")
    if len(text) > limits.chars:
        raise AnswerTooLarge(f"the answer has {len(text)} characters; at most {limits.chars} "
                             "are graded.")
    if not text.isascii():
        text = unicodedata.normalize("NFC", text)
        # NFC composes letters with combining dots where a precomposed letter exists
        # (x-dot); decompose just those again so the dot stays a separate mark
        text = "".join(unicodedata.normalize("NFD", ch) if ord(ch) > 127 and any(
            m in unicodedata.normalize("NFD", ch) for m in _COMBINING) else ch for ch in text)
        for a, b in _REPLACE.items():
            text = text.replace(a, b)
        text = _ROOT_SIGN.sub(r"sqrt(\1)", text).replace("√", "sqrt")
    if "\\" in text or "&" in text:
        text = _LATEX_OPERATORNAME.sub(r"\1", text)
        text = _LATEX_DECOR.sub(r"\2", text)
        text = _LATEX_NOISE.sub(" ", text)
        text = _LATEX_TIMES.sub("*", text)
    if "dt" in text:
        for pattern, rate in _LEIBNIZ:
            text = pattern.sub(rate, text)
    text = _commas_between_equations(text)
    bad = _DISALLOWED.search(text)
    if bad:
        ch, i = bad.group(), bad.start()
        raise AnswerSyntaxError(f"character {ch!r} (U+{ord(ch):04X}) at position {i + 1} "
                                "is not part of a formula; use letters, digits, "
                                "+ - * / ^ = ( ) and names.")
    depth = best = 0
    for ch in _BRACKETS.findall(text):
        if ch in "([{":
            depth += 1
            best = max(best, depth)
        else:
            depth -= 1
    if best > limits.depth:
        raise AnswerTooLarge(f"the answer nests brackets {best} deep; at most "
                             f"{limits.depth} levels are graded.")
    if not text.strip():
        raise AnswerSyntaxError("the answer is empty.")
    return text


def _commas_between_equations(text: str) -> str:
    """``a = b, c = d`` (commas outside brackets, every part an equation) as ``a = b; c = d``."""
    if "," not in text or text.count("=") < 2:
        return text
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    if len(parts) > 1 and all("=" in part for part in parts):
        return ";".join(parts)
    return text


def _hint(token: str) -> str:
    if token in ("'", '"'):
        return " (quotes are not part of a formula; primes go right after a name: theta')"
    if token == "!":
        return " (factorials are not supported)"
    if token.startswith("\\"):
        return f" (the LaTeX command {token} is not supported)"
    if token == "=":
        return " (one `=` per equation)"
    return ""


def _context(text: str, exc) -> str:
    line = text.splitlines()[exc.line - 1] if getattr(exc, "line", 0) and exc.line > 0 else text
    col = max(getattr(exc, "column", 1) - 1, 0)
    snippet = line[max(col - 20, 0): col + 20]
    return f": ...{snippet}..." if snippet else ""


_WHERE = re.compile(r"(?<![A-Za-z0-9_])where(?![A-Za-z0-9_])", re.I)


def split_where(text: str, limits: Limits = LIMITS) -> tuple[str, list[Equation]]:
    """``answer; where x = 2*l*cos(theta) - l0`` -> ``(answer, [the map's equations])``.

    The student's own coordinates, each ``name = expression`` (separated by ``;``, ``,``,
    ``and`` or new lines), read by the same grammar as the answer (:func:`parse`); ``[]``
    when the answer states no map.

    >>> answer, maps = split_where("M*x'' + k*x = 0; where x = 2*l*cos(theta) - l0")
    >>> answer, [m.text for m in maps]
    ("M*x'' + k*x = 0", ['x = 2*l*cos(theta) - l0'])
    """
    if not isinstance(text, str) or not _WHERE.search(text):
        return text, []
    answer, clause = _WHERE.split(text, maxsplit=1)
    if _WHERE.search(clause):
        raise AnswerSyntaxError("write `where` once, then every map: `where x = ..., y = ...`.")
    answer = answer.rstrip().rstrip(";,").rstrip()
    parts, depth, cur = [], 0, ""
    for ch in re.sub(r"(?<![A-Za-z0-9_])and(?![A-Za-z0-9_])", ";", clause):
        depth += ch in "([{"
        depth -= ch in ")]}"
        if ch in ",;\n" and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    maps = []
    for part in (p for p in parts if p.strip()):
        eqs = parse(part, limits)
        if len(eqs) != 1 or eqs[0].rhs is None or eqs[0].lhs.op != "name" or \
                eqs[0].lhs.args[1]:
            raise AnswerSyntaxError(f"after `where`, write each coordinate as `name = "
                                    f"expression` (got `{part.strip()}`).")
        maps.append(eqs[0])
    if not answer.strip() or not maps:
        raise AnswerSyntaxError("write the answer, then `where x = ...` for your own "
                                "coordinates.")
    return answer, maps
