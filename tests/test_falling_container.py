"""Falling container (problems/falling_container.py): two coordinate choices, guides, the errata."""
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings

from dualmech import t
from dualmech.numeric import NumericModel
from dualmech.testing import points
from dualmech.problems.falling_container import (FallingContainer, c, g, k, l0, m1, m2, x1, x2, y1, y2)

_EPS = np.finfo(float).eps
problem = FallingContainer()
D = lambda q: q.diff(t)  # noqa: E731
DD = lambda q: q.diff(t, 2)  # noqa: E731


@pytest.fixture
def comparison(compared):
    return compared("falling_container")


def test_y_models_are_mapped_to_the_x_coordinates():
    assert set(problem.coordinate_maps()) == {"lagrange_y", "newton_euler_y"}


def test_accelerations_are_the_hand_derived_ones():
    # sum F = m a along j for each body (module docstring), spring extension x2 - x1 - l0
    force = k * (x2 - x1 - l0) + c * (D(x2) - D(x1))
    hand = {DD(x1): (force - m1 * g) / m1, DD(x2): (-force - m2 * g) / m2}
    for name in ("lagrange", "newton_euler"):
        sol = problem.model(name).solve()
        assert all(sp.simplify(sol[a] - v) == 0 for a, v in hand.items()), name


def test_guide_reactions_vanish():
    # i-components: H1 - H2 = 0 and H2 = 0 -- nothing pushes sideways
    for name in ("newton_euler", "newton_euler_y"):
        assert set(problem.model(name).reactions_solved().values()) == {0}


def _solve(name, point, q, qd):
    """``[q''; reactions]`` of model ``name`` in its own coordinates, and cond(A)."""
    A, b = NumericModel(problem.model(name), point.params).system(point.time, q, qd)
    return np.linalg.solve(A, b), np.linalg.cond(A)


@settings(max_examples=60)
@given(points(problem))
def test_x_and_y_coordinates_are_the_same_motion(point):
    # map the state by hand (not through change_coordinates): y1 = x1, y2 = x2 - x1 - l0,
    # then y1'' must equal x1'' and y2'' must equal x2'' - x1''
    L0 = point.params[l0]
    (a1, a2), (r1, r2) = point.q, point.qd
    xs, cx = _solve("lagrange", point, (a1, a2), (r1, r2))
    expected = np.array([xs[0], xs[1] - xs[0]])
    for name in ("lagrange_y", "newton_euler_y"):
        ys, cy = _solve(name, point, (a1, a2 - a1 - L0), (r1, r2 - r1))
        scale = max(1.0, float(np.max(np.abs(xs[:2]))))
        tol = 64 * _EPS * (cx + cy) * scale
        assert np.max(np.abs(ys[:2] - expected)) <= tol, name


def test_relative_motion_is_a_damped_oscillator_independent_of_the_fall():
    # subtract the two x-equations divided by their masses: the container's free fall drops out
    # of y2 = x2 - x1 - l0:  y2'' + (1/m1 + 1/m2)(c y2' + k y2) = 0
    sol = problem.model("lagrange_y").solve()
    mu = 1 / m1 + 1 / m2
    assert sp.simplify(sol[DD(y2)] + mu * (c * D(y2) + k * y2)) == 0
    assert sp.simplify(sol[DD(y1)] + g - k * y2 / m1 - c * D(y2) / m1) == 0


def _on_motion(expr, model="lagrange"):
    """``expr`` with the accelerations replaced by the true ones, simplified."""
    return sp.simplify(sp.sympify(expr).xreplace(problem.model(model).accelerations_solved()))


def test_printed_x_equations_miss_l0_and_the_second_has_the_wrong_mass():
    pubs = {p.label: p for p in problem.published()}
    (e1,) = pubs["x-equation 1, x2 from the ground"].printed
    (e2,) = pubs["x-equation 2, x2 from the ground"].printed
    # hand: true eq 1 is m1 x1'' + c(x1' - x2') + k(x1 - x2 + l0) + m1 g, so printed - true = -k l0
    assert _on_motion(e1) == -k * l0
    # hand: true eq 2 has m2 x2'' and k(x2 - x1 - l0), so printed - true = (m1 - m2) x2'' + k l0
    assert sp.simplify(_on_motion(e2) - _on_motion((m1 - m2) * DD(x2) + k * l0)) == 0
    # with l0 = 0 the first is right; the second stays wrong unless m1 = m2
    assert sp.simplify(_on_motion(e1).subs(l0, 0)) == 0
    assert sp.simplify(_on_motion(e2).subs(l0, 0)) != 0
    assert sp.simplify(_on_motion(e2).subs({l0: 0, m1: m2})) == 0


def test_printed_x_equations_read_with_the_energys_datum():
    # x2 measured from the spring's free length (U = k (x1 - x2)^2/2): x2_printed = x2 - l0
    pubs = {p.label: p for p in problem.published()}
    (f1,) = pubs["x-equation 1, x2 from the free length"].printed
    (f2,) = pubs["x-equation 2, x2 from the free length"].printed
    assert sp.expand(f1 - (m1 * DD(x1) + c * (D(x1) - D(x2)) + k * (x1 - x2 + l0) + m1 * g)) == 0
    assert _on_motion(f1) == 0
    # hand: the second keeps only the wrong mass, printed - true = (m1 - m2) x2''
    assert sp.simplify(_on_motion(f2) - _on_motion((m1 - m2) * DD(x2))) == 0


def test_printed_y_equations_hold_in_y_coordinates():
    for p in problem.published():
        if p.coordinates == "lagrange_y":
            assert _on_motion(p.printed[0], "lagrange_y") == 0, p.label


def test_comparator_names_the_missing_l0_and_finds_no_guide_force(comparison):
    detail = {v.label: v.detail for v in comparison.published}
    assert "k*l0" in detail["x-equation 1, x2 from the ground"]
    assert comparison.reactions == {"H1": 0, "H2": 0}
