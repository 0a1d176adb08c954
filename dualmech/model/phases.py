"""Contact phases chained: what a problem becomes when a one-sided reaction lets go.

A one-sided reaction (:attr:`Problem.unilateral <dualmech.model.problem.Problem>`) that would
change sign ends the problem's model: the contact opens and the body moves under another one,
often with other coordinates (a ladder leaving the wall slides on the floor alone, with its
centre's horizontal position free).  A problem declares that next model on
``Problem.phases``::

    phases = {"N_w": Phase(FreeLadder, {x: L / 2 * sp.sin(theta), theta: theta},
                           "the ladder leaves the wall and slides on the floor alone")}

-- the next problem (a class, or a function of no arguments returning one), each of its
reference coordinates as an expression of this problem's coordinates and parameters (the
rates follow by the chain rule: the state is continuous at the switch, no impact), and why.
Parameters pass across by name.  :func:`dualmech.numeric.phases.simulate_phases` integrates
phase after phase; :func:`phase_errors` checks the declaration for :meth:`Problem.validate
<dualmech.model.problem.Problem.validate>`.

Example
-------
>>> import sympy as sp
>>> from dualmech import Problem, coordinate
>>> q = coordinate("q")
>>> Phase(Problem, {q: q}, "the contact opens").why
'the contact opens'
"""
from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Callable

__all__ = ["Phase", "phase_errors", "next_problem"]


@dataclass(frozen=True)
class Phase:
    """The model that follows when a one-sided reaction lets go (see the module docstring).

    Parameters
    ----------
    problem : callable
        The next problem's class, or a function of no arguments returning the problem.
    coordinates : mapping
        ``{next coordinate: expression}``: every reference coordinate of the next problem
        as an expression of this problem's coordinates and parameters.
    why : str
        What happens, in words (charts and reports say it at the switch).

    Example
    -------
    >>> from dualmech import Problem
    >>> Phase(Problem, {}, "free flight").coordinates
    {}
    """

    problem: Callable
    coordinates: Mapping
    why: str = ""

    def __post_init__(self):
        if not callable(self.problem):
            raise TypeError(f"`Phase.problem` must be a problem class or a function returning "
                            f"a problem, got {self.problem!r:.60}.")
        if not isinstance(self.coordinates, Mapping):
            raise TypeError(f"`Phase.coordinates` must be a mapping {{next coordinate: "
                            f"expression}}, got {self.coordinates!r:.60}.")
        object.__setattr__(self, "coordinates", dict(self.coordinates))
        if not isinstance(self.why, str):
            raise TypeError(f"`Phase.why` must be text, got {self.why!r:.60}.")


def next_problem(phase: Phase):
    """The next phase's problem instance (the class called, or the function's result)."""
    from dualmech.model.problem import Problem
    made = phase.problem()
    if not isinstance(made, Problem):
        raise TypeError(f"`Phase.problem` gave {made!r:.60}, not a Problem.")
    return made


def phase_errors(problem) -> list[str]:
    """Every mistake in ``problem.phases`` (empty when none): a key that is not a one-sided
    reaction, a value that is not a :class:`Phase`, a next problem that cannot be built, a map
    that misses one of its coordinates or uses a symbol this problem does not have."""
    phases = getattr(problem, "phases", None) or {}
    if not isinstance(phases, Mapping):
        return [f"`phases` must be a mapping {{reaction: Phase(...)}}, got {phases!r:.60}"]
    one_sided = set(getattr(problem, "unilateral", None) or {})
    errors = []
    for name, phase in phases.items():
        where = f"`phases[{name!r}]`"
        if name not in one_sided:
            errors.append(f"{where}: {name!r} is not a one-sided reaction (declare it in "
                          "`unilateral` first)")
        if not isinstance(phase, Phase):
            errors.append(f"{where} must be a Phase(problem, coordinates, why), got "
                          f"{phase!r:.60}")
            continue
        try:
            nxt = next_problem(phase)
            coords = list(nxt.model(nxt.reference).coordinates)
        except Exception as exc:  # noqa: BLE001 - a teacher's next problem, reported as such
            errors.append(f"{where}: the next problem cannot be built ({type(exc).__name__}: "
                          f"{exc})")
            continue
        errors += _map_errors(problem, where, phase, coords)
    return errors


def _map_errors(problem, where: str, phase: Phase, coords: list) -> list[str]:
    from dualmech.model._expr import as_expr
    mine = set(problem.model(problem.reference).coordinates)
    known = set(problem.parameter_symbols)
    errors = [f"{where}: the next problem's coordinate {q} has no expression"
              for q in coords if q not in phase.coordinates]
    errors += [f"{where}: {k} is not a coordinate of the next problem ({coords})"
               for k in phase.coordinates if k not in coords]
    for k, expr in phase.coordinates.items():
        e = as_expr(expr)
        import sympy as sp
        stray = {f for f in e.atoms(sp.core.function.AppliedUndef) if f not in mine}
        stray |= {s for s in e.free_symbols if s not in known and s.name != "t"}
        if stray:
            errors.append(f"{where}: the expression of {k} uses {sorted(map(str, stray))}, "
                          "not this problem's coordinates or parameters")
    return errors
