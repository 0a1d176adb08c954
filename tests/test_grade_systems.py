"""Systems with constraint rows graded as systems (a DAE in the student's coordinates).

Reference: the pendulum of pendulum_particle in the coordinates of its own `cartesian` model
(bob at (x, y), y downward since V = -m g y, rod pull S, constraint x^2 + y^2 = l^2; see
problems/pendulum_particle.py): m x'' = -S x/l, m y'' = -S y/l + m g.  The constraint at
velocity level is x x' + y y' = 0, at acceleration level x x'' + y y'' + x'^2 + y'^2 = 0."""
import pytest

from dualmech import grade

X = "m*x'' = -S*x/l"
Y = "m*y'' = -S*y/l + m*g"


@pytest.mark.parametrize("constraint, level", [
    ("x^2 + y^2 = l^2", "position"),
    ("x*x' + y*y' = 0", "velocity"),
])
def test_a_complete_system_with_its_constraint_is_right(constraint, level):
    g = grade("pendulum_particle", f"{X}; {Y}; {constraint}")
    assert g.right, str(g)
    assert f"equation 3 ({level} level)" in g.summary


def test_the_constraint_at_acceleration_level_completes_the_system():
    g = grade("pendulum_particle", f"{X}; {Y}; x*x'' + y*y'' + x'^2 + y'^2 = 0")
    assert g.right, str(g)


def test_without_the_constraint_the_system_is_incomplete_and_says_so():
    g = grade("pendulum_particle", f"{X}; {Y}")
    assert g.status == "wrong"
    assert "cannot determine 3 unknowns" in g.summary and "is missing" in g.summary
    assert g.score == pytest.approx(2 / 3)


def test_a_sign_slip_beside_a_right_constraint_is_named():
    g = grade("pendulum_particle", f"{X}; m*y'' = -S*y/l - m*g; x^2 + y^2 = l^2")
    assert g.status == "wrong"
    assert [(e.kind, e.equation) for e in g.edits] == [("sign", 1)]


def test_a_wrong_constraint_is_wrong():
    g = grade("pendulum_particle", f"{X}; {Y}; x^2 + y^2 = 2*l^2")
    assert g.status == "wrong" and "equation 3" in g.summary


def test_a_tautology_is_not_a_constraint():
    g = grade("pendulum_particle", f"{X}; {Y}; x = x")
    assert g.status == "wrong" and "says nothing" in g.summary


def test_answers_in_the_reference_coordinates_are_graded_as_before():
    assert grade("pendulum_particle", "l*theta'' + g*sin(theta) = 0").right
