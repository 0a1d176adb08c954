"""The display solve of equations held in symengine (Gaussian elimination with pivots chosen
by value, :func:`dualmech.verify.display._solve_held`) against sympy's own LU solve of the same
model (:meth:`EquationSet.solve`, pivots chosen by an exact zero test): the same accelerations
and reactions, compared at random real states to 1e-9."""
import random

import pytest
import sympy as sp

from dualmech.model.equations import to_plain
from dualmech.problems import get
from dualmech.verify.display import Budget, solve_display

CASES = [("toy_car", "newton_euler"), ("toy_car", "multiplier"),
         ("bead_on_hoop", "multiplier"),                 # sin^2 + cos^2 in its entries
         ("pendulum_on_rotating_plane", "multiplier"),   # prescribed motion, time in A
         ("two_rod_linkage", "lagrange_x"),              # a square root: complex at the point
         ("block_in_pipe", "multiplier"), ("rolling_cylinder", "newton_euler")]


def _values(expr, coords, rng_seed):
    rng = random.Random(rng_seed)
    e = to_plain(expr, coords)
    subs = {s: sp.Float(rng.uniform(0.2, 0.9), 30) for s in sorted(e.free_symbols, key=str)}
    return complex(e.evalf(30, subs=subs))


@pytest.mark.slow
@pytest.mark.parametrize("name, model", CASES)
def test_display_solve_matches_sympys_lu(name, model):
    m = get(name).model(model)
    assert m.plain_matrix_se() is not None      # the symengine route is the one under test
    mine = solve_display(m, Budget())
    theirs = m.solve()
    assert set(mine) == set(theirs)
    for u in mine:
        for seed in range(3):
            a = _values(mine[u], m.coordinates, seed)
            b = _values(theirs[u], m.coordinates, seed)
            assert abs(a - b) <= 1e-9 * (1 + abs(b)), (u, mine[u], theirs[u])


def test_display_solve_refuses_a_singular_system_like_sympy():
    # copying_machine's massless bar: a row without accelerations (its static balance)
    m = get("copying_machine").model("lagrange")
    with pytest.raises(ValueError, match="not invertible"):
        solve_display(m, Budget())
