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

__all__ = ["Drawing", "ChartScene", "VIEWS"]

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
