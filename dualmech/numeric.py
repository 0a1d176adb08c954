"""Numbers from the canonical equations: compiled right-hand sides, simulation, reactions.

:class:`NumericModel` compiles ``A(q, q', t)`` and ``b(q, q', t)`` of an
:class:`~dualmech.equations.EquationSet` into NumPy code (with common-subexpression
elimination) and solves ``A [q''; lambda] = b`` at states.  :func:`simulate` integrates the
reference (minimal-coordinate) model with :func:`scipy.integrate.solve_ivp` and recovers the
reactions of the direct model along the trajectory.  A singular mass matrix stops the work
with :class:`SingularityError` naming the state, never a silent wrong number.

Example
-------
>>> from problems import get                                    # doctest: +SKIP
>>> traj = simulate(get("toy_car"), t_span=(0, 2))              # doctest: +SKIP
>>> traj.reactions["F_r"].shape                                 # doctest: +SKIP
(200,)
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Mapping, Sequence

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from ._expr import as_expr
from .equations import EquationSet, ModelError, state_symbols, to_plain
from .kinematics import t

__all__ = ["NumericModel", "Trajectory", "SingularityError", "simulate", "reactions_at",
           "reactions_along"]


class SingularityError(ModelError):
    """The mass matrix (or the full system with reactions) is singular at a state."""


class NumericModel:
    """Compiled ``A`` and ``b`` of one equation set, for a fixed set of parameter values.

    Parameters
    ----------
    eqs : EquationSet
    params : mapping symbol -> float
        A value for every parameter symbol in the equations.
    """

    def __init__(self, eqs: EquationSet, params: Mapping):
        self.eqs = eqs
        self.states = [state_symbols(q) for q in eqs.coordinates]
        self.n = eqs.n
        fn, symbols = _compiled(eqs)
        values = {_key(k, symbols): float(v) for k, v in params.items()}
        missing = [s for s in symbols if s not in values]
        if missing:
            raise ModelError(f"`params` lacks values for {sorted(map(str, missing))} "
                             f"(model `{eqs.name}`).")
        self._fn = fn
        self._p = [values[s] for s in symbols]

    def system(self, time: float, q: Sequence[float], qd: Sequence[float]):
        A, b, _ = self._fn(time, *q, *qd, *self._p)
        return np.asarray(A, dtype=float), np.asarray(b, dtype=float).reshape(-1)

    def _size(self, time, q, qd) -> float:
        S = np.asarray(self._fn(time, *q, *qd, *self._p)[2], dtype=float)
        return float(np.max(np.abs(S))) if S.size else 1.0

    def solve(self, time: float, q: Sequence[float], qd: Sequence[float]) -> np.ndarray:
        """``[q''; lambda]`` at one state (least squares if the system is not square)."""
        A, b = self.system(time, q, qd)
        if A.shape[0] == A.shape[1]:
            sv = np.linalg.svd(A, compute_uv=False)
            cond = sv[0] / sv[-1] if sv[-1] > 0 else np.inf
            if not np.isfinite(cond) or cond > 1e12 or sv[-1] < 1e-12 * self._size(time, q, qd):
                raise SingularityError(self._singular_message(time, q, qd, cond))
            return np.linalg.solve(A, b)
        x, *_ = np.linalg.lstsq(A, b, rcond=None)
        return x

    def accelerations(self, time, q, qd) -> np.ndarray:
        return self.solve(time, q, qd)[: self.n]

    def _singular_message(self, time, q, qd, cond) -> str:
        st = ", ".join(f"{s.name}={v:.6g}" for s, v in zip(self.states, q))
        return (f"the system of `{self.eqs.name}` is singular at t={time:.6g}, {st} "
                f"(condition number {cond:.3g}): the coordinates cannot describe the motion "
                "there; stay away from the problem's singular set or choose other coordinates.")


_CACHE: dict = {}


def _key(k, symbols):
    """A parameter given as a symbol or by its name (looked up, never parsed)."""
    if isinstance(k, str):
        for s in symbols:
            if s.name == k:
                return s
        return sp.Symbol(k)  # unknown name: reported as missing/unused by the caller
    return as_expr(k)


def _compiled(eqs: EquationSet):
    """NumPy code for ``(A, b)`` of ``eqs`` with arguments ``(t, q..., q'..., params...)``."""
    key = id(eqs)
    hit = _CACHE.get(key)
    if hit is not None and hit[0] is eqs:
        return hit[1], hit[2]
    coords = eqs.coordinates
    A, b = eqs.matrix()
    A = A.applyfunc(lambda e: to_plain(e, coords))
    b = b.applyfunc(lambda e: to_plain(e, coords))
    states = [state_symbols(q) for q in coords]
    args = [t] + [s.q for s in states] + [s.qd for s in states]
    params = sorted((A.free_symbols | b.free_symbols) - set(args), key=str)
    fn = sp.lambdify(args + params, [A, b, A.applyfunc(_magnitude)], modules="numpy", cse=True)
    _CACHE[key] = (eqs, fn, params)
    return fn, params


def _magnitude(expr):
    """A natural size of ``expr``: its terms in absolute value with every sin/cos taken as 1.

    A pivot far below this size is a cancellation to zero: the matrix is singular there, even
    when its condition number (which ignores scale) looks harmless.
    """
    e = expr.replace(lambda x: isinstance(x, (sp.sin, sp.cos)), lambda x: sp.Integer(1))
    if sp.count_ops(e) < 500:
        e = sp.expand(e)
    return sp.Add(*[sp.Abs(term) for term in sp.Add.make_args(e)])


@dataclass
class Trajectory:
    """A simulated motion: times ``t`` (N,), ``q`` and ``qd`` (n, N), reactions {name: (N,)}."""

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    coordinate_names: list
    reactions: dict = field(default_factory=dict)
    message: str = ""


def default_initial_state(problem) -> tuple[list, list]:
    """``problem.initial_state`` if declared, else 60 % into each coordinate's range, at rest."""
    init = getattr(problem, "initial_state", None)
    ref = problem.model(problem.reference)
    if init:
        q0 = [float(init[q]) for q in ref.coordinates]
        qd0 = [float(init.get(q.diff(t), 0.0)) for q in ref.coordinates]
        return q0, qd0
    q0 = []
    for q in ref.coordinates:
        lo, hi = problem.coordinate_info(q).range
        q0.append(lo + 0.6 * (hi - lo))
    return q0, [0.0] * len(q0)


def simulate(problem, t_span=(0.0, 5.0), y0=None, params: Mapping | None = None,
             samples: int = 200, rtol: float = 1e-9, atol: float = 1e-11,
             method: str = "DOP853", **solve_ivp_kwargs) -> Trajectory:
    """Integrate the reference model and recover the direct model's reactions along the way.

    ``y0`` is ``[q..., q'...]`` (default :func:`default_initial_state`); ``params`` overrides
    the problem's default parameter values.
    """
    values = problem.defaults()
    values.update({_key(k, problem.parameter_symbols): v for k, v in (params or {}).items()})
    ref = problem.model(problem.reference)
    model = NumericModel(ref, values)
    n = ref.n
    if y0 is None:
        q0, qd0 = default_initial_state(problem)
        y0 = q0 + qd0
    y0 = np.asarray(y0, dtype=float)
    if y0.shape != (2 * n,):
        raise ValueError(f"`y0` must hold {2 * n} numbers (q then q'), got shape {y0.shape}.")

    def rhs(time, y):
        return np.concatenate([y[n:], model.accelerations(time, y[:n], y[n:])])

    t_eval = np.linspace(t_span[0], t_span[1], samples)
    sol = solve_ivp(rhs, t_span, y0, method=method, rtol=rtol, atol=atol, t_eval=t_eval,
                    **solve_ivp_kwargs)
    if sol.status < 0:
        raise SingularityError(f"integration of `{problem.name}` failed: {sol.message}")
    traj = Trajectory(sol.t, sol.y[:n], sol.y[n:], [q.func.__name__ for q in ref.coordinates],
                      message=sol.message)
    traj.reactions = reactions_along(problem, traj, values)
    return traj


def reactions_at(problem, q: Sequence[float], qd: Sequence[float], time: float = 0.0,
                 params: Mapping | None = None) -> dict:
    """Reactions ``{name: value}`` of the direct model(s) at one state (reference coordinates).

    The accelerations are the reference model's; each direct model's reactions are then its
    solution of ``A [q''; lambda] = b``.
    """
    values = problem.defaults()
    values.update({_key(k, problem.parameter_symbols): v for k, v in (params or {}).items()})
    ref = problem.model(problem.reference)
    qdd = NumericModel(ref, values).accelerations(time, q, qd)
    out: dict = {}
    for m in problem.models().values():
        if not m.unknowns:
            continue
        m = problem.in_reference_coordinates(m)
        A, b = NumericModel(m, values).system(time, q, qd)
        n = m.n
        lam = np.linalg.lstsq(A[:, n:], b - A[:, :n] @ qdd, rcond=None)[0]
        for u, v in zip(m.unknowns, lam):
            out.setdefault(u.name, float(v))
    return out


def reactions_along(problem, traj: Trajectory, values: Mapping) -> dict:
    """Reactions of every direct model (in the reference coordinates) along ``traj``."""
    out: dict = {}
    for m in problem.models().values():
        if not m.unknowns:
            continue
        m = problem.in_reference_coordinates(m)
        nm = NumericModel(m, values)
        names = [u.name for u in m.unknowns]
        rows = np.array([nm.solve(tk, traj.q[:, k], traj.qd[:, k])[m.n:]
                         for k, tk in enumerate(traj.t)])
        for j, name in enumerate(names):
            out.setdefault(name, rows[:, j])
    return out
