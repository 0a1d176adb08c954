"""The referee: a third derivation dualmech makes itself, from a direct model's declarations.

For every direct model of a problem (an :class:`EquationSet` made by
:class:`~dualmech.model.direct.NewtonEuler`), Kane's method with auxiliary speeds
(:func:`~dualmech.model.kane.kane_equations`) derives the motion and every reaction again from
the model's frames, bodies, loads and reactions -- not from its balances or projections.  The
comparator counts it as one more derivation: with a two-model problem, one wrong model is
outvoted.  Its honest limit, said in every report: it is independent of the direct form's
balances and projections, *not* of its declarations (:data:`INDEPENDENCE`).

Example
-------
>>> from dualmech.problems import get
>>> refs = referees(get("simple_pendulum"))
>>> sorted(refs.models), refs.of["referee"]
(['referee', 'referee (angular_momentum)'], 'newton_euler')
"""
from __future__ import annotations

from dataclasses import dataclass, field

from dualmech.model.direct import declarations_of
from dualmech.model.equations import EquationSet, ModelError
from dualmech.model.kane import kane_equations

__all__ = ["Referees", "referees", "INDEPENDENCE", "referee_name"]

#: what the referee shares with the direct model, said wherever it votes
INDEPENDENCE = ("derived by dualmech from the declarations of the direct model (frames, "
                "bodies, loads, reactions): independent of its balances and projections, not "
                "of its declarations")


def referee_name(direct: str, first: bool) -> str:
    """``"referee"`` for the first direct model, ``"referee (name)"`` for the others."""
    return "referee" if first else f"referee ({direct})"


@dataclass
class Referees:
    """The referees of one problem: ``models`` (name -> EquationSet in the reference
    coordinates), ``of`` (referee name -> its direct model) and ``notes`` (why a direct
    model got no referee)."""

    models: dict = field(default_factory=dict)
    of: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)


def referees(problem) -> Referees:
    """Derive a referee for each direct model of ``problem`` (none when the problem declares
    ``referee = False``, see :class:`~dualmech.model.problem.Problem`)."""
    out = Referees()
    if not getattr(problem, "referee", True):
        why = getattr(problem, "referee_note", "") or "the problem declares referee = False"
        out.notes.append(f"no referee: {why}")
        return out
    models = problem.models()
    for mname, m in models.items():
        decl = declarations_of(m)
        if decl is None:
            continue
        name = referee_name(mname, not out.of)
        try:
            kane = kane_equations(decl, name)
            kane = _in_reference(problem, mname, kane)
        except (ModelError, ValueError, KeyError) as exc:
            out.notes.append(f"no referee for `{mname}`: {exc}")
            continue
        out.models[name] = kane
        out.of[name] = mname
    return out


def _in_reference(problem, direct: str, kane: EquationSet) -> EquationSet:
    ref = problem.model(problem.reference)
    if set(kane.coordinates) == set(ref.coordinates):
        return kane
    maps = problem.coordinate_maps()
    if direct not in maps:
        raise ModelError(f"`{direct}` uses coordinates {list(kane.coordinates)}; give its map "
                         "in coordinate_maps()")
    return kane.change_coordinates(ref.coordinates, maps[direct], name=kane.name)
