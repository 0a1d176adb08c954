r"""sympy.physics.mechanics in and out: a Kane or Lagrange model built there, checked as one more
derivation of a problem; a problem's equations handed back for simulation.

* :func:`from_mechanics` turns a ``KanesMethod``, ``LagrangesMethod`` or ``System`` into an
  :class:`~dualmech.model.equations.EquationSet` in the problem's coordinates and symbols (matched by
  name; the kinematic differential equations ``q' = f(u, q)`` are inverted, so a Kane model's
  generalised speeds become the coordinates' rates; dependent speeds with their velocity
  constraints -- sympy's rolling disk --, dependent coordinates with their configuration
  constraints -- sympy's Whipple bicycle -- and a Lagrange model's constraint equations are
  kept as declared constraints at their own level, so the verdict samples on their manifold;
  a speed of a coordinate the model leaves out is mapped with ``ignorable``);
* :func:`with_derivation` gives the problem with that set as one more model, and
  :func:`check_mechanics` compares it with the problem's own derivations exactly -- a wrong
  Kane model is named as the odd one out, term by term, like any other derivation;
* :func:`to_mechanics` exports a model in state-space form (``mass_matrix_full``,
  ``forcing_full`` in ``dynamicsymbols``, the constants with their defaults), the inputs of
  PyDy's ``generate_ode_function``; :func:`lagranges_method` builds a ``LagrangesMethod`` from a
  Lagrangian written in the problem's coordinates.

Example
-------
>>> import sympy as sp
>>> import sympy.physics.mechanics as me
>>> from dualmech.problems import get
>>> pendulum = get("simple_pendulum")
>>> th = me.dynamicsymbols("theta"); M, a, g = sp.symbols("M a g")
>>> L = M * a**2 * th.diff()**2 / 2 + M * g * a * sp.cos(th)
>>> lm = me.LagrangesMethod(L, [th]); _ = lm.form_lagranges_equations()
>>> check_mechanics(pendulum, lm).equivalent
True
"""
from __future__ import annotations

import types
from dataclasses import dataclass

import sympy as sp
from sympy.core.function import AppliedUndef

from dualmech.model.equations import Constraint, EquationSet, ModelError
from dualmech.model.kinematics import t as T_DUALMECH

__all__ = ["from_mechanics", "with_derivation", "check_mechanics", "to_mechanics",
           "lagranges_method", "MechanicsForm"]


def _mechanics():
    import sympy.physics.mechanics as me
    return me


def _time():
    return _mechanics().dynamicsymbols._t


def _method_of(model):
    """The ``KanesMethod`` or ``LagrangesMethod`` behind ``model`` (a ``System`` forms its
    equations first when it has not)."""
    me = _mechanics()
    if isinstance(model, me.System):
        if model.eom_method is None:
            model.form_eoms()
        return model.eom_method
    if isinstance(model, (me.KanesMethod, me.LagrangesMethod)):
        return model
    raise TypeError(f"from_mechanics takes a KanesMethod, a LagrangesMethod or a System of "
                    f"sympy.physics.mechanics, got {type(model).__name__}.")


def _refuse_kane(km) -> None:
    """A clear error for the ``KanesMethod`` features the bridge does not read."""
    if getattr(km, "_qdot_u_map", None) is None:
        raise ModelError("the KanesMethod has no kinematic differential equations: build it "
                         "with kd_eqs=[q' - f(u, q), ...] (one per coordinate), so each "
                         "generalised speed can be written through the coordinates' rates.")
    aux = list(getattr(km, "_uaux", None) or [])
    if aux:
        raise ModelError(f"the KanesMethod has auxiliary speeds ({', '.join(map(_speed_name, aux))}"
                         "); they only serve sympy's own constraint-force equations, which the "
                         "bridge does not read: build the model without u_auxiliary (the "
                         "toolkit recovers reactions from a direct model).")


def _speeds_through_rates(km, ignorable: dict) -> tuple[dict, list]:
    """``{u: expression in q', u': its time derivative}`` from the kinematic differential
    equations, with each ``ignorable`` speed the rate of a coordinate the model leaves out (a
    placeholder ``dynamicsymbol`` returned in the list, after the model's own)."""
    tt = _time()
    q, u = list(km.q), list(km.u)
    kd = km.kindiffdict()   # {q': f(u, q)}
    rates = [kd[qi.diff(tt)] - qi.diff(tt) for qi in q]
    by_name = {_speed_name(ui): ui for ui in u}
    extra = []
    for key in ignorable:
        name = key if isinstance(key, str) else _speed_name(key)
        if name not in by_name:
            raise ModelError(f"ignorable speed `{name}` is not a generalised speed of the "
                             f"KanesMethod (it has {', '.join(by_name)}).")
        placeholder = _mechanics().dynamicsymbols(f"_ignorable_{name}")
        rates.append(by_name[name] - placeholder.diff(tt))
        extra.append(placeholder)
    if len(rates) != len(u):
        free = [_speed_name(ui) for ui in u
                if not any(r.has(ui) for r in rates)]
        hint = (f"; speed(s) {', '.join(free)} enter no kinematic differential equation: if "
                "each is the rate of a coordinate the model leaves out (an ignorable one, a "
                f"wheel's angle), pass ignorable={{'{free[0]}': <that coordinate of the "
                "problem>, ...}}" if free else "")
        raise ModelError(f"the KanesMethod has {len(q)} coordinates and {len(u)} generalised "
                         f"speeds{' (with ' + str(len(extra)) + ' ignorable)' if extra else ''}"
                         f": each speed must be fixed by the coordinates' rates{hint}.")
    A, b = sp.linear_eq_to_matrix(rates, u)
    if A.det() == 0:
        raise ModelError("the kinematic differential equations do not determine the "
                         "generalised speeds from the coordinates' rates.")
    rule = {}
    for ui, expr in zip(u, A.LUsolve(b)):
        rule[ui.diff(tt)] = sp.diff(expr, tt)
        rule[ui] = expr
    return rule, extra


def _kane_rows(km, ignorable: dict | None = None) -> tuple[list, list, list, list]:
    """``M u' - f`` with ``u`` and ``u'`` written through the coordinates' rates, its labels,
    the declared constraints ``[(name, level, expression)]`` and the placeholder coordinates
    of the ``ignorable`` speeds.

    With dependent speeds (``u_dependent``, ``velocity_constraints``) sympy's ``mass_matrix``
    and ``forcing`` hold the reduced equations of the independent speeds, then the velocity
    constraints differentiated (acceleration level); the constraints themselves are returned
    at velocity level, and the configuration constraints of dependent coordinates
    (``q_dependent``) at position level, so the verdict samples on their manifold."""
    _refuse_kane(km)
    u = list(km.u)
    try:
        M, f = km.mass_matrix, km.forcing
    except (AttributeError, ValueError, TypeError):
        raise ModelError("the KanesMethod has no equations yet: call "
                         "kanes_equations(bodies, loads) first.") from None
    rule, extra = _speeds_through_rates(km, dict(ignorable or {}))
    rows = [e.xreplace(rule) for e in (M * sp.Matrix(u).diff(_time()) - f)]
    dep = list(getattr(km, "_udep", None) or [])
    k_nh = getattr(km, "_k_nh", None)
    constraints = []
    if dep and k_nh is not None and k_nh.rows:
        velocity = k_nh * sp.Matrix(u) + km._f_nh   # B u + C = 0, sympy's form
        for ud, c in zip(dep, velocity):
            constraints.append((_speed_name(ud), "velocity", c.xreplace(rule)))
    names = [_speed_name(ui) for ui in u[:len(u) - len(constraints)]]
    labels = [f"Kane, {nm}" for nm in names]
    labels += [f"constraint {nm} (acceleration level)" for nm, _, _ in constraints]
    qdep = list(getattr(km, "_qdep", None) or [])
    f_h = getattr(km, "_f_h", None)
    if qdep and f_h is not None:
        constraints = _with_configuration(km, list(f_h), constraints)
    return rows, labels, constraints, extra


def _with_configuration(km, f_h: list, constraints: list) -> list:
    """The velocity constraints with each configuration constraint ``g(q) = 0`` in place of
    the one its rate ``g'`` replaces (``g'`` is a combination of sympy's velocity constraints,
    whose rows are its acceleration level; the one with the largest weight, at a generic point,
    gives up its row), so the verdict draws its points on ``g = 0`` and on the velocity
    constraints.  A ``g`` whose rate is not such a combination is kept without a row (declared,
    not sampled on)."""
    import random
    tt = _time()
    u = list(km.u)
    kd = km.kindiffdict()
    rng = random.Random(0)
    point = {qi: sp.Float(rng.uniform(0.1, 0.5), 30) for qi in km.q}
    free = set().union(*(e.free_symbols for e in list(km._k_nh) + f_h)) - {tt}
    point.update({s: sp.Float(rng.uniform(0.5, 1.5), 30) for s in free})
    B = km._k_nh.xreplace(point).evalf(30)
    out, taken = list(constraints), set()
    for i, g in enumerate(f_h):
        rate = sum((g.diff(qi) * kd[qi.diff(tt)] for qi in km.q), sp.S.Zero)
        G = sp.Matrix([[rate.diff(uj) for uj in u]]).xreplace(point).evalf(30)
        alpha = B.T.solve_least_squares(G.T)
        name = f"configuration {km._qdep[i].func.__name__}"
        if (alpha.T * B - G).norm() > 1e-20 * max(1, G.norm()):
            out.append((name, "position", g, None))
            continue
        k = max((j for j in range(len(alpha)) if j not in taken), key=lambda j: abs(alpha[j]))
        taken.add(k)
        out[k] = (name, "position", g, constraints[k][0])
    return out


def _row_label(c: tuple) -> str:
    """The label of the acceleration-level row of constraint ``(name, level, expression[,
    row])``: the row of ``row`` when given (``None``: no row of its own), else its own."""
    row = c[3] if len(c) > 3 else c[0]
    return "" if row is None else f"constraint {row} (acceleration level)"


def _speed_name(u) -> str:
    return getattr(u, "name", None) or u.func.__name__


def _lagrange_rows(lm) -> tuple[list, list, list]:
    """``M [q''; lambda] - f`` of a ``LagrangesMethod`` (forming its equations if needed), its
    labels and its constraints ``[(name, level, expression)]`` at the level they were given
    (``hol_coneqs`` position, ``nonhol_coneqs`` velocity)."""
    try:
        M, f = lm.mass_matrix, lm.forcing
    except (AttributeError, ValueError, TypeError):
        lm.form_lagranges_equations()
        M, f = lm.mass_matrix, lm.forcing
    q = list(lm.q)
    lam = list(getattr(lm, "lam_vec", []) or [])
    tt = _time()
    x = sp.Matrix([qi.diff(tt, 2) for qi in q] + lam)
    rows = list(M * x - f)
    hol = list(getattr(lm, "_hol_coneqs", None) or [])
    velocity = list(getattr(lm, "coneqs", None) or [])   # hol' and nonhol: velocity level
    if len(rows) == len(q):   # sympy's mass_matrix holds the dynamic rows only
        rows += [sp.expand(c.diff(tt)) for c in velocity]
    labels = [f"Lagrange (mechanics), {qi.func.__name__}" for qi in q]
    labels += [f"constraint {i + 1} (acceleration level)" for i in range(len(rows) - len(q))]
    constraints = []
    if len(velocity) == len(rows) - len(q):   # one acceleration row per constraint, in order
        constraints = [(str(i + 1), "position", hol[i]) if i < len(hol) else
                       (str(i + 1), "velocity", c) for i, c in enumerate(velocity)]
    return rows, labels, constraints


def _by_name(things) -> dict:
    return {getattr(x, "name", None) or x.func.__name__: x for x in things}


def _coordinate_rule(method, mech_q: list, problem, targets: dict) -> tuple[list, dict]:
    """The set's coordinates and ``{q'': ..., q': ..., q: ...}`` taking each of the model's
    coordinates ``mech_q`` to its target: ``targets[name]`` (a coordinate of the problem, its
    name, or an expression in one coordinate such as ``-delta`` for an opposite sign
    convention), else the problem's coordinate of the same name."""
    from dualmech.model.kinematics import coordinate
    tt = _time()
    known = _by_name(c.function for c in problem.all_coordinates()) if problem else {}
    coords, rule = [], {}
    for qi in mech_q:
        qname = qi.func.__name__
        shown = qname.removeprefix("_ignorable_")
        target = targets.get(qname, known.get(qname))
        if isinstance(target, str):
            target = known.get(target) if problem is not None else coordinate(target)
        if target is None:
            if problem is not None:
                what = (f"the coordinate whose rate is ignorable speed `{shown}`"
                        if shown != qname else f"coordinate `{qname}`")
                raise ModelError(f"{what} of the {type(method).__name__} is not a coordinate "
                                 f"of `{problem.name}` (it has {', '.join(known)}); pass "
                                 f"{'ignorable' if shown != qname else 'coordinates'}"
                                 f"={{'{shown}': ...}}.")
            target = coordinate(qname)
        target = sp.sympify(target, strict=True)
        inner = [f for f in target.atoms(AppliedUndef) if f.args == (T_DUALMECH,)]
        if len(inner) != 1 or target.free_symbols - {T_DUALMECH}:
            raise ModelError(f"coordinate `{shown}` is mapped to {target}: give a coordinate "
                             "of the problem, or an expression in exactly one (e.g. -delta) "
                             "with numbers only.")
        if inner[0] in coords:
            raise ModelError(f"two coordinates of the {type(method).__name__} are mapped to "
                             f"`{inner[0].func.__name__}`; each needs its own.")
        coords.append(inner[0])
        rule[qi.diff(tt, 2)] = target.diff(T_DUALMECH, 2)
        rule[qi.diff(tt)] = target.diff(T_DUALMECH)
        rule[qi] = target
    return coords, rule


def from_mechanics(model, problem=None, *, name: str = "mechanics", coordinates=None,
                   symbols=None, reactions=None, ignorable: dict | None = None) -> EquationSet:
    """``model`` (``KanesMethod``, ``LagrangesMethod`` or ``System``) as an :class:`EquationSet`.

    Parameters
    ----------
    model : sympy.physics.mechanics KanesMethod, LagrangesMethod or System
        A Kane model with its equations formed (``kanes_equations``), a Lagrange model, or a
        system (its equations are formed when they are not).
    problem : Problem, optional
        Whose coordinates (``theta(t)`` of ``dynamicsymbols("theta")``) and parameters (``m``)
        the model's are matched with, by name.
    name : str
        The derivation's name (``"mechanics"``).
    coordinates, symbols : dict, optional
        Explicit matches ``{model's object or its name: problem's object}`` where the names
        differ (``{"q1": theta}``, ``{"l": R}``).
        A target may be an expression in one coordinate of the problem, for an opposite
        sign convention (``{"q5": -delta}``).
    reactions : dict, optional
        ``{multiplier or its name: reaction name}`` for a Lagrange model with constraints.
    ignorable : dict, optional
        ``{speed or its name: problem's coordinate}`` for a Kane model's speeds that enter no
        kinematic differential equation because the model leaves their coordinate out (an
        ignorable one, a wheel's angle): each such speed is that coordinate's rate.

    Raises
    ------
    ModelError
        Naming what cannot be matched.
    """
    method = _method_of(model)
    me = _mechanics()
    if isinstance(method, me.KanesMethod):
        rows, labels, constraints, extra = _kane_rows(method, ignorable)
    elif ignorable:
        raise ModelError("`ignorable` names speeds of a KanesMethod; a LagrangesMethod has "
                         "none (give every coordinate to it instead).")
    else:
        (rows, labels, constraints), extra = _lagrange_rows(method), []
    tt = _time()
    mech_q = list(method.q) + extra
    targets = {**{(k if isinstance(k, str) else k.func.__name__): v
                  for k, v in (coordinates or {}).items()},
               **{f"_ignorable_{k if isinstance(k, str) else _speed_name(k)}": v
                  for k, v in (ignorable or {}).items()}}
    coords, rule = _coordinate_rule(method, mech_q, problem, targets)
    def _name(x) -> str:
        return x if isinstance(x, str) else (getattr(x, "name", None) or x.func.__name__)

    lam_names = {_name(k): v for k, v in (reactions or {}).items()}
    unknowns = []
    for lam in list(getattr(method, "lam_vec", []) or []):   # lam1(t), ...: the multipliers
        target = sp.Symbol(str(lam_names.get(_name(lam), _name(lam))), real=True)
        rule[lam] = target
        unknowns.append(target)
    stray = {f for r in rows + [c[2] for c in constraints] for f in r.atoms(AppliedUndef)} \
        - set(rule)
    if stray:
        raise ModelError(f"the {type(method).__name__} uses functions of time that are not its "
                         f"coordinates: {', '.join(sorted(map(str, stray)))}; specified inputs "
                         "are not supported (write them as functions of t).")
    free = set().union(*(r.free_symbols for r in rows + [c[2] for c in constraints])) - {tt}
    params = _by_name(problem.parameter_symbols) if problem is not None else {}
    explicit_s = {_name(k): v for k, v in (symbols or {}).items()}
    missing = []
    for s in free:
        target = explicit_s.get(s.name, params.get(s.name))
        if target is not None:
            rule[s] = target
        elif problem is not None:
            missing.append(s.name)
    if missing:
        raise ModelError(f"symbol(s) {', '.join(sorted(missing))} of the "
                         f"{type(method).__name__} are not parameters of `{problem.name}` (it "
                         f"has {', '.join(params)}); pass symbols={{'{sorted(missing)[0]}': "
                         "...} naming the problem's symbol it stands for, or declare it as a "
                         "parameter of the problem.")
    rule[tt] = T_DUALMECH
    equations = tuple(r.xreplace(rule) for r in rows)
    declared = tuple(Constraint(c[0], c[1], c[2].xreplace(rule), _row_label(c))
                     for c in constraints)
    return EquationSet(name, tuple(coords), equations,
                       unknowns=tuple(unknowns),
                       labels=tuple(labels), description=f"{type(method).__name__} of "
                       "sympy.physics.mechanics", constraints=declared)


def with_derivation(problem, equations: EquationSet, coordinate_map: dict | None = None):
    """``problem`` with ``equations`` as one more model (named ``equations.name``); the models
    already derived are kept.  ``coordinate_map`` (``{its q: expression in the reference
    coordinates}``) is needed when the set uses other coordinates."""
    name = equations.name
    if name in problem.model_names:
        raise ValueError(f"problem `{problem.name}` already has a model {name!r}; give the new "
                         "derivation another name.")
    cls = type(problem)

    def coordinate_maps(self):
        maps = dict(cls.coordinate_maps(self))
        if coordinate_map is not None:
            maps[name] = coordinate_map
        return maps

    sub = types.new_class(cls.__name__, (cls,), {}, lambda ns: ns.update(
        {"extra_models": tuple(cls.extra_models) + (name,), name: lambda self: equations,
         "coordinate_maps": coordinate_maps, "__module__": cls.__module__,
         "__qualname__": cls.__qualname__, "__doc__": cls.__doc__}))
    new = object.__new__(sub)
    new.__dict__.update({k: v for k, v in problem.__dict__.items()
                         if k not in ("_models", "_mapped")})
    new.__dict__["_models"] = {**problem.models(), name: equations}
    return new


def check_mechanics(problem, model, *, points: int = 8, seed: int = 0, **match):
    """Compare ``model`` (a sympy.physics.mechanics model) with every derivation of ``problem``,
    exactly; ``match`` goes to :func:`from_mechanics` (``name``, ``coordinates``, ...)."""
    from dualmech.verify.check import compare
    eqs = from_mechanics(model, problem, **match)
    return compare(with_derivation(problem, eqs), points=points, seed=seed)


@dataclass(frozen=True)
class MechanicsForm:
    """A model in sympy.physics.mechanics' state-space form, ``M_full x' = f_full`` for
    ``x = [q; u]`` with ``u = q'``: what PyDy's ``generate_ode_function(forcing_full, q, u,
    constants, mass_matrix=mass_matrix_full)`` takes."""

    q: tuple
    u: tuple
    mass_matrix_full: sp.Matrix
    forcing_full: sp.Matrix
    constants: dict

    def rhs(self) -> sp.Matrix:
        """``x'`` solved symbolically (small models only)."""
        return self.mass_matrix_full.LUsolve(self.forcing_full)


def to_mechanics(problem, model: str | None = None) -> MechanicsForm:
    """``problem``'s model (default: its reference) in ``dynamicsymbols`` named after the
    coordinates (``u_theta`` for the rate of ``theta``), in state-space form.

    >>> from dualmech.problems import get
    >>> form = to_mechanics(get("simple_pendulum"))
    >>> form.q, form.u
    ((theta(t),), (u_theta(t),))
    >>> form.forcing_full.T
    Matrix([[u_theta(t), -M*a*g*sin(theta(t))]])
    """
    me = _mechanics()
    eqs = problem.model(model or problem.reference)
    if eqs.unknowns or not eqs.is_square:
        raise ModelError(f"model `{eqs.name}` of `{problem.name}` has unknown reactions "
                         f"({', '.join(map(str, eqs.unknowns))}); export a model without "
                         f"them, e.g. its reference `{problem.reference}`.")
    tt = _time()
    q = tuple(me.dynamicsymbols(c.func.__name__) for c in eqs.coordinates)
    u = tuple(me.dynamicsymbols(f"u_{c.func.__name__}") for c in eqs.coordinates)
    rule = {T_DUALMECH: tt}
    for c, qi, ui in zip(eqs.coordinates, q, u):
        rule[c.diff(T_DUALMECH)] = ui
        rule[c] = qi
    n = len(q)
    M = eqs.mass_matrix().xreplace(rule)
    f = eqs.forcing().xreplace(rule)
    full = sp.zeros(2 * n, 2 * n)
    full[:n, :n] = sp.eye(n)
    full[n:, n:] = M
    return MechanicsForm(q, u, full, sp.Matrix(list(u) + list(f)),
                         {p.symbol: p.default for p in problem.parameters})


def lagranges_method(problem, lagrangian, forcelist=None, frame=None):
    """A ``LagrangesMethod`` of the Lagrangian ``lagrangian`` written in ``problem``'s
    coordinates (``theta(t)`` made by :func:`dualmech.coordinate`), in ``dynamicsymbols``;
    ``forcelist`` and ``frame`` go to ``LagrangesMethod`` unchanged."""
    me = _mechanics()
    tt = _time()
    coords = [c.function for c in problem.coordinates]
    q = [me.dynamicsymbols(c.func.__name__) for c in coords]
    rule = {T_DUALMECH: tt}
    for c, qi in zip(coords, q):
        rule[c.diff(T_DUALMECH)] = qi.diff(tt)
        rule[c] = qi
    if isinstance(lagrangian, str):
        raise TypeError("`lagrangian` must be a sympy expression built from the problem's "
                        "coordinates, not text (text is never evaluated).")
    L = sp.sympify(lagrangian, strict=True).xreplace(rule)
    return me.LagrangesMethod(L, q, forcelist=forcelist, frame=frame)
