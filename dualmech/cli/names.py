"""The problems a command's NAMEs (or ``--all``) name, for every command alike.

A NAME is anything :func:`dualmech.problems.get` resolves -- a catalogue name, a file
``path.py[:Class]``, ``module:Class``, a registered catalogue's problem (``mech101:pendulum``
or ``pendulum``) -- or, for the commands that take several problems, the name of a
catalogue that an installed course package registers (``mech101``: all its problems).
``--all`` is every problem ``dualmech list`` lists: dualmech's catalogue, then every
registered catalogue's.

Example
-------
>>> [p.name for p in selected(["simple_pendulum"], False)]
['simple_pendulum']
>>> expand(["toy_car"])
['toy_car']
"""
from __future__ import annotations

from dualmech.cli.errors import UsageError

__all__ = ["catalogue", "get", "expand", "everything", "selected"]


def catalogue():
    """The :mod:`dualmech.problems` module (looked up at each call: tests replace parts)."""
    from dualmech import problems
    return problems


def get(spec: str, n: int | None = None):
    """The problem ``spec`` names; ``n`` sizes a parametric problem.  A name that names
    nothing is a :class:`UsageError` saying what to fix; an error raised by the user's own
    code (importing the file, the problem's ``__init__``) is raised as it is, for the error
    handler to show at its line."""
    cat = catalogue()
    try:
        return cat.get(spec, **({"n": n} if n is not None else {}))
    except KeyError as exc:   # SpecError: what to fix, with close matches
        raise UsageError(exc.args[0] if exc.args else str(exc)) from None
    except ValueError as exc:
        if n is not None and "fixed size" in str(exc):
            raise UsageError(f"`--n` sizes a parametric problem; `{spec}` has a fixed size.") \
                from None
        if cat.user_error(exc) is not None:   # raised in the user's own __init__: at its line
            raise
        raise UsageError(str(exc)) from None


def expand(names) -> list:
    """``names`` with each registered catalogue's name (``mech101``) replaced by a spec for
    each of its problems (``mech101:pendulum``, ...) -- unless dualmech's catalogue has a
    problem of that name."""
    cat = catalogue()
    out = []
    for name in names:
        if cat.is_name(name) and name in cat.registered() and not _in_catalogue(name):
            try:
                out += cat.catalogue_specs(name)
            except KeyError as exc:   # SpecError: a course package that does not load
                raise UsageError(exc.args[0] if exc.args else str(exc)) from None
        else:
            out.append(name)
    return out


def _in_catalogue(name: str) -> bool:
    try:
        catalogue().module_of(name)
    except KeyError:
        return False
    return True


def everything() -> list:
    """Every problem ``dualmech list`` lists: the catalogue's, then every registered
    catalogue's (one that does not load is a usage error naming it)."""
    cat = catalogue()
    try:
        specs = cat.registered_specs()
    except KeyError as exc:   # SpecError
        raise UsageError(exc.args[0] if exc.args else str(exc)) from None
    return list(cat.all_problems()) + [get(spec) for spec in specs]


def selected(names, every: bool, n: int | None = None, default_all: bool = False) -> list:
    """The problems of a command's ``names`` or ``--all`` (``every``); with neither, every
    problem when ``default_all``, else a usage error listing the known names."""
    names = list(names or ())
    if every and names:
        raise UsageError("give problem names or --all, not both.")
    if every or (default_all and not names):
        return everything()
    if not names:
        known = ", ".join(d.name for d in catalogue().declarations())
        raise UsageError(f"name at least one problem, or use --all; known problems: {known}.")
    return [get(name, n) for name in expand(names)]
