r"""Index-3 and stabilised index-2 (GGL) forms, solved as DAEs by SUNDIALS IDA.

A model in maximal coordinates with multipliers, ``M(q) q'' + W(q) lambda = b(q, q', t)``
and holonomic constraints ``g(q) = g0`` (:class:`~dualmech.numeric.dae.ConstrainedModel`),
is integrated as a differential-algebraic system by IDA (variable-order BDF with a Newton
iteration on the residual; Brenan, Campbell & Petzold, *Numerical Solution of IVPs in DAEs*)
in two forms (and, for comparison, the index-1 system ``index1``: the constraints at the
acceleration level, ``lambda`` algebraic of index 1):

* ``index3`` -- the original system in ``y = [q, v, lambda]``::

      q' - v = 0,   M v' + W lambda - b = 0,   g(q) - g0 = 0;

  the multipliers (index 3) and the velocities of the coordinates that enter a constraint
  (index 2) are left out of the error test (``atol`` set far above their size), whose
  estimate is not valid for them (Brenan et al., section 5.4); the velocities of coordinates
  no constraint holds are index-1 variables and stay in it;
* ``ggl`` -- Gear, Gupta & Leimkuhler's stabilised index-2 form in ``y = [q, v, lambda, mu]``
  (*J. Comput. Appl. Math.* 12, 1985)::

      q' - v + G^T mu = 0,   M v' + W lambda - b = 0,   g(q) - g0 = 0,   G(q) v = 0,

  with ``G = dg/dq``: position and velocity constraints both hold at every step, the extra
  multiplier ``mu`` is zero on exact solutions; ``lambda`` and ``mu`` are left out of the
  error test.

Both start from a consistent state: ``q`` on the manifold, ``v`` tangent to it, ``v'`` and
``lambda`` from the index-1 system.  IDA's own finite-difference Jacobian of the residual is
used (dense).  Samples come from IDA's interpolant at the requested times; the accepted steps
are counted one by one.

Two routes run the same residual (:attr:`IDASolver.route`): by default the residual is
generated as C and IDA runs in C, calling it through a function pointer with no Python per
step (:mod:`~dualmech.numeric.ida`, :mod:`~dualmech.numeric.ida_driver`); where that cannot
run (no C compiler, no SUNDIALS libraries in scikit-sundae's wheel) IDA calls the Python
:meth:`IDASolver.residual` through the ``scikit-sundae`` bindings, and the run's message
begins with ``"fallback: "`` and the reason.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.numeric.formulations import formulations
>>> forms, _ = formulations(get("pendulum_particle"), stabilisations=("ggl",))
>>> f = {g.name: g for g in forms}["cartesian (DAE, GGL index 2)"]
>>> r = f.run("IDA", (0, 1), [0, 0.5, 1], rtol=1e-8)
>>> r.success, r.y.shape, r.steps > 10
(True, (4, 3), True)
"""
from __future__ import annotations

import os
import time as _time
from dataclasses import replace
from typing import Sequence

import numpy as np

from dualmech.model.equations import ModelError
from dualmech.numeric import ida
from dualmech.numeric.ida import IDA_FORMS, IdaUnavailable
from dualmech.numeric.integrators import (DID_NOT_FINISH, BudgetExceeded, Run, WorkBudget,
                                          _Meter)

__all__ = ["DAE_FORMS", "DAE_METHODS", "IDA_FORMS", "IDASolver", "ROUTES"]

#: The forms the charts solve by a DAE solver, and the solver's method name.
DAE_FORMS = ("index3", "ggl")
DAE_METHODS = ("IDA",)
#: Where the residual runs: ``"auto"`` (compiled C where it can, else Python, saying why),
#: ``"C"`` (compiled, or :class:`IdaUnavailable`), ``"Python"``.
ROUTES = ("auto", "C", "Python")
#: The ``atol`` that takes a component out of IDA's error test (its weight ~ 1e-30).
_EXCLUDED = 1e30
#: A failed run's end is called nearly singular when the constraint gradients' smallest
#: singular value is below this fraction of the largest (the two-rod linkage's GGL form
#: stalls at rtol 1e-9 where it is 1.5e-3, passing a singular configuration of its loop).
NEAR_SINGULAR = 1e-2
#: What a model's evaluation raises at a state where it is not defined.
_FAILURES = (ModelError, ValueError, ZeroDivisionError, FloatingPointError,
             np.linalg.LinAlgError)
#: The square root of the unit round-off: the relative size of a difference quotient's step.
_SRUR = float(np.sqrt(np.finfo(float).eps))


class IDASolver:
    """One DAE form (``"index3"`` or ``"ggl"``) of a constrained model, solved by IDA.

    Parameters
    ----------
    constrained : ConstrainedModel
    form : ``"index3"``, ``"ggl"`` or ``"index1"`` (the index-1 system: the constraints at
        the acceleration level, ``lambda`` algebraic of index 1)
    route : one of :data:`ROUTES`
        Where the residual runs (default ``"auto"``; ``$DUALMECH_IDA_ROUTE`` overrides):
        generated C called by IDA in C (:mod:`~dualmech.numeric.ida`), or the Python
        :meth:`residual` called by scikit-sundae at every evaluation.

    Attributes
    ----------
    route : ``"C"`` or ``"Python"``
        The route the next run takes (``"auto"`` resolved; a failed build turns it to
        ``"Python"``).
    fallback : str
        Why the compiled route does not run here (empty when it does or was not asked).

    Example
    -------
    >>> from dualmech.problems import get
    >>> from dualmech.numeric.formulations import formulations
    >>> forms, _ = formulations(get("pendulum_particle"), stabilisations=("ggl",))
    >>> f = [f for f in forms if f.dae_solver is not None][0]
    >>> c, py = IDASolver(f.constrained, "ggl"), IDASolver(f.constrained, "ggl", "Python")
    >>> a = c.run((0, 1), f.y0, [0.5, 1.0], rtol=1e-8, atol=1e-10)
    >>> b = py.run((0, 1), f.y0, [0.5, 1.0], rtol=1e-8, atol=1e-10)
    >>> c.route if c.route == "C" else c.fallback, c.calls, a.calls > 100  # no Python calls
    ('C', 0, True)
    >>> bool(abs(a.y - b.y).max() < 1e-6)    # both within their error (~1e-7) of the motion
    True
    """

    def __init__(self, constrained, form: str, route: str | None = None):
        if form not in IDA_FORMS:
            raise ValueError(f"`form` must be one of {IDA_FORMS}, got {form!r}.")
        route = route or os.environ.get("DUALMECH_IDA_ROUTE", "auto")
        if route not in ROUTES:
            raise ValueError(f"`route` must be one of {ROUTES}, got {route!r}.")
        self.cm, self.form = constrained, form
        self.fallback, self._compiled = "", None
        self.route, self._asked = route, route
        if route == "auto":
            why = ida.available()
            self.route, self.fallback = ("C", "") if why is None else ("Python", why)
        self.n, self.k = constrained.n, constrained.k
        self.size = 2 * self.n + self.k * (2 if form == "ggl" else 1)
        #: coordinates that enter a constraint (their velocities are index-2 variables)
        self.constrained = np.array([any(row[j] != 0 for row in constrained.constraints.gradients)
                                     for j in range(self.n)])
        self.calls = 0
        self._meter = _Meter(None)

    def residual(self, t: float, y: np.ndarray, yp: np.ndarray, res: np.ndarray) -> None:
        """IDA's residual ``F(t, y, y') = 0`` written into ``res``."""
        n, k = self.n, self.k
        self.calls += 1
        self._meter.charge(t)
        q, v, lam = y[:n], y[n:2 * n], y[2 * n:2 * n + k]
        A, b = self.cm.numeric.system(t, q, v)
        res[:n] = yp[:n] - v
        res[n:2 * n] = A[:n, :n] @ yp[n:2 * n] + A[:n, n:] @ lam - b[:n]
        g, _ = self.cm.residuals(q, v)
        res[2 * n:2 * n + k] = g
        if self.form == "ggl":
            G = self.cm.gradient(q)
            res[:n] += G.T @ y[2 * n + k:]
            res[2 * n + k:] = G @ v
        elif self.form == "index1":  # the acceleration-level rows of the index-1 system
            res[2 * n:] = A[n:, :n] @ yp[n:2 * n] + A[n:, n:] @ lam - b[n:]

    def typical(self, y: np.ndarray, tol: np.ndarray, rtol: float) -> np.ndarray:
        """Each component's typical size, the scale of the Jacobian's difference quotients:
        ``atol / rtol`` for a component in the error test (its range, as the charts set
        ``atol``), else the start's magnitude (at least 1: a multiplier may start at 0)."""
        typ = np.maximum(np.abs(y), 1.0)
        tested = (tol < _EXCLUDED) & (tol > 0)
        typ[tested] = tol[tested] / rtol
        return typ

    def _near_singular(self, q: np.ndarray) -> str:
        """A clause naming a nearly singular configuration of the loop at ``q`` (the
        constraint gradients' smallest singular value below :data:`NEAR_SINGULAR` of the
        largest), where the maximal-coordinate DAE is singular; else ``""``."""
        try:
            s = np.linalg.svd(self.cm.gradient(q), compute_uv=False)
        except (ValueError, np.linalg.LinAlgError):
            return ""
        if not (s.size and np.isfinite(s).all() and s[-1] < NEAR_SINGULAR * s[0]):
            return ""
        return (f"; the constraint gradients are nearly dependent there (smallest singular "
                f"value {s[-1]:.3g}, largest {s[0]:.3g}): a singular configuration of the "
                "loop, where the DAE in maximal coordinates is singular -- integrate the "
                "minimal-coordinate model through it, or loosen the tolerance")

    def initial(self, time: float, y0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A consistent ``(y, y')`` from ``y0 = [q, v]`` (projected onto the manifold)."""
        n = self.n
        y0 = self.cm.project(time, np.asarray(y0, dtype=float))
        x = self.cm.numeric.solve(time, y0[:n], y0[n:])
        y = np.concatenate([y0, x[n:], np.zeros(self.size - 2 * n - self.k)])
        yp = np.concatenate([y0[n:], x[:n], np.zeros(self.size - 2 * n)])
        return y, yp

    def run(self, t_span: Sequence[float], y0, t_eval, *, rtol: float, atol,
            max_steps: int = 500_000, budget: WorkBudget | None = None) -> Run:
        """Integrate from ``y0 = [q, v]``; the :class:`Run` holds ``[q; v]`` at ``t_eval``.

        Past ``budget`` (CPU seconds and residual calls,
        :class:`~dualmech.numeric.integrators.WorkBudget`) the run ends as *did not finish*.
        The compiled residual runs when :attr:`route` is ``"C"``; otherwise the Python
        residual, and ``message`` begins with ``"fallback: "`` and the reason."""
        n = self.n
        t_eval = np.asarray(t_eval, dtype=float)
        y0 = np.asarray(y0, dtype=float)
        if y0.shape != (2 * n,) or not np.isfinite(y0).all():
            raise ValueError(f"`y0` must hold {2 * n} finite numbers (q then v), got "
                             f"{y0.tolist()}.")
        if self.route == "C" and self._compiled is None:  # built before the clock starts
            try:
                self._compiled = ida.compiled_residual(self.cm, self.form, y0[:n])
            except IdaUnavailable as exc:
                if self._asked == "C":
                    raise
                self.route, self.fallback = "Python", str(exc)
            except _FAILURES as exc:  # the constraints are not defined at the start
                return Run(method="IDA", t=t_eval[:0].copy(), y=np.empty((2 * n, 0)),
                           success=False, message=f"IDA failed: {exc}", cpu=0.0, calls=0,
                           evaluations=0, steps=0, t_end=float(t_span[0]))
        start = _time.process_time()
        tol = np.full(self.size, _EXCLUDED)
        tol[:2 * n] = np.broadcast_to(np.asarray(atol, dtype=float), (2 * n,))
        if self.form == "index3":  # index-2 velocities: those of coordinates the loop holds
            tol[n:2 * n][self.constrained] = _EXCLUDED
        t0, t1 = float(t_span[0]), float(t_span[1])
        try:
            y, yp = self.initial(t0, y0)
        except _FAILURES as exc:
            return Run(method="IDA", t=t_eval[:0].copy(), y=np.empty((2 * n, 0)),
                       success=False, message=f"IDA failed: {exc}",
                       cpu=_time.process_time() - start, calls=0, evaluations=0, steps=0,
                       t_end=t0)
        if self.route == "C":
            return self._run_compiled(t0, y, yp, tol, t_eval, rtol, max_steps, budget, start)
        run = self._run_python(t0, t1, y, yp, tol, t_eval, rtol, max_steps, budget, start)
        if self.fallback:
            run = replace(run, message=f"fallback: {self.fallback}; IDA ran the Python "
                          f"residual. {run.message}")
        return run

    def _run_compiled(self, t0, y, yp, tol, t_eval, rtol, max_steps, budget, start) -> Run:
        n = self.n
        first = t_eval <= t0
        tout = t_eval[~first]
        if budget is not None and budget.seconds is not None:  # the set-up counts too
            spent = _time.process_time() - start
            budget = WorkBudget(max(budget.seconds - spent, 1e-9), budget.evaluations)
        out = {"y": np.empty((2 * n, 0)), "steps": 0, "calls": 0, "jacobians": 0,
               "ok": True, "message": "IDA (compiled residual)", "t_end": t0}
        if tout.size:
            differential = np.ones(self.size)
            differential[2 * n:] = 0.0
            out = ida.run_compiled(self._compiled, t0, y, yp, tol, differential,
                                   self.typical(y, tol, rtol), tout, 2 * n, rtol, max_steps,
                                   budget)
        ys = np.concatenate([np.tile(y[:2 * n, None], (1, int(first.sum()))), out["y"]],
                            axis=1)
        m = ys.shape[1]
        message = out["message"]
        if not out["ok"] and not message.startswith(DID_NOT_FINISH):
            message += self._near_singular(out["last"][:n])
        return Run(method="IDA", t=t_eval[:m].copy(), y=ys, success=out["ok"],
                   message=message, cpu=_time.process_time() - start,
                   calls=out["calls"], evaluations=out["calls"], steps=out["steps"],
                   jacobians=out["jacobians"], factorisations=out["jacobians"],
                   t_end=float(t_eval[m - 1]) if m else t0)

    def _run_python(self, t0, t1, y, yp, tol, t_eval, rtol, max_steps, budget,
                    start) -> Run:
        import sksundae as sun
        n = self.n
        self.calls = 0
        self._meter = _Meter(budget)
        typical = self.typical(y, tol, rtol)

        def jacobian(t, yv, ypv, res, cj, JJ):  # the C route's quotients (ida_driver.dm_J)
            f, yv, ypv = np.empty(self.size), yv.copy(), ypv.copy()
            for j in range(self.size):
                yj, vj = yv[j], ypv[j]
                inc = (yj + _SRUR * max(abs(yj), typical[j])) - yj
                yv[j], ypv[j] = yj + inc, vj + cj * inc
                self.residual(t, yv, ypv, f)
                yv[j], ypv[j] = yj, vj
                JJ[:, j] = (f - res) / inc

        solver = sun.ida.IDA(self.residual, rtol=rtol, atol=tol, max_num_steps=max_steps,
                             algebraic_idx=list(range(2 * n, self.size)), jacfn=jacobian)
        ys, k, steps, ok, message, njev = [], 0, 0, True, "IDA", 0
        try:
            while k < t_eval.size and t_eval[k] <= t0:
                ys.append(y[:2 * n].copy())
                k += 1
            solver.init_step(t0, y, yp)
            now = t0
            while k < t_eval.size:
                out = solver.step(t1, method="onestep", tstop=t1)
                if not out.success:
                    ok, message = False, f"IDA stopped at t={now:.6g}: {out.message}" \
                        + self._near_singular(np.asarray(out.y)[:n])
                    break
                # after an interpolated sample IDA's next one-step call returns the step it
                # had already taken: count the steps that advanced
                steps += float(out.t) > now
                now = float(out.t)
                njev = int(out.njev)
                while k < t_eval.size and t_eval[k] <= now * (1 + 1e-15):
                    ys.append(solver.step(t_eval[k]).y[:2 * n].copy())
                    k += 1
                if steps >= max_steps:
                    ok, message = False, f"IDA stopped at t={now:.6g}: more than " \
                        f"{max_steps} steps" + self._near_singular(np.asarray(out.y)[:n])
                    break
        except BudgetExceeded as exc:
            ok, message = False, str(exc)
        except (RuntimeError,) + _FAILURES as exc:
            ok, message = False, f"IDA failed: {exc}"
        y_out = np.array(ys).T if ys else np.empty((2 * n, 0))
        return Run(method="IDA", t=t_eval[: len(ys)].copy(), y=y_out,
                   success=ok and len(ys) == t_eval.size, message=message,
                   cpu=_time.process_time() - start, calls=self.calls,
                   evaluations=self.calls, steps=steps, jacobians=njev, factorisations=njev,
                   t_end=float(t_eval[len(ys) - 1]) if ys else t0)
