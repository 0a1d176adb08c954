"""Do the derivations describe the same motion and give the same reactions?  Who is wrong?

Every model of a problem is brought to the reference coordinates and evaluated at the same
random points (:mod:`dualmech.verify.sampling`).  At each point each model says what it
determines -- its accelerations, its reactions -- or that it determines nothing (singular) or
contradicts itself.  Models are *equivalent* when they give the same accelerations at every
point: one set is then an invertible combination of the other.  A single differing point is a
certain counter-example; agreement at ``k`` points bounds the chance of a false "equal"
(Schwartz--Zippel, printed).

When models disagree, the ones that agree with each other outvote the odd one: the result
names the derivation that holds the error first.  With two models (or a tie) every side is a
suspect and each is explained in its own equations.  Nothing here raises on a wrong model:
a singular or self-contradictory derivation, or one whose reactions are undetermined, is a
mismatch in the result.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t, EquationSet
>>> th = coordinate("theta"); m, l, g = sp.symbols("m l g", positive=True)
>>> a = EquationSet("a", (th,), (m*l**2*th.diff(t, 2) + m*g*l*sp.sin(th),))
>>> b = EquationSet("b", (th,), (th.diff(t, 2) + g/l*sp.sin(th),))
>>> bad = EquationSet("bad", (th,), (th.diff(t, 2) - g/l*sp.sin(th),))
>>> j = judge({"a": a, "b": b, "bad": bad})
>>> j.equivalent, j.odd
(False, ['bad'])
>>> print(j.summary())
`bad` disagrees with `a` and `b`, which agree with each other
"""
from __future__ import annotations

import random
import time
from dataclasses import dataclass, field
from typing import Mapping, Sequence

import mpmath

from dualmech.model.equations import ModelError
from dualmech.exact.form import MP_DIGITS, is_zero
from dualmech.exact.errors import Undecidable
from dualmech.verify.sampling import (MAX_ATTEMPTS, Context, Sampler, System, same_values,
                       shared_manifold, solve_model)

__all__ = ["Judgement", "ModelFault", "ReactionFault", "judge"]


@dataclass
class ModelFault:
    """One derivation's fault at a point: it differs from ``against``, or fails on its own."""

    model: str
    kind: str            # "differs", "undetermined", "inconsistent", "reactions"
    against: tuple = ()  # the models whose accelerations it was checked against
    detail: str = ""


@dataclass
class ReactionFault:
    """Reaction ``name`` takes different values in different models."""

    name: str
    suspects: tuple
    agreeing: tuple = ()


@dataclass
class Judgement:
    """The verdict on every model of a problem at the sampled points.

    ``equivalent``: every model gives the same accelerations everywhere sampled, determines
    its reactions, and every reaction shared by two models has one value.  ``odd`` names the
    derivations held responsible (the minority when a majority agrees; every side of a tie).
    ``point``/``parts``/``solutions`` keep the counter-example for explanations.
    """

    models: dict
    method: str
    points: int
    degree: int
    seconds: float
    groups: list = field(default_factory=list)
    faults: list = field(default_factory=list)
    reaction_faults: list = field(default_factory=list)
    odd: list = field(default_factory=list)
    majority: tuple = ()
    point: dict | None = None
    solutions: dict = field(default_factory=dict)
    parts: dict = field(default_factory=dict)
    bound: float = 0.0
    how: str = ""            # how an "equal" was reached and how sure it is
    agreeing: set = field(default_factory=set)   # frozensets of model pairs equal everywhere
    refusal: str = ""        # why no verdict could be given (then neither equal nor different)
    referees: dict = field(default_factory=dict)   # referee name -> its direct model
    withdrawn: dict = field(default_factory=dict)  # referee name -> why it cannot vote
    notes: list = field(default_factory=list)      # what the referees change in the verdict
    undetermined: dict = field(default_factory=dict)  # referee -> reactions it leaves open

    @property
    def equivalent(self) -> bool:
        return not self.faults and not self.reaction_faults and not self.refusal

    def fault_of(self, model: str) -> list:
        return [f for f in self.faults if f.model == model]

    def summary(self) -> str:
        if self.refusal:
            return f"UNDECIDED: {self.refusal}"
        if self.equivalent:
            return f"all {len(self.models)} derivations agree"
        lines = []
        if self.majority and self.odd:
            lines.append(f"{_names(self.odd)} {'disagrees' if len(self.odd) == 1 else 'disagree'}"
                         f" with {_names(self.majority)}, which agree with each other")
        elif self.groups and len(self.groups) > 1:
            lines.append("the derivations split into " + " | ".join(
                _names(g) for g in self.groups) + ": no majority, every side is a suspect")
        said = set()
        for f in self.faults:
            if f.kind in ("undetermined", "inconsistent", "reactions") and f.detail:
                if f.detail.startswith("no derivation determines"):
                    if f.detail not in said:
                        lines.append(f.detail)
                        said.add(f.detail)
                    continue
                lines.append(f"`{f.model}`: {f.detail}")
        lines += [n for n in self.notes if n not in lines]
        for r in self.reaction_faults:
            if r.agreeing:
                lines.append(f"reaction {r.name}: {_names(r.suspects)} "
                             f"{'differs' if len(r.suspects) == 1 else 'differ'} from "
                             f"{_names(r.agreeing)}")
            else:
                lines.append(f"reaction {r.name}: {_names(r.suspects)} give different values")
        return "\n".join(lines)


def _names(models: Sequence[str]) -> str:
    quoted = [f"`{m}`" for m in models]
    return quoted[0] if len(quoted) == 1 else ", ".join(quoted[:-1]) + " and " + quoted[-1]


def judge(models: Mapping, *, context: Context | None = None, points: int = 8, seed: int = 0,
          reference: str | None = None, claims: Mapping | None = None,
          referees: Mapping | None = None) -> Judgement:
    """Judge every model in ``models`` (name -> EquationSet, all in the same coordinates).

    ``reference`` only breaks ties in the order models are listed; it is not trusted more.
    ``claims`` maps a model written in fewer coordinates to the indices of the coordinates it
    speaks for (default: all).  Static rows (a massless body) are handled on the constraint
    manifold (:class:`~dualmech.verify.sampling.System`).  ``referees`` maps each referee
    (:mod:`dualmech.verify.referee`) to the direct model whose declarations it shares; see
    :func:`_weigh` for what that changes.
    """
    referees = dict(referees or {})
    t0 = time.perf_counter()
    names = list(models)
    if reference in models:
        names.remove(reference)
        names.insert(0, reference)
    first = models[names[0]]
    coords = first.coordinates
    ctx = context or Context.for_models(*[models[n] for n in names])
    systems = [System.of(models[n], coords) for n in names]
    n = len(coords)
    claims = claims or {}
    with mpmath.workdps(MP_DIGITS):
        # the constraint manifold (static rows of massless bodies) is the reference's; other
        # models' static rows must hold on it
        try:
            partial = [nm in claims for nm in names]
            sampler = Sampler(systems, ctx, dependents=shared_manifold(systems, partial, ctx))
        except Undecidable as exc:
            out = Judgement(dict(models), "refused", 0, 0, time.perf_counter() - t0)
            out.refusal = f"the comparator cannot decide {exc.expr}: {exc.why}"
            return out
        except ModelError as exc:
            # a model whose static rows cannot be put on a manifold (e.g. T = 0 leaves no
            # acceleration anywhere): a fault of the model(s) the message names
            out = Judgement(dict(models), "exact", 0, 0, time.perf_counter() - t0)
            named = [nm for nm in names if f"`{nm}`" in str(exc)] or list(names)
            out.faults = [ModelFault(nm, "undetermined", (), f"cannot be compared: {exc}")
                          for nm in named]
            out.odd = named      # the others were not compared with each other: no majority
            return out
        form = sampler.form
        wanted = _points_needed(form, points)
        rng = random.Random(seed)
        good, verdict, undecided = [], None, ""
        withdrawn_all: dict = {}
        open_all: dict = {}
        agreeing = None      # pairs of models that agree at every point used
        for point, _vals, parts, residues in sampler.points(rng, MAX_ATTEMPTS * wanted):
            if not sampler.dependents:
                residues = [_undeclared(s, r) for s, r in zip(systems, residues)]
            sols = {nm: solve_model(A, b, n, s.model.unknowns, claims.get(nm))
                    for nm, s, (A, b) in zip(names, systems, parts)}
            if any(s.status == "undecided" for s in sols.values()):
                continue   # interval values too wide here: no claim either way
            if all(s.status != "ok" for s in sols.values()):
                continue   # a singular state of the motion itself: draw again
            withdrawn = _withdrawn(sols, referees)
            found = _faults_at([nm for nm in names if nm not in withdrawn], sols,
                               dict(zip(names, zip(systems, residues))), referees)
            if found is not None and not _certain(form, point):
                undecided = _where(form, point)
                continue   # a difference only in a branch case nobody confirmed: no claim
            good.append(point)
            for nm, why in withdrawn.items():
                withdrawn_all.setdefault(nm, why)
            for nm in referees:
                if nm in sols and nm not in withdrawn:
                    left = {str(u) for u in sols[nm].undetermined_reactions}
                    if left:
                        open_all.setdefault(nm, set()).update(left)
            here = _agreeing_pairs(names, sols)
            agreeing = here if agreeing is None else agreeing & here
            if found is not None and verdict is None:
                # the counter-example is kept; the other pairs go on being checked so that
                # what agrees is decided on as many points as a full verdict
                verdict = (point, dict(zip(names, parts)), sols, found)
            if len(good) == wanted:
                break
    out = Judgement(dict(models), sampler.method, len(good), form.degree,
                    time.perf_counter() - t0)
    out.referees, out.withdrawn = referees, withdrawn_all
    out.undetermined = open_all
    if not good:
        if undecided:
            out.refusal = ("the derivations differ only in a branch case that could not be "
                           f"confirmed to occur ({undecided}); no verdict")
            return out
        out.faults = [ModelFault(nm, "undetermined", (), "no derivation determines the "
                                 "accelerations at any sampled state: check that every "
                                 "coordinate has inertia and the reactions are independent")
                      for nm in names]
        out.odd = list(names)
        return out
    extra = 4 * sum(s.rows * s.size for s in systems) * max(form.degree, 1)
    out.bound = _bound(form, good, extra)
    out.agreeing = agreeing or set()
    if verdict is None:
        out.how = _describe(form, good, extra)
        out.groups = [tuple(names)]
        return out
    point, parts, sols, (groups, faults, rfaults, odd, majority, notes) = verdict
    out.notes = notes
    out.point, out.parts, out.solutions = point, parts, sols
    out.groups, out.faults, out.reaction_faults = groups, faults, rfaults
    out.odd, out.majority = odd, majority
    return out


def _agreeing_pairs(names, sols) -> set:
    """Pairs of models (frozensets) that both determine the same accelerations here."""
    ok = [nm for nm in names if sols[nm].status == "ok"]
    out = set()
    for i, a in enumerate(ok):
        for b in ok[i + 1:]:
            if same_values(sols[a].qdd, sols[b].qdd):
                out.add(frozenset((a, b)))
    return out


def _points_needed(form, points: int) -> int:
    need = getattr(form, "points_needed", None)
    return max(points, need(points)) if need else points


def _certain(form, point) -> bool:
    check = getattr(form, "certain", None)
    return True if check is None else check(point)


def _where(form, point) -> str:
    where = getattr(form, "where", None)
    return (where(point) if where else "") or "a branch of the expressions"


def _bound(form, good: list, extra: int) -> float:
    try:
        return form.false_equal_bound(good, extra)
    except TypeError:
        return form.false_equal_bound(len(good), extra)


def _describe(form, good: list, extra: int) -> str:
    describe = getattr(form, "describe", None)
    return describe(good, extra) if describe else ""


def _withdrawn(sols: dict, referees: Mapping) -> dict:
    """Referees that cannot vote at this point, with why: equations that contradict each
    other or leave the motion open mean the declarations miss a force the direct form's
    balances never needed (a pivot's), so the referee says nothing rather than accuse."""
    out = {}
    for nm in referees:
        s = sols.get(nm)
        if s is not None and s.status in ("inconsistent", "undetermined"):
            out[nm] = ("its auxiliary balances contradict each other: a force on a released "
                       "body is not declared (a pivot or contact the balances never needed)"
                       if s.status == "inconsistent" else
                       "the declarations do not determine the accelerations")
    return out


def _undeclared(system, residues: list) -> list:
    """The residues of ``system``'s static rows alone, without its declared constraints': at
    points drawn freely (no manifold could be sampled exactly) a declared constraint need not
    vanish, and its acceleration-level row is compared with the other models' rows instead."""
    kept = system.constraints[:len(system.constraints) - system.declared]
    return residues[:sum(len(levels) for levels in kept)]


def _faults_at(names, sols: dict, statics: dict, referees: Mapping | None = None):
    """Group the models by their accelerations at one point; ``None`` when all is well."""
    referees = referees or {}
    groups: list[list[str]] = []
    faults = []
    for nm in names:
        system, residues = statics[nm]
        off = [i for i, v in enumerate(residues) if not is_zero(v, 1)]
        if off:
            labels = []
            pos = 0
            first_declared = len(system.constraints) - getattr(system, "declared", 0)
            declared = False
            for k, (row, levels) in enumerate(zip(system.static, system.constraints)):
                if any(pos <= i < pos + len(levels) for i in off):
                    labels.append(system.model.labels[row])
                    declared = declared or k >= first_declared
                pos += len(levels)
            what = "declared constraint(s) or static equation(s)" if declared else \
                "static equation(s)"
            faults.append(ModelFault(nm, "inconsistent", (), f"its {what} [" +
                                     "], [".join(labels) + "] do not hold on the motion's "
                                     "constraint manifold" + (
                                         " (the other models' constraints); rolling is the "
                                         "velocity of the body's material point at the "
                                         "contact (NewtonEuler.rolling), not of the "
                                         "geometric contact point" if declared else "")))
            continue
        s = sols[nm]
        if s.status != "ok":
            detail = ("its equations do not determine the accelerations (rank "
                      f"{s.rank} short)" if s.status == "undetermined"
                      else "its equations contradict each other (no accelerations satisfy "
                      "all of them)")
            faults.append(ModelFault(nm, s.status, (), detail))
            continue
        for g in groups:
            if same_values(sols[g[0]].qdd, s.qdd):
                g.append(nm)
                break
        else:
            groups.append([nm])
    groups.sort(key=len, reverse=True)
    majority: tuple = ()
    odd: list = [f.model for f in faults]
    if len(groups) > 1 or (groups and faults):
        top = groups[0]
        if len(top) >= 2 and (len(groups) == 1 or len(top) > len(groups[1])):
            majority = tuple(top)
            for g in groups[1:]:
                for nm in g:
                    faults.append(ModelFault(nm, "differs", majority))
                    odd.append(nm)
        else:
            for g in groups:
                others = tuple(x for h in groups if h is not g for x in h)
                for nm in g:
                    faults.append(ModelFault(nm, "differs", others))
                    odd.append(nm)
    # reactions: undetermined ones, and shared names with different values (a referee may
    # leave some undetermined: statically indeterminate from the declarations alone)
    for nm in names:
        s = sols[nm]
        if s.status == "ok" and s.undetermined_reactions and nm not in referees:
            faults.append(ModelFault(nm, "reactions", (), "its equations do not determine the "
                                     "reactions " + ", ".join(map(str, s.undetermined_reactions))))
            odd.append(nm)
    rfaults = []
    if not faults:
        rfaults = _reaction_faults(names, sols)
        for r in rfaults:
            odd += [m for m in r.suspects if m not in odd]
            if r.agreeing:
                majority = majority or r.agreeing
    if not faults and not rfaults:
        return None
    odd, majority, notes = _weigh(groups, faults, rfaults, list(dict.fromkeys(odd)), majority,
                                  referees, sols)
    return [tuple(g) for g in groups], faults, rfaults, odd, majority, notes


def _differ(sols: dict, a: str, b: str, reaction: str) -> bool:
    """Do models ``a`` and ``b`` both determine ``reaction``, with different values?"""
    va = [v for u, v in sols[a].lam.items() if str(u) == reaction] if a in sols else []
    vb = [v for u, v in sols[b].lam.items() if str(u) == reaction] if b in sols else []
    if not va or not vb or va[0] is None or vb[0] is None:
        return False
    return not same_values(va, vb)


def _weigh(groups, faults, rfaults, odd: list, majority: tuple, referees: Mapping,
           sols: dict):
    """What a referee's vote means: ``(odd, majority, notes)``.

    A referee follows from its direct model's declarations, so (1) where the two differ --
    in the motion or in a reaction -- the direct model's balances or projections do not
    follow from its own declarations: the direct model is at fault, whoever else agrees; and
    (2) a majority won only because a direct model and its own referee agree does not clear
    their shared declarations: the note says the mistake may lie in one of them.
    """
    notes = []
    group_of = {nm: i for i, g in enumerate(groups) for nm in g}
    for ref, direct in referees.items():
        split = ref in group_of and direct in group_of and group_of[ref] != group_of[direct]
        split_r = [r.name for r in rfaults if _differ(sols, direct, ref, r.name)]
        if split or split_r:
            what = "motion" if split else "reaction " + ", ".join(split_r)
            notes.append(f"`{direct}`: its balances and projections do not follow from its "
                         f"own declarations (the {what} differs from that of `{ref}`, which "
                         "is derived from them)")
            odd = [direct] + [m for m in odd if m != direct and m != ref]
            for r in rfaults:
                if r.name in split_r and not r.agreeing:
                    r.agreeing = tuple(m for m in r.suspects if m != direct)
                    r.suspects = (direct,)
            if split and group_of[ref] == 0 and len(groups[0]) >= 2:
                majority = tuple(groups[0])
    for r in rfaults:   # a reaction outvoted only by a direct model and its own referee
        pairs = [(ref, d) for ref, d in referees.items()
                 if ref in r.agreeing and d in r.agreeing]
        if pairs and len(r.agreeing) - len(pairs) <= len(r.suspects):
            directs = [d for _, d in pairs]
            notes.append(f"reaction {r.name}: {_names(directs)} and "
                         f"{'its referee' if len(directs) == 1 else 'their referees'} share "
                         "declarations (bodies, loads): the difference may lie in a shared "
                         f"declaration of {_names(directs)}")
            r.suspects = tuple(directs) + r.suspects
            r.agreeing = ()
            odd = list(dict.fromkeys(odd + directs))
    if any(m in odd for m in majority):   # the outvote above did not count: no majority
        majority = ()
    if majority:
        shared = [d for r, d in referees.items() if r in majority and d in majority]
        independent = len(majority) - len(shared)
        rivals = [len(g) - len([r for r, d in referees.items() if r in g and d in g])
                  for g in groups if tuple(g) != tuple(majority)]
        if shared and rivals and independent <= max(rivals):
            names = _names(shared)
            notes.append(f"{names} and {'its referee' if len(shared) == 1 else 'their referees'}"
                         f" share declarations (bodies, masses, inertias, loads): the "
                         f"disagreement may lie in a shared declaration of {names}, not only "
                         f"in {_names([m for m in odd if m not in majority]) or 'the others'}")
    return odd, majority, notes


def _reaction_faults(names, sols) -> list[ReactionFault]:
    """Reactions that two or more models share but give different values."""
    shared: dict = {}
    for nm in names:
        for u, v in sols[nm].lam.items():
            if v is not None:
                shared.setdefault(u, []).append((nm, v))
    out = []
    for u, given in shared.items():
        if len(given) < 2:
            continue
        groups: list[list] = []
        for nm, v in given:
            for g in groups:
                if same_values([g[0][1]], [v]):
                    g.append((nm, v))
                    break
            else:
                groups.append([(nm, v)])
        if len(groups) == 1:
            continue
        groups.sort(key=len, reverse=True)
        if len(groups[0]) >= 2 and len(groups[0]) > len(groups[1]):
            agreeing = tuple(nm for nm, _ in groups[0])
            suspects = tuple(nm for g in groups[1:] for nm, _ in g)
        else:
            agreeing, suspects = (), tuple(nm for g in groups for nm, _ in g)
        out.append(ReactionFault(str(u), suspects, agreeing))
    return out
