"""The mechanisms the second corpus of students' answers needed, one answer each.

Right forms are derived by hand from each problem's statement (see the header of
``tests/corpus/student_answers_2.toml``); each wrong answer carries one known mistake, and the
test asserts the edit the grader names for it -- its kind, its term, its kind of term.
"""
from __future__ import annotations

import pytest

from dualmech.grade import Grader


def _one(problem, text, quantity=None):
    g = Grader.of(problem).grade(text, quantity)
    assert g.status == "wrong" and len(g.edits) == 1, str(g)
    e = g.edits[0]
    return e.kind, e.term, e.correct, e.category


@pytest.mark.parametrize("text", [
    "k x^2/2 + M g x",            # the source's V, F left to Q = F
    "k x^2/2 + M g x - F x",      # F counted as a potential
])
def test_a_steady_load_declared_as_a_generalised_force_may_be_in_v_or_not(text):
    # mass_spring_gravity: V = k x^2/2 + M g x, Q = F (source 002, "mass on a spring")
    assert Grader.of("mass_spring_gravity").grade(text, "PE").right


def test_a_steady_load_is_no_substitute_for_gravity():
    kind, _, correct, category = _one("mass_spring_gravity", "k x^2/2 - F x", "PE")
    assert (kind, correct, category) == ("missing", "M*g*x", "a gravity term")


def test_the_terms_of_a_kinetic_energy_are_named_as_such_in_the_students_names():
    # simple_pendulum: T = m l^2 theta'^2/2 (aliases m, l of the source's M, a)
    assert _one("simple_pendulum", "m*l*theta'^2/2", "KE") == (
        "coefficient", "m*l*theta'^2/2", "m*l^2*theta'^2/2", "a kinetic-energy term")


def test_a_kinetic_energy_with_a_prescribed_rotation_gets_its_edit():
    # bead_on_hoop: T = m R^2 (theta'^2 + omega^2 sin^2 theta)/2, the hoop turned at omega
    kind, _, correct, category = _one("bead_on_hoop", "m*R^2*theta'^2/2", "KE")
    assert (kind, category) == ("missing", "a centrifugal term")
    assert correct == "R^2*m*omega^2*sin(theta)^2/2"


def test_a_term_written_only_inside_a_group_is_missing_not_miscounted():
    # taut_string_masses: V = P/(2a) (x1^2 + (x2 - x1)^2 + x2^2); the third segment dropped
    assert _one("taut_string_masses", "P/(2a) (x1^2 + (x2 - x1)^2)", "PE") == (
        "missing", "", "P*x2^2/(2*a)", "a potential-energy term")


def test_a_term_written_on_its_own_keeps_its_wrong_coefficient():
    # simple_pendulum: l theta'' + g sin(theta) = 0; half the gravity inside m(...)
    kind, term, correct, _ = _one("simple_pendulum", "m*(l*theta'' + g*sin(theta)/2) = 0")
    assert (kind, term, correct) == ("coefficient", "m*g*sin(theta)/2", "m*g*sin(theta)")


def test_a_written_group_in_place_of_one_term_is_one_wrong_term():
    # falling_container: T = m1 x1'^2/2 + m2 x2'^2/2; m2's velocity taken relative
    kind, term, correct, category = _one("falling_container", "m1 x1'^2/2 + m2 (x2' - x1')^2/2",
                                         "KE")
    assert (kind, correct, category) == ("replace", "m2*x2'^2/2", "a kinetic-energy term")
    assert term == "m2*(x2' - x1')^2/2"


def test_a_reaction_that_is_zero_on_the_motion_is_no_missing_term():
    # block_in_pipe: y theta'' + 2 y' theta' + g sin(theta) = 0; the pipe's N is 0 (massless)
    assert _one("block_in_pipe", "y*theta'' + y'*theta' + g*sin(theta) = 0")[:3] == (
        "coefficient", "theta'*y'", "2*theta'*y'")


def test_a_reaction_written_through_another_reactions_row_is_diagnosed():
    # pulley_bent_track: T2 = T1 + m x''/2 with T1 = M1 x'' + c x' + k x (pulley's inertia)
    assert _one("pulley_bent_track", "M1*x'' + c*x' + k*x", "T2") == (
        "missing", "", "m*x''/2", "an inertia term")


def test_a_like_term_written_for_another_is_one_wrong_term():
    # restrained_pendulum_horizontal: the spring's term is k b^2 sin(theta) cos(theta)
    text = "m l^2 theta'' + c a^2 cos(theta)^2 theta' + k b^2 sin(theta) + m g l sin(theta) = 0"
    assert _one("restrained_pendulum_horizontal", text) == (
        "replace", "b^2*k*sin(theta)", "b^2*k*sin(theta)*cos(theta)", "a spring term")


def test_a_swap_names_its_kind_of_term():
    # falling_container: m2 x2'' + c (x2' - x1') + k (x2 - x1 - l0) + m2 g = 0 (source 000
    # prints m1 x2'': an erratum)
    g = Grader.of("falling_container").grade(
        "m1 x2'' + c (x2' - x1') + k (x2 - x1 - l0) + m2 g = 0")
    assert g.edits[0].kind == "swap" and g.edits[0].sentence().endswith("(an inertia term)")
