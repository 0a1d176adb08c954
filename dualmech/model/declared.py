"""Which builder derived a model: the free-body diagrams and energies behind an equation set.

A problem's model methods return only an :class:`~dualmech.model.equations.EquationSet`; the
builder that produced it (a :class:`~dualmech.model.direct.NewtonEuler` with its bodies, loads
and reactions, a :class:`~dualmech.model.lagrange.Lagrangian` with its named ``T``, ``V``,
``R`` and ``Q`` terms) is what a second look needs: the Kane referee derives a third model from
a direct model's declarations, and the diagnosis compares each declared body's energy with
the hand Lagrangian's terms.  Every builder notes the set it derives (:func:`note`);
:func:`builder_of` finds the builder again for as long as the set lives.

Example
-------
>>> import sympy as sp
>>> from dualmech import Lagrangian, coordinate, rate
>>> x = coordinate("x"); m = sp.Symbol("m", positive=True)
>>> lg = Lagrangian(coordinates=[x]); lg.kinetic("T", m * rate(x)**2 / 2)
>>> eqs = lg.equations()
>>> builder_of(eqs) is lg, builder_of(eqs.simplified())
(True, None)
"""
from __future__ import annotations

import weakref

__all__ = ["note", "builder_of"]

#: EquationSet -> the builder that derived it (kept while the set lives)
_BUILDERS: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def note(builder, model) -> None:
    """Called by a builder with the model it derived."""
    _BUILDERS[model] = builder


def builder_of(model):
    """The builder that derived ``model`` (``None`` for a set made any other way, e.g. by
    hand or transformed after it was derived)."""
    try:
        return _BUILDERS.get(model)
    except TypeError:   # not weakly referenceable: not a builder's set
        return None
