r"""SUNDIALS CVODE driving the generated C right-hand side: the C driver, built and loaded.

The driver is a small C file compiled once per machine (and SUNDIALS build) beside the
generated model libraries (:func:`dualmech.numeric.cache_dir`) with the system's C compiler
(:func:`dualmech.numeric.cbackend.compiler`).  It runs CVODE from the first sample time to the
last and calls the model library's ``dm_one`` through a function pointer at every right-hand
side evaluation: no Python runs per step.  A state at which the compiled solve trips the cheap
singularity estimate (:mod:`dualmech.numeric.cbackend`) is handed to a Python callback that
decides it exactly -- the same rule as :meth:`NumericModel.rhs
<dualmech.numeric.model.NumericModel.rhs>` -- so a singular mass matrix stops the run with
:class:`~dualmech.numeric.model.SingularityError`, never a silent wrong number.
Event functions (``dm_events``: a compiled function of the state, rows of other model
libraries' solutions -- reactions -- and coordinate bounds, each with a direction) are CVODE's
root functions; the run stops at the first sign change and says which
(:class:`~dualmech.numeric.cvode_events.Stops`).

Why this route: ``scikit-sundae``, already a dependency (IDA, :mod:`dualmech.numeric.daesolve`),
ships SUNDIALS 7's shared libraries in its Linux wheel (``scikit_sundae.libs/``) but not its
headers, and calls a Python function at every step.  Debian's ``libsundials-dev`` is SUNDIALS 6
(another ABI) and needs root.  So the driver declares the few SUNDIALS 7 functions it calls
itself (below: the prototypes are SUNDIALS 7's ``cvode.h``, ``sundials_*.h``,
``nvector_serial.h``, ``sunmatrix_dense.h``, ``sunlinsol_dense.h`` and
``sunnonlinsol_fixedpoint.h``) and links against the wheel's libraries; what the declarations
assume is checked on the libraries before anything is compiled: the major version (7), the
width of ``sunindextype`` (32 or 64 bits, read off a serial vector's layout) and that
``sunrealtype`` is ``double``.  Where any of this fails -- no compiler, no wheel libraries
(another platform), another SUNDIALS -- :func:`driver` raises :class:`CvodeUnavailable` with
the reason, and :func:`dualmech.numeric.cvode.integrate` falls back to scipy.

Example
-------
>>> "int dm_cvode(" in driver_source("int")
True
"""
from __future__ import annotations

import ctypes
import functools
import importlib.util
from pathlib import Path

from dualmech.numeric import cbackend
from dualmech.numeric._cache import cache_dir, digest, private_dir

__all__ = ["CvodeUnavailable", "driver", "driver_source", "sundials_libraries"]

#: SUNDIALS major version the declarations below are written for.
MAJOR = 7
#: Bumped whenever the driver's C source changes meaning (part of the library's key).
DRIVER_VERSION = "3"
_LIBS = ("core", "nvecserial", "sunmatrixdense", "sunlinsoldense", "cvode")


class CvodeUnavailable(RuntimeError):
    """The CVODE route cannot run here; the message says why (and what would enable it)."""


_DECLARATIONS = r"""
typedef double sunrealtype;
typedef DM_INDEX sunindextype;
typedef int SUNComm;                 /* SUNDIALS built without MPI */
typedef int SUNErrCode;
typedef struct SUNContext_ *SUNContext;
typedef struct _generic_N_Vector *N_Vector;
typedef struct _generic_SUNMatrix *SUNMatrix;
typedef struct _generic_SUNLinearSolver *SUNLinearSolver;
typedef struct _generic_SUNNonlinearSolver *SUNNonlinearSolver;
typedef int (*CVRhsFn)(sunrealtype t, N_Vector y, N_Vector ydot, void *user_data);
typedef int (*CVRootFn)(sunrealtype t, N_Vector y, sunrealtype *gout, void *user_data);

SUNErrCode SUNContext_Create(SUNComm comm, SUNContext *sunctx);
SUNErrCode SUNContext_Free(SUNContext *sunctx);
SUNErrCode SUNContext_ClearErrHandlers(SUNContext sunctx);
N_Vector N_VNew_Serial(sunindextype vec_length, SUNContext sunctx);
void N_VDestroy(N_Vector v);
sunrealtype *N_VGetArrayPointer(N_Vector v);
SUNMatrix SUNDenseMatrix(sunindextype M, sunindextype N, SUNContext sunctx);
void SUNMatDestroy(SUNMatrix A);
SUNLinearSolver SUNLinSol_Dense(N_Vector y, SUNMatrix A, SUNContext sunctx);
SUNErrCode SUNLinSolFree(SUNLinearSolver S);
SUNNonlinearSolver SUNNonlinSol_FixedPoint(N_Vector y, int m, SUNContext sunctx);
SUNErrCode SUNNonlinSolFree(SUNNonlinearSolver NLS);

#define CV_ADAMS 1
#define CV_BDF 2
#define CV_NORMAL 1
#define CV_ROOT_RETURN 2
void *CVodeCreate(int lmm, SUNContext sunctx);
int CVodeInit(void *cvode_mem, CVRhsFn f, sunrealtype t0, N_Vector y0);
int CVodeSStolerances(void *cvode_mem, sunrealtype reltol, sunrealtype abstol);
int CVodeSetUserData(void *cvode_mem, void *user_data);
int CVodeSetMaxNumSteps(void *cvode_mem, long int mxsteps);
int CVodeSetStopTime(void *cvode_mem, sunrealtype tstop);
int CVodeSetLinearSolver(void *cvode_mem, SUNLinearSolver LS, SUNMatrix A);
int CVodeSetNonlinearSolver(void *cvode_mem, SUNNonlinearSolver NLS);
int CVodeRootInit(void *cvode_mem, int nrtfn, CVRootFn g);
int CVode(void *cvode_mem, sunrealtype tout, N_Vector yout, sunrealtype *tret, int itask);
int CVodeGetNumSteps(void *cvode_mem, long int *nsteps);
int CVodeGetNumRhsEvals(void *cvode_mem, long int *nfevals);
int CVodeGetNumLinSolvSetups(void *cvode_mem, long int *nlinsetups);
int CVodeGetNumJacEvals(void *cvode_mem, long int *njevals);
int CVodeGetNumLinRhsEvals(void *cvode_mem, long int *nfevalsLS);
char *CVodeGetReturnFlagName(long int flag);
void CVodeFree(void **cvode_mem);
"""

_DRIVER = r"""
int CVodeSetRootDirection(void *cvode_mem, int *rootdir);
int CVodeGetRootInfo(void *cvode_mem, int *rootsfound);

/* y' = f(t, y) through a model library's dm_one (state in work[0:n2], f into work[n2:]);
   a state dm_one flags goes to `slow` (Python: decided exactly), which returns 0 or stops
   the run with a nonzero value.  Optional event functions (dm_events) stop the run where
   one changes sign in its direction. */
typedef int (*dm_one_fn)(double t, const double *p, const double *k, double *work, int rhs);
typedef int (*dm_slow_fn)(double t, const double *y, double *ydot);
typedef int (*dm_out_fn)(double t, const double *y, const double *p, double *out);

/* The event functions, in this order: nfun compiled functions of the state (cbackend's
   dm_out with the parameters fun_p: a declared singular set); nrow rows of models' solutions
   [q''; lambda] at the state (row[r] of model[r]: a reaction; each of the nsolve models is
   its library's dm_one with its p, k and a work buffer); nbound coordinates' distances
   y[index[b]] - bound[b].  direction[i]: -1, +1 (only a decrease, an increase stops the
   run) or 0 (either); found: CVODE's root information where the run stopped.  A state a
   model's solve flags goes to `slow`, which writes every event value (decided exactly). */
typedef struct {
    dm_out_fn fun; const double *fun_p; int nfun;
    int nsolve; void **one; void **p; void **k; void **work;
    int nrow; const int *model; const int *row;
    int nbound; const int *index; const double *bound;
    int *direction; int *found; dm_slow_fn slow; long nslow;
} dm_events;

typedef struct {
    dm_one_fn one; const double *p, *k; double *work; long n2; dm_slow_fn slow; long nslow;
    dm_events *events;
} dm_ode;

static int dm_g(sunrealtype t, N_Vector y, sunrealtype *gout, void *user)
{
    dm_ode *o = (dm_ode *)user;
    dm_events *e = o->events;
    const double *yv = N_VGetArrayPointer(y);
    int at = 0;
    if (e->nfun > 0) {
        if (e->fun(t, yv, e->fun_p, gout) != 0) return 1;
        at = e->nfun;
    }
    for (int m = 0; m < e->nsolve; m++) {
        double *w = (double *)e->work[m];
        memcpy(w, yv, (size_t)o->n2 * sizeof(double));
        if (((dm_one_fn)e->one[m])(t, (const double *)e->p[m], (const double *)e->k[m], w, 0)) {
            e->nslow++;
            return (e->slow && e->slow(t, yv, gout) == 0) ? 0 : 1;
        }
    }
    for (int r = 0; r < e->nrow; r++)
        gout[at + r] = ((const double *)e->work[e->model[r]])[o->n2 + e->row[r]];
    at += e->nrow;
    for (int b = 0; b < e->nbound; b++) gout[at + b] = yv[e->index[b]] - e->bound[b];
    return 0;
}

static int dm_f(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    dm_ode *o = (dm_ode *)user;
    const double *yv = N_VGetArrayPointer(y);
    double *dv = N_VGetArrayPointer(ydot);
    memcpy(o->work, yv, (size_t)o->n2 * sizeof(double));
    if (o->one(t, o->p, o->k, o->work, 1) == 0) {
        memcpy(dv, o->work + o->n2, (size_t)o->n2 * sizeof(double));
        return 0;
    }
    o->nslow++;
    return (o->slow && o->slow(t, yv, dv) == 0) ? 0 : -1;
}

const char dm_key[] = DM_KEY;

/* Integrate from t0 (state y0) through the nout times tout (strictly beyond t0, in order),
   writing each state into yout (nout x n2, row by row).  lmm: 1 Adams (fixed-point
   iteration), 2 BDF (Newton, dense difference-quotient Jacobian).  stats: outputs written,
   steps, f evaluations, slow (flagged) states, linear-solver setups, Jacobians; the state
   where the run ended (at *t_reached) into ylast.  Returns 0, 2 when an event function
   changed sign (the run stops there; events->found says which),
   a CVODE flag (< 0; its name in msg), or -1000 when SUNDIALS could not allocate. */
int dm_cvode(dm_one_fn one, const double *p, const double *k, double *work, dm_slow_fn slow,
             long n2, int lmm, double t0, const double *y0, long nout, const double *tout,
             double *yout, double rtol, double atol, long max_steps, long *stats,
             double *t_reached, char *msg, long msglen, dm_events *events, double *ylast)
{
    SUNContext ctx = NULL; void *mem = NULL; N_Vector y = NULL; SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL; SUNNonlinearSolver NLS = NULL;
    dm_ode o = {one, p, k, work, n2, slow, 0, events};
    int nroots = events ? events->nfun + events->nrow + events->nbound : 0;
    long i = 0, v = 0;
    double tret = t0;
    int flag = -1000;
    msg[0] = 0;
    for (int s = 0; s < 6; s++) stats[s] = 0;
    if (SUNContext_Create(0, &ctx) != 0 || !ctx) goto done;
    SUNContext_ClearErrHandlers(ctx);  /* the flag is reported to the caller instead */
    y = N_VNew_Serial((sunindextype)n2, ctx);
    mem = y ? CVodeCreate(lmm, ctx) : NULL;
    if (!mem) goto done;
    memcpy(N_VGetArrayPointer(y), y0, (size_t)n2 * sizeof(double));
    if ((flag = CVodeInit(mem, dm_f, t0, y)) < 0) goto done;
    if ((flag = CVodeSetUserData(mem, &o)) < 0) goto done;
    if ((flag = CVodeSStolerances(mem, rtol, atol)) < 0) goto done;
    if ((flag = CVodeSetMaxNumSteps(mem, max_steps)) < 0) goto done;
    if ((flag = CVodeSetStopTime(mem, tout[nout - 1])) < 0) goto done;
    if (nroots > 0 && (flag = CVodeRootInit(mem, nroots, dm_g)) < 0) goto done;
    if (nroots > 0 && (flag = CVodeSetRootDirection(mem, events->direction)) < 0) goto done;
    flag = -1000;
    if (lmm == CV_BDF) {
        A = SUNDenseMatrix((sunindextype)n2, (sunindextype)n2, ctx);
        LS = A ? SUNLinSol_Dense(y, A, ctx) : NULL;
        if (!LS) goto done;
        if ((flag = CVodeSetLinearSolver(mem, LS, A)) < 0) goto done;
    } else {
        NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
        if (!NLS) goto done;
        if ((flag = CVodeSetNonlinearSolver(mem, NLS)) < 0) goto done;
    }
    for (i = 0; i < nout; i++) {
        flag = CVode(mem, tout[i], y, &tret, CV_NORMAL);
        if (flag == CV_ROOT_RETURN) CVodeGetRootInfo(mem, events->found);
        if (flag < 0 || flag == CV_ROOT_RETURN) break;
        memcpy(yout + i * n2, N_VGetArrayPointer(y), (size_t)n2 * sizeof(double));
    }
    memcpy(ylast, N_VGetArrayPointer(y), (size_t)n2 * sizeof(double));
    if (flag > 0 && flag != CV_ROOT_RETURN) flag = 0;  /* CV_TSTOP_RETURN at the end */
    CVodeGetNumSteps(mem, &stats[1]);
    CVodeGetNumRhsEvals(mem, &stats[2]);
    if (lmm == CV_BDF) {
        CVodeGetNumLinSolvSetups(mem, &stats[4]);
        CVodeGetNumJacEvals(mem, &stats[5]);
        CVodeGetNumLinRhsEvals(mem, &v);
        stats[2] += v;  /* with the difference-quotient Jacobians' evaluations */
    }
done:
    stats[0] = i;
    stats[3] = o.nslow;
    *t_reached = tret;
    if (flag == -1000) {
        snprintf(msg, (size_t)msglen, "SUNDIALS could not allocate the solver");
    } else if (flag < 0) {
        char *name = CVodeGetReturnFlagName(flag);
        snprintf(msg, (size_t)msglen, "%s", name ? name : "CVODE error");
        free(name);
    }
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (NLS) SUNNonlinSolFree(NLS);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
    return flag;
}
"""


def driver_source(index_type: str, key: str = "") -> str:
    """The driver's C source for SUNDIALS 7 with ``sunindextype`` = ``index_type``."""
    head = (f"/* dualmech CVODE driver {DRIVER_VERSION}: SUNDIALS {MAJOR} declarations, "
            "then the driver. */\n#include <stdint.h>\n#include <stdio.h>\n"
            "#include <stdlib.h>\n#include <string.h>\n"
            f"#define DM_INDEX {index_type}\n#define DM_KEY \"{key}\"\n")
    return head + _DECLARATIONS + _DRIVER


def sundials_libraries() -> dict[str, Path]:
    """SUNDIALS's shared libraries from scikit-sundae's wheel, ``{"cvode": path, ...}``.

    Raises :class:`CvodeUnavailable` when scikit-sundae is not installed or its installation
    does not carry them (a platform whose wheel stores them elsewhere, a build from source).
    """
    spec = importlib.util.find_spec("sksundae")
    if spec is None or not spec.origin:
        raise CvodeUnavailable("scikit-sundae is not installed (pip install scikit-sundae).")
    package = Path(spec.origin).parent
    places = [package.parent / "scikit_sundae.libs", package / ".libs"]
    found = {}
    for name in _LIBS:
        hits = sorted(p for d in places if d.is_dir() for p in d.glob(f"libsundials_{name}*.so*"))
        if not hits:
            raise CvodeUnavailable(
                f"no libsundials_{name} shared library in scikit-sundae's installation "
                f"({' or '.join(str(d) for d in places)}): its wheel for this platform does "
                "not bundle SUNDIALS where the driver looks.")
        found[name] = hits[-1]
    return found


def _probe(libs: dict[str, Path]) -> str:
    """The C type of the libraries' ``sunindextype``, after checking the version and that
    ``sunrealtype`` is ``double``; :class:`CvodeUnavailable` otherwise."""
    try:
        core = ctypes.CDLL(str(libs["core"]))
        serial = ctypes.CDLL(str(libs["nvecserial"]))
    except OSError as exc:
        raise CvodeUnavailable(f"SUNDIALS's libraries do not load: {exc}") from None
    major, minor, patch = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
    label = ctypes.create_string_buffer(64)
    core.SUNDIALSGetVersionNumber(ctypes.byref(major), ctypes.byref(minor),
                                  ctypes.byref(patch), label, 64)
    if major.value != MAJOR:
        raise CvodeUnavailable(f"scikit-sundae carries SUNDIALS {major.value}.{minor.value}; "
                               f"the CVODE driver is written for SUNDIALS {MAJOR}.")
    ctx = ctypes.c_void_p()
    if core.SUNContext_Create(0, ctypes.byref(ctx)) != 0:
        raise CvodeUnavailable("SUNDIALS could not create a context.")
    serial.N_VNew_Serial.restype = ctypes.c_void_p
    serial.N_VNew_Serial.argtypes = [ctypes.c_int64, ctypes.c_void_p]  # 5 reads the same
    core.N_VGetArrayPointer.restype = ctypes.c_void_p                  # in 32 bits
    core.N_VGetArrayPointer.argtypes = [ctypes.c_void_p]
    core.N_VConst.argtypes = [ctypes.c_double, ctypes.c_void_p]
    core.N_VDestroy.argtypes = [ctypes.c_void_p]
    vec = serial.N_VNew_Serial(5, ctx)
    try:
        data = core.N_VGetArrayPointer(vec)
        core.N_VConst(1.5, vec)
        value = ctypes.c_double.from_address(data).value
        content = ctypes.c_void_p.from_address(vec).value  # N_Vector's first field
        # serial content: {sunindextype length; sunbooleantype own_data; sunrealtype *data}
        layouts = {"int32_t": (ctypes.c_int32, 8), "int64_t": (ctypes.c_int64, 16)}
        index = [name for name, (ctype, at) in layouts.items()
                 if ctype.from_address(content).value == 5
                 and ctypes.c_void_p.from_address(content + at).value == data]
    finally:
        core.N_VDestroy(vec)
        core.SUNContext_Free(ctypes.byref(ctx))
    if value != 1.5:
        raise CvodeUnavailable("scikit-sundae's SUNDIALS is not built in double precision.")
    if len(index) != 1:
        raise CvodeUnavailable("the layout of SUNDIALS's serial vector is not the one the "
                               "driver knows (sunindextype of 32 or 64 bits).")
    return index[0]


@functools.lru_cache(maxsize=1)
def driver():
    """The bound ``dm_cvode`` function of the compiled driver (from the cache, else compiled
    now); :class:`CvodeUnavailable` says why not."""
    libs = sundials_libraries()
    index = _probe(libs)
    key = digest("cvode driver", DRIVER_VERSION, index, *[str(libs[n]) for n in _LIBS])[:24]
    folder = cache_dir() or private_dir()
    lib = folder / f"dm_cvode_{key}.so"
    fn = _open(lib, key)
    if fn is not None:
        return fn
    cc = cbackend.compiler()
    if cc is None:
        raise CvodeUnavailable("no C compiler found (set $CC, or install gcc).")
    flags = [str(libs[n]) for n in reversed(_LIBS)] + [f"-Wl,-rpath,{libs['cvode'].parent}"]
    built = cbackend.compile_library(driver_source(index, key), folder, lib, flags)
    fn = _open(built, key) if built is not None else None
    if fn is None:
        raise CvodeUnavailable(f"the CVODE driver did not compile or load with {' '.join(cc)} "
                               f"against {libs['cvode'].parent}.")
    return fn


def _open(lib: Path, key: str):
    if not lib.is_file():
        return None
    try:
        dll = ctypes.CDLL(str(lib))  # the GIL is released while CVODE runs
        recorded = (ctypes.c_char * (len(key) + 1)).in_dll(dll, "dm_key").value
    except (OSError, ValueError):
        return None
    if recorded.decode() != key:
        return None
    fn = dll.dm_cvode
    fn.restype = ctypes.c_int
    P = ctypes.c_void_p
    fn.argtypes = [P, P, P, P, P, ctypes.c_long, ctypes.c_int, ctypes.c_double, P,
                   ctypes.c_long, P, P, ctypes.c_double, ctypes.c_double, ctypes.c_long, P, P,
                   ctypes.c_char_p, ctypes.c_long, P, P]
    return fn
