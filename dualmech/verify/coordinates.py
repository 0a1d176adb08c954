"""A derivation in its own generalised coordinates, beside the reference's (display only).

A problem declares, per model written in other coordinates, the map ``y = phi(x, t)`` from the
reference coordinates ``x`` to the model's own ``y`` (``Problem.coordinate_maps``).  Verdicts
are reached in the reference coordinates; to explain a wrong equation in the coordinates its
author wrote, :class:`OwnCoordinates` carries a reference state over by the map (``y``, and
``y'``, ``y''`` by the chain rule) and, for the symbolic residual, inverts the map within the
display budget, taking the branch through the state shown.

Example
-------
>>> import sympy as sp
>>> from dualmech import coordinate, t, EquationSet
>>> x, y = coordinate("x"), coordinate("y"); m, l0 = sp.symbols("m l0", positive=True)
>>> own = EquationSet("own", (y,), (m * y.diff(t, 2),))
>>> oc = OwnCoordinates(own, {y: x - l0}, (x,))
>>> X, Y = oc.ref_states[0], oc.own_states[0]
>>> at = {m: 1.0, l0: 0.5, t: 0.0, X.q: 2.0, X.qd: 3.0, X.qdd: 4.0}
>>> v = oc.state(at)
>>> float(v[Y.q]), float(v[Y.qd]), float(v[Y.qdd])
(1.5, 3.0, 4.0)
>>> oc.inverse(at)
{x(t): l0 + y(t)}
"""
from __future__ import annotations

import itertools

import sympy as sp

from dualmech.model._expr import as_expr
from dualmech.model.equations import EquationSet, state_symbols, to_plain
from dualmech.model.kinematics import t
from dualmech.verify.display import Budget, OverBudget, budget

__all__ = ["OwnCoordinates"]

#: at most this many choices of map equations are tried when the map has more equations
#: (own coordinates) than the reference coordinates it uses
_MAX_SUBSETS = 12
#: a branch of the inverse goes through the state when it returns the reference coordinates
#: there to this relative accuracy (the states carry 30 digits)
_BRANCH_TOL = sp.Float("1e-20", 30)

_UNDEF = sp.core.function.AppliedUndef


class OwnCoordinates:
    """Model ``model`` (in its own coordinates) and its map from the reference coordinates.

    Parameters
    ----------
    model : EquationSet
        The derivation as written, in its own coordinates ``y``.
    mapping : dict
        ``{y(t): expression in the reference coordinates x(t), t and parameters}``, one entry
        per own coordinate (as ``Problem.coordinate_maps`` declares it).
    reference : tuple
        The reference coordinates ``x(t)``.
    """

    def __init__(self, model: EquationSet, mapping: dict, reference):
        self.model = model
        self.reference = tuple(reference)
        self.mapping = {q: as_expr(mapping[q]) for q in model.coordinates}
        self.ref_states = [state_symbols(x) for x in self.reference]
        self.own_states = [state_symbols(q) for q in model.coordinates]
        used = set()
        for e in self.mapping.values():
            used |= e.atoms(_UNDEF)
        self.used = [x for x in self.reference if x in used]
        #: reference coordinates the map does not use (a model that speaks for fewer)
        self.uncovered = [s for x, s in zip(self.reference, self.ref_states) if x not in used]
        #: own coordinates the map fixes (a constant or a function of t only)
        self.fixed = [q for q in model.coordinates
                      if not self.mapping[q].atoms(_UNDEF) & set(self.used)]
        self._plain = {q: [to_plain(e.diff(t, k), self.reference) for k in range(3)]
                       for q, e in self.mapping.items()}
        # own coordinates in the inverse (an own and a reference coordinate may share a name)
        self._dummies = [sp.Dummy(s.name) for s in self.own_states]
        self._solutions: list | None = None

    @classmethod
    def of(cls, problem, name: str, mapped: EquationSet) -> "OwnCoordinates | None":
        """The own coordinates of model ``name`` of ``problem`` when they differ from those of
        ``mapped`` (its form in the reference coordinates); ``None`` otherwise."""
        if problem is None:
            return None
        try:
            own = problem.models().get(name)
            mapping = problem.coordinate_maps().get(name)
        except Exception:  # noqa: BLE001 - display must never break a verdict
            return None
        if own is None or not mapping or set(own.coordinates) == set(mapped.coordinates) \
                or any(q not in mapping for q in own.coordinates):
            return None
        return cls(own, mapping, mapped.coordinates)

    @property
    def names(self) -> str:
        return ", ".join(s.name for s in self.own_states)

    def row(self, mapped: EquationSet, i: int) -> int | None:
        """The own model's row that is row ``i`` of ``mapped`` (mapping drops the rows that
        vanish in the new coordinates, so the indices can differ); ``None`` if unclear."""
        own = self.model
        if len(own.equations) == len(mapped.equations) and own.labels == mapped.labels:
            return i
        same = [j for j, label in enumerate(own.labels) if label == mapped.labels[i]]
        return same[0] if len(same) == 1 else None

    def state(self, values: dict) -> dict:
        """``values`` (parameters, ``t``, reference ``x, x', x''``, reactions) carried over to
        the own coordinates: ``y = phi``, ``y' = dphi/dt``, ``y'' = d^2 phi/dt^2``."""
        ref = {sym for s in self.ref_states for sym in (s.q, s.qd, s.qdd)}
        subs = {k: sp.Float(str(v), 30) for k, v in values.items()}
        out = {k: v for k, v in values.items() if k not in ref}
        for s in self.uncovered:
            out.update({sym: values[sym] for sym in (s.q, s.qd) if sym in values})
        for q, s in zip(self.model.coordinates, self.own_states):
            for sym, e in zip((s.q, s.qd, s.qdd), self._plain[q]):
                out[sym] = _real(e.xreplace(subs))
        return out

    def inverse(self, values: dict, limits: Budget | None = None) -> dict | None:
        """``{x(t): expression in the own coordinates}`` for the reference coordinates the map
        uses, on the branch through the reference state ``values`` (the one :meth:`state`
        carries over); ``None`` when no inverse is found within the display budget."""
        limits = limits or Budget()
        if self._solutions is None:
            self._solutions = self._solve(limits)
        own = self.state(values)
        subs = {k: sp.Float(str(v), 30) for k, v in values.items()}
        subs.update({d: sp.Float(str(own[s.q]), 30)
                     for d, s in zip(self._dummies, self.own_states)})
        for psi in self._solutions:
            if all(_returns(psi[x], values[state_symbols(x).q], subs) for x in self.used):
                back = dict(zip(self._dummies, self.model.coordinates))
                return {x: psi[x].xreplace(back) for x in self.used}
        return None

    def _solve(self, limits: Budget) -> list:
        """Solutions ``{x: psi(Y)}`` of ``Y = phi(x)`` for the reference coordinates used."""
        xs = [state_symbols(x).q for x in self.used]
        eqs = [d - self._plain[q][0]
               for q, d in zip(self.model.coordinates, self._dummies) if q not in self.fixed]
        if not xs or len(eqs) < len(xs) or \
                sum(sp.count_ops(e) for e in eqs) > 4 * limits.max_ops:
            return []
        out = []
        try:
            with budget(limits.remaining()):
                for subset in itertools.islice(itertools.combinations(eqs, len(xs)),
                                               _MAX_SUBSETS):
                    for sol in sp.solve(list(subset), xs, dict=True):
                        if set(sol) == set(xs) and not any(sol[v].has(*xs) for v in xs):
                            out.append({x: sol[s] for x, s in zip(self.used, xs)})
        except (OverBudget, NotImplementedError, ValueError, TypeError):
            pass
        return out

    def residual(self, row: int, accelerations: dict, inverse: dict):
        """Own equation ``row`` on the reference motion, in the own coordinates.

        ``accelerations`` are the reference's ``{x''(t): expression in x, x'}``; own
        accelerations follow from the map by the chain rule, and ``inverse`` writes the
        reference coordinates in the own ones.  Own coordinates that the map fixes take
        their value.
        """
        back = {x.diff(t): e.diff(t) for x, e in inverse.items()}
        back.update(inverse)
        rules, fixed = {}, {}
        for q in self.model.coordinates:
            phi = self.mapping[q]
            if q in self.fixed:
                rules[q.diff(t, 2)], rules[q.diff(t)] = phi.diff(t, 2), phi.diff(t)
                fixed[q] = phi
            else:
                rules[q.diff(t, 2)] = phi.diff(t, 2).xreplace(accelerations).xreplace(back)
        return self.model.equations[row].xreplace(rules).xreplace(fixed)


def _returns(psi, x0, subs) -> bool:
    """Does the branch ``psi`` give back ``x0`` at the state ``subs`` (30 digits)?"""
    x0 = sp.Float(str(x0), 30)
    try:
        re, im = sp.N(psi.xreplace(subs), 30).as_real_imag()
        return bool(abs(re - x0) + abs(im) <= _BRANCH_TOL * (1 + abs(x0)))
    except (TypeError, ValueError, ZeroDivisionError):
        return False


def _real(expr):
    """A 30-digit value of ``expr`` (real by construction: a map of real coordinates)."""
    value = sp.N(expr, 30)
    if not value.is_Number:
        raise ValueError(f"the coordinate map leaves {sorted(map(str, value.free_symbols))} "
                         "without a value at the state")
    return value
