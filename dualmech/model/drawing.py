"""How to draw a problem's bodies: the points to show and the lines joining them.

A picture of the motion (an animation, a snapshot) and a measure of error that no coordinate
singularity can distort (positions and velocities in the ground frame) both need the
problem's points in Cartesian components.  By default they come from the direct form's own
declarations -- the ground origin, each body's mass centre and each reaction's point, no
lines -- so a problem declares nothing to be drawn.  A problem that wants more (a rod drawn
from its pivot to its bob, a fixed point that carries no load) declares a :class:`Drawing`:

    drawing = Drawing({"pivot": (0, a * sp.cos(Omega * t)), "bob": bob_point},
                      lines=(("pivot", "bob"),))

Each point is a :class:`~dualmech.model.kinematics.Point` of the direct form, or a sequence of
2 or 3 expressions (the ground frame's x, y[, z] components) in ``t``, the coordinates and
the parameters.  ``lines`` are chains of point names joined by straight segments; ``view``
the two ground axes the picture shows (default: the two along which the points move most).

A problem may also declare further :class:`ChartScene` s -- other parameter values or another
start -- for the report's chart to draw beside its default scene, where the contrast is the
lesson (a shaken pendulum held up, and the same pendulum falling when shaken too slowly).

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate
>>> th, l = coordinate("theta"), sp.Symbol("l", positive=True)
>>> d = Drawing({"pivot": (0, 0), "bob": (l * sp.sin(th), -l * sp.cos(th))}, (("pivot", "bob"),))
>>> d.names, d.lines
(('pivot', 'bob'), (('pivot', 'bob'),))
"""
from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["Drawing", "ChartScene", "VIEWS", "drawing_errors"]

#: The names of the ground axes a view may pick.
VIEWS = ("x", "y", "z")


@dataclass(frozen=True)
class Drawing:
    """Points (name -> Point or 2-3 ground components) and the chains of names joined by
    lines; ``view``: two of ``"x", "y", "z"`` (empty: the two of largest motion)."""

    points: dict
    lines: tuple = ()
    view: tuple = ()
    why: str = field(default="", compare=False)

    def __post_init__(self):
        if not isinstance(self.points, dict) or not self.points:
            raise TypeError("`Drawing.points` must be a non-empty dict {name: Point or "
                            f"(x, y[, z])}}, got {self.points!r:.60}.")
        for name, where in self.points.items():
            if not isinstance(name, str) or not name:
                raise TypeError(f"`Drawing.points`: a name must be a non-empty string, got "
                                f"{name!r}.")
            if not hasattr(where, "pos_from") and not (isinstance(where, (tuple, list))
                                                       and len(where) in (2, 3)):
                raise TypeError(f"`Drawing.points[{name!r}]` must be a Point or 2-3 ground "
                                f"components, got {where!r:.60}.")
        lines = tuple(tuple(chain) for chain in self.lines)
        for chain in lines:
            unknown = [n for n in chain if n not in self.points]
            if len(chain) < 2 or unknown:
                raise ValueError(f"`Drawing.lines`: each chain joins at least two declared "
                                 f"points; {chain} names {unknown or 'fewer than two'}.")
        object.__setattr__(self, "lines", lines)
        view = tuple(self.view)
        if view and (len(view) != 2 or any(v not in VIEWS for v in view)):
            raise ValueError(f"`Drawing.view` must be two of {VIEWS}, got {view}.")
        object.__setattr__(self, "view", view)

    @property
    def names(self) -> tuple:
        """The point names, in declared order."""
        return tuple(self.points)


@dataclass(frozen=True)
class ChartScene:
    """A further scene for the report's chart: parameter values (``{name: value}``) that
    differ from the defaults, the state to start from (a state as ``initial_state`` takes
    it; empty: the problem's initial state) and what it shows, in words.

    Example
    -------
    >>> ChartScene({"Omega": 40.0}, (3.0, 0.0), "too slow: the pendulum falls").params
    {'Omega': 40.0}
    """

    params: dict
    state: tuple | dict = ()
    why: str = ""

    def __post_init__(self):
        if not isinstance(self.params, dict) or not all(isinstance(k, str)
                                                        for k in self.params):
            raise TypeError("`ChartScene.params` must be a dict {parameter name: value}, got "
                            f"{self.params!r:.60}.")
        for k, v in self.params.items():
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise TypeError(f"`ChartScene.params[{k!r}]` must be a number, got {v!r:.40}.")
        if not isinstance(self.why, str):
            raise TypeError(f"`ChartScene.why` must be text, got {self.why!r:.40}.")


def drawing_errors(problem) -> list[str]:
    """Every mistake in ``problem``'s ``drawing`` and ``chart_scenes``, one sentence each:
    components naming symbols that are not the time, a coordinate or a parameter; a scene's
    parameter that is not declared or lies outside its range; a scene's state that does not
    fit the reference coordinates.

    >>> import sympy as sp
    >>> from dualmech import get
    >>> class Typo(type(get("simple_pendulum"))):
    ...     chart_scenes = (ChartScene({"G": 3.0}, (), "weaker gravity"),)
    >>> drawing_errors(Typo())
    ['`chart_scenes[0]`: `G` is not a declared parameter (declared: M, a, g)']
    """
    from dualmech.model.facts import _state_errors, _tuple_of, is_declared
    from dualmech.model.kinematics import t
    errors: list[str] = []
    drawing = getattr(problem, "drawing", None)
    names = {str(p.symbol): p for p in problem.parameters}
    if drawing is not None and not isinstance(drawing, Drawing):
        errors.append(f"`drawing` must be a Drawing(...) or None, got {drawing!r:.60}")
    elif drawing is not None:
        allowed = {t, *(p.symbol for p in problem.parameters)}
        coords = {c.function for c in problem.all_coordinates()}
        for name, where in drawing.points.items():
            if hasattr(where, "pos_from"):
                continue
            for x in where:
                expr = x if hasattr(x, "free_symbols") else None
                if expr is None:
                    continue
                stray = expr.free_symbols - allowed
                odd = {f for f in expr.atoms(_applied()) if f not in coords}
                if stray or odd:
                    what = ", ".join(sorted(map(str, stray | odd)))
                    errors.append(f"`drawing.points[{name!r}]` uses {what}: not the time, a "
                                  "coordinate or a parameter")
                    break
    for i, scene in enumerate(_tuple_of(problem, "chart_scenes", ChartScene, errors)):
        for k, v in scene.params.items():
            if k not in names:
                errors.append(f"`chart_scenes[{i}]`: `{k}` is not a declared parameter "
                              f"(declared: {', '.join(sorted(names))})")
            elif not names[k].range[0] <= v <= names[k].range[1]:
                errors.append(f"`chart_scenes[{i}]`: `{k}` = {v} is outside its declared "
                              f"range {names[k].range}")
        if is_declared(scene.state) and problem.reference in problem.models():
            errors += _state_errors(problem, scene.state, f"`chart_scenes[{i}].state`")
    return errors


def _applied():
    from sympy.core.function import AppliedUndef
    return AppliedUndef
