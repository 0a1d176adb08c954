"""Projection after every accepted step: scipy's ``OdeSolver`` driven one step at a time.

:func:`projected_run` integrates ``y' = f(t, y)`` with scipy's ``RK45``, ``DOP853``,
``Radau`` or ``BDF`` stepper and, after each accepted step, puts the state back on the
constraint manifold with ``projector(t, y)`` (configuration and rates, see
:meth:`ConstrainedModel.project <dualmech.numeric.dae.ConstrainedModel.project>`) -- the
classical projection method (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
IV.4; Hairer & Wanner, *Solving ODEs II*, VII.2).  The stepper goes on from the projected
state with its own step size and order, nothing is restarted: the one-step methods get the
derivative at the projected state (their first stage), ``BDF`` gets the projected value as
the newest entry of its difference table.  Samples inside a step come from the step's own
interpolant and are projected as well.  ``LSODA`` keeps its state inside Fortran and cannot
be projected this way: it is refused with that reason.

Example
-------
>>> import numpy as np
>>> def circle(t, y):      # a particle on the unit circle, as an unconstrained ODE
...     return np.array([y[2], y[3], -y[0] * (y[2]**2 + y[3]**2), -y[1] * (y[2]**2 + y[3]**2)])
>>> def onto(t, y):        # back onto |x| = 1 with x . v = 0
...     x = y[:2] / np.hypot(*y[:2]); v = y[2:] - (y[2:] @ x) * x
...     return np.concatenate([x, v])
>>> run = projected_run(circle, (0, 10), [1.0, 0, 0, 1], "RK45", np.linspace(0, 10, 5),
...                     rtol=1e-3, atol=1e-6, projector=onto)
>>> bool(np.allclose(np.hypot(run.y[0], run.y[1]), 1, atol=1e-14, rtol=0)), run.success
(True, True)
"""
from __future__ import annotations

import time as _time
from typing import Callable, Sequence

import numpy as np
from scipy.integrate import BDF, DOP853, RK45, Radau

from dualmech.model.equations import ModelError
from dualmech.numeric.integrators import WorkBudget, BudgetExceeded, Run, _Meter

__all__ = ["projected_run", "PROJECTABLE", "CHECKED_SCIPY"]

_STEPPERS = {"RK45": RK45, "DOP853": DOP853, "Radau": Radau, "BDF": BDF}
#: The scipy methods :func:`projected_run` can drive.
PROJECTABLE = tuple(_STEPPERS)
#: The scipy releases (major.minor) whose steppers' state :func:`_restart_from` was checked
#: to write correctly.
CHECKED_SCIPY = ("1.17",)


class _Counter:
    def __init__(self, fun, budget: WorkBudget | None = None):
        self.fun, self.calls, self.evaluations = fun, 0, 0
        self.meter = _Meter(budget)

    def __call__(self, t, y):
        self.calls += 1
        k = 1 if np.ndim(y) == 1 else np.shape(y)[1]
        self.evaluations += k
        self.meter.charge(t, k)
        return self.fun(t, y)


def projected_run(fun: Callable, t_span: Sequence[float], y0, method: str, t_eval, *,
                  rtol: float, atol, projector: Callable,
                  max_steps: int = 2_000_000, budget: WorkBudget | None = None) -> Run:
    """Integrate with ``projector(t, y) -> y`` applied after every accepted step.

    Parameters
    ----------
    fun : right-hand side ``f(t, y)`` (vectorised for ``Radau``/``BDF``)
    method : one of :data:`PROJECTABLE`
    t_eval : increasing sample times in ``t_span``
    rtol, atol : the stepper's tolerances
    projector : the projection onto the manifold
    budget : the most the run may spend (:class:`~dualmech.numeric.integrators.WorkBudget`);
        past it the run ends as *did not finish*

    Notes
    -----
    Returns a :class:`~dualmech.numeric.integrators.Run` whose work counts include the
    derivative re-evaluated at every projected state.  A singular system, a state outside the
    model's domain or a projection that does not converge (a ModelError) ends the run with
    ``success = False`` and that message.
    """
    if method not in _STEPPERS:
        raise ValueError(f"projection after every step drives {', '.join(PROJECTABLE)}; "
                         f"{method!r} keeps its state out of reach (LSODA: inside Fortran).")
    t_eval = np.asarray(t_eval, dtype=float)
    counted = _Counter(fun, budget)
    start = _time.process_time()
    y = projector(float(t_span[0]), np.asarray(y0, dtype=float))
    kwargs = {"vectorized": True} if method in ("Radau", "BDF") else {}
    ys, k, steps, message, ok = [], 0, 0, "projected after every accepted step", True
    solver = None
    while k < t_eval.size and t_eval[k] <= t_span[0]:
        ys.append(y.copy())
        k += 1
    try:
        solver = _STEPPERS[method](counted, float(t_span[0]), y, float(t_span[1]), rtol=rtol,
                                   atol=atol, **kwargs)
        while solver.status == "running":
            if steps >= max_steps:
                ok, message = False, f"more than {max_steps} steps"
                break
            msg = solver.step()
            if solver.status == "failed":
                ok, message = False, str(msg)
                break
            steps += 1
            dense = solver.dense_output()
            t = solver.t
            while k < t_eval.size and t_eval[k] <= t:
                ys.append(projector(t_eval[k], dense(t_eval[k])))
                k += 1
            y = projector(t, solver.y)
            _restart_from(solver, y)
    except (ModelError, ValueError, ZeroDivisionError, FloatingPointError,
            np.linalg.LinAlgError, BudgetExceeded) as exc:
        ok, message = False, str(exc)
    y_out = np.array(ys).T if ys else np.empty((np.size(y0), 0))
    return Run(method=method, t=t_eval[: len(ys)].copy(), y=y_out,
               success=ok and len(ys) == t_eval.size, message=message,
               cpu=_time.process_time() - start, calls=counted.calls,
               evaluations=counted.evaluations, steps=steps,
               jacobians=int(getattr(solver, "njev", 0) or 0),
               factorisations=int(getattr(solver, "nlu", 0) or 0),
               t_end=float(t_eval[len(ys) - 1]) if ys else float(t_span[0]))


def _restart_from(solver, y: np.ndarray) -> None:
    """Let ``solver`` go on from the projected state ``y`` (same step size and order).

    scipy has no public way to change a stepper's state, and a restart costs too much:
    measured on the pendulum in Cartesian coordinates over 20 s, a new solver from each
    projected state (``first_step`` the last step) took 2 to 3.7 times the steps with
    ``RK45``, ``DOP853`` and ``Radau`` (``Radau`` a Jacobian at every step), and 35 to 160
    times with ``BDF``, which restarts at order 1 (and strayed by 1.5 at ``rtol = 1e-4``).
    So three attributes are written, checked on the scipy versions of
    :data:`CHECKED_SCIPY` (``tests/test_stepping.py`` pins them and fails on another):
    ``y`` (the state every method steps from), ``f`` (the derivative there: the one-step
    methods' first stage, Radau's Jacobian point) and ``D[0]`` (BDF's newest value in its
    difference table, from which it extrapolates).  Without ``f`` an RK step from the
    projected state is off by the projection times the step; without ``D`` BDF goes on from
    the unprojected state and the projection is silently lost.
    """
    solver.y = y
    if isinstance(solver, BDF):
        solver.D[0] = y  # the newest value of the difference table
    if hasattr(solver, "f"):  # the one-step methods' first stage, Radau's Jacobian point
        solver.f = solver.fun(solver.t, y)
