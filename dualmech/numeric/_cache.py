"""The on-disk cache of generated modules, shared by every process of a user.

A generated module is stored as ``<key>.py`` in :func:`cache_dir` and imported with
:mod:`importlib` (so Python keeps its bytecode beside it).  The key is a digest of what the
code was generated from (:func:`digest`) and of the generator's version: a changed model gets
a new key, and a module whose recorded key does not match (a truncated or foreign file) is
generated again.  Files are written to a temporary name and renamed, so concurrent processes
never import a half-written module.

The directory is ``$DUALMECH_CACHE_DIR`` if set, else ``$XDG_CACHE_HOME/dualmech``, else
``~/.cache/dualmech`` (:func:`dualmech.caches.cache_dir`); it is created private to the user
(mode 0700).  Set
``DUALMECH_CACHE_DIR=off`` to keep generated code in memory only.  Anyone who can write to the
directory can change what runs, as with any directory of Python modules: keep it private.
"""
from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
import tempfile
from pathlib import Path
from typing import Callable, Sequence

import sympy as sp

from dualmech.caches import cache_dir

__all__ = ["cache_dir", "digest", "load_module", "private_dir"]

_MEMORY: dict = {}


def digest(*parts) -> str:
    """A stable hex digest of sympy expressions (and strings, sequences of them).

    Shared subtrees are hashed once (a memo by object identity), so large expressions with
    much repetition -- every derivation of a chain -- hash in time proportional to their
    distinct nodes, not to the length of their printed form.  Symbols contribute their names
    and assumptions; numbers their exact value.
    """
    memo: dict = {}
    held: dict = {}
    h = hashlib.sha256()
    for part in parts:
        h.update(_node(part, memo, held).encode())
        h.update(b"|")
    return h.hexdigest()


def _node(e, memo: dict, held: dict) -> str:
    hit = memo.get(id(e))
    if hit is not None:
        return hit[1]
    rows = getattr(e, "se", None)
    if isinstance(rows, tuple) and hasattr(e, "names"):
        # equations held in symengine (model.equations.Rows): their own trees, and the sympy
        # symbols their names stand for (assumptions included), never the sympy form
        names = sorted((k, v) for k, v in e.names.items() if isinstance(v, sp.Symbol))
        text = "r:" + ",".join([str(e.plain)] + [_node(q, memo, held) for q in e.coordinates]
                               + [_held(x, held) for x in rows]
                               + [k + "=" + _node(v, memo, held) for k, v in names])
    elif _is_held(e):
        text = "h:" + _held(e, held)
    elif isinstance(e, str):
        text = "s:" + e
    elif isinstance(e, (list, tuple, Sequence)):   # also equations held in symengine
        text = "l:" + ",".join(_node(a, memo, held) for a in e)
    elif isinstance(e, sp.Basic) and not e.args:
        text = "a:" + sp.srepr(e)
    elif isinstance(e, sp.Basic):
        # the class name of an undefined function (q(t)) is part of type(e).__name__
        text = f"{type(e).__name__}(" + ",".join(_node(a, memo, held) for a in e.args) + ")"
    else:
        raise TypeError(f"cannot digest {type(e).__name__}")
    value = hashlib.sha256(text.encode()).hexdigest()[:32]
    memo[id(e)] = (e, value)  # keep e alive so its id is not reused
    return value


def _is_held(e) -> bool:
    return (type(e).__module__ or "").startswith("symengine")


def _held(e, memo: dict) -> str:
    """Digest of a symengine tree; a shared subtree (equal trees) is hashed once.

    (Keyed by the tree itself, in a memo of its own: symengine wrappers are made anew at each
    ``.args``, so their ``id`` says nothing; equal trees are found by symengine's hash.)"""
    if isinstance(e, dict):    # a row's {ingredient: term}
        return "d:" + ",".join(k + "=" + _held(v, memo) for k, v in sorted(e.items()))
    hit = memo.get(e)
    if hit is not None:
        return hit
    args, kind = e.args, type(e).__name__
    if args:   # a function's own name (q in q(t)) is not among its args
        head = kind + (":" + e.get_name() if hasattr(e, "get_name") else "")
        text = head + "(" + ",".join(_held(a, memo) for a in args) + ")"
    elif kind == "RealDouble":   # printed digits may round: the exact binary value
        text = "RealDouble:" + float(e).hex()
    elif kind == "ComplexDouble":
        z = complex(e)
        text = f"ComplexDouble:{z.real.hex()},{z.imag.hex()}"
    else:
        text = f"{kind}:{e}"
    value = hashlib.sha256(text.encode()).hexdigest()[:32]
    memo[e] = value
    return value


def load_module(key: str, build: Callable[[], str]):
    """The generated module for ``key``: from memory, from disk, or built by ``build()``."""
    hit = _MEMORY.get(key)
    if hit is not None:
        return hit
    folder = cache_dir()
    module = None
    if folder is not None:
        module = _import(folder / f"dm_{key}.py", key)
    if module is None:
        source = build()
        if folder is None or not _write(folder, f"dm_{key}.py", source):
            folder = private_dir()
            _write(folder, f"dm_{key}.py", source)
        module = _import(folder / f"dm_{key}.py", key)
        if module is None:
            raise RuntimeError(f"generated module {key} could not be imported from {folder}")
    _MEMORY[key] = module
    return module


def _import(path: Path, key: str):
    if not path.is_file():
        return None
    name = f"dualmech_generated_{key}"
    try:
        spec = importlib.util.spec_from_file_location(name, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    except Exception:  # a damaged file: generate it again
        return None
    return module if getattr(module, "KEY", None) == key else None


_PRIVATE: list = []


def private_dir() -> Path:
    """A temporary directory of this process, for when the cache is off or not writable."""
    if not _PRIVATE:
        import atexit
        import shutil
        path = Path(tempfile.mkdtemp(prefix="dualmech_"))
        atexit.register(shutil.rmtree, path, ignore_errors=True)
        _PRIVATE.append(path)
    return _PRIVATE[0]


def _write(folder: Path, name: str, text: str) -> bool:
    try:
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp_", suffix=".py")
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        os.replace(tmp, folder / name)
        return True
    except OSError:
        return False


def clear_memory() -> None:
    """Forget the modules loaded by this process (the files stay); for tests."""
    _MEMORY.clear()
    for name in [m for m in sys.modules if m.startswith("dualmech_generated_")]:
        del sys.modules[name]
