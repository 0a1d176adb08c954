"""The smallest edit of one row of a derivation that makes it agree with another.

When the direct form's declarations agree with the hand Lagrangian (:mod:`dualmech.verify.energies`), a
disagreement is in a balance of the direct form.  Each row is tried with the smallest edits a
person makes -- one ingredient (a load, an inertia term) with its sign flipped or left out,
or the row rewritten into a multiple of a row of the other model with a term or two
changed (a moment about a moving point taken as if the point were fixed misses the term
``m r_BC x a_B``) -- and an edit counts only when the edited model then gives the other's
motion, decided exactly (:func:`~dualmech.verify.verdicts.judge`).  That the edit reconciles
the two is certain; that it is the mistake made is a suggestion (another edit could too).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.model.equations import EquationSet, from_plain
from dualmech.model.kinematics import t
from dualmech.verify.sampling import Context
from dualmech.verify.termdiff import TermEdit, term_edits, term_table
from dualmech.verify.verdicts import judge

__all__ = ["RowEdit", "row_edits"]

#: candidate edits tried per model (each one verdict): more is a search, not an explanation
MAX_TRIES = 80


@dataclass
class RowEdit:
    """An edit of row ``label`` of ``model`` that makes it agree with ``against``.

    ``kind``: ``"sign"`` or ``"dropped"`` of ingredient ``ingredient`` (``term`` its value),
    or ``"terms"`` (``edits``: term edits, expressions in q(t)).
    """

    model: str
    label: str
    against: str
    kind: str
    ingredient: str = ""
    term: sp.Expr | None = None
    edits: list = field(default_factory=list)


def row_edits(problem, model: str, against: str, seed: int = 0) -> list[RowEdit]:
    """Single-row edits of ``model`` (of ``problem``) that make it agree with ``against``
    (all found among the candidates; empty when none does).

    >>> import dataclasses
    >>> from dualmech.problems import get
    >>> p = get("trolley_pendulum")
    >>> class Flipped(type(p)):
    ...     def newton_euler(self):
    ...         m = super().newton_euler()
    ...         parts = [dict(c) for c in m.contributions]
    ...         parts[0]["F on trolley"] = -parts[0]["F on trolley"]
    ...         eqs = [sum(c.values()) for c in parts]
    ...         return dataclasses.replace(m, equations=tuple(eqs), contributions=tuple(parts))
    >>> [(e.label, e.kind, e.ingredient) for e in row_edits(Flipped(), "newton_euler", "lagrange")]
    [('sum F . O.x (trolley)', 'sign', 'F on trolley')]
    """
    m = problem.model(model)
    ref = problem.model(problem.reference).coordinates
    if set(m.coordinates) != set(ref):
        return []
    other = problem.in_reference_coordinates(problem.model(against))
    ctx = Context(ref, problem.parameter_symbols, problem)
    eqs = list(m.equations)
    found, tries = [], 0

    def agrees(i, row) -> bool:
        nonlocal tries
        tries += 1
        rows = eqs[:i] + [row] + eqs[i + 1:]
        try:
            edited = EquationSet(m.name, m.coordinates, tuple(rows), m.unknowns, m.labels)
            j = judge({against: other, "edited": edited}, context=ctx, points=4, seed=seed,
                      reference=against)
        except Exception:  # noqa: BLE001 - an edit that breaks the model is no edit
            return False
        return not j.faults
    for i, parts in enumerate(m.contributions or ()):
        for key, value in parts.items():
            value = as_expr(value)
            if value == 0 or tries >= MAX_TRIES:
                continue
            for kind, factor in (("sign", -1), ("dropped", 0)):
                if agrees(i, eqs[i] + (factor - 1) * value):
                    found.append(RowEdit(model, m.labels[i], against, kind, key, value))
                    break
    if len(found) == 1:
        return found
    if found:   # several single edits reconcile: a term the declarations give is likelier
        return _inertia_edits(problem, model, m, other, agrees, against) + found
    for i in range(len(eqs)):
        if tries >= MAX_TRIES:
            break
        edit = _term_edit(m, i, other, agrees)
        if edit is not None:
            found.append(RowEdit(model, m.labels[i], against, "terms", edits=edit))
    if not found:
        found = _inertia_edits(problem, model, m, other, agrees, against)
    return [e for e in found if all(written(x) for te in e.edits for x in (te.have, te.right))]


def written(term) -> bool:
    """Whether ``term`` is one a person writes in a balance: no denominator that is a sum
    (``L M R m cos(θ) θ̈/(6 M + 4 m)`` is the motion solved into a row, an edit that
    reconciles the models without being anyone's mistake); ``None`` (no term) is.

    >>> M, m, R, a = sp.symbols("M m R a")
    >>> written(M * R * a / (6 * M + 4 * m)), written(-R * m * a / 2), written(None)
    (False, True, True)
    """
    if term is None:
        return True
    for part in sp.Add.make_args(sp.expand(as_expr(term))):
        if sp.denom(sp.factor(part)).atoms(sp.Add) - {sp.Integer(0)}:
            return False
    return True


def _inertia_edits(problem, model: str, m, other, agrees, against: str) -> list[RowEdit]:
    """Rows missing an inertia term of the declarations (a body taken as massless in one
    balance, a moment about a moving point taken as fixed; :mod:`.rowterms`), each edit
    confirmed exactly."""
    from dualmech.model.declared import builder_of
    from dualmech.model.direct import NewtonEuler
    from dualmech.verify.rowterms import missing_inertia
    ne = builder_of(m)
    if not isinstance(ne, NewtonEuler):
        return []
    try:
        proposals = missing_inertia(problem, m, other, ne)
    except Exception:  # noqa: BLE001 - a numeric search that fails proposes nothing
        return []
    out, done = [], set()
    for i, what, term in proposals:
        present = [as_expr(v) for v in (m.contributions or [{}] * (i + 1))[i].values()]
        if any(sp.expand(v - k * term) == 0 for v in present for k in (1, -1, 2, -2)):
            continue        # the row has it: a sign or a double, the ingredient edits' business
        if i in done or not agrees(i, m.equations[i] + term):
            continue
        done.add(i)
        out.append(RowEdit(model, m.labels[i], against, "terms", ingredient=what,
                           edits=[TermEdit("missing", None, term)]))
    return out


def _term_edit(m, i, other, agrees) -> list | None:
    """Term edits turning row ``i`` (free of reactions) into a multiple of a row of
    ``other`` (also free of reactions) -- at most two terms -- that reconcile the models."""
    row = m.to_plain(m.equations[i])
    if row.free_symbols & set(m.unknowns):
        return None
    states = {x for s in m.states for x in (s.q, s.qd, s.qdd)} | {t}
    mine = term_table(row, states)
    if not mine:
        return None
    best = None
    for target in other.equations:
        target = other.to_plain(target)
        if target.free_symbols & set(other.unknowns):
            continue
        if not term_table(target, states):
            continue
        for acc in [s.qdd for s in m.states]:
            theirs = sp.diff(target, acc)
            if theirs == 0 or sp.diff(row, acc) == 0:
                continue
            # the factor may depend on the coordinates (a row divided by a lever arm l sin th)
            scale = sp.cancel(sp.diff(row, acc) / theirs)
            if scale.free_symbols & (states - {s.q for s in m.states}):
                continue
            scaled = sp.expand(scale * target)
            edits = term_edits(row, scaled, states)
            if edits is None or not 0 < len(edits) <= 2:
                continue
            if best is None or len(edits) < len(best[0]):
                best = (edits, scaled)
            break
    if best is None or not agrees(i, from_plain(best[1], m.coordinates)):
        return None
    def shown(x):
        return None if x is None else from_plain(neat(x, states), m.coordinates)
    return [TermEdit(e.kind, shown(e.have), shown(e.right)) for e in best[0]]


def neat(expr, states) -> sp.Expr:
    """``expr`` (plain) with the coefficient of each product of the ``states`` factored, as
    a teacher writes it: a row scaled by ``1/(2 r - 2 R)`` gives ``-R m r ψ̈/2``, not
    ``(R^2 m r/(-2 R + 2 r) - R m r^2/(-2 R + 2 r)) ψ̈``.  Display only; the edit was checked
    on the unfactored form, and the factored one is kept only when it is the same.

    >>> R, r, m, a = sp.symbols("R r m a")
    >>> neat(R**2*m*r*a/(2*r - 2*R) - R*m*r**2*a/(2*r - 2*R), {a})
    -R*a*m*r/2
    """
    try:
        parts = sp.collect(sp.expand(expr), sorted(states, key=str), evaluate=False)
        out = sp.Add(*(sp.factor(c) * k for k, c in parts.items()))
    except Exception:  # noqa: BLE001 - display only
        return expr
    if sp.count_ops(out) >= sp.count_ops(expr) or sp.cancel(out - expr) != 0:
        return expr
    return out
