"""Branch cases: which pieces of ``Abs``/``sign``/``Heaviside``/``Max``/``Min``/``Piecewise`` occur.

A branch function is one of its rational pieces on each region where its conditions ``g_j``
have fixed signs.  Two expressions with branches agree almost everywhere exactly when, for
every sign vector ``s`` whose region ``{sign g_j = s_j}`` has interior points in the domain,
their pieces agree there -- and pieces are analytic, so they agree on that open region exactly
when they agree identically.  Each *case* (a combination of pieces) is therefore decided by the
exact test on its pieces, with no sampling inside the region.

What the regions need is the real domain: a case is

* ``witnessed`` when a real point of the domain certainly has its signs (interval arithmetic);
  a difference there is a certain difference;
* dropped when interval bisection proves its region empty (``sqrt(1 - cos^2)`` is ``sin`` on a
  declared domain ``(0, pi)``);
* ``unknown`` otherwise: it is still tested (an "equal" needs it), but a difference found
  only there is not a proof (:meth:`dualmech.exact.form.ExactForm.certain` says so).

Example
-------
>>> import sympy as sp
>>> from dualmech.exact.sample_space import analyse
>>> th = sp.Symbol("theta")
>>> w = analyse([sp.Abs(sp.cos(th))], [th])
>>> sorted(c.status for c in find_cases(w, {}))
['witnessed', 'witnessed']
>>> w = analyse([sp.Abs(sp.sin(th))], [th])
>>> [c.where for c in find_cases(w, {th: (0, 3)})]
['sin(theta) > 0']
"""
from __future__ import annotations

import math
import random
from collections import deque
from dataclasses import dataclass
from itertools import product

import sympy as sp
from mpmath import iv

from dualmech.exact.interval import Ambiguous, IntervalProgram, Unsupported, domain_of, real_sample
from dualmech.exact.sample_space import NotExact, World

__all__ = ["Case", "find_cases", "regions", "MAX_CONDITIONS", "MAX_CASES"]

#: At most this many distinct branch conditions, and this many cases, are split exactly.
MAX_CONDITIONS = 10
MAX_CASES = 64
_RANDOM_POINTS = 48
_BOXES = 600


@dataclass(frozen=True)
class Case:
    """One combination of branch pieces: ``choices[i]`` is the piece of branch ``i``."""

    choices: tuple
    signs: tuple
    status: str          # "witnessed" or "unknown"
    labels: tuple = ()   # where each chosen piece applies (written out on demand)

    @property
    def where(self) -> str:
        """The case in words: the conditions under which its pieces apply."""
        out: list = []
        for label in map(str, self.labels):
            if label not in out:
                out.append(label)
        return " and ".join(out)


def find_cases(world: World, domains: dict, seed: int = 0) -> list[Case]:
    """The cases of ``world``'s branches that can occur in the domain, witnessed ones first."""
    if not world.branches:
        return [Case((), (), "witnessed")]
    conds = world.conds
    if len(conds) > MAX_CONDITIONS:
        raise NotExact(world.branches[0].node,
                       f"{len(conds)} branch conditions (more than {MAX_CONDITIONS} are not "
                       "split exactly)")
    groups: dict = {}
    for signs in product((1, -1), repeat=len(conds)):
        choices = tuple(b.pick(signs) for b in world.branches)
        if None not in choices:
            groups.setdefault(choices, []).append(signs)
    if len(groups) > MAX_CASES:
        raise NotExact(world.branches[0].node, f"{len(groups)} combinations of branch pieces")
    space = _world_space(world, domains)
    if space is not None:
        exprs, boxes = space
        natural = boxes
    else:
        exprs = [c.real for c in conds]
        syms = sorted(set().union(*(e.free_symbols for e in exprs)), key=str)
        periods = periods_of(exprs, syms)
        boxes = {s: _box(s, domains, periods) for s in syms}
        natural = {s: domain_of(s, domains) for s in syms}
    try:
        prog = IntervalProgram(exprs)
    except Unsupported as exc:
        raise NotExact(exc.expr, f"a branch condition has no interval evaluation: {exc.why}")
    syms = list(boxes)
    wanted = {s for sigmas in groups.values() for s in sigmas}
    seen = _random_witnesses(prog, syms, boxes, natural, wanted, random.Random(seed))
    open_boxes: list = []
    if wanted - seen.keys():
        seen.update(_bisect(prog, boxes, wanted - seen.keys(), open_boxes))
    out = []
    for choices, sigmas in groups.items():
        hit = [s for s in sigmas if s in seen]
        where = tuple(b.labels[c] for b, c in zip(world.branches, choices))
        if hit:
            out.append(Case(choices, hit[0], "witnessed", where))
            continue
        possible = [s for s in sigmas if any(_consistent(s, p) for p in open_boxes)]
        if possible:
            out.append(Case(choices, possible[0], "unknown", where))
    out.sort(key=lambda c: c.status != "witnessed")
    if not out:
        raise NotExact(world.branches[0].node, "no branch case occurs in the declared domain")
    return out


def regions(conditions, domains: dict, seed: int = 0) -> list[dict]:
    """Boxes ``{symbol: (lo, hi)}`` of the domain, one per sign vector of ``conditions`` that
    random points or interval bisection find (a point for a degenerate box).

    The interval method samples them in turn with random points of the whole domain, so a
    branch region far out (``Heaviside(t - 1e9)``) or a narrow domain (``sqrt(x - 1e9)``)
    is visited.
    """
    conditions = list(conditions)[:MAX_CONDITIONS]
    if not conditions:
        return []
    try:
        prog = IntervalProgram(conditions)
    except Unsupported:
        return []
    syms = sorted(set().union(*(e.free_symbols for e in conditions)), key=str)
    natural = {s: domain_of(s, domains) for s in syms}
    wanted = set(product((1, -1), repeat=len(conditions)))
    seen = _random_witnesses(prog, syms, natural, natural, wanted, random.Random(seed))
    if wanted - seen.keys():
        seen.update(_bisect(prog, natural, wanted - seen.keys(), []))
    return list(seen.values())


def _box(sym, domains, periods) -> tuple[float, float]:
    lo, hi = domain_of(sym, domains)
    if sym in periods and not (sym in (domains or {})):
        return 0.0, periods[sym]
    return lo, hi


def _signs(vals) -> list[set]:
    """Signs each condition can take on the box: ``+1`` needs some value ``> 0``, ``-1`` some
    value ``< 0`` (an interval ``[0, x]`` excludes ``-1``: the condition is ``>= 0`` there)."""
    return [({1} if v.b > 0 else set()) | ({-1} if v.a < 0 else set()) for v in vals]


def _certain(vals) -> tuple | None:
    """The sign vector when every condition has a certain strict sign on the box."""
    out = []
    for v in vals:
        if v.a > 0:
            out.append(1)
        elif v.b < 0:
            out.append(-1)
        else:
            return None
    return tuple(out)


def _random_witnesses(prog, syms, boxes, natural, wanted, rng) -> dict:
    """``{sign vector: witness}`` from random points (a witness is a degenerate box)."""
    seen: dict = {}
    for _ in range(_RANDOM_POINTS):
        point = {}
        for s in syms:
            lo, hi = boxes[s] if rng.random() < 0.5 else natural[s]
            point[s] = real_sample(rng, lo, hi)
        try:
            signs = _certain(prog.evaluate(point))
        except (Ambiguous, ZeroDivisionError, ValueError):
            continue
        if signs is not None and signs not in seen:
            seen[signs] = {s: (point[s], point[s]) for s in syms}
        if wanted <= seen.keys():
            break
    return seen


def _bisect(prog, boxes, missing, open_boxes) -> dict:
    """Witness sign vectors by interval bisection (``{sign vector: box where it holds}``);
    leave the sign sets of undecided boxes in ``open_boxes``."""
    syms = list(boxes)
    queue = deque([dict(boxes)])
    seen: dict = {}
    budget = _BOXES
    while queue and budget and not missing <= seen.keys():
        box = queue.popleft()
        budget -= 1
        try:
            vals = prog.evaluate({s: _iv(*box[s]) for s in syms})
        except (Ambiguous, ZeroDivisionError, ValueError):
            vals = None
        sets = _signs(vals) if vals is not None else [{1, -1}] * len(prog.exprs)
        if any(not x for x in sets):
            continue
        signs = _certain(vals) if vals is not None else None
        if signs is not None:
            seen.setdefault(signs, box)
            continue
        halves = _split(box)
        if halves is None:
            open_boxes.append(sets)
        else:
            queue.extend(halves)
    for box in queue:
        try:
            open_boxes.append(_signs(prog.evaluate({s: _iv(*box[s]) for s in syms})))
        except (Ambiguous, ZeroDivisionError, ValueError):
            open_boxes.append([{1, -1}] * len(prog.exprs))
    return seen


def _consistent(signs, sets) -> bool:
    return all(s in x for s, x in zip(signs, sets))


def _iv(lo, hi):
    return iv.mpf([lo, hi])


def _split(box):
    best, width = None, 0.0
    for s, (lo, hi) in box.items():
        w = hi - lo
        if w > width:
            best, width = s, w
    if best is None or width < 1e-12:
        return None
    lo, hi = box[best]
    if math.isinf(lo) and math.isinf(hi):
        mid = 0.0
    elif math.isinf(hi):
        mid = lo + max(1.0, 2 * abs(lo))
    elif math.isinf(lo):
        mid = hi - max(1.0, 2 * abs(hi))
    else:
        mid = (lo + hi) / 2
    a, b = dict(box), dict(box)
    a[best], b[best] = (lo, mid), (mid, hi)
    return [a, b]


def _world_space(world: World, domains: dict):
    """The conditions in the world's own variables, with each variable's box, when those
    variables are independent images of the domain (each symbol feeds one of them: bare, or
    one atom ``symbol/L``); else ``None`` (the conditions are then read in the symbols).

    A circle atom's ``u = tan(a/2)`` covers all reals for a full turn of its symbol, else the
    image of the declared interval (no pole inside); a growth atom's ``w = exp(b)`` the image of
    the symbol's interval.  Polynomial conditions in these variables bisect well.
    """
    conds = world.conds
    if any(c.u_form is None for c in conds):
        return None
    atom_of = {d: i for i, d in world.u_dummies.items()}
    back = {world.pi: sp.pi} if world.pi is not None else {}
    exprs = [c.u_form.xreplace(back) for c in conds]
    boxes, sources = {}, set()
    for v in sorted(set().union(*(e.free_symbols for e in exprs)), key=str):
        i = atom_of.get(v)
        if i is None:
            sym, box = v, domain_of(v, domains)
        else:
            kind, mono, L = world.scales[i]
            if not mono.is_Symbol:
                return None
            sym, box = mono, _atom_box(kind, L, domain_of(mono, domains))
            if box is None:
                return None
        if sym in sources:
            return None
        sources.add(sym)
        boxes[v] = box
    return exprs, boxes


def _atom_box(kind, L, dom):
    lo, hi = dom
    if kind == "growth":
        return (math.exp(lo / L) if math.isfinite(lo) else 0.0,
                math.exp(hi / L) if math.isfinite(hi) else math.inf)
    a, b = lo / (2 * L), hi / (2 * L)
    if not (math.isfinite(a) and math.isfinite(b)) or b - a >= math.pi:
        return (-math.inf, math.inf)
    pole = math.pi / 2 + math.ceil((a - math.pi / 2) / math.pi) * math.pi
    margin = 1e-12 * max(1.0, abs(pole))
    if a < pole - margin and pole + margin < b:
        return None
    ta = -math.inf if abs(a - pole) <= margin else math.tan(a)
    tb = math.inf if abs(b - pole) <= margin or abs(b - pole - math.pi) <= margin else math.tan(b)
    return (ta, tb)


def periods_of(exprs, symbols) -> dict:
    """Symbols that enter ``exprs`` only through ``sin``/``cos``/``tan`` of rational multiples:
    ``{symbol: period}`` (the conditions repeat with that period in the symbol)."""
    out = {}
    for s in symbols:
        q = _period_denominator(exprs, s)
        if q:
            out[s] = 2 * math.pi * q
    return out


def _period_denominator(exprs, s) -> int | None:
    q = 1
    stack = list(exprs)
    while stack:
        e = stack.pop()
        if e == s:
            return None
        if not e.has(s):
            continue
        if isinstance(e, (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)):
            c = e.args[0].coeff(s)
            rest = sp.expand(e.args[0] - c * s)
            if not c.is_Rational or rest.has(s):
                return None
            q = math.lcm(q, int(c.q))
            continue
        stack.extend(e.args)
    return q

