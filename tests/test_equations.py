"""The canonical equation object (dualmech.model.equations)."""
import numpy as np
import pytest
import sympy as sp

from dualmech import EquationSet, ModelError, coordinate, t
from dualmech.model.dimensions import MASS, STIFFNESS, audit

q1, q2, th = coordinate("q1"), coordinate("q2"), coordinate("theta")
m, k, g, l, c = sp.symbols("m k g l c", positive=True)
lam = sp.Symbol("lam")


def chain():
    """Two masses m on springs k (wall-q1-q2): M = m I, K = k [[2, -1], [-1, 1]]."""
    return EquationSet("chain", (q1, q2), (m * q1.diff(t, 2) + 2 * k * q1 - k * q2,
                                           m * q2.diff(t, 2) + k * q2 - k * q1))


def test_matrix_form():
    eqs = EquationSet("r", (q1,), (m * q1.diff(t, 2) - lam + k * q1, lam - m * g), (lam,))
    A, b = eqs.matrix()
    assert A == sp.Matrix([[m, -1], [0, 1]]) and b == sp.Matrix([-k * q1, m * g])
    assert eqs.is_square
    sol = eqs.solve()
    assert sp.simplify(sol[lam] - m * g) == 0
    assert sp.simplify(sol[q1.diff(t, 2)] - (g - k * q1 / m)) == 0


def test_linearize_and_modes_of_the_chain():
    M, C, K = chain().linearize()
    assert M == m * sp.eye(2) and C == sp.zeros(2, 2)
    assert K == sp.Matrix([[2 * k, -k], [-k, k]])
    # hand: w^2 = (3 -+ sqrt(5))/2 k/m
    w, modes = chain().natural_frequencies(values={m: 2.0, k: 8.0})
    expected = np.sqrt(np.array([(3 - 5**0.5) / 2, (3 + 5**0.5) / 2]) * 4.0)
    assert np.allclose(w.real, expected, rtol=1e-12)
    assert modes.shape == (2, 2)


def test_linearize_pendulum_about_bottom_and_top():
    eqs = EquationSet("p", (th,), (l * th.diff(t, 2) + g * sp.sin(th),))
    assert eqs.linearize()[2] == sp.Matrix([[g]])
    assert eqs.linearize({th: sp.pi})[2] == sp.Matrix([[-g]])
    with pytest.raises(ModelError, match="not an equilibrium"):
        eqs.linearize({th: 1})


def test_change_of_coordinates_keeps_the_motion():
    # relative coordinates r1 = q1, r2 = q2 - q1
    r1, r2 = coordinate("r1"), coordinate("r2")
    moved = chain().change_coordinates((r1, r2), {q1: r1, q2: r1 + r2})
    assert moved.coordinates == (r1, r2)
    expected = m * (r1.diff(t, 2) + r2.diff(t, 2)) + k * r2
    assert sp.simplify(moved.equations[1] - expected) == 0


@pytest.mark.parametrize("bad, message", [
    ((m * q1.diff(t, 2) ** 2,), "not linear"),
    ((q1.diff(t, 3),), "second derivatives"),
    ((q1.diff(t, 2) + q2,), "not one of its coordinates"),
    ((), "has no equations"),
], ids=["nonlinear", "jerk", "stranger", "empty"])
def test_bad_models_get_clear_errors(bad, message):
    with pytest.raises(ModelError, match=message):
        EquationSet("bad", (q1,), bad)


def test_coordinate_must_be_a_function_of_time():
    with pytest.raises(ModelError, match="function of t"):
        EquationSet("bad", (sp.Symbol("x"),), (sp.Symbol("x"),))


def test_ingredients_drop_and_flip():
    eqs = EquationSet("e", (q1,), (m * q1.diff(t, 2) + k * q1,),
                      contributions=({"inertia": m * q1.diff(t, 2), "spring": k * q1},))
    assert eqs.ingredients() == ["inertia", "spring"]
    assert eqs.without("spring").equations == (m * q1.diff(t, 2),)
    assert sp.expand(eqs.flipped("spring").equations[0] - (m * q1.diff(t, 2) - k * q1)) == 0
    with pytest.raises(KeyError):
        eqs.without("gravity")


def test_dimension_audit_of_sums_and_functions():
    dims = {m: MASS, k: STIFFNESS, q1: MASS}
    issues = audit(sp.sin(m) + k, dims)
    assert any("argument `m` of sin" in str(i) for i in issues)


def test_zero_has_every_dimension():
    from dualmech.model.dimensions import FORCE
    assert audit(sp.Integer(0), {}, FORCE) == []
    assert audit(k * q1 + 0, {k: STIFFNESS, q1: MASS}) == []
    assert audit(k + 1, {k: STIFFNESS})  # a nonzero number is dimensionless
