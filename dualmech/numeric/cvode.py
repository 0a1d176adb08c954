"""Integration with no Python per step: SUNDIALS CVODE driving the generated C right-hand side.

:func:`integrate` runs a :class:`~dualmech.numeric.model.NumericModel`'s equations of motion
from ``t_span[0]`` to ``t_span[1]`` and returns the states at the requested sample times
(CVODE's own interpolant between its steps) as a :class:`~dualmech.numeric.integrators.Run`
with the work counted.  Methods:

* ``"CVODE-Adams"`` (the default, ``"auto"``): variable-order Adams--Moulton with fixed-point
  iteration, no Jacobian -- the non-stiff method, and the fastest on the catalogue's scenes;
* ``"CVODE-BDF"``: variable-order BDF with Newton's method and a dense difference-quotient
  Jacobian, for stiff scenes;
* any of scipy's methods (``"DOP853"``, ``"RK45"``, ``"Radau"``, ``"BDF"``, ``"LSODA"``):
  :func:`scipy.integrate.solve_ivp` on the generated right-hand side (compiled C where a
  compiler exists), the route every CVODE run can be checked against.

The CVODE route needs a C compiler and SUNDIALS 7's libraries from scikit-sundae's wheel
(:mod:`~dualmech.numeric.cvode_driver` says why that route, and checks both).  Where either is
missing, ``method="auto"`` **falls back** to scipy's ``DOP853`` on the generated right-hand side
and says so in ``Run.message`` (:data:`FALLBACK`); a CVODE method asked for by name raises
:class:`CvodeUnavailable` instead.  A model driven by given inputs runs on CVODE with their
closed forms and tables evaluated in the C (:mod:`~dualmech.numeric.input_code`); one with a
Python function as an input takes the same fallback, the reason in ``Run.message``.  A state where the mass matrix is singular ends the run
with :class:`~dualmech.numeric.model.SingularityError`, on either route, and so does the motion
reaching a declared singular set (``singular``: CVODE's root finding on the expressions
compiled to C, :mod:`~dualmech.numeric.cvode_events`), which the steps may otherwise cross
unseen.

:func:`integrate_until` runs CVODE to the first sign change of any event function of a
:class:`~dualmech.numeric.cvode_events.Stops` -- one-sided reactions (rows of a direct model's
compiled solve), coordinate bounds, a singular set -- and says which stopped it (:class:`Hit`):
the compiled route of :func:`dualmech.numeric.contacts.watch`.

Example
-------
>>> import numpy as np, sympy as sp
>>> from dualmech import EquationSet, coordinate, t
>>> from dualmech.numeric import NumericModel
>>> x = coordinate("x"); m, k = sp.symbols("m k", positive=True)
>>> model = NumericModel(EquationSet("spring", (x,), (m*x.diff(t, 2) + k*x,)), {m: 1, k: 1})
>>> run = integrate(model, (0, np.pi), [1.0, 0.0], t_eval=[np.pi / 2, np.pi], rtol=1e-10,
...                 atol=1e-12)
>>> np.round(run.y[0], 7).tolist() == [0.0, -1.0]   # cos(t) at pi/2 and pi
True
"""
from __future__ import annotations

import ctypes
import time as _time
from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np
from scipy.integrate import solve_ivp

from dualmech.numeric import cbackend
from dualmech.numeric.cvode_driver import CvodeUnavailable, driver
from dualmech.numeric.cvode_events import SingularSet, Stops
from dualmech.numeric.integrators import SCIPY_METHODS, Run
from dualmech.numeric.model import _C_MAX, NumericModel

__all__ = ["CVODE_METHODS", "FALLBACK", "METHODS", "CvodeUnavailable", "Hit", "available",
           "integrate", "integrate_until"]

CVODE_METHODS = ("CVODE-Adams", "CVODE-BDF")
#: Every method :func:`integrate` takes (``"auto"`` picks the first that can run).
METHODS = ("auto",) + CVODE_METHODS + SCIPY_METHODS
#: The route ``method="auto"`` falls back to where CVODE cannot run.
FALLBACK = "DOP853"
#: CVODE steps allowed between two samples before the run is stopped as too much work.
MAX_STEPS = 1_000_000
_SLOW = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_double, ctypes.POINTER(ctypes.c_double),
                         ctypes.POINTER(ctypes.c_double))


def available() -> str | None:
    """``None`` when the CVODE route can run here, else the reason it cannot (one line)."""
    try:
        driver()
    except CvodeUnavailable as exc:
        return str(exc)
    return None


def integrate(model: NumericModel, t_span: Sequence[float], y0, *, t_eval=None,
              rtol: float = 1e-9, atol: float = 1e-11, method: str = "auto",
              singular: Sequence = ()) -> Run:
    """Integrate ``model``'s equations of motion over ``t_span`` from ``y0 = [q, q']``.

    Parameters
    ----------
    model : NumericModel
        A square system (equations of motion, no reactions left unknown).
    t_span : (start, end)
        Forward or backward.
    y0 : sequence of 2n numbers
    t_eval : increasing (decreasing for a backward span) sample times inside ``t_span``;
        default: the end time only.
    rtol, atol : float
        Relative and absolute tolerances (scalar), as scipy and CVODE define them.
    method : one of :data:`METHODS`
    singular : expressions in the model's coordinates whose zeros are its singular set
        (:attr:`Problem.singular <dualmech.model.problem.Problem.singular>`): the run stops
        where one changes sign (CVODE's root finding, scipy's terminal events) with
        :class:`SingularityError`, instead of stepping across the set unseen.

    Returns
    -------
    Run
        ``method`` is the route that ran, ``cpu`` the integration's CPU seconds alone (the
        code is compiled and loaded before the clock starts); on the fallback ``message``
        begins with ``"fallback: "`` and the reason.  ``steps`` counts CVODE's steps; scipy's
        (``solve_ivp`` with ``t_eval``) are not counted and left at 0.

    Raises
    ------
    SingularityError
        The motion reached a state where the mass matrix is singular, or the declared
        singular set.
    CvodeUnavailable
        A CVODE method was asked for by name and cannot run here.
    """
    if method not in METHODS:
        raise ValueError(f"`method` must be one of {', '.join(METHODS)}, got {method!r}.")
    t0, t1, y0 = _start(model, t_span, y0)
    t_eval = _samples(t0, t1, t_eval)
    if model.shape[0] != model.shape[1]:
        raise ValueError(f"model `{model.eqs.name}` is not square ({model.shape}): integrate "
                         "the equations of motion (the reference model), not a direct model "
                         "with its reactions.")
    events = Stops(model, singular)
    slow = getattr(model, "inputs_in_python", None)
    if slow and method in CVODE_METHODS:
        raise CvodeUnavailable(f"CVODE runs compiled code only: {slow}.")
    if slow and method == "auto":   # a Python function per step: scipy's route
        run = _scipy(model, t0, t1, y0, t_eval, rtol, atol, FALLBACK, events.singular)
        return replace(run, message=f"fallback: {slow}; used scipy {FALLBACK} instead. "
                       + run.message)
    if method == "auto":
        try:
            return _singular(*_cvode(model, t0, t1, y0, t_eval, rtol, atol, CVODE_METHODS[0],
                                     events), events)
        except CvodeUnavailable as exc:
            run = _scipy(model, t0, t1, y0, t_eval, rtol, atol, FALLBACK, events.singular)
            return replace(run, message=f"fallback: {exc}; used scipy {FALLBACK} instead. "
                           + run.message)
    if method in CVODE_METHODS:
        return _singular(*_cvode(model, t0, t1, y0, t_eval, rtol, atol, method, events),
                         events)
    return _scipy(model, t0, t1, y0, t_eval, rtol, atol, method, events.singular)


def _singular(run: Run, hit, events: Stops) -> Run:
    if hit is not None:  # an event function changed sign: the singular set
        raise events.singular.error(hit.time, hit.y)
    return run


@dataclass(frozen=True)
class Hit:
    """Where an event function of :func:`integrate_until` stopped the run: its index in
    ``stops.labels()``, the time and the state ``y = [q, q']`` there."""

    index: int
    label: str
    time: float
    y: tuple


def integrate_until(model: NumericModel, t_span: Sequence[float], y0, stops: Stops, *,
                    t_eval=None, rtol: float = 1e-9, atol: float = 1e-11,
                    method: str = "CVODE-Adams") -> tuple[Run, Hit | None]:
    """Integrate on CVODE until the first event function of ``stops`` changes sign in its
    direction (CVODE's root finding on the functions compiled to C), or to the end.

    The samples (``t_eval``, as :func:`integrate` takes them) are those before the event;
    ``Run.t_end`` is where the run stopped.  There is no fallback here: where CVODE cannot run,
    :class:`CvodeUnavailable` says why (the caller takes its own scipy route).

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import EquationSet, coordinate, t
    >>> from dualmech.numeric.cvode_events import Bound
    >>> x = coordinate("x"); g = sp.Symbol("g", positive=True)
    >>> model = NumericModel(EquationSet("fall", (x,), (x.diff(t, 2) + g,)), {g: 9.81})
    >>> run, hit = integrate_until(model, (0, 5), [2.0, 0.0],
    ...                            Stops(model, bounds=[Bound(0, 0.0, -1, "x reaches 0")]))
    >>> hit.label, bool(abs(hit.time - np.sqrt(2 * 2.0 / 9.81)) < 1e-9)   # x = 2 - g t^2 / 2
    ('x reaches 0', True)
    """
    if method not in CVODE_METHODS:
        raise ValueError(f"`method` must be one of {', '.join(CVODE_METHODS)}, got {method!r}.")
    t0, t1, y0 = _start(model, t_span, y0)
    if getattr(model, "inputs_in_python", None):
        raise CvodeUnavailable(f"CVODE runs compiled code only: {model.inputs_in_python}.")
    return _cvode(model, t0, t1, y0, _samples(t0, t1, t_eval), rtol, atol, method, stops)


def _start(model, t_span, y0) -> tuple:
    """``(t0, t1, y0)`` as floats, ``y0`` checked against the model's state size."""
    y0 = np.asarray(y0, dtype=float)
    if y0.shape != (2 * model.n,) or not np.isfinite(y0).all():
        raise ValueError(f"`y0` must hold {2 * model.n} finite numbers (q then q'), got "
                         f"{y0.tolist()}.")
    return float(t_span[0]), float(t_span[1]), y0


def _samples(t0: float, t1: float, t_eval) -> np.ndarray:
    if not (np.isfinite(t0) and np.isfinite(t1)) or t0 == t1:
        raise ValueError(f"`t_span` must be two different finite numbers, got {(t0, t1)}.")
    if t_eval is None:
        return np.array([t1])
    t_eval = np.asarray(t_eval, dtype=float).ravel()
    sign = 1.0 if t1 > t0 else -1.0
    inside = (sign * (t_eval - t0) >= 0) & (sign * (t1 - t_eval) >= 0)
    if t_eval.size == 0 or not inside.all() or (np.diff(t_eval) * sign <= 0).any():
        raise ValueError(f"`t_eval` must be sample times from {t0:g} to {t1:g}, in order.")
    return t_eval


def _scipy(model, t0, t1, y0, t_eval, rtol, atol, method, events: SingularSet) -> Run:
    fast = model if model.backend != "auto" or cbackend.compiler() is None \
        or getattr(model, "_inputs", None) else model.with_backend("c")
    fast.rhs(t0, y0)  # compiled and loaded before the clock starts
    stops = events.scipy_events()
    start = _time.process_time()
    sol = solve_ivp(fast.rhs, (t0, t1), y0, method=method, t_eval=t_eval, rtol=rtol,
                    atol=atol, events=stops or None)
    cpu = _time.process_time() - start
    if sol.status == 1:  # a terminal event: the singular set
        hit = next(i for i, ts in enumerate(sol.t_events) if len(ts))
        raise events.error(float(sol.t_events[hit][0]), sol.y_events[hit][0])
    t = np.asarray(sol.t, dtype=float)   # a list when the run fails before any t_eval
    y = np.asarray(sol.y, dtype=float).reshape(len(y0), t.size)
    return Run(method=method, t=t, y=y, success=sol.status >= 0, message=sol.message,
               cpu=cpu, calls=int(sol.nfev), evaluations=int(sol.nfev),
               steps=max(t.size - 1, 0), jacobians=int(sol.njev),
               factorisations=int(sol.nlu), t_end=float(t[-1]) if t.size else t0)


def _cvode(model, t0, t1, y0, t_eval, rtol, atol, method, events) -> Run:
    if model.shape[1] > _C_MAX:
        raise CvodeUnavailable(f"{model.shape[1]} unknowns: the compiled solve takes at most "
                               f"{_C_MAX}.")
    run_c = driver()
    code = model.c_code   # the model's C library (its given inputs compiled in)
    one = cbackend.load(code.key, code.c_source)
    if one is None:
        raise CvodeUnavailable("the model's right-hand side is not compiled and no C compiler "
                               "was found (set $CC, or install gcc).")
    n2 = 2 * model.n
    failure: list = []
    gslow = _SLOW(lambda t, y, g: _exact_events(events, t, y, g, n2, failure))
    spec = events.c_spec(gslow) if len(events) else None
    if len(events) and spec is None:
        raise CvodeUnavailable("the event functions (singular set, reactions) did not compile "
                               "to C.")
    p, k = (np.ascontiguousarray(a, dtype=float) for a in model._c_args)
    work = np.zeros(2 * n2 + model.shape[1])
    first = t_eval == t0  # CVODE starts there; those samples are y0 itself
    tout = np.ascontiguousarray(t_eval[~first])
    yout = np.zeros((tout.size, n2))
    stats = np.zeros(6, dtype=np.int64 if ctypes.sizeof(ctypes.c_long) == 8 else np.int32)
    reached, ylast = ctypes.c_double(t0), np.zeros(n2)
    msg = ctypes.create_string_buffer(256)
    exact = []

    def slow(t, y, ydot):  # a state the compiled solve flagged: decided exactly
        try:
            if not exact:
                exact.append(model.with_backend("python"))
            f = exact[0].rhs(t, np.ctypeslib.as_array(y, (n2,)).copy())
            np.ctypeslib.as_array(ydot, (n2,))[:] = f
            return 0
        except Exception as exc:  # noqa: BLE001 - re-raised below, once CVODE has returned
            failure.append(exc)
            return 1

    callback = _SLOW(slow)
    lmm = 1 if method == "CVODE-Adams" else 2
    start = _time.process_time()
    flag = 0
    if tout.size:
        flag = run_c(one[0], p.ctypes.data, k.ctypes.data, work.ctypes.data, callback, n2, lmm,
                     t0, y0.ctypes.data, tout.size, tout.ctypes.data, yout.ctypes.data,
                     float(rtol), float(atol), MAX_STEPS, stats.ctypes.data,
                     ctypes.byref(reached), msg, len(msg),
                     ctypes.byref(spec) if spec is not None else None, ylast.ctypes.data)
    cpu = _time.process_time() - start
    if failure:
        raise failure[0]
    hit = None
    if flag == 2:  # an event function changed sign
        which = events.found()
        hit = Hit(which, events.labels()[which], reached.value, tuple(map(float, ylast)))
    done = int(stats[0])
    y = np.concatenate([np.tile(y0, (int(first.sum()), 1)), yout[:done]]).T
    message = "the end of the span was reached" if flag == 0 else \
        f"CVODE stopped at t={reached.value:.9g}: {msg.value.decode()}" if hit is None else \
        f"stopped at t={reached.value:.9g}, where {hit.label} changes sign"
    run = Run(method=method, t=t_eval[: y.shape[1]].copy(), y=y, success=flag in (0, 2),
              message=message, cpu=cpu, calls=int(stats[2]), evaluations=int(stats[2]),
              steps=int(stats[1]), jacobians=int(stats[5]), factorisations=int(stats[4]),
              t_end=reached.value if tout.size else t0)
    return run, hit


def _exact_events(events: Stops, t, y, gout, n2: int, failure: list) -> int:
    """The driver's callback for a state where a compiled solve flagged: every event value
    in Python, exactly decided (a singular system stops the run, its error kept)."""
    try:
        values = events.values(t, np.ctypeslib.as_array(y, (n2,)).copy())
        np.ctypeslib.as_array(gout, (len(events),))[:] = values
        return 0
    except Exception as exc:  # noqa: BLE001 - re-raised once CVODE has returned
        failure.append(exc)
        return 1
