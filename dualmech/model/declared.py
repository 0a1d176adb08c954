"""Which builder declared a derived model: the free-body diagrams and energies behind it.

A problem's model methods return only an :class:`~dualmech.model.equations.EquationSet`; the
builder that produced it (a :class:`~dualmech.model.direct.NewtonEuler` with its bodies and
loads, a :class:`~dualmech.model.lagrange.Lagrangian` with its named ``T``, ``V``, ``R`` and
``Q`` terms) is gone.  An explanation that compares the two models at the level a teacher
acts on needs those declarations again: inside :func:`recording`, every builder notes the
model it derives, and the block gets ``[(builder, model)]``.  Outside, nothing is kept.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t, Lagrangian
>>> x = coordinate("x"); m = sp.Symbol("m", positive=True)
>>> with recording() as seen:
...     lg = Lagrangian(coordinates=[x]); lg.kinetic("T", m*x.diff(t)**2/2)
...     eqs = lg.equations()
>>> seen[0][0] is lg, seen[0][1] is eqs
(True, True)
"""
from __future__ import annotations

import contextlib
import contextvars

__all__ = ["recording", "note"]

_SEEN: contextvars.ContextVar = contextvars.ContextVar("dualmech_declared", default=None)


@contextlib.contextmanager
def recording():
    """Collect ``(builder, model)`` of every model derived inside the block."""
    seen: list = []
    token = _SEEN.set(seen)
    try:
        yield seen
    finally:
        _SEEN.reset(token)


def note(builder, model) -> None:
    """Called by a builder with the model it derived (kept only inside :func:`recording`)."""
    seen = _SEEN.get()
    if seen is not None:
        seen.append((builder, model))
