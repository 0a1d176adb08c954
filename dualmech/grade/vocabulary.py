r"""The names an answer may use for one problem, with their accepted aliases.

A :class:`Vocabulary` maps what a student types to the problem's own sympy symbols: the
coordinates and their first and second derivatives (as the plain symbols of
:func:`dualmech.model.equations.state_symbols`), the parameters, the reactions and multipliers, time
``t``, ``pi`` and, for vector answers, the basis vectors of the quantity asked for.

Aliases, for a coordinate ``theta``: ``θ``, ``\theta``, ``th``; derivatives ``theta'``,
``theta''``, ``thetadot``, ``thetaddot``, ``theta_dot``, ``theta_ddot``, ``theta_d``,
``theta_dd``, ``dtheta``, ``ddtheta``, ``\dot{\theta}``, ``θ̇``.  Subscripts may be written
with or without ``_`` and braces (``m_0``, ``m0``, ``m_{0}``).  A name that is none of these is
read as a product of one-letter names when every letter is one (``mgl`` is ``m*g*l``;
``thetaa`` is an unknown name, not ``theta*a``).  An alias that would mean two different things in one problem is dropped.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate
>>> th = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
>>> v = Vocabulary.build(coordinates=[th], parameters=[m, l, g])
>>> v.lookup("thetadot", 0).symbol, v.lookup("θ", 2).symbol, v.lookup("ml", 0)
(theta_dot, theta_ddot, None)
>>> [r.symbol for r in v.split("mgl")]
[m, g, l]
"""
from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from typing import Sequence

import sympy as sp

from dualmech.model.equations import state_symbols
from dualmech.model.kinematics import t as TIME
from dualmech.grade.parser import GREEK

__all__ = ["Ref", "Vocabulary", "UnknownName", "symbol_table"]

_LETTER = {v: k for k, v in GREEK.items() if not k.startswith("var")}  # θ -> theta
_SHORT = {"theta": "th", "phi": "ph", "psi": "ps", "omega": "w"}
_ORDER_WORDS = (("ddot", 2), ("_ddot", 2), ("dot", 1), ("_dot", 1), ("_dd", 2), ("_d", 1))


class UnknownName(ValueError):
    """A name the problem does not define; the message lists the names it does."""


@dataclass(frozen=True)
class Ref:
    """What a name means: ``kind`` (``coordinate``, ``parameter``, ``reaction``, ``time``,
    ``constant``, ``basis``), the plain ``symbol`` and, for coordinates, the derivative
    ``order`` (0, 1 or 2) and the coordinate's ``base`` name."""

    kind: str
    symbol: object
    order: int = 0
    base: str = ""



def _greek_forms(name: str) -> list[str]:
    """``theta1`` -> ``θ1``; ``omega`` -> ``ω``; names that are not Greek -> []."""
    for word in sorted(GREEK, key=len, reverse=True):
        if name.startswith(word) and not word.startswith("var"):
            rest = name[len(word):]
            if rest == "" or rest[0].isdigit() or rest[0] == "_":
                return [GREEK[word] + rest]
    return []


def _normal(name: str) -> str:
    return name.replace("_", "")


@dataclass
class Vocabulary:
    """Names -> :class:`Ref`; build with :meth:`build` (see the module docstring)."""

    table: dict = field(default_factory=dict)      # exact alias -> Ref
    normal: dict = field(default_factory=dict)     # alias without underscores -> Ref
    canonical: dict = field(default_factory=dict)  # kind -> [display names]
    aliases: dict = field(default_factory=dict)    # canonical name -> [aliases]
    _owners: dict = field(default_factory=dict)    # canonical name -> its Ref
    rates: dict = field(default_factory=dict)      # (coordinate name, order) -> Ref

    @classmethod
    def build(cls, coordinates: Sequence = (), parameters: Sequence = (),
              reactions: Sequence = (), basis: Sequence[str] = (),
              extra_coordinates: Sequence = (), aliases: dict | None = None) -> "Vocabulary":
        """Vocabulary of coordinates ``q(t)``, parameter and reaction symbols, basis names;
        ``aliases`` (``{"l": "a"}``) are extra names a problem declares for its symbols,
        accepted only where they do not clash with a name of the problem."""
        v = cls()
        clash: set = set()
        for q in list(coordinates) + list(extra_coordinates):
            s = state_symbols(q)
            name = s.name
            for order, sym in enumerate((s.q, s.qd, s.qdd)):
                v.rates[(name, order)] = Ref("coordinate", sym, order, name)
            ref = v.rates[(name, 0)]
            forms = [name] + _greek_forms(name)
            if name in _SHORT:
                forms.append(_SHORT[name])
            v._add(name, "coordinate", forms, ref, clash)
            for a in forms:
                for word, order in _ORDER_WORDS:
                    v._put(a + word, v.rates[(name, order)], clash)
                v._put("d" + a, v.rates[(name, 1)], clash)
                v._put("dd" + a, v.rates[(name, 2)], clash)
        for p in parameters:
            v._add(str(p), "parameter", [str(p)] + _greek_forms(str(p)), Ref("parameter", p),
                   clash)
        for r in reactions:
            v._add(str(r), "reaction", [str(r)], Ref("reaction", r), clash)
        for b in basis:
            v._add(b, "basis", [b], Ref("basis", sp.Symbol(b, commutative=True)), clash)
        if "t" not in v.table:
            v._add("t", "time", ["t"], Ref("time", TIME), clash)
        for name in ("pi", "π"):
            if name not in v.table:
                v.table[name] = Ref("constant", sp.pi)
        for alias, target in (aliases or {}).items():
            ref = v.table.get(str(target))
            if ref is not None and ref.kind != "basis" and alias not in v.table and \
                    str(alias).isidentifier():
                v.table[alias] = ref
                v.aliases.setdefault(str(target), []).append(alias)
        for alias in clash:
            owner = v._owners.get(alias)
            if owner is not None:
                v.table[alias] = owner      # a symbol's own name beats another's alias
            else:
                v.table.pop(alias, None)
        for alias, ref in v.table.items():
            key = _normal(alias)
            if key in v.normal and v.normal[key] != ref:
                v.normal[key] = None  # ambiguous without underscores
            else:
                v.normal.setdefault(key, ref)
        return v

    def _add(self, name, kind, forms, ref, clash):
        if name in self._owners and self._owners[name] != ref:
            self._owners[name] = None       # two symbols with one name: neither wins
        else:
            self._owners[name] = ref
        self.canonical.setdefault(kind, []).append(name)
        self.aliases[name] = [f for f in forms if f != name]
        for f in forms:
            self._put(f, ref, clash)

    def _put(self, alias, ref, clash):
        old = self.table.get(alias)
        if old is not None and old != ref:
            clash.add(alias)
        self.table[alias] = ref

    # -- lookup ------------------------------------------------------------------------
    def lookup(self, name: str, primes: int = 0) -> Ref | None:
        """The meaning of ``name`` with ``primes`` extra derivatives, or ``None``."""
        ref = self.table.get(name)
        if ref is None:
            ref = self.normal.get(_normal(name))
        return self.differentiated(ref, primes) if ref is not None else None

    def differentiated(self, ref: Ref, n: int) -> Ref | None:
        """``ref`` with ``n`` more primes (``None`` if that is not allowed)."""
        if n == 0:
            return ref
        if ref.kind != "coordinate" or ref.order + n > 2:
            return None
        return self.rates.get((ref.base, ref.order + n))

    def split(self, name: str, primes: int = 0) -> list[Ref] | None:
        """``name`` as a product of one-letter names (``mgl``; primes on the last), when that
        reading is unique; longer names are never split (``thetaa`` is a typo, not
        ``theta*a``)."""
        if not name.isalnum() or len(name) > 24:
            return None
        best: dict = {0: [[]]}  # position -> splits reaching it (shortest only)
        for i in range(len(name)):
            if i not in best:
                continue
            for j in range(i + 1, i + 2):
                ref = self.table.get(name[i:j])
                if ref is None or ref.kind == "basis":
                    continue
                paths = [p + [name[i:j]] for p in best[i]]
                if j not in best or len(paths[0]) < len(best[j][0]):
                    best[j] = paths
                elif len(paths[0]) == len(best[j][0]):
                    best[j] = best[j] + paths
        found = best.get(len(name))
        if not found or len(found) != 1 or len(found[0]) < 2:
            return None
        refs = [self.table[p] for p in found[0]]
        last = self.differentiated(refs[-1], primes)
        return None if last is None else refs[:-1] + [last]

    def resolve(self, name: str, primes: int = 0) -> list[Ref]:
        """``[Ref]`` for a known name, several for an implicit product; else :class:`UnknownName`."""
        ref = self.lookup(name, primes)
        if ref is not None:
            return [ref]
        base = self.lookup(name, 0)
        if base is not None:
            if base.kind == "coordinate":
                raise UnknownName(f"`{name}" + "'" * primes + "`: at most second derivatives "
                                  "of a coordinate may appear.")
            raise UnknownName(f"`{name}" + "'" * primes + f"`: only coordinates have "
                              f"derivatives; `{name}` is a {base.kind}.")
        parts = self.split(name, primes)
        if parts is not None:
            return parts
        raise UnknownName(self.unknown_message(name))

    def unknown_message(self, name: str) -> str:
        close = difflib.get_close_matches(name, list(self.table), n=3, cutoff=0.6)
        hint = f" Did you mean {', '.join(f'`{c}`' for c in close)}?" if close else ""
        shown = f"`{name}`" if len(name) <= 40 else \
            f"`{name[:20]}...{name[-8:]}` ({len(name)} characters)"
        return f"unknown name {shown}.{hint} {self.describe()}"

    def describe(self) -> str:
        """The problem's names and aliases, in one paragraph."""
        parts = []
        for kind, label in (("coordinate", "coordinates"), ("parameter", "parameters"),
                            ("reaction", "reactions"), ("basis", "basis vectors")):
            names = self.canonical.get(kind, [])
            if names:
                shown = []
                for n in names:
                    al = [a for a in self.aliases.get(n, []) if self.table.get(a) is not None]
                    shown.append(f"{n} ({', '.join(al)})" if al else n)
                parts.append(f"{label}: {', '.join(shown)}")
        coords = self.canonical.get("coordinate", [])
        if coords:
            q = coords[0]
            parts.append(f"derivatives: {q}', {q}'' (or {q}dot, {q}ddot, {q}_d, {q}_dd, "
                         f"d{q}, dd{q}, \\dot{{{q}}})")
        parts.append("time: t")
        return "The problem's names are: " + "; ".join(parts) + "."


def symbol_table(ctx) -> list[dict]:
    """Every name an answer to the problem of ``ctx`` (a grading context) may use: ``name``,
    ``kind``, other accepted spellings (``aliases``), SI ``unit`` and ``description``.
    Coordinates that a model keeps constant (a multiplier model's ``rho = R``) are internal
    and left out.

    >>> from dualmech.grade import Grader
    >>> rows = symbol_table(Grader.of("simple_pendulum").context)
    >>> [(r["name"], r["aliases"], r["unit"]) for r in rows if r["name"] == "a"]
    [('a', ['l'], 'm')]
    >>> [(r["name"], r["unit"]) for r in rows if r["kind"] == "reaction"]
    [('T', 'kg m s^-2')]
    """
    voc, problem = ctx.vocabulary, ctx.problem
    units = {str(sym): _si(dim) for sym, dim in ctx.dims.items()}
    internal = set()
    try:
        maps = problem.coordinate_maps()
    except Exception:   # a problem without maps has no internal coordinates
        maps = {}
    reference = {state_symbols(q).q for q in ctx.coordinates}
    for mapping in maps.values():
        for q, expr in mapping.items():
            expr = sp.sympify(expr, strict=True)
            if not expr.atoms(sp.Function) and q.func.__name__ not in reference:
                internal.add(q.func.__name__)
    described = {str(p.symbol): p.description for p in problem.parameters}
    for c in problem.coordinates:
        described[c.name] = c.description
    for name, info in problem.reaction_info().items():
        described[name] = f"reaction ({info.direction})" if getattr(info, "direction", "") \
            else "reaction"
    rows = []
    for kind in ("coordinate", "parameter", "reaction"):
        for n in voc.canonical.get(kind, []):
            if n in internal:
                continue
            also = [a for a in voc.aliases.get(n, []) if voc.table.get(a) is not None]
            rows.append({"name": n, "kind": kind, "aliases": also,
                         "unit": units.get(n, ""), "description": described.get(n, "")})
    return rows


_SI = {"mass": "kg", "length": "m", "time": "s", "current": "A", "temperature": "K",
       "amount_of_substance": "mol", "luminous_intensity": "cd"}


def _si(dim) -> str:
    """A reduced dimension (``(("length", 1), ("time", -2))``) in SI units: ``m s^-2``."""
    if not dim:
        return "1"
    parts = []
    for name, e in sorted(dim, key=lambda ne: list(_SI).index(ne[0]) if ne[0] in _SI else 9):
        unit = _SI.get(name, name)
        parts.append(unit if e == 1 else f"{unit}^{e}")
    return " ".join(parts)
