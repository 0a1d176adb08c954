"""Prepared grading contexts kept between runs, so that one ``dualmech grade`` starts warm.

Loading a problem for grading -- deriving its models, sampling its exact points on the
motion, building the tables that explain a wrong answer -- takes a one-answer ``dualmech
grade`` 60-100 ms for a problem of the catalogue, as long as the rest of its work above
``import sympy``.  :func:`save` keeps the warmed :class:`~.context.ProblemContext` in the
user's cache directory (:func:`dualmech.caches.cache_dir`); :func:`load` reads it back in a few
milliseconds.  A context is only a cache: whatever it holds is rebuilt identically without it.

**When a file is used.**  Its name is a digest of the problem's name and seed, the versions
of Python, sympy and mpmath, and the size and modification time of symengine's and
python-flint's files and of every source file of ``dualmech`` and of the catalogue: change
any of them (edit a model, upgrade sympy) and the file is simply not found.  Only a catalogue
problem asked for by its name, at its default size, is kept (a problem from a file, a
notebook or another catalogue is built as before).

**What reading one can do.**  The file is written through a temporary name and a rename,
begins with a digest of its contents, and is read only when it and its directory belong to
the user and nobody else may write to them (:func:`dualmech.caches.read_private`).  It is
unpickled by :class:`_Reader`, which refuses every global but the classes a context is made
of: the grader's own data classes, the problem's class, and sympy's expression classes, whose
arguments must not contain text (sympy parses text, so a forged ``sin("...")`` could run
code; a symbol's name and a float's digits are the only text allowed).  A damaged, foreign or
unreadable file is ignored and the context built, as without a cache.

Example
-------
>>> import os, tempfile
>>> os.environ["DUALMECH_CACHE_DIR"] = tempfile.mkdtemp()
>>> from dualmech.grade.api import Grader
>>> g = Grader("simple_pendulum")
>>> print(g.grade("a*theta'' + g*sin(theta) = 0").status)   # builds models, points
right
>>> save(g.context)
True
>>> ctx = load("simple_pendulum")
>>> ctx is not g.context, ctx.coordinates == g.context.coordinates
(True, True)
>>> Grader("simple_pendulum").context.store.keys() == g.context.store.keys()
True
>>> del os.environ["DUALMECH_CACHE_DIR"]
"""
from __future__ import annotations

import hashlib
import io
import os
import pickle
import re
import sys

import sympy as sp

from dualmech.caches import cache_dir, read_private, write_atomic
from dualmech.model.problem import Problem

__all__ = ["load", "save"]

_MAGIC = b"dualmech-context 1\n"
_MOST = 1 << 25   # a context of the catalogue is 20-300 kB; a file past 32 MB is not read

#: modules whose classes a stored context is made of (plain data; building one runs no IO)
_DATA_MODULES = frozenset({
    "dualmech.model.dimensions", "dualmech.model.equations", "dualmech.model.problem",
    "dualmech.grade.answers", "dualmech.grade.audit", "dualmech.grade.context",
    "dualmech.grade.energies", "dualmech.grade.formula", "dualmech.grade.maps",
    "dualmech.grade.terms", "dualmech.grade.vocabulary",
})
_BUILTINS = frozenset({"tuple", "list", "dict", "set", "frozenset", "complex"})
_OTHERS = {("fractions", "Fraction"), ("mpmath.ctx_mp_python", "mpf"),
           ("mpmath.ctx_mp_python", "mpc"),
           ("dualmech.exact.surds", "Surd")}   # exact values at the points of a model with sqrt(3)
#: sympy classes that take text that is never parsed: a symbol's name, a float's digits
_TEXT_OK = (sp.Symbol, sp.Float)

#: the catalogue's modules (a problem's class is one of theirs)
_PROBLEM_MODULE = re.compile(r"dualmech\.problems\.[a-z][a-z0-9_]*")

_STAMP: list = []   # the code stamp, computed once per process


class _Reader(pickle.Unpickler):
    """Unpickles a stored context, every global outside the allowed classes refused."""

    def __init__(self, data: bytes):
        super().__init__(io.BytesIO(data))

    def find_class(self, module, name):
        if module == "builtins" and name in _BUILTINS or (module, name) in _OTHERS:
            return super().find_class(module, name)
        if module in _DATA_MODULES or _PROBLEM_MODULE.fullmatch(module):
            obj = super().find_class(module, name)   # (a catalogue module: imports nothing else)
            if isinstance(obj, type) and obj.__module__ == module and (
                    module in _DATA_MODULES or issubclass(obj, Problem)):
                return obj
        elif module == "sympy.core.function" and name == "_rebuild_undef":
            return _undefined_function
        elif module.startswith("sympy."):
            obj = super().find_class(module, name)
            if isinstance(obj, type) and obj.__module__ == module and (
                    issubclass(obj, (sp.Basic, sp.MatrixBase))
                    or module.startswith("sympy.polys.")):
                return _guarded(obj)
        raise pickle.UnpicklingError(f"a stored grading context names {module}.{name}; "
                                     "refused")


def _undefined_function(name, kwargs):
    if not isinstance(name, str) or not isinstance(kwargs, dict) or \
            not all(isinstance(k, str) and isinstance(v, (bool, type(None)))
                    for k, v in kwargs.items()):
        raise pickle.UnpicklingError("a stored function name is malformed; refused")
    return _guarded(sp.Function(name, **kwargs))


_GUARDS: dict = {}


def _guarded(cls):
    """A stand-in for sympy class ``cls`` that refuses text among the arguments (sympy
    parses text, which evaluates Python) before building the object."""
    guard = _GUARDS.get(cls)
    if guard is None:
        build = _builder(cls)

        def __new__(_, *args, **kwargs):
            if issubclass(cls, _TEXT_OK):
                _no_text(args[1:], kwargs)
            else:
                _no_text(args, kwargs)
            return build(*args, **kwargs)
        guard = _GUARDS[cls] = type(f"Stored{cls.__name__}", (), {"__new__": __new__})
    return guard


def _builder(cls):
    """How to rebuild a stored object of sympy class ``cls`` from its arguments.  They come
    from an object sympy had already put in canonical form, so sums, products, powers and
    functions are rebuilt as they are, without canonicalising them again (the same
    expression, equal and with the same hash, at a fraction of the cost)."""
    if issubclass(cls, (sp.Add, sp.Mul)):
        return lambda *args: cls._from_args(args)
    if issubclass(cls, (sp.Pow, sp.Function, sp.Derivative)):
        return lambda *args: cls(*args, evaluate=False)
    return cls


def _no_text(args, kwargs) -> None:
    stack = list(args) + list(kwargs.values())
    while stack:
        x = stack.pop()
        if isinstance(x, (str, bytes, bytearray)):
            raise pickle.UnpicklingError("a stored sympy object has text among its "
                                         "arguments; refused")
        if isinstance(x, (tuple, list, set, frozenset)):
            stack.extend(x)
        elif isinstance(x, dict):
            stack.extend(x.keys())
            stack.extend(x.values())


def _stamp() -> str:
    """Versions and the size and time of every source file the context depends on."""
    if not _STAMP:
        import importlib.util
        import mpmath
        import dualmech
        from dualmech import problems
        h = hashlib.sha256()
        h.update("\0".join([sys.version, sp.__version__, mpmath.__version__]).encode())
        for name in ("symengine", "flint"):   # their files, not imported just for a version
            try:
                origin = getattr(importlib.util.find_spec(name), "origin", None)
                st = os.stat(origin) if origin else None
            except (ImportError, ValueError, OSError):
                origin = st = None
            h.update(f"{name}\0{origin}\0{st and (st.st_size, st.st_mtime_ns)}\n".encode())
        roots = sorted({os.path.dirname(dualmech.__file__), os.path.dirname(problems.__file__)})
        while roots:
            folder = roots.pop()
            try:
                entries = sorted(os.scandir(folder), key=lambda e: e.name)
            except OSError:
                continue
            for entry in entries:
                if entry.name.endswith(".py"):
                    try:
                        st = entry.stat()
                    except OSError:
                        continue
                    h.update(f"{entry.path}\0{st.st_size}\0{st.st_mtime_ns}\n".encode())
                elif entry.is_dir() and entry.name != "__pycache__":
                    roots.append(entry.path)
        _STAMP.append(h.hexdigest())
    return _STAMP[0]


def _where(name: str, seed: int):
    """``(folder, file name)`` of ``name``'s stored context, or ``None``."""
    from dualmech import problems
    folder = cache_dir()
    if folder is None or not problems.is_name(name) or not isinstance(seed, int):
        return None
    key = hashlib.sha256(f"{name}\0{seed}\0{_stamp()}".encode()).hexdigest()[:32]
    return folder, f"context-{name}-{key}.pickle"


def load(name: str, seed: int = 0):
    """The stored context of catalogue problem ``name`` (a
    :class:`~.context.ProblemContext`), or ``None`` when there is none for this code."""
    where = _where(name, seed)
    if where is None:
        return None
    folder, file = where
    blob = read_private(folder / file, _MOST)
    if not blob or not blob.startswith(_MAGIC):
        return None
    end = blob.find(b"\n", len(_MAGIC))
    payload = memoryview(blob)[end + 1:]    # (no copy of a file that may be large)
    if end < 0 or blob[len(_MAGIC):end] != hashlib.sha256(payload).hexdigest().encode("ascii"):
        return None
    from dualmech.grade.context import ProblemContext
    try:
        ctx = _Reader(payload).load()
    except Exception:   # noqa: BLE001 - a file that does not load is as good as none
        return None
    if not isinstance(ctx, ProblemContext) or ctx.named != name or ctx.seed != seed:
        return None
    ctx.stored = frozenset(ctx.store)
    return ctx


def save(ctx) -> bool:
    """Keep ``ctx`` (warmed as wanted) for later runs, unless what is kept already holds
    everything it has built; ``False`` when it is not kept: a context not built for a bare
    catalogue name (``ctx.named``, set by :class:`~.api.Grader`), caching off, a part that
    does not pickle, an unwritable directory."""
    name = ctx.named
    if name is None or ctx.stored >= frozenset(ctx.store) or \
            not _PROBLEM_MODULE.fullmatch(type(ctx.problem).__module__):
        return False   # (a registered catalogue's problem: its code is not in the stamp)
    where = _where(name, ctx.seed)
    if where is None:
        return False
    folder, file = where
    try:
        payload = pickle.dumps(ctx, protocol=5)
    except Exception:   # noqa: BLE001 - something built that does not pickle: not kept
        return False
    digest = hashlib.sha256(payload).hexdigest().encode("ascii")
    if not write_atomic(folder, file, _MAGIC + digest + b"\n" + payload):
        return False
    ctx.stored = frozenset(ctx.store)
    for old in folder.glob(f"context-{name}-*.pickle"):   # kept by an older build
        if old.name != file:
            try:
                old.unlink()
            except OSError:
                pass
    return True
