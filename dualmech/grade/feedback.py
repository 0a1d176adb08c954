"""Say what is wrong with a wrong answer: the smallest edit, named as terms.

A wrong equation is compared with *targets*: correct equations written the way people write
them -- every row of every model of the problem (Lagrange, Newton--Euler with its reactions,
angular momentum, ...), in the reference coordinates, and simple combinations that eliminate a
reaction.  Both sides are expanded into terms ``coefficient x state part`` (the coefficient
free of the state, the state part a product of coordinates, rates, accelerations, reactions,
trigonometric functions and time).  For each target and each scale factor suggested by a shared
term, the terms that differ are the edit: a term **missing**, one **extra**, a wrong **sign**, a
wrong **coefficient** (``l`` where ``l^2`` belongs), two symbols of the same dimension
**swapped**.  The target needing the fewest edits wins; a small edit is reported, otherwise a
concrete state where answer and truth differ.

The edit is only ever a suggestion about *which* correct form the student meant: the verdict
itself came from exact evaluation (:mod:`.answers`).  Every suggested form is a correct
equation by construction (a constant multiple of a verified one).  Coefficients are compared
exactly at a random point of the parameters.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.grade.context import ProblemContext
>>> ctx = ProblemContext.of(get("simple_pendulum"))
>>> import sympy as sp
>>> th, thdd = sp.Symbol("theta", real=True), sp.Symbol("theta_ddot", real=True)
>>> a, g = sp.symbols("a g", positive=True)
>>> from dualmech.grade.terms import equation_targets
>>> d = best_edit(a*thdd - g*sp.sin(th), lambda mode: equation_targets(ctx, mode), ctx)
>>> [e.sentence() for e in d.edits]
['the term `-g*sin(theta)` has the wrong sign: it is `g*sin(theta)` (a gravity term)']
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp

from dualmech.exact.form import MP_DIGITS
from dualmech.model.kinematics import t
from dualmech.grade.context import ProblemContext, zero
from dualmech.grade.audit import display
from dualmech.grade.formula import Formula
from dualmech.grade.kinds import category as _category
from dualmech.grade.result import Edit
from dualmech.grade.terms import MODES, TermTable, coefficient_env, state_symbols, term_table

__all__ = ["best_edit", "Diagnosis", "concrete_state", "category", "swap_pairs", "MAX_EDITS",
           "differing_kinds"]

MAX_EDITS = 3


@dataclass
class Diagnosis:
    """The closest target, the scale applied to it, and the edits from the answer to it."""

    label: str
    scale: object
    edits: list
    size: int


def best_edit(expr, targets, ctx: ProblemContext, scale: bool = True,
              equation: int | None = None, parts: list | None = None) -> Diagnosis | None:
    """The target needing the fewest term edits to turn ``expr`` into it, or None when none
    is small (at most :data:`MAX_EDITS` edits, fewer than the answer has terms).

    ``targets(mode)`` gives the correct forms for each of :data:`MODES`; the first mode
    reaching the fewest edits wins.  Among equally small edits, a target at the answer's own
    scale, then an earlier target (the reference model's rows come first), is preferred.
    """
    found = None
    for mode in MODES:
        d = _best(expr, targets(mode), ctx, scale, equation, mode, parts)
        if d is not None and (found is None or d.size < found.size):
            found = d
        if found is not None and found.size <= 1:
            break
    return found


def _best(expr, targets, ctx, scale, equation, mode, parts=None) -> Diagnosis | None:
    mine = term_table(expr, ctx, mode=mode, parts=parts)
    if mine is None or not mine.terms:
        return None
    ranked = []
    for index, tab in enumerate(targets):
        for c in _scales(mine, tab) if scale else [Fraction(1)]:
            ranked.append((_count(mine, tab, c), c != 1, index, tab, c))
    if not ranked:
        return None
    ranked.sort(key=lambda r: r[:3])
    # the few closest by single terms, ranked again with the written groups (a group the
    # student dropped, wrote extra or flipped is one edit, as they wrote it); among equally
    # small edits, the scale the student grouped their terms by (the most terms written
    # exactly, the simplest factor) before a rescaled one
    cut = ranked[0][0] + 2
    best = None
    for size, other, index, tab, c in ranked[:24]:
        if size > cut:
            break
        plan = _plan(mine, tab, c, ctx, parts)
        rank = (_plan_size(mine, tab, c, plan), -_matched(mine, tab, c), _height(mine, tab, c),
                other, index)
        if best is None or rank < best[0]:
            best = (rank, tab, c, plan)
    (size, matched, _, _, _), tab, c, plan = best
    if scale and size >= 2 and len(mine.terms) >= 2:
        combined = _combination(mine, targets, ctx, parts, size)
        if combined is not None:
            return _describe(mine, combined[0], Fraction(1), ctx, equation, combined[1])
    kept = sum(1 for k in mine.terms if k in tab.terms)
    if size > max(len(mine.terms) - 1, 1) and _stray(mine, tab, c):
        return None     # a term of the answer on no state part of the correct form
    if size == 0 or not _small(size, -matched, len(mine.terms), kept):
        return None
    if len(mine.terms) > 1 and set(mine.terms) <= set(_differences(mine, tab, c)):
        return None     # every term the student wrote changes: a rewrite, not an edit
    d = _describe(mine, tab, c, ctx, equation, plan, parts)
    return d if d.size <= MAX_EDITS else None    # described in more edits than believable


def _small(size: int, matched: int, written: int, kept: int | None = None) -> bool:
    """An edit of ``size`` terms is believable: fewer edits than the answer has terms, or up
    to :data:`MAX_EDITS` when a term is written exactly as the correct form has it
    (``matched``) and the terms the student kept (``kept``, default ``matched``: state parts
    the correct form has too, whatever their coefficients) are at least all but one of the
    edits (``C psi'' = 0`` for the spin equation: one term kept, two missing)."""
    kept = matched if kept is None else kept
    if size > MAX_EDITS:
        return False
    return size <= max(written - 1, 1) or (matched >= 1 and kept >= size - 1)


def _stray(mine: TermTable, tab: TermTable, c) -> bool:
    """Whether the answer has a term on a state part the correct form lacks, with a
    coefficient no wrong term of the correct form has (not a wrong function: a term the
    student made up, or wrote beyond recognition)."""
    _, pairs = _count_paired(mine, tab, c)
    paired = {p[0] for p in pairs}
    return any(k not in tab.terms and k not in paired for k in mine.terms)


def _matched(mine: TermTable, tab: TermTable, c) -> int:
    """How many of the answer's terms are exactly ``c`` times the target's."""
    return sum(1 for k, (_, v, _) in mine.terms.items()
               if k in tab.terms and zero(v - c * tab.terms[k][1], [v]))


def _height(mine: TermTable, tab: TermTable, c) -> int:
    """The size of the number in the scale factor ``c`` (1 for ``1/m``, 3 for ``3/m``)."""
    if c == 1:
        return 1
    for k in mine.terms:
        if k in tab.terms and zero(mine.terms[k][1] - c * tab.terms[k][1], [1]):
            num = sp.cancel(mine.terms[k][0] / tab.terms[k][0]).as_coeff_Mul()[0]
            if num.is_Rational:
                return max(abs(int(num.p)), int(num.q))
            break
    return 1 << 30


def _accelerations_first(keys) -> list:
    return sorted(keys, key=lambda k: 0 if any(s.name.endswith("_ddot")
                                               for s in k.free_symbols) else 1)


def _combination(mine: TermTable, targets, ctx, parts, size: int):
    """``(target, plan)`` when the answer is a combination ``a A + b B`` of two rows of one
    model (``a``, ``b`` free of the state) with fewer than ``size`` edits -- a slip inside an
    equation the student combined -- else None.  ``a`` and ``b`` come from two of the
    answer's terms (accelerations first) solved against the two rows; the answer must keep
    a term of each row that the other lacks, written exactly."""
    models: dict = {}
    for tb in targets:
        if " minus (" not in tb.label:
            models.setdefault(tb.label.split(":")[0], []).append(tb)
    pairs = [(a, b) for rows in list(models.values())[:4] for i, a in enumerate(rows[:8])
             for b in rows[i + 1:8]]
    keys = _accelerations_first(mine.terms)[:4]
    best = None
    for a, b in pairs:
        if True:
            for j, k1 in enumerate(keys):
                for k2 in keys[j + 1:]:
                    c = _solve_pair(mine, a, b, k1, k2, lambda e: e[1])
                    if c is None:
                        continue
                    vals = _combined_values(a, b, *c)
                    n = _count(mine, TermTable("", None, vals), 1)
                    if best is None or n < best[0]:
                        best = (n, a, b, k1, k2)
    if best is None or best[0] >= size:
        return None
    _, a, b, k1, k2 = best
    ca, cb = _solve_pair(mine, a, b, k1, k2, lambda e: e[0], sp.cancel)
    model, _, first = a.label.partition(": ")
    words = f"{model}: combination of {first} and {b.label.split(': ', 1)[1]}"
    tab = term_table(sp.expand(ca * a.expr + cb * b.expr), ctx, words, mine.mode)
    if tab is None:
        return None
    plan = _plan(mine, tab, 1, ctx, parts)
    n = _plan_size(mine, tab, 1, plan)
    kept = [k for k in mine.terms if k in tab.terms and zero(
        mine.terms[k][1] - tab.terms[k][1], [mine.terms[k][1]])]
    own_a = any(k in a.terms and k not in b.terms for k in kept)
    own_b = any(k in b.terms and k not in a.terms for k in kept)
    if n == 0 or n >= size or not (own_a and own_b) or not _small(n, len(kept),
                                                                   len(mine.terms)):
        return None
    return tab, plan


def _solve_pair(mine, a, b, k1, k2, part, simplify=None):
    """``(x, y)`` with ``x a + y b`` equal to the answer on the terms ``k1``, ``k2`` (values
    or, with ``part`` the coefficient, expressions), None when singular or one is zero."""
    def get(tab, k):
        return part(tab.terms[k]) if k in tab.terms else 0
    a1, b1, a2, b2 = get(a, k1), get(b, k1), get(a, k2), get(b, k2)
    m1, m2 = part(mine.terms[k1]), part(mine.terms[k2])
    det = a1 * b2 - a2 * b1
    if simplify is not None:
        return simplify((m1 * b2 - m2 * b1) / det), simplify((a1 * m2 - a2 * m1) / det)
    if zero(det, [a1 * b2, a2 * b1]):
        return None
    x, y = (m1 * b2 - m2 * b1) / det, (a1 * m2 - a2 * m1) / det
    if zero(x, [1]) or zero(y, [1]):
        return None
    return x, y


def _combined_values(a: TermTable, b: TermTable, x, y) -> dict:
    out = {}
    for k in set(a.terms) | set(b.terms):
        va = a.terms[k][1] if k in a.terms else 0
        vb = b.terms[k][1] if k in b.terms else 0
        v = x * va + y * vb
        if not zero(v, [x * va, y * vb]):
            out[k] = (None, v, [])
    return out


def differing_kinds(expr, targets, ctx: ProblemContext, parts: list | None = None):
    """When no small edit explains a wrong equation: the correct row it is closest to (the
    scale at which most of its terms are written exactly) and, by kind of term (inertia,
    gravity, Coriolis, ...), the sum ``written - right`` of the terms that differ there:
    ``(label, {kind: expression})``; None when no term of the answer is right at any scale.
    """
    mine = term_table(expr, ctx, mode="trig", parts=parts)
    if mine is None or not mine.terms:
        return None
    best = None
    for index, tab in enumerate(targets("trig")):
        for c in _scales(mine, tab):
            rank = (-_matched(mine, tab, c), _count(mine, tab, c), index)
            if best is None or rank < best[0]:
                best = (rank, tab, c)
    if best is None or best[0][0] == 0:
        return None
    _, tab, c = best
    shared = [k for k in mine.terms if k in tab.terms
              and zero(mine.terms[k][1] - c * tab.terms[k][1], [1])]
    c_sym = sp.cancel(mine.terms[shared[0]][0] / tab.terms[shared[0]][0])
    kinds: dict = {}
    for k in _differences(mine, tab, c):
        have = mine.terms[k][0] * k if k in mine.terms else sp.Integer(0)
        right = c_sym * tab.terms[k][0] * k if k in tab.terms else sp.Integer(0)
        kind = category(right if right != 0 else have, ctx) or "another term"
        kinds[kind] = kinds.get(kind, 0) + have - right
    return tab.label, kinds


def _differences(mine: TermTable, tab: TermTable, c) -> dict:
    """``{key: right - have}`` (values) of the state parts whose coefficients differ."""
    out = {}
    for k in set(mine.terms) | set(tab.terms):
        a = mine.terms[k][1] if k in mine.terms else 0
        b = tab.terms[k][1] * c if k in tab.terms else 0
        if not zero(a - b, [a, b]):
            out[k] = b - a
    return out


def _plan(mine: TermTable, tab: TermTable, c, ctx, parts) -> list:
    """Edits of whole written groups: ``[(kind, written term, keys)]`` -- a group of the
    target missing (``kind`` ``missing``), a group of the answer extra (``extra``) or with
    the wrong sign (``sign``) -- each covering keys whose differences it explains exactly."""
    diff = _differences(mine, tab, c)
    if len(diff) < 2:
        return []
    out, covered = [], set()

    def fits(vals, factor):
        return all(k in diff and k not in covered and
                   zero(diff[k] - factor * v, [diff[k], v]) for k, v in vals.items())
    for g, vals in tab.groups(ctx):
        if fits(vals, c):
            out.append(("missing", g, set(vals)))
            covered |= set(vals)
    mine_groups = mine.groups(ctx, parts) if parts is not None else []
    for g, vals in mine_groups:
        for kind, factor in (("extra", -1), ("sign", -2)):
            if fits(vals, factor):
                out.append((kind, g, set(vals)))
                covered |= set(vals)
                break
        else:
            swapped = _replaced_group(vals, diff, covered, tab, c)
            if swapped is not None:   # the group written where one correct term belongs
                out.append(("replace", (g, tab.terms[swapped][0] * swapped),
                            set(vals) | {swapped}))
                covered |= set(vals) | {swapped}
    return out


def _replaced_group(vals: dict, diff: dict, covered: set, tab: TermTable, c):
    """The key of the one correct term that a written group (``vals``) stands in place of:
    without the group, the answer differs from the target there by exactly that term and
    nowhere else on the group's keys (``m2 (x2' - x1')^2/2`` where ``m2 x2'^2/2`` belongs),
    and that one edit explains every difference; else None (a slip inside the group is
    named as that slip)."""
    if covered:
        return None
    rest = {k: diff.get(k, 0) + v for k, v in vals.items()}
    left = [k for k, v in rest.items() if not zero(v, [vals[k]])]
    if len(left) != 1 or left[0] not in tab.terms:
        return None
    k = left[0]
    if set(diff) - set(vals) - {k}:
        return None
    right = tab.terms[k][1] * c
    return k if zero(rest[k] - right, [right]) and not zero(right, [1]) else None


def _plan_size(mine, tab, c, plan) -> int:
    covered = set().union(*(keys for _, _, keys in plan)) if plan else set()
    return len(plan) + _count(mine, tab, c, covered)


def _scales(mine: TermTable, tab: TermTable) -> list:
    """Scale factors (values) suggested by terms the two share; accelerations first."""
    shared = [k for k in mine.terms if k in tab.terms]
    shared.sort(key=lambda k: 0 if any(s.name.endswith("_ddot") for s in k.free_symbols) else 1)
    out = []
    for k in shared:
        c = mine.terms[k][1] / tab.terms[k][1]
        if c not in out:
            out.append(c)
        if len(out) >= 6:
            break
    return out or [Fraction(1)]


def _count(mine: TermTable, tab: TermTable, c, skip=frozenset()) -> int:
    """Edits needed: each differing term, a wrong term with the right coefficient once
    (``skip``: keys already explained) -- or, when fewer, with every wrong term of the
    answer paired with a missing one of the same coefficient (:func:`_replacements`)."""
    return min(_count_keys(mine, tab, c, skip), _count_paired(mine, tab, c, skip)[0])


def _count_paired(mine: TermTable, tab: TermTable, c, skip=frozenset()):
    """``(edits, pairs)``: the answer's wrong terms paired with the correct form's terms of
    the same coefficient on another state part (``-R^2 m w^2 sin(theta)`` where ``... sin
    cos`` belongs, and ``g m R theta`` where ``sin(theta)`` belongs: two wrong functions,
    not a changed coefficient, an extra and a missing term); ``pairs`` ``[(have, right)]``
    keys."""
    have, right = {}, {}
    for k in (set(mine.terms) | set(tab.terms)) - set(skip):
        a = mine.terms[k][1] if k in mine.terms else 0
        b = tab.terms[k][1] * c if k in tab.terms else 0
        if not zero(a - b, [a, b]):
            if k in mine.terms:
                have[k] = a
            if k in tab.terms:
                right[k] = b
    pairs = []
    for k1, a in have.items():
        for k2, b in right.items():
            if k2 != k1 and zero(a - b, [a, b]) and all(k2 != p[1] for p in pairs):
                pairs.append((k1, k2))
                break
    rest = (set(have) - {p[0] for p in pairs}) | (set(right) - {p[1] for p in pairs})
    return len(pairs) + len(rest), pairs


def _count_keys(mine: TermTable, tab: TermTable, c, skip=frozenset()) -> int:
    n = 0
    extra, missing = [], []
    for k in (set(mine.terms) | set(tab.terms)) - set(skip):
        a = mine.terms[k][1] if k in mine.terms else 0
        b = tab.terms[k][1] * c if k in tab.terms else 0
        if not zero(a - b, [a, b]):
            n += 1
            if k not in tab.terms:
                extra.append(a)
            elif k not in mine.terms:
                missing.append(b)
    for a in extra:
        for i, b in enumerate(missing):
            if zero(a - b, [a, b]):
                n -= 1
                del missing[i]
                break
    return n


def _describe(mine: TermTable, tab: TermTable, c, ctx, equation, plan=(),
              parts=None) -> Diagnosis:
    shared = [k for k in mine.terms if k in tab.terms
              and zero(mine.terms[k][1] - c * tab.terms[k][1], [1])]
    if c == 1 or not shared:
        c_sym = sp.Integer(1)
    else:
        c_sym = sp.cancel(mine.terms[shared[0]][0] / tab.terms[shared[0]][0])
    names = ctx.names
    swaps = swap_pairs(ctx)
    if parts is not None:
        mine.groups(ctx, parts)     # what the student wrote as groups, and as single terms
    edits, missing, extra = [], [], []
    covered = set()
    skip = set().union(*(keys for _, _, keys in plan)) if plan else set()
    n_paired, pairs = _count_paired(mine, tab, c, skip)
    if pairs and n_paired < _count_keys(mine, tab, c, skip):
        edits, mine, tab = _paired_edits(mine, tab, pairs, c_sym, ctx, equation)
    for kind, g, keys in plan:
        covered |= keys
        if kind == "missing":
            right = c_sym * g if c_sym != 1 else g
            edits.append(Edit("missing", equation, "", display(right, names),
                              category(sp.expand(right), ctx)))
        elif kind == "extra":
            edits.append(Edit("extra", equation, display(g, names), "",
                              category(sp.expand(g), ctx)))
        elif kind == "replace":
            have, right = g[0], c_sym * g[1] if c_sym != 1 else g[1]
            edits.append(Edit("replace", equation, display(have, names), display(right, names),
                              category(sp.expand(right), ctx)))
        else:
            edits.append(Edit("sign", equation, display(g, names), display(-g, names),
                              category(sp.expand(g), ctx)))
    for k in list(mine.terms) + [k for k in tab.terms if k not in mine.terms]:
        if k in covered:
            continue
        a = mine.terms.get(k)
        if a is None and k in mine.hidden and k in tab.terms:   # written terms that cancel
            bv = tab.terms[k][1] * c
            sub = _written_term(mine.hidden[k], bv, k, ctx, equation, swaps)
            if sub is not None:
                edits.append(sub)
                continue
        b = tab.terms.get(k)
        av = a[1] if a else 0
        bv = b[1] * c if b else 0
        if zero(av - bv, [av, bv]):
            continue
        right = sp.expand(c_sym * b[0]) * k if b else None
        have = a[0] * k if a else None
        if a is None:
            missing.append(right)
        elif b is None:
            extra.append(have)
        elif zero(av + bv, [av, bv]):
            edits.append(Edit("sign", equation, display(have, names), display(right, names),
                              category(have, ctx)))
        else:
            part = _part_missing(mine, k, a, sp.expand(c_sym * b[0]))
            if part is not None:
                edits.append(Edit("missing", equation, "", display(part, names),
                                  category(part, ctx)))
            else:
                edits += _changed(a, sp.expand(c_sym * b[0]), bv, k, ctx, equation, swaps,
                                  extra)
    for have in list(extra):
        for right in list(missing):
            sw = _swap_of(have, right, swaps)
            if sw:
                edits.append(Edit("swap", equation, display(have, names), display(right, names),
                                  category(right, ctx), sw))
                extra.remove(have)
                missing.remove(right)
                break
    for have in list(extra):   # the right coefficient on the wrong state part
        for right in list(missing):
            if zero(_coefficient_value(have, ctx) - _coefficient_value(right, ctx), [1]):
                edits.append(Edit("replace", equation, display(have, names),
                                  display(right, names), category(right, ctx)))
                extra.remove(have)
                missing.remove(right)
                break
    edits += [Edit("missing", equation, "", display(r, names), category(r, ctx)) for r in missing]
    edits += [Edit("extra", equation, display(h, names), "", category(h, ctx)) for h in extra]
    return Diagnosis(tab.label, c_sym, edits, len(edits))


def _part_missing(mine: TermTable, key, a, right_c):
    """The missing part of a term the student wrote only inside their groups, when the
    groups give a simple fraction of it: ``P/(2a) (x1^2 + (x2 - x1)^2)`` has ``x2^2`` only
    inside ``(x2 - x1)^2``, half of the right ``P x2^2/a``; what is missing is the term
    ``P x2^2/(2a)``, not a coefficient the student never wrote.  None otherwise."""
    groups = mine._groups
    if not groups or key in mine.alone or not any(key in vals for _, vals in groups):
        return None     # written as a term of its own: a wrong coefficient of it
    ratio = sp.cancel(a[0] / right_c)
    if not (ratio.is_Rational and 0 < ratio < 1):
        return None
    return sp.expand((right_c - a[0]) * key)


def _paired_edits(mine: TermTable, tab: TermTable, pairs, c_sym, ctx, equation):
    """``(edits, mine, tab)``: a ``replace`` edit for each pair, and the tables without the
    paired terms (what is left is described term by term)."""
    edits = []
    mine_terms, tab_terms = dict(mine.terms), dict(tab.terms)
    for k1, k2 in pairs:
        have = mine_terms.pop(k1)[0] * k1
        right = sp.expand(c_sym * tab_terms.pop(k2)[0]) * k2
        edits.append(Edit("replace", equation, display(have, ctx.names),
                          display(right, ctx.names), category(right, ctx)))
    return (edits, TermTable(mine.label, mine.expr, mine_terms, mine.hidden, mine.mode),
            TermTable(tab.label, tab.expr, tab_terms, tab.hidden, tab.mode))


def _coefficient_value(term, ctx):
    states = state_symbols(ctx)
    coeff = sp.Mul(*[f for f in sp.Mul.make_args(term) if not f.free_symbols & states])
    try:
        return Formula.from_sympy(coeff).evaluate(coefficient_env(ctx))
    except (TypeError, ZeroDivisionError, KeyError):
        return float("nan")


def _changed(a, right_c, bv, key, ctx, equation, swaps, extra: list | None = None) -> list:
    """Edits for a term whose coefficient is wrong (``a``: the answer's entry).  A written
    term that does not belong is put in ``extra`` (sympy) instead, when given, so that it
    can be paired with a missing one as a wrong term."""
    names = ctx.names
    have, right = a[0] * key, right_c * key
    sub = _written_term(a, bv, key, ctx, equation, swaps, extra)
    if sub is not None and sub.kind == "extra" and extra:
        return []
    if sub is not None:
        return [sub]
    sw = _swap_of(have, right, swaps)
    if sw:
        return [Edit("swap", equation, display(have, names), display(right, names),
                     category(right, ctx), sw)]
    split = _monomials(a[0], right_c, key, ctx, equation, swaps)
    if split is not None:
        return split
    return [Edit("coefficient", equation, display(have, names), display(right, names),
                 category(right, ctx))]


def _written_term(a, bv, key, ctx, equation, swaps, extra: list | None = None) -> Edit | None:
    """When the student wrote several like terms, the one whose change explains the
    difference: a simple ratio (``25/6`` where ``25/3`` belongs) or two symbols swapped
    (``m1`` written where ``M`` belongs, beside an ``m1`` that is right) -- else None."""
    subs = a[2]
    if len(subs) < 2:
        return None
    env = coefficient_env(ctx)
    delta = bv - a[1]
    best = None
    for c_i, v_i in subs:
        new = v_i + delta
        for rule, text in swaps:
            swapped = c_i.xreplace(rule)
            if swapped != c_i and zero(Formula.from_sympy(swapped).evaluate(env) - new, [new]):
                return Edit("swap", equation, display(c_i * key, ctx.names),
                            display(swapped * key, ctx.names), category(swapped * key, ctx),
                            text)
        if zero(new, [v_i]):
            cand = (0, Edit("extra", equation, display(c_i * key, ctx.names), "",
                            category(c_i * key, ctx)), c_i * key)
        else:
            ratio = new / v_i
            if not isinstance(ratio, Fraction):
                continue
            height = max(abs(ratio.numerator), ratio.denominator)
            if height > 12:
                continue
            right = sp.Rational(ratio.numerator, ratio.denominator) * c_i * key
            kind = "sign" if ratio == -1 else "coefficient"
            cand = (height, Edit(kind, equation, display(c_i * key, ctx.names),
                                 display(right, ctx.names), category(right, ctx)), None)
        if best is None or cand[0] < best[0]:
            best = cand
    if best is not None and best[2] is not None and extra is not None:
        extra.append(best[2])
    return best[1] if best else None


def _monomials(have_c, right_c, key, ctx, equation, swaps=()) -> list | None:
    """A changed coefficient that is a sum, split into the parameter terms that differ
    (``g*m1`` where ``g*m1 + k*l0`` belongs: the term ``k*l0`` is missing); one term
    extra and one missing are one wrong coefficient (``R*m`` where ``R**2*m`` belongs), or
    one symbol written for another (``2*m1`` where ``M + m1`` belongs: ``m1`` for ``M``)."""
    if not (have_c.is_Add or right_c.is_Add):
        return None

    def split(c):
        out = {}
        for term in sp.Add.make_args(sp.expand(c)):
            num, rest = term.as_coeff_Mul()
            out[rest] = out.get(rest, 0) + num
        return out
    h, r = split(have_c), split(right_c)
    changed = [rest for rest in list(h) + [x for x in r if x not in h]
               if h.get(rest, 0) != r.get(rest, 0)]
    moved = _moved(h, r, changed, key, ctx, equation, swaps)
    if moved is not None:
        return [moved]
    extra = [x for x in changed if r.get(x, 0) == 0]
    missing = [x for x in changed if h.get(x, 0) == 0]
    if len(changed) >= 2 and len(missing) == len(changed):   # one term, a sum coefficient
        right = sp.factor(sum(r[x] * x for x in missing)) * key
        return [Edit("missing", equation, "", display(right, ctx.names), category(right, ctx))]
    if len(changed) >= 2 and len(extra) == len(changed):
        have = sp.factor(sum(h[x] * x for x in extra)) * key
        return [Edit("extra", equation, display(have, ctx.names), "", category(have, ctx))]
    if len(extra) == 1 and len(missing) == 1 and len(changed) == 2:
        have, right = h[extra[0]] * extra[0] * key, r[missing[0]] * missing[0] * key
        return [Edit("coefficient", equation, display(have, ctx.names),
                     display(right, ctx.names), category(right, ctx))]
    edits = []
    for rest in changed:
        hv, rv = h.get(rest, 0), r.get(rest, 0)
        have, right = hv * rest * key, rv * rest * key
        if rv == 0:
            edits.append(Edit("extra", equation, display(have, ctx.names), "",
                              category(have, ctx)))
        elif hv == 0:
            edits.append(Edit("missing", equation, "", display(right, ctx.names),
                              category(right, ctx)))
        else:
            edits.append(Edit("sign" if hv == -rv else "coefficient", equation,
                              display(have, ctx.names), display(right, ctx.names),
                              category(right, ctx)))
    return edits or None


def _moved(h, r, changed, key, ctx, equation, swaps) -> Edit | None:
    """One parameter term counted under a symbol of the same dimension as another's."""
    if len(changed) != 2:
        return None
    a, b = changed
    da, db = h.get(a, 0) - r.get(a, 0), h.get(b, 0) - r.get(b, 0)
    if da != -db:
        return None
    # the symbol written by mistake is the one the answer has more of
    wrong, right = (a, b) if abs(h.get(a, 0)) > abs(r.get(a, 0)) else (b, a)
    d = h.get(wrong, 0) - r.get(wrong, 0)
    for rule, text in swaps:
        if sp.expand(wrong.xreplace(rule) - right) == 0:
            return Edit("swap", equation, display(d * wrong * key, ctx.names),
                        display(d * right * key, ctx.names), category(d * right * key, ctx),
                        text)
    return None


def swap_pairs(ctx) -> list:
    """Pairs of symbols of one dimension (parameters; coordinates with their derivatives)."""
    return ctx.memo("swap_pairs", lambda: _buildswap_pairs(ctx))


def _buildswap_pairs(ctx) -> list:
    pairs = []
    params = list(ctx.parameters)
    for i, a in enumerate(params):
        for b in params[i + 1:]:
            if ctx.dims.get(a) == ctx.dims.get(b):
                pairs.append(({a: b, b: a}, f"`{a}` and `{b}`"))
    st = ctx.states
    for i, a in enumerate(st):
        for b in st[i + 1:]:
            if ctx.dims.get(a.q) == ctx.dims.get(b.q):
                pairs.append(({a.q: b.q, b.q: a.q, a.qd: b.qd, b.qd: a.qd, a.qdd: b.qdd,
                               b.qdd: a.qdd}, f"`{a.name}` and `{b.name}`"))
    return pairs


def _swap_of(have, right, swaps) -> str:
    for rule, text in swaps:
        if sp.expand(have.xreplace(rule) - right) == 0:
            return text
    return ""


def category(term, ctx: ProblemContext) -> str:
    """A short name for what a term is (inertia, Coriolis, gravity, torque, ...), decided
    from what it is made of (:func:`dualmech.grade.kinds.category`)."""
    return _category(term, ctx)


def concrete_state(ctx: ProblemContext, answer: Formula, truth: Formula | None,
                   need=(), coordinates: tuple | None = None) -> tuple[dict, float, float]:
    """A real state in the declared ranges (on the motion): ``(state, answer, truth)`` values.

    ``truth`` None means the answer should vanish there (an equation).  ``coordinates``
    (names of another model's coordinates) gives the state in those instead of the
    reference's.
    """
    point = ctx.points("mpmath")[0]
    env = point.env(need=need)
    with mpmath.workdps(MP_DIGITS):
        a = answer.evaluate(env)
        b = truth.evaluate(env) if truth is not None else 0
    state = {}
    for s in ctx.parameters:
        state[str(s)] = float(point.values[s])
    if coordinates is not None:
        derived = {sym.name: sym for sym in ctx.derived_formulas()}
        with mpmath.workdps(MP_DIGITS):
            full = point.env(need=list(ctx.derived_formulas())).values
        for name in coordinates:
            for key, sym_name in ((name, name), (name + "'", name + "_dot")):
                sym = derived.get(sym_name)
                if sym is not None and sym in full:
                    state[key] = _real(full[sym])
    else:
        for s in ctx.states:
            state[s.name] = float(point.values[s.q])
            state[s.name + "'"] = float(point.values[s.qd])
    if any(answer.symbols & {t}) or (truth is not None and t in truth.symbols):
        state["t"] = float(point.values[t])
    return state, _real(a), _real(b)


def _real(v) -> float:
    try:
        return float(v)
    except TypeError:
        return float(mpmath.re(v))
