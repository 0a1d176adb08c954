r"""What can be asked of a problem: the quantities an answer may be, and their kinds.

Every problem offers, from its own verified models:

==================  ============  ==========================================================
name                kind          right when
==================  ============  ==========================================================
``eom``             equations     equivalent to the equations of motion (scaled, rearranged,
                                  combined, solved for the accelerations): every equation
                                  follows from them and together they determine every
                                  acceleration (and every reaction they use)
``equation``        equation      one equation that follows from the equations of motion;
                                  the feedback says which coordinate's equation it matches
``equation:q``      equation      ``q``'s equation: a multiple of it, or solved for ``q''``
``q''``             expression    the acceleration of ``q`` on the motion
reaction names      expression    the reaction (or multiplier) on the motion; an answer may
                                  contain accelerations (the verified ones are put in)
``T`` / ``KE``      kinetic       the kinetic energy
``V`` / ``PE``      potential     the potential energy, up to a constant
``L``               lagrangian    gives the same Lagrange equations: ``c L + dF(q, t)/dt``
``Q_q``, ``Q``      force         the generalised force on ``q`` (all of them, ``[...]``)
``linearised``      equations     the linearisation about ``about`` (default all zero)
printed labels      expression    a quantity the source prints, e.g. ``(4) angular momentum
                                  h_O`` (components as ``[a, b, c]``)
==================  ============  ==========================================================

(``T`` names a reaction where the problem has one called ``T``; ``KE`` is always the kinetic
energy.)  A problem may add its own quantities with a method ``quantities()`` returning
``{name: expression}``, ``{name: (components...)}`` or ``{name: {"value": ..., "basis":
("i_B", "j_B", "k_B"), "description": ...}}``; expressions may use ``q(t)``, its
derivatives and the reactions, and a vector answer is then typed in its basis
(``m*R^2*(phi'*cos(theta)*i_B + theta'*j_B)``).

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.grade.context import ProblemContext
>>> cat = catalogue(ProblemContext.of(get("toy_car")))
>>> [n for n in cat if not n.startswith("(")]  # doctest: +NORMALIZE_WHITESPACE
['eom', 'equation', 'equation:theta', 'equation:phi', "theta''", "phi''", 'F_r', 'KE', 'T',
 'PE', 'V', 'L', 'Q_theta', 'Q_phi', 'Q', 'linearised', 'p', 'h_O']
"""
from __future__ import annotations

import difflib
from dataclasses import dataclass, field

import sympy as sp

from dualmech.model.equations import EquationSet, ModelError
from dualmech.model.kinematics import t
from dualmech.model.problem import Problem
from dualmech.grade.context import GradingUnavailable, ProblemContext
from dualmech.grade.parser import AnswerError, parse

__all__ = ["Quantity", "catalogue", "find_quantity", "UnknownQuantity", "linearised_context",
           "KINDS"]

KINDS = ("equations", "equation", "expression", "kinetic", "potential", "lagrangian", "force")


class UnknownQuantity(AnswerError):
    """A quantity the problem does not offer; the message lists those it does."""


@dataclass(frozen=True)
class Quantity:
    """One thing an answer may be (see the module docstring).

    ``reference`` are plain sympy expressions (expression kinds), ``basis`` the names of the
    basis vectors of a vector quantity, ``coordinate`` the index of the coordinate an
    ``equation:q`` or ``Q_q`` is about, ``forbid`` the symbols an answer may not use.
    """

    name: str
    kind: str
    description: str
    reference: tuple = ()
    basis: tuple = ()
    coordinate: int | None = None
    forbid: frozenset = field(default_factory=frozenset)
    up_to_constant: bool = False


_ALIASES = {"kinetic": "KE", "kinetic energy": "KE", "potential": "PE",
            "potential energy": "PE", "U": "PE", "lagrangian": "L", "Lagrangian": "L",
            "motion": "eom", "equations": "eom", "equations of motion": "eom",
            "linearized": "linearised", "linear": "linearised"}


def catalogue(ctx: ProblemContext) -> dict[str, Quantity]:
    """Every quantity of the problem, by name (built once per context)."""
    return ctx.memo("catalogue", lambda: _catalogue(ctx))


def _standard(ctx: ProblemContext) -> dict[str, Quantity]:
    """The quantities every problem has (equations, accelerations, reactions, energies,
    generalised forces) -- without reading the printed answers, which costs more than
    grading an answer; a printed answer never takes one of these names."""
    return ctx.memo("standard quantities", lambda: _standard_quantities(ctx))


def _catalogue(ctx: ProblemContext) -> dict[str, Quantity]:
    cat = dict(_standard(ctx))
    names = set(cat)
    for extra in (_published(ctx), _declared(ctx)):
        for name, q in extra.items():   # never hide a reaction, an energy, ...
            if name in names:
                name = f"{name} (printed)" if q.description.startswith("printed") else \
                    f"{name} (declared)"
                q = Quantity(name, q.kind, q.description, q.reference, q.basis)
            cat[name] = q
    return cat


def _standard_quantities(ctx: ProblemContext) -> dict[str, Quantity]:
    cat: dict[str, Quantity] = {}
    acc = frozenset(ctx.qdd) | frozenset(ctx.reactions)
    cat["eom"] = Quantity("eom", "equations", "the equations of motion (a set)")
    cat["equation"] = Quantity("equation", "equation", "one equation of motion")
    for j, s in enumerate(ctx.states):
        cat[f"equation:{s.name}"] = Quantity(f"equation:{s.name}", "equation",
                                             f"the equation of motion of {s.name}", coordinate=j)
    for s in ctx.states:
        cat[s.name + "''"] = Quantity(s.name + "''", "expression",
                                      f"the acceleration {s.name}'' on the motion",
                                      reference=(s.qdd,), forbid=acc)
    info = ctx.problem.reaction_info()
    for u in ctx.reactions:
        direction = info[u.name].direction if u.name in info else "multiplier"
        cat[u.name] = Quantity(u.name, "expression", f"the reaction {u.name} ({direction})",
                               reference=(u,), forbid=frozenset(ctx.reactions))
    names = set(cat)
    for short, long_, kind, text in (("T", "KE", "kinetic", "the kinetic energy"),
                                     ("V", "PE", "potential", "the potential energy"),
                                     ("L", "L", "lagrangian", "the Lagrangian")):
        q = Quantity(long_, kind, text, forbid=acc)
        cat[long_] = q
        if short not in names:
            cat[short] = q
    for j, s in enumerate(ctx.states):
        cat[f"Q_{s.name}"] = Quantity(f"Q_{s.name}", "force",
                                      f"the generalised force on {s.name}", coordinate=j,
                                      forbid=acc)
    if "Q" not in names:
        cat["Q"] = Quantity("Q", "force", "the generalised forces, [" +
                            ", ".join(f"Q_{s.name}" for s in ctx.states) + "]", forbid=acc)
    cat["linearised"] = Quantity("linearised", "equations",
                                 "the equations linearised about an equilibrium (`about`)")
    return cat


def _published(ctx) -> dict:
    out = {}
    try:
        pubs = ctx.problem.published()
    except Exception:  # a broken transcription is the problem's to fix; nothing to offer
        return out
    for pub in pubs:
        if pub.kind != "expression" or (pub.coordinates and
                                        pub.coordinates != ctx.problem.reference):
            continue
        ref = tuple(ctx.plain(e) for e in pub.reference)
        if any(e.has(sp.Derivative) or e.atoms(sp.core.function.AppliedUndef) for e in ref):
            continue
        out[pub.label] = Quantity(pub.label, "expression", f"printed: {pub.where or pub.label}",
                                  reference=ref)
    return out


def _declared(ctx) -> dict:
    hook = getattr(ctx.problem, "quantities", None)
    if not callable(hook):
        return {}
    out = {}
    for name, spec in hook().items():
        basis, text = (), f"declared by the problem: {name}"
        if isinstance(spec, dict):
            basis = tuple(spec.get("basis", ()))
            text = spec.get("description", text)
            spec = spec["value"]
        values = tuple(spec) if isinstance(spec, (tuple, list, sp.MatrixBase)) else (spec,)
        out[name] = Quantity(name, "expression", text,
                             reference=tuple(ctx.plain(sp.sympify(v, strict=True))
                                             for v in values), basis=basis)
    return out


def find_quantity(ctx: ProblemContext, name: str) -> Quantity:
    """The quantity called ``name`` (exact, alias, or a coordinate's acceleration written any
    accepted way, e.g. ``thetaddot``); :class:`UnknownQuantity` lists the choices."""
    name = name.strip()
    standard = _standard(ctx)
    if name in standard:        # no printed answer takes a standard name
        return standard[name]
    cat = catalogue(ctx)        # a printed label (``U``) before an alias (``U`` for PE)
    for key in (name, _ALIASES.get(name), _ALIASES.get(name.lower())):
        if key and key in cat:
            return cat[key]
    if name.startswith(("equation:", "eom:")):
        coord = name.split(":", 1)[1].strip()
        ref = ctx.vocabulary.lookup(coord, 0)
        if ref is not None and ref.kind == "coordinate" and f"equation:{ref.base}" in cat:
            return cat[f"equation:{ref.base}"]
    if name.startswith("Q_"):
        ref = ctx.vocabulary.lookup(name[2:], 0)
        if ref is not None and ref.kind == "coordinate" and f"Q_{ref.base}" in cat:
            return cat[f"Q_{ref.base}"]
    try:  # an acceleration or a reaction written another accepted way
        eqs = parse(name)
        node = eqs[0].lhs if len(eqs) == 1 and eqs[0].rhs is None else None
        if node is not None and node.op == "name":
            ref = ctx.vocabulary.lookup(*node.args)
            if ref is not None and ref.kind == "coordinate" and ref.order == 2:
                return cat[ref.base + "''"]
            if ref is not None and ref.kind == "reaction":
                return cat[str(ref.symbol)]
    except AnswerError:
        pass
    close = difflib.get_close_matches(name, list(cat), n=3, cutoff=0.5)
    hint = f" Did you mean {', '.join(repr(c) for c in close)}?" if close else ""
    raise UnknownQuantity(f"problem `{ctx.problem.name}` has no quantity {name!r}.{hint} "
                          f"It offers: {', '.join(cat)}.")


# -- linearisation ----------------------------------------------------------------------------
class _Linearised(Problem):
    """The linearisation of a problem's reference model, as a problem of its own."""

    reference = "linearised"
    extra_models = ("linearised",)

    def __init__(self, base, equations: EquationSet, about: str):
        self._base = base
        self._eqs = equations
        self.name = f"{base.name} (linearised about {about})"
        self.title = f"{base.title}, linearised"
        self.source = base.source
        self.parameters = base.parameters
        self.coordinates = tuple(base.coordinate_info(q) for q in equations.coordinates)

    @property
    def model_names(self) -> list[str]:
        return ["linearised"]

    def linearised(self) -> EquationSet:
        return self._eqs


def linearised_context(ctx: ProblemContext, about: str | None) -> ProblemContext:
    """The context of the linearisation about ``about`` (``"theta=0, phi=pi"``; default
    every coordinate zero), built once per equilibrium."""
    point = _equilibrium(ctx, about or "")
    key = ("linearised", tuple(sorted((str(k), str(v)) for k, v in point.items())))
    return ctx.memo(key, lambda: _linearise(ctx, point))


def _linearise(ctx: ProblemContext, point: dict) -> ProblemContext:
    ref = ctx.reference
    if ref.unknowns:
        raise GradingUnavailable(f"the reference model of `{ctx.problem.name}` has "
                                 "reactions; it cannot be linearised.")
    try:
        M, C, K = ref.linearize(point)
    except ModelError as exc:
        raise GradingUnavailable(f"cannot linearise `{ctx.problem.name}` about "
                                 f"{_show(point)}: {exc}") from None
    qs = sp.Matrix(ref.coordinates)
    q0 = sp.Matrix([point.get(q, 0) for q in ref.coordinates])
    eqs = M * qs.diff(t, 2) + C * qs.diff(t) + K * (qs - q0)
    lin = EquationSet("linearised", tuple(ref.coordinates), tuple(eqs),
                      labels=tuple(f"linearised, {q.func.__name__}" for q in ref.coordinates))
    problem = _Linearised(ctx.problem, lin, _show(point))
    problem.about_point, problem.about_text = point, _show(point)
    lctx = ProblemContext(problem, ctx.seed)
    lctx.subject = f"the equations of motion linearised about {_show(point)}"
    return lctx


def _show(point: dict) -> str:
    return ", ".join(f"{q.func.__name__}={v}" for q, v in point.items()) or "zero"


def _equilibrium(ctx: ProblemContext, about: str) -> dict:
    """``{q(t): value}`` from ``"theta=0, phi=pi/2"`` (parsed, never evaluated as text)."""
    from dualmech.grade.formula import Formula
    out = {}
    for part in [p for p in about.replace(";", ",").split(",") if p.strip()]:
        eqs = parse(part)
        if len(eqs) != 1 or eqs[0].rhs is None or eqs[0].lhs.op != "name":
            raise AnswerError(f"`about`: write coordinate=value pairs, e.g. 'theta=0, phi=pi'; "
                              f"got {part.strip()!r}.")
        ref = ctx.vocabulary.lookup(*eqs[0].lhs.args)
        if ref is None or ref.kind != "coordinate" or ref.order != 0:
            raise AnswerError(f"`about`: {eqs[0].lhs.args[0]!r} is not a coordinate of "
                              f"`{ctx.problem.name}`.")
        value = Formula.from_node(eqs[0].rhs, ctx.vocabulary).sympy()
        q = next(q for q, s in zip(ctx.coordinates, ctx.states) if s.name == ref.base)
        out[q] = value
    return {q: out.get(q, sp.Integer(0)) for q in ctx.coordinates}
