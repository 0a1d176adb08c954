"""The display solve from symengine trees (:func:`dualmech.exact.rational_functions.solve_rational_held`,
only the atoms converted to sympy) gives exactly the expressions of the sympy route
(:func:`solve_rational` on every entry converted): the same reduced fractions, written alike."""
import pytest
import symengine as se
import sympy as sp

from dualmech.model._algebra import to_sp
from dualmech.problems import get
from dualmech.exact.rational_functions import NotRational, solve_rational, solve_rational_held

#: (problem, model, whether every atom stays an atom in sympy); where one does not (sympy writes
#: sin(theta1 - theta2) as -sin(theta2 - theta1), a product), the held route refuses and the
#: caller converts the entries instead
CASES = [("toy_car", "lagrange", True), ("toy_car", "newton_euler", True),
         ("toy_car", "multiplier", True), ("bead_on_hoop", "multiplier", True),
         ("rolling_cylinder", "newton_euler", True), ("spring_mass_damper", "lagrange", True),
         ("compound_double_pendulum", "lagrange", False)]


def _both(rows, rhs, pivots, names):
    memo: dict = {}
    conv = lambda a: to_sp(a, names, memo)  # noqa: E731
    held = solve_rational_held(rows, rhs, pivots, conv)
    plain = solve_rational([[conv(x) for x in row] for row in rows], [conv(x) for x in rhs],
                           pivots)
    return held, plain


@pytest.mark.parametrize("name, model, atoms_stay", CASES)
def test_held_solve_is_the_sympy_solve(name, model, atoms_stay):
    eqs = get(name).model(model)
    A, b, names = eqs.plain_matrix_se()
    n = A.rows
    rows = [[A[i, j] for j in range(n)] for i in range(n)]
    if not atoms_stay:
        with pytest.raises(NotRational, match="not an atom once in sympy"):
            _both(rows, [b[i] for i in range(n)], list(range(n)), dict(names))
        return
    held, plain = _both(rows, [b[i] for i in range(n)], list(range(n)), dict(names))
    assert held == plain


def test_held_solve_small_system_by_hand():
    # [[a, b], [0, a]] x = [a b, a s]: x2 = s, x1 = (a b - b s) / a = b (a - s) / a
    a, b, s = se.symbols("a b s")
    names = {str(v): sp.Symbol(str(v)) for v in (a, b, s)}
    held, plain = _both([[a, b], [se.Integer(0), a]], [a * b, a * s], [0, 1], names)
    A, B, S = sp.symbols("a b s")
    assert held == plain == [B * (A - S) / A, S]


def test_held_solve_refuses_what_the_sympy_route_refuses():
    x = se.Symbol("x")
    names = {"x": sp.Symbol("x", positive=True)}
    with pytest.raises(NotRational):     # a float
        _both([[x]], [x * se.RealDouble(0.5)], [0], names)
    # an atom sympy splits: sqrt(x y) with positive symbols is sqrt(x) sqrt(y) there
    y = se.Symbol("y")
    names = {"x": sp.Symbol("x", positive=True), "y": sp.Symbol("y", positive=True)}
    with pytest.raises(NotRational):
        solve_rational_held([[x]], [se.sqrt(x * y)], [0],
                            lambda a: to_sp(a, names, {}))
