"""Block in a pipe (problems/block_in_pipe.py): the vanishing normal force, equilibrium, modes."""
import pytest
import sympy as sp

from dualmech.compare import compare, compare_models
from dualmech.problems.block_in_pipe import BlockInPipe, g, k, m, multiplier_model, theta, y, y0

problem = BlockInPipe()
N = sp.Symbol("N", real=True)


@pytest.fixture(scope="module")
def comparison():
    return compare(problem)


def test_declaration_validates():
    problem.validate()
    assert problem.model_names == ["newton_euler", "lagrange"]
    assert problem.dimension_issues() == []


def test_massless_pipe_exerts_no_normal_force():
    # hand: the pipe's moments about O are -y N = 0 (spring and damper act through O)
    assert problem.model("newton_euler").reactions_solved() == {N: 0}


def test_multiplier_of_the_axis_constraint_is_zero_too():
    mapped = problem.in_reference_coordinates(multiplier_model())
    assert mapped.is_square and mapped.unknowns == (N,)
    assert compare_models(problem.model("lagrange"), mapped, explain=False).equivalent
    assert sp.simplify(mapped.reactions_solved()[N]) == 0


def test_equilibrium_and_small_oscillations_derived_by_the_library():
    # hand: theta = 0, k (y - y0) = m g; omega^2 = k/m along the pipe, g/y_eq for the swing
    lg = problem.model("lagrange")
    y_eq = y0 + m * g / k
    found = lg.equilibria()
    assert any(sp.simplify(e[theta]) == 0 and sp.simplify(e[y] - y_eq) == 0 for e in found)
    omegas = lg.natural_frequencies({theta: 0, y: y_eq})
    squares = [w**2 for w in omegas]
    assert len(squares) == 2
    for hand in (k / m, g / y_eq):
        assert sum(sp.simplify(s - hand) == 0 for s in squares) == 1, hand
    M, C, K = lg.linearize({theta: 0, y: y_eq})
    assert C == sp.diag(0, sp.Symbol("d", positive=True))


def test_mass_matrix_is_singular_only_at_the_pivot():
    det = problem.model("lagrange").mass_matrix().det()
    assert sp.simplify(det - m**2 * y**2) == 0 and problem.singular == (y,)


def test_published_verdicts(comparison):
    assert comparison.equivalent, str(comparison)
    assert {v.label: v.verdict for v in comparison.published} == {
        "generalised forces": "correct",   # the damper's -d y' e_r . dr/dq: (0, -d y')
        "Lagrangian": "correct"}           # block as a particle in polar coordinates
