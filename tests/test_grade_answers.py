"""Hand-typed answers to three problems, graded: right ones accepted, wrong ones diagnosed.

The correct forms are the sources' own (toy_car: MIT 2.003J quiz 1 (9), (10); cart_pendulum:
Example 17; pendulum_on_mass: quiz 2 (c)), checked by hand against the problems' docstrings.
The wrong ones include the sources' misprints listed in README.md's errata table; each must get
the diagnosis the table gives.
"""
from __future__ import annotations

import json

import pytest
import sympy as sp

from dualmech.grade import Grader, UnknownQuantity
from dualmech.grade.answers import find_quantity

TOY_THETA = "R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta) = 0"
TOY_PHI = "R*phi''*cos(theta) - 2*R*phi'*theta'*sin(theta) + g*sin(phi) = 0"


@pytest.fixture(scope="module")
def toy():
    return Grader("toy_car")


@pytest.fixture(scope="module")
def cart():
    return Grader("cart_pendulum")


@pytest.fixture(scope="module")
def pom():
    return Grader("pendulum_on_mass")


def edits(result, kind=None):
    return [e for e in result.edits if kind is None or e.kind == kind]


def same(text: str, expected: str, problem: str = "toy_car") -> bool:
    """Two term texts are the same expression (both typed in the answer syntax)."""
    from dualmech.grade.formula import Formula
    from dualmech.grade.parser import parse
    voc = Grader.of(problem).context.vocabulary
    a = Formula.from_node(parse(text)[0].lhs, voc).sympy()
    b = Formula.from_node(parse(expected)[0].lhs, voc).sympy()
    return sp.expand(a - b) == 0


# -- toy car ------------------------------------------------------------------------------------
def test_toy_car_boxed_equations_of_motion(toy):
    r = toy.grade(TOY_THETA + "\n" + TOY_PHI)
    assert r.right and r.quantity == "eom" and "exact rational-point test" in r.method


def test_toy_car_single_equations_name_their_coordinate(toy):
    assert toy.grade(TOY_THETA).matches == "the equation of theta"
    assert toy.grade(TOY_PHI).matches == "the equation of phi"


@pytest.mark.parametrize("form", [
    # scaled by m R, rearranged, other notations, a trigonometric identity
    "m*R^2*theta'' = -m*R^2*phi'^2*sin(theta)*cos(theta) - m*g*R*cos(phi)*sin(theta)",
    r"R\ddot{\theta} + \frac{R}{2}\dot{\phi}^2\sin(2\theta) + g\cos\phi\sin\theta = 0",
    "R θ̈ + R φ̇² sin θ cos θ + g cos φ sin θ = 0",
    "thetaddot = -phidot^2*sin(theta)*cos(theta) - g/R*cos(phi)*sin(theta)",
    "R*theta_dd + R*phi_d^2*sin(th)*cos(th) + g*cos(ph)*sin(th)",
    "R*ddtheta + R*dphi^2*tan(theta)*cos(theta)^2 + g*cos(phi)*sin(theta) = 0",
])
def test_toy_car_equivalent_forms(toy, form):
    assert toy.grade(form, "equation:theta").right


def test_toy_car_combined_and_solved_sets(toy):
    both = f"({TOY_THETA[:-4]}) + ({TOY_PHI[:-4]}) = 0\n{TOY_PHI}"
    assert toy.grade(both).right
    solved = ("theta'' = -phi'^2*sin(theta)*cos(theta) - g/R*cos(phi)*sin(theta);"
              "phi'' = (2*R*phi'*theta'*sin(theta) - g*sin(phi))/(R*cos(theta))")
    assert toy.grade(solved).right


def test_toy_car_newton_euler_with_the_track_force(toy):
    # quiz 1 (8), on i_B, j_B, k_B: F_r k_B - m g K = m a
    ne = ("m*g*sin(theta)*cos(phi) = m*R*(-theta'' - phi'^2*sin(theta)*cos(theta))\n"
          "-m*g*sin(phi) = m*R*(phi''*cos(theta) - 2*phi'*theta'*sin(theta))\n"
          "F_r - m*g*cos(theta)*cos(phi) = m*R*(phi'^2*cos(theta)^2 + theta'^2)")
    r = toy.grade(ne)
    assert r.right and "reactions F_r" in r.summary


def test_toy_car_missing_coriolis_term(toy):
    r = toy.grade("R*phi''*cos(theta) + g*sin(phi) = 0")
    (e,) = edits(r)
    assert r.status == "wrong" and e.kind == "missing" and e.category == "a Coriolis term"
    assert same(e.correct, "-2*R*phi'*theta'*sin(theta)")


def test_toy_car_printed_9_coriolis_sign(toy):
    """Errata: (9) restates the j_B equation with + 2 phi' theta' sin(theta)."""
    r = toy.grade("-m*g*sin(phi) - m*R*(phi''*cos(theta) + 2*phi'*theta'*sin(theta)) = 0")
    (e,) = edits(r)
    assert e.kind == "sign" and e.category == "a Coriolis term"
    assert same(e.term, "-2*m*R*phi'*theta'*sin(theta)")


def test_toy_car_track_force(toy):
    right = "m*(g*cos(phi)*cos(theta) + R*phi'^2*cos(theta)^2 + R*theta'^2)"
    assert toy.grade(right, "F_r").right
    assert toy.grade("F_r = " + right, "F_r").right
    r = toy.grade("m*(g*cos(phi)*cos(theta) + R*phi'^2*cos(theta)^2 - R*theta'^2)", "F_r")
    (e,) = edits(r, "sign")
    assert e.category == "a centripetal term" and same(e.correct, "R*m*theta'^2")
    r = toy.grade("g*cos(phi)*cos(theta) + R*phi'^2*cos(theta)^2 + R*theta'^2", "F_r")
    assert r.dimension_issues and edits(r, "factor")[0].detail == "1/m"


def test_toy_car_track_force_with_accelerations(toy):
    # the k_B row of the direct form does not need the accelerations, but an answer may keep
    # them: m R (theta'' ...) terms that vanish on the motion are put in exactly
    r = toy.grade("m*(g*cos(phi)*cos(theta) + R*phi'^2*cos(theta)^2 + R*theta'^2) + "
                  "m*(R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta))",
                  "F_r")
    assert r.right


def test_toy_car_printed_B_torque_of_gravity(toy):
    """Errata: R missing and the angles swapped."""
    r = toy.grade("[-m*g*sin(theta), -m*g*cos(theta)*sin(phi), 0]",
                  "(B) torque of gravity about O")
    assert r.status == "wrong" and r.dimension_issues
    assert {e.kind for e in r.edits} == {"swap", "factor"}
    assert all(e.detail == "1/R" for e in edits(r, "factor"))
    assert all("`theta` and `phi`" in e.detail for e in edits(r, "swap"))


def test_toy_car_printed_B_rate_of_angular_momentum(toy):
    """Errata: m R instead of m R^2 from the third line on."""
    r = toy.grade("[m*R*(phi''*cos(theta) - 2*phi'*theta'*sin(theta)), "
                  "m*R*(phi'^2*cos(theta)*sin(theta) + theta''), 0]", "(B) rate of h_O")
    assert [e.detail for e in edits(r, "factor")] == ["1/R", "1/R"]
    assert [e.equation for e in edits(r, "factor")] == [0, 1]


def test_toy_car_energies_and_lagrangian(toy):
    T = "m*R^2*(theta'^2 + phi'^2*cos(theta)^2)/2"
    V = "-m*g*R*cos(theta)*cos(phi)"
    assert toy.grade(T, "KE").right and toy.grade(T, "T").right
    assert toy.grade(V, "V").right
    assert toy.grade(V + " + 7*m*g*R", "V").right            # up to a constant
    assert toy.grade(f"{T} - ({V})", "L").right
    assert toy.grade(f"3*({T} - ({V}))", "L").right           # c L
    # + dF/dt with F = m g R t theta phi
    assert toy.grade(f"{T} - ({V}) + m*g*R*(theta*phi + t*theta'*phi + t*theta*phi')",
                     "L").right
    r = toy.grade(f"{T} + ({V})", "L")
    (e,) = edits(r)
    assert e.kind == "sign" and e.category == "a gravity term"
    r = toy.grade("m*R^2*theta'^2/2", "KE")
    (e,) = edits(r)
    assert e.kind == "missing" and same(e.correct, "m*R^2*phi'^2*cos(theta)^2/2")


def test_toy_car_accelerations(toy):
    assert toy.grade("-phi'^2*sin(theta)*cos(theta) - g/R*cos(phi)*sin(theta)", "theta''").right
    r = toy.grade("-phi'^2*sin(theta)*cos(theta) + g/R*cos(phi)*sin(theta)", "thetaddot")
    assert r.status == "wrong" and edits(r, "sign")
    r = toy.grade("theta''", "theta''")
    assert r.status == "invalid" and "without theta''" in r.summary


def test_toy_car_sets_that_determine_nothing(toy):
    r = toy.grade(f"{TOY_THETA}\n2*({TOY_THETA[:-4]}) = 0")
    assert r.status == "wrong" and "do not determine" in r.summary and "phi''" in r.summary
    r = toy.grade(TOY_THETA, "eom")
    assert r.status == "wrong" and "1 equation cannot determine 2 unknowns" in r.summary


def test_toy_car_wrong_coordinate(toy):
    r = toy.grade(TOY_PHI, "equation:theta")
    assert r.status == "wrong" and "not the equation of theta" in r.summary


def test_unknown_names_and_quantities(toy):
    r = toy.grade("R*thta'' = 0")
    assert r.status == "invalid" and "Did you mean `theta`" in r.summary
    assert "theta (θ, th)" in r.summary and "F_r" in r.summary
    with pytest.raises(UnknownQuantity, match="It offers: eom, equation"):
        find_quantity(toy.context, "momentum")


def test_result_json(toy):
    d = toy.grade("R*phi''*cos(theta) + g*sin(phi) = 0").to_dict()
    json.dumps(d)
    assert d["status"] == "wrong" and d["edits"][0]["kind"] == "missing"
    assert set(d) >= {"problem", "quantity", "answer", "status", "summary", "edits",
                      "dimension_issues", "method", "seconds"}


def test_vector_in_a_named_basis():
    """A problem may declare quantities; h_O in i_B, j_B, k_B (quiz 1 (4), by hand)."""
    from dualmech.problems.toy_car import ToyCar, frames, m
    from dualmech import Particle

    class ToyCarWithMomentum(ToyCar):
        def quantities(self):
            f = frames()
            h = Particle("car", m, f.car).angular_momentum(f.o, f.O).express(f.B)
            return {"h_O": {"value": tuple(h.components), "basis": ("i_B", "j_B", "k_B"),
                            "description": "the angular momentum about O"}}

    g = Grader(ToyCarWithMomentum())
    assert g.grade("m*R^2*(phi'*cos(theta)*i_B + theta'*j_B)", "h_O").right
    r = g.grade("m*R^2*(phi'*cos(theta)*i_B - theta'*j_B)", "h_O")
    (e,) = edits(r)
    assert e.kind == "sign" and e.part == "component" and e.equation == 1
    assert g.grade("m*R^2*phi'*cos(theta)*i_B + 1", "h_O").status == "invalid"


# -- cart pendulum ------------------------------------------------------------------------------
CART_X = ("(m + m0)*x'' + c*x' + k*x + m0*l*(theta''*cos(theta) - theta'^2*sin(theta)) "
          "= F0*sin(omega*t)")
CART_TH = ("m0*l^2*theta'' + c_t*theta' + k_t*theta + m0*g*l*sin(theta) + m0*l*x''*cos(theta)"
           " = F0*sin(omega*t)*l*cos(theta)")


def test_cart_pendulum_equations(cart):
    assert cart.grade(CART_X + "\n" + CART_TH).right


def test_cart_pendulum_printed_theta_equation(cart):
    """Errata: m0 l theta'' where m0 l^2 theta'' belongs -- dimensions first."""
    r = cart.grade(CART_TH.replace("m0*l^2*theta''", "m0*l*theta''"))
    assert "`l*m0*theta''`" in r.dimension_issues[0]
    (e,) = edits(r)
    assert e.kind == "coefficient" and same(e.correct, "m0*l^2*theta''", "cart_pendulum")
    assert str(r).index("dimensions:") < str(r).index("smallest edit")


def test_cart_pendulum_dropped_damping(cart):
    r = cart.grade(CART_X.replace("c*x' + ", ""))
    (e,) = edits(r)
    assert e.kind == "missing" and e.category == "a damping term" and same(e.correct, "c*x'", "cart_pendulum")


def test_cart_pendulum_energies_and_forces(cart):
    assert cart.grade("k*x^2/2 + k_t*theta^2/2 + m0*g*l*(1 - cos(theta))", "V").right
    assert cart.grade("m*x'^2/2 + m0*(x'^2 + l^2*theta'^2 + 2*x'*l*theta'*cos(theta))/2",
                      "KE").right
    assert cart.grade("[F0*sin(omega*t), F0*sin(omega*t)*l*cos(theta)]", "Q").right
    r = cart.grade("[F0*sin(omega*t) - c*x', F0*sin(omega*t)*l*cos(theta) - c_t*theta']", "Q")
    assert r.right and "dashpot" in r.summary           # dampers counted in Q, not R
    assert cart.grade("F0*sin(omega*t)*l*cos(theta)", "Q_theta").right
    r = cart.grade("F0*sin(omega*t)*cos(theta)", "Q_theta")
    assert r.status == "wrong" and r.dimension_issues
    # T is the rod tension here; the kinetic energy is KE
    assert find_quantity(cart.context, "T").kind == "expression"


def test_cart_pendulum_tension(cart):
    # bob along R.y: T = m0 g cos(th) + F sin(th) + m0 l th'^2 - m0 x'' sin(th) (docstring)
    right = "m0*g*cos(theta) + F0*sin(omega*t)*sin(theta) + m0*l*theta'^2 - m0*x''*sin(theta)"
    assert cart.grade(right, "T").right
    r = cart.grade(right.replace("+ m0*l*theta'^2", "- m0*l*theta'^2"), "T")
    (e,) = edits(r)
    assert e.kind == "sign" and e.category == "a centripetal term"


# -- pendulum on mass ---------------------------------------------------------------------------
def test_pendulum_on_mass_printed_inertia(pom):
    """Errata: the i_A entry is 335/6 m r^2, printed 331/6."""
    r = pom.grade("[331/6*m*r^2, 0, 0, 0, 1/2*m*r^2, 0, 0, 0, 169/3*m*r^2]",
                  "(b) inertia about A")
    (e,) = edits(r)
    assert e.kind == "coefficient" and e.equation == 0 and same(e.correct, "335/6*m*r^2", "pendulum_on_mass")


def test_pendulum_on_mass_printed_torque(pom):
    """Errata: the weight multiplied out as m g where 3 m g belongs."""
    r = pom.grade("-4*r*m*g*sin(theta)", "(c) torque about A, multiplied out")
    (e,) = edits(r)
    assert e.kind == "coefficient" and same(e.correct, "-12*r*m*g*sin(theta)", "pendulum_on_mass")
    assert pom.grade("-12*r*m*g*sin(theta)", "(c) torque about A").right


def test_pendulum_on_mass_printed_dL_dthetadot(pom):
    """Errata: 25/6 m r^2 theta' where 25/3 m r^2 theta' belongs."""
    r = pom.grade("48*m*r^2*theta' - 12*m*r*y'*sin(theta) + 25/6*m*r^2*theta'",
                  "(c) dL/dtheta'")
    (e,) = edits(r)
    assert e.kind == "coefficient"
    assert same(e.term, "25/6*m*r^2*theta'", "pendulum_on_mass")
    assert same(e.correct, "25/3*m*r^2*theta'", "pendulum_on_mass")


def test_pendulum_on_mass_equations_with_pivot_forces(pom):
    # quiz 2 (c): Newton for M and the pendulum along J, and the theta equation
    assert pom.grade("M*y'' + k*y + F_Ry = M*g\n"
                     "-3*m*y'' + 12*r*m*(theta''*sin(theta) + theta'^2*cos(theta)) = -3*m*g - F_Ry\n"
                     "169/3*m*r^2*theta'' + 12*m*g*r*sin(theta) = 12*m*r*y''*sin(theta)").right
    r = pom.grade("(M + 3*m)*y'' - 12*r*m*(theta''*sin(theta) + theta'^2*cos(theta)) + k*y "
                  "= (M + m)*g")
    (e,) = edits(r)
    assert e.category == "a gravity term"


def test_falling_container_printed_x_equations():
    """Errata: the free length is missing, and m1 x2'' is printed where m2 x2'' belongs."""
    g = Grader("falling_container")
    r = g.grade("m1*x1'' + c*(x1' - x2') + k*(x1 - x2) + m1*g = 0\n"
                "m1*x2'' + c*(x2' - x1') + k*(x2 - x1) + m2*g = 0")
    kinds = sorted((e.equation, e.kind) for e in r.edits)
    assert kinds == [(0, "missing"), (1, "missing"), (1, "swap")]
    assert all(e.category == "a spring term" for e in edits(r, "missing"))
    assert "`m1` and `m2`" in edits(r, "swap")[0].detail


def test_linearised_answers():
    g = Grader("simple_pendulum")
    assert g.grade("a*theta'' + g*theta = 0", "linearised").right
    assert g.grade("theta'' + g/a*theta", "linearised", about="theta=0").right
    assert g.grade("a*theta'' - g*(theta - pi) = 0", "linearised", about="theta=pi").right
    r = g.grade("a*theta'' + g*sin(theta) = 0", "linearised")
    (e,) = edits(r)
    assert e.kind == "replace" and e.term == "g*sin(theta)" and e.correct == "g*theta"
    assert "linearised about theta=0" in r.summary and r.quantity == "linearised"
    r = g.grade("a*theta'' + g*theta = 0", "linearised", about="x=0")
    assert r.status == "invalid" and "not a coordinate" in r.summary


def test_problem_names_are_checked():
    from dualmech.grade import grade
    r = grade("toy_cra", "x")
    assert r.status == "invalid" and "toy_car" in r.summary


def test_non_rational_answers_go_to_the_comparator(toy):
    # sqrt(4)/2 = 1: right; sqrt(1 - cos^2) is |sin(theta)|, not sin(theta), for theta < 0
    r = toy.grade("R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sin(theta)*sqrt(4)/2")
    assert r.right and "exact rational-point test (4 points" not in r.method
    r = toy.grade("R*theta'' + R*phi'^2*sin(theta)*cos(theta) + g*cos(phi)*sqrt(1 - cos(theta)^2)")
    assert r.status == "wrong"
    r = toy.grade("2*R*theta'' + R*phi'^2*sin(2*theta) + 4*g*cos(phi)*sin(theta/2)*cos(theta/2)")
    assert r.right


def test_answers_in_another_models_coordinates():
    # the source's second choice for the falling container: y1 = x1, y2 = x2 - x1 - l0
    g = Grader("falling_container")
    r = g.grade("(m1 + m2)*y1'' + m2*y2'' + (m1 + m2)*g = 0\n"
                "m2*y1'' + m2*y2'' + c*y2' + k*y2 + m2*g = 0")
    assert r.right
    r = g.grade("(m1 + m2)*y1'' + m2*y2'' + (m1 + m2)*g = 0\n"
                "m2*y1'' + m2*y2'' + k*y2 + m2*g = 0")
    assert r.status == "wrong"
