"""The problem's points in the ground frame, numerically: for pictures and for honest errors.

:func:`scene` reads the problem's :class:`~dualmech.model.drawing.Drawing` (``drawing``) or,
by default, the direct form's declarations (the ground origin, each body's mass centre,
each reaction's point) and generates code for their positions and velocities in the ground
frame, as functions of the reference model's state; and, for each declared reaction force,
its direction in the ground frame and the point it acts at (the arrows of an animation).

Cartesian positions and velocities are what a coordinate singularity cannot distort: near
the pole of a pair of angles a tiny move of the body is a large change of one angle, so an
error measured on the angles there says more about the angles than about the motion.
:meth:`Scene.error` measures a run against a reference in them.

Example
-------
>>> import numpy as np
>>> from dualmech.problems import get
>>> s = scene(get("simple_pendulum"))
>>> s.names
('O', 'bob')
>>> s.positions(0.0, np.array([[0.3], [0.0]]))[1, :, 0].round(4)   # a sin 0.3, -a cos 0.3
array([ 0.2364, -0.7643,  0.    ])
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import numpy as np
import sympy as sp

from dualmech.model.direct import declarations_of
from dualmech.model.drawing import VIEWS, Drawing
from dualmech.numeric.model import StateFunction
from dualmech.numeric.simulation import problem_parameters

__all__ = ["Scene", "Arrow", "scene", "NoScene"]


class NoScene(ValueError):
    """The problem's points cannot be found: no direct form in the reference coordinates and
    no :class:`~dualmech.model.drawing.Drawing` declared."""


@dataclass(frozen=True)
class Arrow:
    """A reaction force drawn at point ``at`` (index into the scene's names) along
    ``direction`` (rows 3k..3k+2 of :attr:`Scene._directions`)."""

    reaction: str
    at: int
    row: int


class Scene:
    """Positions and velocities of named points in the ground frame (see the module doc);
    ``hidden`` are the indices of points kept only to attach a reaction arrow (a declared
    drawing that places the body its own way), not drawn and not measured."""

    def __init__(self, names, exprs, velocity_exprs, coordinates, values, lines=(),
                 view=(), arrows=(), arrow_exprs=(), hidden=()):
        self.names, self.lines = tuple(names), tuple(lines)
        self.hidden = frozenset(hidden)   # points only an arrow needs (not drawn)
        self.coordinates = tuple(coordinates)
        self.n = len(self.coordinates)
        self._pos = StateFunction(exprs, self.coordinates, values)
        self._vel = StateFunction(velocity_exprs, self.coordinates, values)
        self.arrows = tuple(arrows)
        self._dirs = StateFunction(arrow_exprs, self.coordinates, values) if arrow_exprs \
            else None
        self.view = tuple(VIEWS.index(v) for v in view)

    def _eval(self, fun, t, Y) -> np.ndarray:
        Y = np.asarray(Y, dtype=float)
        Y = Y[:, None] if Y.ndim == 1 else Y
        t = np.broadcast_to(np.asarray(t, dtype=float), (Y.shape[1],))
        out = np.empty((fun.size, Y.shape[1]))
        for k in range(Y.shape[1]):      # t enters the drawn points (a shaken pivot)
            out[:, k] = fun(float(t[k]), Y[: self.n, k], Y[self.n:, k])
        return out.reshape(-1, 3, Y.shape[1])

    def positions(self, t, Y) -> np.ndarray:
        """``(points, 3, K)`` ground-frame positions [m] at times ``t`` and states ``Y``
        (``(2n, K)``, reference coordinates)."""
        return self._eval(self._pos, t, Y)

    def velocities(self, t, Y) -> np.ndarray:
        """``(points, 3, K)`` ground-frame velocities [m/s]."""
        return self._eval(self._vel, t, Y)

    def directions(self, t, Y) -> np.ndarray:
        """``(arrows, 3, K)`` unit directions of the reaction arrows."""
        if self._dirs is None:
            return np.zeros((0, 3, np.asarray(Y).reshape(2 * self.n, -1).shape[1]))
        return self._eval(self._dirs, t, Y)

    def error(self, t, Y, truth) -> float:
        """The largest error of the points' positions and velocities along ``Y`` against
        ``truth`` (same times), each relative to the root-mean-square size of the moving
        points' positions (velocities) along the truth about their mean: a measure no
        coordinate singularity distorts."""
        k = min(Y.shape[1], truth.shape[1])
        if k == 0:
            return float("nan")
        worst = 0.0
        keep = [i for i in range(len(self.names)) if i not in self.hidden]
        for f in (self.positions, self.velocities):
            a, b = f(t[:k], Y[:, :k])[keep], f(t[:k], truth[:, :k])[keep]
            spread = (b - b.mean(axis=2, keepdims=True))**2
            moving = spread.sum(axis=(1, 2)) > 0        # a fixed point has no size
            size = float(np.sqrt(spread[moving].sum(axis=1).mean())) if moving.any() else 1.0
            worst = max(worst, float(np.linalg.norm(a - b, axis=1).max()) / size)
        return worst

    def view_axes(self, t, Y) -> tuple[int, int]:
        """The two ground axes shown: the declared view, else the two of largest motion."""
        if self.view:
            return self.view
        P = self.positions(t, Y)
        spread = np.ptp(P, axis=2).max(axis=0)
        first, second = sorted(np.argsort(-spread, kind="stable")[:2])
        return int(first), int(second)


def _ground_components(vector, ground) -> list:
    return list(vector.express(ground).components)


def _declared_model(problem):
    """The first direct model whose coordinates are the reference's, with its declarations."""
    ref = tuple(problem.model(problem.reference).coordinates)
    for name in problem.model_names:
        decl = declarations_of(problem.model(name))
        if decl is not None and tuple(decl.coordinates) == ref:
            return decl
    return None


def scene(problem, params: Mapping | None = None) -> Scene:
    """The :class:`Scene` of ``problem`` at its parameter values (overridden by
    ``params``); raises :class:`NoScene` when there is nothing to draw."""
    values = problem_parameters(problem, params)
    coords = tuple(problem.model(problem.reference).coordinates)
    decl = _declared_model(problem)
    drawing = getattr(problem, "drawing", None)
    if drawing is not None and not isinstance(drawing, Drawing):
        raise TypeError(f"`{problem.name}.drawing` must be a Drawing, got {drawing!r:.60}.")
    if drawing is None and decl is None:
        raise NoScene(f"`{problem.name}`: nothing to draw -- no direct form in the reference "
                      "coordinates; declare `drawing = Drawing({name: (x, y), ...})`.")
    ground = decl.ground if decl is not None else None
    points, where_of = {}, {}
    if drawing is not None:
        for name, where in drawing.points.items():
            points[name] = _components(where, ground, problem.name, name)
            if hasattr(where, "pos_from"):
                where_of[id(where)] = name
    else:
        points[ground.name] = [sp.Integer(0)] * 3
        for body in decl.bodies:
            points[body.name] = _ground_components(body.masscenter.pos_from(), ground)
            where_of[id(body.masscenter)] = body.name
    arrows, arrow_exprs, hidden = [], [], []
    for r in (decl.reactions if decl is not None else ()):
        if r.kind != "force":
            continue
        at = r.point if r.point is not None else r.body.masscenter
        name = where_of.get(id(at))
        if name is None:                     # (a drawing's own points: kept for the arrow)
            name = at.name if at.name not in points else f"{at.name} ({r.symbol})"
            if drawing is not None:
                hidden.append(name)
            points[name] = _ground_components(at.pos_from(), ground)
            where_of[id(at)] = name
        arrows.append(Arrow(str(r.symbol), list(points).index(name), len(arrows)))
        arrow_exprs += _ground_components(r.direction, ground)
    names = list(points)
    exprs = [sp.sympify(c) for n in names for c in points[n]]
    tt = _time(coords)
    vel = [sp.diff(e, tt) for e in exprs]
    return Scene(names, exprs, vel, coords, values,
                 lines=drawing.lines if drawing is not None else (),
                 view=drawing.view if drawing is not None else (),
                 arrows=arrows, arrow_exprs=arrow_exprs,
                 hidden=[names.index(h) for h in hidden])


def _time(coords):
    return coords[0].args[0] if coords else sp.Symbol("t")


def _components(where, ground, problem: str, name: str) -> list:
    if hasattr(where, "pos_from"):
        if ground is None:
            raise NoScene(f"`{problem}.drawing`: point `{name}` is a Point, but the problem "
                          "has no direct form in the reference coordinates to place it in.")
        try:
            return _ground_components(where.pos_from(), ground)
        except ValueError as exc:
            raise NoScene(f"`{problem}.drawing`: point `{name}` is not in the direct form's "
                          f"frames ({exc}); give its ground components instead.") from None
    comps = [sp.sympify(c) for c in where]
    return comps + [sp.Integer(0)] * (3 - len(comps))
