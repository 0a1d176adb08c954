"""The direct form's declarations against the hand Lagrangian, body by body and load by load.

Below the vote, compare at the level a teacher acts on (DESIGN.md, "Two models, and a
referee").  The direct form knows its bodies (mass, inertia, the point or frame they move
with) and its loads (gravity, springs, applied forces and torques, reactions at their points
along their directions).  From those declarations alone:

* the kinetic energy ``T`` of each body (:meth:`~dualmech.model.bodies.RigidBody.kinetic_energy`);
* the virtual work ``delta W = sum_j Q_j delta q_j`` of each load, ``Q_j = F . dv_P/dq'_j``
  (plus ``tau . d w/dq'_j`` for a couple); a conservative load's potential ``V`` from it;
* the virtual work of each reaction, which an ideal constraint makes zero.

Each is compared -- exactly, by evaluation at random rational points
(:mod:`dualmech.exact.form`) -- with the hand Lagrangian's named terms (``kinetic``,
``potential``, ``dissipation``, generalised forces; :class:`~dualmech.model.lagrange.Lagrangian`),
matched by name or value.  Where they differ, the body or load is named with the term that
differs (:mod:`dualmech.verify.termdiff`), and the edit that writes the declared value into
the Lagrangian is tried: when it makes the two models agree, the finding says so (checked).

When every ``T``, ``V`` and ``delta W`` agree, the hand Lagrangian is the Lagrangian of the
direct form's own declarations; a disagreement of the equations is then in a balance of the
direct form (a moment about a moving point taken as if fixed, a projection), not in a
declaration -- :mod:`dualmech.verify.edits` finds the row.

Both models are brought to the reference coordinates of the problem through its coordinate
maps before anything is compared.
"""
from __future__ import annotations

import copy
import itertools
import random
from dataclasses import dataclass, field

import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.exact.form import ExactForm, is_zero
from dualmech.model.declared import builder_of
from dualmech.model.direct import NewtonEuler
from dualmech.model.equations import from_plain, state_symbols, to_plain
from dualmech.model.kinematics import t
from dualmech.model.lagrange import Lagrangian
from dualmech.verify.termdiff import TermEdit, term_edits

__all__ = ["Finding", "DeclarationCheck", "builders_of", "check_declarations", "virtual"]


@dataclass
class Finding:
    """One body or load whose energy or virtual work differs between the two models.

    ``quantity`` names it as a teacher does (``"T of bob"``, ``"V of spring"``,
    ``"δW of P on bob"``, ``"reaction N"``); ``edits`` are the term edits from the
    Lagrangian's value (``have``) to the declared one (``right``); ``bodies``/``loads`` the
    declarations it concerns; ``reconciles`` whether writing the declared value into the
    Lagrangian makes the two models agree (checked; ``None`` when not tried).
    """

    quantity: str
    kind: str
    lagrange: str
    direct: str
    have: sp.Expr
    right: sp.Expr
    edits: list = field(default_factory=list)
    bodies: tuple = ()
    loads: tuple = ()
    keys: tuple = ()            # the Lagrangian's term keys
    reconciles: bool | None = None
    probably: bool = False      # the body or load is attributed, not matched
    via: str = ""               # reactions whose values (from the direct balances) are in it
    along: tuple = ()           # loads on the same body whose virtual work differs too

    @property
    def terms(self) -> list:
        """``[(kind, have, right)]`` of the edits (expressions in q(t), q'(t); ``None``
        where a term is missing or extra)."""
        return [(e.kind, e.have, e.right) for e in self.edits]


@dataclass
class DeclarationCheck:
    """The comparison of one direct model's declarations with one hand Lagrangian."""

    direct: str
    lagrange: str
    findings: list = field(default_factory=list)
    compared: tuple = ()        # what was compared: "T", "V and δW", "reactions"
    note: str = ""

    #: reactions whose virtual work does not vanish (a contact force declared at a point
    #: that is not the body's material point does work by the declaration alone): not a
    #: finding, a hint when nothing else explains the disagreement
    working_reactions: list = field(default_factory=list)

    @property
    def agree(self) -> bool:
        return not self.findings and not self.note


def builders_of(problem) -> dict:
    """``{model name: builder}`` of the problem's models made by a :class:`NewtonEuler` or a
    :class:`Lagrangian` (:func:`~dualmech.model.declared.builder_of`)."""
    try:
        models = problem.models()
    except Exception:  # noqa: BLE001 - a model that does not build is the verdict's business
        return {}
    return {name: b for name, eqs in models.items() if (b := builder_of(eqs)) is not None}


def virtual(q) -> sp.Symbol:
    """The virtual displacement ``δq`` of coordinate ``q`` (a plain symbol, shown ``δθ``)."""
    from dualmech.model.notation import symbol_text
    return sp.Symbol("δ" + symbol_text(q.func.__name__), real=True)


class _Frame:
    """Conversion of one model's expressions to the reference coordinates (plain symbols)."""

    def __init__(self, problem, name: str, coords):
        self.ref = tuple(problem.model(problem.reference).coordinates)
        self.coords = tuple(coords)
        if set(self.coords) <= set(self.ref):
            self.mapping = None
        else:
            self.mapping = problem.coordinate_maps()[name]   # KeyError: not comparable
        self.states = [state_symbols(q) for q in self.ref]
        self.deltas = [virtual(q) for q in self.ref]

    def plain(self, expr) -> sp.Expr:
        expr = as_expr(expr)
        if self.mapping is not None:
            rules = {}
            for q, f in self.mapping.items():
                f = as_expr(f)
                rules[q.diff(t, 2)] = f.diff(t, 2)
                rules[q.diff(t)] = f.diff(t)
            expr = expr.xreplace(rules).xreplace(dict(self.mapping))
        return to_plain(expr, self.ref)

    def work(self, Q: list) -> sp.Expr:
        """``sum_j Q_j delta q_j`` (``Q`` per own coordinate) in the reference's ``δq``."""
        total = sp.Integer(0)
        for q, Qj in zip(self.coords, Q):
            if self.mapping is None:
                dq = self.deltas[self.ref.index(q)]
            else:
                f = self.plain(q)
                dq = sum((sp.diff(f, s.q) * d for s, d in zip(self.states, self.deltas)),
                         sp.Integer(0))
            total += self.plain(Qj) * dq
        return total


# -- each side's quantities ---------------------------------------------------------------------
def _direct_side(ne: NewtonEuler, fr: _Frame) -> tuple[dict, dict, dict, dict]:
    """``(T by body, δW by load, δW by reaction, bodies by load)`` of a direct builder."""
    ground = ne.ground
    rates = [q.diff(t) for q in ne.coordinates]
    T, W, R, owners = {}, {}, {}, {}
    for body in ne._bodies.values():
        T[body.name] = fr.plain(body.kinetic_energy(ground))
        omega = body.frame.ang_vel_in(ground) if hasattr(body, "frame") else None
        for ld in ne._all_loads(body):
            Q = [sp.Integer(0)] * len(rates)
            if ld.force is not None:
                v = _material(body, ld.point, ground)
                Q = [a + ld.force.dot(v.diff(r, ground)) for a, r in zip(Q, rates)]
            if ld.torque is not None and omega is not None:
                Q = [a + ld.torque.dot(omega.diff(r, ground)) for a, r in zip(Q, rates)]
            target = R if ld.key.startswith("reaction ") else W
            target[ld.key] = target.get(ld.key, 0) + fr.work(Q)
            owners.setdefault(ld.key, []).append(body.name)
    return T, W, R, owners


def _material(body, point, ground):
    """Velocity of the material point of ``body`` at ``point`` (where a force on it acts):
    ``v_C + w x r_CP`` for a rigid body (the balances take its moment about ``C``, so it
    acts on the body's own point there, as the Kane referee has it); a particle's own
    velocity, wherever the force is drawn.  Not ``point.vel``: a point fixed in the ground at the rim of a
    turning pulley does not move, the rim does.

    >>> import sympy as sp
    >>> from dualmech import Frame, Point, RigidBody, coordinate, rot_z, thin_disk
    >>> th = coordinate("theta"); O = Frame.ground(); o = Point.origin(O)
    >>> wheel = RigidBody("wheel", 1, o, O.child("W", rot_z(th)), thin_disk(1, 1))
    >>> sp.trigsimp(_material(wheel, o.locate("rim", O.x), O).dot(O.y))
    Derivative(theta(t), t)
    """
    from dualmech.model.bodies import RigidBody
    if isinstance(body, RigidBody) and point is not body.masscenter:
        from dualmech.model.constraints import material_velocity
        return material_velocity(body, point, ground)
    return body.masscenter.vel(ground)


def _lagrange_side(lg: Lagrangian, fr: _Frame) -> tuple[dict, dict, dict]:
    """``(T by key, δW by key, V by key)`` of a Lagrangian (``V`` for its potentials)."""
    free = [q for q in lg.coordinates if q not in lg._prescribed]
    states = [state_symbols(q) for q in free]
    T = {k: fr.plain(lg._known(v)) for k, v in lg._T.items()}
    W, V = {}, {}
    for k, v in lg._V.items():
        own = to_plain(lg._known(v), free)
        W[k] = W.get(k, 0) + fr.work([-from_plain(sp.diff(own, s.q), free) for s in states])
        V[k] = fr.plain(lg._known(v))
    for k, v in lg._R.items():
        own = to_plain(lg._known(v), free)
        W[k] = W.get(k, 0) + fr.work([-from_plain(sp.diff(own, s.qd), free) for s in states])
    index = {q: j for j, q in enumerate(lg.coordinates)}
    for k, Q in lg._Q.items():
        W[k] = W.get(k, 0) + fr.work([lg._known(Q[index[q]]) for q in free])
    return T, W, V


# -- exact identity -------------------------------------------------------------------------------
def vanishes(expr, points: int = 3, seed: int = 5) -> bool:
    """Whether ``expr`` is identically zero: exact evaluation at random rational points
    (:mod:`dualmech.exact.form`); a nonzero value is certain."""
    expr = as_expr(expr)
    if expr == 0:
        return True
    symbols = sorted(expr.free_symbols, key=str)
    try:
        form = ExactForm.build([expr], symbols)
    except Exception:  # noqa: BLE001 - then the canonical form decides (display only)
        from dualmech.verify.termdiff import canonical
        return sp.cancel(canonical(expr)) == 0
    rng = random.Random(seed)
    seen = 0
    for _ in range(12 * points):
        point = form.sample(rng, {s: (0.5, 2.0) for s in symbols})
        try:
            (value,) = form.evaluate(point)
        except (ZeroDivisionError, ValueError, OverflowError):
            continue
        if not is_zero(value, 1):
            return False
        seen += 1
        if seen == points:
            return True
    return True


def _sum(d: dict, keys) -> sp.Expr:
    return sp.Add(*[d[k] for k in keys])


# -- matching the two sides' quantities ---------------------------------------------------------
def _words(text: str) -> set:
    return {w for w in text.lower().replace("_", " ").split() if w}


def _match(lag: dict, direct: dict) -> list[tuple[tuple, tuple]]:
    """Groups ``(Lagrangian keys, direct keys)`` that should hold the same quantity: equal
    values first, then names (a body or load named in the term's key), then sums of a few
    equal to one; what is left is one group."""
    L, D = list(lag), list(direct)
    groups = []
    for k in list(L):
        hit = next((d for d in D if vanishes(lag[k] - direct[d])), None)
        if hit is not None:
            groups.append(((k,), (hit,)))
            L.remove(k)
            D.remove(hit)
    for size in (2, 3):
        for k in list(L):
            for combo in itertools.combinations(D, size):
                if len(D) > 8:
                    break
                if vanishes(lag[k] - _sum(direct, combo)):
                    groups.append(((k,), combo))
                    L.remove(k)
                    D = [d for d in D if d not in combo]
                    break
    for k in list(L):
        named = [d for d in D if _words(d) and _words(d) <= _words(k) | {"of", "on"}
                 or d.lower() in k.lower()]
        if len(named) == 1:
            groups.append(((k,), tuple(named)))
            L.remove(k)
            D.remove(named[0])
    if L or D:
        groups.append((tuple(L), tuple(D)))
    return groups


# -- the comparison -------------------------------------------------------------------------------
def check_declarations(problem, direct: str, lagrange: str, builders: dict | None = None,
                       reconcile: bool = True) -> DeclarationCheck:
    """Compare the declarations of direct model ``direct`` with the terms of the hand
    Lagrangian ``lagrange`` of ``problem`` (see the module docstring).

    >>> from dualmech.problems import get
    >>> check_declarations(get("trolley_pendulum"), "newton_euler", "lagrange").agree
    True
    """
    builders = builders if builders is not None else builders_of(problem)
    ne, lg = builders.get(direct), builders.get(lagrange)
    out = DeclarationCheck(direct, lagrange)
    if not isinstance(ne, NewtonEuler) or not isinstance(lg, Lagrangian):
        out.note = "not built with NewtonEuler and Lagrangian: declarations not compared"
        return out
    try:
        fd = _Frame(problem, direct, ne.coordinates)
        fl = _Frame(problem, lagrange, [q for q in lg.coordinates if q not in lg._prescribed])
        Td, Wd, Rd, owners = _direct_side(ne, fd)
        Tl, Wl, Vl = _lagrange_side(lg, fl)
    except (KeyError, TypeError, ValueError, AttributeError) as exc:
        out.note = f"declarations not compared ({type(exc).__name__}: {exc})"
        return out
    states = {x for s in fd.states for x in (s.q, s.qd, s.qdd)} | {t} | set(fd.deltas)
    ctx = (problem, ne, lg, fd, states, reconcile, direct, lagrange)
    out.compared = ("T", "V and δW", "reactions")
    if not vanishes(_sum(Tl, Tl) - _sum(Td, Td)):
        for keys, names in _match(Tl, Td):
            f = _kinetic(ctx, Tl, Td, keys, names)
            if f is not None:
                out.findings.append(f)
    Wd = {k: w for k, w in Wd.items() if not vanishes(w)}   # a load that never works
    for f in _hand_pairs(Wd, Rd, set(ne._unknowns), lagrange, direct, fd, owners):
        out.findings.append(f)
        Wd.pop(f.loads[0])
        for name in f.keys:
            Rd.pop(name, None)
    by_hand = _undeclared(problem.model(direct), Wd, Rd, Td)
    if by_hand:
        out.compared = ("T",)
        out.note = ("the loads were not compared: `" + direct + "` writes "
                    + ", ".join(by_hand) + " by hand, not as declared loads")
    else:
        Wd, via = _through_values(problem, direct, fd, Wd, set(ne._unknowns))
        Wd, Wl, apart = _apart(Wd, Wl, set(ne._unknowns))
        if apart:
            out.note = (", ".join(apart) + " not compared: its virtual work holds a reaction "
                        "(a friction mu N), which `" + lagrange + "` writes through its value")
    if not by_hand and not vanishes(_sum(Wl, Wl) - _sum(Wd, Wd)):
        for keys, loads in _match(Wl, Wd):
            f = _work(ctx, Wl, Wd, Vl, keys, loads, owners)
            if f is not None:
                f.via = ", ".join(sorted({via[ld] for ld in loads if ld in via}))
                f.probably = f.probably or bool(f.via)
                out.findings.append(f)
    _one_body_behind(out.findings)
    for name, w in Rd.items():
        if not vanishes(w) and not _admissibly_zero(w, problem.model(direct), fd):
            edits = term_edits(sp.Integer(0), w, states) or []
            out.working_reactions.append(Finding(
                name, "does work", lagrange, direct, sp.Integer(0), _shown(w, fd),
                _shown_edits(edits, fd), tuple(owners.get(name, ())), (name,), probably=True))
    return out


def _hand_pairs(Wd: dict, Rd: dict, reactions: set, lname: str, dname: str, fd, owners):
    """Loads that repeat a declared reaction with its own sign: the other half of an action
    and reaction drawn by hand (``H = reaction_vector(..., on=rod)`` then ``force(..., wheel,
    H)``).  The pair then does the virtual work ``2 δW``; drawn opposite it does none -- each
    decided exactly.  Findings of kind ``"pair"`` (``keys``: the reactions' own entries)."""
    out = []
    for k, w in Wd.items():
        held = w.free_symbols & reactions
        if not held:
            continue
        mine = [name for name, r in Rd.items() if r.free_symbols & held]
        if not mine:
            continue
        R = _sum(Rd, mine)
        if vanishes(R + w) or not vanishes(R - w):
            continue
        f = Finding(k, "pair", lname, dname, _shown(w, fd), _shown(-w, fd),
                    [TermEdit("sign", _shown(w, fd), _shown(-w, fd))],
                    tuple(owners.get(k, ())), (k,), tuple(mine))
        f.reconciles = None
        out.append(f)
    return out


def _one_body_behind(findings: list) -> None:
    """When ``T`` of a body and the virtual work of loads acting on that body both differ, and
    none of them alone reconciles the models, one slip in where the body is (its position or
    velocity, declared once in the direct model) explains them all better than a slip in each:
    the loads' findings become "probably" and the body's finding names them (``along``).

    >>> T = Finding("T of block", "extra", "lagrange", "newton_euler", 0, 0,
    ...             bodies=("block",), reconciles=False)
    >>> W = Finding("δW of spring", "missing", "lagrange", "newton_euler", 0, 0,
    ...             bodies=("block", "base"), loads=("spring",), reconciles=False)
    >>> _one_body_behind([T, W]); T.along, W.probably
    (('spring',), True)
    """
    moved = {}
    for f in findings:
        if f.quantity.startswith("T of") and f.reconciles is False and len(f.bodies) == 1:
            moved[f.bodies[0]] = f
    for f in findings:
        if f.quantity.startswith("T of") or f.reconciles is not False or not f.loads:
            continue
        bodies = [b for b in f.bodies if b in moved]
        if len(bodies) == 1:
            f.probably = True
            owner = moved[bodies[0]]
            owner.along = owner.along + tuple(x for x in f.loads if x not in owner.along)


def _through_values(problem, direct: str, fr: _Frame, Wd: dict, reactions: set):
    """``(Wd, via)``: the virtual work of each load that holds a reaction (a friction
    ``-mu N ds``) with the reaction's value from the direct model's own balances put in
    (``via``: ``{load: "N"}``), so that it compares with a Lagrangian that writes
    ``mu m g cos alpha``; loads left as they were when the model does not solve (then
    :func:`_apart` sets them apart)."""
    held = {k: w.free_symbols & reactions for k, w in Wd.items()}
    if not any(held.values()):
        return Wd, {}
    try:
        m = problem.in_reference_coordinates(problem.model(direct))
        if not m.is_square or len(m.equations) > 8:
            return Wd, {}
        values = {u: fr.plain(v) for u, v in m.reactions_solved().items()}
    except Exception:  # noqa: BLE001 - a model that does not solve: compared apart
        return Wd, {}
    out, via = dict(Wd), {}
    for k, used in held.items():
        if used and used <= set(values):
            out[k] = sp.expand(Wd[k].xreplace(values))
            via[k] = ", ".join(sorted(u.name for u in used))
    return out, via


def _admissibly_zero(w, model, fr: _Frame, points: int = 3) -> bool:
    """Whether the virtual work ``w`` (in ``δq``) vanishes for every virtual displacement the
    model's declared constraints admit (a rolling friction ``F (r δφ - δx)`` with
    ``x' = r φ'``): its coefficients lie in the span of the constraints' gradients, tried at
    random states (a hint is withheld, never a finding made)."""
    import numpy as np
    rows = []
    for c in getattr(model, "constraints", ()) or ():
        try:
            g = fr.plain(c.expression)
        except Exception:  # noqa: BLE001 - a constraint in other coordinates: not used
            return False
        wrt = [s.qd for s in fr.states] if c.level == "velocity" else [s.q for s in fr.states]
        rows.append([sp.diff(g, x) for x in wrt])
    if not rows:
        return False
    coeff = [sp.diff(w, d) for d in fr.deltas]
    rng = random.Random(3)
    symbols = sorted(set().union(*(sp.Matrix(rows + [coeff]).free_symbols,)), key=str)
    for _ in range(points):
        at = {x: sp.Rational(rng.randint(5, 40), 17) for x in symbols}
        try:
            A = np.array(sp.Matrix(rows).xreplace(at).evalf(30), dtype=float)
            c = np.array(sp.Matrix([coeff]).xreplace(at).evalf(30), dtype=float)
        except (TypeError, ValueError, ZeroDivisionError):
            return False
        if np.linalg.matrix_rank(np.vstack([A, c]), tol=1e-9) != np.linalg.matrix_rank(A, tol=1e-9):
            return False
    return True


def _apart(Wd: dict, Wl: dict, reactions: set) -> tuple[dict, dict, list]:
    """The loads whose virtual work holds a reaction (``-mu N ds``) set apart, with the
    Lagrangian's terms named after them: no term-by-term identity can hold between ``N`` and
    the value a hand Lagrangian writes for it (``m g cos alpha``)."""
    apart = [k for k, w in Wd.items() if w.free_symbols & reactions]
    if not apart:
        return Wd, Wl, []
    words = set().union(*(_words(k) for k in apart))
    Wl = {k: w for k, w in Wl.items() if not (_words(k) and _words(k) <= words | {"of", "on"})}
    return {k: w for k, w in Wd.items() if k not in apart}, Wl, apart


def _undeclared(model, Wd: dict, Rd: dict, Td: dict) -> list:
    """Ingredients of the direct model that are neither a declared load, a reaction, a
    body's inertia nor a declared constraint's row: terms written by hand, which the
    declarations do not show."""
    known = set(Wd) | set(Rd) | {f"inertia of {b}" for b in Td}
    out = []
    for parts in model.contributions or ():
        for key, value in parts.items():
            if key not in known and key not in out and not key.startswith("gravity on ") \
                    and not key.startswith("constraint ") and as_expr(value) != 0:
                out.append(key)
    return out


def _shown(expr, fr: _Frame) -> sp.Expr:
    """A plain expression in the reference coordinates as functions of time (for notation),
    ``sin^2 + cos^2`` of one angle written as 1 (:func:`tidy`)."""
    return _coefficient_factored(tidy(from_plain(expr, fr.ref)))


def _coefficient_factored(expr) -> sp.Expr:
    """A product with its sums factored (``(R^2 m - 2 R m r + m r^2) θ̇^2`` is
    ``m (R - r)^2 θ̇^2``); display only.

    >>> R, r, m, w = sp.symbols("R r m w")
    >>> _coefficient_factored((R**2*m - 2*R*m*r + m*r**2) * w**2)
    m*w**2*(R - r)**2
    """
    if not isinstance(expr, sp.Mul):
        return expr
    def shorter(a):
        f = sp.factor(a)
        f = f.replace(lambda e: e.is_Pow and e.exp.is_even and e.base.is_Add
                      and e.base.could_extract_minus_sign(), lambda e: (-e.base)**e.exp)
        return f if sp.count_ops(f) < sp.count_ops(a) else a
    try:
        return sp.Mul(*(shorter(a) if a.is_Add else a for a in expr.args))
    except Exception:  # noqa: BLE001 - display only
        return expr


def tidy(expr) -> sp.Expr:
    """``expr`` with ``sin^2 + cos^2 = 1`` applied (:func:`~dualmech.verify.termdiff.canonical`)
    where that makes it shorter (a display form: ``F (R - r) sin^2 + F (R - r) cos^2`` is
    ``F (R - r)``); comparisons never depend on it.

    >>> import sympy as sp
    >>> F, R, r, th = sp.symbols("F R r theta")
    >>> tidy(F * (R - r) * sp.sin(th)**2 + F * (R - r) * sp.cos(th)**2)
    F*(R - r)
    """
    expr = as_expr(expr)
    sines = [s for s in expr.atoms(sp.sin)]
    if not sines:
        return expr
    from dualmech.verify.termdiff import canonical
    try:
        out = sp.factor_terms(canonical(expr))      # even powers of cos through sin: one form
    except Exception:  # noqa: BLE001 - display only
        return expr
    return out if sp.count_ops(out) < sp.count_ops(expr) else expr


def _shown_edits(edits, fr) -> list:
    return [TermEdit(e.kind, None if e.have is None else _shown(e.have, fr),
                     None if e.right is None else _shown(e.right, fr)) for e in edits]


def _owner_of(edits, bodies: dict) -> list:
    """The bodies (or loads) whose own value includes every symbol of each edit's change
    (``right - have``: in a lumped ``T`` written ``M x'^2/2`` where ``(M + m) x'^2/2``
    belongs, the change ``m x'^2/2`` is the block's, not the base's).

    >>> M, m, x, u = sp.symbols("M m x u")
    >>> e = TermEdit("differs", M * x**2 / 2, (M + m) * x**2 / 2)
    >>> _owner_of([e], {"base": M * x**2 / 2, "block": m * (x + u)**2 / 2})
    ['block']
    """
    out = []
    for name, T in bodies.items():
        syms = T.free_symbols
        if all(_change(e).free_symbols <= syms | {t} for e in edits):
            out.append(name)
    return out


def _change(e) -> sp.Expr:
    if e.right is None:
        return as_expr(e.have)
    if e.have is None:
        return as_expr(e.right)
    gap = sp.expand(e.right - e.have)
    return gap if gap != 0 else as_expr(e.right)


def _kinetic(ctx, Tl, Td, keys, names) -> Finding | None:
    problem, ne, lg, fd, states, reconcile, dname, lname = ctx
    have, right = _sum(Tl, keys), _sum(Td, names)
    if vanishes(have - right):
        return None
    edits = term_edits(have, right, states)
    quantity = ("T of " + ", ".join(names)) if names else "T of " + ", ".join(keys)
    probably = False
    if len(names) != 1 and edits:       # a lumped T: the body the change is in
        owners = _owner_of(edits, {n: Td[n] for n in names})
        if len(owners) == 1:
            lump = f" (in `{lname}`'s " + ", ".join(keys) + ")" if keys else ""
            quantity, probably = f"T of {owners[0]}{lump}", True
    f = Finding(quantity, _kind(edits), lname, dname, _shown(have, fd), _shown(right, fd),
                _shown_edits(edits or [], fd), tuple(names), (), tuple(keys), probably=probably)
    if reconcile and keys:
        f.reconciles = _reconciles(problem, dname, lg, fd, "T", keys, right)
    return f


def _work(ctx, Wl, Wd, Vl, keys, loads, owners) -> Finding | None:
    problem, ne, lg, fd, states, reconcile, dname, lname = ctx
    have, right = _sum(Wl, keys), _sum(Wd, loads)
    if vanishes(have - right):
        return None
    potential = keys and all(k in Vl for k in keys)
    V_right = _potential(right, fd) if potential else None
    if V_right is not None:
        have_v = _sum(Vl, keys)
        edits = term_edits(have_v, V_right, states, ignore_constant=True)
        quantity = "V of " + ", ".join(keys)
        f = Finding(quantity, _kind(edits), lname, dname, _shown(have_v, fd),
                    _shown(V_right, fd), _shown_edits(edits or [], fd), (), tuple(loads),
                    tuple(keys))
    else:
        edits = term_edits(have, right, states)
        what = ", ".join(loads) if len(loads) == 1 or not keys else ", ".join(keys)
        f = Finding("δW of " + what, _kind(edits), lname, dname, _shown(have, fd),
                    _shown(right, fd), _shown_edits(edits or [], fd), (), tuple(loads),
                    tuple(keys))
    if len(loads) > 1 and edits:                # a lumped V: the load the change is in
        mine = _owner_of(edits, {ld: Wd[ld] for ld in loads})
        if len(mine) == 1:
            lump = f" (in `{lname}`'s " + ", ".join(keys) + ")" if keys else ""
            f.quantity = f.quantity.split(" of ")[0] + " of " + mine[0] + lump
            f.probably = True
    f.bodies = tuple(dict.fromkeys(b for ld in f.loads for b in owners.get(ld, ())))
    if reconcile and keys:
        f.reconciles = _reconciles(problem, dname, lg, fd, "W", keys, right)
    return f


def _kind(edits) -> str:
    if not edits:
        return "differs"
    kinds = {e.kind for e in edits}
    return kinds.pop() if len(kinds) == 1 else "differs"


def _potential(work, fr: _Frame) -> sp.Expr | None:
    """``V(q, t)`` with ``-dV/dq_j`` the coefficient of ``δq_j`` in ``work`` (checked), or
    ``None`` when the load is not conservative or not integrated."""
    grad = [-sp.expand(sp.diff(work, d)) for d in fr.deltas]
    if any(g.free_symbols & {s.qd for s in fr.states} for g in grad):
        return None
    V = sp.Integer(0)
    try:
        for g, s in zip(grad, fr.states):
            rest = sp.expand(g - sp.diff(V, s.q))
            if rest != 0:
                part = sp.integrate(rest, s.q)
                if part.has(sp.Integral):
                    return None
                V += part
    except Exception:  # noqa: BLE001 - a potential is for display; the work is compared
        return None
    if all(vanishes(sp.diff(V, s.q) - g) for g, s in zip(grad, fr.states)):
        return sp.expand(V)
    return None


def _reconciles(problem, direct: str, lg, fd: _Frame, what: str, keys, right) -> bool | None:
    """Whether the Lagrangian with its terms ``keys`` replaced by the declared value
    ``right`` (plain, reference coordinates) gives the direct model's motion."""
    from dualmech.verify.verdicts import judge
    from dualmech.verify.sampling import Context
    if fd.mapping is not None or set(lg.coordinates) != set(fd.ref) or lg._prescribed:
        return None
    edited = copy.copy(lg)
    edited._T, edited._V = dict(lg._T), dict(lg._V)
    edited._R, edited._Q = dict(lg._R), dict(lg._Q)
    value = from_plain(right, fd.ref)
    for k in keys:
        for d in (edited._T, edited._V, edited._R, edited._Q):
            d.pop(k, None)
    if what == "T":
        edited.kinetic(keys[0], value)
    else:
        Q = [from_plain(sp.diff(right, fd.deltas[fd.ref.index(q)]), fd.ref)
             for q in lg.coordinates]
        edited.generalized_force(keys[0], Q)
    try:
        models = {direct: problem.in_reference_coordinates(problem.model(direct)),
                  "edited": edited.equations()}
        ctx = Context(fd.ref, problem.parameter_symbols, problem)
        return judge(models, context=ctx, points=4, reference="edited").equivalent
    except Exception:  # noqa: BLE001 - the check is a bonus; the finding stands without it
        return None
