"""Integrators behind one call, with the work they did counted.

:func:`integrate` runs scipy's ``RK45``, ``DOP853``, ``Radau``, ``BDF`` or ``LSODA`` (through
:func:`scipy.integrate.solve_ivp` with dense output, so the accepted steps are counted and the
samples come from each method's own interpolant), or a symplectic
method of :mod:`~dualmech.numeric.symplectic` on the canonical state ``(q, p = M q')`` of a
natural conservative model (:class:`~dualmech.numeric.energy.EnergyFunction`): ``"midpoint"``
(implicit midpoint, Newton's method), ``"verlet"`` (Stormer--Verlet, constant mass matrix) or
``"rattle"`` (Verlet with holonomic constraints) -- their energy error stays bounded over
long runs instead of drifting.

Every :class:`Run` says what it cost: CPU seconds, right-hand-side calls, states evaluated
(a vectorised call evaluates many -- the implicit methods' finite-difference Jacobians),
accepted steps, Jacobians and LU factorisations.  A :class:`WorkBudget` (CPU seconds and states
evaluated) ends a run that would spend more as a *did not finish* run
(:data:`DID_NOT_FINISH` opens its message; ``success = False``, ``t_end`` where it got to)
instead of letting it stall.  With ``projector`` (a callable
``(t, y) -> y``) the run is cut at every sample time and the state projected there (see
:class:`~dualmech.numeric.dae.ConstrainedModel`).

Example
-------
>>> import numpy as np
>>> run = integrate(lambda t, y: np.array([y[1], -y[0]]), (0, np.pi), [0.0, 1.0], "DOP853",
...                 t_eval=np.linspace(0, np.pi, 3), rtol=1e-10, atol=1e-12)
>>> run.success, np.round(run.y[0], 8).tolist()
(True, [0.0, 1.0, 0.0])
"""
from __future__ import annotations

import time as _time
from dataclasses import dataclass, field, replace
from typing import Callable, Sequence

import numpy as np
from scipy.integrate import solve_ivp

from dualmech.numeric.model import SingularityError

__all__ = ["Run", "integrate", "WorkBudget", "BudgetExceeded", "DID_NOT_FINISH", "METHODS", "SCIPY_METHODS", "EXPLICIT", "IMPLICIT",
           "STRUCTURE_PRESERVING", "SYMPLECTIC", "IntegrationError"]

SCIPY_METHODS = ("RK45", "DOP853", "Radau", "BDF", "LSODA")
STRUCTURE_PRESERVING = ("midpoint",)
METHODS = SCIPY_METHODS + STRUCTURE_PRESERVING
#: Every fixed-step symplectic method (``verlet`` and ``rattle`` only where they apply).
SYMPLECTIC = ("midpoint", "verlet", "rattle")
EXPLICIT = ("RK45", "DOP853")
IMPLICIT = ("Radau", "BDF")


class IntegrationError(RuntimeError):
    """An integrator could not go on; the message says where and what to change."""


#: How the message of a run cut by its :class:`WorkBudget` begins.
DID_NOT_FINISH = "did not finish"


class BudgetExceeded(IntegrationError):
    """A run spent its :class:`WorkBudget`; ``t`` is the last time it evaluated."""

    def __init__(self, message: str, t: float):
        super().__init__(message)
        self.t = float(t)


@dataclass(frozen=True)
class WorkBudget:
    """The most work one run may do: CPU seconds of this process and states evaluated.

    ``None`` leaves a measure unbounded.  :meth:`meter` starts the clock; the meter's
    :meth:`~_Meter.charge` raises :class:`BudgetExceeded` once either is spent.  CPU time,
    not wall time: on a shared machine a wall-clock budget would cut runs that other
    processes slowed down.

    Example
    -------
    >>> meter = WorkBudget(seconds=None, evaluations=3).meter()
    >>> meter.charge(0.0, 3)
    >>> try:
    ...     meter.charge(0.5, 1)
    ... except BudgetExceeded as exc:
    ...     print(exc)
    did not finish: 4 states evaluated at t=0.5 s, over the budget of 3
    """

    seconds: float | None = None
    evaluations: int | None = None

    def __post_init__(self):
        for name in ("seconds", "evaluations"):
            v = getattr(self, name)
            if v is not None and not v > 0:
                raise ValueError(f"`{name}` of a budget must be positive or None, got {v!r}.")

    def meter(self) -> "_Meter":
        return _Meter(self)

    def __str__(self) -> str:
        parts = ([f"{self.seconds:g} s of CPU"] if self.seconds else []) + \
            ([f"{self.evaluations} states evaluated"] if self.evaluations else [])
        return " or ".join(parts) or "unbounded"


class _Meter:
    """One run's spending against a :class:`WorkBudget` (see :meth:`WorkBudget.meter`)."""

    def __init__(self, budget: WorkBudget | None):
        self.budget = budget or WorkBudget()
        self.start, self.evaluations = _time.process_time(), 0

    def charge(self, t: float, evaluations: int = 1) -> None:
        """Count ``evaluations`` states evaluated at time ``t``; raise when over budget."""
        self.evaluations += evaluations
        b = self.budget
        if b.evaluations is not None and self.evaluations > b.evaluations:
            raise BudgetExceeded(f"{DID_NOT_FINISH}: {self.evaluations} states evaluated at "
                                 f"t={float(t):.6g} s, over the budget of {b.evaluations}", t)
        if b.seconds is not None:
            spent = _time.process_time() - self.start
            if spent > b.seconds:
                raise BudgetExceeded(f"{DID_NOT_FINISH}: {spent:.3g} s of CPU spent by "
                                     f"t={float(t):.6g} s, over the budget of "
                                     f"{b.seconds:g} s", t)


@dataclass(frozen=True, kw_only=True, eq=False)
class Run:
    """One integration: the samples it reached and the work it took.

    Attributes
    ----------
    method : str
        The integrator: one of :data:`METHODS`, :data:`SYMPLECTIC` or ``"IDA"``.
    t : ndarray, shape (N,)
        Sample times reached [s], increasing: the requested ``t_eval`` up to where the
        run stopped.
    y : ndarray, shape (m, N)
        The state at each sample, one column per time (``m = 2 n`` for ``n`` coordinates:
        the coordinates [m or rad] then their rates [per s]; a symplectic method's rates
        are the velocities of its canonical state).
    success : bool
        False when the method stopped early; ``t`` and ``y`` then hold what it reached.
    message : str
        The integrator's own word on how it ended (why it stopped, when it did).
    cpu : float
        Process time of the integration [s].
    calls : int
        Right-hand-side calls.
    evaluations : int
        States evaluated: a vectorised call (the implicit methods' finite-difference
        Jacobians) evaluates many.
    steps : int
        Accepted steps.
    jacobians, factorisations : int
        Jacobian evaluations and LU factorisations (0 for the explicit methods).
    t_end : float
        Time where the run stopped [s] (``nan`` when it stopped before a first step).
    events : list of list of float
        The event times [s], one list per event function.
    event_states : list of ndarray
        The states there, one ``(k, m)`` array per event function (a guarded probe
        keeps its last accepted state here).
    nodes : (ndarray (K,), ndarray (m, K)) or None
        A fixed-step method's own steps, times and states (``None`` for the others):
        measures that are properties of the steps (a symplectic method's bounded energy
        error) are taken there, not on the interpolated samples.

    Example
    -------
    >>> run = Run(method="RK45", t=np.array([0.0]), y=np.zeros((2, 1)), success=True,
    ...           message="", cpu=0.0, calls=0, evaluations=0, steps=0)
    >>> run.y.shape, run.t_end
    ((2, 1), nan)
    """

    method: str
    t: np.ndarray
    y: np.ndarray
    success: bool
    message: str
    cpu: float
    calls: int
    evaluations: int
    steps: int
    jacobians: int = 0
    factorisations: int = 0
    t_end: float = float("nan")
    events: list = field(default_factory=list)
    event_states: list = field(default_factory=list)
    nodes: tuple | None = None


class _Counted:
    """A right-hand side that counts its calls and the states it evaluated (and charges
    them to a budget's meter)."""

    def __init__(self, fun: Callable, budget: WorkBudget | None = None):
        self.fun, self.calls, self.evaluations = fun, 0, 0
        self.meter = _Meter(budget)

    def __call__(self, t, y):
        self.calls += 1
        k = 1 if np.ndim(y) == 1 else np.shape(y)[1]
        self.evaluations += k
        self.meter.charge(t, k)
        return self.fun(t, y)


def integrate(fun: Callable, t_span: Sequence[float], y0, method: str, *,
              t_eval: np.ndarray, rtol: float = 1e-6, atol: float | np.ndarray = 1e-9,
              step: float | None = None, events: Sequence[Callable] = (),
              projector: Callable | None = None, hamiltonian=None,
              constraint: tuple | None = None, max_steps: int = 2_000_000,
              budget: WorkBudget | None = None) -> Run:
    """Integrate ``y' = fun(t, y)`` (vectorised ``fun`` accepted) and count the work.

    Parameters
    ----------
    method : one of :data:`METHODS` or :data:`SYMPLECTIC`
    t_eval : sample times inside ``t_span`` (increasing)
    rtol, atol : scipy's tolerances (ignored by the symplectic methods)
    step : the fixed step of a symplectic method (required there)
    events : scipy-style event functions (``terminal`` honoured)
    projector : ``(t, y) -> y`` applied at every sample time (scipy methods)
    hamiltonian : :class:`~dualmech.numeric.energy.EnergyFunction`, for a symplectic method
    constraint : ``(g, G)`` for ``"rattle"``: ``g(q)`` the constraint residuals, ``G(q)``
        their gradients
    budget : :class:`WorkBudget`, optional
        The most the run may spend (scipy methods; the symplectic methods' fixed steps
        bound their work already); past it the run ends as *did not finish*.

    Notes
    -----
    A :class:`~dualmech.numeric.model.SingularityError` raised by ``fun`` ends the run with
    ``success = False`` and its message (nothing is hidden, nothing goes on).
    """
    if method not in METHODS + SYMPLECTIC:
        raise ValueError(f"`method` must be one of {METHODS + SYMPLECTIC}, got {method!r}.")
    t_eval = np.asarray(t_eval, dtype=float)
    y0 = np.asarray(y0, dtype=float)
    if not t_span[1] > t_span[0]:
        raise ValueError(f"`t_span` must run forward, got {tuple(t_span)}.")
    counted = _Counted(fun, budget)
    start = _time.process_time()
    if method in SYMPLECTIC:
        from dualmech.numeric import symplectic
        if hamiltonian is None or step is None:
            raise ValueError(f"`{method}` needs `hamiltonian` (an EnergyFunction) and `step`.")
        if events or projector is not None:
            raise ValueError(f"`{method}` takes no `events` or `projector`.")
        try:
            if method == "rattle":
                if constraint is None:
                    raise ValueError("`rattle` needs `constraint` = (g, G).")
                run = symplectic.rattle(hamiltonian, *constraint, t_span, y0, t_eval,
                                        float(step), max_steps)
            else:
                run = getattr(symplectic, method)(hamiltonian, t_span, y0, t_eval,
                                                  float(step), max_steps)
        except symplectic.SymplecticError as exc:
            raise IntegrationError(str(exc)) from None
    elif projector is None:
        run = _scipy(counted, t_span, y0, method, t_eval, rtol, atol, events)
    else:
        run = _projected(counted, t_span, y0, method, t_eval, rtol, atol, events, projector)
    cpu = _time.process_time() - start
    if method in SYMPLECTIC:
        return replace(run, cpu=cpu)
    return replace(run, cpu=cpu, calls=counted.calls, evaluations=counted.evaluations)


def _scipy(fun, t_span, y0, method, t_eval, rtol, atol, events, first_step=None) -> Run:
    kwargs = {"vectorized": True} if method in IMPLICIT else {}
    if first_step is not None:
        kwargs["first_step"] = first_step
    try:
        sol = solve_ivp(fun, tuple(t_span), y0, method=method, rtol=rtol, atol=atol,
                        dense_output=True, events=list(events) or None, **kwargs)
    except BudgetExceeded as exc:
        return Run(method=method, t=t_eval[:0], y=np.empty((y0.size, 0)), success=False,
                   message=str(exc), cpu=0.0, calls=0, evaluations=0, steps=0, t_end=exc.t)
    except (SingularityError, ValueError, ZeroDivisionError, FloatingPointError) as exc:
        # a singular system or a state outside the model's domain (a square root of a
        # negative number): the run ends here, with the model's own message
        return Run(method=method, t=t_eval[:0], y=np.empty((y0.size, 0)), success=False,
                   message=str(exc), cpu=0.0, calls=0, evaluations=0, steps=0)
    reached = t_eval[t_eval <= sol.t[-1] + 1e-12 * max(1.0, abs(sol.t[-1]))]
    y = sol.sol(reached) if reached.size else np.empty((y0.size, 0))
    if reached.size and reached[0] == sol.t[0]:
        y[:, 0] = y0
    return Run(method=method, t=reached, y=y, success=sol.status >= 0, message=sol.message,
               cpu=0.0, calls=0, evaluations=0, steps=len(sol.t) - 1,
               jacobians=int(sol.njev), factorisations=int(sol.nlu), t_end=float(sol.t[-1]),
               events=[list(e) for e in (sol.t_events or [])],
               event_states=[np.asarray(e) for e in (sol.y_events or [])])


def _projected(fun, t_span, y0, method, t_eval, rtol, atol, events, projector) -> Run:
    """One scipy run per sample interval, the state projected at each sample."""
    ys, steps, jac, lu = [y0.copy()], 0, 0, 0
    y, first = y0.copy(), None
    for a, b in zip(t_eval[:-1], t_eval[1:]):
        run = _scipy(fun, (a, b), y, method, np.array([a, b]), rtol, atol, events, first)
        steps, jac, lu = steps + run.steps, jac + run.jacobians, lu + run.factorisations
        if not run.success or run.t.size < 2:
            ts = t_eval[: len(ys)]
            return Run(method=method, t=ts, y=np.array(ys).T, success=False,
                       message=run.message, cpu=0.0, calls=0, evaluations=0, steps=steps,
                       jacobians=jac, factorisations=lu,
                       t_end=float(a) if not np.isfinite(run.t_end) else run.t_end,
                       events=run.events, event_states=run.event_states)
        y = projector(b, run.y[:, -1])
        ys.append(y)
        if method not in ("BDF", "LSODA"):  # one-step methods resume with the last step size;
            first = 0.5 * (b - a) / max(run.steps, 1)  # multistep ones restart at order 1
    return Run(method=method, t=t_eval.copy(), y=np.array(ys).T, success=True,
               message="projected at every sample", cpu=0.0, calls=0, evaluations=0,
               steps=steps, jacobians=jac, factorisations=lu, t_end=float(t_eval[-1]))
