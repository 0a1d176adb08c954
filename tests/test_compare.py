"""The comparator: verdicts, explanations, reactions, published answers (dualmech.verify.check)."""
import json

import pytest
import sympy as sp

from dualmech import EquationSet, ModelError, coordinate, t
from dualmech.verify.check import compare, compare_models, recover_reactions

from _pendulum import Pendulum, cartesian, g, l, m, th

q1, q2 = coordinate("q1"), coordinate("q2")
k, c = sp.symbols("k c", positive=True)


def test_scaled_and_combined_equations_are_equivalent():
    a = EquationSet("a", (q1, q2), (m * q1.diff(t, 2) + k * (q1 - q2),
                                     m * q2.diff(t, 2) + k * (q2 - q1)))
    # row 1 + row 2 and 3 x row 2: an invertible combination
    b = EquationSet("b", (q1, q2), (m * (q1.diff(t, 2) + q2.diff(t, 2)),
                                     3 * m * q2.diff(t, 2) + 3 * k * (q2 - q1)))
    r = compare_models(a, b)
    assert r.equivalent and r.method == "exact" and r.points == 8
    assert r.bound < 1e-100


def test_wrong_term_is_named_with_its_residual():
    a = EquationSet("a", (q1,), (m * q1.diff(t, 2) + c * q1.diff(t) + k * q1,))
    b = EquationSet("b", (q1,), (m * q1.diff(t, 2) - c * q1.diff(t) + k * q1,), labels=("x-eq",))
    r = compare_models(a, b)
    assert not r.equivalent
    (mm,) = r.mismatches
    assert mm.equation == "x-eq"
    assert mm.residual == "-2*c*q1'"
    assert mm.state and mm.value != 0
    assert any("q1" in term for term, _ in mm.terms)


def test_singular_candidate_is_reported_undetermined():
    a = EquationSet("a", (q1, q2), (q1.diff(t, 2) + q1, q2.diff(t, 2) + q2))
    b = EquationSet("b", (q1, q2), (q1.diff(t, 2) + q1, 2 * q1.diff(t, 2) + 2 * q1))
    r = compare_models(a, b)
    assert not r.equivalent and "do not determine the accelerations" in r.mismatches[0].reason


def test_different_coordinates_are_refused_with_advice():
    a = EquationSet("a", (q1,), (q1.diff(t, 2),))
    b = EquationSet("b", (q2,), (q2.diff(t, 2),))
    with pytest.raises(ModelError, match="change_coordinates"):
        compare_models(a, b)


def test_singular_models_everywhere_are_a_mismatch_not_an_exception():
    a = EquationSet("a", (q1, q2), (q1.diff(t, 2) + q2.diff(t, 2), q1.diff(t, 2) + q2.diff(t, 2)))
    r = compare_models(a, a)
    assert not r.equivalent
    assert "no derivation determines the accelerations" in r.mismatches[0].reason


def test_pendulum_problem_agrees_and_recovers_the_tension():
    c_ = compare(Pendulum())
    assert c_.equivalent and not c_.dimension_issues
    S = c_.reactions["S"]
    assert sp.simplify(S - (m * g * sp.cos(th) + m * l * th.diff(t)**2)) == 0
    assert sp.simplify(sp.sympify(c_.accelerations["theta"]) + g * sp.sin(th) / l) == 0


def test_published_verdicts_of_the_pendulum():
    verdicts = {v.label: v for v in compare(Pendulum()).published}
    assert verdicts["EoM"].verdict == "correct"
    assert verdicts["tension"].verdict == "correct"
    assert verdicts["wrong tension"].verdict == "wrong"
    assert "l*m*theta'**2" in verdicts["wrong tension"].detail
    assert verdicts["small-angle EoM"].verdict == "wrong"
    slip = verdicts["dimension slip"]
    assert slip.verdict == "wrong" and "dimensionally inconsistent" in slip.detail


def test_cartesian_dae_is_the_same_motion_after_changing_coordinates():
    ref = Pendulum().model("lagrange")
    dae = cartesian()
    assert len(dae.unknowns) == 1 and len(dae.equations) == 3
    in_theta = dae.change_coordinates((th,), {coordinate("x"): l * sp.sin(th),
                                              coordinate("y"): -l * sp.cos(th)})
    r = compare_models(ref, in_theta)
    assert r.equivalent, str(r)


def test_json_has_the_documented_schema():
    d = compare(Pendulum()).to_dict()
    json.dumps(d)
    for key in ("name", "title", "source", "coordinates", "parameters", "equivalent", "method",
                "seconds", "eom", "accelerations", "reactions", "reaction_directions",
                "published", "mismatches"):
        assert key in d
    assert d["coordinates"] == ["theta"] and d["parameters"] == ["m", "l", "g"]
    assert d["eom"][0].count("theta''") == 1
    assert {p["verdict"] for p in d["published"]} == {"correct", "wrong"}
    assert d["reaction_directions"]["S"].startswith("rod tension")


def test_report_text_names_the_verdicts():
    text = str(compare(Pendulum()))
    assert "all derivations agree" in text and "[WRONG  ] wrong tension" in text


def test_recover_reactions_needs_no_comparison():
    assert set(recover_reactions(Pendulum())) == {"S"}


def test_integer_systems_stay_exact():
    # regression: int / int in the elimination gave floats, and a float residual of 1e36
    # passed the mpmath tolerance scaled by 1e71 -- a dropped spring was called equivalent
    from fractions import Fraction
    from dualmech.exact import linalg as la
    res, lam, und = la.residual_after_least_squares([[2], [4]], [1, 3])
    assert all(isinstance(v, Fraction) for v in res + lam)
    assert res == [Fraction(1, 5) - 0, Fraction(3) - Fraction(14, 5)] or res[0] != 0


def test_reactions_of_direct_form_and_multiplier_agree():
    c_ = compare(Pendulum())
    (pair,) = [p for p in c_.pairs if p.kind == "reactions"]
    assert pair.equivalent and pair.reactions == ("S",)
    assert pair.method == "exact"


def test_reaction_only_error_is_caught_by_the_multiplier_model():
    from dualmech.verify.check import compare_reactions
    p = Pendulum()
    ref = p.model("lagrange")
    multiplier = p.in_reference_coordinates(p.model("multiplier"))
    ne = p.model("newton_euler")
    bad = ne.flipped("gravity on bob") if "gravity on bob" in ne.ingredients() else None
    assert bad is not None
    # flipping gravity changes the motion too; a pure reaction error: tension doubled
    S = sp.Symbol("S", real=True)
    wrong = ne.substitute({S: 2 * S}, name="ne_wrong")
    assert compare_models(ref, wrong).equivalent          # the motion cannot see it
    r = compare_reactions(ref, multiplier, wrong, [S])
    assert not r.equivalent and r.mismatches[0].equation == "reaction S"


def test_reaction_with_the_wrong_dimension_is_reported():
    from dualmech.model.dimensions import TORQUE
    from dualmech.model.problem import Reaction

    class Mislabelled(Pendulum):
        reactions = (Reaction("S", TORQUE, "declared as a torque by mistake"),)

    c_ = compare(Mislabelled())
    assert any(issue.startswith("reaction S:") for issue in c_.dimension_issues)
    assert c_.equivalent  # the motion is still right; the audit is what flags it


def test_dimension_audit_of_a_derivation_held_in_symengine():
    """A Lagrangian with the track radius dropped from the potential (``-m g cos(theta)
    cos(phi)``, a force where an energy belongs) is flagged in the equations as derived
    (held in symengine), with the same findings as the audit of their sympy form."""
    from dualmech import Lagrangian, rate
    from dualmech.model.dimensions import audit
    from dualmech.model.equations import Rows
    from dualmech.problems import toy_car as tc

    class NoRadius(tc.ToyCar):
        def lagrange(self):
            lg = Lagrangian(coordinates=[tc.theta, tc.phi])
            lg.kinetic("T of car", tc.m * tc.R**2 * (rate(tc.theta)**2
                                                    + rate(tc.phi)**2 * sp.cos(tc.theta)**2) / 2)
            lg.potential("gravity", -tc.m * tc.g * sp.cos(tc.theta) * sp.cos(tc.phi))
            return lg.equations()

    p = NoRadius()
    issues = [i for i in p.dimension_issues() if i.startswith("lagrange")]
    assert len(issues) == 2 and all("g*m*" in i for i in issues), issues
    model = p.model("lagrange")
    assert isinstance(model.equations, Rows)
    dims = p.dimensions()
    held = [str(x) for e in model.equations.se
            for x in audit(e, dims, names=model.equations.names)]
    shown = [str(x) for e in model.equations.materialise() for x in audit(e, dims)]
    assert held == shown and len(held) == 2
