"""Stop where the motion reaches a problem's declared singular set, where a one-sided reaction
reaches zero, or where a coordinate reaches a bound: event functions in C.

A problem declares its coordinate singularities as expressions whose zeros are the singular
set (:attr:`Problem.singular <dualmech.model.problem.Problem.singular>`, e.g. ``cos(theta)``
for the toy car).  An integrator stepping across such a zero sees nothing wrong when no step
lands close to it -- the mass matrix is singular only *on* the set -- and goes on with a
motion the equations no longer describe.  :class:`SingularSet` compiles the expressions to C
(:func:`dualmech.numeric.cbackend.c_function_source`) for CVODE's root finding (the driver
stops at the first sign change, located to rounding), and gives the same functions to scipy
as terminal events (:class:`~dualmech.numeric.model.StateFunction`).  :meth:`SingularSet.error`
is the :class:`~dualmech.numeric.model.SingularityError` raised there.

:class:`Stops` gathers every event function of one run for the CVODE driver
(:mod:`~dualmech.numeric.cvode_driver`): the singular set, reactions (:class:`ReactionEvent`:
a row of a direct model's solution ``[q''; lambda]``, computed by that model's compiled library
at the state) and coordinate bounds (:class:`Bound`), each with the direction of the sign change
that stops the run; :meth:`Stops.values` evaluates them in Python (the exact route a state the
compiled solve flags takes).

Example
-------
>>> import sympy as sp
>>> from dualmech.problems import load
>>> from dualmech.numeric import NumericModel
>>> from dualmech.numeric.simulation import problem_parameters
>>> car = load("toy_car")
>>> model = NumericModel(car.model(car.reference), problem_parameters(car))
>>> events = SingularSet(model, car.singular)
>>> [round(float(f(0.0, [1.0, 0.0, 0.0, 0.0])), 6) for f in events.scipy_events()]
[0.540302]
"""
from __future__ import annotations

import ctypes
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import numpy as np

from dualmech.model._expr import as_expr
from dualmech.model.equations import state_symbols, to_plain
from dualmech.model.kinematics import t
from dualmech.numeric import cbackend, codegen
from dualmech.numeric._cache import cache_dir, digest, private_dir
from dualmech.numeric.model import NumericModel, SingularityError, StateFunction

__all__ = ["Bound", "ReactionEvent", "SingularSet", "Stops"]

_LOADED: dict = {}
_KEPT: list = []


class SingularSet:
    """The declared singular set of ``model``'s coordinates, as event functions.

    Parameters
    ----------
    model : NumericModel
    expressions : sequence of sympy expressions in the model's coordinates (and rates)
    """

    def __init__(self, model: NumericModel, expressions: Sequence):
        self.model = model
        self.expressions = tuple(as_expr(e) for e in expressions)
        self.params = model._code.params
        self.values = model.param_values

    def __len__(self) -> int:
        return len(self.expressions)

    def c_function(self):
        """The address of the compiled ``dm_out`` (``None`` without a compiler)."""
        if not self.expressions:
            return None
        coords = self.model.eqs.coordinates
        key = digest("singular set", codegen.GENERATOR_VERSION, coords, self.expressions,
                     [s.name for s in self.params])[:32]
        if key not in _LOADED:
            _LOADED[key] = self._load(key, coords)
        return _LOADED[key]

    def _load(self, key: str, coords):
        folder = cache_dir() or private_dir()
        lib = folder / f"dm_events_{key}.so"
        fn = _open(lib, key)
        if fn is None:
            states = [state_symbols(q) for q in coords]
            try:
                prog = codegen.program([to_plain(e, coords) for e in self.expressions], t=t,
                                       q=[s.q for s in states], qd=[s.qd for s in states],
                                       params=self.params)
            except ValueError as exc:
                raise ValueError(f"the singular set of `{self.model.eqs.name}`: {exc}") \
                    from None
            built = cbackend.compile_library(cbackend.c_function_source(prog, key), folder, lib)
            fn = _open(built, key) if built is not None else None
        return fn

    def scipy_events(self) -> list:
        """Terminal event functions ``f(t, y)`` for :func:`scipy.integrate.solve_ivp`."""
        if not self.expressions:
            return []
        values = dict(zip(self.params, self.values.tolist()))
        f = StateFunction(self.expressions, self.model.eqs.coordinates, values)
        n = self.model.n
        events = []
        for i in range(len(self.expressions)):
            def event(time, y, i=i):
                return f(time, y[:n], y[n:])[i]
            event.terminal = True
            events.append(event)
        return events

    def error(self, time: float, y) -> SingularityError:
        """The error for a motion that reached the set at ``(time, y)``."""
        names = [q.func.__name__ for q in self.model.eqs.coordinates]
        state = ", ".join(f"{n}={v:.6g}" for n, v in zip(names, y))
        which = " or ".join(f"{e} = 0" for e in self.expressions)
        return SingularityError(
            f"the motion of `{self.model.eqs.name}` reaches the singular set {which} at "
            f"t={time:.9g}, {state}: the coordinates cannot describe the motion there; stay "
            "away from it or choose other coordinates.")


def _open(lib: Path, key: str):
    if not lib.is_file():
        return None
    try:
        dll = ctypes.CDLL(str(lib))
        recorded = (ctypes.c_char * (len(key) + 1)).in_dll(dll, "dm_key").value
    except (OSError, ValueError):
        return None
    if recorded.decode() != key:
        return None
    _KEPT.append(dll)  # loaded for the life of the process, as its address is handed out
    return ctypes.cast(dll.dm_out, ctypes.c_void_p).value


@dataclass(frozen=True)
class Bound:
    """A coordinate reaching a value: the event ``y[index] - value``, stopping the run when it
    changes sign in ``direction`` (-1: from above, +1: from below), and what that means.

    Callable as a terminal event for :func:`scipy.integrate.solve_ivp`.

    >>> b = Bound(0, 2.0, 1, "x leaves its range")
    >>> b(0.0, [2.5, 0.0]), b.terminal
    (0.5, True)
    """

    index: int
    value: float
    direction: int
    what: str
    terminal = True

    def __call__(self, time, y):
        return y[self.index] - self.value


@dataclass(frozen=True)
class ReactionEvent:
    """A reaction as an event: row ``row`` of ``model``'s solution ``[q''; lambda]`` (a square
    direct model in the run's coordinates), stopping the run when it changes sign in
    ``direction`` (-1: reaching zero from above).

    Example
    -------
    The pendulum's string pull at the lowest point, ``M (g + a theta'^2)`` by hand:

    >>> from dualmech.problems import load
    >>> from dualmech.numeric.simulation import direct_models, problem_parameters
    >>> p = load("simple_pendulum")
    >>> values = problem_parameters(p)
    >>> direct = next(direct_models(p, square=True))
    >>> row = direct.n + [u.name for u in direct.unknowns].index("T")
    >>> event = ReactionEvent("T", NumericModel(direct, values), row)
    >>> ref = NumericModel(p.model(p.reference), values)
    >>> round(float(Stops(ref, reactions=[event]).values(0.0, [0.0, 1.5])[0]), 9)
    11.61
    """

    name: str
    model: NumericModel
    row: int
    direction: int = -1


class _Spec(ctypes.Structure):
    """The driver's ``dm_events`` (field for field)."""

    _fields_ = [("fun", ctypes.c_void_p), ("fun_p", ctypes.c_void_p), ("nfun", ctypes.c_int),
                ("nsolve", ctypes.c_int), ("one", ctypes.c_void_p), ("p", ctypes.c_void_p),
                ("k", ctypes.c_void_p), ("work", ctypes.c_void_p), ("nrow", ctypes.c_int),
                ("model", ctypes.c_void_p), ("row", ctypes.c_void_p), ("nbound", ctypes.c_int),
                ("index", ctypes.c_void_p), ("bound", ctypes.c_void_p),
                ("direction", ctypes.c_void_p), ("found", ctypes.c_void_p),
                ("slow", ctypes.c_void_p), ("nslow", ctypes.c_long)]


class Stops:
    """Every event function of one run of ``model``: its singular set (either direction),
    then ``reactions``, then ``bounds``, in that order (:meth:`labels`).

    Example
    -------
    >>> from dualmech.problems import load
    >>> from dualmech.numeric.simulation import problem_parameters
    >>> car = load("toy_car")
    >>> model = NumericModel(car.model(car.reference), problem_parameters(car))
    >>> stops = Stops(model, car.singular, bounds=[Bound(0, 1.0, 1, "theta above 1")])
    >>> stops.labels(), stops.values(0.0, [0.5, 0.0, 0.0, 0.0]).round(6).tolist()
    (['cos(theta(t))', 'theta above 1'], [0.877583, -0.5])
    """

    def __init__(self, model: NumericModel, singular: Sequence = (),
                 reactions: Sequence[ReactionEvent] = (), bounds: Sequence[Bound] = ()):
        self.model = model
        self.singular = SingularSet(model, singular)
        self.reactions = tuple(reactions)
        self.bounds = tuple(bounds)
        self.solvers = list(dict.fromkeys(r.model for r in self.reactions))
        for m in self.solvers:
            if list(m.eqs.coordinates) != list(model.eqs.coordinates):
                raise ValueError(f"the reaction events' model `{m.eqs.name}` has coordinates "
                                 f"{m.eqs.coordinates}, the run's model "
                                 f"{model.eqs.coordinates}: give them in the same ones.")
        self._exact: dict = {}

    def __len__(self) -> int:
        return len(self.singular) + len(self.reactions) + len(self.bounds)

    def labels(self) -> list[str]:
        """What each event function is: a singular-set expression, a reaction's name, a
        bound's ``what``."""
        return ([str(e) for e in self.singular.expressions] + [r.name for r in self.reactions]
                + [b.what for b in self.bounds])

    def directions(self) -> list[int]:
        return ([0] * len(self.singular) + [r.direction for r in self.reactions]
                + [b.direction for b in self.bounds])

    def values(self, time: float, y) -> np.ndarray:
        """Every event function at one state, in Python (reactions solved with the generated
        Python code: a singular system raises :class:`SingularityError`)."""
        y = np.asarray(y, dtype=float)
        n = self.model.n
        out = [float(f(time, y)) for f in self.singular.scipy_events()]
        for r in self.reactions:
            if r.model not in self._exact:
                self._exact[r.model] = r.model.with_backend("python")
            out.append(float(self._exact[r.model].solve(time, y[:n], y[n:])[r.row]))
        out += [float(b(time, y)) for b in self.bounds]
        return np.array(out)

    def c_spec(self, slow) -> _Spec:
        """The driver's ``dm_events`` for these functions (``slow``: the ctypes callback that
        writes every value at a flagged state); the arrays it points to are kept here.
        ``None`` when a part did not compile (no C compiler)."""
        fun = self.singular.c_function() if len(self.singular) else None
        libs = [cbackend.load(m.c_code.key, m.c_code.c_source) for m in self.solvers]
        if (len(self.singular) and fun is None) or any(lib is None for lib in libs):
            return None
        n2 = 2 * self.model.n
        work = [np.zeros(n2 + max(n2, m.shape[1])) for m in self.solvers]
        args = [[np.ascontiguousarray(a, dtype=float) for a in m._c_args] for m in self.solvers]
        ptrs = lambda xs: np.array(xs, dtype=np.uintp)  # noqa: E731 - arrays of addresses
        ints = lambda xs: np.array(xs, dtype=np.intc)   # noqa: E731
        keep = {"one": ptrs([ctypes.cast(lib[0], ctypes.c_void_p).value for lib in libs]),
                "p": ptrs([a[0].ctypes.data for a in args]),
                "k": ptrs([a[1].ctypes.data for a in args]),
                "work": ptrs([w.ctypes.data for w in work]),
                "model": ints([self.solvers.index(r.model) for r in self.reactions]),
                "row": ints([r.row for r in self.reactions]),
                "index": ints([b.index for b in self.bounds]),
                "bound": np.array([b.value for b in self.bounds], dtype=float),
                "direction": ints(self.directions()), "found": ints([0] * len(self))}
        fun_p = np.ascontiguousarray(self.model._c_args[0], dtype=float)
        self._kept = (keep, work, args, fun_p, slow)
        data = {k: (v.ctypes.data if v.size else None) for k, v in keep.items()}
        return _Spec(fun, fun_p.ctypes.data, len(self.singular), len(self.solvers),
                     data["one"], data["p"], data["k"], data["work"], len(self.reactions),
                     data["model"], data["row"], len(self.bounds), data["index"],
                     data["bound"], data["direction"], data["found"],
                     ctypes.cast(slow, ctypes.c_void_p).value, 0)

    def found(self) -> int | None:
        """The first event function CVODE found a root of in the last run of :meth:`c_spec`'s
        structure (``None``: none)."""
        hits = np.flatnonzero(self._kept[0]["found"])
        return int(hits[0]) if hits.size else None
