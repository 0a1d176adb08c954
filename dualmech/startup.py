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
walking, and so copying, its parent's memory.

All of this acts only in the program (:func:`dualmech.cli.command` calls
:func:`as_program`).  A process that calls dualmech's functions and lives on -- tests, a
notebook, the web server -- keeps the default collector: :func:`load` is a plain import
there, :func:`freeze` and :func:`leave` nothing.

Example
-------
>>> load("dualmech.grade.parser")   # not the program: a plain import
>>> import gc; gc.isenabled()
True
"""
from __future__ import annotations

import gc
import importlib

__all__ = ["as_program", "load", "freeze", "leave"]

_PROGRAM = False


def as_program() -> None:
    """Mark this process as the ``dualmech`` program, which exits when the command is done."""
    global _PROGRAM
    _PROGRAM = True


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
