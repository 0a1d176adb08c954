"""Starting and leaving the ``dualmech`` program quickly.

Two things the interpreter does by default cost a one-answer ``dualmech grade`` a third of
its time, for nothing:

* while sympy, symengine and the grader load, the cyclic garbage collector walks the 10^5
  objects they allocate some two hundred times (40-50 ms), though these live as long as the
  process and leave next to no garbage.  :func:`load` imports with the collector paused,
  then moves everything alive out of its reach (``gc.freeze``): later collections walk only
  what the command itself builds;
* at exit, the interpreter frees every object one by one (0.15-0.2 s).  :func:`leave` puts
  what is alive out of the collector's reach, so that shutdown leaves it to the operating
  system; ``atexit`` handlers, thread joins and the flushing of open files happen as before.

The same freezing before a fork (:func:`freeze`) spares a forked grading worker from
walking, and so copying, its parent's memory; and a module a command may not need at all
can be loaded on first use (:func:`defer`).

All of this acts only in the program (:func:`dualmech.cli.main.command` calls
:func:`as_program`).  A process that calls dualmech's functions and lives on -- tests, a
notebook, the web server -- keeps the default collector: :func:`load` is a plain import
there, :func:`defer`, :func:`freeze` and :func:`leave` nothing.

Example
-------
>>> load("dualmech.grade.parser")   # not the program: a plain import
>>> import gc; gc.isenabled()
True
"""
from __future__ import annotations

import gc
import importlib
import types

__all__ = ["as_program", "defer", "load", "freeze", "leave"]

_PROGRAM = False


def as_program() -> None:
    """Mark this process as the ``dualmech`` program, which exits when the command is done."""
    global _PROGRAM
    _PROGRAM = True


def defer(*modules: str) -> None:
    """In the program, let ``modules`` load when first used instead of when imported: a
    one-answer ``dualmech grade`` whose problem's grading context is stored
    (:mod:`dualmech.grade.stored_contexts`) never uses symengine, and so never pays for it and for the
    numpy it imports (some 50 ms).  Modules already imported, or not installed, are left as
    they are.

    Each stands in ``sys.modules`` as a :class:`_Deferred` module until an attribute it lacks
    is read.  (``importlib.util.LazyLoader`` would not do: every later ``import`` statement
    of the module reads its ``__spec__``, which makes LazyLoader load it there and then.)
    """
    if not _PROGRAM:
        return
    import importlib.util
    import sys
    for name in modules:
        if name in sys.modules or "." in name:
            continue
        spec = importlib.util.find_spec(name)
        if spec is not None:
            sys.modules[name] = _Deferred(name, spec)


class _Deferred(types.ModuleType):
    """A module imported on first use of an attribute it does not have (see :func:`defer`);
    from then on it holds every attribute of the real module."""

    def __init__(self, name: str, spec):
        super().__init__(name)
        self.__spec__ = spec

    def __getattr__(self, attr: str):
        import sys
        if sys.modules.get(self.__name__) is self:
            del sys.modules[self.__name__]
        try:
            real = importlib.import_module(self.__name__)
        except BaseException:
            sys.modules.setdefault(self.__name__, self)
            raise
        self.__dict__.update(real.__dict__)
        return getattr(real, attr)


def load(*modules: str) -> None:
    """Import ``modules``; in the program, with the collector paused, and what exists then
    frozen (see the module docstring)."""
    if not _PROGRAM:
        for name in modules:
            importlib.import_module(name)
        return
    was = gc.isenabled()
    gc.disable()
    try:
        for name in modules:
            importlib.import_module(name)
    finally:
        gc.freeze()
        if was:
            gc.enable()


def freeze() -> None:
    """In the program, put what is alive now out of the collector's reach: before forking a
    worker, so that the child's collections walk -- and copy from its parent -- only what
    the child itself builds."""
    if _PROGRAM:
        gc.freeze()


def leave() -> None:
    """In the program, once the command is done: let shutdown skip freeing every object."""
    freeze()
