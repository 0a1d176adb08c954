"""Steady motions: some coordinates held fixed while every rate stays constant.

A steady motion (a relative equilibrium) keeps the coordinates ``fixed`` constant and every
rate constant: ``q'' = 0`` for every coordinate and ``q' = 0`` for the fixed ones.  What is
left of the equations of motion ties the remaining rates to the fixed coordinates -- the
circular orbit of a satellite (``r`` fixed: ``theta'^2 = mu / r^3``), the steady precession of
a top (``theta`` fixed: a quadratic in the precession rate ``phi'``).  With no rate left free
this is :meth:`~dualmech.model.equations.EquationSet.equilibria`.

The conditions come straight from the (verified) equations, with no symbolic inverse of the
mass matrix: where the mass matrix is regular, ``q'' = 0`` in the equations is the same as
``q'' = 0`` in their solved form.

Example
-------
>>> import sympy as sp
>>> from dualmech import Lagrangian, coordinate, t
>>> from dualmech.model.steady import steady_rates
>>> r, th = coordinate("r"), coordinate("theta"); m, mu = sp.symbols("m mu", positive=True)
>>> lg = Lagrangian(coordinates=[r, th])
>>> lg.kinetic("T", m * (r.diff(t)**2 + r**2 * th.diff(t)**2) / 2)
>>> lg.potential("V", -m * mu / r)
>>> steady_rates(lg.equations(), fixed=[r], solve_for=th.diff(t))
[-sqrt(mu)*sqrt(r(t)**(-3)), sqrt(mu)*sqrt(r(t)**(-3))]
"""
from __future__ import annotations

from typing import Mapping, Sequence

import sympy as sp

from dualmech.model._expr import refuse_text

from dualmech.model.equations import EquationSet, ModelError, from_plain, state_symbols, to_plain

__all__ = ["steady_conditions", "steady_rates"]


def _check(eqs: EquationSet, fixed: Sequence) -> None:
    if eqs.unknowns:
        raise ModelError(f"model `{eqs.name}` has reactions {list(eqs.unknowns)}; find steady "
                         "motions of a reaction-free model (e.g. the Lagrangian one), or check a "
                         "candidate with `dualmech.linearize_about`, which takes any model.")
    unknown = [q for q in fixed if q not in eqs.coordinates]
    if unknown:
        raise ModelError(f"`fixed` holds {unknown}, which are not coordinates of "
                         f"`{eqs.name}` {list(eqs.coordinates)}.")


@refuse_text
def steady_conditions(eqs: EquationSet, fixed: Sequence,
                      values: Mapping | None = None) -> list[sp.Expr]:
    """The equations of ``eqs`` on a steady motion, left sides ``= 0``.

    Every acceleration is set to zero and so is the rate of each coordinate in ``fixed``;
    equations that then vanish identically are dropped.  ``values`` (parameter -> value)
    may fix parameters first.  The result uses ``q(t)`` and ``q'(t)`` as the models do.
    """
    _check(eqs, fixed)
    still = {}
    for s in eqs.states:
        still[s.qdd] = 0
        if s.function in fixed:
            still[s.qd] = 0
    out = []
    for e in eqs.equations:
        e = to_plain(e, eqs.coordinates).subs(still)
        if values:
            e = e.subs(values)
        e = sp.expand(e)
        if e != 0 and sp.simplify(e) != 0:
            out.append(from_plain(e, eqs.coordinates))
    return out


@refuse_text
def steady_rates(eqs: EquationSet, fixed: Sequence, solve_for,
                 values: Mapping | None = None) -> list[sp.Expr]:
    """The values of the rate ``solve_for`` (a ``q'(t)``) on the steady motions of ``eqs``.

    Solves :func:`steady_conditions` for ``solve_for``; every other free rate stays a
    symbol of the answer.  Returns the solutions :func:`sympy.solve` finds, ordered as it
    gives them (factors free of ``solve_for``, such as ``sin(theta)`` of a top standing
    upright, are not solutions for the rate and are left out).
    """
    if not (isinstance(solve_for, sp.Derivative) and solve_for.derivative_count == 1
            and solve_for.expr in eqs.coordinates):
        raise ModelError(f"`solve_for` must be the rate q'(t) of a coordinate of `{eqs.name}`, "
                         f"got {solve_for}.")
    if solve_for.expr in fixed:
        raise ModelError(f"`solve_for` is the rate of {solve_for.expr}, which `fixed` holds at "
                         "rest; solve for the rate of a coordinate that moves.")
    conds = steady_conditions(eqs, fixed, values)
    if not conds:
        raise ModelError(f"every equation of `{eqs.name}` holds on any such steady motion: "
                         "nothing determines the rate.")
    x = state_symbols(solve_for.expr).qd
    plain = [to_plain(c, eqs.coordinates) for c in conds]
    involved = [c for c in plain if c.has(x)]
    if not involved:
        raise ModelError(f"no steady-motion condition of `{eqs.name}` involves {solve_for}; "
                         f"the conditions are {conds}.")
    rest = [from_plain(c, eqs.coordinates) for c in plain if not c.has(x)]
    if rest:
        raise ModelError(f"steady motions of `{eqs.name}` also need {rest} = 0, which do not "
                         f"involve {solve_for}; fix those coordinates or parameters first.")
    sols = sp.solve(involved, [x], dict=True)
    return [from_plain(s[x], eqs.coordinates) for s in sols if x in s]

