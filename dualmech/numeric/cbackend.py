"""The same generated programs compiled to C: solves at C speed where a compiler exists.

:func:`c_source` prints a :class:`~dualmech.numeric.codegen.Program` of an equation set as one
C function ``dm_solve`` that, for each of ``K`` states, evaluates ``A`` and ``b`` once, solves
``A x = b`` by Gaussian elimination with partial pivoting and writes the first ``nrows``
entries of ``x`` (and ``dm_one``, the same for one state held in a work buffer, with the
right-hand side ``[q'; q'']`` as an option).  A state whose pivots trip the cheap singularity estimate (or gives a
non-finite value) is flagged instead, and the caller decides it with the exact test.

The library is compiled with the system's C compiler (``$CC``, else Python's configured one,
else ``cc``), stored beside the generated Python modules (:func:`dualmech.numeric.cache_dir`)
and loaded with :mod:`ctypes`.  Without a working compiler :func:`load` returns ``None`` and
the NumPy code is used.

Example
-------
>>> import sympy as sp
>>> from dualmech.numeric.codegen import program
>>> x, v, k = sp.symbols("x v k")
>>> prog = program([1, -k * x, 1], t=sp.Symbol("t"), q=[x], qd=[v], params=[k])
>>> "int dm_solve(" in c_source(prog, "example", (1, 1))
True
"""
from __future__ import annotations

import ctypes
import functools
import itertools
import os
import shlex
import shutil
import subprocess
import sysconfig
import tempfile
from pathlib import Path

from dualmech.numeric import codegen
from dualmech.numeric._cache import cache_dir, private_dir

__all__ = ["c_function_source", "c_source", "compile_library", "compiler", "load"]

_C_FUNCS = {"sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos",
            "atan": "atan", "atan2": "atan2", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh",
            "log": "log", "Abs": "fabs"}


class CPrinter(codegen.Printer):
    """C99 source of symengine expressions."""

    language = "c"

    def __init__(self):
        super().__init__(numpy=False)
        self.funcs = _C_FUNCS
        self.exp = "exp"
        self.sqrt = "sqrt"

    def power(self, base: str, ex: str) -> str:
        return f"pow({base}, {ex})"

    def _sign(self, e):
        arg = self(e.args[0])
        return f"(double)(({arg} > 0) - ({arg} < 0))"

    def sympy_printer(self):
        from sympy.printing.c import C99CodePrinter
        return C99CodePrinter()


_SOLVE = r"""
static int lu_solve(int N, double *A, double *b, double scale)
{
    double pmax = 0.0, pmin = INFINITY;
    for (int c = 0; c < N; c++) {
        int piv = c;
        double best = fabs(A[c * N + c]);
        for (int r = c + 1; r < N; r++) {
            double v = fabs(A[r * N + c]);
            if (v > best) { best = v; piv = r; }
        }
        if (!(best > 0.0)) return 1;
        if (piv != c) {
            for (int j = 0; j < N; j++) {
                double tmp = A[c * N + j]; A[c * N + j] = A[piv * N + j]; A[piv * N + j] = tmp;
            }
            double tmp = b[c]; b[c] = b[piv]; b[piv] = tmp;
        }
        if (best > pmax) pmax = best;
        if (best < pmin) pmin = best;
        double inv = 1.0 / A[c * N + c];
        for (int r = c + 1; r < N; r++) {
            double f = A[r * N + c] * inv;
            if (f != 0.0) {
                for (int j = c + 1; j < N; j++) A[r * N + j] -= f * A[c * N + j];
                b[r] -= f * b[c];
            }
        }
    }
    for (int c = N - 1; c >= 0; c--) {
        double x = b[c];
        for (int j = c + 1; j < N; j++) x -= A[c * N + j] * b[j];
        b[c] = x / A[c * N + c];
        if (!isfinite(b[c])) return 1;
    }
    double ref = pmax > scale ? pmax : scale;
    return !(pmin > TRIP * ref);
}
"""


_TABLE = r"""
/* A table (times, values) interpolated linearly at t, as numpy.interp: p[at] is the offset
   of its `rows` times in p (the values follow them), p[at + 1] the number of rows.  The
   caller checked that the table covers the run; t beyond it by rounding takes the end
   value. */
static double dm_table(double t, const double *p, long at)
{
    const double *x = p + (long)p[at];
    long rows = (long)p[at + 1];
    const double *v = x + rows;
    if (!(t > x[0])) return v[0];
    if (!(t < x[rows - 1])) return v[rows - 1];
    long lo = 0, hi = rows - 1;          /* x[lo] <= t < x[hi] */
    while (hi - lo > 1) {
        long mid = lo + (hi - lo) / 2;
        if (x[mid] <= t) lo = mid; else hi = mid;
    }
    double slope = (v[lo + 1] - v[lo]) / (x[lo + 1] - x[lo]);
    return slope * (t - x[lo]) + v[lo];
}
"""


def c_source(prog: codegen.Program, key: str, shape: tuple, trip: float = 1e-8,
             input_code: tuple = ()) -> str:
    """C source of ``dm_solve`` for the program of a square system ``A`` (``shape``), ``b``
    and the scale (its outputs in that order).

    A program with given inputs ``w_i`` (:func:`~dualmech.numeric.codegen.program`'s
    ``inputs``) needs ``input_code``: for each, a C expression of ``t_`` and the parameters
    ``p_j`` (a closed form) or ``dm_table(t_, p, at)`` (a table stored in ``p``, see
    :mod:`dualmech.numeric.input_code`)."""
    m, N = shape
    if m != N:
        raise ValueError("the C backend solves square systems only")
    if len(input_code) != prog.n_inputs:
        raise ValueError(f"the program has {prog.n_inputs} given inputs; `input_code` defines "
                         f"{len(input_code)}.")
    printer = CPrinter()
    n = prog.n
    lines = [f"/* Generated by dualmech.numeric.cbackend {codegen.GENERATOR_VERSION}; "
             f"key {key}; do not edit. */", "#include <math.h>", "#include <stddef.h>",
             f"#define TRIP {trip!r}", _SOLVE, _TABLE if prog.n_inputs else "",
             f'const char dm_key[] = "{key}";', "",
             "/* A and b at the state y (entries `stride` apart), then b := A^-1 b. */",
             "static int eval_solve(double t_, const double *y, long stride, const double *p,",
             f"                      const double *k, double b[{N}])", "{"]
    lines += [f"    const double p_{i} = p[{i}];" for i in range(prog.n_params)]
    lines += [f"    const double w_{i} = {c};" for i, c in enumerate(input_code)]
    lines += [f"    const double {s.name} = k[{i}];" for i, s in enumerate(prog.static_names)]
    lines += [f"    const double q_{j} = y[{j} * stride];" for j in range(n)]
    lines += [f"    const double u_{j} = y[{n + j} * stride];" for j in range(n)]
    lines += [f"    const double {s.name} = {printer(e)};" for s, e in prog.body]
    outs = prog.outputs
    lines += [f"    double A[{N * N}];"]
    lines += [f"    A[{j}] = {printer(outs[j])};" for j in range(N * N)]
    lines += [f"    b[{j}] = {printer(outs[N * N + j])};" for j in range(N)]
    lines += [f"    const double scale = {printer(outs[-1])};",
              "    (void)t_; (void)p; (void)k;",
              f"    return lu_solve({N}, A, b, scale);", "}", "",
              "/* K states in the columns of Y (2n x K); x (first nrows) into X (nrows x K). */",
              "int dm_solve(long K, double t0, const double *tv, const double *Y,",
              "             const double *p, const double *k, double *X, long nrows,",
              "             unsigned char *trip)", "{", "    int tripped = 0;",
              "    for (long i = 0; i < K; i++) {",
              f"        double b[{N}];",
              "        int bad = eval_solve(tv ? tv[i] : t0, Y + i, K, p, k, b);",
              "        if (trip) trip[i] = (unsigned char)bad;",
              "        tripped += bad;",
              "        for (long j = 0; j < nrows; j++) X[j * K + i] = b[j];",
              "    }", "    return tripped;", "}", "",
              "/* One state in work[0:2n]; the right-hand side (rhs != 0) or the solution into",
              "   work[2n:]. */",
              "int dm_one(double t, const double *p, const double *k, double *work, int rhs)",
              "{", f"    double b[{N}];",
              "    int bad = eval_solve(t, work, 1, p, k, b);",
              f"    double *out = work + {2 * n};",
              "    if (rhs) {",
              f"        for (int j = 0; j < {n}; j++) {{ out[j] = work[{n} + j]; "
              f"out[{n} + j] = b[j]; }}",
              "    } else {",
              f"        for (int j = 0; j < {N}; j++) out[j] = b[j];",
              "    }", "    return bad;", "}"]
    return "\n".join(lines) + "\n"


def c_function_source(prog: codegen.Program, key: str) -> str:
    """C source of ``int dm_out(double t, const double *y, const double *p, double *out)``:
    the outputs of ``prog`` at the state ``y = [q, q']`` with the parameters ``p`` (its
    static coefficients computed in the call: for short expressions, e.g. event functions).

    >>> import sympy as sp
    >>> from dualmech.numeric.codegen import program
    >>> x, v, L = sp.symbols("x v L")
    >>> prog = program([sp.cos(x / L)], t=sp.Symbol("t"), q=[x], qd=[v], params=[L])
    >>> "out[0] = cos(" in c_function_source(prog, "example")
    True
    """
    printer = CPrinter()
    n, nk = prog.n, len(prog.static_names)
    lines = [f"/* Generated by dualmech.numeric.cbackend {codegen.GENERATOR_VERSION}; "
             f"key {key}; do not edit. */", "#include <math.h>",
             f'const char dm_key[] = "{key}";', "",
             "int dm_out(double t_, const double *y, const double *p, double *out)", "{"]
    lines += [f"    const double p_{i} = p[{i}];" for i in range(prog.n_params)]
    lines += [f"    double kv[{max(nk, 1)}];", "    {"]
    lines += [f"        const double {s.name} = {printer(e)};" for s, e in prog.static]
    lines += [f"        kv[{i}] = {s.name};" for i, s in enumerate(prog.static_names)]
    lines += ["    }"]
    lines += [f"    const double {s.name} = kv[{i}];" for i, s in enumerate(prog.static_names)]
    lines += [f"    const double q_{j} = y[{j}];" for j in range(n)]
    lines += [f"    const double u_{j} = y[{n + j}];" for j in range(n)]
    lines += [f"    const double {s.name} = {printer(e)};" for s, e in prog.body]
    lines += [f"    out[{j}] = {printer(e)};" for j, e in enumerate(prog.outputs)]
    lines += ["    (void)t_; (void)p; (void)kv;", "    return 0;", "}"]
    return "\n".join(lines) + "\n"


def compiler() -> list[str] | None:
    """The C compiler command (``$CC``, Python's configured ``CC``, ``cc``), if one exists."""
    return _find_compiler(os.environ.get("CC", ""), os.environ.get("PATH", ""))


@functools.lru_cache(maxsize=8)
def _find_compiler(cc: str, _path: str) -> list[str] | None:
    for cand in (cc, sysconfig.get_config_var("CC"), "cc", "gcc", "clang"):
        if not cand:
            continue
        argv = shlex.split(cand)
        if argv and shutil.which(argv[0]):
            return argv
    return None


_LOADED: dict = {}
_SERIAL = itertools.count()


def load(key: str, build) -> tuple | None:
    """``(dm_one, dm_solve)`` from the compiled library for ``key`` (``build()`` gives the
    source), or ``None`` when no compiler works here.

    The library is loaded with :class:`ctypes.PyDLL` (the calls keep the GIL: they are short,
    and the per-model work buffer must not be shared by two threads at once).
    """
    if key in _LOADED:
        return _LOADED[key]
    folder = cache_dir() or private_dir()
    lib = folder / f"dm_{key}.so"
    fn = _open(lib, key)
    if fn is None:  # not there, or stale/damaged: build it (again)
        lib = _compile(build(), folder, lib)
        fn = _open(lib, key) if lib is not None else None
    _LOADED[key] = fn
    return fn


_OPENED: set = set()


def _open(lib: Path, key: str):
    if not lib.is_file():
        return None
    path = lib
    if lib in _OPENED:  # the dynamic loader would hand back the stale library it already has
        path = lib.with_name(f"{lib.stem}.{os.getpid()}_{next(_SERIAL)}.so")
        shutil.copyfile(lib, path)
    _OPENED.add(lib)
    try:
        return _bind(ctypes.PyDLL(str(path)), key)
    except (OSError, AttributeError):
        return None


def _compile(source: str, folder: Path, lib: Path) -> Path | None:
    return compile_library(source, folder, lib)


def compile_library(source: str, folder: Path, lib: Path, flags=()) -> Path | None:
    """Compile the C ``source`` into the shared library ``lib`` (named in ``folder``, or in a
    private directory when ``folder`` is not writable), atomically, with ``flags`` (libraries
    to link, linker options) after the source; the library's path, or ``None`` when there is
    no compiler or it fails."""
    cc = compiler()
    if cc is None:
        return None
    try:
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    except OSError:
        folder = private_dir()
    lib = folder / lib.name
    with tempfile.TemporaryDirectory(dir=folder, prefix=".build_") as tmp:
        src = Path(tmp) / "dm.c"
        src.write_text(source, encoding="utf-8")
        out = Path(tmp) / "dm.so"
        cmd = cc + ["-O2", "-shared", "-fPIC", "-o", str(out), str(src), *flags, "-lm"]
        try:
            done = subprocess.run(cmd, capture_output=True, timeout=600)
        except (OSError, subprocess.TimeoutExpired):
            return None
        if done.returncode != 0 or not out.is_file():
            return None
        os.replace(out, lib)
    return lib


def _bind(dll, key: str):
    try:
        recorded = (ctypes.c_char * (len(key) + 1)).in_dll(dll, "dm_key").value
    except ValueError:
        return None
    if recorded.decode() != key:  # a foreign or stale library under this name
        return None
    many = dll.dm_solve
    many.restype = ctypes.c_int
    many.argtypes = [ctypes.c_long, ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p,
                     ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_long,
                     ctypes.c_void_p]
    one = dll.dm_one
    one.restype = ctypes.c_int
    one.argtypes = [ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p,
                    ctypes.c_int]
    return one, many
