"""Every way a problem's models can be integrated: ODE forms and DAE forms, side by side.

A **formulation** is one model of a problem made into ``y' = f(t, y)``:

* ``ode`` -- a square model (the Lagrangian in minimal coordinates, or a direct model whose
  reactions are unknowns next to the accelerations): ``A [q''; lambda] = b`` solved at each
  call;
* ``dae`` -- a model in maximal coordinates with constraints (a multiplier model, or a direct
  model in the same coordinates completed by the multiplier model's constraints), as an
  index-1 DAE, unstabilised, with Baumgarte stabilisation (gains swept with
  ``baumgarte_gains``) or with projection after every accepted step
  (:class:`~dualmech.numeric.dae.ConstrainedModel`, :mod:`~dualmech.numeric.stepping`);
  or as the index-3 DAE or Gear-Gupta-Leimkuhler's stabilised index-2 form solved by IDA
  (:mod:`~dualmech.numeric.daesolve`, method ``"IDA"``).  Constraints are taken at the level
  they are declared: a model whose constraints are all velocity-level (rolling) has an
  index-2 DAE (``"DAE, index 2"``, under ``"ggl"``) and no index-3 form; a model with static
  rows of a massless part has its index-1 forms only.  A form a model cannot take is
  listed with the reason, as ``"model (form)"``, among the skipped.

Each formulation starts from the problem's initial state mapped into its own coordinates
(:meth:`Problem.coordinate_maps <dualmech.model.problem.Problem.coordinate_maps>`) and can map any
reference trajectory the same way, so all of them are compared in their own coordinates
against one reference motion.  Reactions come from the formulation itself when it has them
(direct models, multipliers), else from the problem's direct models at its states.

Example
-------
>>> from dualmech.problems import get
>>> [f.name for f in formulations(get("pendulum_particle"))[0]][:3]
['lagrange', 'newton_euler', 'newton_euler_inertial (DAE, index 1)']
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Mapping, Sequence

import numpy as np

from dualmech.model._expr import as_expr
from dualmech.model.equations import EquationSet, ModelError, state_symbols
from dualmech.model.kinematics import t
from dualmech.numeric.dae import (STABILISATIONS, ConstrainedModel, Constraints, constraints_of,
                                  dae_refusal)
from dualmech.numeric.daesolve import DAE_FORMS, IDASolver
from dualmech.numeric.energy import (EnergyFunction, conservative_reason, dynamic_rows,
                                     identically_zero)
from dualmech.numeric.integrators import SYMPLECTIC, WorkBudget, Run, integrate
from dualmech.numeric.model import NumericModel, StateFunction
from dualmech.numeric.simulation import default_initial_state, problem_parameters
from dualmech.numeric.stepping import projected_run

__all__ = ["Formulation", "formulations", "state_scales", "outside_parameters",
           "static_coordinates", "with_static_rows", "dae_refusal"]

_LABEL = {"none": "DAE, index 1", "baumgarte": "DAE, Baumgarte", "projection": "DAE, projection",
          "index3": "DAE, index 3", "ggl": "DAE, GGL index 2"}


@dataclass
class Formulation:
    """One integrable form of a problem (see the module docstring).

    ``coordinates`` are its ``q(t)``; ``y0`` its initial state; ``scales`` the width of each
    coordinate's and rate's declared range (the unit of the state errors).
    """

    name: str
    kind: str
    model: EquationSet
    rhs: Callable
    y0: np.ndarray
    scales: np.ndarray
    mapping: StateFunction
    reaction_names: tuple = ()
    constrained: ConstrainedModel | None = None
    energy: EnergyFunction | None = None
    energy_note: str = ""
    _solve: Callable | None = field(default=None, repr=False)
    _outside: Callable | None = field(default=None, repr=False)
    dae_solver: IDASolver | None = field(default=None, repr=False)
    numeric: NumericModel | None = field(default=None, repr=False)
    #: ``""`` when the motion is the free Hamiltonian flow of ``energy`` (a symplectic rule
    #: may integrate it), else why not: the energy's model holds constraints, which the
    #: symplectic rules of :mod:`~dualmech.numeric.symplectic` would not keep
    not_free_flow: str = ""

    @property
    def backend(self) -> str:
        """Where its generated code runs: ``"C"`` or ``"NumPy"`` (IDA's residual: ``"C"``,
        or ``"Python"`` on its fallback)."""
        if self.dae_solver is not None:
            return self.dae_solver.route
        if self.numeric is None:
            return ""
        return "C" if self.numeric.compiled else "NumPy"

    @property
    def coordinates(self) -> tuple:
        return self.model.coordinates

    @property
    def n(self) -> int:
        return self.model.n

    @property
    def stabilisation(self) -> str:
        return self.constrained.stabilisation if self.constrained else ""

    def from_reference(self, time, q, qd) -> np.ndarray:
        """A reference trajectory (states in columns) in this formulation's coordinates."""
        return self.mapping(time, q, qd)

    def reactions(self, time, y: np.ndarray) -> dict:
        """``{name: (K,)}`` along states ``y`` (``(2n, K)``)."""
        n = self.n
        if self._solve is not None:
            rows = self._solve(time, y[:n], y[n:])[n:]
            return dict(zip(self.reaction_names, rows))
        if self._outside is not None:
            return self._outside(time, y[:n], y[n:])
        return {}

    def drift(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
        """``(g, g')`` along states ``y`` for a DAE form, else ``None``."""
        if self.constrained is None:
            return None
        return self.constrained.residuals(y[: self.n], y[self.n:])

    def energy_change(self, y: np.ndarray) -> np.ndarray | None:
        """``E(t) - E(t0)`` along states ``y`` when the model conserves energy, else ``None``."""
        if self.energy is None:
            return None
        return self.energy.along(y[: self.n], y[self.n:])

    def methods(self, candidates: Sequence[str]) -> list[str]:
        """The methods of ``candidates`` that can integrate this form (``"IDA"`` for the
        DAE-solved forms, the projectable scipy steppers for projection)."""
        from dualmech.numeric.stepping import PROJECTABLE
        if self.dae_solver is not None:
            return [m for m in candidates if m == "IDA"]
        if self.stabilisation == "projection":
            return [m for m in candidates if m in PROJECTABLE]
        return [m for m in candidates if m != "IDA"]

    def run(self, method: str, t_span, t_eval, rtol: float = 1e-6, step: float | None = None,
            events: Sequence = (), budget: WorkBudget | None = None) -> Run:
        """Integrate from ``y0`` (``atol = rtol * scales``; projection after every accepted
        step for ``"projection"``; IDA for the index-3 and GGL forms); past ``budget`` the
        run ends as *did not finish* (:class:`~dualmech.numeric.integrators.WorkBudget`)."""
        atol = rtol * self.scales
        if method in SYMPLECTIC and self.not_free_flow:
            raise ValueError(f"`{method}` integrates the free Hamiltonian flow of the "
                             f"energy; `{self.name}` is not that flow: {self.not_free_flow}.")
        if self.dae_solver is not None or method == "IDA":
            if self.dae_solver is None or events:
                raise ValueError(f"`{self.name}` is not solved by IDA (no events either); "
                                 f"its methods: {', '.join(self.methods(['RK45', 'DOP853']))}.")
            return self.dae_solver.run(t_span, self.y0, t_eval, rtol=rtol, atol=atol,
                                       budget=budget)
        if self.stabilisation == "projection":
            if events:
                raise ValueError("projection after every step takes no events.")
            return projected_run(self.rhs, t_span, self.y0, method, t_eval, rtol=rtol,
                                 atol=atol, projector=self.constrained.project,
                                 budget=budget)
        return integrate(self.rhs, t_span, self.y0, method, t_eval=t_eval, rtol=rtol,
                         atol=atol, step=step, events=events, hamiltonian=self.energy,
                         budget=budget)


def state_scales(problem, coordinates) -> np.ndarray:
    """Width of each coordinate's and each rate's declared range (``(2n,)``)."""
    infos = [problem.coordinate_info(q) for q in coordinates]
    widths = [c.range[1] - c.range[0] for c in infos]
    rates = [c.rate_range[1] - c.rate_range[0] for c in infos]
    return np.array(widths + rates, dtype=float)


def _mapping(problem, ref: EquationSet, eqs: EquationSet, values) -> StateFunction:
    if set(eqs.coordinates) == set(ref.coordinates):
        exprs = list(eqs.coordinates)
    else:
        maps = problem.coordinate_maps()
        if eqs.name not in maps:
            raise ModelError(f"model `{eqs.name}` has no coordinate map to the reference.")
        exprs = [as_expr(maps[eqs.name][q]) for q in eqs.coordinates]
    return StateFunction(exprs + [e.diff(t) for e in exprs], ref.coordinates, values)


def _energy(problem, eqs: EquationSet, values, q0) -> tuple[EnergyFunction | None, str, str]:
    """The energy of ``eqs``' coordinates from the first conservative model that has them
    (and a positive definite mass matrix at ``q0``: a direct model's rows may be signed),
    why not, and why the motion is not its free flow (:func:`_held_by`)."""
    candidates = [eqs] + [m for m in problem.models().values()
                          if m is not eqs and tuple(m.coordinates) == tuple(eqs.coordinates)]
    reason = ""
    for m in candidates:
        why = conservative_reason(m, values)
        if why is None:
            energy = EnergyFunction(m, values)
            try:
                np.linalg.cholesky(energy.mass_matrix(q0))
                return energy, "", _held_by(m)
            except np.linalg.LinAlgError:
                why = "its mass matrix is not positive definite (signed rows)"
        reason = reason or why
    return None, reason or "no model in these coordinates", ""


def _held_by(m: EquationSet) -> str:
    """Why ``m``'s motion is not the free flow of its energy (``""``: it is)."""
    rows = len(m.equations) - len(dynamic_rows(m))
    if rows or m.constraints:
        return (f"its energy comes from model `{m.name}`, whose motion keeps "
                f"{max(rows, len(m.constraints))} constraint(s)")
    return ""


def _outside_reactions(problem, values) -> Callable:
    """Reactions of the problem's direct models at states in the reference coordinates."""
    direct = [problem.in_reference_coordinates(m) for m in problem.models().values()
              if m.unknowns]
    numeric = [(m, NumericModel(m, values)) for m in direct if m.is_square]

    def reactions(time, q, qd) -> dict:
        out: dict = {}
        for m, nm in numeric:
            for u, row in zip(m.unknowns, nm.solve(time, q, qd)[m.n:]):
                out.setdefault(u.name, row)
        return out
    return reactions


def outside_parameters(problem, params: Mapping) -> dict:
    """The defaults with ``params`` applied by name or symbol, past the declared ranges (for
    studies that leave them on purpose, such as a stiff spring); names are still checked."""
    values = problem_parameters(problem)
    by_name = {s.name: s for s in values}
    for k, v in params.items():
        name = k if isinstance(k, str) else k.name
        if name not in by_name:
            problem_parameters(problem, {k: v})  # raises with the close names suggested
        values[by_name[name]] = float(v)
    return values


def formulations(problem, params: Mapping | None = None, y0=None,
                 stabilisations: Sequence[str] = STABILISATIONS,
                 models: Sequence[str] | None = None,
                 strict: bool = True,
                 baumgarte_gains: Sequence[float] | None = None) -> tuple[list[Formulation], dict]:
    """The problem's formulations and ``{model: why it is not one}`` for the rest.

    ``stabilisations`` choose the DAE forms (:data:`~dualmech.numeric.dae.STABILISATIONS`
    and :data:`~dualmech.numeric.dae.DAE_SOLVED`); ``baumgarte_gains`` (``alpha = beta`` in
    1/s) give one Baumgarte form each, named with its gain (default: one, 5/s, unnamed).

    ``y0`` is the initial state in the reference coordinates (default
    :func:`~dualmech.numeric.simulation.default_initial_state`); ``models`` limits the models.
    The reference model comes first.  ``strict=False`` lets ``params`` leave the declared
    ranges (:func:`outside_parameters`).
    """
    values = problem_parameters(problem, params) if strict else \
        outside_parameters(problem, params or {})
    ref = problem.model(problem.reference)
    if y0 is None:
        q0, qd0 = default_initial_state(problem)
        y0 = q0 + qd0
    y0 = np.asarray(y0, dtype=float)
    n = ref.n
    names = [problem.reference] + [m for m in problem.models() if m != problem.reference]
    if models is not None:
        names = [m for m in names if m in models]
    out, skipped = [], {}
    for name in names:
        eqs = problem.model(name)
        try:
            forms, refused = _forms(problem, ref, eqs, values, y0, n, stabilisations,
                                    baumgarte_gains)
        except (ModelError, ValueError, NotImplementedError, ZeroDivisionError) as exc:
            skipped[name] = str(exc)
            continue
        out.extend(forms)
        skipped.update(refused)
    return out, skipped


def _forms(problem, ref, eqs, values, y0, n, stabilisations,
           gains) -> tuple[list[Formulation], dict]:
    """The forms of one model and ``{form: why not}`` for the DAE forms it cannot take."""
    mapping = _mapping(problem, ref, eqs, values)
    y_own = mapping(0.0, y0[:n], y0[n:])
    scales = state_scales(problem, eqs.coordinates)
    energy, note, held = _energy(problem, eqs, values, y_own[: eqs.n])
    constraint_rows = len(eqs.equations) - len(dynamic_rows(eqs))
    square = len(eqs.equations) == eqs.n + len(eqs.unknowns)
    # a direct form's declared rolling rows beside reactions that are not their multipliers
    # (the disk's F_z keeps no constraint): its square system is solved as an ODE, as before
    # the rolling was declared; a multiplier per constraint row makes it a DAE
    unpaired = constraint_rows and constraint_rows != len(eqs.unknowns)
    if square and (not constraint_rows or unpaired) and not static_coordinates(eqs):
        nm = NumericModel(eqs, values)
        own = bool(eqs.unknowns)
        in_ref = tuple(eqs.coordinates) == tuple(ref.coordinates)
        return [Formulation(eqs.name, "ode", eqs, nm.rhs, y_own, scales, mapping,
                            tuple(u.name for u in eqs.unknowns), None, energy, note,
                            nm.solve if own else None,
                            _outside_reactions(problem, values) if in_ref and not own
                            else None, None, nm, held)], {}
    if square:
        constraints = constraints_of(eqs) if constraint_rows else None
    elif len(eqs.equations) < eqs.n + len(eqs.unknowns):
        constraints = _borrowed_constraints(problem, eqs)
    else:
        raise ModelError(f"model `{eqs.name}` has more equations than unknowns.")
    constraints = with_static_rows(eqs, constraints)
    out, refused = [], {}
    for stab in stabilisations:
        why = dae_refusal(stab, constraints)
        if why:
            refused[f"{eqs.name} ({_LABEL[stab]})"] = why
            continue
        for gain in (gains or (None,)) if stab == "baumgarte" else (None,):
            extra = {} if gain is None else {"alpha": gain, "beta": gain}
            cm = ConstrainedModel(eqs, values, constraints, anchor=y_own[: eqs.n],
                                  stabilisation=stab, **extra)
            start = _consistent(cm, y_own)
            solver, label = _ida(cm, stab)
            label += "" if gain is None else f" {gain:g}/s"
            out.append(Formulation(f"{eqs.name} ({label})", "dae", eqs, cm.rhs, start,
                                   scales, mapping, cm.reaction_names, cm, energy, note,
                                   cm.numeric.solve, None, solver, cm.numeric,
                                   f"a DAE form, whose motion keeps {cm.k} constraint(s)"))
    return out, refused


def _ida(cm: ConstrainedModel, stab: str) -> tuple[IDASolver | None, str]:
    """IDA's solver of a DAE-solved form and its label.  Every constraint at velocity level:
    the DAE as written is index 2 and GGL adds nothing to it (no position level to hold),
    so ``"ggl"`` is IDA's ``"index3"`` residual with the velocity rows as the invariant."""
    if stab not in DAE_FORMS:
        return None, _LABEL[stab]
    if stab == "ggl" and "position" not in cm.constraints.levels:
        return IDASolver(cm, "index3"), "DAE, index 2"
    return IDASolver(cm, stab), _LABEL[stab]


def _consistent(cm: ConstrainedModel, y: np.ndarray) -> np.ndarray:
    """``y`` itself, or projected onto the manifold when the model has static balances or
    velocity-level constraints: their initial values are not the problem's to choose (a
    massless part sits where its balance puts it; the rates must roll), and projection in
    the kinetic-energy metric moves only what carries no inertia or violates a constraint."""
    if not cm.constraints.has_velocity_level and \
            all(r is None for r in cm.constraints.static_rows):
        return y
    return cm.project(0.0, np.asarray(y, dtype=float))


def static_coordinates(eqs: EquationSet, constraints=None) -> list:
    """The coordinates whose acceleration no equation holds (nor a constraint): a massless
    part's, whose rows are static balances -- the model is then a DAE in them, not an ODE.

    Decided exactly (a column of ``A [q''; unknowns] = b`` identically zero).

    >>> from dualmech.problems import get
    >>> static_coordinates(get("copying_machine").model("lagrange"))
    [theta(t)]
    """
    A, _ = eqs.plain_matrix()
    held = set()
    if constraints is not None:
        for row in constraints.gradients:
            held |= {j for j, d in enumerate(row) if d != 0}
    out = []
    for j, q in enumerate(eqs.coordinates):
        column = [A[i, j] for i in range(A.rows)]
        symbols = sorted(set().union(*[e.free_symbols for e in column]), key=lambda x: x.name)
        if j not in held and identically_zero(column, symbols):
            out.append(q)
    return out


def with_static_rows(eqs: EquationSet, constraints=None):
    """``constraints`` completed by the static balances of ``eqs``' massless parts.

    A coordinate whose acceleration no equation holds (:func:`static_coordinates`) is fixed
    by the rows that hold neither an acceleration nor a reaction -- static balances
    ``s(q) = 0`` (or ``s(q, q') = 0`` with a damper on the part): they become constraints
    held by no multiplier, at position (velocity) level, whose acceleration-level rows
    replace them in the index-1 system (:func:`~dualmech.numeric.dae.index1_equations`).
    Raises :class:`ModelError` when they do not hold every static coordinate.

    >>> from dualmech.problems import get
    >>> c = with_static_rows(get("copying_machine").model("lagrange"))
    >>> c.levels, c.static_rows, c.multipliers, c.names()
    (('position',), (1,), (None,), ['[Lagrange, theta]'])
    """
    static = static_coordinates(eqs, constraints)
    if not static:
        return constraints
    A, _ = eqs.plain_matrix()
    symbols = sorted(set().union(*[e.free_symbols for e in A]), key=lambda x: x.name)
    rows = [i for i in dynamic_rows(eqs)
            if identically_zero([A[i, j] for j in range(A.cols)], symbols)]
    exprs, levels = [], []
    for i in rows:
        e = eqs.equations[i]
        plain = eqs.to_plain(e)
        if t in plain.free_symbols:
            raise ModelError(f"model `{eqs.name}`, static row [{eqs.labels[i]}] depends on "
                             "time; a static balance held as a constraint must not (the "
                             "DAE forms take time-independent static rows).")
        rates = [state_symbols(q).qd for q in eqs.coordinates]
        exprs.append(e)
        levels.append("velocity" if plain.has(*rates) else "position")
    base = constraints or Constraints(eqs.coordinates, (), ())
    out = Constraints(eqs.coordinates, base.multipliers + (None,) * len(rows),
                      base.expressions + tuple(exprs), base.levels + tuple(levels),
                      base.static_rows + tuple(rows),
                      base.labels + tuple(eqs.labels[i] for i in rows))
    left = static_coordinates(eqs, out)
    if left:
        names = ", ".join(str(q).replace("(t)", "") for q in left)
        raise ModelError(
            f"model `{eqs.name}` is a differential-algebraic system: no equation holds the "
            f"acceleration of {names} (a massless part), and no static row (one holding no "
            "acceleration and no reaction) fixes it either, so neither an ODE integrator nor "
            "the DAE forms can integrate it; eliminate the static coordinate(s) through "
            "their static rows in a model of its own (fewer coordinates), or give the part a "
            "mass.")
    return out


def _borrowed_constraints(problem, eqs: EquationSet):
    """The constraints of a multiplier model in ``eqs``' coordinates holding its reactions."""
    names = {u.name for u in eqs.unknowns}
    for other in problem.models().values():
        if other is eqs or tuple(other.coordinates) != tuple(eqs.coordinates):
            continue
        try:
            c = constraints_of(other)
        except ModelError:
            continue
        if {u.name for u in c.multipliers} == names:
            order = {u.name: i for i, u in enumerate(c.multipliers)}
            idx = [order[u.name] for u in eqs.unknowns]
            return type(c)(c.coordinates, tuple(eqs.unknowns),
                           tuple(c.expressions[i] for i in idx),
                           tuple(c.levels[i] for i in idx))
    raise ModelError(f"model `{eqs.name}` has fewer equations than unknowns and no multiplier "
                     "model in its coordinates supplies the constraints.")
