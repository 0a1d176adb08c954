"""What a term is, in physics words, decided from what it is made of -- not from its shape.

A term of a correct equation is traced to the ingredient of the problem's Lagrangian that
produced it (a kinetic energy ``T``, a potential ``V``, a dissipation ``R``, a generalised force
``Q``, a constraint), by the state part it sits on; the parameters of that ingredient, with the
dimensions the problem *declares* for them (a torque is ``TORQUE``, a torsional spring
``TORQUE / ANGLE``), then name it:

* from ``T``: an accelerated coordinate is **inertia**; a product of two different rates
  **Coriolis**; one rate squared **centripetal**; one rate with a prescribed angular rate
  (a ``1/TIME`` parameter) **Coriolis**; no rate, a prescribed angular rate squared
  **centrifugal**; anything depending on time a term **of the prescribed motion**;
* from ``V``: a parameter declared as an acceleration is **gravity**, a stiffness **spring**;
* from ``R``: **damping**; from a constraint: a **constraint force**;
* from ``Q``: by the declared dimension of its parameters: a **torque**, a **force**, damping,
  spring, gravity.

A state part that two ingredients share is named by the ingredient whose coefficient the term
has; when neither matches, both names are given ("a gravity or spring term"), never one
with certainty.  A term on a state part no ingredient produces (a term the student made up)
is named only by what is certain of it: an acceleration is inertia, a reaction a reaction, a
declared torque a torque.

Example
-------
>>> import sympy as sp
>>> from dualmech.problems import get
>>> from dualmech.grade.context import ProblemContext
>>> ctx = ProblemContext.of(get("bead_on_hoop"))
>>> th = sp.Symbol("theta", real=True)
>>> R, m, w = sp.symbols("R m omega", positive=True)
>>> category(-R**2*m*w**2*sp.sin(th)*sp.cos(th), ctx)
'a centrifugal term'
"""
from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar

import sympy as sp

from dualmech.model.declared import builder_of
from dualmech.model.dimensions import (ACCELERATION, ANGLE, DAMPING, DIMENSIONLESS, FORCE,
                                      INERTIA, LENGTH, MASS, STIFFNESS, TIME, TORQUE,
                                      TORSIONAL_DAMPING, TORSIONAL_STIFFNESS, as_dimension,
                                      reduce)
from dualmech.model.kinematics import t
from dualmech.grade.context import ProblemContext, zero

__all__ = ["category", "sources", "naming_energy"]

#: set while the terms of an energy or a Lagrangian are named (:func:`naming_energy`)
_ENERGY: ContextVar[bool] = ContextVar("naming_energy", default=False)


@contextmanager
def naming_energy():
    """Within it, :func:`category` names the terms of an energy, not of an equation: a term
    with rates is a kinetic-energy term (``m l^2 theta'^2/2`` is not "centripetal"); terms
    without rates keep their kind (gravity, spring, centrifugal)."""
    token = _ENERGY.set(True)
    try:
        yield
    finally:
        _ENERGY.reset(token)

#: an acceleration (g) or a gravitational parameter (mu = G M, L^3 T^-2)
_GRAVITY = (ACCELERATION, LENGTH**3 / TIME**2)
_SPRING = (STIFFNESS, TORSIONAL_STIFFNESS)
_DAMPER = (DAMPING, TORSIONAL_DAMPING)


def _declared(ctx: ProblemContext) -> dict:
    """``{parameter or given input symbol: declared Dimension}`` (angles kept: a torque is
    not a stiffness)."""
    def build():
        out = {}
        declared = list(ctx.problem.parameters) + [
            x for x in (getattr(ctx.problem, "inputs", None) or ()) if hasattr(x, "dimension")]
        for p in declared:
            try:
                out[p.symbol] = as_dimension(p.dimension)
            except (TypeError, ValueError):
                continue
        return out
    return ctx.memo("declared_dimensions", build)


def sources(ctx: ProblemContext) -> dict:
    """``{state part: [(ingredient, coefficient)]}`` over the rows of every Lagrangian model
    of the problem written in the reference coordinates; ingredient one of ``T``, ``V``,
    ``R``, ``Q``, ``constraint``."""
    from dualmech.grade.terms import term_table
    from dualmech.model.lagrange import Lagrangian

    def build():
        out: dict = {}
        for m in ctx.problem.models().values():
            b = builder_of(m)
            if not isinstance(b, Lagrangian) or tuple(m.coordinates) != ctx.coordinates:
                continue
            origin = {k: "T" for k in b._T} | {k: "V" for k in b._V} | \
                {k: "R" for k in b._R} | {k: "Q" for k in b._Q}
            for row in m.contributions:
                for key, piece in row.items():
                    kind = origin.get(key, "constraint" if key.startswith("constraint")
                                      else None)
                    if kind is None or piece == 0:
                        continue
                    tab = term_table(ctx.plain(piece), ctx, mode="trig")
                    for k, (coeff, value, _) in (tab.terms.items() if tab else ()):
                        entry = out.setdefault(k, [])
                        if not any(o == kind and zero(v - value, [v]) for o, _, v in entry):
                            entry.append((kind, coeff, value))
        return out
    return ctx.memo("term_sources", build)


def category(term, ctx: ProblemContext) -> str:
    """A short name for what ``term`` (plain state symbols) is: ``an inertia term``, ``a
    Coriolis term``, ``a torque term``, ...; "" when nothing certain can be said."""
    from dualmech.grade.terms import term_table
    term = sp.sympify(term)
    if term.free_symbols & set(ctx.reactions):
        return "a reaction term"
    if _ENERGY.get():
        if term.free_symbols & {s.qd for s in ctx.states}:
            return "a kinetic-energy term"
        return _by_gradient(term, ctx)
    tab = term_table(term, ctx, mode="trig")
    if tab is None or not tab.terms:
        return ""
    table = sources(ctx)
    names: list = []
    for key, (coeff, value, _) in tab.terms.items():
        found = table.get(key)
        name = _traced(found, key, value, coeff, ctx) if found else _by_rates(key, coeff, ctx)
        if not name:
            return ""
        if name not in names:
            names.append(name)
    if len(names) == 1:
        return names[0]
    return " and ".join(names[:-1]) + " and " + names[-1] if len(names) <= 3 else ""


def _by_gradient(term, ctx: ProblemContext) -> str:
    """A term of an energy without rates, named by the terms it puts in the equations (its
    gradient): ``P x2^2/(2a)`` of a string's V by the string's terms, ``m g l cos(theta)``
    as gravity; "" when its components are named differently."""
    token = _ENERGY.set(False)
    try:
        names = {category(sp.diff(term, s.q), ctx) for s in ctx.states
                 if sp.diff(term, s.q) != 0}
    finally:
        _ENERGY.reset(token)
    return names.pop() if len(names) == 1 else ""


def _signature(key, ctx):
    """The rates and accelerations of a state part, and whether it depends on time."""
    moving = {s.qd for s in ctx.states} | {s.qdd for s in ctx.states} | {t}
    return sp.Mul(*[f for f in sp.Mul.make_args(key) if f.free_symbols & moving])


def _by_rates(key, coeff, ctx) -> str:
    """A term on a state part no ingredient has (a row scaled by a function of the
    coordinates, or a term the student made up): named by the ingredients with its rates and
    accelerations, narrowed by what is certain of its own parameters."""
    def build():
        out: dict = {}
        for k, found in sources(ctx).items():
            for kind, c, _ in found:
                name = _name(kind, c, k, ctx)
                if name:
                    out.setdefault(_signature(k, ctx), set()).add(name)
        return out
    names = {n for n in ctx.memo("term_signatures", build).get(_signature(key, ctx), set())
             if _supported(n, key * coeff, ctx)}
    certain = _certain(key * coeff, ctx)
    if len(names) == 1 and (not certain or certain in names):
        return next(iter(names))
    if certain:
        return certain
    if len(names) in (2, 3):
        words = sorted(n.split(" ", 1)[1].removesuffix(" term") for n in names)
        return f"{'an' if words[0][0] in 'aeiou' else 'a'} {' or '.join(words)} term"
    return ""


def _supported(name: str, term, ctx) -> bool:
    """Whether ``term``'s own make-up allows ``name``: gravity needs a parameter declared as
    gravity, a spring a stiffness, a centrifugal term a rate parameter, inertia an
    acceleration, ... (a term at another scale keeps what defines its kind)."""
    syms = term.free_symbols
    declared = _declared(ctx)
    dims = {declared.get(s) for s in syms if s in declared}
    rates = any(s.qd in syms for s in ctx.states)
    needs = (("gravity", lambda: dims & set(_GRAVITY)), ("spring", lambda: dims & set(_SPRING)),
             ("damping", lambda: dims & set(_DAMPER) or rates),
             ("torque", lambda: TORQUE in dims), ("force", lambda: FORCE in dims),
             ("centrifugal", lambda: any(reduce(d) == reduce(1 / TIME) for d in dims if d)),
             ("prescribed", lambda: t in syms),
             ("inertia", lambda: any(s.qdd in syms for s in ctx.states)),
             ("Coriolis", lambda: rates), ("centripetal", lambda: rates))
    return all(bool(test()) for word, test in needs if word in name)


def _traced(found: list, key, value, coeff, ctx) -> str:
    """The name of a term on ``key`` from the ingredients that produce that state part: the
    one whose coefficient the term has; else what its own parameters make certain (a term at
    another scale, or made up: ``5 M g x`` where only ``k x`` sits on ``x``); else every
    ingredient's name."""
    named = [(_name(kind, c, key, ctx), v) for kind, c, v in found]
    kinds = list(dict.fromkeys(n for n, _ in named if n))
    exact = list(dict.fromkeys(n for n, v in named if n and zero(value - v, [value, v])))
    if len(exact) == 1:
        return exact[0]
    # the same parameters times another number (a wrong sign, a factor 2): the same kind
    scaled = list(dict.fromkeys(n for (n, _), (_, c, _) in zip(named, found)
                                if n and _numeric_ratio(coeff, c)))
    if len(scaled) == 1:
        return scaled[0]
    certain = _certain(key * coeff, ctx)
    if certain:
        return certain
    kinds = [k for k in kinds if _supported(k, key * coeff, ctx)]
    if not kinds:
        return _by_rates(key, coeff, ctx)
    if len(kinds) == 1:
        return kinds[0]
    words = [k.split(" ", 1)[1].removesuffix(" term") for k in kinds]
    article = "an" if words[0][0] in "aeiou" else "a"
    return f"{article} {' or '.join(words)} term"


def _numeric_ratio(a, b) -> bool:
    """Whether ``a / b`` is a nonzero number (no parameter in it)."""
    if b == 0 or a == 0:
        return False
    r = sp.cancel(sp.sympify(a) / b)
    return bool(r.is_number and r != 0)


def _name(kind: str, coeff, key, ctx) -> str:
    syms = (key * coeff).free_symbols
    if kind == "T":
        return _kinetic(coeff, key, ctx)
    if kind == "R":
        return "a damping term"
    if kind == "constraint":
        return "a constraint-force term"
    declared = _declared(ctx)
    dims = {declared.get(s) for s in syms if s in declared}
    if kind == "V":
        gravity, spring = bool(dims & set(_GRAVITY)), bool(dims & set(_SPRING))
        if gravity and spring:
            return "a gravity and spring term"
        return ("a gravity term" if gravity else "a spring term" if spring
                else "a potential-energy term")
    # a generalised force: named by what its parameters are declared to be
    driven = "a driving" if t in syms else "an applied"
    for group, name in ((_DAMPER, "a damping term"), ((TORQUE,), f"{driven} torque term"),
                        ((FORCE,), f"{driven} force term"), (_SPRING, "a spring term"),
                        (_GRAVITY, "a gravity term")):
        if dims & set(group):
            return name
    return "a generalised-force term"


def _kinetic(coeff, key, ctx) -> str:
    """A term from the kinetic energy, by the rates it is made of."""
    powers = key.as_powers_dict()
    if any(s.qdd in key.free_symbols for s in ctx.states):
        return "an inertia term"
    rates = [s.qd for s in ctx.states if s.qd in key.free_symbols]
    if t in (key * coeff).free_symbols:
        return "a term of the prescribed motion"
    spin = any(p in _declared(ctx) and reduce(_declared(ctx)[p]) == reduce(1 / TIME)
               for p in coeff.free_symbols)
    if len(rates) >= 2:
        return "a Coriolis term"
    if rates:
        if powers.get(rates[0], 0) >= 2:
            return "a centripetal term"
        return "a Coriolis term" if spin else "a kinetic-energy term"
    return "a centrifugal term" if spin else "a kinetic-energy term"


def _certain(term, ctx) -> str:
    """What is certain of a term no ingredient produces: its acceleration, or a parameter
    declared as a torque, force, damper, spring or acceleration (gravity)."""
    syms = term.free_symbols
    if any(s.qdd in syms for s in ctx.states):
        return "an inertia term"
    declared = _declared(ctx)
    dims = {declared.get(s) for s in syms if s in declared}
    rates = any(s.qd in syms for s in ctx.states)
    if rates and dims & set(_DAMPER):
        return "a damping term"
    driven = "a driving" if t in syms else "an applied"
    for group, name in (((TORQUE,), f"{driven} torque term"), ((FORCE,), f"{driven} force term"),
                        (_SPRING, "a spring term"), (_GRAVITY, "a gravity term")):
        if not rates and dims & set(group) and len(dims - {None}) >= 1:
            others = dims - set(group) - {None}
            if not others & set(_SPRING + _GRAVITY + (TORQUE, FORCE) + _DAMPER):
                return name
    inertial = {MASS, LENGTH, INERTIA, ANGLE, DIMENSIONLESS}
    spin = {d for d in dims if d is not None and reduce(d) == reduce(1 / TIME)}
    if rates and not dims - inertial - spin:   # rates times masses and lengths: kinematics
        moving = [s.qd for s in ctx.states if s.qd in syms]
        powers = term.as_powers_dict()
        if len(moving) >= 2:
            return "a Coriolis term"
        if spin and t not in syms and powers.get(moving[0], 0) == 1:
            return "a Coriolis term"   # a rate times a prescribed angular rate (2 m Omega r')
        if not spin and powers.get(moving[0], 0) >= 2:
            return "a centripetal term"
    return ""
