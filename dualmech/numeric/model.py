"""Compiled equation sets: ``A [q''; lambda] = b`` at one state or at many states at once.

:class:`NumericModel` binds parameter values to the generated code of an
:class:`~dualmech.model.equations.EquationSet` (see :mod:`dualmech.numeric.codegen`): one evaluation
of the generated function per call gives ``A``, ``b`` and the scale used by the singularity
detector.  One state is solved with a closed form (``n <= 2``) or LAPACK's ``dgesv``; arrays
of states (in the columns, like :func:`scipy.integrate.solve_ivp`'s ``y``) with elementwise
closed forms or one batched :func:`numpy.linalg.solve`.

Near-singular systems are caught by a cheap estimate -- the determinant and Frobenius norm for
``n <= 2``, the LU pivots for one state, a random probe column solved with the same
factorisation for many -- and only then checked exactly (singular values):
:class:`SingularityError` names the state.  Every call returns a fresh array.

Example
-------
>>> import sympy as sp
>>> from dualmech import EquationSet, coordinate, t
>>> x = coordinate("x"); m, k = sp.symbols("m k", positive=True)
>>> nm = NumericModel(EquationSet("spring", (x,), (m*x.diff(t, 2) + k*x,)), {m: 2.0, k: 8.0})
>>> nm.rhs(0.0, np.array([0.5, 0.0]))
array([ 0., -2.])
"""
from __future__ import annotations

import copy
import os
import threading
from dataclasses import dataclass
from functools import lru_cache
from typing import Callable, Mapping, Sequence

import numpy as np
import sympy as sp
from scipy.linalg.lapack import dgesv

from dualmech.model._expr import as_expr
from dualmech.model.equations import EquationSet, ModelError, state_symbols, to_plain
from dualmech.model.kinematics import t
from dualmech.numeric import cbackend, codegen
from dualmech.numeric._cache import digest, load_module
from dualmech.numeric.input_code import compiled_inputs, python_inputs
from dualmech.numeric.inputs import InputError

__all__ = ["NumericModel", "SingularityError", "StateFunction"]

#: The exact test: a system is singular where its condition number exceeds COND_LIMIT or its
#: smallest singular value is below SCALE_LIMIT times the scale of its entries' terms.
COND_LIMIT, SCALE_LIMIT = 1e12, 1e-12
#: The cheap estimate trips (and the exact test runs) well before those limits.  It is
#: compiled into the C code: change codegen.GENERATOR_VERSION with it.
_TRIP = 1e-8
_PROBE = np.random.default_rng(20240611).standard_normal(64)
#: Sizes of the square systems that ``backend="auto"`` solves with compiled code: from 3 on
#: (below, the closed forms in Python cost no more than a call into C, and nothing needs
#: compiling) up to 120 (the matrix lives on the C stack).
_C_MIN, _C_MAX = 3, 120


class SingularityError(ModelError):
    """The mass matrix (or the full system with reactions) is singular at a state."""


@dataclass(frozen=True)
class _Code:
    module: object
    params: tuple
    shape: tuple
    key: str
    c_source: Callable[[], str]


_BY_ID: dict = {}


def parameters_of(exprs, exclude=()) -> tuple:
    """Parameter symbols of ``exprs`` (every free symbol but ``t`` and ``exclude``), sorted.

    Two different symbols with one name are refused: values given by name would be ambiguous.
    """
    free = set().union(*[as_expr(e).free_symbols for e in exprs]) - {t} - set(exclude)
    params = tuple(sorted(free, key=lambda s: (s.name, sp.srepr(s))))
    names = [s.name for s in params]
    twins = sorted({n for n in names if names.count(n) > 1})
    if twins:
        raise ModelError(f"the equations use different symbols with the same name {twins} "
                         "(differing assumptions); give each quantity one symbol.")
    return params


def _held_parameters(eqs: EquationSet, held: tuple) -> tuple:
    """:func:`parameters_of` for equations held in symengine: the free symbols of ``A`` and
    ``b`` but the state symbols and ``t``, as the sympy symbols their names stand for."""
    A, b, names = held
    states = {x.name for q in eqs.coordinates for s in [state_symbols(q)]
              for x in (s.q, s.qd, s.qdd)} | {t.name}
    free = set().union(*[e.free_symbols for e in list(A) + list(b)])
    params = [names[s.name] for s in free if s.name not in states]
    return tuple(sorted(params, key=lambda s: (s.name, sp.srepr(s))))


def _generated(eqs: EquationSet) -> _Code:
    hit = _BY_ID.get(id(eqs))
    if hit is not None and hit[0] is eqs:
        return hit[1]
    key = digest("equations", codegen.GENERATOR_VERSION, eqs.coordinates, eqs.unknowns,
                 eqs.equations)
    # equations a derivation holds in symengine go to the generator as they are: the sympy
    # form, never read here, costs more than the code (seconds on a bicycle)
    held = eqs.plain_matrix_se()
    A, b = held[:2] if held is not None else eqs.plain_matrix()

    @lru_cache(maxsize=1)
    def prog(params: tuple) -> codegen.Program:
        states = [state_symbols(q) for q in eqs.coordinates]
        return codegen.program(list(A) + list(b), t=t, q=[s.q for s in states],
                               qd=[s.qd for s in states], params=params,
                               scale_of=A.rows * A.cols)

    def build() -> str:
        params = parameters_of(eqs.equations, eqs.unknowns) if held is None else \
            _held_parameters(eqs, held)
        return codegen.python_source(prog(params), key, params)

    module = load_module(key, build)
    # the parameters as the code was generated for them (a cache hit skips the tree walk)
    params = tuple(sp.Symbol(name, **assumptions) for name, assumptions in module.PARAMS)
    code = _Code(module, params, A.shape, key,
                 lambda: cbackend.c_source(prog(params), key, A.shape, _TRIP))
    _BY_ID[id(eqs)] = (eqs, code)  # keep eqs alive so its id is not reused
    return code


def _bind(code_params: tuple, params: Mapping, what: str) -> tuple:
    """Parameter values in the generated code's order; missing ones named."""
    values = {}
    for k, v in params.items():
        values[_key(k, code_params)] = v
    missing = [s for s in code_params if s not in values]
    if missing:
        raise ModelError(f"`params` lacks values for {sorted(map(str, missing))} ({what}); "
                         "if one is a given input (Problem.inputs), pass its history: "
                         "simulate(..., inputs={name: function of t or (times, values)}).")
    out = []
    for s in code_params:
        try:
            v = float(values[s])
        except (TypeError, ValueError):
            raise ModelError(f"`params`: {s} = {values[s]!r} is not a number.") from None
        if not np.isfinite(v):
            raise ModelError(f"`params`: {s} = {v} must be finite.")
        out.append(v)
    return tuple(out)


def _key(k, symbols):
    """A parameter given as a symbol or by its name (looked up, never parsed)."""
    if isinstance(k, str):
        for s in symbols:
            if s.name == k:
                return s
        return sp.Symbol(k)  # unknown name: reported as missing/unused by the caller
    return as_expr(k)


class NumericModel:
    """Compiled ``A`` and ``b`` of one equation set, for a fixed set of parameter values.

    Parameters
    ----------
    eqs : EquationSet
    params : mapping symbol (or its name) -> float
        A value for every parameter symbol in the equations (others are ignored).
    backend : {"auto", "python", "c"}, optional
        Where :meth:`solve` and :meth:`rhs` run: generated Python/NumPy code, or the same
        program compiled to C (:mod:`~dualmech.numeric.cbackend`, compiled on first use and
        cached).  ``"auto"`` (default; ``$DUALMECH_BACKEND`` overrides) compiles square
        systems of 3 to 120 unknowns when a C compiler exists.  :meth:`system` always runs
        the Python/NumPy code.
    inputs : mapping symbol (or its name) -> callable, optional
        Given inputs (:class:`~dualmech.model.inputs.Input`): each a function of time whose
        value is bound at every evaluation (:mod:`dualmech.numeric.inputs` builds them from
        closed forms, tables and callables, with the checks).  Closed forms and tables are
        also compiled into the C code (:mod:`dualmech.numeric.input_code`); a Python callable
        keeps the Python code (:attr:`inputs_in_python` says why).

    Notes
    -----
    States are given as ``q`` and ``qd`` of shape ``(n,)`` (one state) or ``(n, K)`` (``K``
    states in the columns); ``time`` is a number or, for many states, an array ``(K,)``.
    """

    def __init__(self, eqs: EquationSet, params: Mapping, *, backend: str | None = None,
                 inputs: Mapping | None = None):
        backend = backend or os.environ.get("DUALMECH_BACKEND", "auto")
        if backend not in ("auto", "python", "c"):
            raise ValueError(f"`backend` must be 'auto', 'python' or 'c', got {backend!r}.")
        self.eqs = eqs
        self.states = [state_symbols(q) for q in eqs.coordinates]
        self.n = eqs.n
        self._code = code = _generated(eqs)
        inputs = {_key(k, code.params): f for k, f in (inputs or {}).items()}
        inputs = {k: f for k, f in inputs.items() if k in code.params}
        p = _bind(code.params, {**params, **{k: 0.0 for k in inputs}}, f"model `{eqs.name}`")
        #: why the given inputs cannot run in compiled code (None: they can, or there are none)
        self.inputs_in_python = None
        self._setup(p, "python" if inputs else backend)
        if inputs:   # given inputs F(t): their values bound at each time in Python ...
            self._inputs = [(code.params.index(k), f) for k, f in inputs.items()]
            self._p = list(p)
            self._scalar, self._vector = self._driven_scalar, self._driven_vector
            self._compile_inputs(params, inputs, backend)   # ... and in C where they can

    def _compile_inputs(self, params: Mapping, inputs: dict, backend: str) -> None:
        """Closed forms and tables evaluated in the generated C (:mod:`~dualmech.numeric.
        input_code`); a Python callable keeps the Python code, the reason recorded."""
        if backend == "python":
            self.inputs_in_python = "backend='python' was asked for"
            return
        self.inputs_in_python = python_inputs(inputs)
        if self.inputs_in_python:
            return
        known = {_key(k, self._code.params): v for k, v in params.items()}
        self._c_pending = lambda: compiled_inputs(  # noqa: E731 - generated on first use
            self.eqs, self._code.params, self._code.shape, known, inputs, _TRIP)
        self.backend = backend
        m, N = self.shape
        usable = m == N and N <= _C_MAX and (backend == "c" or (
            backend == "auto" and N >= _C_MIN and cbackend.compiler() is not None))
        self._c = False if usable else None

    # -- given inputs ----------------------------------------------------------------------
    def _bound_at(self, time):
        """The generated scalar code with each given input's value at ``time`` bound."""
        p = list(self._p)
        for i, f in self._inputs:
            p[i] = f(float(time))
        p = tuple(p)
        module = self._code.module
        return module.scalar(p, module.static(p))

    def _driven_scalar(self, time, y):
        return self._bound_at(time)(time, y)

    def _driven_vector(self, time, Y):
        K = Y.shape[1]
        times = np.broadcast_to(np.asarray(time, dtype=float), (K,))
        cols = [self._bound_at(times[i])(times[i], Y[:, i].tolist()) for i in range(K)]
        return [np.array([c[j] for c in cols], dtype=float) for j in range(len(cols[0]))]

    def __getstate__(self) -> dict:
        """Pickled as the equations, parameter values and backend (code is rebuilt)."""
        if getattr(self, "_inputs", None):
            raise TypeError("a model driven by given inputs (Python functions of time) does "
                            "not pickle; build it where it runs.")
        # (with_backend copies a driven model instead)
        return {"eqs": self.eqs, "p": tuple(self._c_args[0].tolist()), "backend": self.backend}

    def __setstate__(self, state: dict) -> None:
        self.eqs = state["eqs"]
        self.states = [state_symbols(q) for q in self.eqs.coordinates]
        self.n = self.eqs.n
        self._code = _generated(self.eqs)
        self._setup(state["p"], state["backend"])

    def with_backend(self, backend: str) -> "NumericModel":
        """The same equations and parameter values evaluated by another ``backend``.

        Example
        -------
        >>> import sympy as sp
        >>> from dualmech import EquationSet, coordinate, t
        >>> x = coordinate("x"); m, k = sp.symbols("m k", positive=True)
        >>> eqs = EquationSet("spring", (x,), (m*x.diff(t, 2) + k*x,))
        >>> nm = NumericModel(eqs, {m: 2.0, k: 8.0})
        >>> nm.with_backend("python").rhs(0.0, np.array([0.5, 0.0]))
        array([ 0., -2.])
        """
        if backend not in ("auto", "python", "c"):
            raise ValueError(f"`backend` must be 'auto', 'python' or 'c', got {backend!r}.")
        if getattr(self, "_inputs", None):
            if backend != "python":
                raise ValueError("a model driven by given inputs changes backend to "
                                 "'python' only; build another for C.")
            other = copy.copy(self)
            other._c, other.backend = None, "python"
            return other
        other = object.__new__(NumericModel)
        other.__setstate__({**self.__getstate__(), "backend": backend})
        return other

    def _setup(self, p: tuple, backend: str) -> None:
        code = self._code
        k = code.module.static(p)
        self._scalar = code.module.scalar(p, k)
        self._vector = code.module.vector(p, k)
        self.shape = code.shape
        self._mn = code.shape[0] * code.shape[1]
        self.backend = backend
        self._c_args = (np.array(p, dtype=float), np.array(k, dtype=float))
        #: the parameter values in the order of ``_code.params`` (the C library's ``p`` may
        #: differ: with given inputs in C it holds their tables instead)
        self.param_values = self._c_args[0]
        m, N = code.shape
        usable = m == N and N <= _C_MAX and (backend == "c" or (
            backend == "auto" and N >= _C_MIN and cbackend.compiler() is not None))
        self._c = False if usable else None  # False: not loaded yet

    @property
    def c_code(self):
        """The C library's ``key`` and ``c_source`` (with the given inputs in C, if any: then
        generated on first use, and ``_c_args`` with them)."""
        pending = self.__dict__.pop("_c_pending", None)
        if pending is not None:
            ci = pending()
            self._c_code, self._c_args = ci, (ci.p, ci.k)
        return getattr(self, "_c_code", None) or self._code

    @property
    def compiled(self) -> bool:
        """Whether :meth:`solve` and :meth:`rhs` run compiled C code (else NumPy/Python)."""
        return self._c is not None and self._c_solver() is not None

    def _c_solver(self):
        """The compiled solver (loaded, or compiled, on first use), or ``None``."""
        if self._c is False:
            code = self.c_code
            fns = cbackend.load(code.key, code.c_source)
            if fns is None and self.backend == "c":
                raise RuntimeError("`backend='c'` needs a working C compiler (set $CC); "
                                   "use backend='python' or 'auto' without one.")
            if fns is None:
                self._c = None
            else:
                p, k = self._c_args
                work = np.zeros(2 * self.n + max(2 * self.n, self.shape[1]))
                self._c = (*fns, p.ctypes.data, k.ctypes.data, work, work.ctypes.data,
                           threading.Lock())
        return self._c

    def _c_one(self, time, y: np.ndarray, rhs: int):
        """The right-hand side (``rhs=1``) or the solution at one state, or ``None`` if the
        state tripped the cheap estimate (or there is no compiled code)."""
        c = self._c if self._c is not False else self._c_solver()
        if c is None:
            return None
        one, _, pp, kp, work, wp, lock = c
        n2 = 2 * self.n
        with lock:
            work[:n2] = y
            if one(float(time), pp, kp, wp, rhs):
                return None
            return work[n2: n2 + (n2 if rhs else self.shape[1])].copy()

    def _c_many(self, time, Y: np.ndarray, out: np.ndarray, offset: int, nrows: int):
        """Solve at the states in the columns of ``Y`` (any layout) into rows ``offset...``
        of ``out`` (a C-ordered float array: the compiled code writes it row by row)
        with the compiled code; ``None`` when done, else the mask of states that tripped the
        cheap estimate."""
        _, many, pp, kp, *_ = self._c_solver()
        K = Y.shape[1]
        tv = None
        if np.ndim(time):
            tv = np.ascontiguousarray(np.broadcast_to(np.asarray(time, float), (K,)))
        Y = np.ascontiguousarray(Y, dtype=float)
        trip = np.zeros(K, dtype=np.uint8)
        bad = many(K, 0.0 if tv is not None else float(time),
                   None if tv is None else tv.ctypes.data, Y.ctypes.data, pp, kp,
                   out.ctypes.data + 8 * offset * K, nrows, trip.ctypes.data)
        return trip.astype(bool) if bad else None

    # -- evaluation ----------------------------------------------------------------------
    def _state(self, q, qd) -> np.ndarray:
        y = np.concatenate([np.asarray(q, dtype=float), np.asarray(qd, dtype=float)])
        if y.shape[0] != 2 * self.n or y.ndim > 2:
            raise ValueError(f"`q` and `qd` must each hold {self.n} numbers (or {self.n} rows "
                             f"of states) for model `{self.eqs.name}`; got {y.shape[0]} in all.")
        return y

    def _many(self, time, Y: np.ndarray):
        """``(A (K, m, N), b (K, m), scale (K,))`` at the states in the columns of ``Y``."""
        outs = self._vector(time, Y)
        K = Y.shape[1]
        m, N = self.shape
        flat = np.empty((K, self._mn + m + 1))
        for j, v in enumerate(outs):
            flat[:, j] = v
        A = flat[:, : self._mn].reshape(K, m, N)
        return A, flat[:, self._mn: self._mn + m], flat[:, -1]

    def system(self, time, q, qd):
        """``(A, b)``: ``(m, N)`` and ``(m,)`` at one state, ``(K, m, N)`` and ``(K, m)`` at many."""
        y = self._state(q, qd)
        if y.ndim == 2:
            A, b, _ = self._many(time, y)
            return A, b
        outs = self._eval_one(time, y.tolist())
        return (np.array(outs[: self._mn]).reshape(self.shape),
                np.array(outs[self._mn: self._mn + self.shape[0]]))

    def solve(self, time, q, qd) -> np.ndarray:
        """``[q''; lambda]``: ``(N,)`` at one state, ``(N, K)`` at many (least squares if the
        system is not square)."""
        y = self._state(q, qd)
        if y.ndim == 1:
            x = self._c_one(time, y, 0) if self._c is not None else None
            return x if x is not None else np.array(self._solve_one(time, y.tolist()))
        if self._c_solver() is None:
            return self._solve_many(time, y)
        x = np.empty((self.shape[1], y.shape[1]))
        self._fix(time, y, x, 0, self._c_many(time, y, x, 0, self.shape[1]))
        return x

    def accelerations(self, time, q, qd) -> np.ndarray:
        """``q''``: ``(n,)`` at one state, ``(n, K)`` at many."""
        return self.solve(time, q, qd)[: self.n]

    def rhs(self, time, y) -> np.ndarray:
        """``d/dt [q; q']`` for :func:`scipy.integrate.solve_ivp`: ``y`` is ``(2n,)`` or
        ``(2n, K)`` (``vectorized=True``); the result is a new array of the same shape."""
        y = np.asarray(y, dtype=float)
        n = self.n
        if y.shape[0] != 2 * n or y.ndim > 2:
            raise ValueError(f"`y` must hold {2 * n} numbers (q then q') per state, got shape "
                             f"{y.shape}.")
        if y.ndim == 1:
            out = self._c_one(time, y, 1) if self._c is not None else None
            if out is not None:
                return out
            yl = y.tolist()
            return np.array(yl[n:] + self._solve_one(time, yl)[:n])
        out = np.empty(y.shape)  # C order: the compiled code writes it row by row
        out[:n] = y[n:]
        if self._c_solver() is None:
            out[n:] = self._solve_many(time, y)[:n]
        else:
            self._fix(time, y, out, n, self._c_many(time, y, out, n, n))
        return out

    def _fix(self, time, Y, out, offset, bad) -> None:
        """Decide the states flagged by the compiled code exactly (raise if singular)."""
        if bad is None:
            return
        times = np.broadcast_to(np.asarray(time, dtype=float), (Y.shape[1],))
        rows = out.shape[0] - offset
        for i in np.flatnonzero(bad):
            out[offset:, i] = self._solve_one(times[i], Y[:, i].tolist())[:rows]

    # -- one state -------------------------------------------------------------------------
    def _eval_one(self, time, y: list) -> tuple:
        try:
            return self._scalar(time, y)
        except InputError:
            raise   # the input's own history failed: its message says where
        except (ValueError, ZeroDivisionError, OverflowError) as exc:
            raise ValueError(_failed(self.eqs.name, self._state_text(time, y), exc)) from None

    def _solve_one(self, time, y: list) -> list:
        outs = self._eval_one(time, y)
        m, N = self.shape
        mn = self._mn
        if m != N:
            A = np.array(outs[:mn]).reshape(m, N)
            return np.linalg.lstsq(A, np.array(outs[mn: mn + m]), rcond=None)[0].tolist()
        scale = outs[-1]
        if N == 1:
            a, f = outs[0], outs[1]
            if abs(a) > _TRIP * scale:
                return [f / a]
        elif N == 2:
            a, b, c, d, f0, f1 = outs[:6]
            det = a * d - b * c
            fro = a * a + b * b + c * c + d * d
            if det * det > _TRIP * _TRIP * fro * max(fro, scale * scale):
                return [(d * f0 - b * f1) / det, (a * f1 - c * f0) / det]
        else:
            A = np.fromiter(outs[:mn], float, mn).reshape(N, N)
            lu, _, x, info = dgesv(A, np.fromiter(outs[mn: mn + N], float, N))
            if info == 0:  # (Python on short lists is faster than NumPy reductions here)
                piv = [abs(v) for v in lu.diagonal().tolist()]
                xl = x.tolist()
                total = sum(xl)
                if min(piv) > _TRIP * max(max(piv), scale) and total - total == 0.0:
                    return xl
        A = np.array(outs[:mn], dtype=float).reshape(N, N)
        self._check(A, scale, time, y)
        return np.linalg.solve(A, np.array(outs[mn: mn + N], dtype=float)).tolist()

    def _check(self, A: np.ndarray, scale: float, time, y) -> None:
        """Raise :class:`SingularityError` if ``A`` is singular by the exact test."""
        if not (np.isfinite(A).all() and np.isfinite(y).all() and np.isfinite(time)):
            raise ValueError(f"the system of `{self.eqs.name}` is not finite at "
                             f"{self._state_text(time, y)}: check the state and the "
                             "parameter values (a diverging integration ends like this).")
        sv = np.linalg.svd(A, compute_uv=False)
        cond = sv[0] / sv[-1] if sv[-1] > 0 else np.inf
        if np.isfinite(cond) and cond <= COND_LIMIT and sv[-1] >= SCALE_LIMIT * scale:
            return
        raise SingularityError(self._singular_message(time, y, cond))

    # -- many states -----------------------------------------------------------------------
    def _solve_many(self, time, Y: np.ndarray) -> np.ndarray:
        m, N = self.shape
        K = Y.shape[1]
        times = np.broadcast_to(np.asarray(time, dtype=float), (K,))
        if m != N:
            A, b, _ = self._many(time, Y)
            return np.stack([np.linalg.lstsq(A[i], b[i], rcond=None)[0] for i in range(K)], 1)
        if N <= 2:
            return self._closed_form_many(times, Y)
        A, b, scale = self._many(time, Y)
        rhs = np.empty((K, N, 2))
        rhs[:, :, 0] = b
        rhs[:, :, 1] = _PROBE[:N] if N <= _PROBE.size else 1.0
        try:
            X = np.linalg.solve(A, rhs)
        except np.linalg.LinAlgError:
            X = np.full((K, N, 2), np.nan)
        z = np.sqrt(np.einsum("kn,kn->k", X[:, :, 1], X[:, :, 1]))
        fro = np.sqrt(np.einsum("kij,kij->k", A, A))
        sigma = np.linalg.norm(rhs[0, :, 1]) / z  # >= the smallest singular value
        with np.errstate(invalid="ignore"):
            ok = (sigma > _TRIP * np.maximum(fro, scale)) & np.isfinite(X[:, :, 0]).all(1)
        x = X[:, :, 0].T.copy()
        for i in np.flatnonzero(~ok):
            self._check(A[i], scale[i], times[i], Y[:, i].tolist())
            x[:, i] = np.linalg.solve(A[i], b[i])
        return x

    def _closed_form_many(self, times, Y) -> np.ndarray:
        outs = self._vector(times, Y)
        K = Y.shape[1]
        scale = outs[-1]
        with np.errstate(divide="ignore", invalid="ignore"):
            if self.shape[1] == 1:
                a, f = outs[0], outs[1]
                x = np.broadcast_to(np.asarray(f / a, dtype=float), (1, K)).copy()
                ok = np.abs(a) > _TRIP * scale
            else:
                a, b, c, d, f0, f1 = outs[:6]
                det = a * d - b * c
                fro = a * a + b * b + c * c + d * d
                x = np.empty((2, K))
                x[0] = (d * f0 - b * f1) / det
                x[1] = (a * f1 - c * f0) / det
                ok = det * det > _TRIP * _TRIP * fro * np.maximum(fro, scale * scale)
        ok = np.broadcast_to(ok, (K,))
        if not ok.all():
            A, b, sc = self._many(times, Y)
            for i in np.flatnonzero(~ok):
                self._check(A[i], sc[i], times[i], Y[:, i].tolist())
                x[:, i] = np.linalg.solve(A[i], b[i])
        return x

    def _state_text(self, time, y) -> str:
        names = [s.name for s in self.states] + [f"{s.name}'" for s in self.states]
        return f"t={float(time):.6g}, " + ", ".join(f"{n}={v:.6g}" for n, v in zip(names, y))

    def _singular_message(self, time, y, cond) -> str:
        st = ", ".join(f"{s.name}={v:.6g}" for s, v in zip(self.states, y))
        return (f"the system of `{self.eqs.name}` is singular at t={float(time):.6g}, {st} "
                f"(condition number {cond:.3g}): the coordinates cannot describe the motion "
                "there; stay away from the problem's singular set or choose other coordinates.")


def _failed(what: str, where: str, exc: Exception) -> str:
    return (f"evaluating `{what}` at {where} failed ({type(exc).__name__}: {exc}): a square "
            "root or logarithm of a negative number, or a division by zero, at this state.")


class StateFunction:
    """Generated code for any expressions of the state, e.g. an energy or a constraint.

    Parameters
    ----------
    exprs : sequence of sympy expressions in ``t``, the coordinates ``q(t)`` and ``q'(t)``
    coordinates : sequence of ``q(t)``
    params : mapping symbol (or name) -> float

    Notes
    -----
    Calling it with ``(time, q, qd)`` gives an array ``(len(exprs),)`` for one state or
    ``(len(exprs), K)`` for states in columns.

    Example
    -------
    >>> import sympy as sp
    >>> from dualmech import coordinate, t
    >>> x = coordinate("x"); m, k = sp.symbols("m k", positive=True)
    >>> energy = StateFunction([m*x.diff(t)**2/2 + k*x**2/2], [x], {m: 2.0, k: 8.0})
    >>> energy(0.0, [0.5], [1.0])
    array([2.])
    """

    def __init__(self, exprs: Sequence, coordinates: Sequence, params: Mapping):
        exprs = [as_expr(e) for e in exprs]
        coords = tuple(coordinates)
        states = [state_symbols(q) for q in coords]
        code_params = parameters_of(exprs)
        key = digest("state function", codegen.GENERATOR_VERSION, coords, exprs)

        def build() -> str:
            outs = [to_plain(e, coords) for e in exprs]
            prog = codegen.program(outs, t=t, q=[s.q for s in states],
                                   qd=[s.qd for s in states], params=code_params)
            return codegen.python_source(prog, key, code_params)

        module = load_module(key, build)
        p = _bind(code_params, params, "state function")
        k = module.static(p)
        self.n, self.size = len(coords), len(exprs)
        self._scalar = module.scalar(p, k)
        self._vector = module.vector(p, k)

    def __call__(self, time, q, qd) -> np.ndarray:
        y = np.concatenate([np.asarray(q, dtype=float), np.asarray(qd, dtype=float)])
        if y.shape[0] != 2 * self.n:
            raise ValueError(f"`q` and `qd` must each hold {self.n} numbers.")
        if y.ndim == 1:
            try:
                return np.array(self._scalar(time, y.tolist()), dtype=float)
            except (ValueError, ZeroDivisionError, OverflowError) as exc:
                raise ValueError(_failed("state function", f"t={time}, y={y.tolist()}",
                                         exc)) from None
        out = np.empty((self.size, y.shape[1]))
        for j, v in enumerate(self._vector(time, y)):
            out[j] = v
        return out
