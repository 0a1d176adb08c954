"""Reaction values at one state: the direct form's and the referee's, side by side.

A reaction whose formula is past the display budget (:mod:`dualmech.verify.display`) is still
a number at any state.  :func:`reactions_at_state` gives, for each declared reaction, its value
at a state ``(q, q')`` of the reference coordinates two ways:

* **direct**: the accelerations from the verified equations of motion (the reference model),
  then the direct model's linear solve for its reactions
  (:func:`~dualmech.numeric.simulation.reactions_at`);
* **referee**: the Kane referee's own square system (:mod:`dualmech.verify.referee`), solved
  for its accelerations and reactions together -- nothing shared with the direct form's
  balances.

The state is a mapping ``{"theta": 0.3, "theta_dot": 1.0}`` (coordinate names of the reference
model and ``name_dot`` for rates; the command line reads it from ``--at 'theta=0.3, ...'`` with
the strict parser of ``dualmech stability --about``).  Coordinates not named keep the problem's
default state (its declared ``initial_state``, else 60 % into each declared range, at rest).

Example
-------
>>> from dualmech import get
>>> r = reactions_at_state(get("simple_pendulum"), {"theta": 0.0, "theta_dot": 2.0})
>>> v = {str(k): x for k, x in get("simple_pendulum").defaults().items()}
>>> round(r.direct["T"] - v["M"] * (v["g"] + v["a"] * 4.0), 9), round(r.referee["T"][0], 6) \
== round(r.direct["T"], 6)
(0.0, True)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping

import numpy as np

from dualmech.numeric.inputs import declared_inputs, default_values, input_functions
from dualmech.numeric.model import NumericModel
from dualmech.numeric.simulation import default_initial_state, problem_parameters, reactions_at

__all__ = ["StateReactions", "reactions_at_state", "state_from_names"]


@dataclass
class StateReactions:
    """Reactions at one state (see :func:`reactions_at_state`).

    ``state`` holds every coordinate and rate (``name``, ``name_dot``) of the reference model;
    ``given`` the names the caller set (the rest are the default state's); ``direct`` maps a
    reaction to its value; ``referee`` to ``(value, referee name)`` where a referee derives it;
    ``others`` to ``[(value, model name)]``, the other derivations of a reaction no referee
    derives (a multiplier model's, say).
    """

    problem: str
    state: dict
    given: tuple
    time: float
    direct: dict = field(default_factory=dict)
    referee: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    others: dict = field(default_factory=dict)

    def where(self) -> str:
        """The state as ``theta = 0.3, theta_dot = 0``, saying which values are defaults."""
        shown = ", ".join(f"{k} = {v:.6g}" for k, v in self.state.items())
        if not self.given:
            return (f"{shown} (the problem's default state inside its declared ranges; "
                    "choose another with --at 'name=value, name_dot=value')")
        rest = [k for k in self.state if k not in self.given]
        return shown + (f" ({', '.join(rest)} from the default state)" if rest else "")

    def lines(self) -> list[str]:
        """One line per reaction: the direct value, the referee's beside it, their gap."""
        out = [f"at t = {self.time:g} s, {self.where()}:"]
        width = max((len(k) for k in self.direct), default=1)
        for name, value in self.direct.items():
            line = f"  {name:<{width}} = {value:.10g}   (direct form)"
            if name in self.referee:
                other, who = self.referee[name]
                gap = abs(other - value) / max(1.0, abs(value))
                line += f";  {other:.10g} ({who}, Kane; relative gap {gap:.1e})"
            elif self.others.get(name):
                line += "".join(f";  {v:.10g} ({who})" for v, who in self.others[name])
            else:
                line += ";  no other derivation gives it"
            out.append(line)
        return out + [f"  {n}" for n in self.notes]

    def to_dict(self) -> dict:
        return {"time": self.time, "state": dict(self.state), "given": list(self.given),
                "default_state": not self.given,
                "values": {name: {"direct": value,
                                  "referee": self.referee.get(name, (None, None))[0],
                                  "referee_model": self.referee.get(name, (None, None))[1],
                                  "others": {who: v for v, who in self.others.get(name, ())}}
                           for name, value in self.direct.items()},
                "notes": list(self.notes)}


def state_from_names(problem, at: Mapping[str, float] | None) -> tuple[list, list, tuple]:
    """``(q, q', given)`` in the reference coordinates: the default state with the values of
    ``at`` (``name`` or ``name_dot``) put in; an unknown name or a value that is not a finite
    number is refused (``ValueError``) naming the coordinates."""
    from dualmech.numeric.stability import steady_state_from_names
    q0, qd0 = (list(map(float, v)) for v in default_initial_state(problem))
    inputs = declared_inputs(problem)   # an input's value is read by reactions_at_state
    at = {k: v for k, v in (at or {}).items() if k not in inputs}
    if not at:
        return q0, qd0, ()
    for name, value in at.items():
        if isinstance(value, (bool, str, bytes)) or not np.isfinite(_float(value)):
            raise ValueError(f"`--at`: {name} = {value!r:.40} is not a finite number.")
    try:
        exact = steady_state_from_names(problem, dict(at))
    except ValueError as exc:
        more = f"; given inputs: {', '.join(inputs)}" if inputs else ""
        raise ValueError(str(exc).replace("`--about`", "`--at`")[:-1] + more + ".") from None
    coords = list(problem.model(problem.reference).coordinates)
    for i, q in enumerate(coords):
        rate = q.diff(q.args[0])
        q0[i] = float(exact.get(q, q0[i]))
        qd0[i] = float(exact.get(rate, qd0[i]))
    return q0, qd0, tuple(at)


def _float(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        return float("nan")


def reactions_at_state(problem, at: Mapping[str, float] | None = None,
                       params: Mapping | None = None, time: float = 0.0,
                       comparison=None) -> StateReactions:
    """Each declared reaction at one state, by the direct form and by the referee.

    ``comparison`` (a :class:`~dualmech.verify.check.Comparison` of ``problem``) lends its
    referees; without it they are derived here.  ``at`` is read by :func:`state_from_names`.
    """
    at, drive, named = _split_inputs(problem, at, time, params)
    q, qd, given = state_from_names(problem, at)
    if not np.isfinite(float(time)):
        raise ValueError(f"`time` must be finite, got {time!r}.")
    coords = [c.func.__name__ for c in problem.model(problem.reference).coordinates]
    state = dict(zip(coords, q)) | {f"{c}_dot": v for c, v in zip(coords, qd)} | drive
    out = StateReactions(problem.name, state, given + named, float(time))
    declared = [r.name for r in problem.reactions]
    histories = {k: (lambda t, v=v: v) for k, v in drive.items()}
    direct = reactions_at(problem, q, qd, time, params, check_ranges=False, inputs=histories)
    out.direct = {k: direct[k] for k in declared if k in direct}
    values = problem_parameters(problem, params, check_ranges=False)
    fns = input_functions(problem, histories)
    for name, model in _referee_models(problem, comparison).items():
        for rname, value in _referee_values(model, values, q, qd, time, out.notes,
                                            fns).items():
            if rname in out.direct and rname not in out.referee:
                out.referee[rname] = (value, name)
    lonely = [k for k in out.direct if k not in out.referee]
    if lonely:   # no referee: the problem's other derivations of them, beside
        for mname, got in _other_models(problem, values, fns, q, qd, time).items():
            for k in lonely:
                if k in got:
                    out.others.setdefault(k, []).append((got[k], mname))
    if comparison is not None and lonely:
        out.notes += list(comparison.referees.notes)
    missing = [k for k in declared if k not in out.direct]
    if missing:
        out.notes.append(f"no square direct model gives {', '.join(missing)}")
    return out


def _other_models(problem, values, fns, q, qd, time) -> dict:
    """``{model: {reaction: value}}`` of every model with reactions after the first (the one
    :func:`reactions_at` reads), each by the reference accelerations and its linear solve."""
    from dualmech.numeric.simulation import direct_models
    ref = problem.model(problem.reference)
    qdd = NumericModel(ref, values, inputs=fns).accelerations(time, q, qd)
    out = {}
    for m in list(direct_models(problem))[1:]:
        A, b = NumericModel(m, values, backend="python", inputs=fns).system(time, q, qd)
        if np.linalg.matrix_rank(A[:, m.n:]) < len(m.unknowns):
            continue
        lam = np.linalg.lstsq(A[:, m.n:], b - A[:, : m.n] @ qdd, rcond=None)[0]
        out[m.name] = {u.name: float(v) for u, v in zip(m.unknowns, lam)}
    return out


def _split_inputs(problem, at: Mapping | None, time: float = 0.0,
                  params: Mapping | None = None) -> tuple[dict, dict, tuple]:
    """``(state names, {input: value}, inputs named)``: the given inputs' values at the
    instant are read from ``at`` too (``F=2``); one not named takes its declared default
    history's value at ``time``, else zero."""
    inputs = declared_inputs(problem)
    at = dict(at or {})
    named = tuple(k for k in inputs if k in at)
    defaults = default_values(problem, time, params) if len(named) < len(inputs) else {}
    drive = {}
    for name in inputs:
        value = at.pop(name, defaults.get(name, 0.0))
        if isinstance(value, (bool, str, bytes)) or not np.isfinite(_float(value)):
            raise ValueError(f"`--at`: {name} = {value!r:.40} is not a finite number.")
        drive[name] = float(value)
    return at, drive, named


def _referee_models(problem, comparison) -> dict:
    """``{referee name: EquationSet in the reference coordinates}`` of the referees that vote."""
    if comparison is not None:
        j = comparison.judgement
        return {k: m for k, m in comparison.referees.models.items() if k not in j.withdrawn}
    from dualmech.verify.referee import referees
    return referees(problem).models


def _referee_values(model, values, q, qd, time, notes: list, inputs=None) -> dict:
    """The referee's reactions from its own system (its accelerations solved with them);
    ``{}`` with a note when the system is singular at the state.  A referee of a rolling
    body has more rows than unknowns (Kane's rows of the constrained speeds beside the
    auxiliary ones): solved by least squares when its rank is full and its rows consistent
    (the residual at rounding level), as its exact verdict found them everywhere."""
    held = None if inputs else _substituted(model, values, q, qd, time)
    A, b = held if held is not None else \
        NumericModel(model, values, backend="python", inputs=inputs).system(time, q, qd)
    rank = np.linalg.matrix_rank(A)
    if A.shape[0] < A.shape[1] or rank < A.shape[1]:
        notes.append(f"`{model.name}` does not fix every reaction at this state (its system is "
                     f"{A.shape[0]} x {A.shape[1]}, rank {rank})")
        return {}
    x = np.linalg.lstsq(A, b, rcond=None)[0] if A.shape[0] > A.shape[1] else \
        np.linalg.solve(A, b)
    scale = np.max(np.abs(A)) * np.max(np.abs(x)) + np.max(np.abs(b))
    if np.max(np.abs(A @ x - b)) > 1e-8 * scale:
        notes.append(f"`{model.name}`'s rows are not consistent at this state (its system is "
                     f"{A.shape[0]} x {A.shape[1]}): no values from it")
        return {}
    return {u.name: float(v) for u, v in zip(model.unknowns, x[model.n:])}


def _substituted(model, values, q, qd, time) -> tuple | None:
    """``(A, b)`` of ``model`` at one state by substituting numbers into the rows it holds in
    symengine: for one state far cheaper than generating its code (a bicycle's referee: under
    a second against minutes); ``None`` when it holds none or a value is not real."""
    import symengine as se

    from dualmech.model.equations import state_symbols
    held = model.plain_matrix_se()
    if held is None:
        return None
    A, b, _ = held
    at = {se.Symbol("t"): float(time)}
    for s_, v in values.items():
        at[se.Symbol(str(s_))] = float(v)
    for c, x, v in zip(model.coordinates, q, qd):
        st = state_symbols(c)
        at[se.Symbol(st.q.name)], at[se.Symbol(st.qd.name)] = float(x), float(v)
    try:
        An = np.array([[0.0 if A[i, j] == 0 else float(A[i, j].xreplace(at))
                        for j in range(A.cols)] for i in range(A.rows)])
        bn = np.array([0.0 if b[i] == 0 else float(b[i].xreplace(at)) for i in range(b.rows)])
    except (TypeError, RuntimeError, ValueError):
        return None
    return An, bn
