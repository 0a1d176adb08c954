"""Model no more than a scene needs: fidelity ladders and what each simplification buys and costs.

A **ladder** is a list of models of one scene, from the simplest to the richest:

* linear against nonlinear -- the small-oscillation model about a stable equilibrium (the
  Jacobian of the richest model there) below the nonlinear model, for every problem that has
  one;
* the rungs a problem declares (``fidelity_ladder = (FidelityRung(...), ...)``, simplest
  first, :class:`~dualmech.model.facts.FidelityRung`): point masses on massless rods below
  uniform rods, a simplified model that neglects a reaction below the detailed one, a
  source's own model below the richer variant the catalogue adds to it.

A scene **driven by given inputs** (``Problem.inputs``) has a ladder when it declares the
inputs' history for the study, ``fidelity_inputs = {"F": F0 * sp.sin(w * t)}``: every rung
then runs driven by that history from the same initial state, and the linearised rung is
the small-motion model about the equilibrium without inputs, forced by the same history
(``y' = J (y - y_eq) + B u(t)``, with ``B u(t)`` the richest model's response to the input
at the equilibrium, exact since a load enters the equations linearly).

For each rung, :func:`ladder` measures its **derivation time** (building its equations from a
fresh problem instance), its **right-hand-side cost** (CPU per call of the generated code at
states of the standard trajectory) and its **error against the richest model** along a
standard trajectory (the richest problem's initial state over a span that fits its scene),
each coordinate's error divided by the width of its declared range -- and names the reactions
a rung neglects, with their size along that trajectory.

Example
-------
>>> from dualmech.problems import get
>>> lad = ladder(get("simple_pendulum"), duration=1.0)
>>> [(r.label, r.error_path > 0) for r in lad.rungs]
[('linearised (small oscillations about [0.0])', True), ('nonlinear', False)]
"""
from __future__ import annotations

import copy
import json
import re
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np
import sympy as sp

from dualmech.model._expr import dotted
from dualmech.model.facts import not_declared
from dualmech.model.kinematics import t as _t
from dualmech.model.notation import mathtext
from dualmech.numeric.charts import conditions
from dualmech.numeric.contacts import scene_span
from dualmech.numeric.formulations import formulations
from dualmech.numeric.integrators import integrate
from dualmech.numeric.model import NumericModel, SingularityError
from dualmech.numeric.studies.regimes import stable_equilibrium, jacobian
from dualmech.numeric.simulation import default_initial_state, direct_models, problem_parameters

__all__ = ["Rung", "Ladder", "ladder", "has_ladder", "not_applicable", "NO_LADDER",
           "NO_DRIVE"]

#: What ``dualmech fidelity`` says of a problem with no declared ladder and no equilibrium.
NO_LADDER = not_declared("fidelity ladder", "fidelity_ladder = (FidelityRung(label, simpler "
                         "problem, what it neglects), FidelityRung(label, this problem))")


#: What ``dualmech fidelity`` says of a driven problem with no history for the study.
NO_DRIVE = ("declare the history the study drives the scene with, an expression of t "
            "(from dualmech) and the parameters for each input, e.g. "
            "`fidelity_inputs = {{{example}}}`: every rung then runs driven by it from the "
            "initial state")


@dataclass
class Rung:
    """One model of the ladder and what it costs and misses."""

    label: str
    problem: str
    model: str
    derivation_s: float
    rhs_us: float
    error_final: float
    error_path: float
    neglects: str = ""
    neglected: dict = field(default_factory=dict)
    by_coordinate: dict = field(default_factory=dict)
    times: list = field(default_factory=list, repr=False)
    error_curve: list = field(default_factory=list, repr=False)


@dataclass
class Ladder:
    """Rungs simplest first; the last is the richest (its errors are zero by definition);
    ``conditions`` the scene's parameters and start, written under the chart."""

    scene: str
    span: tuple
    span_note: str
    rungs: list
    conditions: str = ""     # the scene's parameters and start (the chart's caption)
    inputs: dict = field(default_factory=dict)   # {input: its declared history}, if driven

    def __str__(self) -> str:
        driven = ", ".join(f"{k}(t) = {v}" for k, v in self.inputs.items())
        head = (f"fidelity ladder of {self.scene}, t in [{self.span[0]:g}, {self.span[1]:.3g}] s"
                + (f" ({self.span_note})" if self.span_note else "")
                + (f", driven by {driven}" if driven else "") + "; errors relative "
                "to each coordinate's declared range, against the richest rung")
        rows = [("rung", "model", "derivation [s]", "RHS [us/call]", "error at end",
                 "max error", "neglects")]
        for r in self.rungs:
            miss = r.neglects
            if r.neglected:
                miss += " (" + ", ".join(f"max |{k}| = {v:.4g} N" for k, v in
                                         r.neglected.items()) + ")"
            rows.append((r.label, f"{r.problem}.{r.model}", f"{r.derivation_s:.3f}",
                         f"{r.rhs_us:.1f}", f"{r.error_final:.3g}", f"{r.error_path:.3g}",
                         miss or "-"))
        widths = [max(len(str(row[i])) for row in rows) for i in range(len(rows[0]))]
        lines = [head] + ["  " + "  ".join(str(c).ljust(w) for c, w in zip(row, widths))
                          .rstrip() for row in rows]
        return "\n".join(lines)

    def to_dict(self) -> dict:
        return {"scene": self.scene, "span": list(self.span), "span_note": self.span_note,
                "inputs": dict(self.inputs), "rungs": [{k: v for k, v in asdict(r).items()
                           if k not in ("times", "error_curve")} for r in self.rungs]}

    def write(self, out_dir: Path) -> list[Path]:
        from dualmech.numeric.charts import panels, save
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        stem = out_dir / f"{self.scene}_fidelity"
        stem.with_suffix(".json").write_text(json.dumps(self.to_dict(), indent=1) + "\n")
        fig, (ax,) = panels(1, f"{self.scene}: each rung against the richest model",
                            height=3.4)
        for r in self.rungs[:-1]:
            ax.plot(r.times, np.maximum(r.error_curve, 1e-17), label=_legend(r))
        ax.set_yscale("log")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("state error [relative to range]")
        ax.legend(fontsize="small")
        return [stem.with_suffix(".json")] + save(fig, stem, caption=self.conditions)


def _legend(rung: Rung) -> str:
    """The rung's label for the chart, each reaction it neglects named as a symbol (the
    label's ``H`` as :math:`H`, :func:`~dualmech.model.notation.mathtext`)."""
    label = rung.label.replace("$", r"\$")
    for name in rung.neglected:
        label = re.sub(rf"(?<![\w$\\{{]){re.escape(name)}(?![\w$}}])",
                       lambda _m, n=name: mathtext(n), label)
    return label


def has_ladder(problem) -> bool:
    """Whether :func:`ladder` has something to compare for ``problem``."""
    if problem.input_symbols and not _declared_drive(problem):
        return False
    if problem.fidelity_ladder:
        return True
    try:
        free = _free(problem)
        f = formulations(free, models=[free.reference], stabilisations=())[0][0]
        stable_equilibrium(free, f)
        return True
    except (ValueError, IndexError):
        return False


def not_applicable(problem) -> str | None:
    """Why :func:`ladder` has nothing to compare for ``problem``, with the declaration that
    would make it applicable; ``None`` when it applies.

    An equilibrium that lies on the singular set of the reference model's coordinates (the
    spherical pendulum hanging down, at ``sin(theta) = 0``) is named as such: it exists, but
    these coordinates cannot linearise the motion about it.

    A problem driven by given inputs needs their history for the study
    (``fidelity_inputs``, else each input's default history); its equilibrium is sought
    without inputs.

    >>> from dualmech.problems import get
    >>> not_applicable(get("simple_pendulum")) is None
    True
    """
    driven = [str(x) for x in problem.input_symbols]
    if driven and not _declared_drive(problem):
        example = ", ".join(f'"{x}": {x}0 * sp.sin(w * t)' for x in driven)
        return (f"it is driven by given inputs ({', '.join(driven)}) and declares no history "
                "of them for the study; " + NO_DRIVE.format(example=example) + ".")
    if problem.fidelity_ladder:
        return None
    problem = _free(problem)
    made, skipped = formulations(problem, models=[problem.reference], stabilisations=())
    if not made:
        return (f"its reference model `{problem.reference}` cannot be integrated "
                f"({'; '.join(skipped.values())}), and {NO_LADDER}.")
    f = made[0]
    try:
        stable_equilibrium(problem, f)
        return None
    except ValueError as exc:
        why = str(exc)
    at = _singular_equilibrium(problem, f)
    if at is None:
        return f"no stable equilibrium to linearise about ({why}), and {NO_LADDER}."
    state = ", ".join(f"{q.func.__name__} = {v:.6g}" for q, v in zip(f.coordinates, at))
    declared = [dotted(e) for e in problem.singular
                if _vanishes(problem, e, f.coordinates, at)]
    where = (f"on the declared singular set ({', '.join(d + ' = 0' for d in declared)})"
             if declared else "where the reference model is singular (declare that set: "
             "`singular = (...)`)")
    return (f"its equilibrium at rest, {state}, lies {where}: the coordinates of "
            f"`{problem.reference}` cannot describe the motion there, so no linearised model "
            "about it can be made in them.  To make the ladder applicable, declare it: "
            "`fidelity_ladder = (FidelityRung(label, the scene in coordinates regular at "
            "that equilibrium, what it neglects), FidelityRung(label, this problem))`, or "
            "give the scene an equilibrium off that set (its parameters, ranges or "
            "`initial_state`).")


def _singular_equilibrium(problem, f, steps=(1e-2, 1e-5)) -> np.ndarray | None:
    """A state at rest on the singular set of ``f``'s coordinates that is an equilibrium --
    the accelerations shrink to zero as it is approached from every side -- tried at
    ``q = 0``, the initial state and the middle of the declared ranges; else None."""
    n = f.n
    mids = [np.mean(problem.coordinate_info(q).range) for q in f.coordinates]
    directions = np.random.default_rng(0).normal(size=(4, n))
    directions /= np.linalg.norm(directions, axis=1)[:, None]

    def acc(q):
        return f.rhs(0.0, np.concatenate([q, np.zeros(n)]))[n:]
    for guess in (np.zeros(n), f.y0[:n], np.array(mids)):
        try:
            acc(guess)
            continue                        # regular here: not on the singular set
        except SingularityError:
            pass
        try:
            far, near = ([np.abs(acc(guess + h * d)).max() for d in directions]
                         for h in steps)
        except (SingularityError, ValueError, ArithmeticError):
            continue
        if max(near) <= 1e-2 * max(max(far), 1e-300) or max(near) < 1e-9:
            return guess
    return None


def _vanishes(problem, expr, coordinates, at) -> bool:
    """Whether the singular-set expression ``expr`` is zero at the state ``at``."""
    values = dict(problem_parameters(problem))
    values.update({q: float(v) for q, v in zip(coordinates, at)})
    try:
        return abs(complex(expr.subs(values).evalf())) < 1e-9
    except (TypeError, ValueError):
        return False


def _derive(factory: Callable, model: str | None):
    """A fresh problem and the CPU seconds its model ``model`` (default: the reference) takes
    to derive -- that model's method alone, not the problem's other models."""
    p = factory()
    name = model or p.reference
    start = time.process_time()
    eqs = getattr(p, name)()
    return p, eqs, time.process_time() - start


def _rhs_cost(rhs: Callable, states: np.ndarray, times: np.ndarray,
              calls: int = 2000) -> float:
    """CPU microseconds per call of ``rhs`` on one state, cycling through ``states`` (at
    their ``times``)."""
    cols = [states[:, j].copy() for j in range(states.shape[1])]
    start = time.process_time()
    for i in range(calls):
        j = i % len(cols)
        rhs(float(times[j]), cols[j])
    return 1e6 * (time.process_time() - start) / calls


def ladder(problem, duration: float = 5.0, rtol: float = 1e-10, samples: int = 201) -> Ladder:
    """The fidelity ladder of ``problem``'s scene (see the module docstring)."""
    spec = [(r.label, r.problem, r.neglects, r.neglected_reactions)
            for r in problem.fidelity_ladder] or [("nonlinear", lambda: type(problem)(), "", ())]
    richest_label, richest_factory, _, _ = spec[-1]
    fresh, top_eqs, top_time = _derive(richest_factory, None)
    # the numbers use the given problem when it is the richest (its models may be built)
    top = problem if problem.name == fresh.name and \
        getattr(problem, "n", None) == getattr(fresh, "n", None) else fresh
    drive = _drive(top)
    scene_problem = _driven(top, drive)
    q0, qd0 = default_initial_state(top)
    y0 = np.array(q0 + qd0, dtype=float)
    scene = scene_span(scene_problem, duration, y0)
    te = np.linspace(scene.t0, scene.t_end, samples)
    ref = formulations(scene_problem, y0=y0, models=[top.reference], stabilisations=())[0][0]
    truth = integrate(ref.rhs, (te[0], te[-1]), y0, "DOP853", t_eval=te, rtol=rtol,
                      atol=rtol * ref.scales)
    truth_reactions = _reactions(scene_problem, truth.y, truth.t)
    rungs = []
    entries = list(spec[:-1])
    linear = _linear_entry(top, ref, y0, drive, (te[0], te[-1]))
    if linear is not None:
        entries.insert(0, linear)
    for label, factory, neglects, dropped in entries + [(richest_label, None, "", ())]:
        if factory is None:
            p, eqs, secs, rhs = top, top_eqs, top_time, ref.rhs
        elif isinstance(factory, tuple):
            p, eqs, rhs, extra = top, top_eqs, factory[1], factory[2]
            secs = top_time + extra
        else:
            p, eqs, secs = _derive(factory, None)
            rhs = NumericModel(_driven_equations(p, eqs, drive), problem_parameters(p)).rhs
        run = integrate(rhs, (te[0], te[-1]), y0, "DOP853", t_eval=te, rtol=rtol,
                        atol=rtol * ref.scales)
        k = run.y.shape[1]
        each = np.abs(run.y - truth.y[:, :k]) / ref.scales[:, None]
        err = each.max(axis=0)
        name = "linearised" if isinstance(factory, tuple) else eqs.name
        rung = Rung(label, p.name, name, secs, _rhs_cost(rhs, truth.y[:, ::10], truth.t[::10]),
                    float(err[-1]) if k == te.size else float("inf"),
                    float(err.max()) if k else float("inf"), neglects,
                    times=list(te[:k]), error_curve=list(err))
        rung.neglected = {name: float(np.abs(truth_reactions[name]).max()) for name in dropped
                          if name in truth_reactions}
        names = [q.func.__name__ for q in ref.coordinates]
        names += [f"{c}'" for c in names]
        rung.by_coordinate = {c: float(e.max()) for c, e in zip(names, each)} if k else {}
        rungs.append(rung)
    return Ladder(top.name, (float(te[0]), float(te[-1])), scene.reason, rungs,
                  conditions(scene_problem, state=list(y0), tex=True),
                  {k: str(v) for k, v in _declared_drive(top).items()})


def _linear_entry(top, ref, y0, drive: dict, span) -> tuple | None:
    """The linearised rung's ``(label, ("linear", rhs, seconds), neglects, ())``: the small
    motions about the stable equilibrium without inputs, forced by ``drive`` when the scene
    is driven -- ``J (y - y_eq) + B u(t)``, ``B u(t)`` being ``ref``'s response to the
    input at the equilibrium (a load enters linearly; :func:`_forcing`) -- or None when
    there is none."""
    free = ref
    if drive:
        zero = _free(top)
        free = formulations(zero, y0=y0, models=[top.reference], stabilisations=())[0][0]
    try:
        q_eq, _ = stable_equilibrium(top, free)
    except ValueError:
        return None
    start = time.process_time()
    y_eq = np.concatenate([q_eq, np.zeros(len(q_eq))])
    J = jacobian(free.rhs, 0.0, y_eq)       # what deriving the linear model costs here
    if drive:
        f_eq = free.rhs(0.0, y_eq)
        fitted = _forcing(ref, f_eq, y_eq, drive, span)
        if fitted is not None:
            B, u = fitted
            rhs = (lambda t, y, J=J, y_eq=y_eq: J @ (y - y_eq) + B @ u(t))
        else:   # not affine in the inputs at the equilibrium: the response itself, per call
            rhs = (lambda t, y, J=J, y_eq=y_eq: J @ (y - y_eq) + (ref.rhs(t, y_eq) - f_eq))
    else:
        rhs = (lambda t, y, J=J, y_eq=y_eq: J @ (y - y_eq))
    secs = time.process_time() - start
    about = [round(float(x), 4) for x in q_eq]
    label = (f"linearised (small motions about {about}, forced by "
             f"{', '.join(f'{k}(t)' for k in drive)})" if drive else
             f"linearised (small oscillations about {about})")
    return label, ("linear", rhs, secs), "every term of higher order in the motion", ()


def _forcing(ref, f_eq, y_eq, drive: dict, span) -> tuple | None:
    """``(B, u)``: the input matrix at the equilibrium and ``u(t)``, the inputs' values,
    such that ``B @ u(t) = ref.rhs(t, y_eq) - f_eq`` -- fitted at random times of ``span``
    and checked at as many others (exact where the loads enter linearly, as a load does);
    None when the check fails."""
    fns = [sp.lambdify(_t, drive[k], "math") for k in drive]

    def u(time):
        return np.array([float(f(time)) for f in fns])
    times = np.random.default_rng(0).uniform(span[0], span[1], (2, 2 * len(fns) + 5))
    U = [np.array([u(x) for x in row]) for row in times]
    G = [np.array([ref.rhs(x, y_eq) - f_eq for x in row]) for row in times]
    B = np.linalg.lstsq(U[0], G[0], rcond=None)[0].T
    size = max(np.abs(G[0]).max(), np.abs(G[1]).max(), 1e-300)
    return (B, u) if np.abs(U[1] @ B.T - G[1]).max() <= 1e-12 * size else None


def _declared_drive(problem) -> dict:
    """``{input name: history}`` as ``problem.fidelity_inputs`` declares them, else every
    input's declared default history (``Input(..., history=...)``, what simulations and
    charts drive the scene with) when each input has one as a closed form; else empty."""
    own = {getattr(k, "name", k): v for k, v in (problem.fidelity_inputs or {}).items()}
    if own:
        return own
    inputs = getattr(problem, "inputs", ()) or ()
    if inputs and all(isinstance(i.history, sp.Basic) for i in inputs):
        return {i.symbol.name: i.history for i in inputs}
    return {}


def _drive(problem) -> dict:
    """``{input name: closed form of t alone}``: the declared ``fidelity_inputs``, each
    parameter at its default value (empty for a scene without inputs)."""
    if not problem.input_symbols:
        return {}
    values = {s.name: v for s, v in problem_parameters(problem).items()}
    out = {}
    for name, h in _declared_drive(problem).items():
        if isinstance(h, (int, float)):
            h = sp.Float(h)
        if not isinstance(h, sp.Expr):
            raise TypeError(f"`fidelity_inputs`: `{name}` must be a sympy expression of t and "
                            f"the parameters, got {h!r:.60}.")
        out[name] = h.xreplace({s: _t if s.name == "t" else sp.Float(values[s.name])
                                for s in h.free_symbols})
    return out


def _free(problem):
    """``problem`` with every given input set to zero (itself when it has none)."""
    return _driven(problem, {x.name: sp.Integer(0) for x in problem.inputs or ()})


def _driven(problem, drive: dict):
    """``problem`` with each given input replaced in its models by ``drive[name]`` (a closed
    form of ``t``): an input-free problem whose stated conditions keep the inputs."""
    if not problem.input_symbols:
        return problem
    models = {n: _driven_equations(problem, eqs, drive) for n, eqs in problem.models().items()}
    out = copy.copy(problem)
    stated = {k: str(v) for k, v in _declared_drive(problem).items()} if any(
        v != 0 for v in drive.values()) else {k: "0" for k in drive}
    out.__dict__.update({"_models": models, "inputs": (), "driven_by": stated})
    return out


def _driven_equations(problem, eqs, drive: dict):
    """``eqs`` of ``problem`` with its given inputs replaced by ``drive`` (by name)."""
    symbols = {x.name: x.symbol for x in problem.inputs or ()}
    missing = sorted(set(symbols) - set(drive))
    if missing:
        raise ValueError(f"`{problem.name}` is driven by {', '.join(missing)}, which the "
                         "scene's `fidelity_inputs` does not give (a rung's inputs take the "
                         "richest problem's histories by name)")
    return eqs.substitute({symbols[k]: drive[k] for k in symbols}) if symbols else eqs


def _reactions(problem, Y: np.ndarray, times: np.ndarray) -> dict:
    """The problem's direct-model reactions along states ``Y`` at ``times`` (reference
    coordinates)."""
    values = problem_parameters(problem)
    out = {}
    for m in direct_models(problem, square=True):
        n = m.n
        sol = NumericModel(m, values).solve(times, Y[:n], Y[n:])
        for u, row in zip(m.unknowns, sol[n:]):
            out.setdefault(u.name, row)
    return out
