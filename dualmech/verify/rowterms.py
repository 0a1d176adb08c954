"""A balance row that leaves out a body's inertia term or a load, found from the declarations.

Two slips of a free-body diagram leave a row of the direct form short of one inertia term
while every declaration (bodies, loads, reactions) is right: a body taken as massless in one
balance (a pulley's ``(T1 - T2) a = 0`` where ``I x''/a`` belongs) and a moment about a
moving point taken as if the point were fixed (``m r_PC x a_P`` left out).  Such a row
usually holds reactions, so it is no multiple of a row of the other model and the term edits
of :mod:`dualmech.verify.edits` cannot reach it.

The search here uses what the declarations give: every body's linear inertia ``-m a_C . d``,
every rigid body's angular inertia ``-dH_C/dt . d`` and every transport term ``-m (r_PC x
a_P) . d`` (``P`` a point where a load acts, ``d`` an axis of a frame of the model).  At a few
random states inside the declared ranges it takes the accelerations of the other model,
solves the remaining rows of the direct form for the reactions, and reads what row ``i``
misses; a candidate that is that value times a small factor (``±1``, ``±2``, ``±1/2``) at
every point is proposed.  The search is numeric (floats); the edit it proposes counts only
when the edited model then agrees with the other, decided exactly by the caller.
"""
from __future__ import annotations

import random
import time

import numpy as np
import sympy as sp

from dualmech.model.bodies import RigidBody
from dualmech.model.kinematics import t

__all__ = ["inertia_terms", "missing_inertia"]

#: seconds the candidates are evaluated for, at most (each is a few float evaluations)
SECONDS = 10.0

#: factors a hand-written row is allowed to miss a term by (the sign, a half, a double)
FACTORS = (1, -1, 2, -2, sp.Rational(1, 2), -sp.Rational(1, 2))


def _axes(ne) -> list:
    """``[(name, unit vector)]``: the axes of the ground and of every rigid body's frame, and
    the direction of every declared reaction (a balance is usually projected on those)."""
    frames: list = []
    for f in [ne.ground] + [b.frame for b in ne._bodies.values() if isinstance(b, RigidBody)]:
        if not any(f is g for g in frames):
            frames.append(f)
    out = [(f"{f.name}.{c}", getattr(f, c)) for f in frames for c in "xyz"]
    for r in getattr(ne, "_reactions", ()):
        out.append((f"the direction of {r.symbol.name}", r.direction))
    return out


def inertia_terms(ne) -> list[tuple[str, sp.Expr]]:
    """``[(what, expression)]``: the inertia terms and load components a row of direct
    builder ``ne`` could leave out (expressions in ``q(t)`` and its derivatives; zero ones and
    repeats dropped; loads through a reaction kept, the caller sets them aside).

    >>> import sympy as sp
    >>> from dualmech import Frame, NewtonEuler, Particle, Point, coordinate
    >>> x = coordinate("x"); O = Frame.ground("O"); m = sp.Symbol("m", positive=True)
    >>> ne = NewtonEuler(coordinates=[x], ground=O)
    >>> ne.linear_momentum(Particle("block", m, Point.origin(O).locate("P", x * O.x)), O.x)
    >>> inertia_terms(ne)
    [('the inertia of block along O.x (-m a_C): block taken as massless in this balance', -m*Derivative(x(t), (t, 2)))]
    """
    ground = ne.ground
    bodies = list(ne._bodies.values())
    points = []
    for b in bodies:
        for ld in ne._all_loads(b):
            if ld.point is not None and not any(ld.point is p for p in points):
                points.append(ld.point)
    out: list = []
    for b in bodies:
        C = b.masscenter
        a_C = C.acc(ground)
        Hdot = None
        if isinstance(b, RigidBody):
            Hdot = b.angular_momentum(C, ground).dt(ground)
        for axis_name, d in _axes(ne):
            out.append((f"the inertia of {b.name} along {axis_name} (-m a_C): {b.name} "
                        "taken as massless in this balance", -b.mass * a_C.dot(d)))
            if Hdot is not None:
                out.append((f"the rate of {b.name}'s angular momentum about its centre along "
                            f"{axis_name}: {b.name} taken as massless in this balance",
                            -Hdot.dot(d)))
            for P in points:
                if P is C:
                    continue
                r = C.pos_from(P)
                out.append((f"the transport term -m r_{P.name}{C.name} x a_{P.name} of "
                            f"{b.name} along {axis_name}: a moment about the moving point "
                            f"{P.name} taken as if it were fixed",
                            -b.mass * r.cross(P.acc(ground)).dot(d)))
    for b in bodies:
        for ld in ne._all_loads(b):
            if ld.key.startswith("reaction "):
                continue
            for axis_name, d in _axes(ne):
                if ld.force is not None:
                    out.append((f"the load {ld.key} along {axis_name}: left out of this "
                                "balance", ld.force.dot(d)))
                if ld.torque is not None:
                    out.append((f"the couple {ld.key} along {axis_name}: left out of this "
                                "balance", ld.torque.dot(d)))
    kept, seen = [], set()
    for what, e in out:
        e = sp.expand(e)
        if e != 0 and e not in seen and -e not in seen:
            seen.add(e)
            kept.append((what, e))
    return kept


class _Numbers:
    """Float evaluation of plain expressions at random states in the declared ranges."""

    def __init__(self, problem, model, points: int, seed: int):
        self.states = model.states
        self.params = list(problem.parameter_symbols)
        ranges = {p.symbol: p.range for p in problem.parameters}
        coords = {q.function: q for q in problem.coordinates}
        rng = random.Random(seed)
        self.points = []
        for _ in range(points):
            pt = {s: rng.uniform(*_inside(ranges.get(s, (0.5, 2.0)))) for s in self.params}
            for s in self.states:
                c = coords.get(s.function)
                pt[s.q] = rng.uniform(*_inside(c.range if c else (-1, 1)))
                pt[s.qd] = rng.uniform(*_inside(c.rate_range if c else (-1, 1)))
            pt[t] = rng.uniform(0.1, 1.0)
            self.points.append(pt)

    def values(self, expr, accelerations: list) -> np.ndarray:
        return np.array([complex(sp.N(expr.xreplace({**pt, **acc}), 20))
                         for pt, acc in zip(self.points, accelerations)]).real


def _inside(r) -> tuple:
    lo, hi = float(r[0]), float(r[1])
    return lo + 0.1 * (hi - lo), hi - 0.1 * (hi - lo)


def _motion(other, nums: _Numbers) -> list | None:
    """The other model's accelerations at each point (``{q_ddot: value}``)."""
    acc = [s.qdd for s in other.states]
    unknowns = acc + list(other.unknowns)
    rows = [other.to_plain(e) for e in other.equations]
    A, b = sp.linear_eq_to_matrix(rows, unknowns)
    out = []
    for pt in nums.points:
        An = np.array(A.xreplace(pt).evalf(20), dtype=float)
        bn = np.array(b.xreplace(pt).evalf(20), dtype=float).ravel()
        sol, *_ = np.linalg.lstsq(An, bn, rcond=None)
        if not np.allclose(An @ sol, bn, rtol=1e-9, atol=1e-9 * (1 + abs(bn).max())):
            return None
        out.append({s: float(v) for s, v in zip(acc, sol[:len(acc)])})
    return out


def missing_inertia(problem, model, other, ne, points: int = 3, seed: int = 0) -> list:
    """``[(row index, what, term)]``: rows of ``model`` (an equation set of direct builder
    ``ne``, in the reference coordinates) that agree with the motion of ``other`` once
    ``term`` (an inertia term of :func:`inertia_terms` times a small factor) is added.
    Numeric proposals: the caller confirms each exactly."""
    nums = _Numbers(problem, model, points, seed)
    motion = _motion(other, nums)
    if motion is None:
        return []
    rows = [model.to_plain(e) for e in model.equations]
    R = list(model.unknowns)
    A, b = sp.linear_eq_to_matrix(rows, R) if R else (sp.zeros(len(rows), 0),
                                                      -sp.Matrix(rows))
    An = [np.array(A.xreplace({**pt, **acc}).evalf(20), dtype=float).reshape(len(rows), len(R))
          for pt, acc in zip(nums.points, motion)]
    bn = [np.array(b.xreplace({**pt, **acc}).evalf(20), dtype=float).ravel()
          for pt, acc in zip(nums.points, motion)]
    short = []
    for i in range(len(rows)):
        keep = [j for j in range(len(rows)) if j != i]
        miss = []
        for Ak, bk in zip(An, bn):
            sol, *_ = np.linalg.lstsq(Ak[keep], bk[keep], rcond=None) if R else (np.zeros(0),)
            scale = 1 + abs(bk).max()
            if not np.allclose(Ak[keep] @ sol, bk[keep], atol=1e-8 * scale):
                break
            miss.append(bk[i] - Ak[i] @ sol)      # row i = A R - b: it misses b_i - A_i R
        if len(miss) == len(An) and max(abs(v) for v in miss) > 1e-8 * (1 + max(map(
                lambda v: abs(v).max(), bn))):
            short.append((i, np.array(miss)))
    if not short:
        return []
    found = []
    start = time.monotonic()
    for what, term in inertia_terms(ne):
        if time.monotonic() - start > SECONDS:
            break               # a search, not a proof: bounded like the edits' MAX_TRIES
        plain = model.to_plain(term)
        if plain.free_symbols & set(R):
            continue            # a load through a reaction (mu N): no value of its own
        try:
            values = nums.values(plain, motion)
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        for i, miss in short:
            for k in FACTORS:
                if np.allclose(float(k) * values, miss, rtol=1e-7, atol=1e-9):
                    found.append((i, what, k * term))
    return found
