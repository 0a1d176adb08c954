"""Simulation of a problem's reference model and its reactions along the way.

:func:`simulate` integrates the reference (minimal-coordinate) model with
:func:`scipy.integrate.solve_ivp` through its generated right-hand side
(:meth:`NumericModel.rhs <dualmech.numeric.model.NumericModel.rhs>`) and recovers the reactions
of every direct model along the trajectory in one vectorised solve per model.  Bad input --
misspelt or out-of-range parameters, empty or infinite time spans -- is refused with a message
that names the argument, what was given and what is allowed.

Example
-------
>>> from dualmech.problems import get
>>> traj = simulate(get("toy_car"), t_span=(0, 2))
>>> traj.reactions["F_r"].shape
(200,)
"""
from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field
from typing import Callable, Mapping, Sequence

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from dualmech.model.facts import is_declared, state_vector
from dualmech.numeric.inputs import input_functions
from dualmech.numeric.model import NumericModel, SingularityError

__all__ = ["Trajectory", "simulate", "reactions_at", "reactions_along", "direct_models",
           "default_initial_state", "problem_parameters", "right_hand_side", "check_t_span"]


@dataclass
class Trajectory:
    """A simulated motion, as :func:`simulate` returns it.

    Attributes
    ----------
    t : ndarray, shape (N,)
        Output times (s).
    q, qd : ndarray, shape (n, N)
        Coordinates and their rates at those times, in ``coordinate_names`` order.
    coordinate_names : list of str
    reactions : dict of str to ndarray, shape (N,)
        Each direct model's reactions along the motion.
    message : str
        The integrator's message.

    Examples
    --------
    >>> from dualmech import get, simulate
    >>> run = simulate(get("simple_pendulum"), t_span=(0, 1), samples=11)
    >>> run.q.shape, run.coordinate_names, sorted(run.reactions)
    ((1, 11), ['theta'], ['T'])
    """

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    coordinate_names: list
    reactions: dict = field(default_factory=dict)
    message: str = ""


def problem_parameters(problem, params: Mapping | None = None, *,
                       check_ranges: bool = True) -> dict:
    """The problem's default parameter values with ``params`` (symbols or names) applied.

    Every key must be one of the problem's parameters (a misspelt name is refused with the
    close ones suggested) and every value a finite number inside the parameter's declared
    range (``check_ranges=False`` lets a study go outside it on purpose, e.g. a stiff spring).

    Example
    -------
    >>> from dualmech.problems import get
    >>> problem_parameters(get("toy_car"), {"L": 2})
    Traceback (most recent call last):
    ValueError: `params`: unknown parameter 'L'. Problem `toy_car` has parameters R, g, m.
    """
    declared = {p.symbol: p for p in problem.parameters}
    by_name = {s.name: s for s in declared}
    values = problem.defaults()
    if params is not None and not isinstance(params, Mapping):
        raise TypeError(f"`params` must be a mapping {{parameter: value}}, got {params!r:.60} "
                        f"({type(params).__name__}).")
    for key, value in (params or {}).items():
        symbol = _parameter(key, declared, by_name, problem.name)
        decl = declared[symbol]
        if isinstance(value, (bool, str, bytes)):
            raise ValueError(f"`params`: {symbol.name} = {value!r} is not a number.")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"`params`: {symbol.name} = {value!r} is not a number.") from None
        lo, hi = (float(x) for x in decl.range)
        if not math.isfinite(v):
            raise ValueError(f"`params`: {symbol.name} = {value!r} must be finite.")
        if check_ranges and not lo <= v <= hi:
            raise ValueError(f"`params`: {symbol.name} = {value!r} is outside the admissible "
                             f"range [{lo:g}, {hi:g}] declared by problem `{problem.name}` "
                             "(pass check_ranges=False to go outside it on purpose).")
        values[symbol] = v
    return values


def _parameter(key, declared: dict, by_name: dict, problem_name: str):
    if isinstance(key, sp.Symbol) and key in declared:
        return key
    name = key.name if isinstance(key, sp.Symbol) else key
    if isinstance(name, str) and name in by_name:
        return by_name[name]
    names = sorted(by_name)
    shown = name if isinstance(name, str) else repr(key)
    lower = {n.lower(): n for n in names}
    close = [lower[c] for c in difflib.get_close_matches(str(shown).lower(), list(lower), n=3,
                                                           cutoff=0.5)]
    hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else "."
    raise ValueError(f"`params`: unknown parameter {shown!r}{hint} Problem `{problem_name}` "
                     f"has parameters {', '.join(names) or '(none)'}.")


def check_t_span(t_span) -> tuple[float, float]:
    """``t_span`` as two finite, different numbers (a backward span is allowed)."""
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ValueError(f"`t_span` must be two numbers (start, end), got {t_span!r}.") from None
    if not (math.isfinite(t0) and math.isfinite(t1)):
        raise ValueError(f"`t_span` must be finite, got {t_span!r}: give an end time.")
    if t0 == t1:
        raise ValueError(f"`t_span` is empty ({t_span!r}): the end time must differ from the "
                         "start time.")
    return t0, t1


def default_initial_state(problem) -> tuple[list, list]:
    """The problem's declared ``initial_state`` (:class:`~dualmech.model.problem.Problem`), else
    60 % into each coordinate's range, at rest: ``(q0, q'0)`` in the reference coordinates."""
    ref = problem.model(problem.reference)
    n = ref.n
    init = getattr(problem, "initial_state", None)
    if is_declared(init):
        y0 = state_vector(problem, init, "`initial_state`")
        return y0[:n], y0[n:]
    q0 = []
    for q in ref.coordinates:
        lo, hi = problem.coordinate_info(q).range
        q0.append(lo + 0.6 * (hi - lo))
    return q0, [0.0] * len(q0)


def right_hand_side(problem, params: Mapping | None = None, *,
                    check_ranges: bool = True) -> Callable:
    """``rhs(t, y)`` of the problem's reference model for :func:`solve_ivp`.

    ``y`` is ``[q..., q'...]`` of shape ``(2n,)``, or ``(2n, K)`` for ``K`` states at once
    (``solve_ivp(..., vectorized=True)``); each call returns a new array.
    """
    values = problem_parameters(problem, params, check_ranges=check_ranges)
    return NumericModel(problem.model(problem.reference), values).rhs


def simulate(problem, t_span=(0.0, 5.0), y0=None, params: Mapping | None = None,
             samples: int = 200, rtol: float = 1e-9, atol: float = 1e-11,
             method: str = "DOP853", *, check_ranges: bool = True,
             inputs: Mapping | None = None, **solve_ivp_kwargs) -> Trajectory:
    """Integrate the reference model and recover the direct model's reactions along the way.

    Parameters
    ----------
    problem : Problem
    t_span : (start, end)
        Finite and non-empty.
    y0 : sequence of 2n numbers, optional
        ``[q..., q'...]``; default :func:`default_initial_state`.
    params : mapping, optional
        Overrides of the problem's default parameter values, by symbol or name; see
        :func:`problem_parameters`.
    samples : int
        Number of evenly spaced output times (at least 2).
    rtol, atol, method, **solve_ivp_kwargs
        Passed to :func:`scipy.integrate.solve_ivp`.
    check_ranges : bool
        Refuse parameter values outside their declared ranges (default).
    inputs : mapping, optional
        The history of each given input the problem declares (``Problem.inputs``), by name:
        a function of ``t`` or a table ``(times, values)`` interpolated linearly
        (:func:`~dualmech.numeric.inputs.input_functions`); required when it declares any.

    Raises
    ------
    SingularityError
        The integration reached a state where the mass matrix is singular.

    Examples
    --------
    The pendulum's string pull at the lowest point is ``M (g + a theta'^2)``:

    >>> from dualmech import get, simulate
    >>> p = get("simple_pendulum")
    >>> run = simulate(p, t_span=(0, 1), y0=[0.0, 1.5], samples=2)
    >>> v = {str(s): value for s, value in p.defaults().items()}
    >>> bool(abs(run.reactions["T"][0] - v["M"] * (v["g"] + v["a"] * 1.5**2)) < 1e-9)
    True
    """
    t0, t1 = check_t_span(t_span)
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 2:
        raise ValueError(f"`samples` must be an integer >= 2, got {samples!r}.")
    values = problem_parameters(problem, params, check_ranges=check_ranges)
    drive = input_functions(problem, inputs, (t0, t1), values)
    ref = problem.model(problem.reference)
    refuse_static(problem, ref)
    model = NumericModel(ref, values, inputs=drive)
    n = ref.n
    if y0 is None:
        q0, qd0 = default_initial_state(problem)
        y0 = q0 + qd0
    try:
        y0 = np.asarray(y0, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"`y0` must hold {2 * n} numbers (q then q'), got {y0!r:.80}.") \
            from None
    if y0.shape != (2 * n,):
        raise ValueError(f"`y0` must hold {2 * n} numbers (q then q'), got shape {y0.shape}.")
    if not np.isfinite(y0).all():
        raise ValueError(f"`y0` must be finite, got {y0.tolist()}.")
    t_eval = np.linspace(t0, t1, int(samples))
    sol = solve_ivp(model.rhs, (t0, t1), y0, method=method, rtol=rtol, atol=atol,
                    t_eval=t_eval, **solve_ivp_kwargs)
    if sol.status < 0:
        raise SingularityError(f"integration of `{problem.name}` failed: {sol.message}")
    traj = Trajectory(sol.t, sol.y[:n], sol.y[n:], [q.func.__name__ for q in ref.coordinates],
                      message=sol.message)
    traj.reactions = reactions_along(problem, traj, values, drive)
    return traj


def refuse_static(problem, eqs) -> None:
    """A reference model with static rows (a massless part's balance: no acceleration in the
    row) is a DAE: its mass matrix is singular at every state, so it is not integrated as an
    ODE -- say so, and where its motion is computed, instead of a singular state."""
    fast = eqs.plain_matrix_se()
    A = fast[0] if fast is not None else eqs.plain_matrix()[0]
    static = [eqs.labels[i] if i < len(eqs.labels) else f"row {i + 1}" for i in range(A.rows)
              if all(A[i, j] == 0 for j in range(A.cols))]
    if static:
        raise SingularityError(
            f"the reference model `{eqs.name}` of `{problem.name}` holds static rows "
            f"({'; '.join(static)}: a massless part's balance, with no acceleration), so it is "
            "a DAE and is not integrated as an ODE; `dualmech chart "
            f"{problem.name}` integrates it as the DAE it is (the projected DAE forms).")


def direct_models(problem, square: bool = False):
    """The problem's models with reactions, in the reference coordinates (only those with
    as many equations as accelerations and reactions when ``square``)."""
    for m in problem.models().values():
        if m.unknowns:
            m = problem.in_reference_coordinates(m)
            if not square or m.is_square:
                yield m


def reactions_at(problem, q: Sequence[float], qd: Sequence[float], time: float = 0.0,
                 params: Mapping | None = None, *, check_ranges: bool = True,
                 inputs: Mapping | None = None) -> dict:
    """Reactions ``{name: value}`` of the direct model(s) at one state (reference coordinates).

    The accelerations are the reference model's; each direct model's reactions are then its
    solution of ``A [q''; lambda] = b`` (a model whose reaction columns are rank-deficient at
    the state, so that they do not fix its reactions, gives none).
    """
    values = problem_parameters(problem, params, check_ranges=check_ranges)
    drive = input_functions(problem, inputs, params=values)
    ref = problem.model(problem.reference)
    qdd = NumericModel(ref, values, inputs=drive).accelerations(time, q, qd)
    out: dict = {}
    for m in direct_models(problem):
        A, b = NumericModel(m, values, inputs=drive).system(time, q, qd)
        if np.linalg.matrix_rank(A[:, m.n:]) < len(m.unknowns):
            continue    # the reactions are not fixed by this model: no least-norm guess
        lam = np.linalg.lstsq(A[:, m.n:], b - A[:, : m.n] @ qdd, rcond=None)[0]
        for u, v in zip(m.unknowns, lam):
            out.setdefault(u.name, float(v))
    return out


def reactions_along(problem, traj: Trajectory, values: Mapping,
                    inputs: Mapping | None = None) -> dict:
    """Reactions of every direct model (in the reference coordinates) along ``traj``
    (``inputs``: the given inputs' functions of time, as :func:`simulate` binds them).

    Each direct model is solved at all samples at once (one batched solve).
    """
    out: dict = {}
    for m in direct_models(problem):  # one batched solve: nothing to compile for it
        rows = NumericModel(m, values, backend="python", inputs=inputs).solve(
            traj.t, traj.q, traj.qd)[m.n:]
        for name, row in zip((u.name for u in m.unknowns), rows):
            out.setdefault(name, row)
    return out
