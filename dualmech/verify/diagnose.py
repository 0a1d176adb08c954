"""Name the mistake when two derivations disagree: the body, the load, the term.

With two models a vote names nobody.  Below the vote (DESIGN.md, "Two models, and a
referee"), :func:`diagnose` compares the direct form's declarations with each hand Lagrangian
(:mod:`dualmech.verify.energies`: ``T`` of each body, ``V`` and virtual work of each load, the work of each
reaction) and, where they agree, finds the balance of the direct form that does not follow
from them (:mod:`.edits`).  Each statement says how sure it is: that a quantity differs
between the two models is decided exactly; *which* of the two holds the slip, and that an
edit is the one the author should make, is said with "probably" unless the comparison
proves it (the hand Lagrangian agreeing with every declaration puts the error in a balance
of the direct form -- given those declarations).

``str()`` is the readable form; :meth:`Diagnosis.to_dict` the JSON.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from dualmech.model.direct import NewtonEuler
from dualmech.model.lagrange import Lagrangian
from dualmech.verify.display import wrap
from dualmech.verify.edits import RowEdit, row_edits
from dualmech.verify.energies import DeclarationCheck, Finding, builders_of, check_declarations

__all__ = ["Diagnosis", "Statement", "diagnose"]


@dataclass
class Statement:
    """One thing the diagnosis says: ``subject`` (``"T of bob"``, ``"newton_euler [sum F .
    O.x (cart)]"``), ``model`` (the model the edit is written for), ``parts`` (a sentence:
    text and expressions, see :func:`dualmech.model.notation.sentence`), ``certain``
    (whether the subject is proved to be where the models differ)."""

    subject: str
    model: str
    parts: tuple
    certain: bool
    kind: str = ""
    terms: list = field(default_factory=list)   # [(kind, have, right)] expressions

    def text(self, notation: str = "dots") -> str:
        from dualmech.model.notation import sentence
        return sentence(self.parts, notation)

    def to_dict(self) -> dict:
        from dualmech.verify.display import dotted
        show = lambda e: None if e is None else dotted(e)  # noqa: E731
        return {"subject": self.subject, "model": self.model, "kind": self.kind,
                "certain": self.certain, "text": self.text(),
                "terms": [[k, show(h), show(r)] for k, h, r in self.terms]}


@dataclass
class Diagnosis:
    """What :func:`diagnose` found: its statements, most specific first."""

    statements: list = field(default_factory=list)
    checks: list = field(default_factory=list)      # the DeclarationCheck of each pair
    row_edits: list = field(default_factory=list)   # RowEdit of the balances blamed

    def __bool__(self) -> bool:
        return bool(self.statements)

    def __str__(self) -> str:
        return self.text()

    def text(self, notation: str = "dots", width: int | None = None) -> str:
        lines = []
        for s in self.statements:
            mark = "" if s.certain else "(probably) "
            lines.append(wrap(f"- {s.subject}: {mark}{s.text(notation)}", width, indent="  "))
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {"statements": [s.to_dict() for s in self.statements]}


def diagnose(problem, judgement=None) -> Diagnosis:
    """The diagnosis of a problem whose derivations disagree (empty when nothing is named).

    >>> from dualmech.problems import get
    >>> diagnose(get("trolley_pendulum")).statements
    []
    """
    if judgement is None:
        judgement = _judge(problem)
    builders = builders_of(problem)
    direct = [n for n, b in builders.items() if isinstance(b, NewtonEuler)]
    hand = [n for n, b in builders.items() if isinstance(b, Lagrangian)]
    out = Diagnosis()
    suspects = set(judgement.odd) if judgement is not None else set(builders)
    for d in direct:
        for lname in hand:
            if judgement is not None and {d, lname}.isdisjoint(suspects):
                continue
            check = check_declarations(problem, d, lname, builders)
            out.checks.append(check)
            for f in check.findings:
                _merge(out.statements, _finding(f, judgement), f)
            # findings that rest on a reaction's value from the balances leave the balances
            # open: a row that gives that reaction a wrong value is as likely
            open_rows = all(f.via for f in check.findings)
            if open_rows and not _agree(judgement, d, lname) and \
                    not any(e.model == d for e in out.row_edits):
                edits = row_edits(problem, d, lname)
                out.row_edits += edits
                for f in check.working_reactions:   # a reaction drawn the wrong way
                    _merge(out.statements, _finding(f, judgement), f)
                out.statements += _balances(check, edits)
    out.statements += _opposite_reactions(problem, judgement)
    if not out.row_edits and not any(s.kind not in ("balance",) for s in out.statements):
        for check in out.checks:   # nothing else explains it: a reaction that does work
            for f in check.working_reactions:
                _merge(out.statements, _finding(f, judgement), f)
    return out


def _judge(problem):
    """The verdict on every model of ``problem`` (as :func:`~dualmech.verify.check.compare`
    judges them)."""
    from dualmech.verify.check import claims_of
    from dualmech.verify.sampling import Context
    from dualmech.verify.verdicts import judge
    ref = problem.model(problem.reference)
    ctx = Context(ref.coordinates, problem.parameter_symbols, problem)
    mapped = {n: problem.in_reference_coordinates(m) for n, m in problem.models().items()}
    return judge(mapped, context=ctx, reference=problem.reference, claims=claims_of(problem))


def _agree(judgement, a: str, b: str) -> bool:
    if judgement is None:
        return False
    if judgement.equivalent:
        return True
    return frozenset((a, b)) in judgement.agreeing and not judgement.fault_of(a) \
        and not judgement.fault_of(b)


def _merge(statements: list, new: Statement, f: Finding) -> None:
    """Add ``new`` unless the same quantity of the same direct model is already named
    against another hand model (then that statement names both)."""
    for s in statements:
        if s.subject == new.subject and s.kind == new.kind and getattr(s, "_direct", None) \
                == f.direct:
            return
    new._direct = f.direct
    statements.append(new)


def _finding(f: Finding, judgement=None) -> Statement:
    lg, ne = f"`{f.lagrange}`", f"`{f.direct}`"
    odd = set(judgement.odd) if judgement is not None and judgement.majority else set()
    if f.kind == "does work":
        parts = ("in ", ne, f" it does the virtual work δW = ", f.right,
                 "; the reaction of an ideal constraint does none: its direction or point "
                 "is wrong, or the motion of the body's point where it acts (a rolling body "
                 "turning the wrong way), or the constraint is not ideal")
        return Statement(f.quantity, f.direct, _flat(parts), False, f.kind, f.terms)
    if f.kind == "pair":
        names = ", ".join(x.removeprefix("reaction ") for x in f.keys)
        on = ", ".join(f.bodies) or "its body"
        parts = ("in ", ne, f" the load `{f.quantity}` on {on} repeats the reaction {names} "
                 "with the sign it has on the other body: the pair does the virtual work ",
                 2 * f.have, "; an action and its reaction are equal and opposite, "
                 "and drawn opposite the pair does none (checked): reverse it (or declare the "
                 f"reaction with against={on})")
        return Statement(f"load {f.quantity}", f.direct, _flat(parts), True, f.kind, f.terms)
    source = _source(f)
    parts: list = []
    edits = f.edits
    if len(edits) > 1 and all(e.kind == "sign" for e in edits):
        have = _factored(sum((e.have for e in edits), sp.Integer(0)))
        parts += ["sign: ", lg, " has ", have, f" where {source} gives ", -have]
        edits = []
    for e in edits:
        if parts:
            parts.append("; ")
        if e.kind == "missing":
            parts += [lg, " is missing the term ", e.right, f", which {source} gives"]
        elif e.kind == "extra" and not f.loads and not f.quantity.startswith("T of"):
            parts += [lg, " has the term ", e.have, f", which no load of {ne} gives (a load "
                      f"left out of {ne}, or one too many in {lg})"]
        elif e.kind == "extra":
            parts += [lg, " has the term ", e.have, f", which {source} does not give"]
        elif e.kind == "sign":
            parts += ["sign: ", lg, " has ", e.have, f" where {source} gives ", e.right]
        else:
            parts += [lg, " has ", e.have, f" where {source} gives ", e.right]
            gap = _difference(e.have, e.right)
            if gap is not None:
                parts += [f" (`{f.lagrange}`'s minus the declared: ", gap, ")"]
    if not parts:
        parts = [lg, " has ", f.have, f" where {source} gives ", f.right]
    if len(edits) > 1:
        gap = _total_gap(f.have, f.right)
        if gap is not None and sp.count_ops(gap) < sum(
                sp.count_ops(x) for e in f.edits for x in (e.have, e.right) if x is not None):
            parts += [f"; in all, {lg}'s minus the declared: ", gap]
    if f.reconciles:
        parts.append(f"; with the declared value in {lg} the two models agree (checked)")
    elif f.reconciles is False:
        parts.append(f"; that alone does not reconcile {lg} with {ne}: more differs")
    if f.along:
        body = ", ".join(f.bodies)
        parts.append(f": the virtual work of the loads on {body} ({', '.join(f.along)}) too, "
                     f"so probably {body} is not where {ne} declares it (its position or "
                     f"velocity), or its velocity in {lg}'s T is wrong")
    if odd == {f.direct}:
        parts.append(f" -- {ne} is outvoted: the slip is probably in its declaration")
        model = f.direct
    elif odd == {f.lagrange}:
        parts.append(f" -- {lg} is outvoted: the slip is probably in its term")
        model = f.lagrange
    else:
        parts.append(f" -- the slip is in {lg}'s term or in {ne}'s declaration")
        model = f.lagrange
    return Statement(f.quantity, model, _flat(parts), not f.probably, f.kind, f.terms)


def _source(f: Finding) -> str:
    if f.quantity.startswith("T of"):
        what = ", ".join(f.bodies) or "the bodies"
        return f"the declaration of {what} in `{f.direct}`"
    what = ", ".join(f.loads) or "the loads"
    if f.via:
        return (f"the load {what} of `{f.direct}` (with {f.via} as `{f.direct}`'s own "
                "balances give it)")
    return f"the load {what} of `{f.direct}`"


def _balances(check: DeclarationCheck, edits: list[RowEdit]) -> list[Statement]:
    ne, lg = f"`{check.direct}`", f"`{check.lagrange}`"
    proved = check.agree and not check.working_reactions
    if check.agree and check.working_reactions:
        names = ", ".join(f.quantity for f in check.working_reactions)
        head = (f"{lg} is the Lagrangian of {ne}'s own bodies and loads (T, V and virtual "
                f"work agree term by term), so the error is in a balance of {ne} or in the "
                f"direction of {names}, which does work")
    elif proved:
        head = (f"{lg} is the Lagrangian of {ne}'s own bodies and loads (T, V and virtual "
                "work agree term by term), so the error is in a balance of " + ne)
    else:
        why = f" ({check.note})" if check.note else ""
        head = (f"the kinetic energies of {ne}'s bodies agree with {lg}{why}; the "
                f"error is probably in a balance of {ne}")
    if not edits:
        return [Statement(check.direct, check.direct,
                          (head + "; no single-row edit reconciles the two",),
                          check.agree, "balance")]
    out = [Statement(check.direct, check.direct, (head,), check.agree, "balance")]
    certain = len(edits) == 1 and proved
    for e in edits:
        subject = f"{e.model} [{e.label}]"
        if e.kind == "sign":
            parts = ("the ingredient ", e.ingredient, " has the wrong sign: ", e.term,
                     " should be ", -e.term)
            terms = [("sign", e.term, -e.term)]
        elif e.kind == "dropped":
            parts = ("the ingredient ", e.ingredient, " does not belong here: ", e.term)
            terms = [("extra", e.term, None)]
        else:
            parts, terms = [], []
            for x in e.edits:
                parts += ["; " if parts else ""]
                parts += (["missing the term ", x.right] if x.kind == "missing" else
                          ["the term ", x.have, " is extra"] if x.kind == "extra" else
                          ["has ", x.have, " where ", x.right, " belongs"])
                terms.append((x.kind, x.have, x.right))
            parts = tuple(parts)
            if e.ingredient:                    # an inertia term of the declarations
                parts += (f" ({e.ingredient})",)
            elif any(x.kind == "missing" and x.right is not None and _has_acc(x.right)
                     for x in e.edits):
                parts += (" (a transport term: a moment about a moving point, or an "
                          "acceleration of the frame, left out)",)
        parts = tuple(parts) + (f"; with this edit {ne} agrees with {lg} (checked)",)
        out.append(Statement(subject, e.model, _flat(parts), certain, e.kind, terms))
    return out


def _opposite_reactions(problem, judgement) -> list[Statement]:
    """A reaction two models give with opposite signs at every state (checked exactly): a
    multiplier whose sign convention is the reverse of the free-body diagram's arrow."""
    from dualmech.verify.energies import vanishes
    if judgement is None or not getattr(judgement, "reaction_faults", None):
        return []
    solved: dict = {}
    out = []
    for fault in judgement.reaction_faults:
        models = list(fault.suspects) + list(fault.agreeing)
        values = {}
        for name in models:
            if name not in solved:
                solved[name] = _reactions_of(problem, name)
            if fault.name in solved[name]:
                values[name] = solved[name][fault.name]
        pairs = [(a, b) for i, a in enumerate(values) for b in list(values)[i + 1:]]
        for a, b in pairs:
            (pa, va), (pb, vb) = values[a], values[b]
            if vanishes(pa + pb) and not vanishes(pa - pb):
                parts = (f"`{a}` gives ", va, f" and `{b}` gives ", vb, ", its negative, at "
                         "every state (checked): the two take opposite positive directions "
                         "(a multiplier's force on the coordinates is +λ times the "
                         "constraint's gradient; the free-body diagram's arrow may point the "
                         "other way); reverse one of them")
                out.append(Statement(f"reaction {fault.name}", a, parts, True, "sign",
                                     [("sign", va, vb)]))
                break
    return out


def _reactions_of(problem, name: str) -> dict:
    """``{reaction name: (plain value, value)}`` of model ``name`` solved for its reactions (in
    the reference coordinates), ``{}`` when it does not solve or is large (past the display
    budget, :func:`~dualmech.verify.display.solve_display`: a symbolic solve of coupled
    unknowns takes minutes)."""
    from dualmech.verify.display import solve_display
    try:
        m = problem.in_reference_coordinates(problem.model(name))
        if not m.unknowns or not m.is_square or len(m.equations) > 8:
            return {}
        solved = solve_display(m)
        return {u.name: (m.to_plain(solved[u]), solved[u]) for u in m.unknowns}
    except Exception:  # noqa: BLE001 - a hint, never a failure of the diagnosis
        return {}


def _difference(have, right):
    """``have - right`` factored, when that is shorter than either side (a coefficient of
    three terms against another of three: ``m r (2 R - r)/4 θ̇^2``); else ``None``."""
    try:
        gap = sp.factor(sp.expand(have - right))
    except Exception:  # noqa: BLE001 - display only
        return None
    if gap == 0 or sp.count_ops(gap) >= min(sp.count_ops(have), sp.count_ops(right)):
        return None
    return gap


def _total_gap(have, right):
    """``have - right`` in its shortest factored form, with ``sin^2`` written through ``cos``
    or the other way (a teacher's ``-a^2 m cos(θ) φ̇ (cos(θ) φ̇ + 2 ψ̇)/4``, not the
    canonical basis's four terms); ``None`` when it is zero or cannot be formed.  Display only.

    >>> th, a, b = sp.symbols("theta a b")
    >>> _total_gap(a * sp.sin(th)**2 + b, a + b)
    -a*cos(theta)**2
    """
    w = sp.Wild("w")
    try:
        gap = sp.expand(have - right)
        if gap == 0:
            return None
        forms = [gap, sp.expand(gap.replace(sp.sin(w)**2, 1 - sp.cos(w)**2)),
                 sp.expand(gap.replace(sp.cos(w)**2, 1 - sp.sin(w)**2))]
        return min((sp.factor(x) for x in forms), key=sp.count_ops)
    except Exception:  # noqa: BLE001 - display only
        return None


def _factored(expr):
    """``expr`` factored when that is shorter (``L₀ k y - L₀ k x`` is ``L₀ k (y - x)``);
    display only."""
    try:
        out = sp.factor(expr)
    except Exception:  # noqa: BLE001 - display only
        return expr
    return out if sp.count_ops(out) < sp.count_ops(expr) else expr


def _has_acc(expr) -> bool:
    return any(d.derivative_count == 2 for d in expr.atoms(sp.Derivative))


def _flat(parts) -> tuple:
    return tuple(p for p in parts if not (isinstance(p, str) and p == ""))
