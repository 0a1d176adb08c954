"""Partial credit: the documented rule of :func:`dualmech.grade.result.score_of` applied to real
answers.  The toy car's equations (Lagrange, as the catalogue derives them, checked in
tests/test_toy_car.py): R theta'' + R phi'^2 sin cos + g cos(phi) sin(theta) = 0 and
R cos(theta) phi'' - 2 R phi' theta' sin(theta) + g sin(phi) = 0."""
import pytest

from dualmech import grade
from dualmech.grade.result import FEW_TERMS, ONE_TERM, score_of

THETA = "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0"
PHI = "R*cos(theta)*phi'' - 2*R*phi'*theta'*sin(theta) + g*sin(phi) = 0"


def test_right_system_scores_one():
    assert grade("toy_car", f"{THETA}; {PHI}").score == 1.0


def test_one_sign_slip_in_one_equation_of_two_scores_three_quarters():
    slipped = PHI.replace("- 2*R", "+ 2*R")
    g = grade("toy_car", f"{THETA}; {slipped}")
    assert g.status == "wrong" and len(g.edits) == 1
    assert g.score == pytest.approx((1 + ONE_TERM) / 2)


def test_an_equation_no_small_edit_explains_scores_nothing_for_that_equation():
    g = grade("toy_car", f"{THETA}; R*phi'' = 0")
    assert g.status == "wrong" and not [e for e in g.edits if e.equation == 1]
    assert g.score == pytest.approx(1 / 2)


def test_a_right_but_incomplete_system_scores_the_share_it_determines():
    g = grade("toy_car", THETA, "eom")
    assert g.status == "wrong" and "undetermined" in g.summary
    assert g.score == pytest.approx(1 / 2)     # theta'' determined, phi'' not


def test_a_single_wrong_equation_with_one_term_off_scores_one_term():
    g = grade("simple_pendulum", "a*theta'' - g*sin(theta) = 0")
    assert len(g.edits) == 1 and g.score == ONE_TERM


def test_invalid_scores_zero():
    assert grade("simple_pendulum", "a*theta'' + (g = 0").score == 0.0


@pytest.mark.parametrize("n_edits, expected", [(0, 0.0), (1, ONE_TERM), (2, FEW_TERMS),
                                               (3, FEW_TERMS), (4, 0.0)])
def test_the_rule_per_wrong_part(n_edits, expected):
    from dualmech.grade.result import Edit
    edits = [Edit("sign", None, "x", "-x")] * n_edits
    assert score_of("wrong", parts=1, edits=edits) == expected


def test_the_score_is_in_the_json_and_the_text():
    g = grade("simple_pendulum", "a*theta'' - g*sin(theta) = 0")
    assert g.to_dict()["score"] == ONE_TERM and "score: 0.5" in str(g)
