"""Stop where the motion reaches a problem's declared singular set: event functions in C.

A problem declares its coordinate singularities as expressions whose zeros are the singular
set (:attr:`Problem.singular <dualmech.model.problem.Problem.singular>`, e.g. ``cos(theta)``
for the toy car).  An integrator stepping across such a zero sees nothing wrong when no step
lands close to it -- the mass matrix is singular only *on* the set -- and goes on with a
motion the equations no longer describe.  :class:`SingularSet` compiles the expressions to C
(:func:`dualmech.numeric.cbackend.c_function_source`) for CVODE's root finding (the driver
stops at the first sign change, located to rounding), and gives the same functions to scipy
as terminal events (:class:`~dualmech.numeric.model.StateFunction`).  :meth:`SingularSet.error`
is the :class:`~dualmech.numeric.model.SingularityError` raised there.

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
from pathlib import Path
from typing import Sequence

import numpy as np

from dualmech.model._expr import as_expr
from dualmech.model.equations import state_symbols, to_plain
from dualmech.model.kinematics import t
from dualmech.numeric import cbackend, codegen
from dualmech.numeric._cache import cache_dir, digest, private_dir
from dualmech.numeric.model import NumericModel, SingularityError, StateFunction

__all__ = ["SingularSet"]

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
