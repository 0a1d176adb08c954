r"""IDA with no Python per step: the DAE forms' residuals generated as C and run by the C driver.

:func:`compiled_residual` prints the residual ``F(t, y, y') = 0`` of one DAE form of a
:class:`~dualmech.numeric.dae.ConstrainedModel` as C, from the same equations the Python
residual (:meth:`IDASolver.residual <dualmech.numeric.daesolve.IDASolver.residual>`) uses:
the index-1 system ``A [q''; lambda] = b`` of the model (its first ``n`` rows are the
equations of motion ``M q'' + W lambda = f``, the last ``k`` the constraints at the
acceleration level) and the position-level constraints ``g`` with their gradient
``G = dg/dq``.  One straight-line program (:func:`dualmech.numeric.codegen.program`) computes
the entries of ``A`` and ``b`` the form needs, ``g`` and ``G`` at ``(t, q, v)``; the C around
it assembles, with ``y = [q, v, lambda(, mu)]``:

* ``index3``: ``q' - v``, ``M v' + W lambda - f``, ``g(q) - g0``;
* ``ggl``: ``q' - v + G^T mu``, ``M v' + W lambda - f``, ``g(q) - g0``, ``G v``;
* ``index1``: ``q' - v``, ``M v' + W lambda - f`` and the acceleration-level rows
  ``A_c [v'; lambda] - b_c``.

The library is compiled once per model and form and cached (:mod:`~dualmech.numeric.cbackend`);
:func:`run_compiled` hands its ``dm_res`` to the IDA driver (:mod:`~dualmech.numeric.ida_driver`)
through a function pointer.  Where a compiler or SUNDIALS's wheel libraries are missing both
raise :class:`~dualmech.numeric.ida_driver.IdaUnavailable` with the reason, and
:class:`~dualmech.numeric.daesolve.IDASolver` falls back to its Python residual.

Example
-------
>>> from dualmech.problems import get
>>> from dualmech.numeric.formulations import formulations
>>> forms, _ = formulations(get("pendulum_particle"), stabilisations=("ggl",))
>>> f = {g.name: g for g in forms}["cartesian (DAE, GGL index 2)"]
>>> src = residual_source(f.constrained, "ggl", "example")
>>> "int dm_res(" in src and "void dm_static(" in src
True
"""
from __future__ import annotations

import ctypes
import time as _time
from dataclasses import dataclass

import numpy as np
import sympy as sp

from dualmech.model.equations import state_symbols, to_plain
from dualmech.model.kinematics import t
from dualmech.numeric import cbackend, codegen
from dualmech.numeric._cache import cache_dir, digest, private_dir
from dualmech.numeric.ida_driver import IdaUnavailable, driver
from dualmech.numeric.integrators import DID_NOT_FINISH, WorkBudget

__all__ = ["IDA_FORMS", "CompiledResidual", "IdaUnavailable", "available", "compiled_residual",
           "residual_source", "run_compiled"]

#: The forms whose residual is generated (``index3`` and ``ggl`` are the charts' IDA forms).
IDA_FORMS = ("index3", "ggl", "index1")
#: Bumped whenever the generated residual changes meaning (part of the library's key).
RESIDUAL_VERSION = "1"


@dataclass(frozen=True)
class CompiledResidual:
    """A loaded ``dm_res`` and the arrays it reads: parameters ``p``, then in ``k`` the static
    coefficients followed by the constraint offsets ``g0``."""

    form: str
    size: int
    address: int
    p: np.ndarray
    k: np.ndarray
    library: object


def available() -> str | None:
    """``None`` when the compiled IDA route can run here, else the reason it cannot."""
    try:
        driver()
    except IdaUnavailable as exc:
        return str(exc)
    return None


def _outputs(cm, form: str) -> tuple[list, list]:
    """The expressions the C program computes (plain symbols) and the parameter symbols
    that are not the index-1 model's (only a constraint's constant term can hold one: set
    to 0, the difference goes into the offsets)."""
    n, k = cm.n, cm.k
    A, b = cm.index1.plain_matrix()
    rows = range(n + k) if form == "index1" else range(n)
    outs = [A[i, j] for i in rows for j in range(n + k)] + [b[i] for i in rows]
    coords = cm.eqs.coordinates
    g = [to_plain(e, coords) for e in cm.constraints.expressions]
    G = [to_plain(d, coords) for row in cm.constraints.gradients for d in row]
    params = set(cm.numeric._code.params)
    plain = {s for q in coords for s in (state_symbols(q).q, state_symbols(q).qd)} | {t}
    foreign = sorted(set().union(*[e.free_symbols for e in g + G]) - params - plain,
                     key=lambda s: s.name)
    zero = {s: 0 for s in foreign}
    return outs + [e.xreplace(zero) for e in g + G], foreign


def residual_source(cm, form: str, key: str) -> str:
    """C source of ``dm_static(p, k)`` (the static coefficients) and ``dm_res(t, y, y', res,
    p, k)`` (the residual of ``form``; returns 1 where a value is not finite)."""
    if form not in IDA_FORMS:
        raise ValueError(f"`form` must be one of {IDA_FORMS}, got {form!r}.")
    n, k = cm.n, cm.k
    outs, _ = _outputs(cm, form)
    states = [state_symbols(q) for q in cm.eqs.coordinates]
    prog = codegen.program(outs, t=t, q=[s.q for s in states], qd=[s.qd for s in states],
                           params=list(cm.numeric._code.params))
    pr = cbackend.CPrinter()
    ns = len(prog.static_names)
    lines = [f"/* Generated by dualmech.numeric.ida {RESIDUAL_VERSION} (codegen "
             f"{codegen.GENERATOR_VERSION}); key {key}; form {form}; do not edit. */",
             "#include <math.h>", f'const char dm_key[] = "{key}";',
             f"const long dm_nstatic = {ns};", "",
             "void dm_static(const double *p, double *k)", "{"]
    lines += [f"    const double p_{i} = p[{i}];" for i in range(prog.n_params)]
    lines += [f"    const double {s.name} = {pr(e)};" for s, e in prog.static]
    lines += [f"    k[{i}] = {s.name};" for i, s in enumerate(prog.static_names)]
    lines += ["    (void)p; (void)k;", "}", "",
              "int dm_res(double t_, const double *y, const double *yp, double *res,",
              "           const double *p, const double *k)", "{"]
    lines += [f"    const double p_{i} = p[{i}];" for i in range(prog.n_params)]
    lines += [f"    const double {s.name} = k[{i}];" for i, s in enumerate(prog.static_names)]
    lines += [f"    const double q_{j} = y[{j}];" for j in range(n)]
    lines += [f"    const double u_{j} = y[{n + j}];" for j in range(n)]
    lines += [f"    const double {s.name} = {pr(e)};" for s, e in prog.body]
    lines += [f"    double o[{len(prog.outputs)}];"]
    lines += [f"    o[{j}] = {pr(e)};" for j, e in enumerate(prog.outputs)]
    lines += ["    (void)t_; (void)p;", *_assemble(n, k, form, ns), "}"]
    return "\n".join(lines) + "\n"


def _assemble(n: int, k: int, form: str, ns: int) -> list[str]:
    """C lines writing ``res`` from ``o`` (``A`` rows, ``b`` rows, ``g``, ``G``), ``y``, ``yp``."""
    N, m = n + k, (n + k if form == "index1" else n)
    A, B, g, G = 0, m * N, m * N + m, m * N + m + k   # offsets into o
    size = 2 * n + k * (2 if form == "ggl" else 1)
    c = [f"    const double *A = o + {A}, *b = o + {B}, *g = o + {g}, *G = o + {G};",
         f"    const double *lam = y + {2 * n}, *off = k + {ns};",
         "    (void)G; (void)g; (void)off;",
         f"    for (int i = 0; i < {n}; i++) res[i] = yp[i] - y[{n} + i];",
         f"    for (int i = 0; i < {m}; i++) {{",
         "        double r = -b[i];",
         f"        for (int j = 0; j < {n}; j++) r += A[i * {N} + j] * yp[{n} + j];",
         f"        for (int l = 0; l < {k}; l++) r += A[i * {N} + {n} + l] * lam[l];",
         f"        res[{n} + i] = r;", "    }"]
    if form != "index1":
        c += [f"    for (int l = 0; l < {k}; l++) res[{2 * n} + l] = g[l] - off[l];"]
    if form == "ggl":
        c += [f"    const double *mu = y + {2 * n + k};",
              f"    for (int l = 0; l < {k}; l++) {{",
              "        double r = 0.0;",
              f"        for (int j = 0; j < {n}; j++) {{",
              f"            res[j] += G[l * {n} + j] * mu[l];",
              f"            r += G[l * {n} + j] * y[{n} + j];", "        }",
              f"        res[{2 * n + k} + l] = r;", "    }"]
    c += [f"    for (int i = 0; i < {size}; i++) if (!isfinite(res[i])) return 1;",
          "    return 0;"]
    return c


_LOADED: dict = {}


def compiled_residual(cm, form: str, q_on: np.ndarray) -> CompiledResidual:
    """The compiled residual of ``form`` for ``cm`` (compiled now, or from the cache).

    ``q_on`` is any configuration where ``g`` is defined: the offsets ``g0`` are set so that
    the generated ``g(q) - g0`` equals ``cm.residuals(q)[0]`` there, hence everywhere (the
    two differ by a constant at most: a constraint's coordinate-free term), which makes the
    constraint rows the Python residual's.
    Raises :class:`IdaUnavailable` when there is no C compiler.
    """
    if form not in IDA_FORMS:
        raise ValueError(f"`form` must be one of {IDA_FORMS}, got {form!r}.")
    params = cm.numeric._code.params
    key = digest("ida residual", RESIDUAL_VERSION, codegen.GENERATOR_VERSION, form,
                 cm.eqs.coordinates, cm.index1.equations, cm.constraints.expressions,
                 tuple(s.name for s in params))[:32]
    lib = _LOADED.get(key) or _load(key, lambda: residual_source(cm, form, key))
    _LOADED[key] = lib
    p = np.ascontiguousarray(cm.numeric._c_args[0], dtype=float)
    static = np.zeros(max(_statics(lib), 1) + cm.k)
    lib.dm_static(p.ctypes.data, static.ctypes.data)
    ns = _statics(lib)
    k = np.ascontiguousarray(np.concatenate([static[:ns], np.zeros(cm.k)]))
    # g0 such that the generated g(q_on) - g0 is the model's own g(q_on) - g0
    y = np.zeros(2 * cm.n + cm.k * (2 if form == "ggl" else 1))
    y[: cm.n] = q_on
    res = np.zeros_like(y)
    lib.dm_res(0.0, y.ctypes.data, np.zeros_like(y).ctypes.data, res.ctypes.data,
               p.ctypes.data, k.ctypes.data)
    g_own, _ = cm.residuals(np.asarray(q_on, dtype=float), np.zeros(cm.n))
    k[ns:] = res[2 * cm.n: 2 * cm.n + cm.k] - g_own
    address = ctypes.cast(lib.dm_res, ctypes.c_void_p).value
    return CompiledResidual(form, y.size, address, p, k, lib)


def _statics(lib) -> int:
    return int(ctypes.c_long.in_dll(lib, "dm_nstatic").value)


def _load(key: str, build):
    folder = cache_dir() or private_dir()
    path = folder / f"dm_ida_res_{key}.so"
    lib = _open(path, key)
    if lib is None:
        if cbackend.compiler() is None:
            raise IdaUnavailable("no C compiler found (set $CC, or install gcc).")
        source = build()
        built = cbackend.compile_library(source, folder, path)
        lib = _open(built, key) if built is not None else None
    if lib is None:
        raise IdaUnavailable(f"the generated residual did not compile or load ({path}).")
    return lib


def _open(path, key: str):
    if not path.is_file():
        return None
    try:
        lib = ctypes.CDLL(str(path))
        if (ctypes.c_char * (len(key) + 1)).in_dll(lib, "dm_key").value.decode() != key:
            return None
        _statics(lib)
    except (OSError, ValueError):
        return None
    lib.dm_static.restype = None
    lib.dm_static.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
    lib.dm_res.restype = ctypes.c_int
    lib.dm_res.argtypes = [ctypes.c_double] + [ctypes.c_void_p] * 5
    return lib


def run_compiled(res: CompiledResidual, t0: float, y: np.ndarray, yp: np.ndarray,
                 atol: np.ndarray, differential: np.ndarray, typical: np.ndarray,
                 tout: np.ndarray, nkeep: int, rtol: float, max_steps: int,
                 budget: WorkBudget | None) -> dict:
    """IDA from the consistent ``(y, yp)`` at ``t0`` through the times ``tout`` (beyond
    ``t0``, in order), in C; the first ``nkeep`` components of each state are kept.

    ``atol``, ``differential`` (1 differential, 0 algebraic) and ``typical`` (each
    component's typical size: the Jacobian's difference quotients perturb it by
    ``sqrt(eps) max(|y_j|, typical_j)``) are per component.  Returns
    ``{"y": (nkeep, reached), "last" (the state where it ended), "steps", "calls",
    "jacobians", "setups", "cpu", "ok", "message", "t_end"}``; a run past ``budget`` ends
    with ``ok`` false and a message that opens with
    :data:`~dualmech.numeric.integrators.DID_NOT_FINISH`.
    """
    run_c = driver()
    size = res.size
    arrays = [np.ascontiguousarray(a, dtype=float)
              for a in (y, yp, atol, differential, typical)]
    if any(a.shape != (size,) for a in arrays) or not arrays[-1].min() > 0:
        raise ValueError(f"`y`, `yp`, `atol`, `differential` and `typical` (positive) must "
                         f"hold {size} numbers.")
    tout = np.ascontiguousarray(tout, dtype=float)
    yout = np.zeros((tout.size, nkeep))
    stats = np.zeros(6, dtype=np.int64 if ctypes.sizeof(ctypes.c_long) == 8 else np.int32)
    reached, over_at = ctypes.c_double(t0), ctypes.c_double(t0)
    msg = ctypes.create_string_buffer(256)
    last = np.array(arrays[0])
    b = budget or WorkBudget()
    start = _time.process_time()
    flag = run_c(res.address, res.p.ctypes.data, res.k.ctypes.data, size, float(t0),
                 *[a.ctypes.data for a in arrays], tout.size, tout.ctypes.data, nkeep,
                 yout.ctypes.data, float(rtol), int(max_steps), int(b.evaluations or 0),
                 float(b.seconds or 0.0), stats.ctypes.data, ctypes.byref(reached),
                 ctypes.byref(over_at), msg, len(msg), last.ctypes.data)
    cpu = _time.process_time() - start
    done, calls = int(stats[0]), int(stats[2])
    if stats[5] == 1:
        message = (f"{DID_NOT_FINISH}: {calls} states evaluated at t={over_at.value:.6g} s, "
                   f"over the budget of {b.evaluations}")
    elif stats[5] == 2:
        message = (f"{DID_NOT_FINISH}: {cpu:.3g} s of CPU spent by t={over_at.value:.6g} s, "
                   f"over the budget of {b.seconds:g} s")
    elif flag < 0:
        message = f"IDA stopped at t={reached.value:.6g}: {msg.value.decode()}"
    else:
        message = "IDA (compiled residual)"
    return {"y": yout[:done].T, "last": last, "steps": int(stats[1]), "calls": calls,
            "jacobians": int(stats[3]), "setups": int(stats[4]), "cpu": cpu,
            "ok": flag == 0 and done == tout.size, "message": message,
            "t_end": float(reached.value)}
