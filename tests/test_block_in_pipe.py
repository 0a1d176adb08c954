"""Block in a pipe (problems/block_in_pipe.py): the vanishing normal force, derived twice and
compared, equilibrium, modes."""
import pytest
import sympy as sp

from dualmech import Lagrangian, t
from dualmech.verify.check import compare, compare_models
from dualmech.verify.mutation import mutation_report
from dualmech.problems.block_in_pipe import (BlockInPipe, d, g, k, m, multiplier_model, theta, w,
                                             y, y0)

problem = BlockInPipe()
N = sp.Symbol("N", real=True)


@pytest.fixture
def comparison(compared):
    return compared("block_in_pipe")


def test_massless_pipe_exerts_no_normal_force():
    # hand: the pipe's moments about O are -y N = 0 (spring and damper act through O)
    assert problem.model("newton_euler").reactions_solved() == {N: 0}


def test_multiplier_of_the_axis_constraint_is_zero_too():
    mapped = problem.in_reference_coordinates(multiplier_model())
    assert mapped.is_square and mapped.unknowns == (N,)
    assert compare_models(problem.model("lagrange"), mapped, explain=False).equivalent
    assert sp.simplify(mapped.reactions_solved()[N]) == 0


def test_N_is_derived_twice_and_compared(comparison):
    assert comparison.reaction_derivations == {"N": ["newton_euler", "multiplier"]}
    assert "NOT CROSS-CHECKED" not in str(comparison)


class _SpuriousTangential(BlockInPipe):
    """The multiplier model with a stray force ``c m g`` along ``e_th`` put on the offset ``w``
    only (a student's generalised force computed for the wrong coordinate).  On ``w = 0`` it
    leaves the motion alone and moves the multiplier to ``N = -c m g``."""

    def multiplier(self):
        s, c = sp.sin(theta), sp.cos(theta)
        e_r, e_th = sp.Matrix([s, -c]), sp.Matrix([c, s])
        r = y * e_r + w * e_th
        v = r.diff(t)
        lg = Lagrangian("multiplier", coordinates=[theta, y, w])
        lg.kinetic("T of block", m * (v.T * v)[0, 0] / 2)
        lg.potential("gravity", m * g * r[1])
        lg.spring("spring", k, y - y0)
        damper = -d * y.diff(t) * e_r
        lg.generalized_force("damper", [damper.dot(r.diff(q)) for q in (theta, y, w)])
        lg.generalized_force("stray", [0, 0, sp.Rational(3, 7) * m * g])
        lg.constraint("N", w)
        return lg.equations()


def test_a_wrong_N_in_the_multiplier_model_is_a_named_disagreement():
    broken = compare(_SpuriousTangential())
    assert all(p.equivalent for p in broken.pairs if p.kind == "motion")   # motion untouched
    assert not broken.equivalent
    (pair,) = [p for p in broken.pairs if p.kind == "reactions"]
    assert not pair.equivalent and pair.mismatches
    assert {mm.equation for mm in pair.mismatches} == {"reaction N"}
    assert "DIFFERENT" in str(broken) and "all derivations agree" not in str(broken)
    # the stray force's value, exactly: the broken model's N is -3/7 m g at any state
    mapped = broken.problem.in_reference_coordinates(broken.problem.model("multiplier"))
    assert sp.simplify(mapped.reactions_solved()[N] + sp.Rational(3, 7) * m * g) == 0


def test_mutants_of_the_vanishing_multiplier_are_equivalent_not_survivors():
    report = mutation_report(problem)
    assert report.kill_rate == 1.0 and report.total >= 30, str(report)
    # -N and 2 N are N when N = 0: the same motion and the same reaction, counted apart --
    # so is the unknown N flipped in either model (N -> -N), never a survivor
    assert sorted(report.equivalent) == ["multiplier: double `constraint N`",
                                         "multiplier: flip the sign of `constraint N`",
                                         "multiplier: flip the sign of unknown `N`",
                                         "newton_euler: flip the sign of unknown `N`"]
    # dropping the constraint loses N: a catch, never an equivalence
    killed = dict(report.killed)
    assert killed["multiplier: drop `constraint N`"] == ["multiplier: reactions"]


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

