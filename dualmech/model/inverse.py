"""Inverse dynamics: the inputs (motor forces, torques) and reactions a prescribed motion needs.

Given an :class:`~dualmech.model.equations.EquationSet` and a motion ``q(t)`` prescribed for every
coordinate, the equations become linear equations for the chosen *inputs* -- parameters such
as a motor force ``f`` or torque ``T`` that enter linearly -- and for the model's reaction
unknowns.  :func:`required_inputs` solves them exactly (a sympy linear solve, no
simplification) and returns each as an expression in ``t``; :func:`peak` finds the largest
magnitude of such an expression over a time interval.

This is how a design study sizes its motors: "what force must the base motor give to move the
base along this profile?"

Example
-------
>>> import sympy as sp
>>> from dualmech import EquationSet, coordinate, t
>>> x = coordinate("x"); m, f = sp.symbols("m f", positive=True)
>>> eqs = EquationSet("block", (x,), (m*x.diff(t, 2) - f,))
>>> required_inputs(eqs, [f], {x: t**3})
{f: 6*m*t}
"""
from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np
import sympy as sp

from dualmech.model._expr import as_expr, refuse_text
from dualmech.model.equations import EquationSet, ModelError
from dualmech.model.kinematics import t

__all__ = ["required_inputs", "peak"]


def _parameters(eqs: EquationSet) -> set:
    """Every symbol of ``eqs`` other than ``t`` and its reaction unknowns."""
    free = set().union(*(e.free_symbols for e in eqs.equations))
    return free - {t} - set(eqs.unknowns)


def _along(eqs: EquationSet, motion: Mapping) -> list:
    """The equations with every ``q'', q', q`` replaced by the prescribed motion."""
    missing = [q for q in eqs.coordinates if q not in motion]
    if missing:
        raise ModelError(f"`motion` must prescribe every coordinate of `{eqs.name}`; missing "
                         f"{missing}.")
    path = {q: as_expr(motion[q]) for q in eqs.coordinates}
    second = {q.diff(t, 2): e.diff(t, 2) for q, e in path.items()}
    first = {q.diff(t): e.diff(t) for q, e in path.items()}
    return [e.xreplace(second).xreplace(first).xreplace(path) for e in eqs.equations]


@refuse_text
def required_inputs(eqs: EquationSet, inputs: Sequence[sp.Symbol], motion: Mapping) -> dict:
    """Inputs and reactions that make ``eqs`` hold along ``motion`` (exact, in ``t``).

    Parameters
    ----------
    eqs : EquationSet
        The model; its equations must be linear in the ``inputs``.
    inputs : sequence of symbols
        Parameters of the model to solve for (e.g. a motor force and a torque); with the
        model's reaction unknowns they must be as many as its equations.
    motion : mapping ``{q(t): expression in t}``
        The prescribed motion of every coordinate (it may use parameters of its own, such as
        a rate; the results are then expressions in them too).

    Returns
    -------
    dict
        ``{input or reaction symbol: expression in t}`` (reactions are ``eqs.unknowns``).

    Raises
    ------
    ModelError
        A coordinate without motion, an input the equations do not contain or contain
        nonlinearly, or inputs and reactions that the equations do not determine.
    """
    inputs = [as_expr(u) for u in inputs]
    absent = [u for u in inputs if u not in _parameters(eqs)]
    if absent:
        raise ModelError(f"`inputs` {absent} do not appear in `{eqs.name}`; pick parameters "
                         "of the model.")
    unknowns = inputs + list(eqs.unknowns)
    if len(unknowns) != len(eqs.equations):
        raise ModelError(f"`{eqs.name}` has {len(eqs.equations)} equations but {len(inputs)} "
                         f"inputs and {len(eqs.unknowns)} reactions: give as many inputs as "
                         "the equations can fix.")
    rows = sp.Matrix(_along(eqs, motion))
    A = rows.jacobian(unknowns)
    if any(a.has(u) for a in A for u in unknowns):
        raise ModelError(f"`{eqs.name}` is not linear in {unknowns}; inverse dynamics needs "
                         "inputs that enter linearly (forces, torques).")
    b = -rows.xreplace({u: 0 for u in unknowns})
    try:
        solution = A.LUsolve(b)
    except (ValueError, ZeroDivisionError, sp.matrices.exceptions.NonInvertibleMatrixError):
        raise ModelError(f"the equations of `{eqs.name}` do not determine {unknowns} along "
                         "the motion: the inputs act in the same way (choose other ones)."
                         ) from None
    return dict(zip(unknowns, solution))


@refuse_text
def peak(expr, t_span: tuple[float, float], params: Mapping | None = None,
         samples: int = 4001) -> tuple[float, float]:
    """``(time, value)`` where ``|expr(t)|`` is largest on ``t_span`` (a sampled search).

    ``expr`` is an expression in ``t`` and parameters (values in ``params``).  The search
    samples ``samples`` evenly spaced times including both ends, then refines the best one
    with a bounded scalar minimisation, so a peak at an end of the interval is found exactly.
    An interior peak is flat: its value comes out to rounding, its time only to about
    ``sqrt(eps)`` times the time scale.
    """
    from scipy.optimize import minimize_scalar

    e = as_expr(expr).subs(dict(params or {}))
    extra = e.free_symbols - {t}
    if extra:
        raise ModelError(f"`params` lacks values for {sorted(map(str, extra))}.")
    f = sp.lambdify(t, e, "numpy")
    t0, t1 = (float(v) for v in t_span)
    ts = np.linspace(t0, t1, int(samples))
    vals = np.abs(np.broadcast_to(np.asarray(f(ts), dtype=float), ts.shape))
    k = int(np.argmax(vals))
    lo, hi = ts[max(k - 1, 0)], ts[min(k + 1, len(ts) - 1)]
    if hi > lo:
        res = minimize_scalar(lambda s: -abs(float(f(s))), bounds=(lo, hi), method="bounded",
                              options={"xatol": 1e-12 * max(1.0, abs(hi))})
        if -res.fun > vals[k]:
            return float(res.x), float(f(res.x))
    return float(ts[k]), float(f(ts[k]))
