"""LALR parsers whose tables are built once per user and kept in the cache directory.

Building the answer grammar's LALR tables takes lark some 30-40 ms, more than the rest of
the parse of a typical answer by a factor of a hundred; loading saved tables takes 2-3 ms.
:func:`lalr_parser` keeps them in the user's cache directory (:func:`dualmech.caches.cache_dir`)
under a name that is a digest of the grammar, the options, the lark version and the Python
version, and in memory, so one process builds or loads them at most once whatever number of
transformers it attaches.

The file is written through a temporary name and a rename (a concurrent process sees the whole
file or none), begins with a digest of its contents, and is read only when it and its directory
belong to the user and nobody else may write to them (:func:`dualmech.caches.read_private`).
Its tables are unpickled with every global refused, so even a forged file could not run code.
A missing, foreign, damaged or unreadable file, an unwritable directory, or a lark that loads
tables differently: the tables are built, as without a cache.

Example
-------
>>> from lark import Transformer
>>> class Sum(Transformer):
...     def add(self, c): return int(c[0]) + int(c[1])
>>> p = lalr_parser('start: add\\nadd: NUMBER "+" NUMBER\\n%import common.NUMBER', Sum())
>>> p.parse("2+3").children
[5]
"""
from __future__ import annotations

import hashlib
import io
import pickle
import sys

import lark
from lark import Lark

from dualmech.caches import cache_dir, read_private, write_atomic

__all__ = ["lalr_parser"]

_MAGIC = b"dualmech-lalr 1\n"
_TABLES: dict = {}   # key -> the pickled tables (bytes), built or read once per process
_UNLOADABLE: set = set()   # keys whose tables this lark cannot load


class _NoGlobals(pickle.Unpickler):
    """Unpickles plain data only (lark's tables are dicts, lists, strings and numbers)."""

    def find_class(self, module, name):
        raise pickle.UnpicklingError(f"the parser tables name {module}.{name}; refused")


def _key(grammar: str, options: dict) -> str:
    text = "\0".join([grammar, repr(sorted(options.items())), lark.__version__,
                      sys.version, sys.implementation.cache_tag or ""])
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:24]


def _build(grammar: str, options: dict) -> bytes:
    buffer = io.BytesIO()
    Lark(grammar, parser="lalr", **options).save(buffer)
    return buffer.getvalue()


def _unpack(blob: bytes | None):
    """The tables of a cache file, or ``None`` when it is not a whole one."""
    if not blob or not blob.startswith(_MAGIC):
        return None
    head, _, payload = blob[len(_MAGIC):].partition(b"\n")
    if head != hashlib.sha256(payload).hexdigest().encode("ascii"):
        return None
    return payload


def _tables(key: str, grammar: str, options: dict, fresh: bool = False) -> bytes:
    payload = None if fresh else _TABLES.get(key)
    if payload is not None:
        return payload
    folder = cache_dir()
    name = f"lalr-{key}.pickle"
    if folder is not None and not fresh:
        payload = _unpack(read_private(folder / name))
    if payload is None:
        payload = _build(grammar, options)
        if folder is not None:
            digest = hashlib.sha256(payload).hexdigest().encode("ascii")
            write_atomic(folder, name, _MAGIC + digest + b"\n" + payload)
    _TABLES[key] = payload
    return payload


def _load(payload: bytes, transformer) -> Lark:
    data = _NoGlobals(io.BytesIO(payload)).load()
    return Lark.__new__(Lark)._load(data, transformer=transformer)


def lalr_parser(grammar: str, transformer=None, **options) -> Lark:
    """A lark LALR parser of ``grammar`` calling ``transformer`` at each reduction, its tables
    from memory, from the cache directory, or built (and then saved there).

    ``options`` are further ``lark.Lark`` options that shape the tables (``lexer``,
    ``maybe_placeholders``, ...); they are part of the cache key.
    """
    key = _key(grammar, options)
    if key not in _UNLOADABLE:
        try:
            return _load(_tables(key, grammar, options), transformer)
        except Exception:   # tables that do not load: build them afresh, replace the file
            pass
        try:
            return _load(_tables(key, grammar, options, fresh=True), transformer)
        except Exception:   # a lark that no longer loads saved tables: build each parser
            _UNLOADABLE.add(key)
            _TABLES.pop(key, None)
    return Lark(grammar, parser="lalr", transformer=transformer, **options)
