"""Hypothesis strategies and assertions for property-testing your own models.

Draw parameters and states of any :class:`~dualmech.model.problem.Problem` within its declared ranges
and away from its singular set, then assert that every derivation gives the same accelerations
and that the recovered reactions satisfy the direct equations.  Tolerances come from the linear
solve's own error bound (``eps * cond(A)``), not from a round number.

Example
-------
A property test of a problem in four lines (the problem is built once, outside the test: built
inside, its models would be derived again at every example, and shrinking a failure would take
minutes)::

    from hypothesis import given
    from dualmech.testing import points, assert_same_motion
    from dualmech.problems import get

    toy_car = get("toy_car")

    @given(points(toy_car))
    def test_toy_car_both_ways(point):
        assert_same_motion(toy_car, point)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp
try:
    from hypothesis import strategies as st
except ImportError as exc:  # the plain install has no hypothesis
    raise ImportError("dualmech.testing needs hypothesis: install it with "
                      "`pip install hypothesis` (the `test` extra has it too).") from exc

from dualmech.model.kinematics import t
from dualmech.numeric import NumericModel

__all__ = ["Point", "parameters", "states", "points", "assert_same_motion",
           "assert_reactions_consistent"]

_EPS = np.finfo(float).eps


@dataclass(frozen=True)
class Point:
    """Parameter values and a state: ``params`` {symbol: float}, ``time``, ``q``, ``qd``."""

    params: dict
    time: float
    q: tuple
    qd: tuple


def _interval(lo, hi):
    lo, hi = float(lo), float(hi)
    return st.floats(min_value=lo, max_value=hi, allow_nan=False, allow_infinity=False)


def parameters(problem) -> st.SearchStrategy:
    """Dictionaries ``{symbol: value}`` with every parameter inside its declared range."""
    return st.fixed_dictionaries({p.symbol: _interval(*p.range) for p in problem.parameters})


def states(problem, margin: float = 0.05) -> st.SearchStrategy:
    """``(time, q, qd)`` in the declared ranges, at least ``margin`` away from the singular set.

    The singular set is where one of ``problem.singular`` (expressions in the coordinates)
    vanishes; states with ``|expr| < margin`` are rejected.
    """
    ref = problem.model(problem.reference)
    infos = [problem.coordinate_info(q) for q in ref.coordinates]
    qs = st.tuples(*[_interval(*c.range) for c in infos])
    qds = st.tuples(*[_interval(*c.rate_range) for c in infos])
    tt = _interval(0.0, 10.0)
    checks = [sp.lambdify([t] + list(ref.coordinates), s, "math") for s in problem.singular]

    def regular(s):
        time, q, _ = s
        return all(abs(f(time, *q)) >= margin for f in checks)

    return st.tuples(tt, qs, qds).filter(regular)


def points(problem, margin: float = 0.05) -> st.SearchStrategy:
    """:class:`Point` objects: parameters and a regular state."""
    return st.builds(lambda p, s: Point(p, s[0], s[1], s[2]), parameters(problem),
                     states(problem, margin))


def has_static_rows(problem) -> bool:
    """Whether the reference model has static rows (a massless body: a DAE)."""
    A, _ = problem.model(problem.reference).plain_matrix()
    return any(all(x == 0 for x in A.row(i)) for i in range(A.rows))


def _solve_all(problem, point: Point):
    if has_static_rows(problem):
        from dualmech.model.equations import ModelError
        raise ModelError(f"`{problem.name}` is differential-algebraic (static rows of a "
                         "massless body): its states must lie on the constraint manifold, which "
                         "these float assertions do not sample; `compare()` decides it exactly "
                         "on the manifold.")
    out = {}
    for name, m in problem.models().items():
        m = problem.in_reference_coordinates(m)
        nm = NumericModel(m, point.params)
        A, b = nm.system(point.time, point.q, point.qd)
        if A.shape[0] == A.shape[1]:
            x = np.linalg.solve(A, b)
        else:
            x = np.linalg.lstsq(A, b, rcond=None)[0]
        mag = _term_magnitude(m, point)
        out[name] = (x, np.linalg.cond(A), A, b, m, mag / max(float(np.max(np.abs(A))), 1e-300))
    return out


_TERMS: dict = {}


def _term_magnitude(eqs, point: Point) -> float:
    """``max_i sum_k |term_k of b_i|`` at ``point``: the size of what rounding cancels in the
    forcing (a geometry's large terms that nearly cancel), which bounds its evaluation error."""
    import sympy as sp
    key = id(eqs)
    hit = _TERMS.get(key)
    if hit is None or hit[0] is not eqs:
        _, b = eqs.plain_matrix()
        states = eqs.states
        from dualmech.model.kinematics import t as time_symbol
        symbols = [time_symbol] + [s.q for s in states] + [s.qd for s in states]
        params = sorted(set().union(*(e.free_symbols for e in b)) - set(symbols), key=str)
        rows = [sum(sp.Abs(term) for term in sp.Add.make_args(e)) for e in b]
        fn = sp.lambdify(symbols + params, rows, modules="math")
        hit = _TERMS[key] = (eqs, fn, params)
    _, fn, params = hit
    values = [point.time, *point.q, *point.qd] + [float(point.params[p]) for p in params]
    try:
        return float(max(fn(*values), default=0.0))
    except (ValueError, ZeroDivisionError, OverflowError, KeyError):
        return 0.0


def assert_same_motion(problem, point: Point, factor: float = 64.0) -> None:
    """Every model of ``problem`` gives the reference accelerations at ``point``.

    Tolerance: ``factor * eps * (cond(A_ref) + cond(A_model)) * max(1, |q''|, |b|_terms /
    |A|)``, the error bound of the two linear solves, where ``|b|_terms`` is the size of the
    forcing's terms before they cancel (so rounding in a nearly cancelling geometry counts).
    """
    sols = _solve_all(problem, point)
    x_ref, c_ref, *_r, mag_ref = sols[problem.reference]
    n = len(point.q)
    a_ref = x_ref[:n]
    for name, (x, c, *_rest, mag) in sols.items():
        tol = factor * _EPS * (c_ref + c) * max(1.0, float(np.max(np.abs(a_ref))), mag_ref,
                                                mag)
        err = float(np.max(np.abs(x[:n] - a_ref)))
        if not err <= tol:
            raise AssertionError(
                f"{problem.name}: model `{name}` gives q'' = {x[:n]} but `{problem.reference}` "
                f"gives {a_ref} at t={point.time}, q={point.q}, q'={point.qd} "
                f"(difference {err:.3g} > tolerance {tol:.3g})")


def assert_reactions_consistent(problem, point: Point, factor: float = 64.0) -> None:
    """The direct equations hold with the reference accelerations and the recovered reactions."""
    sols = _solve_all(problem, point)
    x_ref, c_ref, *_ = sols[problem.reference]
    n = len(point.q)
    for name, (x, c, A, b, m, _mag) in sols.items():
        if not m.unknowns:
            continue
        full = np.concatenate([x_ref[:n], x[n:]])
        residual = A @ full - b
        scale = max(1.0, float(np.max(np.abs(b))), float(np.max(np.abs(A))) *
                    float(np.max(np.abs(full))))
        tol = factor * _EPS * (c_ref + c) * scale
        if not float(np.max(np.abs(residual))) <= tol:
            raise AssertionError(f"{problem.name}: with the recovered reactions the equations of "
                                 f"`{name}` leave residual {residual} (tolerance {tol:.3g})")
